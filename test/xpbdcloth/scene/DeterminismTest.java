package xpbdcloth.scene;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.Simulation;

/** Same scene, same parameters: bitwise-identical positions, also across a mid-run mode switch. */
@Tag("slow")
class DeterminismTest {
    static double[] run(String scene, boolean switchModes) {
        Simulation sim = Scene.builtIn(scene).simulation();
        for (int s = 0; s < 1000; s++) {
            if (switchModes && s == 300) sim.settings(sim.settings().withMode(ConstraintMode.PBD));
            if (switchModes && s == 600) sim.settings(sim.settings().withMode(ConstraintMode.XPBD));
            sim.step();
        }
        return sim.particles().positions().clone();
    }

    @Test
    void sameRunSameBits() {
        for (String scene : new String[] {"sphere-pass", "rope"}) {
            assertArrayEquals(run(scene, false), run(scene, false), 0.0, scene);
            assertArrayEquals(run(scene, true), run(scene, true), 0.0, scene + " with PBD/XPBD switches");
        }
    }

    /** A hash of the state after 1000 steps of the corners scene, printed so a change in the bits shows up in review. */
    @Test
    void cornersHashIsStableWithinARun() {
        double[] a = run("corners", true), b = run("corners", true);
        assertEquals(java.util.Arrays.hashCode(a), java.util.Arrays.hashCode(b));
        System.out.printf("corners after 1000 steps with mode switches: state hash %08x%n", java.util.Arrays.hashCode(a));
    }
}
