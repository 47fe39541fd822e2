package xpbdcloth.engine;

import java.util.Arrays;

/**
 * XPBD's constraint system solved for all constraints at once (Macklin et al. 2016, eq. 11–12, the
 * Schur complement of the KKT system): each iteration linearises the constraints at the current
 * positions and solves
 * <pre>
 *   (J W Jᵀ + α̃) Δλ = −C − α̃λ,    then   x += W Jᵀ Δλ,   λ += Δλ
 * </pre>
 * by preconditioned conjugate gradients, with a Jacobi or an aggregation-multigrid preconditioner. One
 * iteration of it is one Newton step of the same system whose Gauss–Seidel sweep is one projection per
 * constraint; Gauss–Seidel reduces local error fast and global error slowly, a global solve does both.
 *
 * <p>The topology (which constraint touches which particle, the sparsity pattern of J W Jᵀ, the
 * multigrid hierarchy) is built once for a set of constraints and reused; each linearisation refills
 * values in place, so a step allocates nothing.
 */
final class GlobalSolver {
    private final Constraint[] cs;
    private final int m;
    private final boolean multigrid;
    private final double tolerance;
    private final int maxIterations;

    private final int[] entryStart, entryParticle, entryOwner;
    private final double[] grad;
    /** For each pair of entries on one particle: where their product goes in A, and the two entries. */
    private final int[] pairSlot, pairE, pairF;
    private final SparseMatrix a;
    private final double[] c, alphaTilde, b, dl, r, z, p, ap, scratch;
    /** W JᵀΔλ per particle coordinate, and the positions the line search starts from. */
    private final double[] move, start;
    /** Per particle, the most it may move in one iteration (m): {@link #MAX_MOVE} of its shortest distance constraint. */
    private final double[] reach;
    private AggregationMultigrid mg;
    private int lastIterations, totalIterations, rejectedSteps;
    private double lastRelativeResidual;

    /**
     * Levenberg–Marquardt damping μ: the matrix solved is J W Jᵀ + μ·diag(J W Jᵀ) + α̃. Hard constraints
     * (α = 0) outnumber the degrees of freedom of a cloth with all three families (4865 against 3066 at
     * 32²), so J W Jᵀ alone is only semi-definite; the damping makes it definite, so conjugate gradients
     * and the multigrid's coarse Cholesky have a unique answer. It changes the step, never the solution:
     * at C + α̃λ = 0 the right-hand side is 0 and so is Δλ (Nocedal and Wright 2006, §10.3). It does not
     * make an infeasible hard system feasible (pins pulled wider than a hard cloth's rest shape): that
     * cloth still tears, finitely; see the README's Robustness section.
     */
    static final double DAMPING = 1e-6;
    /** Armijo's sufficient-decrease constant: any small positive value; 1e-4 is the textbook one. */
    static final double ARMIJO = 1e-4;
    /** The shortest step the line search tries, relative to its first, before it gives the iteration up. */
    static final double MIN_STEP = 1.0 / 256;
    /** The most a particle may move in one global iteration, as a fraction of its shortest distance constraint. */
    static final double MAX_MOVE = 0.5;

    GlobalSolver(Constraint[] constraints, int particleCount, boolean multigrid, double tolerance, int maxIterations) {
        this.cs = constraints;
        this.m = constraints.length;
        this.multigrid = multigrid;
        this.tolerance = tolerance;
        this.maxIterations = maxIterations;
        entryStart = new int[m + 1];
        int[][] ps = new int[m][];
        int maxEntries = 0;
        for (int i = 0; i < m; i++) {
            ps[i] = constraints[i].particles();
            entryStart[i + 1] = entryStart[i] + ps[i].length;
            maxEntries = Math.max(maxEntries, ps[i].length);
        }
        int entries = entryStart[m];
        entryParticle = new int[entries];
        entryOwner = new int[entries];
        for (int i = 0; i < m; i++)
            for (int k = 0; k < ps[i].length; k++) {
                entryParticle[entryStart[i] + k] = ps[i][k];
                entryOwner[entryStart[i] + k] = i;
            }
        grad = new double[3 * entries];
        scratch = new double[3 * maxEntries];

        // Entries by particle.
        int[] pStart = new int[particleCount + 1];
        for (int e = 0; e < entries; e++) pStart[entryParticle[e] + 1]++;
        for (int q = 0; q < particleCount; q++) pStart[q + 1] += pStart[q];
        int[] fill = pStart.clone(), byParticle = new int[entries];
        for (int e = 0; e < entries; e++) byParticle[fill[entryParticle[e]]++] = e;

        // Pattern of A: constraints sharing a particle.
        int[] rowStart = new int[m + 1];
        int[] mark = new int[m];
        Arrays.fill(mark, -1);
        int[][] rowCols = new int[m][];
        int pairs = 0;
        for (int i = 0; i < m; i++) {
            int[] buf = new int[16];
            int nb = 0;
            for (int e = entryStart[i]; e < entryStart[i + 1]; e++) {
                int q = entryParticle[e];
                for (int t = pStart[q]; t < pStart[q + 1]; t++) {
                    int j = entryOwner[byParticle[t]];
                    pairs++;
                    if (mark[j] != i) {
                        mark[j] = i;
                        if (nb == buf.length) buf = Arrays.copyOf(buf, 2 * nb);
                        buf[nb++] = j;
                    }
                }
            }
            rowCols[i] = Arrays.copyOf(buf, nb);
            Arrays.sort(rowCols[i]);
            rowStart[i + 1] = rowStart[i] + nb;
        }
        int[] col = new int[rowStart[m]];
        for (int i = 0; i < m; i++) System.arraycopy(rowCols[i], 0, col, rowStart[i], rowCols[i].length);
        a = new SparseMatrix(m, rowStart, col);
        pairSlot = new int[pairs];
        pairE = new int[pairs];
        pairF = new int[pairs];
        int k = 0;
        for (int i = 0; i < m; i++)
            for (int e = entryStart[i]; e < entryStart[i + 1]; e++) {
                int q = entryParticle[e];
                for (int t = pStart[q]; t < pStart[q + 1]; t++) {
                    int f = byParticle[t];
                    pairSlot[k] = a.find(i, entryOwner[f]);
                    pairE[k] = e;
                    pairF[k] = f;
                    k++;
                }
            }
        c = new double[m];
        alphaTilde = new double[m];
        b = new double[m];
        dl = new double[m];
        r = new double[m];
        z = new double[m];
        p = new double[m];
        ap = new double[m];
        move = new double[3 * particleCount];
        start = new double[3 * particleCount];
        reach = new double[particleCount];
        Arrays.fill(reach, Double.POSITIVE_INFINITY);
        for (Constraint con : constraints) {
            if (!(con instanceof DistanceConstraint) || ((DistanceConstraint) con).restLength() <= 0) continue;
            double r = MAX_MOVE * ((DistanceConstraint) con).restLength();
            for (int q : con.particles()) reach[q] = Math.min(reach[q], r);
        }
    }

    boolean multigrid() { return multigrid; }
    Constraint[] constraints() { return cs; }
    double tolerance() { return tolerance; }
    int maxIterations() { return maxIterations; }
    int lastIterations() { return lastIterations; }
    int totalIterations() { return totalIterations; }
    double lastRelativeResidual() { return lastRelativeResidual; }
    /** Iterations whose step was not taken (no decrease of the merit, or a non-finite Δλ). */
    int rejectedSteps() { return rejectedSteps; }
    long multigridSetupNanos() { return mg == null ? 0 : mg.setupNanos; }
    int multigridLevels() { return mg == null ? 0 : mg.levelCount(); }

    /**
     * One global iteration: linearise, solve for Δλ, then move the particles by x += s·W JᵀΔλ and
     * λ += s·Δλ with the longest step s ∈ {s₀, s₀/2, s₀/4, …} that lowers the merit ‖C(x) + α̃λ‖² by
     * Armijo's rule (Nocedal and Wright 2006, §3.1 and §11.2). Δλ makes the merit's slope −‖b‖²(1 − η)
     * at s = 0 for a linear solve to relative residual η < 1, so near a solution s = 1 is taken and the
     * iteration is the plain Newton step; far from one (a sphere or a pin has just moved the cloth a long way, a
     * grab, thin triangles) the linearisation overshoots, and without the search the overshoot grew
     * from step to step until positions overflowed (24 of 300 fuzz cloths under Jacobi-PCG). A step
     * with no decrease at s = s₀/256, or a Δλ that is not finite, is not taken: the iteration then moves
     * nothing, which is never wrong, only slow. s₀ ≤ 1 is the trust region ({@link #longestStep}).
     */
    void iterate(Particles particles, SolverContext ctx) {
        linearise(particles, ctx);
        solve();
        double merit0 = dot(b, b);
        if (merit0 == 0) return;
        final double[] x = particles.x, w = particles.w;
        Arrays.fill(move, 0);
        for (int i = 0; i < m; i++) {
            double d = dl[i];
            if (!Double.isFinite(d)) { rejectedSteps++; return; }
            for (int e = entryStart[i]; e < entryStart[i + 1]; e++) {
                int q = entryParticle[e];
                double s = w[q] * d;
                move[3 * q] += s * grad[3 * e];
                move[3 * q + 1] += s * grad[3 * e + 1];
                move[3 * q + 2] += s * grad[3 * e + 2];
            }
        }
        System.arraycopy(x, 0, start, 0, x.length);
        double slope = -dot(b, b) + dot(b, r); // d/ds of ‖F‖² / 2 at s = 0, with F(0) = −b and F'(0) = b − r
        double first = longestStep();
        for (double s = first; s >= first * MIN_STEP; s *= 0.5) {
            for (int k = 0; k < x.length; k++) x[k] = start[k] + s * move[k];
            double merit = meritAt(particles, s);
            if (merit <= merit0 + 2 * ARMIJO * s * slope) {
                for (int i = 0; i < m; i++) cs[i].block.lambda[cs[i].index] += s * dl[i];
                return;
            }
        }
        System.arraycopy(start, 0, x, 0, x.length);
        rejectedSteps++;
    }

    /**
     * The trust region: the largest s ≤ 1 at which no particle moves more than its {@link #reach}. Far
     * from a solution (a collider has just pushed particles out by its radius) the Newton step asks for
     * moves of many edge lengths that still lower the merit; taken, they became velocities of tens of
     * m/s. Gauss–Seidel's projections move a particle at most to its constraint, and so does this.
     */
    private double longestStep() {
        double first = 1;
        for (int q = 0; q < reach.length; q++) {
            double mx = move[3 * q], my = move[3 * q + 1], mz = move[3 * q + 2];
            double m2 = mx * mx + my * my + mz * mz;
            if (m2 > reach[q] * reach[q]) first = Math.min(first, reach[q] / Math.sqrt(m2));
        }
        return first;
    }

    /** ‖C(x) + α̃(λ + s·Δλ)‖² at the current positions (a NaN merit compares false: rejected). */
    private double meritAt(Particles particles, double s) {
        double sum = 0;
        for (int i = 0; i < m; i++) {
            double f = cs[i].evaluate(particles) + alphaTilde[i] * (cs[i].lambda() + s * dl[i]);
            sum += f * f;
        }
        return sum;
    }

    private void linearise(Particles particles, SolverContext ctx) {
        for (int i = 0; i < m; i++) {
            Constraint con = cs[i];
            c[i] = con.evaluate(particles);
            alphaTilde[i] = con.compliance() * ctx.inverseH2; // XPBD only: SolverSettings refuses PBD here
            con.gradient(particles, scratch);
            int n = 3 * (entryStart[i + 1] - entryStart[i]);
            System.arraycopy(scratch, 0, grad, 3 * entryStart[i], n);
            b[i] = -c[i] - alphaTilde[i] * con.lambda();
        }
        Arrays.fill(a.val, 0);
        final double[] w = particles.w;
        for (int k = 0; k < pairSlot.length; k++) {
            int e = 3 * pairE[k], f = 3 * pairF[k];
            a.val[pairSlot[k]] += w[entryParticle[pairE[k]]] * (grad[e] * grad[f] + grad[e + 1] * grad[f + 1] + grad[e + 2] * grad[f + 2]);
        }
        for (int i = 0; i < m; i++) {
            // A constraint on pinned particles only (a zero row) keeps a unit diagonal and gets Δλ = 0.
            if (a.val[a.diag[i]] + alphaTilde[i] <= 0) { a.val[a.diag[i]] = 1; b[i] = 0; }
            else a.val[a.diag[i]] = (1 + DAMPING) * a.val[a.diag[i]] + alphaTilde[i];
        }
        if (multigrid) {
            if (mg == null) mg = new AggregationMultigrid(a);
            else mg.refresh();
        }
    }

    private void precondition(double[] in, double[] out) {
        if (multigrid) mg.apply(in, out);
        else for (int i = 0; i < m; i++) out[i] = in[i] / a.val[a.diag[i]];
    }

    /** Conjugate gradients on A Δλ = b from Δλ = 0, to ‖r‖ ≤ tolerance·‖b‖. */
    private void solve() {
        Arrays.fill(dl, 0);
        System.arraycopy(b, 0, r, 0, m);
        double bNorm = Math.sqrt(dot(b, b));
        lastIterations = 0;
        lastRelativeResidual = 0;
        if (bNorm == 0) return;
        precondition(r, z);
        System.arraycopy(z, 0, p, 0, m);
        double rz = dot(r, z);
        for (int it = 1; it <= maxIterations; it++) {
            a.multiply(p, ap);
            double pap = dot(p, ap);
            if (pap <= 0) break;
            double alpha = rz / pap;
            for (int i = 0; i < m; i++) { dl[i] += alpha * p[i]; r[i] -= alpha * ap[i]; }
            lastIterations = it;
            lastRelativeResidual = Math.sqrt(dot(r, r)) / bNorm;
            if (!(lastRelativeResidual > tolerance)) break; // converged, or NaN: the line search rejects it
            precondition(r, z);
            double rzNew = dot(r, z);
            double beta = rzNew / rz;
            rz = rzNew;
            for (int i = 0; i < m; i++) p[i] = z[i] + beta * p[i];
        }
        totalIterations += lastIterations;
    }

    private static double dot(double[] u, double[] v) {
        double s = 0;
        for (int i = 0; i < u.length; i++) s += u[i] * v[i];
        return s;
    }

    /** The dense A (tests compare PCG against a direct solve). */
    double[][] denseMatrix() {
        double[][] d = new double[m][m];
        for (int i = 0; i < m; i++) for (int k = a.rowStart[i]; k < a.rowStart[i + 1]; k++) d[i][a.col[k]] = a.val[k];
        return d;
    }

    /** Linearises and solves without moving anything: returns {A, b, Δλ} for tests. */
    double[][][] linearSystemForTest(Particles particles, SolverContext ctx) {
        linearise(particles, ctx);
        solve();
        return new double[][][] {denseMatrix(), {b.clone()}, {dl.clone()}};
    }
}
