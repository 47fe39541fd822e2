package xpbdcloth.scene;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Hot loops allocate nothing: every shipped scene, wind switched on, allocates (next to) no bytes per
 * step once warmed up. Counted with the JVM's exact per-thread allocation counter, not timed. The
 * benchmark covers bare grids; this covers what scenes add: wind, pin scripts, spheres, meshes. (A
 * validation that built its parameter names on every call once made the flag allocate 44 kB a step.)
 */
@Tag("slow")
class AllocationTest {
    @Test
    void everySceneStepsWithoutAllocating() {
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        StringBuilder report = new StringBuilder();
        for (String name : PresetLoader.BUILT_IN) {
            Scene s = Scene.builtIn(name);
            s.setWind(true);
            for (int i = 0; i < 300; i++) s.simulation().step();
            // The smaller of two windows: a one-time event on this thread (the JIT recompiling the step can make it
            // load a class it had not needed yet, tens of kB once) is not an allocation per step; one per step shows in both.
            double perStep = Double.MAX_VALUE;
            for (int window = 0; window < 2; window++) {
                long before = threads.getCurrentThreadAllocatedBytes();
                for (int i = 0; i < 100; i++) s.simulation().step();
                perStep = Math.min(perStep, (threads.getCurrentThreadAllocatedBytes() - before) / 100.0);
            }
            report.append(String.format(java.util.Locale.ROOT, "%s %.1f B/step; ", name, perStep));
            assertTrue(perStep < 16, name + " allocates " + perStep + " bytes per step");
        }
        System.out.println(report);
    }
}
