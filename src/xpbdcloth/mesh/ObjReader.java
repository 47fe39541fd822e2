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

    private ObjReader() {}

    public static ClothMesh read(Path path, double weldTolerance) {
        String file = path.toString();
        if (!Files.isRegularFile(path)) throw new MeshFileException(file, 0, Files.exists(path) ? "is not a regular file" : "does not exist");
        try {
            return parse(file, Files.readString(path, StandardCharsets.UTF_8), weldTolerance);
        } catch (IOException e) {
            throw new MeshFileException(file, 0, "cannot be read: " + e.getMessage());
        }
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
                    default: throw fail(ln, "unsupported statement \"" + tok[0] + "\" (a cloth reads v, vt, f, l, p, g, o; vn, vp, s, usemtl, mtllib are read past)");
                }
            }
            if (faces.isEmpty() && segments.isEmpty()) throw fail(0, "has no faces (f) or lines (l): nothing to build a cloth from");
            return build();
        }

        void vertex(int ln, String[] tok) {
            if (tok.length < 4) throw fail(ln, "a vertex needs x y z, was " + (tok.length - 1) + " numbers");
            double[] p = coordinates(ln, tok, "vertex coordinate ", "xyz");
            vertices.add(p);
            weldedOf.add(weld(p));
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
                    throw fail(ln, what + axes.charAt(d) + " is not a number: \"" + tok[d + 1] + "\"");
                }
                if (!Double.isFinite(out[d])) throw fail(ln, what + axes.charAt(d) + " must be finite, was " + tok[d + 1]);
            }
            return out;
        }

        /** The texture coordinate a corner token names ("7/2", "7/2/3"), or null if it names none. */
        double[] cornerUV(int ln, String token) {
            String[] parts = token.split("/", -1);
            if (parts.length < 2 || parts[1].isEmpty()) return null;
            int i;
            try {
                i = Integer.parseInt(parts[1]);
            } catch (NumberFormatException e) {
                throw fail(ln, "corner \"" + token + "\": its texture index is not a number");
            }
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

        /** The welded vertex a corner token names ("7", "7/2", "7//3", "7/2/3", "-1"). */
        int corner(int ln, String token) {
            String v = token.split("/", -1)[0];
            int i;
            try {
                i = Integer.parseInt(v);
            } catch (NumberFormatException e) {
                throw fail(ln, "corner \"" + token + "\" does not start with a vertex index");
            }
            int n = vertices.size();
            int at = i > 0 ? i - 1 : n + i;
            if (i == 0 || at < 0 || at >= n)
                throw fail(ln, "vertex index " + i + " is out of range: " + n + " vertices are defined above this line (1.." + n + ", or -1..-" + n + ")");
            return weldedOf.get(at);
        }

        void face(int ln, String[] tok) {
            if (tok.length < 4) throw fail(ln, "a face needs at least 3 corners, was " + (tok.length - 1));
            int[] f = new int[tok.length - 1];
            for (int j = 0; j < f.length; j++) {
                f[j] = corner(ln, tok[j + 1]);
                for (int i = 0; i < j; i++)
                    if (f[i] == f[j])
                        throw fail(ln, "face is degenerate: corners " + (i + 1) + " (" + tok[i + 1] + ") and " + (j + 1) + " (" + tok[j + 1] + ") are the same vertex"
                                + (tolerance > 0 ? " after welding within " + tolerance + " m" : ""));
            }
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
