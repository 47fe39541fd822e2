package xpbdcloth.mesh;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * What a cloth's constraint families are built from, derived from a {@link ClothMesh} alone:
 * <ul>
 * <li><b>edges</b>: the polygons' sides and the polyline segments, each once, as (a &lt; b), sorted by a
 *     then b. On a grid of quads these are the row and column threads in row-major order.</li>
 * <li><b>corners</b>: one per face, (vertex, end1, end2) = (first corner, last corner, second corner),
 *     the angle at the face's first corner between its two sides. On a grid quad this is the right angle
 *     between the row and the column thread at its top-left particle.</li>
 * <li><b>straight runs</b>: triples (b₀, v, b₁) where the edges v–b₀ and v–b₁ continue each other through
 *     v: each is the other's straightest partner among v's edges (largest rest angle, ties to the lower
 *     index) and the angle is at least {@link #STRAIGHT_DEGREES}. b₀ &lt; b₁, sorted by b₀ then v. On a
 *     grid these are the rows and columns through each particle, the lines a grid cloth bends along; on a
 *     regular triangle mesh the three lines through each interior vertex; on a polar mesh the rings and
 *     the spokes. A vertex with a zero-length edge has no runs through that edge.</li>
 * </ul>
 * The mesh must be manifold: no edge may be a side of more than two faces.
 */
public final class MeshTopology {
    /** Two edges through a vertex count as one straight run if they make at least this angle at rest. */
    public static final double STRAIGHT_DEGREES = 150;
    private static final double STRAIGHT_COS = Math.cos(Math.toRadians(STRAIGHT_DEGREES));

    private final int[] edges;
    private final int[] corners;
    private final int[] runs;

    private MeshTopology(int[] edges, int[] corners, int[] runs) {
        this.edges = edges;
        this.corners = corners;
        this.runs = runs;
    }

    public static MeshTopology of(ClothMesh mesh) {
        int n = mesh.vertexCount();
        // Each side keyed a·n + b (a < b), with its face (or -1 for a segment), so sorting finds repeats.
        List<long[]> sides = new ArrayList<>();
        for (int k = 0; k < mesh.faceCount(); k++) {
            int[] f = mesh.face(k);
            for (int j = 0; j < f.length; j++) {
                int a = f[j], b = f[(j + 1) % f.length];
                sides.add(new long[] {key(a, b, n), k});
            }
        }
        int[] s = mesh.segments();
        for (int i = 0; i < s.length; i += 2) sides.add(new long[] {key(s[i], s[i + 1], n), -1});
        sides.sort((p, q) -> p[0] != q[0] ? Long.compare(p[0], q[0]) : Long.compare(p[1], q[1]));
        List<Integer> unique = new ArrayList<>();
        for (int i = 0; i < sides.size(); ) {
            int j = i, faces = 0;
            while (j < sides.size() && sides.get(j)[0] == sides.get(i)[0]) { if (sides.get(j)[1] >= 0) faces++; j++; }
            long k = sides.get(i)[0];
            int a = (int) (k / n), b = (int) (k % n);
            if (faces > 2) {
                StringBuilder which = new StringBuilder();
                for (int m = i; m < j; m++) if (sides.get(m)[1] >= 0) which.append(which.length() == 0 ? "" : ", ").append(sides.get(m)[1]);
                throw new IllegalArgumentException("edge (" + a + ", " + b + ") is a side of " + faces + " faces (" + which + "): the mesh is not manifold");
            }
            unique.add(a);
            unique.add(b);
            i = j;
        }
        int[] edges = unique.stream().mapToInt(Integer::intValue).toArray();

        int[] corners = new int[3 * mesh.faceCount()];
        for (int k = 0; k < mesh.faceCount(); k++) {
            int[] f = mesh.face(k);
            corners[3 * k] = f[0];
            corners[3 * k + 1] = f[f.length - 1];
            corners[3 * k + 2] = f[1];
        }
        return new MeshTopology(edges, corners, straightRuns(mesh, edges));
    }

    private static long key(int a, int b, int n) {
        return a < b ? (long) a * n + b : (long) b * n + a;
    }

    private static int[] straightRuns(ClothMesh mesh, int[] edges) {
        int n = mesh.vertexCount();
        int[][] neighbours = neighbours(n, edges);
        List<int[]> runs = new ArrayList<>();
        for (int v = 0; v < n; v++) {
            int[] nb = neighbours[v];
            int[] best = new int[nb.length];
            double[] bestCos = new double[nb.length];
            for (int i = 0; i < nb.length; i++) {
                best[i] = -1;
                bestCos[i] = Double.POSITIVE_INFINITY;
                for (int j = 0; j < nb.length; j++) {
                    if (j == i) continue;
                    double c = cosine(mesh, v, nb[i], nb[j]);
                    if (c < bestCos[i]) { bestCos[i] = c; best[i] = j; }
                }
            }
            for (int i = 0; i < nb.length; i++) {
                int j = best[i];
                if (j > i && best[j] == i && bestCos[i] <= STRAIGHT_COS) runs.add(new int[] {nb[i], v, nb[j]});
            }
        }
        runs.sort((p, q) -> p[0] != q[0] ? Integer.compare(p[0], q[0]) : Integer.compare(p[1], q[1]));
        int[] out = new int[3 * runs.size()];
        for (int k = 0; k < runs.size(); k++) System.arraycopy(runs.get(k), 0, out, 3 * k, 3);
        return out;
    }

    /** Each vertex's edge neighbours, ascending. */
    private static int[][] neighbours(int n, int[] edges) {
        int[] count = new int[n];
        for (int e : edges) count[e]++;
        int[][] nb = new int[n][];
        for (int v = 0; v < n; v++) nb[v] = new int[count[v]];
        Arrays.fill(count, 0);
        for (int i = 0; i < edges.length; i += 2) {
            int a = edges[i], b = edges[i + 1];
            nb[a][count[a]++] = b;
            nb[b][count[b]++] = a;
        }
        for (int[] list : nb) Arrays.sort(list);
        return nb;
    }

    /** cos of the rest angle a–v–b; +∞ (never straight) when an edge has zero length. */
    private static double cosine(ClothMesh m, int v, int a, int b) {
        double ax = m.x(a) - m.x(v), ay = m.y(a) - m.y(v), az = m.z(a) - m.z(v);
        double bx = m.x(b) - m.x(v), by = m.y(b) - m.y(v), bz = m.z(b) - m.z(v);
        double la = Math.sqrt(ax * ax + ay * ay + az * az), lb = Math.sqrt(bx * bx + by * by + bz * bz);
        if (la == 0 || lb == 0) return Double.POSITIVE_INFINITY;
        return (ax * bx + ay * by + az * bz) / (la * lb);
    }

    /** Edges as pairs (a &lt; b), 2 indices each. */
    public int[] edges() { return edges.clone(); }

    /** Face corners as (vertex, end1, end2), 3 indices each, one per face. */
    public int[] corners() { return corners.clone(); }

    /** Straight runs as (b₀, v, b₁), 3 indices each. */
    public int[] straightRuns() { return runs.clone(); }
}
