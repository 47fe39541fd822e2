package xpbdcloth.mesh;

/**
 * Where a cloth tears: one vertex of an overstretched edge is split in two by the plane through it square
 * to the edge. The triangles around it whose centroids lie on the far side (towards the edge's other end)
 * take the new vertex; the others keep the old one, so the mesh opens along the fan between them (Müller,
 * Heidelberger, Hennix, Ratcliff 2007, "Position Based Dynamics", the cloth simulator's tearing). Edges stay manifold: a
 * split never adds a triangle to an edge.
 */
public final class VertexSplit {
    private VertexSplit() {}

    /**
     * Gives {@code newVertex} the corners of the triangles around {@code vertex} whose centroids (at positions
     * x, xyz interleaved) lie on the side of the plane through {@code vertex} that (nx, ny, nz) points to.
     *
     * @return how many triangles moved; 0, with the triangles untouched, when all or none of them would
     *         (the plane does not cut the vertex's fan)
     */
    public static int split(int[] triangles, double[] x, int vertex, double nx, double ny, double nz, int newVertex) {
        if (!cuts(triangles, x, vertex, nx, ny, nz)) return 0;
        int far = 0;
        for (int t = 0; t < triangles.length; t += 3) {
            int corner = cornerOf(triangles, t, vertex);
            if (corner >= 0 && farSide(triangles, t, x, vertex, nx, ny, nz)) {
                triangles[t + corner] = newVertex;
                far++;
            }
        }
        return far;
    }

    /** Whether the plane through {@code vertex} square to (nx, ny, nz) parts its triangles (some on each side). Reads only. */
    public static boolean cuts(int[] triangles, double[] x, int vertex, double nx, double ny, double nz) {
        int around = 0, far = 0;
        for (int t = 0; t < triangles.length; t += 3) {
            if (cornerOf(triangles, t, vertex) < 0) continue;
            around++;
            if (farSide(triangles, t, x, vertex, nx, ny, nz)) far++;
        }
        return far > 0 && far < around;
    }

    private static int cornerOf(int[] triangles, int t, int vertex) {
        for (int k = 0; k < 3; k++) if (triangles[t + k] == vertex) return k;
        return -1;
    }

    private static boolean farSide(int[] triangles, int t, double[] x, int vertex, double nx, double ny, double nz) {
        double cx = 0, cy = 0, cz = 0;
        for (int k = 0; k < 3; k++) {
            int q = 3 * triangles[t + k];
            cx += x[q]; cy += x[q + 1]; cz += x[q + 2];
        }
        int v = 3 * vertex;
        return (cx / 3 - x[v]) * nx + (cy / 3 - x[v + 1]) * ny + (cz / 3 - x[v + 2]) * nz > 0;
    }
}
