package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/** What the shear and bend families add to a cloth, measured. */
class ShearBendTest {

    /** Largest |θ − π/2| over the grid's row/column corners. */
    static double worstCornerAngleError(Cloth cloth) {
        Particles p = cloth.particles();
        double worst = 0;
        for (int r = 0; r + 1 < cloth.rows(); r++)
            for (int c = 0; c + 1 < cloth.columns(); c++) {
                int i = cloth.index(r, c);
                ShearConstraint probe = new ShearConstraint(ConstraintFamily.SHEAR, i, i + 1, i + cloth.columns(), Math.PI / 2);
                worst = Math.max(worst, Math.abs(probe.evaluate(p)));
            }
        return worst;
    }

    /**
     * A vertical 10×10 patch with its top row pinned, pushed sideways at its bottom row, no gravity.
     * Structural edges alone let every quad shear into a rhombus (they keep lengths, not angles), so
     * the patch leans over; stiff shear constraints keep every corner near 90°.
     */
    static double shearedAngleError(boolean withShear, ConstraintMode mode) {
        ClothBuilder b = new ClothBuilder().resolution(10, 10).size(0.5, 0.5).arealDensity(0.2)
                .family(ConstraintFamily.STRUCTURAL, 1, 1e-8);
        if (withShear) b.family(ConstraintFamily.SHEAR, 1, 1e-7);
        for (int c = 0; c < 10; c++) b.pin(0, c);
        Cloth cloth = b.build();
        Simulation sim = cloth.simulation(new SolverSettings().withMode(mode).withGravity(0, 0, 0).withIterations(10).withSubsteps(4));
        for (int s = 0; s < 300; s++) {
            for (int c = 0; c < 10; c++) cloth.particles().addForce(cloth.index(9, c), 0.02, 0, 0);
            sim.step();
        }
        return worstCornerAngleError(cloth);
    }

    @Test
    void shearKeepsCornerAnglesUnderShearingLoad() {
        for (ConstraintMode mode : ConstraintMode.values()) {
            double with = shearedAngleError(true, mode), without = shearedAngleError(false, mode);
            System.out.printf("%s shear load: worst corner angle error with shear %.4f rad, without %.4f rad%n", mode, with, without);
            assertTrue(with < 0.05, mode + ": with shear constraints corners stay within 0.05 rad of 90°, was " + with);
            assertTrue(without > 0.3, mode + ": without them the patch shears by more than 0.3 rad, was " + without);
        }
    }

    /**
     * Tip droop (m) of a 10×2 horizontal strip, 18 cm long, clamped by its first two columns, after 20 s
     * (settled). Without bending it hangs almost straight down from the clamp (droop ≈ 0.16 m).
     */
    static double cantileverDroop(boolean withBend, int iterations) {
        ClothBuilder b = new ClothBuilder().resolution(10, 2).size(0.18, 0.02).plane(ClothBuilder.Plane.HORIZONTAL)
                .arealDensity(0.2).family(ConstraintFamily.STRUCTURAL, 1, 1e-5);
        if (withBend) b.family(ConstraintFamily.BEND, 1, 0.1);
        for (int r = 0; r < 2; r++) { b.pin(r, 0); b.pin(r, 1); }
        Cloth cloth = b.build();
        Simulation sim = cloth.simulation(new SolverSettings().withMode(ConstraintMode.XPBD).withIterations(iterations).withTimestep(1 / 60.0));
        for (int s = 0; s < 1200; s++) sim.step();
        return -cloth.particles().y(cloth.index(1, 9));
    }

    /**
     * Bending holds the strip up, and once Gauss–Seidel has converged the XPBD droop no longer depends on
     * the iteration count (n = 100 vs 200 within 2 %). Below convergence it does (n = 5 droops more):
     * XPBD removes the coupling of stiffness and iterations only for a converged solve, which the
     * experiments command shows in full.
     */
    @Test
    void bendingHoldsACantileverUpIndependentlyOfIterations() {
        double off = cantileverDroop(false, 100);
        double on5 = cantileverDroop(true, 5), on100 = cantileverDroop(true, 100), on200 = cantileverDroop(true, 200);
        System.out.printf("cantilever tip droop: bend off %.4f m; bend on n=5 %.4f, n=100 %.4f, n=200 %.4f m%n", off, on5, on100, on200);
        assertTrue(off > 0.15, "without bending the strip hangs down, droop " + off);
        assertTrue(on100 < 0.8 * off, "bending holds the tip up by over 20 %: " + on100 + " vs " + off);
        assertEquals(on200, on100, 0.02 * on200, "XPBD droop independent of n once converged");
        assertTrue(on5 > on100, "unconverged (n=5) droops more");
    }
}
