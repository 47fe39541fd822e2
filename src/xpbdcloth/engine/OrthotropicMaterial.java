package xpbdcloth.engine;

/**
 * A woven fabric's in-plane elasticity: Young's moduli along warp and weft, the Poisson ratio ν₁₂
 * (contraction along weft under a pull along warp) and the in-plane shear modulus, all per unit width
 * (N/m: the modulus in Pa times the thickness, as textile tests report them). Plane stress:
 *
 * <pre>
 *   ν₂₁ = ν₁₂ E₂/E₁ (Maxwell's reciprocity),   D = 1 − ν₁₂ν₂₁
 *   Q = [[E₁/D, ν₂₁E₁/D, 0], [ν₁₂E₂/D, E₂/D, 0], [0, 0, G₁₂]]   (σ = Q ε, ε = (ε_uu, ε_vv, γ))
 * </pre>
 * Q is symmetric (ν₂₁E₁ = ν₁₂E₂) and positive definite exactly when E₁, E₂, G₁₂ &gt; 0 and ν₁₂² &lt; E₁/E₂;
 * outside that the energy has no minimum and the material is refused.
 */
public final class OrthotropicMaterial {
    public final double warpModulus, weftModulus, poisson, shearModulus;

    /**
     * @param warpModulus  E₁·t along warp, N/m, &gt; 0
     * @param weftModulus  E₂·t along weft, N/m, &gt; 0
     * @param poisson      ν₁₂, with ν₁₂² &lt; E₁/E₂
     * @param shearModulus G₁₂·t, N/m, &gt; 0
     */
    public OrthotropicMaterial(double warpModulus, double weftModulus, double poisson, double shearModulus) {
        this.warpModulus = Check.inRange("warpModulus", warpModulus, Double.MIN_NORMAL, 1e12);
        this.weftModulus = Check.inRange("weftModulus", weftModulus, Double.MIN_NORMAL, 1e12);
        this.shearModulus = Check.inRange("shearModulus", shearModulus, Double.MIN_NORMAL, 1e12);
        double limit = Math.sqrt(warpModulus / weftModulus);
        if (!(Math.abs(poisson) < limit))
            throw new IllegalArgumentException(String.format(java.util.Locale.ROOT,
                    "poisson must satisfy |ν12| < sqrt(E1/E2) = %.4g for a positive-definite stiffness, was %s", limit, poisson));
        this.poisson = poisson;
    }

    /** From moduli in Pa and a thickness in m. */
    public static OrthotropicMaterial ofModuli(double warpPa, double weftPa, double poisson, double shearPa, double thickness) {
        Check.inRange("thickness", thickness, Double.MIN_NORMAL, 1);
        return new OrthotropicMaterial(warpPa * thickness, weftPa * thickness, poisson, shearPa * thickness);
    }

    /**
     * From the plane-stress stiffness itself (N/m), as data-driven cloth models tabulate it
     * (energy per area ½Q₁₁ε_uu² + Q₁₂ε_uuε_vv + ½Q₂₂ε_vv² + ½G₁₂γ²): the inverse of {@link #stiffness()},
     * E₁ = Q₁₁ − Q₁₂²/Q₂₂, E₂ = Q₂₂ − Q₁₂²/Q₁₁, ν₁₂ = Q₁₂/Q₂₂.
     */
    public static OrthotropicMaterial fromStiffness(double q11, double q12, double q22, double shearModulus) {
        Check.inRange("q11", q11, Double.MIN_NORMAL, 1e12);
        Check.inRange("q22", q22, Double.MIN_NORMAL, 1e12);
        if (!(q12 * q12 < q11 * q22))
            throw new IllegalArgumentException(String.format(java.util.Locale.ROOT,
                    "q12 must satisfy q12² < q11·q22 = %.4g for a positive-definite stiffness, was %s", q11 * q22, q12));
        return new OrthotropicMaterial(q11 - q12 * q12 / q22, q22 - q12 * q12 / q11, q12 / q22, shearModulus);
    }

    /** An isotropic sheet: E·t, ν, G = E/(2(1 + ν)). */
    public static OrthotropicMaterial isotropic(double modulus, double poisson) {
        return new OrthotropicMaterial(modulus, modulus, poisson, modulus / (2 * (1 + poisson)));
    }

    /** ν₂₁ = ν₁₂ E₂/E₁. */
    public double weftPoisson() { return poisson * weftModulus / warpModulus; }

    /** Q (N/m), row-major 3×3, for ε = (ε_uu, ε_vv, γ). */
    public double[] stiffness() {
        double nu21 = weftPoisson(), d = 1 - poisson * nu21;
        return new double[] {warpModulus / d, nu21 * warpModulus / d, 0, poisson * weftModulus / d, weftModulus / d, 0, 0, 0, shearModulus};
    }

    /**
     * The modulus (N/m) of a strip pulled at θ to the warp, free to contract (Jones, eq. 2.97):
     * 1/E(θ) = cos⁴θ/E₁ + (1/G₁₂ − 2ν₁₂/E₁) sin²θ cos²θ + sin⁴θ/E₂.
     */
    public double modulusAt(double theta) {
        double c = Math.cos(theta), s = Math.sin(theta);
        return 1 / (c * c * c * c / warpModulus + (1 / shearModulus - 2 * poisson / warpModulus) * s * s * c * c + s * s * s * s / weftModulus);
    }
}
