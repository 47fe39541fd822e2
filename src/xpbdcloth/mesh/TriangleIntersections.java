package xpbdcloth.mesh;

import java.util.Arrays;

/**
 * How many pairs of triangles of a mesh pass through each other, over pairs that share no vertex: the
 * measure of a cloth that has gone through itself (0 for a cloth whose self-collision held).
 *
 * <p>Two triangles that are not coplanar intersect exactly when an edge of one crosses the other; each
 * edge is tested against the other triangle with the segment–triangle test of Möller and Trumbore (1997,
 * "Fast, Minimum Storage Ray/Triangle Intersection"), on the segment's parameter range [0, 1]. Coplanar
 * overlaps (a set of measure zero for a moving cloth) are not counted. Candidate pairs come from a uniform
 * grid over the triangles' bounding boxes (cell: twice the mean edge), so a frame of a 48² cloth costs
 * milliseconds, not the 10⁷ pairs of a brute-force count.
 */
public final class TriangleIntersections {
    private TriangleIntersections() {}

    /** Pairs of vertex-disjoint triangles of {@code t} (3 indices each) over positions {@code x} that intersect. */
    public static int count(double[] x, int[] t) { return count(x, t, null); }

    /**
     * As {@link #count(double[], int[])}, with vertices {@code same[a] == same[b]} taken as one (a garment's
     * stitched pairs: triangles that meet across a seam are neighbours, not a crossing); null: each its own.
     */
    public static int count(double[] x, int[] t, int[] same) {
        int n = t.length / 3;
        if (n < 2) return 0;
        double mean = 0;
        for (int k = 0; k < t.length; k++) {
            int a = 3 * t[k], b = 3 * t[k % 3 == 2 ? k - 2 : k + 1];
            mean += Math.sqrt(sq(x[a] - x[b]) + sq(x[a + 1] - x[b + 1]) + sq(x[a + 2] - x[b + 2]));
        }
        double cell = Math.max(2 * mean / t.length, 1e-9);
        // Each triangle listed in every cell its bounding box touches (hashed), by counting sort.
        int[][] boxes = new int[n][6];
        int entries = 0;
        for (int i = 0; i < n; i++) {
            int[] bx = boxes[i];
            for (int d = 0; d < 3; d++) {
                double lo = Math.min(x[3 * t[3 * i] + d], Math.min(x[3 * t[3 * i + 1] + d], x[3 * t[3 * i + 2] + d]));
                double hi = Math.max(x[3 * t[3 * i] + d], Math.max(x[3 * t[3 * i + 1] + d], x[3 * t[3 * i + 2] + d]));
                bx[d] = (int) Math.floor(lo / cell);
                bx[d + 3] = (int) Math.floor(hi / cell);
            }
            entries += (bx[3] - bx[0] + 1) * (bx[4] - bx[1] + 1) * (bx[5] - bx[2] + 1);
        }
        int table = 2 * entries + 1;
        int[][] cells = new int[n][];
        for (int i = 0; i < n; i++) cells[i] = hashedCells(boxes[i], table);
        int[] start = new int[table + 1], list = new int[entries];
        for (int i = 0; i < n; i++) for (int h : cells[i]) start[h]++;
        for (int c = 0, sum = 0; c <= table; c++) { sum += start[c]; start[c] = sum; }
        for (int i = 0; i < n; i++) for (int h : cells[i]) list[--start[h]] = i;
        int[] seen = new int[n];
        Arrays.fill(seen, -1);
        int found = 0;
        for (int i = 0; i < n; i++)
            for (int h : cells[i])
                for (int s = start[h]; s < start[h + 1]; s++) {
                    int j = list[s];
                    if (j <= i || seen[j] == i) continue;
                    seen[j] = i;
                    if (!overlap(boxes[i], boxes[j]) || shareVertex(t, i, j, same)) continue;
                    if (intersect(x, t, i, j)) found++;
                }
        return found;
    }

    /** The hashed cells a bounding box {min x, y, z, max x, y, z} (in cells) touches. */
    private static int[] hashedCells(int[] box, int table) {
        int[] out = new int[(box[3] - box[0] + 1) * (box[4] - box[1] + 1) * (box[5] - box[2] + 1)];
        int k = 0;
        for (int cx = box[0]; cx <= box[3]; cx++)
            for (int cy = box[1]; cy <= box[4]; cy++)
                for (int cz = box[2]; cz <= box[5]; cz++) out[k++] = hash(cx, cy, cz, table);
        return out;
    }

    private static boolean overlap(int[] a, int[] b) {
        for (int d = 0; d < 3; d++) if (a[d + 3] < b[d] || b[d + 3] < a[d]) return false;
        return true;
    }

    private static boolean shareVertex(int[] t, int i, int j, int[] same) {
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                int u = t[3 * i + a], v = t[3 * j + b];
                if (u == v || same != null && same[u] == same[v]) return true;
            }
        return false;
    }

    /** Whether triangles i and j cross: an edge of either passes through the other. */
    static boolean intersect(double[] x, int[] t, int i, int j) {
        for (int e = 0; e < 3; e++) {
            if (segmentCrosses(x, t[3 * i + e], t[3 * i + (e + 1) % 3], t, j)) return true;
            if (segmentCrosses(x, t[3 * j + e], t[3 * j + (e + 1) % 3], t, i)) return true;
        }
        return false;
    }

    /** Möller–Trumbore: does segment p→q cross triangle k (its interior or boundary)? */
    private static boolean segmentCrosses(double[] x, int p, int q, int[] t, int k) {
        return segmentHit(x, p, q, t[3 * k], t[3 * k + 1], t[3 * k + 2], null);
    }

    /**
     * Möller–Trumbore: whether the segment from particle p to q crosses the triangle (a, b, c), its interior or
     * boundary, over positions x (xyz interleaved); where it does, the crossing's barycentric coordinates on
     * the triangle (of b and of c) go into at[0], at[1] if at is given. A segment parallel to the triangle's
     * plane (within round-off) does not cross it: coplanar overlaps are not counted. Allocates nothing.
     */
    public static boolean segmentHit(double[] x, int p, int q, int a, int b, int c, double[] at) {
        a *= 3; b *= 3; c *= 3;
        double dx = x[3 * q] - x[3 * p], dy = x[3 * q + 1] - x[3 * p + 1], dz = x[3 * q + 2] - x[3 * p + 2];
        double e1x = x[b] - x[a], e1y = x[b + 1] - x[a + 1], e1z = x[b + 2] - x[a + 2];
        double e2x = x[c] - x[a], e2y = x[c + 1] - x[a + 1], e2z = x[c + 2] - x[a + 2];
        double px = dy * e2z - dz * e2y, py = dz * e2x - dx * e2z, pz = dx * e2y - dy * e2x;
        double det = e1x * px + e1y * py + e1z * pz;
        double scale = Math.sqrt(dx * dx + dy * dy + dz * dz) * Math.sqrt(e1x * e1x + e1y * e1y + e1z * e1z) * Math.sqrt(e2x * e2x + e2y * e2y + e2z * e2z);
        if (!(Math.abs(det) > 1e-12 * scale)) return false; // parallel to the plane (or not finite): coplanar cases not counted
        double inv = 1 / det;
        double sx = x[3 * p] - x[a], sy = x[3 * p + 1] - x[a + 1], sz = x[3 * p + 2] - x[a + 2];
        double u = (sx * px + sy * py + sz * pz) * inv;
        if (u < 0 || u > 1) return false;
        double qx = sy * e1z - sz * e1y, qy = sz * e1x - sx * e1z, qz = sx * e1y - sy * e1x;
        double v = (dx * qx + dy * qy + dz * qz) * inv;
        if (v < 0 || u + v > 1) return false;
        double s = (e2x * qx + e2y * qy + e2z * qz) * inv;
        if (!(s >= 0 && s <= 1)) return false;
        if (at != null) { at[0] = u; at[1] = v; }
        return true;
    }

    private static int hash(int x, int y, int z, int table) {
        return Math.floorMod((x * 92837111) ^ (y * 689287499) ^ (z * 283923481), table);
    }

    private static double sq(double v) { return v * v; }
}
