package xpbdcloth.scene;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.MembraneBlock;
import xpbdcloth.engine.Metrics;
import xpbdcloth.engine.Simulation;

/**
 * The strain the HUD and its plot read measures whatever the cloth is made of: on a fabric scene, the
 * membrane's largest principal stretch less one, √(1 + 2E₁) − 1 with E₁ the larger eigenvalue of each
 * triangle's Green strain tensor, not 0 for want of springs.
 */
class ClothStrainReadoutTest {
    @Test
    void aFabricScenesReadoutIsItsMembranesLargestPrincipalStretch() {
        Scene scene = Scene.of(PresetLoader.builtIn("fabric"));
        Simulation sim = scene.simulation();
        for (int s = 0; s < 25; s++) sim.step();
        double expectedMax = 0, sum = 0;
        int n = 0;
        for (ConstraintBlock b : sim.blocks())
            if (b instanceof MembraneBlock) {
                MembraneBlock m = (MembraneBlock) b;
                for (int t = 0; t < m.triangleCount(); t++, n++) {
                    double[] e = m.strain(t, sim.particles()); // E_uu, E_vv, γ = 2 E_uv
                    double mean = 0.5 * (e[0] + e[1]), half = 0.5 * (e[0] - e[1]);
                    double e1 = mean + Math.sqrt(half * half + 0.25 * e[2] * e[2]);
                    double stretch = Math.sqrt(1 + 2 * e1) - 1;
                    expectedMax = Math.max(expectedMax, Math.abs(stretch));
                    sum += stretch;
                }
            }
        assertTrue(n > 0, "the fabric scene has membrane triangles");
        assertTrue(expectedMax > 1e-3, "the hanging denim visibly stretches somewhere: " + expectedMax);
        assertEquals(expectedMax, Metrics.maxClothStrain(sim), 1e-12);
        assertEquals(sum / n, Metrics.meanClothStrain(sim), 1e-12);
    }

    @Test
    void aSpringClothStillReadsItsStructuralSprings() {
        Scene scene = Scene.of(PresetLoader.builtIn("hanging"));
        Simulation sim = scene.simulation();
        for (int s = 0; s < 10; s++) sim.step();
        assertEquals(Metrics.maxStrain(sim, xpbdcloth.engine.ConstraintFamily.STRUCTURAL), Metrics.maxClothStrain(sim), 0.0);
        assertTrue(Metrics.maxClothStrain(sim) > 1e-3);
    }
}
