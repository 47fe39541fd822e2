package xpbdcloth.mesh;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * A cloth's rest shape: vertex positions, polygon faces as authored (a quad keeps its four corners), the
 * faces' triangulation, polyline segments (a rope is a polyline with no faces) and named vertex groups.
 * Immutable and validated: every index is in range, every face has at least three distinct corners,
 * every position is finite.
 *
 * <p>Why keep polygons and not only triangles: a quad's diagonal is where it was split for drawing, not
 * a thread of the fabric. The cloth's edges (the structural family) are the polygons' sides, so a grid
 * of quads gets its row and column threads and no diagonals, as the original simulator had it.
 */
public final class ClothMesh {
    private final double[] positions;
    private final int[][] faces;
    private final int[] triangles;
    private final int[] segments;
    private final Map<String, int[]> groups;
    /** Texture coordinates per triangle corner (u, v; 6 per triangle), or null. */
    private final double[] triangleUVs;
    /** Why there are no texture coordinates, for messages (null when there are). */
    private final String withoutUVs;
    /** The bounding box, per axis (x, y, z). */
    private final double[] min = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE}, max = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};

    private ClothMesh(double[] positions, int[][] faces, int[] triangles, int[] segments, Map<String, int[]> groups, double[] triangleUVs, String withoutUVs) {
        for (int i = 0; i < positions.length; i++) {
            min[i % 3] = Math.min(min[i % 3], positions[i]);
            max[i % 3] = Math.max(max[i % 3], positions[i]);
        }
        this.positions = positions;
        this.faces = faces;
        this.triangles = triangles;
        this.segments = segments;
        this.groups = groups;
        this.triangleUVs = triangleUVs;
        this.withoutUVs = triangleUVs == null ? (withoutUVs == null ? "it has no texture coordinates" : withoutUVs) : null;
    }

    /**
     * A mesh from its parts (copied). {@code triangles} may be null: each face is then split as a fan
     * from its first corner. {@code segments} and {@code groups} may be null or empty.
     */
    public static ClothMesh of(double[] positions, int[][] faces, int[] triangles, int[] segments, Map<String, int[]> groups) {
        if (positions == null || positions.length % 3 != 0)
            throw new IllegalArgumentException("positions must be 3 numbers per vertex, was " + (positions == null ? "null" : positions.length + " numbers"));
        int n = positions.length / 3;
        for (int i = 0; i < positions.length; i++)
            if (!Double.isFinite(positions[i]))
                throw new IllegalArgumentException("positions of vertex " + i / 3 + " must be finite, was " + positions[i]);
        int[][] f = faces == null ? new int[0][] : new int[faces.length][];
        for (int k = 0; k < f.length; k++) {
            int[] face = faces[k];
            if (face == null || face.length < 3)
                throw new IllegalArgumentException("face " + k + " must have at least 3 corners, was " + (face == null ? "null" : face.length));
            for (int j = 0; j < face.length; j++) {
                index("face " + k + " corner", face[j], n);
                for (int i = 0; i < j; i++)
                    if (face[i] == face[j]) throw new IllegalArgumentException("face " + k + " must have distinct corners, vertex " + face[j] + " appears twice");
            }
            f[k] = face.clone();
        }
        int[] t = triangles == null ? fan(f) : triangles.clone();
        if (t.length % 3 != 0) throw new IllegalArgumentException("triangles must be 3 indices each, was " + t.length + " indices");
        for (int i = 0; i < t.length; i++) index("triangle " + i / 3 + " corner", t[i], n);
        int[] s = segments == null ? new int[0] : segments.clone();
        if (s.length % 2 != 0) throw new IllegalArgumentException("segments must be 2 indices each, was " + s.length + " indices");
        for (int i = 0; i < s.length; i++) index("segment " + i / 2 + " end", s[i], n);
        for (int i = 0; i < s.length; i += 2)
            if (s[i] == s[i + 1]) throw new IllegalArgumentException("segment " + i / 2 + " must join two vertices, was " + s[i] + " to itself");
        Map<String, int[]> g = new LinkedHashMap<>();
        if (groups != null)
            for (Map.Entry<String, int[]> e : groups.entrySet()) {
                for (int v : e.getValue()) index("group " + e.getKey() + " vertex", v, n);
                g.put(e.getKey(), e.getValue().clone());
            }
        return new ClothMesh(positions.clone(), f, t, s, Collections.unmodifiableMap(g), null, null);
    }

    /**
     * A mesh whose faces carry texture coordinates, {@code faceUVs[k]} the (u, v) of face k's corners in
     * order; the faces are split as fans, and each triangle takes its corners' coordinates.
     */
    public static ClothMesh withTextureCoordinates(double[] positions, int[][] faces, double[][] faceUVs, int[] segments, Map<String, int[]> groups) {
        ClothMesh m = of(positions, faces, null, segments, groups);
        if (faceUVs == null || faceUVs.length != m.faces.length)
            throw new IllegalArgumentException("faceUVs must give one entry per face (" + m.faces.length + "), was " + (faceUVs == null ? "null" : faceUVs.length));
        double[] uv = new double[2 * m.triangles.length];
        int k = 0;
        for (int f = 0; f < faceUVs.length; f++) {
            double[] c = faceUVs[f];
            if (c == null || c.length != 2 * m.faces[f].length)
                throw new IllegalArgumentException("faceUVs of face " + f + " must be " + 2 * m.faces[f].length + " numbers (u, v per corner), was " + (c == null ? "null" : c.length));
            for (double x : c) if (!Double.isFinite(x)) throw new IllegalArgumentException("faceUVs of face " + f + " must be finite, was " + java.util.Arrays.toString(c));
            for (int j = 1; j + 1 < m.faces[f].length; j++)  // the fan, as of() split it
                for (int corner : new int[] {0, j, j + 1}) { uv[k++] = c[2 * corner]; uv[k++] = c[2 * corner + 1]; }
        }
        return new ClothMesh(m.positions, m.faces, m.triangles, m.segments, m.groups, uv, null);
    }

    /** This mesh without texture coordinates, saying why (for the message of whoever needs them). */
    public ClothMesh withoutTextureCoordinates(String why) {
        return new ClothMesh(positions, faces, triangles, segments, groups, null, why);
    }

    /** Texture coordinates (u, v) of each triangle's corners, 6 per triangle in {@link #triangles()} order; null if none. */
    public double[] triangleUVs() { return triangleUVs == null ? null : triangleUVs.clone(); }

    /** Why the mesh has no texture coordinates (null if it has them). */
    public String whyNoTextureCoordinates() { return withoutUVs; }

    /** A polyline through the given points in order (a rope). */
    public static ClothMesh polyline(double[] positions) {
        int n = positions == null ? 0 : positions.length / 3;
        int[] s = new int[2 * Math.max(0, n - 1)];
        for (int i = 0; i + 1 < n; i++) { s[2 * i] = i; s[2 * i + 1] = i + 1; }
        return of(positions, null, null, s, null);
    }

    private static int[] fan(int[][] faces) {
        int count = 0;
        for (int[] f : faces) count += f.length - 2;
        int[] t = new int[3 * count];
        int k = 0;
        for (int[] f : faces)
            for (int j = 1; j + 1 < f.length; j++) { t[k++] = f[0]; t[k++] = f[j]; t[k++] = f[j + 1]; }
        return t;
    }

    private static void index(String what, int i, int n) {
        if (i < 0 || i >= n) throw new IllegalArgumentException(what + " must be a vertex index in [0, " + (n - 1) + "], was " + i);
    }

    public int vertexCount() { return positions.length / 3; }
    public int faceCount() { return faces.length; }
    public double x(int i) { return positions[3 * i]; }
    public double y(int i) { return positions[3 * i + 1]; }
    public double z(int i) { return positions[3 * i + 2]; }

    /** The smallest coordinate along an axis (0 = x, 1 = y, 2 = z) of any vertex. */
    public double min(int axis) { return min[axis]; }

    /** The largest coordinate along an axis of any vertex. */
    public double max(int axis) { return max[axis]; }

    /** A copy of the positions, 3 per vertex. */
    public double[] positions() { return positions.clone(); }

    /** A copy of face k's corners. */
    public int[] face(int k) { return faces[k].clone(); }

    /** A copy of the triangulation, 3 indices per triangle. */
    public int[] triangles() { return triangles.clone(); }

    /** A copy of the polyline segments, 2 indices each. */
    public int[] segments() { return segments.clone(); }

    /** Named vertex groups (OBJ {@code g} and {@code o} names), each a sorted list of vertex indices. */
    public Map<String, int[]> groups() {
        Map<String, int[]> out = new LinkedHashMap<>();
        groups.forEach((k, v) -> out.put(k, v.clone()));
        return out;
    }

    /** The vertices of a named group; an unknown name is an error listing the names there are. */
    public int[] group(String name) {
        int[] g = groups.get(name);
        if (g == null)
            throw new IllegalArgumentException("group must be one of " + (groups.isEmpty() ? "(the mesh has no groups)" : String.join(", ", groups.keySet())) + ", was \"" + name + "\"");
        return g.clone();
    }

    /** Vertices inside the axis-aligned box [min, max] (inclusive), in index order. */
    public int[] inBox(double[] lo, double[] hi) {
        return java.util.stream.IntStream.range(0, vertexCount()).filter(i -> {
            for (int d = 0; d < 3; d++) if (positions[3 * i + d] < lo[d] || positions[3 * i + d] > hi[d]) return false;
            return true;
        }).toArray();
    }

    /** Area of face k: the sum of its fan triangles' areas (exact for a planar convex polygon). */
    public double faceArea(int k) {
        int[] f = faces[k];
        double a = 0;
        for (int j = 1; j + 1 < f.length; j++) a += triangleArea(f[0], f[j], f[j + 1]);
        return a;
    }

    double triangleArea(int a, int b, int c) {
        double[] x = positions;
        double e1x = x[3 * b] - x[3 * a], e1y = x[3 * b + 1] - x[3 * a + 1], e1z = x[3 * b + 2] - x[3 * a + 2];
        double e2x = x[3 * c] - x[3 * a], e2y = x[3 * c + 1] - x[3 * a + 1], e2z = x[3 * c + 2] - x[3 * a + 2];
        double nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
        return 0.5 * Math.sqrt(nx * nx + ny * ny + nz * nz);
    }

    /** Total area of the faces (m²). */
    public double area() {
        double a = 0;
        for (int k = 0; k < faces.length; k++) a += faceArea(k);
        return a;
    }

    public int segmentCount() { return segments.length / 2; }

    /** Length of segment k (m). */
    public double segmentLength(int k) { return distance(segments[2 * k], segments[2 * k + 1]); }

    /**
     * The shortest edge between particles at rest (m): a triangle's side or a segment; +∞ for a mesh of
     * neither. A cloth's thickness against itself may not exceed it, or neighbours would push apart.
     */
    public double shortestEdge() {
        double shortest = Double.POSITIVE_INFINITY;
        for (int k = 0; k < triangles.length; k++) shortest = Math.min(shortest, distance(triangles[k], triangles[k % 3 == 2 ? k - 2 : k + 1]));
        for (int k = 0; k < segments.length; k += 2) shortest = Math.min(shortest, distance(segments[k], segments[k + 1]));
        return shortest;
    }

    /** Distance between vertices a and b (m). */
    public double distance(int a, int b) {
        double dx = positions[3 * b] - positions[3 * a], dy = positions[3 * b + 1] - positions[3 * a + 1], dz = positions[3 * b + 2] - positions[3 * a + 2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /**
     * This mesh scaled by s, then rotated by the angles (rx, ry, rz) in degrees about x, then y, then z,
     * then moved by t: how a preset places a mesh file in its scene.
     */
    public ClothMesh transformed(double s, double[] rotationDegrees, double[] t) {
        return new ClothMesh(place(positions, s, rotationDegrees, t), faces, triangles, segments, groups, triangleUVs, withoutUVs);
    }

    /** Positions (3 per vertex) scaled by s, rotated about x, then y, then z by the angles in degrees, then moved by t (a copy). */
    public static double[] place(double[] positions, double s, double[] rotationDegrees, double[] t) {
        double[] p = positions.clone();
        double ax = Math.toRadians(rotationDegrees[0]), ay = Math.toRadians(rotationDegrees[1]), az = Math.toRadians(rotationDegrees[2]);
        for (int i = 0; i < p.length; i += 3) {
            double x = s * p[i], y = s * p[i + 1], z = s * p[i + 2], u;
            u = y * Math.cos(ax) - z * Math.sin(ax); z = y * Math.sin(ax) + z * Math.cos(ax); y = u;
            u = x * Math.cos(ay) + z * Math.sin(ay); z = -x * Math.sin(ay) + z * Math.cos(ay); x = u;
            u = x * Math.cos(az) - y * Math.sin(az); y = x * Math.sin(az) + y * Math.cos(az); x = u;
            p[i] = x + t[0]; p[i + 1] = y + t[1]; p[i + 2] = z + t[2];
        }
        return p;
    }
}
