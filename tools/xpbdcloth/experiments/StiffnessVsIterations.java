package xpbdcloth.experiments;

import static xpbdcloth.engine.ConstraintMode.PBD;
import static xpbdcloth.engine.ConstraintMode.XPBD;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import xpbdcloth.engine.Simulation;

/**
 * Experiment 1: the steady-state stretch of a hanging rope and sag of a hanging cloth against the
 * number of Gauss–Seidel sweeps n, for PBD with the raw k, PBD with Müller's k', and XPBD with α.
 * The seeds claim PBD stiffens with n and XPBD does not, once converged.
 */
final class StiffnessVsIterations implements Experiment {
    static final int LINKS = 20;
    static final double LINK = 0.05, MASS = 0.005, K = 0.5, ALPHA_ROPE = 1e-2;
    static final int CLOTH_RES = 16;
    static final double CLOTH_SIZE = 0.5, ALPHA_CLOTH = 1e-3;
    static final double DT = 1 / 60.0;

    @Override public String name() { return "stiffness-vs-iterations"; }

    @Override public String claim() { return "PBD stiffens with the sweep count n; XPBD does not once converged"; }

    static int[] iterations(boolean quick) {
        return quick ? new int[] {1, 5, 20, 100} : new int[] {1, 2, 3, 5, 7, 10, 15, 20, 30, 50, 70, 100};
    }

    static Rigs.Solver[] solvers(int n, double alpha) {
        return new Rigs.Solver[] {
                new Rigs.Solver(PBD, K, 0, n, 1, DT, false),
                new Rigs.Solver(PBD, K, 0, n, 1, DT, true),
                new Rigs.Solver(XPBD, 1, alpha, n, 1, DT, true)};
    }

    static final String[] LABELS = {"PBD raw k=0.5", "PBD Müller k'", "XPBD alpha"};

    /** Relative stretch of the rope (extension / rest length) at steady state. */
    static double ropeStretch(Rigs.Solver s, double seconds) {
        Simulation sim = Rigs.chain(LINKS, LINK, MASS, s);
        return Rigs.steady(sim, seconds, x -> Rigs.chainExtension(x, LINKS, LINK)) / (LINKS * LINK);
    }

    static double clothSag(Rigs.Solver s, double seconds) {
        Simulation sim = Rigs.hangingCloth(CLOTH_RES, CLOTH_SIZE, s);
        return Rigs.steady(sim, seconds, x -> Rigs.clothSag(x, CLOTH_RES, CLOTH_SIZE));
    }

    @Override public List<String> run(Context ctx) throws IOException {
        Table t = new Table(name(), "rig", "solver", "iterations", "stretch_relative", "cloth_sag_m");
        int[] ns = iterations(ctx.quick);
        double seconds = ctx.quick ? 4 : 12;
        List<List<Double>> rope = new ArrayList<>(), cloth = new ArrayList<>();
        for (int j = 0; j < 3; j++) { rope.add(new ArrayList<>()); cloth.add(new ArrayList<>()); }
        List<Double> xs = new ArrayList<>();
        for (int n : ns) {
            ctx.progress(name(), "n = " + n);
            xs.add((double) n);
            Rigs.Solver[] ropeSolvers = solvers(n, ALPHA_ROPE), clothSolvers = solvers(n, ALPHA_CLOTH);
            for (int j = 0; j < 3; j++) {
                double r = ropeStretch(ropeSolvers[j], seconds);
                double c = clothSag(clothSolvers[j], seconds);
                rope.get(j).add(r);
                cloth.get(j).add(c);
                t.add("rope", LABELS[j], n, r, "");
                t.add("cloth", LABELS[j], n, "", c);
            }
        }
        ctx.save(t);
        // Closed form for the XPBD rope: Σ_i α g m (LINKS − i) = α g m LINKS (LINKS + 1)/2.
        double closed = ALPHA_ROPE * Rigs.G * MASS * LINKS * (LINKS + 1) / 2 / (LINKS * LINK);
        Plot p = new Plot("Rope stretch vs Gauss-Seidel sweeps (20 links, dt = 1/60 s)", "iterations n", "steady stretch (extension / rest length)", true, true);
        for (int j = 0; j < 3; j++) p.line(LABELS[j], xs, rope.get(j));
        List<Double> cf = new ArrayList<>();
        for (int i = 0; i < xs.size(); i++) cf.add(closed);
        p.dashed("XPBD closed form alpha g m", xs, cf);
        ctx.save(p, name());
        Plot pc = new Plot("Cloth sag vs sweeps (16x16, 0.5 m, two top corners pinned)", "iterations n", "sag of bottom centre (m)", true, false);
        for (int j = 0; j < 3; j++) pc.line(LABELS[j], xs, cloth.get(j));
        ctx.save(pc, name() + "-cloth");

        List<String> out = new ArrayList<>();
        int last = ns.length - 1;
        out.add(String.format("rope stretch n=1 -> n=%d: PBD raw %.4g -> %.4g (x%.1f), Müller %.4g -> %.4g (x%.1f), XPBD %.4g -> %.4g (closed form %.4g)",
                ns[last], rope.get(0).get(0), rope.get(0).get(last), rope.get(0).get(0) / rope.get(0).get(last),
                rope.get(1).get(0), rope.get(1).get(last), rope.get(1).get(0) / rope.get(1).get(last),
                rope.get(2).get(0), rope.get(2).get(last), closed));
        out.add(String.format("cloth sag n=1 -> n=%d: PBD raw %.4g -> %.4g m, Müller %.4g -> %.4g m, XPBD %.4g -> %.4g m",
                ns[last], cloth.get(0).get(0), cloth.get(0).get(last), cloth.get(1).get(0), cloth.get(1).get(last), cloth.get(2).get(0), cloth.get(2).get(last)));
        return out;
    }
}
