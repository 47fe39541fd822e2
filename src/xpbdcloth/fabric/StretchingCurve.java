package xpbdcloth.fabric;

import java.util.Arrays;

/**
 * A fabric's measured stretching beyond small strain: the piecewise-linear model of Wang, O'Brien and
 * Ramamoorthi 2011 as ARCSim evaluates it (dde.cpp, {@code evaluate_stretching_sample}). Six samples of the
 * four stiffnesses (k₀, k₁, k₂, k₃): one at zero stretch and five at a principal stretch of 1/6, along 0°,
 * 22.5°, 45°, 67.5° and 90° to the data's u axis (our warp).
 *
 * <pre>
 *   C = FᵀF = I + 2E in the material frame;  λ = √(largest eigenvalue of C)   (the largest principal stretch)
 *   φ ∈ [0, π/2]: the angle of its direction to u, ½·atan2(2|C_uv|, C_uu − C_vv)
 *   s = clamp(6(λ − 1), 0, 1),   a = 8φ/π ∈ [0, 4],  j = ⌊a⌋ (4 at most 3),  t = a − j
 *   k = (1 − s)·k⁰ + s·((1 − t)·k^(j) + t·k^(j+1))
 *   Q₁₁ = 2k₀, Q₁₂ = 2k₁, Q₂₂ = 2k₂, G₁₂ = k₃   (ARCSim's doubling, as {@link DataDrivenSample})
 * </pre>
 * The stiffness is a secant one, as ARCSim uses it: stress = Q(C)·ε with Q taken at the current strain and held
 * while the step solves. At zero strain it is the linear fabric {@link DataDrivenSample} makes.
 * Where ours differs: ARCSim tabulates this on a 30³ grid of the Green strain (G_uv ≥ 0, looked up by |G_uv|,
 * which is why φ is folded here) and interpolates trilinearly; we evaluate it exactly. ARCSim floors each k at 0,
 * which leaves no shear stiffness where a sample's k₃ is negative (six of the nine fabrics have one): a
 * compliance of infinity for XPBD; we floor k₀, k₂ and k₃ at a thousandth of their zero-strain values and keep
 * Q₁₂ inside positive definiteness (|Q₁₂| ≤ 0.999 √(Q₁₁Q₂₂)).
 */
public final class StretchingCurve {
    /** The fraction of the zero-strain stiffness no sample may fall below. */
    static final double FLOOR = 1e-3;
    /** k⁰ and the five directional samples k^(0..4), four numbers each, as tabulated (before the doubling). */
    private final double[] zero, directions;

    /**
     * @param zeroStrain the zero-stretch sample (k₀, k₁, k₂, k₃), N/m as tabulated
     * @param atOneSixth five samples at a principal stretch of 1/6, along 0°, 22.5°, 45°, 67.5°, 90° to u
     */
    public StretchingCurve(double[] zeroStrain, double[][] atOneSixth) {
        if (zeroStrain == null || zeroStrain.length != 4)
            throw new IllegalArgumentException("zeroStrain must hold 4 numbers (k0, k1, k2, k3), was " + Arrays.toString(zeroStrain));
        if (!(zeroStrain[0] > 0 && zeroStrain[2] > 0 && zeroStrain[3] > 0))
            throw new IllegalArgumentException("zeroStrain's k0, k2 and k3 must be positive, was " + Arrays.toString(zeroStrain));
        if (atOneSixth == null || atOneSixth.length != 5)
            throw new IllegalArgumentException("stretchingCurve must hold 5 samples (0°, 22.5°, 45°, 67.5°, 90°), had " + (atOneSixth == null ? "null" : atOneSixth.length));
        zero = zeroStrain.clone();
        directions = new double[20];
        for (int j = 0; j < 5; j++) {
            if (atOneSixth[j] == null || atOneSixth[j].length != 4)
                throw new IllegalArgumentException("stretchingCurve[" + j + "] must hold 4 numbers, was " + Arrays.toString(atOneSixth[j]));
            for (int k = 0; k < 4; k++) {
                if (!Double.isFinite(atOneSixth[j][k])) throw new IllegalArgumentException("stretchingCurve[" + j + "][" + k + "] must be finite, was " + atOneSixth[j][k]);
                directions[4 * j + k] = atOneSixth[j][k];
            }
        }
    }

    /**
     * The secant stiffness at right Cauchy–Green tensor (cuu, cvv, cuv) into q = (Q₁₁, Q₁₂, Q₂₂, G₁₂), N/m.
     * Allocation-free.
     */
    public void stiffness(double cuu, double cvv, double cuv, double[] q) {
        double mean = 0.5 * (cuu + cvv), half = 0.5 * (cuu - cvv), radius = Math.sqrt(half * half + cuv * cuv);
        double stretch = Math.sqrt(Math.max(0, mean + radius));
        double s = Math.max(0, Math.min(1, 6 * (stretch - 1)));
        double a = Math.min(4, 8 / Math.PI * 0.5 * Math.atan2(2 * Math.abs(cuv), cuu - cvv));
        int j = Math.min(3, (int) a);
        double t = a - j;
        for (int k = 0; k < 4; k++) {
            double along = (1 - t) * directions[4 * j + k] + t * directions[4 * (j + 1) + k];
            double v = (1 - s) * zero[k] + s * along;
            q[k] = k == 1 ? v : Math.max(v, FLOOR * zero[k]);
        }
        double q11 = 2 * q[0], q22 = 2 * q[2], most = 0.999 * Math.sqrt(q11 * q22);
        q[1] = Math.max(-most, Math.min(most, 2 * q[1]));
        q[0] = q11;
        q[2] = q22;
    }
}
