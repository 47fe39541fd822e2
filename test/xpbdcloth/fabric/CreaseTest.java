package xpbdcloth.fabric;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.HingePlasticity;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SolverSettings;

/**
 * A fabric strip folded by 180° over a band of its length, held, and let go: with bending that yields, it keeps
 * the crease the yield model gives, the fold less κ_y times the band's width (each folded hinge springs back by
 * its yield angle κ_y w, and the band's hinges' widths add up to its length); below the yield it returns flat.
 */
class CreaseTest {
    static final int COLUMNS = 41, ROWS = 3, FOLDED = 10;
    static final double SPACING = 0.005;

    /** The crease left after a fold held for 0.5 s and 4 s of letting go, rad (π − the angle between the strip's two ends). */
    static double creaseAfterFold(double yieldCurvature, double rate) {
        Cloth strip = new ClothBuilder().resolution(COLUMNS, ROWS).size((COLUMNS - 1) * SPACING, (ROWS - 1) * SPACING)
                .plane(ClothBuilder.Plane.HORIZONTAL).arealDensity(0.2).build();
        Particles p = strip.particles();
        Simulation sim = new Simulation(p, new SolverSettings().withMode(ConstraintMode.XPBD).withIterations(10).withSubsteps(10)
                .withTimestep(0.01).withGravity(0, 0, 0).withDamping(5));
        double[] up = {1, 0, 0};
        for (ConstraintBlock b : FabricConstraints.build(p, strip.triangles(), up, FabricConstraintMathsTest.FABRIC, 1e-3, false, true)) sim.add(b);
        sim.add(new HingePlasticity(sim.blocks(), p, yieldCurvature, rate));
        // Fold: the strip's centre line turns by π/FOLDED at each of FOLDED columns in its middle, about lines along z.
        int first = (COLUMNS - FOLDED) / 2;
        double heading = 0, x = 0, y = 0;
        for (int c = 0; c < COLUMNS; c++) {
            for (int r = 0; r < ROWS; r++) {
                int i = strip.index(r, c);
                p.setPosition(i, x, y, p.z(i));
                p.pin(i);
            }
            if (c >= first && c < first + FOLDED) heading += Math.PI / FOLDED;
            x += SPACING * Math.cos(heading);
            y += SPACING * Math.sin(heading);
        }
        for (int s = 0; s < 50; s++) sim.step();
        for (int i = 0; i < p.count(); i++) p.unpin(i);
        for (int s = 0; s < 400; s++) sim.step();
        int mid = ROWS / 2;
        double[] a = direction(p, strip.index(mid, 0), strip.index(mid, 1)), b = direction(p, strip.index(mid, COLUMNS - 2), strip.index(mid, COLUMNS - 1));
        return Math.acos(Math.max(-1, Math.min(1, a[0] * b[0] + a[1] * b[1] + a[2] * b[2])));
    }

    static double[] direction(Particles p, int from, int to) {
        double dx = p.x(to) - p.x(from), dy = p.y(to) - p.y(from), dz = p.z(to) - p.z(from), l = Math.sqrt(dx * dx + dy * dy + dz * dz);
        return new double[] {dx / l, dy / l, dz / l};
    }

    @Test
    void aFoldHeldPastTheYieldKeepsTheFoldLessTheYieldsSpringBack() {
        double yieldCurvature = 20;
        // Held 0.5 s at r = 50/s (e^(−25) of the overstress left): each folded hinge's rest is its fold less κ_y w.
        double expected = Math.PI - yieldCurvature * FOLDED * SPACING;
        double crease = creaseAfterFold(yieldCurvature, 50);
        System.out.printf("crease %.4f rad, the yield model's %.4f (%.2f %%)%n", crease, expected, 100 * (crease / expected - 1));
        assertEquals(expected, crease, 0.01 * expected);
    }

    @Test
    void aFoldBelowTheYieldReturnsFlat() {
        // κ_y = 80/m: θ_y = 0.4 rad, above each folded hinge's π/10.
        double crease = creaseAfterFold(80, 50);
        System.out.printf("crease below the yield %.5f rad%n", crease);
        assertTrue(crease < 0.01, "crease " + crease);
    }
}
