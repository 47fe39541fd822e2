package xpbdcloth.engine;

import java.util.Arrays;

/**
 * Shear (angle) constraints: each keeps the angle between two edges that meet at a vertex o,
 * e₁ = x₁ − x_o and e₂ = x₂ − x_o, at its rest value θ₀ (for a grid cloth: the row and column edges at a
 * vertex, θ₀ = π/2; on a general mesh, the angle at each face's first corner, see {@link MeshClothBuilder}).
 *
 * <pre>
 *   C(x)  = acos(ê₁·ê₂) − θ₀,                    c = ê₁·ê₂,  sin θ = √(1 − c²)
 *   ∂ê/∂e = (I − êêᵀ) / |e|                       (the gradient of a normalised edge)
 *   ∇₁C   = −(I − ê₁ê₁ᵀ) ê₂ / (|e₁| sin θ) = −(ê₂ − c ê₁) / (|e₁| sin θ)
 *   ∇₂C   = −(ê₁ − c ê₂) / (|e₂| sin θ),          ∇_o C = −(∇₁C + ∇₂C)
 * </pre>
 * |∇₁C| = 1/|e₁| and |∇₂C| = 1/|e₂| because |ê₂ − c ê₁| = sin θ. Particle order: o, end 1, end 2.
 * Source: the original simulator's shear constraint (seed text), an angle constraint in the family of
 * Müller et al. 2007 §4; normalised-edge gradient as in any vector-calculus text.
 * Degenerate cases: at θ = 0 or π (edges parallel or anti-parallel) the direction (ê₂ − c ê₁)/sin θ is
 * undefined and the projection is skipped; so is a zero-length edge. No NaN can leave this class.
 * Trust region: θ is far from linear in the positions. When only the vertex can move and it is far from
 * its two pinned ends, ∇_o C = −(∇₁C + ∇₂C) nearly cancels and the linearised step C/|∇_o C| flings the
 * vertex away, which shrinks θ further (a divergent Newton step, found by the fuzzer). So no particle
 * moves more than half its shorter edge in one projection; λ records only what was applied.
 */
public final class ShearBlock extends ConstraintBlock {
    /** Below this sin θ the edges count as parallel. */
    static final double MIN_SIN = 1e-9;
    /** The most a particle may move in one projection, as a fraction of the shorter edge. */
    static final double MAX_MOVE = 0.5;

    /** θ₀ per constraint, radians. */
    double[] restAngle;

    public ShearBlock(ConstraintFamily family, int capacity) {
        super(family, 3, capacity);
        restAngle = new double[lambda.length];
    }

    /** Adds a constraint keeping the angle at {@code vertex} between its edges to end1 and end2 at restAngle. */
    public int add(int vertex, int end1, int end2, double angle) {
        if (vertex == end1 || vertex == end2 || end1 == end2)
            throw new IllegalArgumentException("particles must be distinct, was " + vertex + ", " + end1 + ", " + end2);
        Check.atLeast("vertex", vertex, 0);
        Check.atLeast("end1", end1, 0);
        Check.atLeast("end2", end2, 0);
        Check.inRange("restAngle", angle, 0, Math.PI);
        int i = newSlot();
        particles[3 * i] = vertex;
        particles[3 * i + 1] = end1;
        particles[3 * i + 2] = end2;
        restAngle[i] = angle;
        return i;
    }

    /** Adds a constraint at the particles' current angle. */
    public int addAtCurrentAngle(Particles p, int vertex, int end1, int end2) {
        int i = add(vertex, end1, end2, 0);
        restAngle[i] = angle(i, p);
        return i;
    }

    public double restAngle(int i) { return restAngle[i]; }

    /** Whether the corner at {@code vertex} has an angle now: both its sides longer than {@link DistanceBlock#MIN_LENGTH}. */
    static boolean hasAngle(Particles p, int vertex, int end1, int end2) {
        return side(p, vertex, end1) >= DistanceBlock.MIN_LENGTH && side(p, vertex, end2) >= DistanceBlock.MIN_LENGTH;
    }

    private static double side(Particles p, int a, int b) {
        double dx = p.x[3 * b] - p.x[3 * a], dy = p.x[3 * b + 1] - p.x[3 * a + 1], dz = p.x[3 * b + 2] - p.x[3 * a + 2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /** The current angle θ of constraint i in radians (π/2 if an edge has zero length). */
    public double angle(int i, Particles p) {
        double[] x = p.x;
        int o = particles[3 * i], p1 = particles[3 * i + 1], p2 = particles[3 * i + 2];
        double e1x = x[3 * p1] - x[3 * o], e1y = x[3 * p1 + 1] - x[3 * o + 1], e1z = x[3 * p1 + 2] - x[3 * o + 2];
        double e2x = x[3 * p2] - x[3 * o], e2y = x[3 * p2 + 1] - x[3 * o + 1], e2z = x[3 * p2 + 2] - x[3 * o + 2];
        double l1 = Math.sqrt(e1x * e1x + e1y * e1y + e1z * e1z), l2 = Math.sqrt(e2x * e2x + e2y * e2y + e2z * e2z);
        if (l1 < DistanceBlock.MIN_LENGTH || l2 < DistanceBlock.MIN_LENGTH) return Math.PI / 2;
        double c = (e1x * e2x + e1y * e2y + e1z * e2z) / (l1 * l2);
        return Math.acos(Math.max(-1, Math.min(1, c)));
    }

    @Override public double evaluate(int i, Particles p) { return angle(i, p) - restAngle[i]; }

    @Override public void gradient(int i, Particles p, double[] out) {
        Arrays.fill(out, 0, 9, 0);
        double[] x = p.x;
        int o = particles[3 * i], p1 = particles[3 * i + 1], p2 = particles[3 * i + 2];
        double e1x = x[3 * p1] - x[3 * o], e1y = x[3 * p1 + 1] - x[3 * o + 1], e1z = x[3 * p1 + 2] - x[3 * o + 2];
        double e2x = x[3 * p2] - x[3 * o], e2y = x[3 * p2 + 1] - x[3 * o + 1], e2z = x[3 * p2 + 2] - x[3 * o + 2];
        double l1 = Math.sqrt(e1x * e1x + e1y * e1y + e1z * e1z), l2 = Math.sqrt(e2x * e2x + e2y * e2y + e2z * e2z);
        if (l1 < DistanceBlock.MIN_LENGTH || l2 < DistanceBlock.MIN_LENGTH) return;
        e1x /= l1; e1y /= l1; e1z /= l1;
        e2x /= l2; e2y /= l2; e2z /= l2;
        double c = Math.max(-1, Math.min(1, e1x * e2x + e1y * e2y + e1z * e2z));
        double sin = Math.sqrt(1 - c * c);
        if (sin < MIN_SIN) return;
        double s1 = -1 / (l1 * sin), s2 = -1 / (l2 * sin);
        out[3] = s1 * (e2x - c * e1x); out[4] = s1 * (e2y - c * e1y); out[5] = s1 * (e2z - c * e1z);
        out[6] = s2 * (e1x - c * e2x); out[7] = s2 * (e1y - c * e2y); out[8] = s2 * (e1z - c * e2z);
        out[0] = -(out[3] + out[6]); out[1] = -(out[4] + out[7]); out[2] = -(out[5] + out[8]);
    }

    @Override void project(int i, Particles p, SolverContext ctx) {
        final double[] x = p.x;
        final int o = particles[3 * i], p1 = particles[3 * i + 1], p2 = particles[3 * i + 2];
        final int io = 3 * o, i1 = 3 * p1, i2 = 3 * p2;
        double e1x = x[i1] - x[io], e1y = x[i1 + 1] - x[io + 1], e1z = x[i1 + 2] - x[io + 2];
        double e2x = x[i2] - x[io], e2y = x[i2 + 1] - x[io + 1], e2z = x[i2 + 2] - x[io + 2];
        double l1 = Math.sqrt(e1x * e1x + e1y * e1y + e1z * e1z), l2 = Math.sqrt(e2x * e2x + e2y * e2y + e2z * e2z);
        if (l1 < DistanceBlock.MIN_LENGTH || l2 < DistanceBlock.MIN_LENGTH) return;
        double inv1 = 1 / l1, inv2 = 1 / l2;
        e1x *= inv1; e1y *= inv1; e1z *= inv1;
        e2x *= inv2; e2y *= inv2; e2z *= inv2;
        double c = Math.max(-1, Math.min(1, e1x * e2x + e1y * e2y + e1z * e2z));
        double C = Math.acos(c) - restAngle[i];
        double sin = Math.sqrt(1 - c * c);
        if (sin < MIN_SIN) return;
        double s1 = -inv1 / sin, s2 = -inv2 / sin;
        double g1x = s1 * (e2x - c * e1x), g1y = s1 * (e2y - c * e1y), g1z = s1 * (e2z - c * e1z);
        double g2x = s2 * (e1x - c * e2x), g2y = s2 * (e1y - c * e2y), g2z = s2 * (e1z - c * e2z);
        double g0x = -(g1x + g2x), g0y = -(g1y + g2y), g0z = -(g1z + g2z);
        double w0 = p.w[o], w1 = p.w[p1], w2 = p.w[p2];
        double wGradSq = w0 * (g0x * g0x + g0y * g0y + g0z * g0z) + w1 * inv1 * inv1 + w2 * inv2 * inv2;
        double dLambda = deltaLambda(i, C, wGradSq, ctx);
        double largestMove = Math.abs(dLambda) * Math.max(w0 * Math.sqrt(g0x * g0x + g0y * g0y + g0z * g0z), Math.max(w1 * inv1, w2 * inv2));
        double allowed = MAX_MOVE * Math.min(l1, l2);
        if (largestMove > allowed) {
            double scale = allowed / largestMove;
            lambda[i] -= dLambda * (1 - scale); // λ keeps only what was applied
            dLambda *= scale;
        }
        double a0 = w0 * dLambda, a1 = w1 * dLambda, a2 = w2 * dLambda;
        x[io] += a0 * g0x; x[io + 1] += a0 * g0y; x[io + 2] += a0 * g0z;
        x[i1] += a1 * g1x; x[i1 + 1] += a1 * g1y; x[i1 + 2] += a1 * g1z;
        x[i2] += a2 * g2x; x[i2 + 1] += a2 * g2y; x[i2 + 2] += a2 * g2z;
    }

    @Override void projectRange(int from, int to, Particles p, SolverContext ctx) {
        for (int i = from; i < to; i++) project(i, p, ctx);
    }

    @Override void projectListed(int[] order, int from, int to, Particles p, SolverContext ctx) {
        for (int k = from; k < to; k++) project(order[k], p, ctx);
    }

    @Override ShearConstraint view(int i) { return new ShearConstraint(this, i); }

    @Override ShearBlock emptyLike(int capacity) { return new ShearBlock(family(), capacity); }

    @Override void copyRest(int i, ConstraintBlock from, int j) { restAngle[i] = ((ShearBlock) from).restAngle[j]; }

    @Override void grow(int capacity) {
        super.grow(capacity);
        restAngle = Arrays.copyOf(restAngle, capacity);
    }
}
