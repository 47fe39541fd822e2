package xpbdcloth.scene;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;
import xpbdcloth.engine.Metrics;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;

/**
 * No jitter on a box: the shipped `table` scene (a round tablecloth dropped on a square table, at its own
 * settings) comes to rest in 10 s, and never enters the table.
 */
class RestingContactTest {
    @Test
    void aTableclothDrapedOnATableComesToRest() {
        Scene scene = Scene.builtIn("table");
        Simulation sim = scene.simulation();
        Particles p = scene.cloth().particles();
        double[] before = null;
        double deepest = 0; // how far inside the table top's margin any particle over the table went
        for (int step = 1; step <= 500; step++) {
            sim.step();
            if (step == 450) before = p.positions().clone();
            for (int i = 0; i < p.count(); i++)
                if (Math.abs(p.x(i)) < 0.35 && Math.abs(p.z(i)) < 0.35) deepest = Math.max(deepest, 0.76 - p.y(i));
        }
        double moved = 0;
        double[] x = p.positions();
        for (int k = 0; k < x.length; k += 3)
            moved = Math.max(moved, Math.sqrt((x[k] - before[k]) * (x[k] - before[k]) + (x[k + 1] - before[k + 1]) * (x[k + 1] - before[k + 1]) + (x[k + 2] - before[k + 2]) * (x[k + 2] - before[k + 2])));
        double ke = Metrics.kineticEnergy(p);
        System.out.printf("table after 10 s: kinetic energy %.3e J, largest motion in the last second %.3e m, deepest below the top's margin %.2e m%n", ke, moved, deepest);
        assertTrue(ke < 1e-6, "at rest: " + ke + " J");
        assertTrue(moved < 1e-4, "no particle moves more than 0.1 mm in the last second: " + moved + " m");
        assertTrue(deepest < 1e-3, "never into the table top: " + deepest + " m");
    }
}
