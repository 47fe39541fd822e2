package xpbdcloth.fit;

import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.Particles;

/**
 * The derivative of a constraint's vector function (its ∇C, or Cⱼ∇Cⱼ) along a direction u in the
 * positions of its particles, by central differences of the block's own functions: the second
 * derivatives both fits need, with no second copy of any constraint's maths.
 *
 * <pre>
 *   D(ε) = (f(x + εû) − f(x − εû)) / (2ε)·|u|,   û = u/|u|
 *   Df·u ≈ (4·D(ε/2) − D(ε)) / 3                 (Richardson: the h² error term cancels, O(ε⁴) left)
 * </pre>
 * Where f varies on a scale shorter than ε (a flat triangle bend's ∇²C grows as 1/|d|) the two levels
 * disagree; then ε is quartered, up to {@code shrinks} times, until they agree to 1e-4. Asking them to
 * agree closer drives ε into round-off: at 1e-8 the gradient of a 1 s trajectory was off by 1e-3, at 1e-4
 * by 1e-7. The particles' positions are restored after.
 */
final class DirectionalDifference {
    /** A vector function of one constraint at the particles' current positions, 3 entries per particle. */
    interface BlockFunction {
        void at(ConstraintBlock b, int i, Particles p, double[] out);
    }

    static final BlockFunction GRADIENT = (b, i, p, out) -> b.gradient(i, p, out);

    private final double[] saved = new double[3 * ConstraintBlock.MAX_ARITY], plus = new double[3 * ConstraintBlock.MAX_ARITY], minus = new double[3 * ConstraintBlock.MAX_ARITY], coarse = new double[3 * ConstraintBlock.MAX_ARITY];

    /** out = (∂f/∂x)·u for constraint i of b (u and out 3·arity long, |u| &gt; 0), first step eps along û. */
    void along(ConstraintBlock b, int i, Particles p, BlockFunction f, double[] u, double eps, int shrinks, double[] out) {
        int m = 3 * b.arity();
        double norm = 0;
        for (int e = 0; e < m; e++) norm += u[e] * u[e];
        norm = Math.sqrt(norm);
        for (int attempt = 0; ; attempt++) {
            central(b, i, p, f, u, eps / norm, coarse);
            central(b, i, p, f, u, eps / 2 / norm, out);
            double diff = 0, size = 0;
            for (int e = 0; e < m; e++) {
                diff = Math.max(diff, Math.abs(out[e] - coarse[e]));
                size = Math.max(size, Math.abs(out[e]));
            }
            if (diff <= 1e-4 * size || attempt >= shrinks) {
                for (int e = 0; e < m; e++) out[e] += (out[e] - coarse[e]) / 3;
                return;
            }
            eps /= 4;
        }
    }

    /** out = (f(x + s·u) − f(x − s·u)) / (2s). */
    private void central(ConstraintBlock b, int i, Particles p, BlockFunction f, double[] u, double s, double[] out) {
        double[] x = p.positions();
        int arity = b.arity();
        for (int q = 0; q < arity; q++) {
            int c = 3 * b.particle(i, q);
            for (int e = 0; e < 3; e++) saved[3 * q + e] = x[c + e];
        }
        move(b, i, x, u, s);
        f.at(b, i, p, plus);
        move(b, i, x, u, -s);
        f.at(b, i, p, minus);
        for (int q = 0; q < arity; q++) {
            int c = 3 * b.particle(i, q);
            for (int e = 0; e < 3; e++) x[c + e] = saved[3 * q + e];
        }
        for (int e = 0; e < 3 * arity; e++) out[e] = (plus[e] - minus[e]) / (2 * s);
    }

    private void move(ConstraintBlock b, int i, double[] x, double[] u, double s) {
        for (int q = 0; q < b.arity(); q++) {
            int c = 3 * b.particle(i, q);
            for (int e = 0; e < 3; e++) x[c + e] = saved[3 * q + e] + s * u[3 * q + e];
        }
    }
}
