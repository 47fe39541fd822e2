package xpbdcloth.fabric;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.OrthotropicMaterial;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SolverSettings;
import xpbdcloth.engine.TetherBlock;

/**
 * Tethers (Kim et al. 2012): every free particle of a cloth hung by its top edge stays within its rest
 * distance along the mesh from its nearest pin, however few sweeps the membrane gets; without them a
 * long cloth's bottom sags past it.
 */
class TetherTest {
    static double worstOverstretch(boolean tethers) {
        int n = 40;
        ClothBuilder b = new ClothBuilder().resolution(n, n).size(1, 1).origin(0, 2, 0).arealDensity(0.2);
        for (int c = 0; c < n; c++) b.pin(0, c);
        Cloth cloth = b.build();
        Particles p = cloth.particles();
        Simulation sim = new Simulation(p, new SolverSettings().withMode(ConstraintMode.XPBD).withIterations(2).withSubsteps(2).withTimestep(0.02).withGravity(0, -9.81, 0));
        TetherBlock rest = null;
        for (ConstraintBlock block : FabricConstraints.build(p, cloth.triangles(), new double[] {1, 0, 0},
                new OrthotropicMaterial(500, 500, 0.3, 50), 1e-5, true)) {
            if (block instanceof TetherBlock) { rest = (TetherBlock) block; if (!tethers) continue; }
            sim.add(block);
        }
        // Each tether's length after 2 s, against its rest distance: the anchors are the top row.
        double worst = Double.NEGATIVE_INFINITY;
        for (int s = 0; s < 100; s++) sim.step();
        for (int i = 0; i < rest.count(); i++) {
            int a = rest.particle(i, 0), f = rest.particle(i, 1);
            double dx = p.x(f) - p.x(a), dy = p.y(f) - p.y(a), dz = p.z(f) - p.z(a);
            worst = Math.max(worst, Math.sqrt(dx * dx + dy * dy + dz * dz) - rest.restDistance(i));
        }
        assertEquals(n * (n - 1), rest.count(), "one tether per free particle");
        return worst;
    }

    @Test
    void noParticleHangsFartherThanItsRestDistanceFromItsPin() {
        double with = worstOverstretch(true), without = worstOverstretch(false);
        assertTrue(with <= 1e-9, "largest stretch past the rest distance with tethers: " + with + " m");
        assertTrue(without > 0.01, "without tethers the bottom sags past it (" + without + " m): the test can tell");
    }
}
