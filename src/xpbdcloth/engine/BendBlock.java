package xpbdcloth.engine;

import java.util.Arrays;

/**
 * Triangle bending constraints, each over three particles b₀, v, b₁ (v in the middle): keeps the distance
 * from v to the triangle's centroid c = (b₀ + b₁ + v)/3 at its rest value h₀.
 *
 * <pre>
 *   d = x_v − c = (2x_v − x_b₀ − x_b₁)/3,   C(x) = |d| − h₀,   n = d/|d|
 *   ∇_v C = (2/3) n,   ∇_b₀ C = ∇_b₁ C = −(1/3) n,   Σ wᵢ|∇ᵢC|² = (4w_v + w_b₀ + w_b₁)/9
 * </pre>
 * Particle order: b₀, v, b₁. On a grid the triples run along rows and columns; on a general mesh, along
 * its straight runs of edges ({@link MeshClothBuilder}).
 * Source: Kelager, Niebe, Erleben 2010, "A Triangle Bending Constraint Model for Position-Based
 * Dynamics". Why not a dihedral angle: the dihedral constraint needs acos of a normal product and
 * normalised cross products of two triangles, whose gradients blow up as a triangle degenerates and whose
 * C is flat near 0 and π; the centroid distance is a plain length with a bounded gradient (|∇C| ≤ 2/3),
 * needs one square root, and works on a rope as well as a cloth.
 * Degenerate case: a straight triple at rest has h₀ = 0 and, once straight again, d = 0 with no
 * direction n; the projection is then skipped, which is right because C = |d| − 0 = 0 is satisfied.
 */
public final class BendBlock extends ConstraintBlock {
    /** h₀ per constraint, m. */
    double[] restDistance;

    public BendBlock(ConstraintFamily family, int capacity) {
        super(family, 3, capacity);
        restDistance = new double[lambda.length];
    }

    /** Adds a constraint keeping v at restDistance (m) from the centroid of b0, v, b1. */
    public int add(int b0, int v, int b1, double rest) {
        if (b0 == v || b1 == v || b0 == b1)
            throw new IllegalArgumentException("particles must be distinct, was " + b0 + ", " + v + ", " + b1);
        Check.atLeast("b0", b0, 0);
        Check.atLeast("v", v, 0);
        Check.atLeast("b1", b1, 0);
        Check.nonNegative("restDistance", rest);
        int i = newSlot();
        particles[3 * i] = b0;
        particles[3 * i + 1] = v;
        particles[3 * i + 2] = b1;
        restDistance[i] = rest;
        return i;
    }

    /** Adds a constraint at the particles' current shape. */
    public int addAtCurrentShape(Particles p, int b0, int v, int b1) {
        int i = add(b0, v, b1, 0);
        restDistance[i] = centroidDistance(i, p);
        return i;
    }

    public double restDistance(int i) { return restDistance[i]; }

    /** |x_v − centroid| of constraint i. */
    public double centroidDistance(int i, Particles p) {
        double[] x = p.x;
        int b0 = particles[3 * i], v = particles[3 * i + 1], b1 = particles[3 * i + 2];
        double dx = (2 * x[3 * v] - x[3 * b0] - x[3 * b1]) / 3;
        double dy = (2 * x[3 * v + 1] - x[3 * b0 + 1] - x[3 * b1 + 1]) / 3;
        double dz = (2 * x[3 * v + 2] - x[3 * b0 + 2] - x[3 * b1 + 2]) / 3;
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    @Override public double evaluate(int i, Particles p) { return centroidDistance(i, p) - restDistance[i]; }

    @Override public void gradient(int i, Particles p, double[] out) {
        Arrays.fill(out, 0, 9, 0);
        double[] x = p.x;
        int b0 = particles[3 * i], v = particles[3 * i + 1], b1 = particles[3 * i + 2];
        double dx = (2 * x[3 * v] - x[3 * b0] - x[3 * b1]) / 3;
        double dy = (2 * x[3 * v + 1] - x[3 * b0 + 1] - x[3 * b1 + 1]) / 3;
        double dz = (2 * x[3 * v + 2] - x[3 * b0 + 2] - x[3 * b1 + 2]) / 3;
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        if (len < DistanceBlock.MIN_LENGTH) return;
        double nx = dx / len, ny = dy / len, nz = dz / len;
        out[0] = out[6] = -nx / 3; out[1] = out[7] = -ny / 3; out[2] = out[8] = -nz / 3;
        out[3] = 2 * nx / 3; out[4] = 2 * ny / 3; out[5] = 2 * nz / 3;
    }

    @Override void project(int i, Particles p, SolverContext ctx) {
        final double[] x = p.x;
        final int b0 = particles[3 * i], v = particles[3 * i + 1], b1 = particles[3 * i + 2];
        final int i0 = 3 * b0, iv = 3 * v, i1 = 3 * b1;
        double dx = (2 * x[iv] - x[i0] - x[i1]) * (1.0 / 3);
        double dy = (2 * x[iv + 1] - x[i0 + 1] - x[i1 + 1]) * (1.0 / 3);
        double dz = (2 * x[iv + 2] - x[i0 + 2] - x[i1 + 2]) * (1.0 / 3);
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double C = len - restDistance[i];
        if (len < DistanceBlock.MIN_LENGTH) return;
        double w0 = p.w[b0], wv = p.w[v], w1 = p.w[b1];
        double dLambda = deltaLambda(i, C, (4 * wv + w0 + w1) * (1.0 / 9), ctx);
        double s = dLambda / (3 * len); // (1/3) n Δλ, with n = d/len
        double sv = 2 * wv * s, s0 = -w0 * s, s1 = -w1 * s;
        x[iv] += sv * dx; x[iv + 1] += sv * dy; x[iv + 2] += sv * dz;
        x[i0] += s0 * dx; x[i0 + 1] += s0 * dy; x[i0 + 2] += s0 * dz;
        x[i1] += s1 * dx; x[i1 + 1] += s1 * dy; x[i1 + 2] += s1 * dz;
    }

    @Override void projectRange(int from, int to, Particles p, SolverContext ctx) {
        for (int i = from; i < to; i++) project(i, p, ctx);
    }

    @Override void projectListed(int[] order, int from, int to, Particles p, SolverContext ctx) {
        for (int k = from; k < to; k++) project(order[k], p, ctx);
    }

    @Override BendConstraint view(int i) { return new BendConstraint(this, i); }

    @Override BendBlock emptyLike(int capacity) { return new BendBlock(family(), capacity); }

    @Override void copyRest(int i, ConstraintBlock from, int j) { restDistance[i] = ((BendBlock) from).restDistance[j]; }

    @Override void grow(int capacity) {
        super.grow(capacity);
        restDistance = Arrays.copyOf(restDistance, capacity);
    }
}
