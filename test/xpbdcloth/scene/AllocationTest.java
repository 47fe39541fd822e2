package xpbdcloth.scene;

import static org.junit.jupiter.api.Assertions.*;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import xpbdcloth.TwoAtATime;

/**
 * Hot loops allocate nothing: every shipped scene, wind switched on, allocates nothing in all but a few
 * steps once warmed up (a list grown to a new largest size, a one-time event). Counted step by step with the
 * JVM's exact per-thread allocation counter, not timed. The
 * benchmark covers bare grids; this covers what scenes add: wind, pin scripts, spheres, meshes. (A
 * validation that built its parameter names on every call once made the flag allocate 44 kB a step.)
 */
@Tag("slow")
class AllocationTest {
    @Test
    void everySceneStepsWithoutAllocating() throws Exception {
        // Each scene counted on the thread that steps it (the counter is per thread), two scenes at a time.
        List<Callable<long[]>> scenes = new ArrayList<>();
        for (String name : PresetLoader.BUILT_IN) scenes.add(() -> allocatingSteps(name));
        List<long[]> counts = TwoAtATime.results(scenes);
        StringBuilder report = new StringBuilder();
        List<String> failures = new ArrayList<>();
        for (int k = 0; k < counts.size(); k++) {
            String name = PresetLoader.BUILT_IN.get(k);
            long steps = counts.get(k)[0], bytes = counts.get(k)[1];
            report.append(String.format(java.util.Locale.ROOT, "%s %d of %d steps, %d B; ", name, steps, WATCHED, bytes));
            if (steps > ALLOCATING) failures.add(name + " allocates in " + steps + " of " + WATCHED + " steps, " + bytes + " bytes in all");
        }
        System.out.println(report);
        assertTrue(failures.isEmpty(), String.join("; ", failures));
    }

    /** Steps watched after the warm-up, and how many of them may allocate at all. */
    static final int WATCHED = 100, ALLOCATING = 5;

    /**
     * How many of {@link #WATCHED} steps of the shipped scene allocate on this thread once warmed up, wind on,
     * and the bytes they allocate. An allocation
     * in a hot loop shows in every step (or every few); what may show in a few is a one-time event (the JIT
     * recompiling the step can load a class it had not needed yet, tens of kB once) or a list doubling its
     * capacity when a new largest count of contacts or candidates needs it (the crossing guard's, while the
     * garment on the turning body is carried into new places).
     */
    private static long[] allocatingSteps(String name) {
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        Scene s = Scene.builtIn(name);
        s.setWind(true);
        // 150 steps: the step's code is compiled by then, and the garments have closed their seams (by step 75).
        for (int i = 0; i < 150; i++) s.simulation().step();
        int allocating = 0;
        long bytes = 0;
        for (int i = 0; i < WATCHED; i++) {
            long before = threads.getCurrentThreadAllocatedBytes();
            s.simulation().step();
            long step = threads.getCurrentThreadAllocatedBytes() - before;
            if (step > 0) { allocating++; bytes += step; }
        }
        s.simulation().close();
        return new long[] {allocating, bytes};
    }
}
