package xpbdcloth.linalg;

/**
 * A symmetric n × n matrix with half-bandwidth b (entry (i, j) is zero when |i − j| &gt; b), stored as its
 * lower band, and its Cholesky factor L Lᵀ in the same storage.
 *
 * <p>Why banded: the Hessian of a cloth's energy couples a particle only to the particles its constraints
 * reach, and a grid numbered row by row keeps those within about two rows, so b ≈ 6·columns degrees of
 * freedom. Factoring then costs n·b² (0.01 s for a 16² cloth, 0.2 s for 32²) where a dense factor costs
 * n³/3; a general mesh numbered badly only costs more, never gives a wrong answer.
 */
public final class BandedMatrix {
    public final int n, band;
    /** Row i holds entries (i, i − band … i) at [i·(band+1) + (j − i + band)]. */
    private final double[] lower;
    private boolean factored;

    public BandedMatrix(int n, int band) {
        this.n = n;
        this.band = Math.min(band, Math.max(n - 1, 0));
        lower = new double[n * (this.band + 1)];
    }

    private int at(int i, int j) { return i * (band + 1) + (j - i + band); }

    /** Adds v to (i, j) and, by symmetry, (j, i): call it once per unordered pair with i ≥ j, or for both orders with v/2. */
    public void add(int i, int j, double v) {
        if (i < j) { int t = i; i = j; j = t; }
        if (i - j > band) throw new IllegalStateException("entry (" + i + ", " + j + ") outside the band " + band);
        lower[at(i, j)] += v;
    }

    public double get(int i, int j) {
        if (i < j) { int t = i; i = j; j = t; }
        return i - j > band ? 0 : lower[at(i, j)];
    }

    public BandedMatrix copy() {
        BandedMatrix m = new BandedMatrix(n, band);
        System.arraycopy(lower, 0, m.lower, 0, lower.length);
        m.factored = factored;
        return m;
    }

    /**
     * Replaces the matrix by its Cholesky factor; false (and the matrix left half-factored, so copy first)
     * when it is not positive definite: a pivot at or below {@code 1e-14} of the largest diagonal entry.
     */
    public boolean factor() {
        double maxDiag = 0;
        for (int i = 0; i < n; i++) maxDiag = Math.max(maxDiag, lower[at(i, i)]);
        double floor = 1e-14 * maxDiag;
        for (int i = 0; i < n; i++) {
            int j0 = Math.max(0, i - band), ri = at(i, 0); // (i, k) is lower[ri + k] for k in the band
            for (int j = j0; j <= i; j++) {
                int rj = at(j, 0), k0 = Math.max(j0, j - band);
                // Four running sums: one waits on each of its additions in turn (the floating-point adder's
                // latency), four keep it busy; the band's dot products are nearly all of a factorisation's work.
                double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
                int k = k0;
                for (; k + 3 < j; k += 4) {
                    s0 += lower[ri + k] * lower[rj + k];
                    s1 += lower[ri + k + 1] * lower[rj + k + 1];
                    s2 += lower[ri + k + 2] * lower[rj + k + 2];
                    s3 += lower[ri + k + 3] * lower[rj + k + 3];
                }
                for (; k < j; k++) s0 += lower[ri + k] * lower[rj + k];
                double s = lower[ri + j] - ((s0 + s1) + (s2 + s3));
                if (j == i) {
                    if (!(s > floor)) return false;
                    lower[ri + i] = Math.sqrt(s);
                } else {
                    lower[ri + j] = s / lower[rj + j];
                }
            }
        }
        factored = true;
        return true;
    }

    /** Solves A x = b in place with the factor (b becomes x). */
    public void solve(double[] b) {
        if (!factored) throw new IllegalStateException("factor() first");
        for (int i = 0; i < n; i++) {
            double s = b[i];
            for (int k = Math.max(0, i - band); k < i; k++) s -= lower[at(i, k)] * b[k];
            b[i] = s / lower[at(i, i)];
        }
        for (int i = n - 1; i >= 0; i--) {
            double s = b[i];
            for (int k = i + 1; k <= Math.min(n - 1, i + band); k++) s -= lower[at(k, i)] * b[k];
            b[i] = s / lower[at(i, i)];
        }
    }
}
