package xpbdcloth.linalg;

import java.util.Arrays;

/**
 * Line Gauss–Seidel on A x = b: the unknowns are split into chains along their strongest couplings, and
 * each sweep solves every chain's tridiagonal block exactly (Thomas' algorithm), its couplings to the
 * other chains taken from the current x (Trottenberg, Oosterlee, Schüller 2001, "Multigrid", §5.1, line
 * relaxation for anisotropic operators).
 *
 * <p>Why: a cloth's stretch rows couple strongly only to the rows of edges in line with them (two edges
 * meeting at a particle couple by w cos θ, 0 for a grid's perpendicular edges), so J W Jᵀ is close to a
 * set of 1-D chains, one per grid line, each an edge Laplacian. Point smoothers remove error one row at
 * a time along them, which is why Jacobi-PCG needs N − 1 iterations on an N² grid; a chain solve
 * removes it along the whole line at once, and only the weak couplings across lines are left for the
 * coarse levels.
 *
 * <p>Chains (built once per pattern, from the first values): couplings with |A_ij| ≥ θ √(A_ii A_jj) are
 * taken strongest first when neither end has two chain neighbours yet, they close no cycle, and no other
 * row of the one path shares an entry with the other (a greedy maximum-weight cover by induced paths:
 * each chain's block of A is then exactly tridiagonal, and a sweep is block Gauss–Seidel, convergent for
 * any symmetric positive-definite A). Values are refactored in place after each linearisation.
 */
public final class ChainSmoother {
    private static final double STRENGTH = 0.25;

    private final SparseMatrix a;
    /** Rows in chain order; chain c is order[start[c] .. start[c+1]). */
    private final int[] order, start;
    /** For position k of order: where A(order[k], order[k−1]) sits in a.val (−1 at a chain's start). */
    private final int[] link;
    /** The chain each row is in. */
    private final int[] chainOf;
    /** Thomas factors: pivot d and multiplier l per position; rhs scratch. */
    private final double[] pivot, lower, y;
    /**
     * Per chain position k, the couplings of its row outside its chain (all but the diagonal and the two
     * chain neighbours), {@code outside[outsideStart[k] ..]}: positions in a.val; {@code outsideCol}: their
     * columns. Listed once, so that a sweep's right-hand side is a plain dot product.
     */
    private final int[] outsideStart, outside, outsideCol;

    /** Chains along A's strongest couplings. */
    ChainSmoother(SparseMatrix a) {
        this(a, strongChains(a));
    }

    /** Given chains: {order, start} as in {@link #order} and {@link #start}, every row in exactly one. */
    public ChainSmoother(SparseMatrix a, int[][] chains) {
        this.a = a;
        order = chains[0];
        start = chains[1];
        int n = a.size;
        link = new int[n];
        chainOf = new int[n];
        for (int c = 0; c + 1 < start.length; c++)
            for (int k = start[c]; k < start[c + 1]; k++) {
                link[k] = k == start[c] ? -1 : a.find(order[k], order[k - 1]);
                chainOf[order[k]] = c;
            }
        pivot = new double[n];
        lower = new double[n];
        y = new double[n];
        outsideStart = new int[n + 1];
        listOutside(null, null); // counts into outsideStart
        outside = new int[outsideStart[n]];
        outsideCol = new int[outsideStart[n]];
        listOutside(outside, outsideCol);
    }

    /** Fills {@link #outsideStart} (and, given arrays, the entries) for every chain position. */
    private void listOutside(int[] entries, int[] cols) {
        int count = 0;
        for (int c = 0; c + 1 < start.length; c++)
            for (int k = start[c]; k < start[c + 1]; k++) {
                int i = order[k];
                int prevRow = k > start[c] ? order[k - 1] : -1, nextRow = k + 1 < start[c + 1] ? order[k + 1] : -1;
                for (int q = a.rowStart[i]; q < a.rowStart[i + 1]; q++) {
                    int j = a.col[q];
                    if (j == i || j == prevRow || j == nextRow) continue;
                    if (entries != null) { entries[count] = q; cols[count] = j; }
                    count++;
                }
                outsideStart[k + 1] = count;
            }
    }

    /** {order, start}: a greedy maximum-weight path cover of the strong couplings (see the class comment). */
    private static int[][] strongChains(SparseMatrix a) {
        int n = a.size;
        int strong = 0;
        for (int i = 0; i < n; i++) for (int k = a.rowStart[i]; k < a.rowStart[i + 1]; k++) if (a.col[k] > i && isStrong(a, i, k)) strong++;
        long[] keys = new long[strong];
        double[] weight = new double[strong];
        Integer[] byWeight = new Integer[strong];
        int s = 0;
        for (int i = 0; i < n; i++)
            for (int k = a.rowStart[i]; k < a.rowStart[i + 1]; k++)
                if (a.col[k] > i && isStrong(a, i, k)) {
                    keys[s] = (long) i << 32 | a.col[k];
                    weight[s] = Math.abs(a.val[k]) / Math.sqrt(a.val[a.diag[i]] * a.val[a.diag[a.col[k]]]);
                    byWeight[s] = s;
                    s++;
                }
        Arrays.sort(byWeight, (p, q) -> Double.compare(weight[q], weight[p]));
        int[] degree = new int[n], parent = new int[n];
        int[][] next = new int[n][2];
        // The rows of each path (by its root), merged small into large, to check that a join keeps it induced.
        int[][] members = new int[n][];
        int[] size = new int[n];
        for (int i = 0; i < n; i++) { parent[i] = i; next[i][0] = next[i][1] = -1; members[i] = new int[] {i}; size[i] = 1; }
        for (Integer e : byWeight) {
            int i = (int) (keys[e] >>> 32), j = (int) keys[e];
            if (degree[i] == 2 || degree[j] == 2) continue;
            int ri = root(parent, i), rj = root(parent, j);
            if (ri == rj) continue;
            if (size[ri] > size[rj]) { int t = ri; ri = rj; rj = t; }
            if (couplesElsewhere(a, parent, members[ri], size[ri], rj, i, j)) continue;
            parent[ri] = rj;
            if (size[rj] + size[ri] > members[rj].length) members[rj] = Arrays.copyOf(members[rj], 2 * (size[rj] + size[ri]));
            System.arraycopy(members[ri], 0, members[rj], size[rj], size[ri]);
            size[rj] += size[ri];
            members[ri] = null;
            next[i][degree[i]++] = j;
            next[j][degree[j]++] = i;
        }
        int[] order = new int[n], starts = new int[n + 1];
        boolean[] placed = new boolean[n];
        int pos = 0, chains = 0;
        for (int i = 0; i < n; i++) {
            if (placed[i] || degree[i] == 2) continue; // walk each path from an end (degree 0 or 1)
            starts[chains++] = pos;
            int prev = -1, cur = i;
            while (cur >= 0) {
                placed[cur] = true;
                order[pos++] = cur;
                int nxt = -1;
                for (int t = 0; t < degree[cur]; t++) if (next[cur][t] != prev && !placed[next[cur][t]]) nxt = next[cur][t];
                prev = cur;
                cur = nxt;
            }
        }
        starts[chains] = pos;
        return new int[][] {order, Arrays.copyOf(starts, chains + 1)};
    }

    /**
     * Whether a row of one path shares a pattern entry with a row of the path rooted at {@code other},
     * apart from the joining pair (i, j). Such a pair would be a coupling inside the chain that its
     * tridiagonal solve leaves out: the chain's block would no longer be solved exactly, and the sweep
     * can then diverge (three edges of one triangle in one chain gave the V-cycle a negative eigenvalue
     * and multigrid-PCG stalled on every triangle mesh). The test is on the pattern, not the values, so
     * that a chain stays exact however the cloth later bends.
     */
    private static boolean couplesElsewhere(SparseMatrix a, int[] parent, int[] rows, int count, int other, int i, int j) {
        for (int t = 0; t < count; t++) {
            int u = rows[t];
            for (int k = a.rowStart[u]; k < a.rowStart[u + 1]; k++) {
                int v = a.col[k];
                if (v == u || (u == i && v == j) || (u == j && v == i)) continue;
                if (root(parent, v) == other) return true;
            }
        }
        return false;
    }

    private static int root(int[] parent, int i) {
        while (parent[i] != i) { parent[i] = parent[parent[i]]; i = parent[i]; }
        return i;
    }

    private static boolean isStrong(SparseMatrix a, int i, int k) {
        int j = a.col[k];
        return j != i && Math.abs(a.val[k]) >= STRENGTH * Math.sqrt(a.val[a.diag[i]] * a.val[a.diag[j]]);
    }

    public int chainCount() { return start.length - 1; }
    /** Rows in chain order; chain c is {@code order()[start()[c] .. start()[c+1])}. */
    public int[] order() { return order; }
    public int[] start() { return start; }
    public int chainOf(int row) { return chainOf[row]; }

    /** LDLᵀ of each chain's tridiagonal block, from A's current values. */
    public void refresh() {
        for (int c = 0; c + 1 < start.length; c++)
            for (int k = start[c]; k < start[c + 1]; k++) {
                double d = a.val[a.diag[order[k]]];
                if (k > start[c]) {
                    double off = a.val[link[k]];
                    lower[k] = off / pivot[k - 1];
                    d -= lower[k] * off;
                }
                pivot[k] = d;
            }
    }

    /** One sweep over the chains, forwards or backwards, each chain solved exactly given the others' x. */
    void sweep(double[] b, double[] x, boolean forward) {
        int chains = start.length - 1;
        for (int t = 0; t < chains; t++) {
            int c = forward ? t : chains - 1 - t;
            int from = start[c], to = start[c + 1];
            // Right-hand side: b minus the couplings outside the chain (the chain's own ones are in the factor).
            final double[] val = a.val;
            for (int k = from; k < to; k++) {
                double s = b[order[k]];
                for (int q = outsideStart[k]; q < outsideStart[k + 1]; q++) s -= val[outside[q]] * x[outsideCol[q]];
                y[k] = s;
            }
            for (int k = from + 1; k < to; k++) y[k] -= lower[k] * y[k - 1];
            for (int k = from; k < to; k++) y[k] /= pivot[k];
            for (int k = to - 2; k >= from; k--) y[k] -= lower[k + 1] * y[k + 1];
            for (int k = from; k < to; k++) x[order[k]] = y[k];
        }
    }

    /**
     * x = T⁻¹ b on the listed chains (T: each chain's tridiagonal block, couplings between chains left
     * out: block Jacobi), for rows {@code offset + row} of b and x.
     */
    public void solveChains(int[] chains, int count, double[] b, double[] x, int offset) {
        for (int t = 0; t < count; t++) {
            int c = chains[t], from = start[c], to = start[c + 1];
            for (int k = from; k < to; k++) y[k] = b[offset + order[k]];
            for (int k = from + 1; k < to; k++) y[k] -= lower[k] * y[k - 1];
            for (int k = from; k < to; k++) y[k] /= pivot[k];
            for (int k = to - 2; k >= from; k--) y[k] -= lower[k + 1] * y[k + 1];
            for (int k = from; k < to; k++) x[offset + order[k]] = y[k];
        }
    }
}
