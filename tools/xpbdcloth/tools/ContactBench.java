package xpbdcloth.tools;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.util.Locale;
import xpbdcloth.engine.Simulation;
import xpbdcloth.mesh.TriangleIntersections;
import xpbdcloth.scene.PresetLoader;
import xpbdcloth.scene.Scene;

/**
 * What the scenes with contacts cost: {@code drop-fold} (a spring cloth lowered onto the floor and folded
 * over itself, Gauss–Seidel 4 × 10) at N = 32, 64, 128 with self-collision off and on, and
 * {@code denim-fold} (measured denim, vertex block descent 2 × 10) at 64² and 128² on one and two threads.
 * Each runs the scene's whole motion, 8 s (400 steps): the fold and the rest after it. Per step, averaged
 * over the run: the whole step, the contact stage (finding the contacts and projecting them) and the
 * solve; bytes allocated per step over the last 100 steps (arrays have grown by then); and the most
 * vertex-disjoint triangle pairs crossing each other in any step. Last, drop-fold and denim-fold at 64² with
 * self-collision's continuous triangle guard ({@code self} = continuous), then with particle pairs and the
 * untangler ({@code self} = untangle), then with particle pairs and point–triangle contacts
 * ({@code self} = point-triangle).
 *
 * <p>The cloth keeps the scene's size (1 m), so its spacing shrinks with N: the thickness is the scene's
 * or 0.9 of the spacing, whichever is less, and the floor's margin 5 mm or 0.45 of the spacing (both must
 * fit the spacing, see the preset loader). Printed as CSV after {@code gradle bench -Pfull}'s other cases:
 * {@code case,n,threads,self,ms_per_step,contact_ms,solve_ms,alloc_bytes_per_step,max_crossing_pairs}.
 */
final class ContactBench {
    private ContactBench() {}

    /**
     * Self-collision in a row: none, particle pairs, pairs and the continuous guard, pairs and the untangler,
     * pairs and point–triangle contacts (the self column).
     */
    enum Self {
        OFF("off"), PAIRS("on"), CONTINUOUS("continuous"), UNTANGLE("untangle"), POINT_TRIANGLE("point-triangle");
        final String column;
        Self(String column) { this.column = column; }
    }

    static final String HEADER = "case,n,threads,self,ms_per_step,contact_ms,solve_ms,alloc_bytes_per_step,max_crossing_pairs";
    static final int STEPS = 400, STEADY = 100;

    static void run() {
        System.out.println(HEADER);
        // One run first so the timed ones are compiled code.
        measure("denim-fold", 32, Self.PAIRS, 1);
        for (int n : new int[] {32, 64, 128}) {
            System.out.println(measure("drop-fold", n, Self.OFF, 1));
            System.out.println(measure("drop-fold", n, Self.PAIRS, 1));
        }
        for (int n : new int[] {64, 128})
            for (int threads : new int[] {1, 2}) System.out.println(measure("denim-fold", n, Self.PAIRS, threads));
        // The continuous triangle guard on the same scenes (opt-in: several times the step).
        System.out.println(measure("drop-fold", 64, Self.CONTINUOUS, 1));
        for (int threads : new int[] {1, 2}) System.out.println(measure("denim-fold", 64, Self.CONTINUOUS, threads));
        // Particle pairs with the untangler (opt-in): what is crossed at a step's end is put back.
        System.out.println(measure("drop-fold", 64, Self.UNTANGLE, 1));
        System.out.println(measure("denim-fold", 64, Self.UNTANGLE, 1));
        // Particle pairs with point–triangle contacts (opt-in): each vertex kept from the faces too.
        System.out.println(measure("drop-fold", 64, Self.POINT_TRIANGLE, 1));
        System.out.println(measure("denim-fold", 64, Self.POINT_TRIANGLE, 1));
    }

    /** One row: the scene at N × N with the given self-collision, on the given threads. */
    static String measure(String name, int n, Self self, int threads) {
        Scene scene = scene(name, n, self);
        Simulation sim = scene.simulation();
        sim.settings(sim.settings().withThreads(threads));
        int[] triangles = scene.cloth().triangles();
        com.sun.management.ThreadMXBean bean = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        double total = 0, contact = 0, solve = 0;
        long alloc = 0;
        int worst = 0;
        for (int step = 0; step < STEPS; step++) {
            long a0 = bean.getCurrentThreadAllocatedBytes(), t0 = System.nanoTime();
            sim.step();
            total += (System.nanoTime() - t0) / 1e6;
            if (step >= STEPS - STEADY) alloc += bean.getCurrentThreadAllocatedBytes() - a0;
            contact += sim.profile().contactMs();
            solve += sim.profile().constraintSolveMs();
            worst = Math.max(worst, TriangleIntersections.count(sim.particles().positions(), triangles));
        }
        sim.close();
        return String.format(Locale.ROOT, "%s,%d,%d,%s,%.2f,%.2f,%.2f,%d,%d", name, n, threads, self.column,
                total / STEPS, contact / STEPS, solve / STEPS, alloc / STEADY, worst);
    }

    /** The built-in preset at N × N, its thickness and margin fitted to the spacing, with the given self-collision. */
    static Scene scene(String name, int n, Self self) {
        try {
            ObjectMapper json = new ObjectMapper();
            ObjectNode root = (ObjectNode) json.readTree(PresetLoader.text(name));
            double spacing = 1.0 / (n - 1);
            ObjectNode cloth = (ObjectNode) root.get("cloth");
            cloth.put("columns", n).put("rows", n);
            ObjectNode floor = (ObjectNode) root.get("colliders").get(0);
            floor.put("margin", Math.min(floor.get("margin").asDouble(), 0.45 * spacing));
            ObjectNode sc = (ObjectNode) root.get("selfCollision");
            if (self != Self.OFF) sc.put("thickness", Math.min(sc.get("thickness").asDouble(), 0.9 * spacing))
                    .put("continuous", self == Self.CONTINUOUS).put("untangle", self == Self.UNTANGLE)
                    .put("pointTriangle", self == Self.POINT_TRIANGLE);
            else root.remove("selfCollision");
            return Scene.of(PresetLoader.parse(name + " at " + n + "²", json.writeValueAsString(root)));
        } catch (IOException e) {
            throw new IllegalStateException("the built-in " + name + " preset cannot be read", e);
        }
    }
}
