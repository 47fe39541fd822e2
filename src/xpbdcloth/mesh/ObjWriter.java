package xpbdcloth.mesh;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Writes a cloth's current shape as Wavefront OBJ: one {@code v} and one {@code vn} per vertex (in the
 * mesh's vertex order, the same every frame, so a sequence of files imports as an animation), then the
 * mesh's polygons as {@code f v//vn} (or, for a mesh of triangles with texture coordinates, one {@code vt}
 * per corner and {@code f v/vt/vn}, so a pattern's grain survives the file), its polylines as {@code l}, and each named vertex group as
 * {@code g name} with one {@code p} statement listing its vertices. Coordinates are written in Java's
 * shortest round-trip form, so {@link ObjReader} reads back the same doubles.
 */
public final class ObjWriter {
    private ObjWriter() {}

    /**
     * The mesh's faces with the given positions (3 per vertex; the rest mesh's own when null) and
     * normals computed from the triangulation.
     */
    public static void write(Writer out, ClothMesh mesh, double[] positions, String comment) throws IOException {
        double[] x = positions == null ? mesh.positions() : positions;
        if (x.length != 3 * mesh.vertexCount())
            throw new IllegalArgumentException("positions must have " + 3 * mesh.vertexCount() + " entries, was " + x.length);
        double[] n = new double[x.length];
        VertexNormals.compute(x, mesh.triangles(), n);
        StringBuilder s = new StringBuilder();
        if (comment != null && !comment.isEmpty()) for (String line : comment.split("\n")) s.append("# ").append(line).append('\n');
        for (int i = 0; i < x.length; i += 3) s.append("v ").append(x[i]).append(' ').append(x[i + 1]).append(' ').append(x[i + 2]).append('\n');
        boolean faces = mesh.faceCount() > 0;
        if (faces) for (int i = 0; i < n.length; i += 3) s.append("vn ").append(n[i]).append(' ').append(n[i + 1]).append(' ').append(n[i + 2]).append('\n');
        double[] uv = mesh.triangleUVs();
        boolean corners = uv != null && mesh.triangles().length == 3 * mesh.faceCount();
        if (corners) for (int i = 0; i < uv.length; i += 2) s.append("vt ").append(uv[i]).append(' ').append(uv[i + 1]).append('\n');
        for (int k = 0; k < mesh.faceCount(); k++) {
            s.append('f');
            int[] face = mesh.face(k);
            for (int c = 0; c < face.length; c++) {
                int v = face[c] + 1;
                s.append(' ').append(v).append('/');
                if (corners) s.append(3 * k + c + 1);
                s.append('/').append(v);
            }
            s.append('\n');
        }
        int[] seg = mesh.segments();
        for (int i = 0; i < seg.length; i += 2) s.append("l ").append(seg[i] + 1).append(' ').append(seg[i + 1] + 1).append('\n');
        for (java.util.Map.Entry<String, int[]> g : mesh.groups().entrySet()) {
            s.append("g ").append(g.getKey()).append("\np");
            for (int v : g.getValue()) s.append(' ').append(v + 1);
            s.append('\n');
        }
        out.write(s.toString());
    }

    public static void write(Path file, ClothMesh mesh, double[] positions, String comment) throws IOException {
        try (Writer w = Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
            write(w, mesh, positions, comment);
        }
    }
}
