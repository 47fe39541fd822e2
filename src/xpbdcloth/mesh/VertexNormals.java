package xpbdcloth.mesh;

import java.util.Arrays;

/**
 * Area-weighted vertex normals of a triangle mesh: each vertex gets the sum of its triangles'
 * unnormalised normals (whose length is twice the area), then unit length. Large triangles count more,
 * which is what a smooth-shaded cloth should show. A vertex of no triangle, or whose triangles cancel,
 * gets (0, 0, 0).
 */
public final class VertexNormals {
    private VertexNormals() {}

    /** Fills {@code out} (3 per vertex, same length as {@code x}) without allocating. */
    public static void compute(double[] x, int[] triangles, double[] out) {
        if (out.length != x.length) throw new IllegalArgumentException("out must have " + x.length + " entries, was " + out.length);
        Arrays.fill(out, 0);
        for (int k = 0; k < triangles.length; k += 3) {
            int a = 3 * triangles[k], b = 3 * triangles[k + 1], c = 3 * triangles[k + 2];
            double e1x = x[b] - x[a], e1y = x[b + 1] - x[a + 1], e1z = x[b + 2] - x[a + 2];
            double e2x = x[c] - x[a], e2y = x[c + 1] - x[a + 1], e2z = x[c + 2] - x[a + 2];
            double nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
            out[a] += nx; out[a + 1] += ny; out[a + 2] += nz;
            out[b] += nx; out[b + 1] += ny; out[b + 2] += nz;
            out[c] += nx; out[c + 1] += ny; out[c + 2] += nz;
        }
        for (int k = 0; k < out.length; k += 3) {
            double l = Math.sqrt(out[k] * out[k] + out[k + 1] * out[k + 1] + out[k + 2] * out[k + 2]);
            if (l > 0) { out[k] /= l; out[k + 1] /= l; out[k + 2] /= l; }
        }
    }
}
