package xpbdcloth.mesh;

/**
 * A closed upright cylinder on y = 0 (a drape tester's pedestal, say): its side as {@code segments} quads
 * split into triangles, each end a fan round a centre vertex, all wound outwards. Generated, so its
 * provenance is this code.
 */
public final class Cylinder {
    private Cylinder() {}

    public static ClothMesh generate(double radius, double height, int segments) {
        if (!(radius > 0) || !Double.isFinite(radius)) throw new IllegalArgumentException("radius must be > 0, was " + radius);
        if (!(height > 0) || !Double.isFinite(height)) throw new IllegalArgumentException("height must be > 0, was " + height);
        if (segments < 3 || segments > 10_000) throw new IllegalArgumentException("segments must be in [3, 10000], was " + segments);
        // Vertices: the bottom ring, the top ring, then the bottom and top centres.
        double[] p = new double[3 * (2 * segments + 2)];
        for (int i = 0; i < segments; i++) {
            double a = 2 * Math.PI * i / segments, x = radius * Math.cos(a), z = -radius * Math.sin(a) + 0.0;
            p[3 * i] = x; p[3 * i + 2] = z;
            p[3 * (segments + i)] = x; p[3 * (segments + i) + 1] = height; p[3 * (segments + i) + 2] = z;
        }
        int bottom = 2 * segments, top = bottom + 1;
        p[3 * top + 1] = height;
        int[][] faces = new int[4 * segments][];
        int f = 0;
        for (int i = 0; i < segments; i++) {
            int j = (i + 1) % segments, bi = i, bj = j, ti = segments + i, tj = segments + j;
            // The ring runs counter-clockwise seen from +y (angle from +x towards −z), so bi → bj → tj faces out.
            faces[f++] = new int[] {bi, bj, tj};
            faces[f++] = new int[] {bi, tj, ti};
            faces[f++] = new int[] {top, ti, tj};
            faces[f++] = new int[] {bottom, bj, bi};
        }
        return ClothMesh.of(p, faces, null, null, null);
    }
}
