package xpbdcloth.experiments;

import java.util.function.ToDoubleFunction;

/**
 * Nelder–Mead simplex search for a minimum without derivatives (Nelder &amp; Mead 1965), for fitting
 * parameters whose effect is only known by simulating: PBD's k and a simulated XPBD rest, in experiment 9.
 */
final class NelderMead {
    private NelderMead() {}

    /**
     * The point of least f found from u0 (initial simplex: u0 and u0 plus 1 along each axis) within
     * {@code evaluations} calls of f, stopping early once the simplex's values agree to 1e-6 relative.
     * Reflection 1, expansion 2, contraction ½, shrink ½ (Lagarias et al. 1998, the standard coefficients).
     */
    static double[] minimise(ToDoubleFunction<double[]> f, double[] u0, int evaluations) {
        int n = u0.length;
        double[][] s = new double[n + 1][];
        double[] v = new double[n + 1];
        for (int i = 0; i <= n; i++) {
            s[i] = u0.clone();
            if (i > 0) s[i][i - 1] += 1;
            v[i] = f.applyAsDouble(s[i]);
        }
        int used = n + 1;
        while (used < evaluations) {
            // Best first (insertion sort: the simplex has n + 1 ≤ a handful of points).
            for (int i = 1; i <= n; i++)
                for (int j = i; j > 0 && v[j] < v[j - 1]; j--) {
                    double[] ps = s[j]; s[j] = s[j - 1]; s[j - 1] = ps;
                    double pv = v[j]; v[j] = v[j - 1]; v[j - 1] = pv;
                }
            if (v[n] - v[0] <= 1e-6 * Math.abs(v[0]) + 1e-12) break;
            double[] centroid = new double[n];
            for (int i = 0; i < n; i++) for (int d = 0; d < n; d++) centroid[d] += s[i][d] / n;
            double[] reflected = along(centroid, s[n], -1);
            double fr = f.applyAsDouble(reflected);
            used++;
            if (fr < v[0]) {
                double[] expanded = along(centroid, s[n], -2);
                double fe = f.applyAsDouble(expanded);
                used++;
                if (fe < fr) { s[n] = expanded; v[n] = fe; } else { s[n] = reflected; v[n] = fr; }
            } else if (fr < v[n - 1]) {
                s[n] = reflected;
                v[n] = fr;
            } else {
                double[] contracted = fr < v[n] ? along(centroid, s[n], -0.5) : along(centroid, s[n], 0.5);
                double fc = f.applyAsDouble(contracted);
                used++;
                if (fc < Math.min(fr, v[n])) {
                    s[n] = contracted;
                    v[n] = fc;
                } else {
                    for (int i = 1; i <= n; i++) {
                        s[i] = along(s[0], s[i], 0.5);
                        v[i] = f.applyAsDouble(s[i]);
                        used++;
                    }
                }
            }
        }
        int best = 0;
        for (int i = 1; i <= n; i++) if (v[i] < v[best]) best = i;
        return s[best];
    }

    /** c + t·(p − c). */
    private static double[] along(double[] c, double[] p, double t) {
        double[] out = new double[c.length];
        for (int d = 0; d < c.length; d++) out[d] = c[d] + t * (p[d] - c[d]);
        return out;
    }
}
