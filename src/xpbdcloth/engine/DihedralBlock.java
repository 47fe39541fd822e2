package xpbdcloth.engine;

import java.util.Arrays;

/**
 * Dihedral bending on an interior edge: the angle between the two triangles that share it keeps its rest
 * value, with a compliance that makes the sum over edges the continuum bending energy ½ B κ² per area.
 *
 * <pre>
 *   particles: p₀, p₁ the two opposite vertices, p₂–p₃ the shared edge e = x₃ − x₂
 *   n₀ = (x₀ − x₂) × (x₀ − x₃),  n₁ = (x₁ − x₃) × (x₁ − x₂)   (unnormalised; each |n| = 2A)
 *   θ = atan2((n̂₀ × n̂₁)·ê, n̂₀·n̂₁),   C(x) = θ − θ₀   (θ₀ the rest angle, wrapped into (−π, π])
 *   ∇₀C = −|e| n₀/|n₀|²,   ∇₁C = −|e| n₁/|n₁|²,   s_k = (x_k − x₂)·e/|e|²  (where p_k projects on the edge)
 *   ∇₂C = −(∇₀C (1 − s₀) + ∇₁C (1 − s₁)),   ∇₃C = −(∇₀C s₀ + ∇₁C s₁)   (Σ∇C = 0: translation invariance)
 *   α = (A₀ + A₁) / (B |e|²)     (B the bending stiffness per unit width, N·m)
 * </pre>
 * The gradient is Bridson, Marino, Fedkiw 2003, "Simulation of Clothing with Folds and Wrinkles", §4
 * (the four bending modes); atan2 keeps θ and its sign well defined through 0 and ±π, unlike acos of
 * n̂₀·n̂₁. The energy is the discrete-shell form ½ k (θ − θ₀)² with k ∝ |e|²/(A₀ + A₁) (Grinspun, Hirani,
 * Desbrun, Schröder 2003, "Discrete Shells"); with k = B |e|²/(A₀ + A₁) it equals ½ B κ² A on a grid,
 * square or equilateral, rolled into a cylinder along a row of edges (derived: the rows of triangles
 * become flat strips of width w, each turned by θ = κ w from the next, and there |e| w = A₀ + A₁, so
 * Σ ½ k θ² = ½ B κ² Σ (A₀ + A₁), the area the bent edges span; tested on rolled meshes). Rolled along a diagonal, a grid bends
 * its diagonal edges too and the sum differs: the discrete energy is not isotropic on every mesh.
 * Degenerate case: a triangle of zero area has no normal; the projection is skipped.
 */
public final class DihedralBlock extends ConstraintBlock {
    /** θ₀ per constraint, rad. */
    double[] restAngle;
    /** (A₀ + A₁)/|e|² at rest per constraint: α = this / B. */
    double[] areaOverEdgeSquared;

    public DihedralBlock(ConstraintFamily family, int capacity) {
        super(family, 4, capacity);
        restAngle = new double[lambda.length];
        areaOverEdgeSquared = new double[lambda.length];
    }

    /**
     * Adds a bend on edge (e0, e1) between the triangles with opposite vertices o0 and o1, at the
     * particles' current shape, with bending stiffness B (N·m per unit width).
     */
    public int addAtCurrentShape(Particles p, int o0, int o1, int e0, int e1, double bendingStiffness) {
        int[] ids = {o0, o1, e0, e1};
        for (int a = 0; a < 4; a++) for (int b = a + 1; b < 4; b++)
            if (ids[a] == ids[b]) throw new IllegalArgumentException("particles must be distinct, was " + o0 + ", " + o1 + ", " + e0 + ", " + e1);
        int i = newSlot();
        System.arraycopy(ids, 0, particles, 4 * i, 4);
        double[] x = p.x;
        double twoA0 = crossLength(x, o0, e0, e1), twoA1 = crossLength(x, o1, e1, e0), e2 = distanceSquared(x, e0, e1);
        if (!(twoA0 > 0 && twoA1 > 0 && e2 > 0)) {
            count--;
            throw new IllegalArgumentException("edge (" + e0 + ", " + e1 + ") between " + o0 + " and " + o1 + " has a zero-area triangle at rest");
        }
        areaOverEdgeSquared[i] = 0.5 * (twoA0 + twoA1) / e2;
        restAngle[i] = angle(i, p);
        setBendingStiffness(i, bendingStiffness);
        return i;
    }

    /**
     * Adds a bend that is flat at rest (θ₀ = 0) on edge (e0, e1) between triangles given by their rest shape,
     * (A₀ + A₁)/|e|², not by where the particles are now: a hinge across a seam still open, whose two
     * triangles meet only once it is sewn. It starts with the given compliance (see {@link #setBendingStiffness}).
     */
    public int addFlat(int o0, int o1, int e0, int e1, double restAreaOverEdgeSquared, double compliance) {
        int[] ids = {o0, o1, e0, e1};
        for (int a = 0; a < 4; a++) for (int b = a + 1; b < 4; b++)
            if (ids[a] == ids[b]) throw new IllegalArgumentException("particles must be distinct, was " + o0 + ", " + o1 + ", " + e0 + ", " + e1);
        Check.positive("restAreaOverEdgeSquared", restAreaOverEdgeSquared);
        int i = newSlot();
        System.arraycopy(ids, 0, particles, 4 * i, 4);
        areaOverEdgeSquared[i] = restAreaOverEdgeSquared;
        restAngle[i] = 0;
        setCompliance(i, compliance);
        return i;
    }

    /** Bending stiffness B (N·m) of constraint i: sets its compliance. */
    public void setBendingStiffness(int i, double bendingStiffness) {
        Check.inRange("bendingStiffness", bendingStiffness, Double.MIN_NORMAL, 1e6);
        setCompliance(i, areaOverEdgeSquared[i] / bendingStiffness);
    }

    public double restAngle(int i) { return restAngle[i]; }

    /** (A₀ + A₁)/|e|² of constraint i at rest, 1 (its curvature is |θ − θ₀| over this times |e|). */
    public double restAreaOverEdgeSquared(int i) { return areaOverEdgeSquared[i]; }

    /** The signed dihedral angle θ of constraint i, rad. */
    public double angle(int i, Particles p) { return angleAndGradient(i, p.x, null); }

    private static double crossLength(double[] x, int o, int a, int b) {
        double ux = x[3 * o] - x[3 * a], uy = x[3 * o + 1] - x[3 * a + 1], uz = x[3 * o + 2] - x[3 * a + 2];
        double vx = x[3 * o] - x[3 * b], vy = x[3 * o + 1] - x[3 * b + 1], vz = x[3 * o + 2] - x[3 * b + 2];
        double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
        return Math.sqrt(cx * cx + cy * cy + cz * cz);
    }

    private static double distanceSquared(double[] x, int a, int b) {
        double dx = x[3 * a] - x[3 * b], dy = x[3 * a + 1] - x[3 * b + 1], dz = x[3 * a + 2] - x[3 * b + 2];
        return dx * dx + dy * dy + dz * dz;
    }

    /**
     * θ of constraint i, and ∇θ into g[0..11] (p₀, p₁, p₂, p₃) unless g is null; NaN (and g untouched)
     * when a triangle has no normal.
     */
    double angleAndGradient(int i, double[] x, double[] g) {
        final int a = 3 * particles[4 * i], b = 3 * particles[4 * i + 1], c = 3 * particles[4 * i + 2], d = 3 * particles[4 * i + 3];
        double ex = x[d] - x[c], ey = x[d + 1] - x[c + 1], ez = x[d + 2] - x[c + 2];
        double el2 = ex * ex + ey * ey + ez * ez;
        // n₀ = (x₀ − x₂) × (x₀ − x₃), n₁ = (x₁ − x₃) × (x₁ − x₂)
        double ax = x[a] - x[c], ay = x[a + 1] - x[c + 1], az = x[a + 2] - x[c + 2];
        double a3x = x[a] - x[d], a3y = x[a + 1] - x[d + 1], a3z = x[a + 2] - x[d + 2];
        double n0x = ay * a3z - az * a3y, n0y = az * a3x - ax * a3z, n0z = ax * a3y - ay * a3x;
        double bx = x[b] - x[d], by = x[b + 1] - x[d + 1], bz = x[b + 2] - x[d + 2];
        double b2x = x[b] - x[c], b2y = x[b + 1] - x[c + 1], b2z = x[b + 2] - x[c + 2];
        double n1x = by * b2z - bz * b2y, n1y = bz * b2x - bx * b2z, n1z = bx * b2y - by * b2x;
        double n0sq = n0x * n0x + n0y * n0y + n0z * n0z, n1sq = n1x * n1x + n1y * n1y + n1z * n1z;
        double tiny = 1e-24 * el2 * el2;
        if (!(n0sq > tiny && n1sq > tiny && el2 > 0)) return Double.NaN;
        double el = Math.sqrt(el2), n0l = Math.sqrt(n0sq), n1l = Math.sqrt(n1sq);
        double cos = (n0x * n1x + n0y * n1y + n0z * n1z) / (n0l * n1l);
        double cx = n0y * n1z - n0z * n1y, cy = n0z * n1x - n0x * n1z, cz = n0x * n1y - n0y * n1x;
        double sin = (cx * ex + cy * ey + cz * ez) / (n0l * n1l * el);
        double theta = Math.atan2(sin, cos);
        if (g == null) return theta;
        double k0 = -el / n0sq, k1 = -el / n1sq;
        double s0 = (ax * ex + ay * ey + az * ez) / el2, s1 = (b2x * ex + b2y * ey + b2z * ez) / el2;
        g[0] = k0 * n0x; g[1] = k0 * n0y; g[2] = k0 * n0z;
        g[3] = k1 * n1x; g[4] = k1 * n1y; g[5] = k1 * n1z;
        for (int k = 0; k < 3; k++) {
            g[6 + k] = -(g[k] * (1 - s0) + g[3 + k] * (1 - s1));
            g[9 + k] = -(g[k] * s0 + g[3 + k] * s1);
        }
        return theta;
    }

    /** θ − θ₀ wrapped into (−π, π]: a fold through the flat state is one angle, not two. */
    double wrapped(int i, double theta) {
        double c = theta - restAngle[i];
        if (c > Math.PI) c -= 2 * Math.PI;
        else if (c <= -Math.PI) c += 2 * Math.PI;
        return c;
    }

    @Override public double evaluate(int i, Particles p) {
        double theta = angle(i, p);
        return Double.isNaN(theta) ? 0 : wrapped(i, theta);
    }

    @Override public void gradient(int i, Particles p, double[] out) {
        Arrays.fill(out, 0, 12, 0);
        angleAndGradient(i, p.x, out);
    }

    /** The gradient's scratch space, one per thread (the parallel sweeps project one block from several threads). */
    private final ThreadLocal<double[]> scratch = ThreadLocal.withInitial(() -> new double[12]);

    /** Solved with its compliance in PBD mode too: α comes from the bending stiffness B. */
    @Override boolean compliantInAnyMode() { return true; }

    @Override void project(int i, Particles p, SolverContext ctx) {
        project(i, p, ctx, scratch.get());
    }

    private void project(int i, Particles p, SolverContext ctx, double[] g) {
        final double[] x = p.x;
        double theta = angleAndGradient(i, x, g);
        if (Double.isNaN(theta)) return;
        double C = wrapped(i, theta);
        final int base = 4 * i;
        double wGradSq = 0;
        for (int k = 0; k < 4; k++) {
            int q = particles[base + k];
            wGradSq += p.w[q] * (g[3 * k] * g[3 * k] + g[3 * k + 1] * g[3 * k + 1] + g[3 * k + 2] * g[3 * k + 2]);
        }
        double dLambda = deltaLambda(i, C, wGradSq, ctx);
        for (int k = 0; k < 4; k++) {
            int q = particles[base + k];
            double s = p.w[q] * dLambda;
            x[3 * q] += s * g[3 * k]; x[3 * q + 1] += s * g[3 * k + 1]; x[3 * q + 2] += s * g[3 * k + 2];
        }
    }

    @Override void projectRange(int from, int to, Particles p, SolverContext ctx) {
        double[] g = scratch.get();
        for (int i = from; i < to; i++) project(i, p, ctx, g);
    }

    @Override void projectListed(int[] order, int from, int to, Particles p, SolverContext ctx) {
        double[] g = scratch.get();
        for (int k = from; k < to; k++) project(order[k], p, ctx, g);
    }

    @Override Constraint view(int i) { return new BlockConstraint(this, i); }

    @Override DihedralBlock emptyLike(int capacity) { return new DihedralBlock(family(), capacity); }

    @Override void copyRest(int i, ConstraintBlock from, int j) {
        restAngle[i] = ((DihedralBlock) from).restAngle[j];
        areaOverEdgeSquared[i] = ((DihedralBlock) from).areaOverEdgeSquared[j];
    }

    @Override void grow(int capacity) {
        super.grow(capacity);
        restAngle = Arrays.copyOf(restAngle, capacity);
        areaOverEdgeSquared = Arrays.copyOf(areaOverEdgeSquared, capacity);
    }
}
