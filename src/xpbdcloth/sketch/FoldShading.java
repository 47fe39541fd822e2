package xpbdcloth.sketch;

/**
 * Darkening where the cloth folds, a cheap stand-in for ambient occlusion: a vertex whose neighbours rise
 * above it along its normal sits in a valley that sees less of the sky, so it is drawn darker on that
 * side (and the ridge it makes on the other side is not).
 *
 * <pre>
 *   valley(i) = n̂ᵢ · (mean of the neighbours' positions − xᵢ) / mean edge length
 * </pre>
 * positive in a valley seen from the front, negative from the back; the light that reaches it is
 * 1 − {@link #STRENGTH}·valley, clamped to [{@link #DARKEST}, 1]. Neighbours are taken through the
 * triangles (a neighbour shared by two triangles counts twice, which weights it by the fan around the
 * vertex). Arrays are kept between frames, so a frame allocates nothing.
 */
final class FoldShading {
    /** How much a valley as deep as one edge length darkens. */
    static final double STRENGTH = 1.6;
    /** The darkest a valley gets, as a fraction of the full light. */
    static final float DARKEST = 0.45f;

    private double[] sum = new double[0];
    private int[] count = new int[0];
    /** Light factor per vertex for the front side and for the back side. */
    float[] front = new float[0], back = new float[0];

    /** Recomputes the factors for positions x (xyz interleaved), triangles t and unit vertex normals n. */
    void compute(double[] x, int[] t, double[] n) {
        int vertices = x.length / 3;
        if (count.length != vertices) {
            sum = new double[x.length];
            count = new int[vertices];
            front = new float[vertices];
            back = new float[vertices];
        }
        java.util.Arrays.fill(sum, 0);
        java.util.Arrays.fill(count, 0);
        double edges = 0;
        for (int k = 0; k < t.length; k += 3)
            for (int j = 0; j < 3; j++) {
                int a = 3 * t[k + j], b = 3 * t[k + (j + 1) % 3], c = 3 * t[k + (j + 2) % 3];
                for (int d = 0; d < 3; d++) sum[a + d] += x[b + d] + x[c + d];
                count[a / 3] += 2;
                double ex = x[b] - x[a], ey = x[b + 1] - x[a + 1], ez = x[b + 2] - x[a + 2];
                edges += Math.sqrt(ex * ex + ey * ey + ez * ez);
            }
        double meanEdge = t.length == 0 ? 1 : Math.max(edges / t.length, 1e-9);
        for (int i = 0; i < vertices; i++) {
            if (count[i] == 0) { front[i] = back[i] = 1; continue; }
            int k = 3 * i;
            double valley = 0;
            for (int d = 0; d < 3; d++) valley += n[k + d] * (sum[k + d] / count[i] - x[k + d]);
            valley /= meanEdge;
            front[i] = light(valley);
            back[i] = light(-valley);
        }
    }

    private static float light(double valley) {
        return (float) Math.max(DARKEST, Math.min(1, 1 - STRENGTH * Math.max(0, valley)));
    }
}
