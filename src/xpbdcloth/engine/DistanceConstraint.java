package xpbdcloth.engine;

/**
 * Keeps two particles a, b at a rest distance L (structural edges, rope links).
 *
 * <pre>
 *   C(x)   = |x_a − x_b| − L
 *   ∇_a C  =  n,   ∇_b C = −n,   n = (x_a − x_b) / |x_a − x_b|,   Σ wᵢ|∇ᵢC|² = w_a + w_b
 * </pre>
 * Source: Müller et al. 2007, "Position Based Dynamics", §3.3 and eq. (9)–(10); compliant form from
 * Macklin et al. 2016, eq. (18).
 * Degenerate cases: coincident particles have no direction n, so the projection is skipped (any chosen
 * direction would be arbitrary; the neighbours' constraints separate them); both particles pinned
 * (w_a + w_b = 0) leaves them untouched.
 */
public final class DistanceConstraint extends Constraint {
    /** Below this length (m) the direction n is numerically meaningless. */
    static final double MIN_LENGTH = 1e-12;

    final int a, b;
    final double restLength;

    public DistanceConstraint(ConstraintFamily family, int a, int b, double restLength) {
        super(family);
        if (a == b) throw new IllegalArgumentException("b must differ from a, was " + b);
        this.a = Check.atLeast("a", a, 0);
        this.b = Check.atLeast("b", b, 0);
        this.restLength = Check.nonNegative("restLength", restLength);
    }

    /** A structural constraint at the particles' current distance. */
    public static DistanceConstraint between(Particles p, int a, int b) {
        Check.index("a", a, p.count());
        Check.index("b", b, p.count());
        return new DistanceConstraint(ConstraintFamily.STRUCTURAL, a, b, distance(p, a, b));
    }

    static double distance(Particles p, int a, int b) {
        double dx = p.x[3 * a] - p.x[3 * b], dy = p.x[3 * a + 1] - p.x[3 * b + 1], dz = p.x[3 * a + 2] - p.x[3 * b + 2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    public int a() { return a; }
    public int b() { return b; }
    public double restLength() { return restLength; }

    /** |x_a − x_b| / L − 1 (0 at rest, &gt; 0 stretched); 0 for a zero rest length. */
    public double strain(Particles p) {
        return restLength > 0 ? distance(p, a, b) / restLength - 1 : 0;
    }

    @Override public int[] particles() { return new int[] {a, b}; }

    @Override public double evaluate(Particles p) { return distance(p, a, b) - restLength; }

    @Override public void gradient(Particles p, double[] out) {
        double dx = p.x[3 * a] - p.x[3 * b], dy = p.x[3 * a + 1] - p.x[3 * b + 1], dz = p.x[3 * a + 2] - p.x[3 * b + 2];
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double s = len < MIN_LENGTH ? 0 : 1 / len;
        out[0] = dx * s; out[1] = dy * s; out[2] = dz * s;
        out[3] = -dx * s; out[4] = -dy * s; out[5] = -dz * s;
    }

    @Override protected void project(Particles p, SolverContext ctx) {
        final double[] x = p.x;
        final int ia = 3 * a, ib = 3 * b;
        double w0 = p.w[a], w1 = p.w[b];
        double dx = x[ia] - x[ib], dy = x[ia + 1] - x[ib + 1], dz = x[ia + 2] - x[ib + 2];
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double C = len - restLength;
        if (len < MIN_LENGTH) return;
        double dLambda = deltaLambda(C, w0 + w1, ctx);
        double s = dLambda / len; // folds n = d/len into the update
        double s0 = w0 * s, s1 = w1 * s;
        x[ia] += s0 * dx; x[ia + 1] += s0 * dy; x[ia + 2] += s0 * dz;
        x[ib] -= s1 * dx; x[ib + 1] -= s1 * dy; x[ib + 2] -= s1 * dz;
    }
}
