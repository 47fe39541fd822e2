package xpbdcloth.linalg;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * An unsmoothed-aggregation algebraic multigrid V-cycle for the constraint system A = J W Jᵀ + α̃,
 * used as the preconditioner of conjugate gradients (MGPBD, Li et al. 2025, after Vaněk et al.).
 *
 * <p>Setup (once per constraint topology, "lazy"): constraints i, j are strongly connected when
 * |A_ij| ≥ θ √(A_ii A_jj) with θ = 0.25 (θ = 0, every coupling, where that would shrink a level by
 * less than 10 %: aggressive coarsening as a fallback); aggregates are grown greedily (a seed and its
 * strong neighbours, then leftovers join a neighbouring aggregate), each level's from its own values;
 * the prolongator P is the binary map from a constraint to its aggregate; coarse operators are Galerkin
 * products A_c = Pᵀ A P, whose pattern and scatter map are built once so that refreshing values after
 * each linearisation costs O(nnz). Levels are added until at most {@link #COARSEST} unknowns remain,
 * which are solved by dense Cholesky.
 *
 * <p>The cycle is symmetric (a forward sweep before the coarse correction, a backward one after), as
 * conjugate gradients require. For a grid cloth's structural edges, perpendicular edges do not couple
 * (their gradients are orthogonal at rest), so aggregates follow the rows and columns: the hierarchy is
 * then the geometric one along each grid line, and needs no grid knowledge. The same fact makes the
 * finest level's smoother a line smoother ({@link ChainSmoother}): it solves each grid line's chain of
 * rows exactly, which a point Gauss–Seidel sweep does one row at a time; with it one linear solve takes
 * one CG iteration at 32² to 256² on a flat grid (31 / 47 / 69 at 32² / 64² / 128² with point smoothing)
 * and 5–6 on a crumpled one, so the coarse levels only carry what couples the lines.
 *
 * <p>On a triangle mesh of hard edges it is no better than a diagonal: the edges outnumber the in-plane
 * degrees of freedom, A equals α̃ on their self-stresses (Jᵀ Δλ = 0), a space about as large as the mesh,
 * which neither a smoother nor a coarse space reaches (docs/experiments.md, experiment 12).
 */
public final class AggregationMultigrid {
    public static final int COARSEST = 64;
    /** A Cholesky pivot below this fraction of its diagonal counts as zero (semi-definite A). */
    private static final double PIVOT_TOLERANCE = 1e-12;
    private static final double STRENGTH = 0.25;
    /** Smoothing sweeps before and after the coarse correction (line Gauss–Seidel on the finest level, point Gauss–Seidel below). */
    private static final int SMOOTHING = 1;
    /**
     * The coarse correction is scaled up: a piecewise-constant prolongator represents smooth error too
     * crudely and its Galerkin operator is too stiff, so the plain correction undershoots (Vaněk et al.;
     * 1.5 measured best of 1, 1.5 and 2 on the global-solver experiment).
     */
    private static final double OVER_CORRECTION = 1.5;

    private final List<SparseMatrix> levels = new ArrayList<>();
    /** aggregateOf.get(l)[i]: aggregate (row of level l+1) of row i of level l. */
    private final List<int[]> aggregateOf = new ArrayList<>();
    /** scatter.get(l)[k]: position in level l+1's values of level l's value k. */
    private final List<int[]> scatter = new ArrayList<>();
    private final List<double[]> rhs = new ArrayList<>(), sol = new ArrayList<>(), tmp = new ArrayList<>();
    /** The finest level's smoother. */
    private final ChainSmoother chains;
    private double[] cholesky;
    private int coarseSize;
    public final long setupNanos;

    public AggregationMultigrid(SparseMatrix fine) {
        long t0 = System.nanoTime();
        SparseMatrix a = fine;
        levels.add(a);
        while (a.size > COARSEST) {
            int[] agg = aggregate(a, STRENGTH);
            int coarse = count(agg);
            if (coarse >= a.size * 0.9) {
                // Strong couplings have run out (on a triangle mesh the coarse rows' couplings cancel in
                // sign): aggregate over all couplings rather than solve a large level densely.
                agg = aggregate(a, 0);
                coarse = count(agg);
            }
            if (coarse >= a.size * 0.9) break; // no real coarsening left
            SparseMatrix c = galerkinPattern(a, agg, coarse);
            aggregateOf.add(agg);
            scatter.add(scatterMap(a, c, agg));
            levels.add(c);
            // The next level's aggregates are grown from these values (a pattern alone calls every coupling strong).
            restrict(levels.size() - 2);
            a = c;
        }
        for (SparseMatrix l : levels) {
            rhs.add(new double[l.size]);
            sol.add(new double[l.size]);
            tmp.add(new double[l.size]);
        }
        coarseSize = a.size;
        cholesky = new double[coarseSize * coarseSize];
        chains = new ChainSmoother(fine);
        refresh();
        setupNanos = System.nanoTime() - t0;
    }

    public int levelCount() { return levels.size(); }

    /** Unknowns of the coarsest level, solved densely. */
    public int coarsestSize() { return coarseSize; }

    /** The finest level's chains (the global solver lays its stiffness rows along them). */
    public ChainSmoother chains() { return chains; }

    /** Recomputes the coarse values from the fine level's current values (after a linearisation). */
    public void refresh() {
        chains.refresh();
        for (int l = 0; l + 1 < levels.size(); l++) restrict(l);
        factorCoarsest();
    }

    /** Level l+1's values = Pᵀ A P from level l's. */
    private void restrict(int l) {
        SparseMatrix f = levels.get(l), c = levels.get(l + 1);
        Arrays.fill(c.val, 0);
        int[] map = scatter.get(l);
        for (int k = 0; k < f.val.length; k++) c.val[map[k]] += f.val[k];
    }

    /** z = M⁻¹ r on the fine level's rows (the first ones of r and z): one V-cycle from a zero guess. */
    public void apply(double[] r, double[] z) {
        int n = levels.get(0).size;
        System.arraycopy(r, 0, rhs.get(0), 0, n);
        cycle(0);
        System.arraycopy(sol.get(0), 0, z, 0, n);
    }

    private void cycle(int l) {
        SparseMatrix a = levels.get(l);
        double[] b = rhs.get(l), x = sol.get(l), t = tmp.get(l);
        Arrays.fill(x, 0);
        if (l == levels.size() - 1) { solveCoarsest(b, x); return; }
        for (int s = 0; s < SMOOTHING; s++) smooth(l, b, x, true);
        a.multiply(x, t);
        int[] agg = aggregateOf.get(l);
        double[] bc = rhs.get(l + 1);
        Arrays.fill(bc, 0);
        for (int i = 0; i < a.size; i++) bc[agg[i]] += b[i] - t[i];
        cycle(l + 1);
        double[] xc = sol.get(l + 1);
        for (int i = 0; i < a.size; i++) x[i] += OVER_CORRECTION * xc[agg[i]];
        for (int s = 0; s < SMOOTHING; s++) smooth(l, b, x, false);
    }

    private void smooth(int l, double[] b, double[] x, boolean forward) {
        if (l == 0) chains.sweep(b, x, forward);
        else levels.get(l).gaussSeidel(b, x, forward);
    }

    private static int count(int[] agg) {
        int coarse = 0;
        for (int x : agg) coarse = Math.max(coarse, x + 1);
        return coarse;
    }

    private static int[] aggregate(SparseMatrix a, double strength) {
        int n = a.size;
        int[] agg = new int[n];
        Arrays.fill(agg, -1);
        int next = 0;
        // Phase 1: a seed whose strong neighbours are all free forms an aggregate with them.
        for (int i = 0; i < n; i++) {
            if (agg[i] >= 0) continue;
            boolean free = true;
            for (int k = a.rowStart[i]; k < a.rowStart[i + 1]; k++) if (strong(a, i, k, strength) && agg[a.col[k]] >= 0) { free = false; break; }
            if (!free) continue;
            agg[i] = next;
            for (int k = a.rowStart[i]; k < a.rowStart[i + 1]; k++) if (strong(a, i, k, strength)) agg[a.col[k]] = next;
            next++;
        }
        // Phase 2: leftovers join the aggregate of their strongest aggregated neighbour, or stand alone.
        for (int i = 0; i < n; i++) {
            if (agg[i] >= 0) continue;
            int best = -1;
            double bestW = 0;
            for (int k = a.rowStart[i]; k < a.rowStart[i + 1]; k++) {
                int j = a.col[k];
                if (j != i && agg[j] >= 0 && Math.abs(a.val[k]) > bestW) { bestW = Math.abs(a.val[k]); best = agg[j]; }
            }
            agg[i] = best >= 0 && strongAny(a, i, strength) ? best : next++;
        }
        return agg;
    }

    private static boolean strong(SparseMatrix a, int i, int k, double strength) {
        int j = a.col[k];
        if (j == i) return false;
        return Math.abs(a.val[k]) >= strength * Math.sqrt(a.val[a.diag[i]] * a.val[a.diag[j]]);
    }

    private static boolean strongAny(SparseMatrix a, int i, double strength) {
        for (int k = a.rowStart[i]; k < a.rowStart[i + 1]; k++) if (strong(a, i, k, strength)) return true;
        return false;
    }

    /** The pattern of Pᵀ A P for a binary P given by agg. */
    private static SparseMatrix galerkinPattern(SparseMatrix a, int[] agg, int coarse) {
        int[][] members = new int[coarse][];
        int[] count = new int[coarse];
        for (int x : agg) count[x]++;
        for (int c = 0; c < coarse; c++) members[c] = new int[count[c]];
        Arrays.fill(count, 0);
        for (int i = 0; i < agg.length; i++) members[agg[i]][count[agg[i]]++] = i;
        int[] mark = new int[coarse];
        Arrays.fill(mark, -1);
        int[] rowStart = new int[coarse + 1];
        List<Integer> cols = new ArrayList<>();
        for (int c = 0; c < coarse; c++) {
            int[] buf = new int[64];
            int nb = 0;
            for (int i : members[c])
                for (int k = a.rowStart[i]; k < a.rowStart[i + 1]; k++) {
                    int cj = agg[a.col[k]];
                    if (mark[cj] != c) {
                        mark[cj] = c;
                        if (nb == buf.length) buf = Arrays.copyOf(buf, 2 * nb);
                        buf[nb++] = cj;
                    }
                }
            Arrays.sort(buf, 0, nb);
            for (int q = 0; q < nb; q++) cols.add(buf[q]);
            rowStart[c + 1] = cols.size();
        }
        int[] col = new int[cols.size()];
        for (int q = 0; q < col.length; q++) col[q] = cols.get(q);
        return new SparseMatrix(coarse, rowStart, col);
    }

    private static int[] scatterMap(SparseMatrix f, SparseMatrix c, int[] agg) {
        int[] map = new int[f.val.length];
        for (int i = 0; i < f.size; i++)
            for (int k = f.rowStart[i]; k < f.rowStart[i + 1]; k++) map[k] = c.find(agg[i], agg[f.col[k]]);
        return map;
    }

    /**
     * Dense Cholesky of the coarsest operator. With hard constraints (α = 0) in surplus, A is only
     * semi-definite: a pivot that falls to round-off of its diagonal marks a direction A does not see,
     * and its unknown is set to 0 (a zero row of L⁻¹) instead of dividing by the round-off, which made
     * the old factor's entries reach 1e150 and the preconditioned residual overflow.
     */
    private void factorCoarsest() {
        SparseMatrix a = levels.get(levels.size() - 1);
        int n = coarseSize;
        Arrays.fill(cholesky, 0);
        for (int i = 0; i < n; i++)
            for (int k = a.rowStart[i]; k < a.rowStart[i + 1]; k++) cholesky[i * n + a.col[k]] = a.val[k];
        for (int j = 0; j < n; j++) {
            double diagonal = cholesky[j * n + j];
            double d = diagonal;
            for (int k = 0; k < j; k++) d -= cholesky[j * n + k] * cholesky[j * n + k];
            if (!(d > PIVOT_TOLERANCE * Math.abs(diagonal))) {
                cholesky[j * n + j] = Double.POSITIVE_INFINITY; // x_j = s / ∞ = 0
                for (int i = j + 1; i < n; i++) cholesky[i * n + j] = 0;
                continue;
            }
            d = Math.sqrt(d);
            cholesky[j * n + j] = d;
            for (int i = j + 1; i < n; i++) {
                double s = cholesky[i * n + j];
                for (int k = 0; k < j; k++) s -= cholesky[i * n + k] * cholesky[j * n + k];
                cholesky[i * n + j] = s / d;
            }
        }
    }

    private void solveCoarsest(double[] b, double[] x) {
        int n = coarseSize;
        for (int i = 0; i < n; i++) {
            double s = b[i];
            for (int k = 0; k < i; k++) s -= cholesky[i * n + k] * x[k];
            x[i] = s / cholesky[i * n + i];
        }
        for (int i = n - 1; i >= 0; i--) {
            double s = x[i];
            for (int k = i + 1; k < n; k++) s -= cholesky[k * n + i] * x[k];
            x[i] = s / cholesky[i * n + i];
        }
    }
}
