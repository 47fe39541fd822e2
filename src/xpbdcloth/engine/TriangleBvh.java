package xpbdcloth.engine;

/**
 * A bounding-volume hierarchy of a triangle mesh's triangles in flat arrays: built once from the rest
 * shape (median split of the triangles' centroids along the box's longest axis, a leaf holding at most
 * {@link #LEAF} triangles), its boxes refitted bottom-up whenever the vertices move, here to the boxes
 * that hold each triangle over a whole substep (start and end), padded. Queries walk it with a stack
 * sized once. Nothing is allocated after construction.
 */
final class TriangleBvh {
    static final int LEAF = 4;

    private final int[] triangles;
    /** Triangle order: the leaves' ranges index into it. */
    private final int[] order;
    /** Per node: its box (6 numbers: min xyz, max xyz), its children (−1 for a leaf) or its range of {@link #order}. */
    final double[] box;
    private final int[] left, right, first, count;
    private int nodes;
    private final int[] stack;

    TriangleBvh(int[] triangles, double[] rest) {
        this.triangles = triangles;
        int n = triangles.length / 3;
        order = new int[n];
        for (int t = 0; t < n; t++) order[t] = t;
        int capacity = Math.max(1, 2 * n);
        box = new double[6 * capacity];
        left = new int[capacity];
        right = new int[capacity];
        first = new int[capacity];
        count = new int[capacity];
        double[] centroid = new double[3 * n];
        for (int t = 0; t < n; t++)
            for (int d = 0; d < 3; d++)
                centroid[3 * t + d] = (rest[3 * triangles[3 * t] + d] + rest[3 * triangles[3 * t + 1] + d] + rest[3 * triangles[3 * t + 2] + d]) / 3;
        build(0, n, centroid);
        stack = new int[2 * 64 + 2 * nodes];
        refit(rest, rest, 0);
    }

    private int build(int from, int to, double[] centroid) {
        int node = nodes++;
        first[node] = from;
        count[node] = to - from;
        left[node] = right[node] = -1;
        if (to - from <= LEAF) return node;
        double[] lo = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE}, hi = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        for (int k = from; k < to; k++)
            for (int d = 0; d < 3; d++) {
                lo[d] = Math.min(lo[d], centroid[3 * order[k] + d]);
                hi[d] = Math.max(hi[d], centroid[3 * order[k] + d]);
            }
        int axis = hi[0] - lo[0] >= hi[1] - lo[1] && hi[0] - lo[0] >= hi[2] - lo[2] ? 0 : hi[1] - lo[1] >= hi[2] - lo[2] ? 1 : 2;
        int mid = (from + to) >>> 1;
        select(from, to - 1, mid, axis, centroid);
        left[node] = build(from, mid, centroid);
        right[node] = build(mid, to, centroid);
        return node;
    }

    /** Puts the k-th smallest centroid (along axis) of order[lo..hi] at k, smaller before and larger after (quickselect). */
    private void select(int lo, int hi, int k, int axis, double[] centroid) {
        while (hi > lo) {
            double pivot = centroid[3 * order[(lo + hi) >>> 1] + axis];
            int i = lo, j = hi;
            while (i <= j) {
                while (centroid[3 * order[i] + axis] < pivot) i++;
                while (centroid[3 * order[j] + axis] > pivot) j--;
                if (i <= j) { int s = order[i]; order[i] = order[j]; order[j] = s; i++; j--; }
            }
            if (k <= j) hi = j;
            else if (k >= i) lo = i;
            else return;
        }
    }

    /** Refits every box to hold each triangle at both vertex sets v0 and v1, grown by pad on every side. */
    void refit(double[] v0, double[] v1, double pad) {
        for (int node = nodes - 1; node >= 0; node--) { // children are built after their parent: reverse order is bottom-up
            int b = 6 * node;
            if (left[node] < 0) {
                box[b] = box[b + 1] = box[b + 2] = Double.MAX_VALUE;
                box[b + 3] = box[b + 4] = box[b + 5] = -Double.MAX_VALUE;
                for (int k = first[node], end = k + count[node]; k < end; k++)
                    for (int corner = 0; corner < 3; corner++) {
                        int v = 3 * triangles[3 * order[k] + corner];
                        for (int d = 0; d < 3; d++) {
                            double p = v0[v + d], q = v1[v + d];
                            box[b + d] = Math.min(box[b + d], Math.min(p, q) - pad);
                            box[b + 3 + d] = Math.max(box[b + 3 + d], Math.max(p, q) + pad);
                        }
                    }
            } else {
                int l = 6 * left[node], r = 6 * right[node];
                for (int d = 0; d < 3; d++) {
                    box[b + d] = Math.min(box[l + d], box[r + d]);
                    box[b + 3 + d] = Math.max(box[l + 3 + d], box[r + 3 + d]);
                }
            }
        }
    }

    /** The triangles whose boxes overlap [lo, hi] into out (as many as fit); returns how many were found. */
    int overlapping(double lx, double ly, double lz, double hx, double hy, double hz, int[] out) {
        int found = 0, top = 0;
        stack[top++] = 0;
        while (top > 0) {
            int node = stack[--top], b = 6 * node;
            if (box[b] > hx || box[b + 3] < lx || box[b + 1] > hy || box[b + 4] < ly || box[b + 2] > hz || box[b + 5] < lz) continue;
            if (left[node] < 0) {
                for (int k = first[node], end = k + count[node]; k < end && found < out.length; k++) out[found++] = order[k];
            } else {
                stack[top++] = left[node];
                stack[top++] = right[node];
            }
        }
        return found;
    }

    /** The box of the root: every triangle over the substep, padded. */
    double rootMin(int axis) { return box[axis]; }
    double rootMax(int axis) { return box[3 + axis]; }

    /**
     * The triangle nearest to point p among those whose boxes come within {@code bound} of it (∞ for any),
     * by the distance {@code metric} gives; −1 if none. Nodes farther than the best so far are not entered.
     */
    int nearest(double px, double py, double pz, double bound, TriangleMetric metric) {
        double best = bound * bound;
        int bestTriangle = -1, top = 0;
        stack[top++] = 0;
        while (top > 0) {
            int node = stack[--top], b = 6 * node;
            double dx = Math.max(0, Math.max(box[b] - px, px - box[b + 3]));
            double dy = Math.max(0, Math.max(box[b + 1] - py, py - box[b + 4]));
            double dz = Math.max(0, Math.max(box[b + 2] - pz, pz - box[b + 5]));
            if (dx * dx + dy * dy + dz * dz > best) continue;
            if (left[node] < 0) {
                for (int k = first[node], end = k + count[node]; k < end; k++) {
                    double d = metric.squaredDistance(order[k]);
                    if (d < best) { best = d; bestTriangle = order[k]; }
                }
            } else {
                stack[top++] = left[node];
                stack[top++] = right[node];
            }
        }
        return bestTriangle;
    }

    /** The squared distance from the query's point to triangle t. */
    interface TriangleMetric {
        double squaredDistance(int t);
    }
}
