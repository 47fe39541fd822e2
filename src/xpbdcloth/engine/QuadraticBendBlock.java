package xpbdcloth.engine;

import java.util.Arrays;

/**
 * Bending on an interior edge of a flat rest mesh as a linear vector constraint (the isometric bending
 * of Bergou, Wardetzky, Harmon, Zorin, Grinspun 2006, "A Quadratic Bending Model for Inextensible
 * Surfaces"): the hinge's four points may not leave the plane they were flat in.
 *
 * <pre>
 *   particles: p₀, p₁ the two opposite vertices, p₂–p₃ the shared edge (as {@link DihedralBlock})
 *   C(x) = Σ_k c_k x_k ∈ ℝ³    three rows, its x, y and z components
 *   c: the affine dependency of the four flat rest points (Σ c_k = 0, Σ c_k x̄_k = 0), scaled so
 *      c₀ = 1/h₀, c₁ = 1/h₁ (hₖ the distance of pₖ from the edge's line): then |C| = 2 sin(θ/2) ≈ θ
 *      for a hinge bent by θ, whatever rigid motion or in-plane affine stretch the cloth also has
 *   ∇_k C_a = c_k e_a,   Σ_k w_k |∇_k C_a|² = Σ_k w_k c_k²   (the same for the three rows, which are independent)
 *   α = (A₀ + A₁) / (B |e|²)     as DihedralBlock: a small bend stores ½ B |e|² θ² / (A₀ + A₁)
 * </pre>
 * Why: the energy is quadratic in x, so a projection solves its constraint exactly, with no angle, no
 * square root and a constant gradient (what a dihedral projection spends on atan2 and three norms).
 * It equals the dihedral energy for small bends and saturates at 4 sin²(θ/2) for large ones (a hinge
 * folded flat pushes back no harder than one folded at 90°), which a cloth's fold spread over several
 * edges never reaches. Rotations leave C unchanged (Σ c_k = 0), so the energy is that of the bend alone.
 * It needs a flat rest: {@link #isFlat} tells, and a hinge bent at rest stays a {@link DihedralBlock}.
 * A block may hold {@link BendingPatch} rows instead (up to twelve particles, three rows per triangle), the same
 * kind of constraint, C linear in x, with an energy that does not depend on the triangulation.
 * Degenerate case: a zero-height triangle has no dependency; it is refused when added.
 */
public final class QuadraticBendBlock extends ConstraintBlock {
    /** c_k of each unit, {@link #arity()} per unit (four for a hinge, up to twelve for a patch row). */
    double[] coefficient;
    /** Whether the units are patch rows (any arity) rather than hinges (four particles). */
    private final boolean patch;
    /** α·B per unit, so α = this / B: (A₀ + A₁)/|e|² for a hinge, 1 for a patch row (its C carries √A). */
    double[] complianceTimesStiffness;
    /** A patch block's rows' particles and coefficients in the coloured sweep's order ({@link #layOutIn}). */
    private int[] sweepParticles;
    private double[] sweepCoefficient;

    /** A block of hinges (four particles each). */
    public QuadraticBendBlock(ConstraintFamily family, int hingeCapacity) { this(family, 4, false, hingeCapacity); }

    /**
     * A block of {@link BendingPatch} rows on {@code slots} particles each (added by {@link #addPatch}): 12 for
     * a triangle inside a mesh, fewer near its edges.
     */
    public static QuadraticBendBlock patches(ConstraintFamily family, int slots, int triangleCapacity) {
        if (slots < 4 || slots > BendingPatch.MAX_SLOTS) throw new IllegalArgumentException("slots must be within [4, " + BendingPatch.MAX_SLOTS + "], was " + slots);
        return new QuadraticBendBlock(family, slots, true, 3 * Math.max(triangleCapacity, 1));
    }

    private QuadraticBendBlock(ConstraintFamily family, int arity, boolean patch, int unitCapacity) {
        super(family, arity, 3, 3 * Math.max(unitCapacity, 1));
        this.patch = patch;
        coefficient = new double[arity * (lambda.length / 3)];
        complianceTimesStiffness = new double[lambda.length / 3];
    }

    /** A unit's three rows are C's components: one compliance for the three. */
    @Override boolean rowsShareMaterial() { return true; }

    /** C = Σ c_k x_k: hinges and patch rows alike. */
    @Override public boolean isLinear() { return true; }

    /** Whether the units are {@link BendingPatch} rows rather than hinges. */
    public boolean isPatchBlock() { return patch; }

    /** Units in the block (three rows each): hinges, or a patch block's curvature rows (three per triangle). */
    public int hingeCount() { return count / 3; }

    /**
     * Whether the hinge (o0, o1 opposite the edge e0–e1) is flat within {@code tolerance} rad at the
     * particles' current positions: o0 and o1 on either side of the edge, and o1's distance from the plane
     * of (o0, e0, e1) at most {@code tolerance} times its distance from the edge.
     */
    public static boolean isFlat(Particles p, int o0, int o1, int e0, int e1, double tolerance) {
        double[] x = p.x;
        double ex = x[3 * e1] - x[3 * e0], ey = x[3 * e1 + 1] - x[3 * e0 + 1], ez = x[3 * e1 + 2] - x[3 * e0 + 2];
        double ax = x[3 * o0] - x[3 * e0], ay = x[3 * o0 + 1] - x[3 * e0 + 1], az = x[3 * o0 + 2] - x[3 * e0 + 2];
        double bx = x[3 * o1] - x[3 * e0], by = x[3 * o1 + 1] - x[3 * e0 + 1], bz = x[3 * o1 + 2] - x[3 * e0 + 2];
        double nx = ey * az - ez * ay, ny = ez * ax - ex * az, nz = ex * ay - ey * ax;
        double nl = Math.sqrt(nx * nx + ny * ny + nz * nz), el = Math.sqrt(ex * ex + ey * ey + ez * ez);
        if (!(nl > 0 && el > 0)) return false;
        double out = Math.abs(bx * nx + by * ny + bz * nz) / nl;
        double cx = by * ez - bz * ey, cy = bz * ex - bx * ez, cz = bx * ey - by * ex;
        double height = Math.sqrt(cx * cx + cy * cy + cz * cz) / el;
        // Either side: (e × a)·(e × b) < 0; with n = e × a and c = b × e = −(e × b), n·c > 0.
        boolean opposite = nx * cx + ny * cy + nz * cz > 0;
        return opposite && height > 0 && out <= tolerance * height;
    }

    /**
     * Adds a bend on edge (e0, e1) between the triangles with opposite vertices o0 and o1, flat at the
     * particles' current (rest) positions, with bending stiffness B (N·m per unit width).
     */
    public int addAtCurrentShape(Particles p, int o0, int o1, int e0, int e1, double bendingStiffness) {
        if (patch) throw new IllegalStateException("a patch block takes patches (addPatch), not hinges");
        int[] ids = {o0, o1, e0, e1};
        for (int a = 0; a < 4; a++) for (int b = a + 1; b < 4; b++)
            if (ids[a] == ids[b]) throw new IllegalArgumentException("particles must be distinct, was " + o0 + ", " + o1 + ", " + e0 + ", " + e1);
        double[] x = p.x;
        double ex = x[3 * e1] - x[3 * e0], ey = x[3 * e1 + 1] - x[3 * e0 + 1], ez = x[3 * e1 + 2] - x[3 * e0 + 2];
        double el2 = ex * ex + ey * ey + ez * ez, el = Math.sqrt(el2);
        // Each opposite point's position along the edge (s) and its distance from the edge's line (h).
        double s0 = 0, s1 = 0, h0 = 0, h1 = 0;
        for (int k = 0; k < 2; k++) {
            int o = k == 0 ? o0 : o1;
            double ax = x[3 * o] - x[3 * e0], ay = x[3 * o + 1] - x[3 * e0 + 1], az = x[3 * o + 2] - x[3 * e0 + 2];
            double along = (ax * ex + ay * ey + az * ez) / el;
            double cx = ay * ez - az * ey, cy = az * ex - ax * ez, cz = ax * ey - ay * ex;
            double height = Math.sqrt(cx * cx + cy * cy + cz * cz) / el;
            if (k == 0) { s0 = along; h0 = height; } else { s1 = along; h1 = height; }
        }
        if (!(el > 0 && h0 > 1e-9 * el && h1 > 1e-9 * el))
            throw new IllegalArgumentException("edge (" + e0 + ", " + e1 + ") between " + o0 + " and " + o1 + " has a zero-area triangle at rest");
        int u = hingeCount();
        for (int r = 0; r < 3; r++) {
            int i = newSlot();
            System.arraycopy(ids, 0, particles, 4 * i, 4);
        }
        if (coefficient.length < 4 * (u + 1)) growHinges(lambda.length / 3);
        // The opposite points lie on either side of the edge: c₀h₀ = c₁h₁ cancels the across-edge coordinate,
        // c₀s₀ + c₁s₁ + c₃|e| = 0 the along-edge one, and Σ c = 0 the translation.
        double c0 = 1 / h0, c1 = 1 / h1, c3 = -(c0 * s0 + c1 * s1) / el, c2 = -c0 - c1 - c3;
        coefficient[4 * u] = c0; coefficient[4 * u + 1] = c1; coefficient[4 * u + 2] = c2; coefficient[4 * u + 3] = c3;
        complianceTimesStiffness[u] = 0.5 * el * (h0 + h1) / el2;
        setBendingStiffness(u, bendingStiffness);
        return u;
    }

    /**
     * Adds a triangle's three curvature rows, as {@link BendingPatch#rows} gave them (n particles, c_rk at
     * rows[MAX_SLOTS·r + k]), with bending stiffness B (N·m); the block's arity must be n. Returns the first row's unit.
     */
    public int addPatch(int[] stencil, int n, double[] rows, double bendingStiffness) {
        if (!this.patch || arity() != n)
            throw new IllegalStateException("this block takes " + (this.patch ? "patches of " + arity() + " particles" : "hinges") + ", not a patch of " + n);
        int first = hingeCount();
        for (int r = 0; r < 3; r++) {
            int u = hingeCount();
            for (int row = 0; row < 3; row++) {
                int i = newSlot();
                System.arraycopy(stencil, 0, particles, n * i, n);
            }
            if (coefficient.length < n * (u + 1)) growHinges(lambda.length / 3);
            System.arraycopy(rows, BendingPatch.MAX_SLOTS * r, coefficient, n * u, n);
            // C is √A times the curvature, so α = 1/B gives ½ B A |H|².
            complianceTimesStiffness[u] = 1;
            setBendingStiffness(u, bendingStiffness);
        }
        return first;
    }

    /** Bending stiffness B (N·m) of hinge u: sets its rows' compliance. */
    public void setBendingStiffness(int u, double bendingStiffness) {
        Check.inRange("bendingStiffness", bendingStiffness, Double.MIN_NORMAL, 1e6);
        setCompliance(3 * u, complianceTimesStiffness[u] / bendingStiffness); // and its other two rows
    }

    /** |C| of hinge u: 2 sin(θ/2) for a hinge bent by θ from its flat rest. */
    public double bend(int u, Particles p) {
        double s = 0;
        for (int a = 0; a < 3; a++) { double c = evaluate(3 * u + a, p); s += c * c; }
        return Math.sqrt(s);
    }

    /** Row i: component i mod 3 of C of hinge i / 3. */
    @Override public double evaluate(int i, Particles p) {
        int u = i / 3, a = i % 3, n = arity(), base = 3 * n * u;
        double[] x = p.x;
        double c = 0;
        for (int k = 0; k < n; k++) c += coefficient[n * u + k] * x[3 * particles[base + k] + a];
        return c;
    }

    @Override public void gradient(int i, Particles p, double[] out) {
        int u = i / 3, a = i % 3;
        int n = arity();
        Arrays.fill(out, 0, 3 * n, 0);
        for (int k = 0; k < n; k++) out[3 * k + a] += coefficient[n * u + k];
    }

    /** Solved with its compliance in PBD mode too: α comes from the bending stiffness B. */
    @Override boolean compliantInAnyMode() { return true; }

    @Override void project(int u, Particles p, SolverContext ctx) {
        if (!patch) projectHinge(u, p, ctx);
        else projectPatchRow(u, p, ctx);
    }

    private void projectHinge(int u, Particles p, SolverContext ctx) {
        final double[] x = p.x, w = p.w;
        final int base = 12 * u, i = 3 * u;
        final int q0 = particles[base], q1 = particles[base + 1], q2 = particles[base + 2], q3 = particles[base + 3];
        final int a = 3 * q0, b = 3 * q1, c = 3 * q2, d = 3 * q3;
        final double c0 = coefficient[4 * u], c1 = coefficient[4 * u + 1], c2 = coefficient[4 * u + 2], c3 = coefficient[4 * u + 3];
        final double w0 = w[q0], w1 = w[q1], w2 = w[q2], w3 = w[q3];
        double cx = c0 * x[a] + c1 * x[b] + c2 * x[c] + c3 * x[d];
        double cy = c0 * x[a + 1] + c1 * x[b + 1] + c2 * x[c + 1] + c3 * x[d + 1];
        double cz = c0 * x[a + 2] + c1 * x[b + 2] + c2 * x[c + 2] + c3 * x[d + 2];
        double wGradSq = w0 * c0 * c0 + w1 * c1 * c1 + w2 * c2 * c2 + w3 * c3 * c3;
        double lx = deltaLambda(i, cx, wGradSq, ctx), ly = deltaLambda(i + 1, cy, wGradSq, ctx), lz = deltaLambda(i + 2, cz, wGradSq, ctx);
        double s0 = w0 * c0, s1 = w1 * c1, s2 = w2 * c2, s3 = w3 * c3;
        x[a] += s0 * lx; x[a + 1] += s0 * ly; x[a + 2] += s0 * lz;
        x[b] += s1 * lx; x[b + 1] += s1 * ly; x[b + 2] += s1 * lz;
        x[c] += s2 * lx; x[c + 1] += s2 * ly; x[c + 2] += s2 * lz;
        x[d] += s3 * lx; x[d + 1] += s3 * ly; x[d + 2] += s3 * lz;
    }

    /** One curvature row of a patch: up to twelve particles, the same arithmetic as a hinge. */
    private void projectPatchRow(int u, Particles p, SolverContext ctx) {
        projectPatchRow(u, particles, 3 * arity() * u, coefficient, arity() * u, p, ctx);
    }

    /** Patch row u with its particles at q[qBase …] and its coefficients at c[cBase …] (the block's, or the sweep-ordered copy's). */
    private void projectPatchRow(int u, int[] q, int qBase, double[] c, int cBase, Particles p, SolverContext ctx) {
        final double[] x = p.x, w = p.w;
        final int n = arity(), i = 3 * u;
        double cx = 0, cy = 0, cz = 0, wGradSq = 0;
        for (int k = 0; k < n; k++) {
            int xq = 3 * q[qBase + k];
            double ck = c[cBase + k];
            cx += ck * x[xq]; cy += ck * x[xq + 1]; cz += ck * x[xq + 2];
            wGradSq += w[q[qBase + k]] * ck * ck;
        }
        double lx = deltaLambda(i, cx, wGradSq, ctx), ly = deltaLambda(i + 1, cy, wGradSq, ctx), lz = deltaLambda(i + 2, cz, wGradSq, ctx);
        for (int k = 0; k < n; k++) {
            int xq = 3 * q[qBase + k];
            double s = w[q[qBase + k]] * c[cBase + k];
            x[xq] += s * lx; x[xq + 1] += s * ly; x[xq + 2] += s * lz;
        }
    }

    @Override void projectRange(int from, int to, Particles p, SolverContext ctx) {
        for (int u = from; u < to; u++) project(u, p, ctx);
    }

    @Override void projectListed(int[] order, int from, int to, Particles p, SolverContext ctx) {
        if (laidOutIn(order)) {
            final int n = arity();
            for (int k = from; k < to; k++) projectPatchRow(order[k], sweepParticles, n * k, sweepCoefficient, n * k, p, ctx);
        } else for (int k = from; k < to; k++) project(order[k], p, ctx);
    }

    /**
     * A patch block copies its rows' particles and coefficients into the coloured sweep's order: a colour
     * takes every few rows from all over the block, and a row's 12 indices and 12 coefficients read from
     * wherever it lies cost more than its arithmetic once the block outgrows the cache (the 64² fabric's
     * Gauss–Seidel step 2.4× the as-built order's). Read in order, the copy streams. The same rows, the same
     * arithmetic: the same bits. Hinges (four particles) are left as they are.
     */
    @Override boolean layOutIn(int[] order) {
        if (!patch) return false;
        final int n = arity();
        sweepParticles = inOrder(particles, 3 * n, n, order); // a row's three components list the same particles
        sweepCoefficient = inOrder(coefficient, n, n, order);
        return true;
    }

    @Override Constraint view(int i) { return new BlockConstraint(this, i); }

    @Override QuadraticBendBlock emptyLike(int capacity) { return new QuadraticBendBlock(family(), arity(), patch, (capacity + 2) / 3); }

    @Override void copyRest(int i, ConstraintBlock from, int j) {
        QuadraticBendBlock q = (QuadraticBendBlock) from;
        int u = i / 3, v = j / 3;
        int n = arity();
        if (coefficient.length < n * (u + 1)) growHinges(lambda.length / 3);
        System.arraycopy(q.coefficient, n * v, coefficient, n * u, n);
        complianceTimesStiffness[u] = q.complianceTimesStiffness[v];
    }

    @Override void grow(int capacity) {
        super.grow(capacity);
        growHinges(capacity / 3 + 1);
    }

    private void growHinges(int hinges) {
        if (coefficient.length < arity() * hinges) coefficient = Arrays.copyOf(coefficient, arity() * hinges);
        if (complianceTimesStiffness.length < hinges) complianceTimesStiffness = Arrays.copyOf(complianceTimesStiffness, hinges);
    }
}
