package xpbdcloth.engine;

import java.util.Arrays;

/**
 * Distance constraints: each keeps two particles a, b at a rest distance L (structural edges, rope links).
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
public final class DistanceBlock extends ConstraintBlock implements LinearLength {
    /** Below this length (m) the direction n is numerically meaningless. */
    static final double MIN_LENGTH = 1e-12;

    /** L per constraint, m. */
    double[] rest;
    /** The constraints' ends and L in the coloured sweep's order ({@link #layOutIn}). */
    private int[] sweepParticles;
    private double[] sweepRest;

    public DistanceBlock(ConstraintFamily family, int capacity) {
        super(family, 2, capacity);
        rest = new double[lambda.length];
    }

    /** Adds a constraint keeping a and b at distance restLength (m); returns its index. */
    public int add(int a, int b, double restLength) {
        checkEnds(a, b, restLength);
        int i = newSlot();
        particles[2 * i] = a;
        particles[2 * i + 1] = b;
        rest[i] = restLength;
        return i;
    }

    /** Adds a constraint at the particles' current distance. */
    public int addAtCurrentLength(Particles p, int a, int b) {
        Check.index("a", a, p.count());
        Check.index("b", b, p.count());
        return add(a, b, distance(p, a, b));
    }

    /** Two distinct particle indices and a rest length ≥ 0, or the error naming what is wrong. */
    static void checkEnds(int a, int b, double restLength) {
        if (a == b) throw new IllegalArgumentException("b must differ from a, was " + b);
        Check.atLeast("a", a, 0);
        Check.atLeast("b", b, 0);
        Check.nonNegative("restLength", restLength);
    }

    static double distance(Particles p, int a, int b) {
        double dx = p.x[3 * a] - p.x[3 * b], dy = p.x[3 * a + 1] - p.x[3 * b + 1], dz = p.x[3 * a + 2] - p.x[3 * b + 2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    @Override public double coefficient(int k) { return k == 0 ? 1 : -1; }

    public int a(int i) { return particles[2 * i]; }
    public int b(int i) { return particles[2 * i + 1]; }
    public double restLength(int i) { return rest[i]; }

    /** |x_a − x_b| / L − 1 (0 at rest, &gt; 0 stretched); 0 for a zero rest length. */
    public double strain(int i, Particles p) {
        return rest[i] > 0 ? distance(p, a(i), b(i)) / rest[i] - 1 : 0;
    }

    @Override public double evaluate(int i, Particles p) { return distance(p, a(i), b(i)) - rest[i]; }

    @Override public void gradient(int i, Particles p, double[] out) { unitGradient(p, a(i), b(i), out); }

    /** ∇C of |x_a − x_b| − L: n for a, −n for b (zero where the two coincide). */
    static void unitGradient(Particles p, int a, int b, double[] out) {
        double dx = p.x[3 * a] - p.x[3 * b], dy = p.x[3 * a + 1] - p.x[3 * b + 1], dz = p.x[3 * a + 2] - p.x[3 * b + 2];
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double s = len < MIN_LENGTH ? 0 : 1 / len;
        out[0] = dx * s; out[1] = dy * s; out[2] = dz * s;
        out[3] = -dx * s; out[4] = -dy * s; out[5] = -dz * s;
    }

    @Override void project(int i, Particles p, SolverContext ctx) { projectPair(this, i, particles[2 * i], particles[2 * i + 1], rest[i], p, ctx); }

    /**
     * The projection of row i of a block whose row is |x_a − x_b| − L (this block's, and a stitch's, whose L
     * the sewing moves): Δλ by the block's material and mode, the move along n shared by inverse mass.
     */
    static void projectPair(ConstraintBlock block, int i, int a, int b, double restLength, Particles p, SolverContext ctx) {
        final double[] x = p.x;
        final int ia = 3 * a, ib = 3 * b;
        double w0 = p.w[a], w1 = p.w[b];
        double dx = x[ia] - x[ib], dy = x[ia + 1] - x[ib + 1], dz = x[ia + 2] - x[ib + 2];
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double C = len - restLength;
        if (len < MIN_LENGTH) return;
        double dLambda = block.deltaLambda(i, C, w0 + w1, ctx);
        double s = dLambda / len; // folds n = d/len into the update
        double s0 = w0 * s, s1 = w1 * s;
        x[ia] += s0 * dx; x[ia + 1] += s0 * dy; x[ia + 2] += s0 * dz;
        x[ib] -= s1 * dx; x[ib + 1] -= s1 * dy; x[ib + 2] -= s1 * dz;
    }

    @Override void projectRange(int from, int to, Particles p, SolverContext ctx) {
        if (uniformXpbd(ctx)) { final double alphaTilde = compliance(0) * ctx.inverseH2; for (int i = from; i < to; i++) projectXpbd(i, p, alphaTilde); }
        else for (int i = from; i < to; i++) project(i, p, ctx);
    }

    @Override void projectListed(int[] order, int from, int to, Particles p, SolverContext ctx) {
        if (!laidOutIn(order)) {
            if (uniformXpbd(ctx)) { final double alphaTilde = compliance(0) * ctx.inverseH2; for (int k = from; k < to; k++) projectXpbd(order[k], p, alphaTilde); }
            else for (int k = from; k < to; k++) project(order[k], p, ctx);
        } else if (uniformXpbd(ctx)) {
            final double alphaTilde = compliance(0) * ctx.inverseH2;
            for (int k = from; k < to; k++) projectXpbd(order[k], sweepParticles[2 * k], sweepParticles[2 * k + 1], sweepRest[k], p, alphaTilde);
        } else for (int k = from; k < to; k++) projectPair(this, order[k], sweepParticles[2 * k], sweepParticles[2 * k + 1], sweepRest[k], p, ctx);
    }

    /**
     * The constraints' ends and rest lengths copied into the coloured sweep's order, which then reads them in
     * order rather than from wherever each constraint lies (as {@link QuadraticBendBlock#layOutIn} does).
     */
    @Override boolean layOutIn(int[] order) {
        sweepParticles = inOrder(particles, 2, 2, order);
        sweepRest = inOrder(rest, 1, 1, order);
        return true;
    }

    /**
     * XPBD's projection with the block's one α̃ ({@link #project}'s arithmetic, the mode and material looked up
     * once per range instead of per constraint): Δλ = (−C − α̃λ)/(w₀ + w₁ + α̃) and the move Δλ·d/|d| taken as one
     * quotient, (−C − α̃λ)/((w₀ + w₁ + α̃)|d|), so a projection divides once.
     */
    private void projectXpbd(int i, Particles p, double alphaTilde) { projectXpbd(i, particles[2 * i], particles[2 * i + 1], rest[i], p, alphaTilde); }

    private void projectXpbd(int i, int a, int b, double restLength, Particles p, double alphaTilde) {
        final double[] x = p.x, w = p.w;
        final int ia = 3 * a, ib = 3 * b;
        final double w0 = w[a], w1 = w[b];
        double dx = x[ia] - x[ib], dy = x[ia + 1] - x[ib + 1], dz = x[ia + 2] - x[ib + 2];
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        if (len < MIN_LENGTH) return;
        double denominator = w0 + w1 + alphaTilde;
        if (denominator <= 0) return;
        double numerator = -(len - restLength) - alphaTilde * lambda[i];
        double s = numerator / (denominator * len);
        lambda[i] += s * len;
        double s0 = w0 * s, s1 = w1 * s;
        x[ia] += s0 * dx; x[ia + 1] += s0 * dy; x[ia + 2] += s0 * dz;
        x[ib] -= s1 * dx; x[ib + 1] -= s1 * dy; x[ib + 2] -= s1 * dz;
    }

    @Override DistanceConstraint view(int i) { return new DistanceConstraint(this, i); }

    @Override DistanceBlock emptyLike(int capacity) { return new DistanceBlock(family(), capacity); }

    @Override void copyRest(int i, ConstraintBlock from, int j) { rest[i] = ((DistanceBlock) from).rest[j]; }

    @Override void grow(int capacity) {
        super.grow(capacity);
        rest = Arrays.copyOf(rest, capacity);
    }
}
