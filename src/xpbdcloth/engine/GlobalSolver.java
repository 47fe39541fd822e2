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
    private AggregationMultigrid mg;
    private int lastIterations, totalIterations;
    private double lastRelativeResidual;

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
    }

    boolean multigrid() { return multigrid; }
    double tolerance() { return tolerance; }
    int maxIterations() { return maxIterations; }
    int lastIterations() { return lastIterations; }
    int totalIterations() { return totalIterations; }
    double lastRelativeResidual() { return lastRelativeResidual; }
    long multigridSetupNanos() { return mg == null ? 0 : mg.setupNanos; }
    int multigridLevels() { return mg == null ? 0 : mg.levelCount(); }

    /** One global iteration: linearise, solve for Δλ, move the particles and accumulate λ. */
    void iterate(Particles particles, SolverContext ctx) {
        linearise(particles, ctx);
        solve();
        final double[] x = particles.x, w = particles.w;
        for (int i = 0; i < m; i++) {
            double d = dl[i];
            cs[i].lambda += d;
            for (int e = entryStart[i]; e < entryStart[i + 1]; e++) {
                int q = entryParticle[e];
                double s = w[q] * d;
                x[3 * q] += s * grad[3 * e];
                x[3 * q + 1] += s * grad[3 * e + 1];
                x[3 * q + 2] += s * grad[3 * e + 2];
            }
        }
    }

    private void linearise(Particles particles, SolverContext ctx) {
        for (int i = 0; i < m; i++) {
            Constraint con = cs[i];
            c[i] = con.evaluate(particles);
            con.lastC = c[i];
            alphaTilde[i] = ctx.mode == ConstraintMode.XPBD ? con.compliance() * ctx.inverseH2 : 0;
            con.gradient(particles, scratch);
            int n = 3 * (entryStart[i + 1] - entryStart[i]);
            System.arraycopy(scratch, 0, grad, 3 * entryStart[i], n);
            b[i] = -c[i] - alphaTilde[i] * con.lambda;
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
            else a.val[a.diag[i]] += alphaTilde[i];
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
            if (lastRelativeResidual <= tolerance) break;
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
