package xpbdcloth.engine;

/**
 * Triangle bending constraint over three particles b₀, v, b₁ (v in the middle): keeps the distance from v
 * to the triangle's centroid c = (b₀ + b₁ + v)/3 at its rest value h₀.
 *
 * <pre>
 *   d = x_v − c = (2x_v − x_b₀ − x_b₁)/3,   C(x) = |d| − h₀,   n = d/|d|
 *   ∇_v C = (2/3) n,   ∇_b₀ C = ∇_b₁ C = −(1/3) n,   Σ wᵢ|∇ᵢC|² = (4w_v + w_b₀ + w_b₁)/9
 * </pre>
 * Source: Kelager, Niebe, Erleben 2010, "A Triangle Bending Constraint Model for Position-Based
 * Dynamics". Why not a dihedral angle: the dihedral constraint needs acos of a normal product and
 * normalised cross products of two triangles, whose gradients blow up as a triangle degenerates and whose
 * C is flat near 0 and π; the centroid distance is a plain length with a bounded gradient (|∇C| ≤ 2/3),
 * needs one square root, and works on a rope as well as a cloth.
 * Degenerate case: a straight triple at rest has h₀ = 0 and, once straight again, d = 0 with no
 * direction n; the projection is then skipped, which is right because C = |d| − 0 = 0 is satisfied.
 */
public final class BendConstraint extends Constraint {
    final int b0, v, b1;
    final double restDistance;

    public BendConstraint(ConstraintFamily family, int b0, int v, int b1, double restDistance) {
        super(family);
        if (b0 == v || b1 == v || b0 == b1)
            throw new IllegalArgumentException("particles must be distinct, was " + b0 + ", " + v + ", " + b1);
        this.b0 = Check.atLeast("b0", b0, 0);
        this.v = Check.atLeast("v", v, 0);
        this.b1 = Check.atLeast("b1", b1, 0);
        this.restDistance = Check.nonNegative("restDistance", restDistance);
    }

    /** A bend constraint at the particles' current shape. */
    public static BendConstraint atCurrentShape(ConstraintFamily family, Particles p, int b0, int v, int b1) {
        BendConstraint c = new BendConstraint(family, b0, v, b1, 0);
        return new BendConstraint(family, b0, v, b1, c.centroidDistance(p));
    }

    public double restDistance() { return restDistance; }

    /** |x_v − centroid|. */
    public double centroidDistance(Particles p) {
        double[] x = p.x;
        double dx = (2 * x[3 * v] - x[3 * b0] - x[3 * b1]) / 3;
        double dy = (2 * x[3 * v + 1] - x[3 * b0 + 1] - x[3 * b1 + 1]) / 3;
        double dz = (2 * x[3 * v + 2] - x[3 * b0 + 2] - x[3 * b1 + 2]) / 3;
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    @Override public int[] particles() { return new int[] {b0, v, b1}; }

    @Override public double evaluate(Particles p) { return centroidDistance(p) - restDistance; }

    @Override public void gradient(Particles p, double[] out) {
        java.util.Arrays.fill(out, 0, 9, 0);
        double[] x = p.x;
        double dx = (2 * x[3 * v] - x[3 * b0] - x[3 * b1]) / 3;
        double dy = (2 * x[3 * v + 1] - x[3 * b0 + 1] - x[3 * b1 + 1]) / 3;
        double dz = (2 * x[3 * v + 2] - x[3 * b0 + 2] - x[3 * b1 + 2]) / 3;
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        if (len < DistanceConstraint.MIN_LENGTH) return;
        double nx = dx / len, ny = dy / len, nz = dz / len;
        out[0] = out[6] = -nx / 3; out[1] = out[7] = -ny / 3; out[2] = out[8] = -nz / 3;
        out[3] = 2 * nx / 3; out[4] = 2 * ny / 3; out[5] = 2 * nz / 3;
    }

    @Override protected void project(Particles p, SolverContext ctx) {
        final double[] x = p.x;
        final int i0 = 3 * b0, iv = 3 * v, i1 = 3 * b1;
        double dx = (2 * x[iv] - x[i0] - x[i1]) * (1.0 / 3);
        double dy = (2 * x[iv + 1] - x[i0 + 1] - x[i1 + 1]) * (1.0 / 3);
        double dz = (2 * x[iv + 2] - x[i0 + 2] - x[i1 + 2]) * (1.0 / 3);
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double C = len - restDistance;
        if (len < DistanceConstraint.MIN_LENGTH) return;
        double w0 = p.w[b0], wv = p.w[v], w1 = p.w[b1];
        double dLambda = deltaLambda(C, (4 * wv + w0 + w1) * (1.0 / 9), ctx);
        double s = dLambda / (3 * len); // (1/3) n Δλ, with n = d/len
        double sv = 2 * wv * s, s0 = -w0 * s, s1 = -w1 * s;
        x[iv] += sv * dx; x[iv + 1] += sv * dy; x[iv + 2] += sv * dz;
        x[i0] += s0 * dx; x[i0 + 1] += s0 * dy; x[i0 + 2] += s0 * dz;
        x[i1] += s1 * dx; x[i1 + 1] += s1 * dy; x[i1 + 2] += s1 * dz;
    }
}
