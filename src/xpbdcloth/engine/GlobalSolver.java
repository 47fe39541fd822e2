package xpbdcloth.engine;

import java.util.Arrays;
import xpbdcloth.linalg.AggregationMultigrid;
import xpbdcloth.linalg.ChainSmoother;
import xpbdcloth.linalg.SparseMatrix;

/**
 * XPBD's constraint system for the stretch (the distance constraints, {@link #takes}) solved for all of
 * them at once (Macklin et al. 2016, eq. 11–12, the Schur complement of the KKT system): each iteration
 * linearises the constraints at the current positions and solves
 * <pre>
 *   (J W Jᵀ + α̃) Δλ = −C − α̃λ,    then   x += W Jᵀ Δλ,   λ += Δλ
 * </pre>
 * by preconditioned conjugate gradients, with a Jacobi or an aggregation-multigrid preconditioner, the
 * system widened by two rows per tensioned constraint that carry its geometric stiffness
 * ({@link GeometricStiffness}: J and W Jᵀ then include them, with a zero right-hand side). One iteration
 * is one Newton step of the same system whose Gauss–Seidel sweep is one projection per constraint;
 * Gauss–Seidel reduces local error fast and global error slowly, a global solve does both.
 *
 * <p>The topology (which constraint touches which particle, the sparsity patterns, the multigrid
 * hierarchy and its chains) is built once for a set of constraints and reused; each linearisation refills
 * values in place, so a step allocates nothing.
 */
final class GlobalSolver {
    /** The rows the system takes, as (block, index). */
    private final ConstraintBlock[] rowBlock;
    private final int[] rowIndex;
    /** Constraints, and rows of the system: the constraints', then two per {@link GeometricStiffness} entry. */
    private final int m, rows;
    private final GeometricStiffness geometric;
    private final boolean multigrid;
    private final double tolerance;
    private final int maxIterations;

    private final int[] entryStart, entryParticle, entryOwner;
    private final double[] grad;
    /** For each pair of entries on one particle: where their product goes in A, and the two entries. */
    private final int[] pairSlot, pairE, pairF;
    /** A = J W Jᵀ + α̃ over the constraint rows (with Levenberg–Marquardt damping). */
    private final SparseMatrix a;
    /**
     * The geometric-stiffness rows m, m+1, … of the system, as rows over all columns (constraint and
     * stiffness): their couplings to the constraint rows are A's missing columns, used transposed. Only
     * {@link #active} rows are filled and take part, so a cloth without significant tension solves the
     * same system, at the same cost, as without them.
     */
    private final int[] geoRowStart, geoCol, geoDiag;
    private final double[] geoVal;
    private final int[] geoPairStart, geoPairSlot, geoPairE, geoPairF;
    private final boolean[] active;
    /**
     * The stiffness rows' block among themselves (rows and columns numbered from 0), with {@link #geoToBlock}
     * mapping each geoVal entry into it (−1 for a constraint column), and its chains: the stiffness rows
     * of in-line edges couple like the edges' own rows, so with multigrid they are preconditioned by
     * exact solves along the constraint chains of the finest level (block Jacobi), and a tensioned
     * curtain's thousands of stiffness rows do not fall back on a diagonal. Inactive rows are the
     * identity there.
     */
    private final SparseMatrix geoBlock;
    private final int[] geoToBlock;
    private ChainSmoother geoChains;
    /** Chains with an active row, {@link #activeChainCount} of them; marks per chain, stamped per linearisation. */
    private int[] activeChains, chainStamp;
    private int activeChainCount, stamp;
    /** The rows active at the previous linearisation, reset to the identity in {@link #geoBlock} first. */
    private final int[] wasActive;
    private int wasActiveCount;
    /** The active stiffness rows (system row indices), {@link #activeCount} of them. */
    private final int[] activeRows;
    private int activeCount;
    private final double[] c, alphaTilde, b, dl, r, z, p, ap, scratch;
    /** W JᵀΔλ per particle coordinate, and the positions the line search starts from. */
    private final double[] move, start;
    /** Per particle, the most it may move in one iteration (m): {@link #MAX_MOVE} of its shortest distance constraint. */
    private final double[] reach;
    private AggregationMultigrid mg;
    /** Time to build the topology (entries, patterns, pair maps), once per constraint set. */
    private final long patternNanos;
    private int lastIterations, totalIterations, rejectedSteps;
    private double lastRelativeResidual;

    /**
     * Levenberg–Marquardt damping μ: the diagonal solved is d + max(α̃, μ d) with d = (J W Jᵀ)ᵢᵢ. Hard
     * constraints (α = 0) can outnumber the degrees of freedom (a pinned triangle mesh has about as many
     * edges as coordinates), so J W Jᵀ alone may be only semi-definite; the damping makes it definite, so
     * conjugate gradients and the multigrid's coarse Cholesky have a unique answer. Within a step it changes
     * the step, never the solution: at C + α̃λ = 0 the right-hand side is 0 and so is Δλ (Nocedal and
     * Wright 2006, §10.3). But one iteration per step never reaches that point, and the damped matrix then
     * biases the result: a 40-link chain (α̃ = 0.36/kg against d = 200/kg) settled 5.6e-4 off Hooke with
     * μ d added to every row. A compliance already larger than μ d makes the row definite by itself, so
     * such rows get none, and the chain settles within 1e-11 (7e-12).
     * It does not make an infeasible hard system feasible (pins pulled wider than a hard cloth's rest
     * shape): that cloth still tears, finitely; see docs/robustness.md.
     */
    static final double DAMPING = 1e-6;
    /** Armijo's sufficient-decrease constant: any small positive value; 1e-4 is the textbook one. */
    static final double ARMIJO = 1e-4;
    /** The shortest step the line search tries, relative to its first, before it gives the iteration up. */
    static final double MIN_STEP = 1.0 / 256;
    /** The most a particle may move in one global iteration, as a fraction of its shortest distance constraint. */
    static final double MAX_MOVE = 0.5;
    /** The least κ Σ cₖ² wₖ (geometric stiffness against the masses it moves) worth a pair of rows. */
    static final double SIGNIFICANT = 0.1;
    /** The most κ Σ cₖ² wₖ a stiffness row is given (see {@link #lineariseStiffness}). */
    static final double STIFFEST = 100;

    GlobalSolver(ConstraintRows constraints, int particleCount, boolean multigrid, double tolerance, int maxIterations) {
        long t0 = System.nanoTime();
        this.rowBlock = constraints.block;
        this.rowIndex = constraints.index;
        this.m = constraints.count();
        this.multigrid = multigrid;
        this.tolerance = tolerance;
        this.maxIterations = maxIterations;
        geometric = new GeometricStiffness(constraints);
        rows = m + 2 * geometric.count();
        entryStart = new int[rows + 1];
        int[][] ps = new int[rows][];
        int maxEntries = 0;
        for (int i = 0; i < rows; i++) {
            ps[i] = constraints.particles(i < m ? i : geometric.constraint[(i - m) / 2]);
            entryStart[i + 1] = entryStart[i] + ps[i].length;
            maxEntries = Math.max(maxEntries, ps[i].length);
        }
        int entries = entryStart[rows];
        entryParticle = new int[entries];
        entryOwner = new int[entries];
        for (int i = 0; i < rows; i++)
            for (int k = 0; k < ps[i].length; k++) {
                entryParticle[entryStart[i] + k] = ps[i][k];
                entryOwner[entryStart[i] + k] = i;
            }
        grad = new double[3 * entries];
        scratch = new double[3 * maxEntries];

        // Entries by particle, in entry order (so a particle's constraint rows come before its stiffness rows).
        int[] pStart = new int[particleCount + 1];
        for (int e = 0; e < entries; e++) pStart[entryParticle[e] + 1]++;
        for (int q = 0; q < particleCount; q++) pStart[q + 1] += pStart[q];
        int[] fill = pStart.clone(), byParticle = new int[entries];
        for (int e = 0; e < entries; e++) byParticle[fill[entryParticle[e]]++] = e;

        // Patterns: A over the constraint rows (rows sharing a particle), and the stiffness rows' own
        // rows over all columns (A's stiffness columns are their transpose).
        int[] rowStart = new int[rows + 1];
        int[] mark = new int[rows];
        Arrays.fill(mark, -1);
        int[][] rowCols = new int[rows][];
        int pairs = 0, geoPairs = 0;
        for (int i = 0; i < rows; i++) {
            int[] buf = new int[16];
            int nb = 0;
            for (int e = entryStart[i]; e < entryStart[i + 1]; e++) {
                int q = entryParticle[e];
                for (int t = pStart[q]; t < pStart[q + 1]; t++) {
                    int j = entryOwner[byParticle[t]];
                    if (i < m && j >= m) continue;
                    if (i < m) pairs++; else geoPairs++;
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
        a = new SparseMatrix(m, Arrays.copyOf(rowStart, m + 1), col);
        int g = rows - m;
        geoRowStart = new int[g + 1];
        for (int j = 0; j < g; j++) geoRowStart[j + 1] = geoRowStart[j] + rowCols[m + j].length;
        geoCol = new int[geoRowStart[g]];
        geoVal = new double[geoCol.length];
        geoDiag = new int[g];
        for (int j = 0; j < g; j++) {
            System.arraycopy(rowCols[m + j], 0, geoCol, geoRowStart[j], rowCols[m + j].length);
            geoDiag[j] = geoRowStart[j] + Arrays.binarySearch(rowCols[m + j], m + j);
        }
        pairSlot = new int[pairs];
        pairE = new int[pairs];
        pairF = new int[pairs];
        geoPairStart = new int[g + 1];
        geoPairSlot = new int[geoPairs];
        geoPairE = new int[geoPairs];
        geoPairF = new int[geoPairs];
        int k = 0, kg = 0;
        for (int i = 0; i < rows; i++) {
            for (int e = entryStart[i]; e < entryStart[i + 1]; e++) {
                int q = entryParticle[e];
                for (int t = pStart[q]; t < pStart[q + 1]; t++) {
                    int f = byParticle[t], j = entryOwner[f];
                    if (i < m) {
                        if (j >= m) continue;
                        pairSlot[k] = a.find(i, j);
                        pairE[k] = e;
                        pairF[k] = f;
                        k++;
                    } else {
                        int row = i - m;
                        geoPairSlot[kg] = geoRowStart[row] + Arrays.binarySearch(rowCols[i], j);
                        geoPairE[kg] = e;
                        geoPairF[kg] = f;
                        kg++;
                    }
                }
            }
            if (i >= m) geoPairStart[i - m + 1] = kg;
        }
        active = new boolean[g];
        activeRows = new int[g];
        wasActive = new int[g];
        int[] blockStart = new int[g + 1];
        for (int j = 0; j < g; j++) {
            int own = 0;
            for (int c2 : rowCols[m + j]) if (c2 >= m) own++;
            blockStart[j + 1] = blockStart[j] + own;
        }
        int[] blockCol = new int[blockStart[g]];
        for (int j = 0, q = 0; j < g; j++) for (int c2 : rowCols[m + j]) if (c2 >= m) blockCol[q++] = c2 - m;
        geoBlock = new SparseMatrix(g, blockStart, blockCol);
        for (int j = 0; j < g; j++) geoBlock.val[geoBlock.diag[j]] = 1;
        geoToBlock = new int[geoCol.length];
        for (int j = 0; j < g; j++)
            for (int t = geoRowStart[j]; t < geoRowStart[j + 1]; t++) geoToBlock[t] = geoCol[t] >= m ? geoBlock.find(j, geoCol[t] - m) : -1;
        c = new double[m];
        alphaTilde = new double[rows];
        b = new double[rows];
        dl = new double[rows];
        r = new double[rows];
        z = new double[rows];
        p = new double[rows];
        ap = new double[rows];
        move = new double[3 * particleCount];
        start = new double[3 * particleCount];
        reach = new double[particleCount];
        Arrays.fill(reach, Double.POSITIVE_INFINITY);
        for (int i = 0; i < m; i++) {
            if (!(rowBlock[i] instanceof DistanceBlock)) continue;
            DistanceBlock edge = (DistanceBlock) rowBlock[i];
            double rest = edge.restLength(rowIndex[i]);
            if (rest <= 0) continue;
            for (int end = 0; end < 2; end++) {
                int q = edge.particle(rowIndex[i], end);
                reach[q] = Math.min(reach[q], MAX_MOVE * rest);
            }
        }
        patternNanos = System.nanoTime() - t0;
    }

    /** Whether a block's constraints go into the global system (the others are swept after each global step). */
    static boolean takes(ConstraintBlock b) { return b instanceof DistanceBlock; }

    boolean multigrid() { return multigrid; }
    /** Checks every row's particles after an iteration (the replay of a step that diverged). */
    void check(StepProbe probe) {
        for (int i = 0; i < m; i++) probe.check(rowBlock[i], rowIndex[i]);
    }
    double tolerance() { return tolerance; }
    int maxIterations() { return maxIterations; }
    int lastIterations() { return lastIterations; }
    int totalIterations() { return totalIterations; }
    double lastRelativeResidual() { return lastRelativeResidual; }
    /** Iterations whose step was not taken (no decrease of the merit, or a non-finite Δλ). */
    int rejectedSteps() { return rejectedSteps; }
    long multigridSetupNanos() { return mg == null ? 0 : mg.setupNanos; }
    /** The whole setup, once per constraint topology: patterns and pair maps, and the multigrid hierarchy. */
    long setupNanos() { return patternNanos + multigridSetupNanos(); }
    int multigridLevels() { return mg == null ? 0 : mg.levelCount(); }
    int multigridCoarsestSize() { return mg == null ? 0 : mg.coarsestSize(); }

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
        step(particles, ctx);
        geometric.remember(rowBlock, rowIndex);
    }

    private void step(Particles particles, SolverContext ctx) {
        linearise(particles, ctx);
        solve();
        double merit0 = dot(b, b);
        if (merit0 == 0) return;
        final double[] x = particles.x, w = particles.w;
        Arrays.fill(move, 0);
        for (int i = 0; i < m; i++) if (!addMove(i, w)) { rejectedSteps++; return; }
        for (int k = 0; k < activeCount; k++) if (!addMove(activeRows[k], w)) { rejectedSteps++; return; }
        System.arraycopy(x, 0, start, 0, x.length);
        double slope = -dot(b, b) + dot(b, r); // d/ds of ‖F‖² / 2 at s = 0, with F(0) = −b and F'(0) = b − r
        double first = longestStep();
        for (double s = first; s >= first * MIN_STEP; s *= 0.5) {
            for (int k = 0; k < x.length; k++) x[k] = start[k] + s * move[k];
            double merit = meritAt(particles, s);
            if (merit <= merit0 + 2 * ARMIJO * s * slope) {
                for (int i = 0; i < m; i++) rowBlock[i].lambda[rowIndex[i]] += s * dl[i];
                return;
            }
        }
        System.arraycopy(start, 0, x, 0, x.length);
        rejectedSteps++;
    }

    /** move += W gᵢᵀ Δλᵢ for row i; false if its Δλ is not finite. */
    private boolean addMove(int i, double[] w) {
        double d = dl[i];
        if (!Double.isFinite(d)) return false;
        for (int e = entryStart[i]; e < entryStart[i + 1]; e++) {
            int q = entryParticle[e];
            double s = w[q] * d;
            move[3 * q] += s * grad[3 * e];
            move[3 * q + 1] += s * grad[3 * e + 1];
            move[3 * q + 2] += s * grad[3 * e + 2];
        }
        return true;
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
            ConstraintBlock blk = rowBlock[i];
            int j = rowIndex[i];
            double f = blk.evaluate(j, particles) + alphaTilde[i] * (blk.lambda[j] + s * dl[i]);
            sum += f * f;
        }
        return sum;
    }

    private void linearise(Particles particles, SolverContext ctx) {
        for (int i = 0; i < m; i++) {
            ConstraintBlock blk = rowBlock[i];
            int j = rowIndex[i];
            c[i] = blk.evaluate(j, particles);
            alphaTilde[i] = blk.compliance(j) * ctx.inverseH2; // XPBD only: SolverSettings refuses PBD here
            blk.gradient(j, particles, scratch);
            int n = 3 * (entryStart[i + 1] - entryStart[i]);
            System.arraycopy(scratch, 0, grad, 3 * entryStart[i], n);
            b[i] = -c[i] - alphaTilde[i] * blk.lambda[j];
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
            else a.val[a.diag[i]] += Math.max(alphaTilde[i], DAMPING * a.val[a.diag[i]]);
        }
        lineariseStiffness(particles);
        if (multigrid) {
            if (mg == null) mg = new AggregationMultigrid(a);
            else mg.refresh();
            if (rows > m) refreshStiffnessChains();
        }
    }

    /**
     * Fills the stiffness rows of the constraints whose tension matters here: a row pair is active when
     * κ Σ cₖ² wₖ ≥ {@link #SIGNIFICANT}, the geometric stiffness against the masses it moves. Below that
     * it changes a particle's transverse response by less than 10 %, far from where leaving it explicit
     * goes unstable (near 1: a zigzag grows when h² w T / l passes about ½ per edge), and is left out (its
     * rows zero), so a cloth whose substeps are short next to its tension pays little for it: on
     * `hanging` (h = 2 ms) about 250 of its 3968 stiffness rows are on, on the 20 ms curtain all.
     * κ Σ cₖ² wₖ is capped at {@link #STIFFEST}, a bound on how much stiffer than the masses a row may
     * make the system; a precaution, not a measured need (a featherweight cloth, 1 µg particles, behaved
     * the same with a cap of 10: what it needed was more CG iterations, now 300 by default).
     */
    private void lineariseStiffness(Particles particles) {
        final double[] w = particles.w;
        System.arraycopy(activeRows, 0, wasActive, 0, activeCount);
        wasActiveCount = activeCount;
        activeCount = 0;
        for (int j = 0; j < geometric.count(); j++) {
            int row = m + 2 * j, e0 = entryStart[row], e1 = entryStart[row + 1], e2 = entryStart[row + 2];
            double compliance = geometric.fill(j, particles, rowBlock[geometric.constraint[j]], rowIndex[geometric.constraint[j]], grad, 3 * e0, 3 * e1);
            double wSum = 0;
            for (int e = e0; e < e1; e++) {
                double gx = grad[3 * e], gy = grad[3 * e + 1], gz = grad[3 * e + 2];
                wSum += w[entryParticle[e]] * (gx * gx + gy * gy + gz * gz);
            }
            // Hysteresis: a pair stays on down to half the threshold. Without it rows near the threshold
            // switched on and off from step to step, and `hanging`'s largest strain jumped between 0.02 %
            // and 0.15 % every few steps.
            boolean on = wSum > 0 && wSum >= (active[2 * j] ? SIGNIFICANT / 2 : SIGNIFICANT) * compliance;
            compliance = Math.max(compliance, wSum / STIFFEST);
            active[2 * j] = active[2 * j + 1] = on;
            if (!on) {
                Arrays.fill(grad, 3 * e0, 3 * e2, 0);
                dl[row] = dl[row + 1] = r[row] = r[row + 1] = z[row] = z[row + 1] = p[row] = p[row + 1] = ap[row] = ap[row + 1] = b[row] = b[row + 1] = 0;
                continue;
            }
            alphaTilde[row] = alphaTilde[row + 1] = compliance;
            b[row] = b[row + 1] = 0;
            activeRows[activeCount++] = row;
            activeRows[activeCount++] = row + 1;
        }
        for (int k = 0; k < activeCount; k++) {
            int j = activeRows[k] - m;
            Arrays.fill(geoVal, geoRowStart[j], geoRowStart[j + 1], 0);
            for (int t = geoPairStart[j]; t < geoPairStart[j + 1]; t++) {
                int e = 3 * geoPairE[t], f = 3 * geoPairF[t];
                geoVal[geoPairSlot[t]] += w[entryParticle[geoPairE[t]]] * (grad[e] * grad[f] + grad[e + 1] * grad[f + 1] + grad[e + 2] * grad[f + 2]);
            }
            geoVal[geoDiag[j]] += alphaTilde[m + j]; // ≥ Σ cₖ² wₖ / STIFFEST: definite without damping
        }
    }

    /** Copies the active stiffness rows into {@link #geoBlock}, refactors its chains and lists those with an active row. */
    private void refreshStiffnessChains() {
        if (geoChains == null) geoChains = new ChainSmoother(geoBlock, stiffnessChains(mg.chains()));
        for (int k = 0; k < wasActiveCount; k++) {
            int j = wasActive[k] - m;
            for (int q = geoBlock.rowStart[j]; q < geoBlock.rowStart[j + 1]; q++) geoBlock.val[q] = 0;
            geoBlock.val[geoBlock.diag[j]] = 1;
        }
        stamp++;
        activeChainCount = 0;
        for (int k = 0; k < activeCount; k++) {
            int j = activeRows[k] - m;
            for (int t = geoRowStart[j]; t < geoRowStart[j + 1]; t++) if (geoToBlock[t] >= 0) geoBlock.val[geoToBlock[t]] = geoVal[t];
            int c = geoChains.chainOf(j);
            if (chainStamp[c] != stamp) { chainStamp[c] = stamp; activeChains[activeChainCount++] = c; }
        }
        // Symmetry: an active row's entry in an inactive row was zeroed above and is 0 in geoVal too (zero gradients).
        geoChains.refresh();
    }

    /**
     * The stiffness rows' chains: for each chain of constraint rows c₀, c₁, …, the first stiffness rows
     * of those constraints in the same order, and the second ones; a constraint without stiffness rows
     * ends a chain, and any stiffness row left over is a chain of its own.
     */
    private int[][] stiffnessChains(ChainSmoother constraintChains) {
        int g = rows - m;
        int[] pairOf = new int[m];
        java.util.Arrays.fill(pairOf, -1);
        for (int j = 0; j < geometric.count(); j++) pairOf[geometric.constraint[j]] = j;
        int[] order = new int[g], start = new int[g + 1];
        boolean[] placed = new boolean[g];
        int pos = 0, chains = 0;
        int[] cOrder = constraintChains.order(), cStart = constraintChains.start();
        for (int c = 0; c + 1 < cStart.length; c++)
            for (int side = 0; side < 2; side++) {
                int prev = -1;
                for (int k = cStart[c]; k < cStart[c + 1]; k++) {
                    int j = pairOf[cOrder[k]];
                    if (j < 0) { prev = -1; continue; }
                    int row = 2 * j + side;
                    // A new chain wherever the next row does not couple to the last (a constraint without stiffness rows between them).
                    if (prev < 0 || geoBlock.find(row, prev) < 0) start[chains++] = pos;
                    order[pos++] = row;
                    placed[row] = true;
                    prev = row;
                }
            }
        for (int r = 0; r < g; r++) if (!placed[r]) { start[chains++] = pos; order[pos++] = r; }
        start[chains] = pos;
        activeChains = new int[chains];
        chainStamp = new int[chains];
        return new int[][] {order, java.util.Arrays.copyOf(start, chains + 1)};
    }

    /** y = A x over the whole system (constraint rows, then the active stiffness rows). */
    private void multiply(double[] x, double[] y) {
        a.multiply(x, y);
        for (int k = 0; k < activeCount; k++) {
            int row = activeRows[k], j = row - m;
            double s = 0, xr = x[row];
            for (int t = geoRowStart[j]; t < geoRowStart[j + 1]; t++) {
                int col = geoCol[t];
                double v = geoVal[t];
                s += v * x[col]; // an inactive column's x is 0
                if (col < m) y[col] += v * xr;
            }
            y[row] = s;
        }
    }

    /**
     * The multigrid V-cycle (or Jacobi) on the constraint rows and Jacobi on the stiffness rows: a
     * block-diagonal preconditioner, symmetric and positive definite as conjugate gradients need. The
     * hierarchy is built once for the constraints' topology, which the stiffness rows (switched on and
     * off with the tension) do not change.
     */
    private void precondition(double[] in, double[] out) {
        if (multigrid) {
            mg.apply(in, out);
            if (activeCount > 0) geoChains.solveChains(activeChains, activeChainCount, in, out, m);
            return;
        }
        for (int i = 0; i < m; i++) out[i] = in[i] / a.val[a.diag[i]];
        for (int k = 0; k < activeCount; k++) {
            int row = activeRows[k];
            out[row] = in[row] / geoVal[geoDiag[row - m]];
        }
    }

    /** Conjugate gradients on A Δλ = b from Δλ = 0, to ‖r‖ ≤ tolerance·‖b‖. */
    private void solve() {
        fill(dl, 0);
        copy(b, r);
        double bNorm = Math.sqrt(dot(b, b));
        lastIterations = 0;
        lastRelativeResidual = 0;
        if (bNorm == 0) return;
        precondition(r, z);
        copy(z, p);
        double rz = dot(r, z);
        for (int it = 1; it <= maxIterations; it++) {
            multiply(p, ap);
            double pap = dot(p, ap);
            if (pap <= 0) break;
            double alpha = rz / pap;
            axpy(alpha, p, dl);
            axpy(-alpha, ap, r);
            lastIterations = it;
            lastRelativeResidual = Math.sqrt(dot(r, r)) / bNorm;
            if (!(lastRelativeResidual > tolerance)) break; // converged, or NaN: the line search rejects it
            precondition(r, z);
            double rzNew = dot(r, z);
            double beta = rzNew / rz;
            rz = rzNew;
            for (int i = 0; i < m; i++) p[i] = z[i] + beta * p[i];
            for (int k = 0; k < activeCount; k++) { int i = activeRows[k]; p[i] = z[i] + beta * p[i]; }
        }
        totalIterations += lastIterations;
    }

    // Vector operations over the constraint rows and the active stiffness rows (the others stay 0).
    private double dot(double[] u, double[] v) {
        double s = 0;
        for (int i = 0; i < m; i++) s += u[i] * v[i];
        for (int k = 0; k < activeCount; k++) { int i = activeRows[k]; s += u[i] * v[i]; }
        return s;
    }

    private void axpy(double alpha, double[] x, double[] y) {
        for (int i = 0; i < m; i++) y[i] += alpha * x[i];
        for (int k = 0; k < activeCount; k++) { int i = activeRows[k]; y[i] += alpha * x[i]; }
    }

    private void copy(double[] from, double[] to) {
        System.arraycopy(from, 0, to, 0, m);
        for (int k = 0; k < activeCount; k++) { int i = activeRows[k]; to[i] = from[i]; }
    }

    private void fill(double[] v, double value) {
        Arrays.fill(v, 0, m, value);
        for (int k = 0; k < activeCount; k++) v[activeRows[k]] = value;
    }

    /** Active stiffness rows after the last linearisation (two per tensioned constraint that counts). */
    int activeStiffnessRows() { return activeCount; }

    /** The dense A over the constraint rows and the active stiffness rows, in that order (tests compare PCG against a direct solve). */
    double[][] denseMatrix() {
        int n = m + activeCount;
        int[] index = new int[rows];
        Arrays.fill(index, -1);
        for (int i = 0; i < m; i++) index[i] = i;
        for (int k = 0; k < activeCount; k++) index[activeRows[k]] = m + k;
        double[][] d = new double[n][n];
        for (int i = 0; i < m; i++) for (int k = a.rowStart[i]; k < a.rowStart[i + 1]; k++) d[i][a.col[k]] = a.val[k];
        for (int k = 0; k < activeCount; k++) {
            int j = activeRows[k] - m;
            for (int t = geoRowStart[j]; t < geoRowStart[j + 1]; t++) {
                int col = index[geoCol[t]];
                if (col < 0) continue;
                d[m + k][col] = geoVal[t];
                d[col][m + k] = geoVal[t];
            }
        }
        return d;
    }

    /** Values of the constraint rows and active stiffness rows of v, in {@link #denseMatrix}'s order. */
    private double[] packed(double[] v) {
        double[] out = new double[m + activeCount];
        System.arraycopy(v, 0, out, 0, m);
        for (int k = 0; k < activeCount; k++) out[m + k] = v[activeRows[k]];
        return out;
    }

    /** Linearises and solves without moving anything (tests that need the hierarchy, not the matrix). */
    void linearSolveForTest(Particles particles, SolverContext ctx) {
        linearise(particles, ctx);
        solve();
    }

    /** Linearises and solves without moving anything: returns {A, b, Δλ} for tests. */
    double[][][] linearSystemForTest(Particles particles, SolverContext ctx) {
        linearSolveForTest(particles, ctx);
        return new double[][][] {denseMatrix(), {packed(b)}, {packed(dl)}};
    }
}
