package xpbdcloth.fabric;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.MembraneBlock;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SolverSettings;
import xpbdcloth.engine.SolverType;
import xpbdcloth.engine.StepBalance;

/**
 * A heavy strip of a measured fabric hanging from its top edge, its stiffness following its strain step by step:
 * it comes to rest (the step's own equation balanced, so the lagged stiffness has caught up with the strain) and
 * stretches less than the same strip as the linear fabric, by about what the curve says at that strain.
 */
class StiffeningUnderLoadTest {
    static final double[][] DENIM_CURVE = {
            {232.027634, 40.646339, 1052.84289, 64.980499}, {224.592209, 40.384563, 1054.43444, 67.184807},
            {225.951050, 62.095657, 1059.59741, 83.992020}, {226.039566, 40.502792, 1058.27771, 75.118423},
            {225.767487, 40.917892, 1051.55712, 71.810631}};
    static final double[] DENIM_ZERO = {205.352005, 10.234077, 1013.88629, 53.387184};

    /** The strip's mean warp strain at rest and the step's balance, with or without the curve. */
    static double[] hang(boolean curve) {
        Cloth strip = new ClothBuilder().resolution(5, 13).size(0.04, 0.12).arealDensity(40).pinTopCorners().build();
        Particles p = strip.particles();
        for (int c = 0; c < 5; c++) p.pin(strip.index(0, c));
        Fabric denim = DataDrivenSample.fabric("denim", "", "", 0.324, DENIM_ZERO, new double[] {64e-6, 73e-6, 97e-6}, DENIM_CURVE, null);
        Simulation sim = new Simulation(p, new SolverSettings().withMode(ConstraintMode.XPBD).withSolver(SolverType.VERTEX_BLOCK_DESCENT)
                .withIterations(4).withSubsteps(5).withTimestep(0.01).withDamping(20));
        // Warp along the strip's length (y): it hangs by its warp.
        for (ConstraintBlock b : FabricConstraints.build(p, strip.triangles(), new double[] {0, 1, 0}, denim.membrane, denim.bendingStiffness, false)) sim.add(b);
        if (curve) sim.add(new MeasuredStiffening(sim.blocks(), denim.stretchingCurve));
        for (int s = 0; s < 600; s++) sim.step();
        MembraneBlock m = (MembraneBlock) sim.blocks().get(0);
        double strain = 0;
        for (int t = 0; t < m.triangleCount(); t++) strain += m.largestNormalStrain(t, p);
        return new double[] {strain / m.triangleCount(), sim.balance()};
    }

    @Test
    void aHeavyStripComesToRestStifferThanTheLinearFabric() {
        double[] linear = hang(false), curve = hang(true);
        System.out.printf("mean warp Green strain: linear %.5f (balance %.2e), measured curve %.5f (balance %.2e)%n", linear[0], linear[1], curve[0], curve[1]);
        assertTrue(curve[1] < StepBalance.CONVERGED, "balance " + curve[1]);
        // The strains' ratio against the warp moduli's, E = Q₁₁ − Q₁₂²/Q₂₂ (a strip free to narrow), linear over the
        // curve's at the mean strain: the data's rows interpolated at stretch λ = √(1 + 2E_uu).
        double s = 6 * (Math.sqrt(1 + 2 * curve[0]) - 1);
        double[] k = new double[4];
        for (int i = 0; i < 4; i++) k[i] = 2 * ((1 - s) * DENIM_ZERO[i] + s * DENIM_CURVE[0][i]);
        double stiffened = k[0] - k[1] * k[1] / k[2], zero = 2 * DENIM_ZERO[0] - 2 * DENIM_ZERO[1] * DENIM_ZERO[1] / DENIM_ZERO[2];
        double expected = zero / stiffened, ratio = curve[0] / linear[0];
        System.out.printf("strain ratio %.4f, the moduli's at the mean strain %.4f%n", ratio, expected);
        // Within 1.5 points: the strain runs from twice the mean at the pins to none at the hem, and the secant with it.
        assertTrue(Math.abs(ratio - expected) < 0.015, "ratio " + ratio + ", expected " + expected);
        assertTrue(ratio < 0.97, "the curve must be felt: ratio " + ratio);
    }
}
