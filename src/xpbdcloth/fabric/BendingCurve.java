package xpbdcloth.fabric;

import java.util.Arrays;

/**
 * A fabric's measured bending beyond small curvature: the piecewise-linear model of Wang, O'Brien and
 * Ramamoorthi 2011 as ARCSim evaluates it (dde.cpp, {@code bending_stiffness}). Fifteen samples of the edge
 * stiffness k_e: for edges along u (our warp), at 45° and along v, each at α = 0, 5, 10, 15 and 20 m⁻¹.
 *
 * <pre>
 *   κ = |θ − θ₀| |e| / (A₀ + A₁)   (the hinge's curvature, 1/m; |e|, A₀, A₁ at rest)
 *   v = clamp(κ/10, 0, 4),  i = min(⌊v⌋, 3),  s = v − i   (ARCSim's α = κ/2 sampled every 5 m⁻¹)
 *   a = 4φ/π folded into [0, 2]  (φ the edge's angle to u),  j = min(⌊a⌋, 1),  t = a − j
 *   k_e = (1 − t)(1 − s) d[j][i] + t(1 − s) d[j+1][i] + (1 − t) s d[j][i+1] + t s d[j+1][i+1]
 *   B = k_e / 4   (ARCSim's edge energy k_e|e|²θ²/(8(A₀ + A₁)) against our B|e|²θ²/(2(A₀ + A₁)), {@link DataDrivenSample})
 * </pre>
 * A secant stiffness, as ARCSim uses it: the moment is B(κ)·κ per unit length at the hinge's own curvature.
 * Where ours differs: ARCSim takes the signed θ, so a fold one way reads the table at a negative curvature and
 * extrapolates below its first column; a fabric bends alike either way, so κ is the angle's magnitude here.
 * B is floored at a thousandth of its zero-curvature value (no sample in the catalogue comes near).
 */
public final class BendingCurve {
    /** The fraction of the zero-curvature stiffness B may not fall below. */
    static final double FLOOR = 1e-3;
    /** The curvature between the table's columns: α = κ/2 is sampled every 5 m⁻¹. */
    public static final double SAMPLE_SPACING = 10;
    /** k_e per direction (0°, 45°, 90°) and curvature column (5 each), N·m as tabulated. */
    private final double[] d = new double[15];
    private final double floor;

    /**
     * @param zeroCurvature the three zero-curvature samples (0°, 45°, 90°), as tabulated
     * @param beyond        per direction (0°, 45°, 90°), the four samples at α = 5, 10, 15, 20 m⁻¹
     */
    public BendingCurve(double[] zeroCurvature, double[][] beyond) {
        if (zeroCurvature == null || zeroCurvature.length != 3)
            throw new IllegalArgumentException("bending must hold 3 numbers (0°, 45°, 90°), was " + Arrays.toString(zeroCurvature));
        if (beyond == null || beyond.length != 3)
            throw new IllegalArgumentException("bendingCurve must hold 3 rows (0°, 45°, 90°), had " + (beyond == null ? "null" : beyond.length));
        for (int j = 0; j < 3; j++) {
            if (!(zeroCurvature[j] > 0 && zeroCurvature[j] < 1e6)) throw new IllegalArgumentException("bending[" + j + "] must be in (0, 1e6), was " + zeroCurvature[j]);
            if (beyond[j] == null || beyond[j].length != 4)
                throw new IllegalArgumentException("bendingCurve[" + j + "] must hold 4 numbers (α = 5, 10, 15, 20 /m), was " + Arrays.toString(beyond[j]));
            d[5 * j] = zeroCurvature[j];
            for (int i = 0; i < 4; i++) {
                if (!(beyond[j][i] >= 0 && beyond[j][i] < 1e6)) throw new IllegalArgumentException("bendingCurve[" + j + "][" + i + "] must be in [0, 1e6), was " + beyond[j][i]);
                d[5 * j + i + 1] = beyond[j][i];
            }
        }
        floor = FLOOR * DataDrivenSample.bendingStiffness(zeroCurvature);
    }

    /**
     * The secant bending stiffness B (N·m) of a hinge at curvature κ (1/m, its magnitude is used) whose edge
     * makes the angle φ (rad) with u. Allocation-free.
     */
    public double stiffness(double curvature, double edgeAngle) {
        double v = Math.min(Math.abs(curvature) / SAMPLE_SPACING, 4);
        int i = Math.min((int) v, 3);
        double s = v - i;
        double a = Math.abs(edgeAngle) * 4 / Math.PI % 8;  // the edge's direction, in eighths of a turn
        if (a > 4) a = 8 - a;
        if (a > 2) a = 4 - a;
        int j = Math.min((int) a, 1);
        double t = a - j;
        double ke = (1 - t) * (1 - s) * d[5 * j + i] + t * (1 - s) * d[5 * (j + 1) + i]
                + (1 - t) * s * d[5 * j + i + 1] + t * s * d[5 * (j + 1) + i + 1];
        return Math.max(ke / 4, floor);
    }
}
