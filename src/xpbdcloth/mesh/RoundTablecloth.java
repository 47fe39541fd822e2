package xpbdcloth.mesh;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * A round tablecloth lying flat in the x–z plane, centred on the origin: a triangle mesh (no quads), a
 * centre vertex and {@code rings} concentric rings, ring r holding 6r vertices evenly spaced, so every
 * triangle is close to equilateral (the mesh is the hexagonal lattice bent round: around the centre it is
 * exactly that lattice). Neighbouring rings are stitched by walking both in angle, always advancing the
 * ring whose next vertex comes first. All triangles are counter-clockwise seen from +y.
 * Vertex 0 is the centre; ring r (1 … rings) starts at index 1 + 3r(r − 1), its vertex j at angle
 * 2πj/(6r) from +x towards −z. Groups: "centre" and "hem" (the outer ring).
 *
 * <p>Its straight runs (bending lines, see {@link MeshTopology}): the three lattice lines through every
 * vertex near the centre and, from the third ring out (where a ring turns by at most 20° per vertex), the
 * rings themselves.
 */
public final class RoundTablecloth {
    private RoundTablecloth() {}

    public static ClothMesh generate(double radius, int rings) {
        if (!(radius > 0) || !Double.isFinite(radius)) throw new IllegalArgumentException("radius must be > 0, was " + radius);
        if (rings < 1 || rings > 200) throw new IllegalArgumentException("rings must be in [1, 200], was " + rings);
        int n = 1 + 3 * rings * (rings + 1);
        double[] x = new double[3 * n];
        for (int r = 1; r <= rings; r++)
            for (int j = 0; j < 6 * r; j++) {
                int i = first(r) + j;
                double rho = radius * r / rings, phi = 2 * Math.PI * j / (6 * r);
                x[3 * i] = rho * Math.cos(phi);
                x[3 * i + 2] = -rho * Math.sin(phi) + 0.0; // + 0.0: no "-0.0" in the file
            }
        int[][] faces = new int[6 * rings * rings][];
        int k = 0;
        for (int r = 1; r <= rings; r++) {
            int inner = r == 1 ? 1 : 6 * (r - 1), outer = 6 * r;
            int i = 0, j = 0;
            while (i < inner || j < outer) {
                // Advance the ring whose next vertex comes first in angle (the inner one on a tie).
                boolean advanceInner = j == outer || i < inner && (double) (i + 1) / inner <= (double) (j + 1) / outer;
                int a = vertex(r - 1, i % inner), b = vertex(r, j % outer);
                int c = advanceInner ? vertex(r - 1, (i + 1) % inner) : vertex(r, (j + 1) % outer);
                if (r == 1 && advanceInner) { i++; continue; } // the centre is a ring of one vertex
                faces[k++] = upward(x, a, b, c);
                if (advanceInner) i++; else j++;
            }
        }
        int[] hem = new int[6 * rings];
        for (int j = 0; j < hem.length; j++) hem[j] = first(rings) + j;
        Map<String, int[]> groups = new LinkedHashMap<>();
        groups.put("centre", new int[] {0});
        groups.put("hem", hem);
        return ClothMesh.of(x, java.util.Arrays.copyOf(faces, k), null, null, groups);
    }

    private static int first(int ring) { return ring == 0 ? 0 : 1 + 3 * ring * (ring - 1); }

    private static int vertex(int ring, int j) { return ring == 0 ? 0 : first(ring) + j; }

    /** The triangle (a, b, c) or (a, c, b), whichever is counter-clockwise seen from +y. */
    private static int[] upward(double[] x, int a, int b, int c) {
        double e1x = x[3 * b] - x[3 * a], e1z = x[3 * b + 2] - x[3 * a + 2];
        double e2x = x[3 * c] - x[3 * a], e2z = x[3 * c + 2] - x[3 * a + 2];
        return e1z * e2x - e1x * e2z > 0 ? new int[] {a, b, c} : new int[] {a, c, b};
    }
}
