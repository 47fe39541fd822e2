package xpbdcloth.linalg;

/** A symmetric sparse matrix in compressed rows, with its pattern fixed and its values refilled in place. */
public final class SparseMatrix {
    public final int size;
    public final int[] rowStart, col;
    public final double[] val;
    /** Index of the diagonal entry of each row in {@link #val}. */
    public final int[] diag;

    public SparseMatrix(int size, int[] rowStart, int[] col) {
        this.size = size;
        this.rowStart = rowStart;
        this.col = col;
        this.val = new double[col.length];
        this.diag = new int[size];
        for (int i = 0; i < size; i++) diag[i] = find(i, i);
    }

    /** Position of (i, j) in the value array, or -1 (columns of a row are sorted). */
    public int find(int i, int j) {
        int lo = rowStart[i], hi = rowStart[i + 1] - 1;
        while (lo <= hi) {
            int mid = (lo + hi) >>> 1;
            if (col[mid] < j) lo = mid + 1;
            else if (col[mid] > j) hi = mid - 1;
            else return mid;
        }
        return -1;
    }

    /** y = A x. */
    public void multiply(double[] x, double[] y) {
        for (int i = 0; i < size; i++) {
            double s = 0;
            for (int k = rowStart[i]; k < rowStart[i + 1]; k++) s += val[k] * x[col[k]];
            y[i] = s;
        }
    }

    /** One Gauss–Seidel sweep on A x = b, forwards or backwards. */
    void gaussSeidel(double[] b, double[] x, boolean forward) {
        for (int t = 0; t < size; t++) {
            int i = forward ? t : size - 1 - t;
            double s = b[i];
            for (int k = rowStart[i]; k < rowStart[i + 1]; k++) if (col[k] != i) s -= val[k] * x[col[k]];
            x[i] = s / val[diag[i]];
        }
    }
}
