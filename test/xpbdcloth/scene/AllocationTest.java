package xpbdcloth.scene;

import static org.junit.jupiter.api.Assertions.*;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import xpbdcloth.TwoAtATime;

/**
 * Hot loops allocate nothing: every shipped scene, wind switched on, allocates (next to) no bytes per
 * step once warmed up. Counted with the JVM's exact per-thread allocation counter, not timed. The
 * benchmark covers bare grids; this covers what scenes add: wind, pin scripts, spheres, meshes. (A
 * validation that built its parameter names on every call once made the flag allocate 44 kB a step.)
 */
@Tag("slow")
class AllocationTest {
    @Test
    void everySceneStepsWithoutAllocating() throws Exception {
        // Each scene counted on the thread that steps it (the counter is per thread), two scenes at a time.
        List<Callable<Double>> scenes = new ArrayList<>();
        for (String name : PresetLoader.BUILT_IN) scenes.add(() -> bytesPerStep(name));
        List<Double> counts = TwoAtATime.results(scenes);
        StringBuilder report = new StringBuilder();
        List<String> failures = new ArrayList<>();
        for (int k = 0; k < counts.size(); k++) {
            String name = PresetLoader.BUILT_IN.get(k);
            double perStep = counts.get(k);
            report.append(String.format(java.util.Locale.ROOT, "%s %.1f B/step; ", name, perStep));
            if (!(perStep < 16)) failures.add(name + " allocates " + perStep + " bytes per step");
        }
        System.out.println(report);
        assertTrue(failures.isEmpty(), String.join("; ", failures));
    }

    /** Bytes a step of the shipped scene allocates on this thread once warmed up, wind on. */
    private static double bytesPerStep(String name) {
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        Scene s = Scene.builtIn(name);
        s.setWind(true);
        // 150 steps: the step's code is compiled by then, and the garments have closed their seams (by step 75).
        for (int i = 0; i < 150; i++) s.simulation().step();
        // The smaller of two windows: a one-time event on this thread (the JIT recompiling the step can make it
        // load a class it had not needed yet, tens of kB once) is not an allocation per step; one per step shows in both.
        double perStep = Double.MAX_VALUE;
        for (int window = 0; window < 2; window++) {
            long before = threads.getCurrentThreadAllocatedBytes();
            for (int i = 0; i < 50; i++) s.simulation().step();
            perStep = Math.min(perStep, (threads.getCurrentThreadAllocatedBytes() - before) / 50.0);
        }
        s.simulation().close();
        return perStep;
    }
}
