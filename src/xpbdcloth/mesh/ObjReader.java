package xpbdcloth.mesh;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;

/**
 * Reads a Wavefront OBJ file as a {@link ClothMesh}, strictly: everything is checked before a mesh
 * exists, and the first problem is a {@link MeshFileException} naming {@code file:line: problem}.
 *
 * <ul>
 * <li>{@code v x y z} vertices; {@code f} faces of 3 or more corners in any of the forms {@code v},
 *     {@code v/vt}, {@code v//vn}, {@code v/vt/vn}, with negative indices counting back from the last
 *     vertex; {@code l} polylines (a rope); {@code g} and {@code o} name the vertex groups that the
 *     vertices of the following faces, lines and points ({@code p}, which only tag vertices a face or
 *     line already uses) belong to. Texture coordinates ({@code vt u v}) are kept when every face gives
 *     one at every corner (a fabric's warp can follow them); normals, smoothing and materials
 *     ({@code vn vp s usemtl mtllib}) are read past; any other statement is an error, because skipping
 *     it (a free-form surface, say) would load half a model without a word.</li>
 * <li>Vertices closer than the weld tolerance (m) become one, the first in file order (an exporter
 *     that splits vertices along UV seams would otherwise cut the cloth along them); 0 merges only
 *     identical positions. Vertices no face or line uses are dropped. The mesh's vertex indices count
 *     the remaining vertices in file order, from 0.</li>
 * <li>Refused: a face with a corner repeated (also after welding), a face of zero area, a face given
 *     twice, an edge that is a side of more than two faces (not a manifold), an index out of range, a
 *     number that is not finite, a file with no faces or lines.</li>
 * </ul>
 */
public final class ObjReader {
    /** A face whose area is below this fraction of its longest side squared counts as degenerate. */
    static final double DEGENERATE_AREA = 1e-12;
    /**
     * The largest OBJ file read, bytes. A cloth has at most 262 144 vertices (the presets' limit), a few
     * tens of MB as text with its faces, normals and texture coordinates; past that a file would take
     * minutes and gigabytes to refuse.
     */
    public static final long MAX_FILE_BYTES = 64L << 20;
    /** Vertex statements in one file (before welding): four times the largest cloth. */
    public static final int MAX_VERTICES = 1 << 20;
    /** Corners of one face: a polygon has tens at most; the checks on a face are then cheap. */
    public static final int MAX_CORNERS = 256;
    /** The largest |coordinate| in a file, in its own units: beyond it areas and lengths overflow. */
    public static final double MAX_COORDINATE = 1e12;

    private ObjReader() {}

    public static ClothMesh read(Path path, double weldTolerance) {
        return parse(path.toString(), text(path), weldTolerance);
    }

    /** A file's text, guarded: a regular file (a link that leads nowhere said so), at most {@link #MAX_FILE_BYTES}, UTF-8. */
    static String text(Path path) {
        String file = path.toString();
        if (!Files.isRegularFile(path)) {
            String why = Files.exists(path) ? "is not a regular file"
                    : Files.isSymbolicLink(path) ? "is a symbolic link that leads to no file (a loop, or a missing target)" : "does not exist";
            throw new MeshFileException(file, 0, why);
        }
        try {
            long size = Files.size(path);
            if (size > MAX_FILE_BYTES)
                throw new MeshFileException(file, 0, "is " + size + " bytes, more than the " + MAX_FILE_BYTES + " an OBJ cloth may have (a cloth has 262144 vertices at most)");
            return utf8(file, Files.readAllBytes(path));
        } catch (IOException e) {
            throw new MeshFileException(file, 0, "cannot be read: " + e.getMessage());
        }
    }

    /**
     * Only the vertex positions of an OBJ, in file order, xyz interleaved, unwelded and whatever its faces
     * (an observation of a cloth is its vertices in the scene's order: two that coincide are two vertices,
     * and the faces are the scene's). The same limits on the file, its text and its numbers as {@link #read}.
     */
    public static double[] vertices(Path path) {
        String file = path.toString(), text = text(path);
        Parse parse = new Parse(file, 0);
        String[] lines = text.split("\r\n|\n|\r", -1);
        double[] out = new double[3 * 64];
        int n = 0;
        for (int ln = 1; ln <= lines.length; ln++) {
            String line = lines[ln - 1].trim();
            if (!line.startsWith("v ") && !line.startsWith("v\t")) continue;
            int hash = line.indexOf('#');
            String[] tok = (hash >= 0 ? line.substring(0, hash) : line).trim().split("\\s+");
            double[] p = parse.position(ln, tok, n);
            if (3 * n + 3 > out.length) out = Arrays.copyOf(out, 2 * out.length);
            System.arraycopy(p, 0, out, 3 * n, 3);
            n++;
        }
        if (n == 0) throw new MeshFileException(file, 0, "has no vertices (v)");
        return Arrays.copyOf(out, 3 * n);
    }

    /** The bytes as UTF-8 text, a byte-order mark dropped; bytes that are not UTF-8 are named by their line. */
    static String utf8(String file, byte[] bytes) {
        java.nio.charset.CharsetDecoder strict = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(java.nio.charset.CodingErrorAction.REPORT).onUnmappableCharacter(java.nio.charset.CodingErrorAction.REPORT);
        try {
            String text = strict.decode(java.nio.ByteBuffer.wrap(bytes)).toString();
            return text.startsWith("\uFEFF") ? text.substring(1) : text;
        } catch (java.nio.charset.CharacterCodingException e) {
            int line = 1;
            for (int start = 0; start < bytes.length; line++) {
                int end = start;
                while (end < bytes.length && bytes[end] != '\n') end++;
                try {
                    strict.reset().decode(java.nio.ByteBuffer.wrap(bytes, start, end - start));
                } catch (java.nio.charset.CharacterCodingException bad) {
                    throw new MeshFileException(file, line, "is not UTF-8 text here (an OBJ file is text; is this a binary file?)");
                }
                start = end + 1;
            }
            throw new MeshFileException(file, 0, "is not UTF-8 text");
        }
    }

    /** A token of the file as an error message may show it: at most 24 characters, control characters escaped. */
    static String shown(String token) {
        String t = token.length() > 24 ? token.substring(0, 24) + "…" : token;
        StringBuilder b = new StringBuilder();
        for (char c : t.toCharArray()) b.append(Character.isISOControl(c) ? String.format("\\u%04x", (int) c) : String.valueOf(c));
        return b.toString();
    }

    /** Parses OBJ text; {@code file} names it in errors. */
    public static ClothMesh parse(String file, String text, double weldTolerance) {
        if (!(weldTolerance >= 0) || !Double.isFinite(weldTolerance))
            throw new IllegalArgumentException("weldTolerance must be >= 0 and finite, was " + weldTolerance);
        return new Parse(file, weldTolerance).run(text);
    }

    private static final class Parse {
        final String file;
        final double tolerance;
        final List<double[]> vertices = new ArrayList<>();
        /** File vertex → welded vertex. */
        final List<Integer> weldedOf = new ArrayList<>();
        final List<double[]> welded = new ArrayList<>();
        final Map<List<Long>, List<Integer>> cells = new HashMap<>();
        final List<int[]> faces = new ArrayList<>();
        final List<Integer> faceLines = new ArrayList<>();
        final List<int[]> segments = new ArrayList<>();
        final Map<String, TreeSet<Integer>> groups = new LinkedHashMap<>();
        List<String> currentGroups = List.of();
        final Map<Long, int[]> edgeFaces = new HashMap<>();
        final Map<String, Integer> faceKeys = new HashMap<>();
        final List<Integer> pointLines = new ArrayList<>();
        final List<double[]> texture = new ArrayList<>();
        /** Per face, the texture coordinates of its corners (u, v interleaved), or null if it gives none. */
        final List<double[]> faceUVs = new ArrayList<>();
        /** The line of the first face without texture coordinates, 0 if every face has them. */
        int firstFaceWithoutUV;
        final List<int[]> pointSets = new ArrayList<>();

        Parse(String file, double tolerance) {
            this.file = file;
            this.tolerance = tolerance;
        }

        MeshFileException fail(int line, String problem) { return new MeshFileException(file, line, problem); }

        ClothMesh run(String text) {
            if (text.startsWith("\uFEFF")) text = text.substring(1); // a byte-order mark is no statement
            String[] lines = text.split("\r\n|\n|\r", -1);
            for (int ln = 1; ln <= lines.length; ln++) {
                String s = lines[ln - 1];
                int hash = s.indexOf('#');
                if (hash >= 0) s = s.substring(0, hash);
                s = s.trim();
                if (s.isEmpty()) continue;
                String[] tok = s.split("\\s+");
                switch (tok[0]) {
                    case "v": vertex(ln, tok); break;
                    case "f": face(ln, tok); break;
                    case "l": line(ln, tok); break;
                    case "p": points(ln, tok); break;
                    case "g": case "o":
                        currentGroups = Arrays.asList(Arrays.copyOfRange(tok, 1, tok.length));
                        break;
                    case "vt": textureCoordinate(ln, tok); break;
                    case "vn": case "vp": case "s": case "usemtl": case "mtllib": break;
                    default:
                        // A file whose first statement is not OBJ is not an OBJ file: say so, and echo nothing more of it.
                        if (vertices.isEmpty() && faces.isEmpty() && texture.isEmpty())
                            throw fail(ln, "is not an OBJ file: its first statement is not one (a cloth reads v, vt, f, l, p, g, o)");
                        throw fail(ln, "unsupported statement \"" + shown(tok[0]) + "\" (a cloth reads v, vt, f, l, p, g, o; vn, vp, s, usemtl, mtllib are read past)");
                }
            }
            if (faces.isEmpty() && segments.isEmpty()) throw fail(0, "has no faces (f) or lines (l): nothing to build a cloth from");
            return build();
        }

        void vertex(int ln, String[] tok) {
            double[] p = position(ln, tok, vertices.size());
            vertices.add(p);
            weldedOf.add(weld(p));
        }

        /** The position a {@code v} statement gives, checked (the file's {@code count + 1}th vertex). */
        double[] position(int ln, String[] tok, int count) {
            if (count == MAX_VERTICES) throw fail(ln, "more than " + MAX_VERTICES + " vertices: too many for a cloth");
            if (tok.length < 4) throw fail(ln, "a vertex needs x y z, was " + (tok.length - 1) + " numbers");
            double[] p = coordinates(ln, tok, "vertex coordinate ", "xyz");
            for (int d = 0; d < 3; d++)
                if (Math.abs(p[d]) > MAX_COORDINATE) throw fail(ln, "vertex coordinate " + "xyz".charAt(d) + " must be within ±" + MAX_COORDINATE + ", was " + shown(tok[d + 1]));
            return p;
        }

        /** vt u [v [w]]: a missing v is 0 (a 1-D texture), w is read past. */
        void textureCoordinate(int ln, String[] tok) {
            if (tok.length < 2) throw fail(ln, "a texture coordinate needs u (and v), was none");
            texture.add(coordinates(ln, tok, "texture coordinate ", tok.length == 2 ? "u" : "uv"));
        }

        /** The finite numbers after the statement, one per letter of {@code axes} (named by it in errors), at least two. */
        double[] coordinates(int ln, String[] tok, String what, String axes) {
            double[] out = new double[Math.max(axes.length(), 2)];
            for (int d = 0; d < axes.length(); d++) {
                try {
                    out[d] = Double.parseDouble(tok[d + 1]);
                } catch (NumberFormatException e) {
                    throw fail(ln, what + axes.charAt(d) + " is not a number: \"" + shown(tok[d + 1]) + "\"");
                }
                if (!Double.isFinite(out[d])) throw fail(ln, what + axes.charAt(d) + " must be finite, was " + shown(tok[d + 1]));
            }
            return out;
        }

        /** The texture coordinate a corner token names ("7/2", "7/2/3"), or null if it names none. */
        double[] cornerUV(int ln, String token) {
            String[] parts = token.split("/", -1);
            if (parts.length < 2 || parts[1].isEmpty()) return null;
            int i = index(ln, parts[1], "corner \"" + shown(token) + "\": its texture index is not a number", "texture index ");
            int n = texture.size();
            int at = i > 0 ? i - 1 : n + i;
            if (i == 0 || at < 0 || at >= n)
                throw fail(ln, "texture index " + i + " is out of range: " + n + " texture coordinates (vt) are defined above this line");
            return texture.get(at);
        }

        /** The welded vertex for p: the first earlier one within the tolerance, or a new one. */
        int weld(double[] p) {
            double cell = tolerance > 0 ? tolerance : 1;
            long cx = (long) Math.floor(p[0] / cell), cy = (long) Math.floor(p[1] / cell), cz = (long) Math.floor(p[2] / cell);
            int found = -1;
            for (long i = cx - 1; i <= cx + 1; i++)
                for (long j = cy - 1; j <= cy + 1; j++)
                    for (long k = cz - 1; k <= cz + 1; k++) {
                        List<Integer> in = cells.get(List.of(i, j, k));
                        if (in == null) continue;
                        for (int w : in) {
                            double[] q = welded.get(w);
                            double dx = q[0] - p[0], dy = q[1] - p[1], dz = q[2] - p[2];
                            if (Math.sqrt(dx * dx + dy * dy + dz * dz) <= tolerance && (found < 0 || w < found)) found = w;
                        }
                    }
            if (found >= 0) return found;
            welded.add(p);
            cells.computeIfAbsent(List.of(cx, cy, cz), key -> new ArrayList<>()).add(welded.size() - 1);
            return welded.size() - 1;
        }

        /** An index as written: an integer, however long (one too large for any file is out of range, not "not a number"). */
        int index(int ln, String digits, String notANumber, String what) {
            if (!digits.matches("-?[0-9]+")) throw fail(ln, notANumber);
            try {
                return Integer.parseInt(digits);
            } catch (NumberFormatException tooLong) {
                throw fail(ln, what + shown(digits) + " is out of range: no file has that many");
            }
        }

        /** The welded vertex a corner token names ("7", "7/2", "7//3", "7/2/3", "-1"). */
        int corner(int ln, String token) {
            String v = token.split("/", -1)[0];
            int i = index(ln, v, "corner \"" + shown(token) + "\" does not start with a vertex index", "vertex index ");
            int n = vertices.size();
            int at = i > 0 ? i - 1 : n + i;
            if (i == 0 || at < 0 || at >= n)
                throw fail(ln, "vertex index " + i + " is out of range: " + n + " vertices are defined above this line (1.." + n + ", or -1..-" + n + ")");
            return weldedOf.get(at);
        }

        void face(int ln, String[] tok) {
            if (tok.length < 4) throw fail(ln, "a face needs at least 3 corners, was " + (tok.length - 1));
            if (tok.length - 1 > MAX_CORNERS) throw fail(ln, "a face has at most " + MAX_CORNERS + " corners, this one " + (tok.length - 1));
            int[] f = new int[tok.length - 1];
            Map<Integer, Integer> seen = new HashMap<>(); // vertex → its first corner: one pass, not every pair
            for (int j = 0; j < f.length; j++) {
                f[j] = corner(ln, tok[j + 1]);
                Integer i = seen.putIfAbsent(f[j], j);
                if (i != null)
                    throw fail(ln, "face is degenerate: corners " + (i + 1) + " (" + shown(tok[i + 1]) + ") and " + (j + 1) + " (" + shown(tok[j + 1]) + ") are the same vertex"
                            + (tolerance > 0 ? " after welding within " + tolerance + " m" : ""));
            }
            if (f.length > 3) selfIntersection(ln, f);
            int[] sorted = f.clone();
            Arrays.sort(sorted);
            Integer twin = faceKeys.putIfAbsent(Arrays.toString(sorted), ln);
            if (twin != null) throw fail(ln, "face repeats the face on line " + twin);
            for (int j = 0; j < f.length; j++) {
                int a = Math.min(f[j], f[(j + 1) % f.length]), b = Math.max(f[j], f[(j + 1) % f.length]);
                int[] on = edgeFaces.computeIfAbsent((long) a << 32 | b, key -> new int[3]);
                if (on[0] == 2)
                    throw fail(ln, "not a manifold: this face's side from " + point(a) + " to " + point(b)
                            + " is already a side of the faces on lines " + on[1] + " and " + on[2] + " (a cloth edge has at most two faces)");
                on[++on[0]] = ln;
            }
            double[] uv = new double[2 * f.length];
            for (int j = 0; j < f.length && uv != null; j++) {
                double[] c = cornerUV(ln, tok[j + 1]);
                if (c == null) uv = null;
                else { uv[2 * j] = c[0]; uv[2 * j + 1] = c[1]; }
            }
            if (uv == null && firstFaceWithoutUV == 0) firstFaceWithoutUV = ln;
            faces.add(f);
            faceUVs.add(uv);
            faceLines.add(ln);
            group(f);
        }

        /**
         * A polygon whose sides cross (a bowtie) is no face: its corners are projected onto the plane of its
         * Newell normal, and no two sides that share no corner may cross there.
         */
        void selfIntersection(int ln, int[] f) {
            double nx = 0, ny = 0, nz = 0;
            for (int j = 0; j < f.length; j++) {
                double[] a = welded.get(f[j]), b = welded.get(f[(j + 1) % f.length]);
                nx += (a[1] - b[1]) * (a[2] + b[2]);
                ny += (a[2] - b[2]) * (a[0] + b[0]);
                nz += (a[0] - b[0]) * (a[1] + b[1]);
            }
            // Drop the axis the normal is most along: the polygon's shadow on the other two keeps its shape.
            // A bowtie's Newell normal cancels to nothing: then drop the axis the corners spread least along.
            double[] lo = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE}, hi = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
            for (int c : f) for (int d = 0; d < 3; d++) { lo[d] = Math.min(lo[d], welded.get(c)[d]); hi[d] = Math.max(hi[d], welded.get(c)[d]); }
            double extent = Math.max(hi[0] - lo[0], Math.max(hi[1] - lo[1], hi[2] - lo[2]));
            if (Math.sqrt(nx * nx + ny * ny + nz * nz) < 1e-9 * extent * extent) { nx = extent - (hi[0] - lo[0]); ny = extent - (hi[1] - lo[1]); nz = extent - (hi[2] - lo[2]); }
            int drop = Math.abs(nx) >= Math.abs(ny) && Math.abs(nx) >= Math.abs(nz) ? 0 : Math.abs(ny) >= Math.abs(nz) ? 1 : 2;
            int u = drop == 0 ? 1 : 0, v = drop == 2 ? 1 : 2;
            for (int a = 0; a < f.length; a++)
                for (int b = a + 2; b < f.length; b++) {
                    if (a == 0 && b == f.length - 1) continue; // adjacent through the last corner
                    double[] p = welded.get(f[a]), q = welded.get(f[(a + 1) % f.length]), r = welded.get(f[b]), t = welded.get(f[(b + 1) % f.length]);
                    if (cross(p[u], p[v], q[u], q[v], r[u], r[v], t[u], t[v]))
                        throw fail(ln, "face crosses itself: its sides " + (a + 1) + "–" + (a + 2) + " and " + (b + 1) + "–" + ((b + 1) % f.length + 1) + " cross (corners out of order?)");
                }
        }

        /** Whether segments pq and rt cross at a point inside both (touching at an end does not count). */
        static boolean cross(double px, double py, double qx, double qy, double rx, double ry, double tx, double ty) {
            double d1 = orient(rx, ry, tx, ty, px, py), d2 = orient(rx, ry, tx, ty, qx, qy);
            double d3 = orient(px, py, qx, qy, rx, ry), d4 = orient(px, py, qx, qy, tx, ty);
            return d1 * d2 < 0 && d3 * d4 < 0;
        }

        static double orient(double ax, double ay, double bx, double by, double cx, double cy) {
            return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
        }

        void line(int ln, String[] tok) {
            if (tok.length < 3) throw fail(ln, "a line needs at least 2 vertices, was " + (tok.length - 1));
            int[] l = new int[tok.length - 1];
            for (int j = 0; j < l.length; j++) l[j] = corner(ln, tok[j + 1]);
            for (int j = 0; j + 1 < l.length; j++) {
                if (l[j] == l[j + 1]) throw fail(ln, "line joins a vertex to itself at points " + (j + 1) + " and " + (j + 2));
                segments.add(new int[] {l[j], l[j + 1]});
            }
            group(l);
        }

        /** Point elements only tag vertices with the current groups; every vertex still needs a face or line. */
        void points(int ln, String[] tok) {
            if (tok.length < 2) throw fail(ln, "a point statement needs at least 1 vertex, was 0");
            int[] p = new int[tok.length - 1];
            for (int j = 0; j < p.length; j++) p[j] = corner(ln, tok[j + 1]);
            pointLines.add(ln);
            pointSets.add(p);
            group(p);
        }

        void group(int[] vs) {
            for (String g : currentGroups)
                for (int v : vs) groups.computeIfAbsent(g, key -> new TreeSet<>()).add(v);
        }

        String point(int v) {
            double[] p = welded.get(v);
            return "(" + p[0] + ", " + p[1] + ", " + p[2] + ")";
        }

        /** Drops unused welded vertices and renumbers the rest in file order. */
        ClothMesh build() {
            int[] newIndex = new int[welded.size()];
            Arrays.fill(newIndex, -1);
            for (int[] f : faces) for (int v : f) newIndex[v] = 0;
            for (int[] s : segments) for (int v : s) newIndex[v] = 0;
            for (int k = 0; k < pointSets.size(); k++)
                for (int v : pointSets.get(k))
                    if (newIndex[v] < 0) throw fail(pointLines.get(k), "point " + point(v) + " is on no face or line, so it is no part of the cloth");
            int n = 0;
            for (int i = 0; i < newIndex.length; i++) if (newIndex[i] == 0) newIndex[i] = n++;
            double[] positions = new double[3 * n];
            for (int i = 0; i < newIndex.length; i++)
                if (newIndex[i] >= 0) System.arraycopy(welded.get(i), 0, positions, 3 * newIndex[i], 3);
            int[][] f = new int[faces.size()][];
            for (int k = 0; k < f.length; k++) f[k] = Arrays.stream(faces.get(k)).map(v -> newIndex[v]).toArray();
            int[] s = new int[2 * segments.size()];
            for (int k = 0; k < segments.size(); k++) { s[2 * k] = newIndex[segments.get(k)[0]]; s[2 * k + 1] = newIndex[segments.get(k)[1]]; }
            Map<String, int[]> g = new LinkedHashMap<>();
            groups.forEach((name, vs) -> g.put(name, vs.stream().mapToInt(v -> newIndex[v]).sorted().toArray()));
            ClothMesh mesh = firstFaceWithoutUV == 0 && !faces.isEmpty()
                    ? ClothMesh.withTextureCoordinates(positions, f, faceUVs.toArray(new double[0][]), s, g)
                    : ClothMesh.of(positions, f, null, s, g).withoutTextureCoordinates(faces.isEmpty() ? "it has no faces"
                            : "the face on line " + firstFaceWithoutUV + " has no texture coordinates (vt)");
            for (int k = 0; k < mesh.faceCount(); k++) {
                int[] corners = mesh.face(k);
                double longest = 0;
                for (int j = 0; j < corners.length; j++) longest = Math.max(longest, mesh.distance(corners[j], corners[(j + 1) % corners.length]));
                double area = mesh.faceArea(k);
                if (area <= DEGENERATE_AREA * longest * longest) throw fail(faceLines.get(k), "face is degenerate: its area is " + area + " m² (its corners are in a line)");
            }
            return mesh;
        }
    }
}
