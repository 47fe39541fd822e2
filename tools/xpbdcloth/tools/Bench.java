package xpbdcloth.tools;

import java.lang.management.ManagementFactory;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.ConstraintOrder;
import xpbdcloth.engine.DistanceBlock;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SolverSettings;
import xpbdcloth.engine.SolverType;
import xpbdcloth.engine.Sphere;
import xpbdcloth.engine.SpherePath;

/**
 * The benchmark behind {@code gradle bench}: an N×N grid of structural distance constraints (two top
 * corners pinned, 1 cm spacing, 0.1 g per particle, XPBD α = 1e-7 m/N, g = 9.81 m/s², dt = 1/60 s,
 * 10 iterations, no substeps) for N = 32, 64, 128 on one thread, in the engine's coloured order (see
 * {@link ConstraintOrder}). Prints CSV and nothing else on stdout:
 * {@code n,particles,constraints,ms_per_step,projections_per_s,alloc_bytes_per_step}.
 *
 * <p>{@code --full} prints the same columns after a first column {@code case}: the row-major order, the
 * Ten Minute Physics workload (15 substeps × 1 iteration, stretch + bending distance constraints), all
 * families with a sphere, the fabric (membrane, bending, tethers; Gauss–Seidel, then vertex block descent), N = 256, the coloured solve on
 * 1 and 2 threads, and the `hanging` scene under each solver; memory per particle and
 * per constraint goes to stderr. Then the contact cases of {@link ContactBench}, under their own header.
 *
 * <p>Timing is a warmed-up loop: at least 2 s and 500 steps of warm-up, then at least 3 s measured; allocation is
 * measured over the same steady-state steps with the JVM's per-thread allocation counter (helper
 * threads of the parallel solve allocate nothing either: they are made during warm-up).
 */
public final class Bench {
    private Bench() {}

    static final String HEADER = "n,particles,constraints,ms_per_step,projections_per_s,alloc_bytes_per_step";

    public static void main(String[] args) {
        boolean full = args.length > 0 && args[0].equals("--full");
        if (!full) {
            System.out.println(HEADER);
            for (int n : new int[] {32, 64, 128}) System.out.println(row(grid(n, ConstraintOrder.COLOURED, 1)));
            return;
        }
        System.out.println("case," + HEADER);
        for (int n : new int[] {32, 64, 128, 256}) System.out.println("coloured," + row(grid(n, ConstraintOrder.COLOURED, 1)));
        for (int n : new int[] {32, 64, 128, 256}) System.out.println("row-major," + row(grid(n, ConstraintOrder.AS_BUILT, 1)));
        for (int n : new int[] {32, 64, 128}) System.out.println("ten-minute-physics," + row(tenMinutePhysics(n)));
        for (int n : new int[] {32, 64, 128}) System.out.println("all-families-sphere," + row(allFamilies(n, 1)));
        System.out.println("all-families-sphere-2-threads," + row(allFamilies(64, 2)));
        for (int n : new int[] {32, 64, 128}) System.out.println("fabric," + row(fabric(n)));
        for (int n : new int[] {64, 128}) System.out.println("fabric-vertex-block-descent," + row(fabricDescent(n)));
        for (int t : new int[] {1, 2}) System.out.println("parallel-" + t + "-threads," + row(grid(128, ConstraintOrder.COLOURED, t)));
        for (int t : new int[] {1, 2}) System.out.println("parallel-" + t + "-threads," + row(grid(256, ConstraintOrder.COLOURED, t)));
        for (SolverType type : SolverType.values()) System.out.println("hanging-" + type.name().toLowerCase(Locale.ROOT).replace('_', '-') + "," + row(hanging(type)));
        memory();
        ContactBench.run();
    }

    static Simulation grid(int n, ConstraintOrder order, int threads) {
        Cloth cloth = new ClothBuilder().resolution(n, n).size(0.01 * (n - 1), 0.01 * (n - 1))
                .family(ConstraintFamily.STRUCTURAL, 1.0, 1e-7).pinTopCorners().build();
        Particles p = cloth.particles();
        for (int i = 0; i < p.count(); i++) p.setMass(i, 1e-4);
        SolverSettings s = new SolverSettings().withMode(ConstraintMode.XPBD).withIterations(10).withSubsteps(1)
                .withTimestep(1 / 60.0).withGravity(0, -9.81, 0).withOrder(order).withThreads(threads);
        return cloth.simulation(s);
    }

    /**
     * The Ten Minute Physics cloth: stretch constraints on the triangle edges (α = 0) and bending
     * constraints as distances between the opposite vertices of triangle pairs (α = 1 m/N), 15 substeps
     * of 1 iteration. Our grid's triangles differ in diagonal pattern; the constraint counts are the same
     * kind (edges + one bending pair per interior edge).
     */
    static Simulation tenMinutePhysics(int n) {
        Cloth cloth = new ClothBuilder().resolution(n, n).size(0.01 * (n - 1), 0.01 * (n - 1))
                .arealDensity(0.2).pinTopCorners().build();
        Particles p = cloth.particles();
        Simulation sim = new Simulation(p, new SolverSettings().withMode(ConstraintMode.XPBD).withIterations(1).withSubsteps(15)
                .withTimestep(1 / 60.0).withOrder(ConstraintOrder.COLOURED));
        int[] t = cloth.triangles();
        Map<Long, Integer> firstOpposite = new HashMap<>();
        DistanceBlock stretch = new DistanceBlock(ConstraintFamily.STRUCTURAL, t.length / 2); // α = 0
        DistanceBlock bending = new DistanceBlock(ConstraintFamily.BEND, t.length / 2);
        bending.setCompliance(1.0); // α = 1 m/N
        for (int k = 0; k < t.length; k += 3)
            for (int e = 0; e < 3; e++) {
                int a = t[k + e], b = t[k + (e + 1) % 3], opposite = t[k + (e + 2) % 3];
                long key = (long) Math.min(a, b) * p.count() + Math.max(a, b);
                Integer other = firstOpposite.putIfAbsent(key, opposite);
                if (other == null) stretch.addAtCurrentLength(p, a, b);
                else bending.addAtCurrentLength(p, other, opposite);
            }
        sim.add(stretch).add(bending);
        return sim;
    }

    /** All three families (defaults of the hanging scene) and a sphere the cloth hangs against. */
    static Simulation allFamilies(int n, int threads) {
        Cloth cloth = new ClothBuilder().resolution(n, n).size(1, 1).origin(0, 1.6, 0).arealDensity(0.2).pinTopCorners()
                .family(ConstraintFamily.STRUCTURAL, 1, 1e-6).family(ConstraintFamily.SHEAR, 0.5, 1e-3).family(ConstraintFamily.BEND, 0.1, 1e-2).build();
        Simulation sim = cloth.simulation(new SolverSettings().withMode(ConstraintMode.XPBD).withIterations(2).withSubsteps(10)
                .withTimestep(0.02).withOrder(ConstraintOrder.COLOURED).withThreads(threads));
        sim.add(new Sphere(SpherePath.oscillation(0, 1.1, 0.1, 0, 0, 0.15, 0.5), 0.2, 0.01, 0.5, 0.35));
        return sim;
    }

    /**
     * A fabric at N × N: an orthotropic membrane per triangle (three rows, solved together), bending
     * patches on every triangle and tethers to the two pinned corners, Gauss–Seidel 2 × 10 sweeps.
     */
    static Simulation fabric(int n) {
        Cloth cloth = new ClothBuilder().resolution(n, n).size(1, 1).origin(0, 1.6, 0).arealDensity(0.2).pinTopCorners().build();
        Simulation sim = cloth.simulation(new SolverSettings().withMode(ConstraintMode.XPBD).withIterations(2).withSubsteps(10)
                .withTimestep(0.02).withOrder(ConstraintOrder.COLOURED));
        for (xpbdcloth.engine.ConstraintBlock b : xpbdcloth.fabric.FabricConstraints.build(cloth.particles(), cloth.triangles(), new double[] {1, 0, 0},
                new xpbdcloth.engine.OrthotropicMaterial(2000, 800, 0.25, 30), 1e-5, true)) sim.add(b);
        return sim;
    }

    /** The same fabric solved by vertex block descent, 2 × 10, without tethers (it needs none to hold the material). */
    static Simulation fabricDescent(int n) {
        Cloth cloth = new ClothBuilder().resolution(n, n).size(1, 1).origin(0, 1.6, 0).arealDensity(0.2).pinTopCorners().build();
        Simulation sim = cloth.simulation(new SolverSettings().withMode(ConstraintMode.XPBD).withSolver(SolverType.VERTEX_BLOCK_DESCENT).withIterations(2).withSubsteps(10)
                .withTimestep(0.02));
        for (xpbdcloth.engine.ConstraintBlock b : xpbdcloth.fabric.FabricConstraints.build(cloth.particles(), cloth.triangles(), new double[] {1, 0, 0},
                new xpbdcloth.engine.OrthotropicMaterial(2000, 800, 0.25, 30), 1e-5, false)) sim.add(b);
        return sim;
    }

    /** The `hanging` scene as shipped (32², all three families, 10 substeps × 2 iterations), under one solver. */
    static Simulation hanging(SolverType type) {
        Simulation sim = xpbdcloth.scene.Scene.builtIn("hanging").simulation();
        sim.settings(sim.settings().withSolver(type));
        return sim;
    }

    static String row(Simulation sim) {
        int n = (int) Math.round(Math.sqrt(sim.particles().count()));
        int constraints = sim.constraintCount();
        // Build the solve order, then let a full collection compact the new objects: the collector
        // copies them in the order the order array reaches them, which is the order a sweep visits them.
        // Without it the first run of a big grid measures where the allocator happened to put them.
        sim.colourCount();
        System.gc();
        // At least 2 s and 500 steps: a big grid's first seconds are still compiling (and allocating for it).
        long warmEnd = System.nanoTime() + 2_000_000_000L;
        for (int s = 0; s < 500 || System.nanoTime() < warmEnd; s++) sim.step();
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long alloc0 = threads.getCurrentThreadAllocatedBytes();
        long t0 = System.nanoTime();
        long steps = 0;
        long t;
        do {
            for (int k = 0; k < 5; k++) sim.step();
            steps += 5;
            t = System.nanoTime();
        } while (t - t0 < 3_000_000_000L);
        long alloc1 = threads.getCurrentThreadAllocatedBytes();
        sim.close();
        double msPerStep = (t - t0) / 1e6 / steps;
        double projections = (double) constraints * sim.settings().iterations() * sim.settings().substeps();
        return String.format(Locale.ROOT, "%d,%d,%d,%.4f,%.0f,%d", n, sim.particles().count(), constraints,
                msPerStep, projections / (msPerStep / 1000), (alloc1 - alloc0) / steps);
    }

    /** Heap bytes per particle and per constraint, from the heap growth of building big grids (stderr). */
    static void memory() {
        Runtime rt = Runtime.getRuntime();
        System.gc();
        long base = rt.totalMemory() - rt.freeMemory();
        Particles p = new Particles(1_000_000);
        System.gc();
        long afterParticles = rt.totalMemory() - rt.freeMemory();
        // Sized as the cloth builders size their blocks (constraints added one by one grow it by doubling).
        DistanceBlock cs = new DistanceBlock(ConstraintFamily.STRUCTURAL, 1_000_000);
        for (int i = 0; i < 1_000_000; i++) cs.add(i, i + 1, 0.01);
        System.gc();
        long afterConstraints = rt.totalMemory() - rt.freeMemory();
        System.err.printf(Locale.ROOT, "memory: %.0f bytes per particle, %.0f bytes per distance constraint (in its block)%n",
                (afterParticles - base) / 1e6, (afterConstraints - afterParticles) / 1e6);
        if (p.count() + cs.count() == 0) System.err.println();
    }
}
