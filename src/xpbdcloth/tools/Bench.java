package xpbdcloth.tools;

import java.lang.management.ManagementFactory;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SolverSettings;

/**
 * The benchmark behind {@code gradle bench}: an N×N grid of structural distance constraints (two top
 * corners pinned, 1 cm spacing, 0.1 g per particle, XPBD α = 1e-7 m/N, g = 9.81 m/s², dt = 1/60 s,
 * 10 iterations, no substeps, row-major order) for N = 32, 64, 128 on one thread. Prints CSV and nothing
 * else on stdout:
 * {@code n,particles,constraints,ms_per_step,projections_per_s,alloc_bytes_per_step}.
 * Timing is a warmed-up loop (at least 2 s of warm-up, then at least 3 s measured); allocation is
 * measured over the same steady-state steps with the JVM's per-thread allocation counter.
 */
public final class Bench {
    private Bench() {}

    public static void main(String[] args) {
        System.out.println("n,particles,constraints,ms_per_step,projections_per_s,alloc_bytes_per_step");
        for (int n : new int[] {32, 64, 128}) row(n);
    }

    static Simulation grid(int n) {
        Cloth cloth = new ClothBuilder().resolution(n, n).size(0.01 * (n - 1), 0.01 * (n - 1))
                .family(xpbdcloth.engine.ConstraintFamily.STRUCTURAL, 1.0, 1e-7).pinTopCorners().build();
        Particles p = cloth.particles();
        for (int i = 0; i < p.count(); i++) p.setMass(i, 1e-4);
        SolverSettings s = new SolverSettings().mode(ConstraintMode.XPBD).iterations(10).substeps(1)
                .timestep(1 / 60.0).gravity(0, -9.81, 0);
        return cloth.simulation(s);
    }

    static void row(int n) {
        Simulation sim = grid(n);
        int constraints = sim.constraints().length;
        long warmEnd = System.nanoTime() + 2_000_000_000L;
        while (System.nanoTime() < warmEnd) sim.step();
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long alloc0 = threads.getCurrentThreadAllocatedBytes();
        long t0 = System.nanoTime();
        long steps = 0;
        long t;
        do {
            for (int k = 0; k < 10; k++) sim.step();
            steps += 10;
            t = System.nanoTime();
        } while (t - t0 < 3_000_000_000L);
        long alloc1 = threads.getCurrentThreadAllocatedBytes();
        double msPerStep = (t - t0) / 1e6 / steps;
        double projections = (double) constraints * sim.settings().iterations() * sim.settings().substeps();
        System.out.printf(java.util.Locale.ROOT, "%d,%d,%d,%.4f,%.0f,%d%n", n, sim.particles().count(), constraints,
                msPerStep, projections / (msPerStep / 1000), (alloc1 - alloc0) / steps);
    }
}
