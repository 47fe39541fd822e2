package xpbdcloth.experiments;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import xpbdcloth.engine.ConstraintMode;

/**
 * Experiment 3: where Müller's k' = 1 − (1 − k)^(1/n) stops compensating. For each k, the rope's
 * stretch is measured at n = 1 … 50 with k' and with the raw k; the spread (max − min)/min across n
 * says how much the material still depends on the solver.
 */
final class MullerSaturation implements Experiment {
    static final double[] KS = {0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.8, 0.9, 0.95, 0.99, 0.999, 1.0};
    static final int[] NS = {1, 2, 5, 10, 20, 50};

    @Override public String name() { return "muller-saturation"; }

    @Override public String claim() { return "Müller's k' compensates for n only for soft k, and saturates as k -> 1"; }

    /** Spread (max − min)/min of the rope stretch over the n values, with or without Müller. */
    static double spread(double k, int[] ns, boolean muller, double seconds, List<Double> stretches) {
        double lo = Double.MAX_VALUE, hi = 0;
        for (int n : ns) {
            double s = StiffnessVsIterations.ropeStretch(new Rigs.Solver(ConstraintMode.PBD, k, 0, n, 1, 1 / 60.0, muller), seconds);
            if (stretches != null) stretches.add(s);
            lo = Math.min(lo, s);
            hi = Math.max(hi, s);
        }
        return (hi - lo) / lo;
    }

    @Override public List<String> run(Context ctx) throws IOException {
        Table t = new Table(name(), "k", "iterations", "stretch_muller_relative", "stretch_raw_relative");
        double seconds = ctx.quick ? 4 : 12;
        double[] ks = ctx.quick ? new double[] {0.1, 0.5, 0.9, 0.999} : KS;
        List<Double> xs = new ArrayList<>(), muller = new ArrayList<>(), raw = new ArrayList<>();
        List<String> out = new ArrayList<>();
        for (double k : ks) {
            ctx.progress(name(), "k = " + k);
            List<Double> m = new ArrayList<>(), r = new ArrayList<>();
            double sm = spread(k, NS, true, seconds, m), sr = spread(k, NS, false, seconds, r);
            for (int i = 0; i < NS.length; i++) t.add(k, NS[i], m.get(i), r.get(i));
            xs.add(k);
            muller.add(sm);
            raw.add(sr);
            out.add(String.format("k=%.3f: spread of stretch over n=1..50: Müller %.3g, raw %.3g (stretch at n=1 %.3g, n=50 %.3g with k')",
                    k, sm, sr, m.get(0), m.get(NS.length - 1)));
        }
        ctx.save(t);
        Plot p = new Plot("How much the rope's stretch still depends on n (spread over n = 1..50)", "PBD stiffness k", "(max - min) / min of stretch over n", false, true);
        p.line("Müller k'", xs, muller).line("raw k", xs, raw);
        ctx.save(p, name());
        return out;
    }
}
