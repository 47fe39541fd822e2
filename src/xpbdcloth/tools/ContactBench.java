package xpbdcloth.tools;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.InputStream;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.util.Locale;
import xpbdcloth.engine.Simulation;
import xpbdcloth.mesh.TriangleIntersections;
import xpbdcloth.scene.PresetLoader;
import xpbdcloth.scene.Scene;

/**
 * What contacts cost: the {@code drop-fold} scene (the cloth lowered onto the floor and folded over
 * itself, 5 s, 250 steps of its 4 × 10 sweeps) at N = 32, 64 and 128, with self-collision off and on,
 * and on at a hash rebuilt every 1, 2 and 5 substeps. Per step, averaged over the run: the whole step,
 * the contact stage (hash, self-collision pairs and collider contacts found, then projected in every
 * sweep) and the cloth's own constraint solve; bytes allocated per step over the last 100 steps (arrays
 * have grown by then); and the most vertex-disjoint triangle pairs crossing each other in any step.
 *
 * <p>The cloth keeps the scene's size (1 m), so its spacing shrinks with N: the thickness is the scene's
 * 2 cm or 0.9 of the spacing, whichever is less, and the floor's margin 5 mm or 0.45 of the spacing
 * (both must fit the spacing, see the preset loader). Printed as CSV after {@code gradle bench -Pfull}'s
 * other cases: {@code case,n,self,rebuild_every,ms_per_step,contact_ms,constraint_ms,alloc_bytes_per_step,max_crossing_pairs}.
 */
final class ContactBench {
    private ContactBench() {}

    static final String HEADER = "case,n,self,rebuild_every,ms_per_step,contact_ms,constraint_ms,alloc_bytes_per_step,max_crossing_pairs";
    static final int STEPS = 250, STEADY = 100;

    static void run() {
        System.out.println(HEADER);
        // One run first so the timed ones are compiled code.
        measure(32, true, 1);
        for (int n : new int[] {32, 64, 128}) {
            System.out.println(measure(n, false, 1));
            System.out.println(measure(n, true, 1));
        }
        for (int every : new int[] {2, 5}) System.out.println(measure(64, true, every));
    }

    static String measure(int n, boolean self, int rebuildEvery) {
        Scene scene = dropFold(n, self, rebuildEvery);
        Simulation sim = scene.simulation();
        int[] triangles = scene.cloth().triangles();
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        double total = 0, contact = 0, constraint = 0;
        long alloc = 0;
        int worst = 0;
        for (int step = 0; step < STEPS; step++) {
            long a0 = threads.getCurrentThreadAllocatedBytes(), t0 = System.nanoTime();
            sim.step();
            total += (System.nanoTime() - t0) / 1e6;
            if (step >= STEPS - STEADY) alloc += threads.getCurrentThreadAllocatedBytes() - a0;
            contact += sim.contactMs();
            constraint += sim.constraintSolveMs();
            worst = Math.max(worst, TriangleIntersections.count(sim.particles().positions(), triangles));
        }
        sim.close();
        return String.format(Locale.ROOT, "drop-fold,%d,%s,%d,%.2f,%.2f,%.2f,%d,%d", n, self ? "on" : "off", self ? rebuildEvery : 0,
                total / STEPS, contact / STEPS, constraint / STEPS, alloc / STEADY, worst);
    }

    /** The drop-fold preset at N × N, its thickness and margin fitted to the spacing. */
    static Scene dropFold(int n, boolean self, int rebuildEvery) {
        try (InputStream in = PresetLoader.class.getResourceAsStream("/presets/drop-fold.json")) {
            ObjectMapper json = new ObjectMapper();
            ObjectNode root = (ObjectNode) json.readTree(new String(in.readAllBytes(), StandardCharsets.UTF_8));
            double spacing = 1.0 / (n - 1);
            ObjectNode cloth = (ObjectNode) root.get("cloth");
            cloth.put("columns", n).put("rows", n);
            ((ObjectNode) root.get("colliders").get(0)).put("margin", Math.min(0.005, 0.45 * spacing));
            ObjectNode sc = (ObjectNode) root.get("selfCollision");
            if (self) sc.put("thickness", Math.min(0.02, 0.9 * spacing)).put("rebuildEvery", rebuildEvery);
            else root.remove("selfCollision");
            return Scene.of(PresetLoader.parse("drop-fold at " + n + "²", json.writeValueAsString(root)));
        } catch (IOException e) {
            throw new IllegalStateException("the built-in drop-fold preset cannot be read", e);
        }
    }
}
