package xpbdcloth.experiments;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;

/**
 * Experiment 4: XPBD against Hooke's law. A single spring stretches by α·m·g; link i of a hanging chain
 * by α·g·(mass below link i). For chains of N links: the Gauss–Seidel sweeps it takes to get every
 * link within 1 % of the closed form, with the chain loaded quasi-statically (gravity ramped up).
 */
final class ClosedForm implements Experiment {
    static final double MASS = 0.01, LINK = 0.05, CHAIN_ALPHA = 1e-2;
    static final int[] SWEEPS = {1, 2, 3, 5, 7, 10, 15, 20, 30, 50, 70, 100, 150, 200, 300, 500, 700, 1000};

    @Override public String name() { return "closed-form"; }

    @Override public String claim() { return "XPBD stretches links by alpha*g*(mass below); sweeps to 1% grow with chain length"; }

    /** Largest relative error over the links of an N-link chain after settling, with n sweeps. */
    static double chainError(int links, int n, double seconds, double[] perLink) {
        Simulation sim = Rigs.chain(links, LINK, MASS, new Rigs.Solver(ConstraintMode.XPBD, 1, CHAIN_ALPHA, n, 1, 1 / 60.0, true));
        // Load the chain quasi-statically: gravity ramps up over the first 60 % of the run and then holds,
        // so the long chains do not bounce (XPBD with a converged solve barely damps) and what is left
        // at the end is the solver's error, not an oscillation.
        int steps = (int) Math.round(seconds * 60), ramp = (int) (0.6 * steps);
        for (int s = 0; s < steps; s++) {
            double u = Math.min(1.0, (s + 1.0) / ramp), ease = u * u * (3 - 2 * u);
            sim.settings(sim.settings().withGravity(0, -Rigs.G * ease, 0));
            sim.step();
        }
        Particles p = sim.particles();
        double worst = 0;
        for (int i = 0; i < links; i++) {
            double stretch = p.y(i) - p.y(i + 1) - LINK;
            if (perLink != null) perLink[i] = stretch;
            double expected = CHAIN_ALPHA * Rigs.G * MASS * (links - i);
            worst = Math.max(worst, Math.abs(stretch - expected) / expected);
        }
        return worst;
    }

    /** The fewest sweeps in {@link #SWEEPS} that bring every link within 1 %, or -1. */
    static int sweepsToOnePercent(int links, double seconds) {
        for (int n : SWEEPS) if (chainError(links, n, seconds, null) < 0.01) return n;
        return -1;
    }

    @Override public List<String> run(Context ctx) throws IOException {
        Table t = new Table(name(), "kind", "links", "link", "iterations", "compliance_m_per_N", "measured_m", "closed_form_m", "relative_error");
        List<String> out = new ArrayList<>();
        List<Double> cfx = new ArrayList<>(), cfy = new ArrayList<>();
        double worstSpring = 0;
        ctx.progress(name(), "single spring");
        for (double alpha = 1e-6; alpha <= 1.01e-1; alpha *= 10) {
            double m = 0.1;
            Simulation sim = Rigs.chain(1, 1.0, m, new Rigs.Solver(ConstraintMode.XPBD, 1, alpha, 2, 1, 1 / 60.0, true));
            double ext = Rigs.steady(sim, 20, x -> Rigs.chainExtension(x, 1, 1.0));
            double expected = alpha * m * Rigs.G;
            worstSpring = Math.max(worstSpring, Math.abs(ext - expected) / expected);
            t.add("spring", 1, 0, 2, alpha, ext, expected, Math.abs(ext - expected) / expected);
            cfx.add(expected);
            cfy.add(ext);
        }
        out.add(String.format("single spring, alpha 1e-6..1e-1 m/N, n=2: worst relative error %.2e", worstSpring));

        int[] lengths = ctx.quick ? new int[] {5, 10} : new int[] {5, 10, 20, 40, 80};
        double seconds = ctx.quick ? 20 : 40;
        List<Double> nx = new ArrayList<>(), ny = new ArrayList<>();
        StringBuilder sweeps = new StringBuilder("sweeps for every link within 1 %:");
        for (int links : lengths) {
            ctx.progress(name(), "chain of " + links);
            int n = sweepsToOnePercent(links, seconds);
            double[] per = new double[links];
            double err = chainError(links, n > 0 ? n : SWEEPS[SWEEPS.length - 1], seconds, per);
            for (int i = 0; i < links; i++) {
                double expected = CHAIN_ALPHA * Rigs.G * MASS * (links - i);
                t.add("chain", links, i, n, CHAIN_ALPHA, per[i], expected, Math.abs(per[i] - expected) / expected);
                cfx.add(expected);
                cfy.add(per[i]);
            }
            if (n > 0) { nx.add((double) links); ny.add((double) n); }
            sweeps.append(String.format(" N=%d: %s (worst %.2g%%)", links, n > 0 ? String.valueOf(n) : ">1000", 100 * err));
        }
        out.add(sweeps.toString());
        ctx.save(t);
        Plot p = new Plot("XPBD against Hooke: measured vs closed-form stretch (springs and every chain link)", "closed form alpha g m_below (m)", "measured (m)", true, true);
        p.line("measured", cfx, cfy);
        List<Double> diag = List.of(Math.min(cfx.get(0), 1e-7), 1.0);
        p.dashed("y = x", diag, diag);
        ctx.save(p, name());
        Plot q = new Plot("Gauss-Seidel sweeps for every link within 1 % of Hooke (alpha = 1e-2 m/N, 10 g particles)", "links N", "sweeps n", true, true);
        q.line("sweeps to 1 %", nx, ny);
        ctx.save(q, name() + "-sweeps");
        return out;
    }
}
