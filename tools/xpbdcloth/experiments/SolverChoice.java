package xpbdcloth.experiments;

import java.awt.Color;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SolverSettings;
import xpbdcloth.engine.SolverType;
import xpbdcloth.fabric.Fabric;
import xpbdcloth.fabric.FabricConstraints;
import xpbdcloth.scene.FabricCatalogue;

/**
 * Experiment 13: what each solver setting buys. Measured denim, 1 m at 64 segments a side, hung by its
 * two top corners (the fabric scene's cloth, twice as fine), settles for 8 s under each setting; the error
 * of its rest (sag of the top edge and largest Green strain) against the converged rest, set against the
 * cost of a step on one thread. The converged rest is vertex block descent's at 4 × 10 sweeps, its
 * balance (the worst particle's leftover force over its weight) reported; the tests hold that rest to
 * Newton's at 32 and 64 segments. The plot is a user's guide to choosing settings: Gauss–Seidel's error
 * falls only slowly with its sweeps (its rest is biased by how few it has), vertex block descent's
 * rest is the converged one at every setting, and its sweeps buy only how closely it follows a moving
 * cloth.
 */
final class SolverChoice implements Experiment {
    static final int SEGMENTS = 64;

    @Override public String name() { return "solver-choice"; }

    @Override public String claim() { return "a fabric's converged rest at the cost of a real-time step needs a solver whose rest is the energy's minimum"; }

    /** Sag (m), largest strain, balance and ms per step (the last 200 of 400 steps, one thread). */
    static double[] settle(SolverType solver, int iterations, int substeps, int segments) {
        int n = segments + 1;
        Cloth cloth = new ClothBuilder().resolution(n, n).size(1, 1).origin(0, 2, 0).arealDensity(0.324).pinTopCorners().build();
        Particles p = cloth.particles();
        Simulation sim = cloth.simulation(new SolverSettings().withMode(ConstraintMode.XPBD).withSolver(solver).withIterations(iterations).withSubsteps(substeps)
                .withTimestep(0.02).withGravity(0, -9.81, 0).withDamping(2));
        Fabric denim = FabricCatalogue.named("denim");
        for (ConstraintBlock block : FabricConstraints.build(p, cloth.triangles(), new double[] {1, 0, 0}, denim.membrane, denim.bendingStiffness, false))
            sim.add(block);
        long t0 = 0;
        for (int s = 0; s < 400; s++) {
            if (s == 200) t0 = System.nanoTime();
            sim.step();
        }
        double ms = (System.nanoTime() - t0) / 1e6 / 200;
        double middle = 0.5 * (p.y(cloth.index(0, (n - 1) / 2)) + p.y(cloth.index(0, n / 2)));
        double[] out = {p.y(cloth.index(0, 0)) - middle, xpbdcloth.engine.Metrics.largestGreenStrain(sim), sim.balance(), ms};
        sim.close();
        return out;
    }

    /** Sorts the pairs (x[i], y[i]) by x, so a line through them runs left to right. */
    static void sortByFirst(List<Double> x, List<Double> y) {
        List<double[]> pairs = new ArrayList<>();
        for (int i = 0; i < x.size(); i++) pairs.add(new double[] {x.get(i), y.get(i)});
        pairs.sort((a, b) -> Double.compare(a[0], b[0]));
        for (int i = 0; i < pairs.size(); i++) { x.set(i, pairs.get(i)[0]); y.set(i, pairs.get(i)[1]); }
    }

    @Override public List<String> run(Context ctx) throws IOException {
        int segments = ctx.quick ? 24 : SEGMENTS;
        double[] reference = settle(SolverType.VERTEX_BLOCK_DESCENT, 4, 10, segments);
        ctx.progress(name(), String.format("reference (vertex block descent 4 × 10): sag %.5f m, strain %.4f, balance %.1e", reference[0], reference[1], reference[2]));
        Table t = new Table(name(), "solver", "iterations", "substeps", "ms_per_step", "sag_m", "sag_error", "strain", "strain_error", "balance");
        int[][] gsSettings = ctx.quick ? new int[][] {{2, 10}, {10, 10}} : new int[][] {{2, 10}, {4, 10}, {10, 10}, {1, 20}, {1, 40}, {20, 10}};
        int[][] vbdSettings = ctx.quick ? new int[][] {{1, 10}, {2, 10}} : new int[][] {{1, 10}, {2, 10}, {1, 20}, {2, 20}};
        List<Double> gsCost = new ArrayList<>(), gsError = new ArrayList<>(), vbdCost = new ArrayList<>(), vbdError = new ArrayList<>();
        List<String> out = new ArrayList<>();
        for (SolverType type : new SolverType[] {SolverType.GAUSS_SEIDEL, SolverType.VERTEX_BLOCK_DESCENT})
            for (int[] setting : type == SolverType.GAUSS_SEIDEL ? gsSettings : vbdSettings) {
                double[] r = settle(type, setting[0], setting[1], segments);
                double sagError = Math.abs(r[0] / reference[0] - 1), strainError = Math.abs(r[1] / reference[1] - 1);
                t.add(type.label(), setting[0], setting[1], r[3], r[0], sagError, r[1], strainError, r[2]);
                String line = String.format("%s %d × %d: %.1f ms a step, sag %.1f %% off, largest strain %.1f %% off, balance %.1e",
                        type.label(), setting[1], setting[0], r[3], 100 * sagError, 100 * strainError, r[2]);
                ctx.progress(name(), line);
                out.add(line);
                (type == SolverType.GAUSS_SEIDEL ? gsCost : vbdCost).add(r[3]);
                (type == SolverType.GAUSS_SEIDEL ? gsError : vbdError).add(Math.max(sagError, 1e-4));
            }
        ctx.save(t);
        Plot p = new Plot("Error of the rest against the cost of a step: denim, " + segments + " segments, one thread", "ms per step (log)",
                "sag error against the converged rest (log; floor 1e-4)", true, true);
        sortByFirst(gsCost, gsError);
        sortByFirst(vbdCost, vbdError);
        p.line("Gauss-Seidel (its settings, by cost)", gsCost, gsError, new Color(0.85f, 0.45f, 0.1f))
                .line("vertex block descent (by cost)", vbdCost, vbdError, new Color(0.3f, 0.2f, 0.8f))
                .dashed("the 20 ms a step that is real time", List.of(20.0, 20.0), List.of(1e-4, 100.0));
        ctx.save(p, name());
        out.add(0, String.format("converged rest (vertex block descent 10 × 4): sag %.4f m, largest strain %.4f, balance %.1e", reference[0], reference[1], reference[2]));
        return out;
    }
}
