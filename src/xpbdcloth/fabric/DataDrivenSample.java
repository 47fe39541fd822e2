package xpbdcloth.fabric;

import xpbdcloth.engine.OrthotropicMaterial;

/**
 * A measured fabric from the data-driven cloth models of Wang, O'Brien and Ramamoorthi 2011 ("Data-Driven
 * Elastic Models for Cloth: Modeling and Measurement", SIGGRAPH; the ten fabrics as distributed with the
 * ARCSim simulator, materials/*.json), taken at small strain and small curvature, where those piecewise
 * models are linear.
 *
 * <pre>
 *   stretching s = (s₀, s₁, s₂, s₃): the table's first (zero-strain) sample. ARCSim evaluates it doubled,
 *     k = 2s, in the energy per area ½k₀E_uu² + k₁E_uuE_vv + ½k₂E_vv² + k₃E_uv² (Green strain E);
 *     with γ = 2E_uv, k₃E_uv² = ½(k₃/2)γ², so it is ½εᵀQε for Q₁₁ = 2s₀, Q₁₂ = 2s₁, Q₂₂ = 2s₂, G₁₂ = k₃/2 = s₃ (N/m)
 *   bending b = (b₀°, b₄₅°, b₉₀°): the zero-curvature samples for edges along u, diagonal, along v. ARCSim's
 *     edge energy is k_e |e|² θ²/(8(A₀ + A₁)); ours is B |e|² θ²/(2(A₀ + A₁)) ({@code DihedralBlock}), so
 *     B = k_e/4. Our bending is isotropic: B is the mean of the 0° and 90° samples (the 45° one is left out)
 * </pre>
 * The u axis of the data is E₁ here (our "warp"), v is E₂; the data name no warp or weft.
 */
public final class DataDrivenSample {
    private DataDrivenSample() {}

    /**
     * @param stretching the four zero-strain stretching values as tabulated (N/m, before ARCSim's doubling)
     * @param bending    the three zero-curvature bending values as tabulated (0°, 45°, 90°)
     */
    public static Fabric fabric(String name, String description, String source, double arealDensity, double[] stretching, double[] bending) {
        return fabric(name, description, source, arealDensity, stretching, bending, null, null);
    }

    /**
     * As above, with the five samples at 1/6 stretch that make the whole measured stretching curve
     * ({@link StretchingCurve}), or null; and per direction the four samples at larger curvature that make
     * the whole bending curve ({@link BendingCurve}), or null.
     */
    public static Fabric fabric(String name, String description, String source, double arealDensity, double[] stretching, double[] bending,
                                double[][] stretchingCurve, double[][] bendingCurve) {
        if (stretching == null || stretching.length != 4)
            throw new IllegalArgumentException("stretching must hold 4 numbers (k0, k1, k2, k3), was " + java.util.Arrays.toString(stretching));
        if (bending == null || bending.length != 3)
            throw new IllegalArgumentException("bending must hold 3 numbers (0°, 45°, 90°), was " + java.util.Arrays.toString(bending));
        OrthotropicMaterial m = OrthotropicMaterial.fromStiffness(2 * stretching[0], 2 * stretching[1], 2 * stretching[2], stretching[3]);
        return new Fabric(name, description, source, arealDensity, m, bendingStiffness(bending),
                stretchingCurve == null ? null : new StretchingCurve(stretching, stretchingCurve),
                bendingCurve == null ? null : new BendingCurve(bending, bendingCurve));
    }

    /** B (N·m) from the three zero-curvature samples: the mean of 0° and 90°, over ARCSim's factor 4. */
    public static double bendingStiffness(double[] bending) {
        return (bending[0] + bending[2]) / 2 / 4;
    }
}
