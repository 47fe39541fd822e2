package xpbdcloth.mesh;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * One {@code Mesh} prim of a USD text file and its time-sampled points: an animated body, or an observed
 * motion, brought in from Blender, Houdini or a recording of this project. Its topology
 * ({@code faceVertexCounts}, {@code faceVertexIndices}) is read once; its points per time code, in
 * metres after the stage's {@code metersPerUnit}. Refused by name: a prim that is not a Mesh, a mesh
 * under a transform (this does not apply {@code xformOp}s; bake them into the points), points of
 * changing count, indices out of range, non-finite coordinates.
 */
public final class UsdMeshAnimation {
    /** The most vertices a mesh read here may have (as an OBJ cloth). */
    public static final int MAX_VERTICES = ObjReader.MAX_VERTICES;

    public final String file, prim;
    public final int[] faceVertexCounts, faceVertexIndices;
    /** The time codes that have points, ascending, and the points at each (3 per vertex, metres). */
    public final double[] timeCodes;
    public final double[][] points;
    /** Time codes per second of the stage (USD's default, 24, when the file does not say). */
    public final double timeCodesPerSecond;

    private UsdMeshAnimation(String file, String prim, int[] counts, int[] indices, double[] codes, double[][] points, double timeCodesPerSecond) {
        this.file = file;
        this.prim = prim;
        this.faceVertexCounts = counts;
        this.faceVertexIndices = indices;
        this.timeCodes = codes;
        this.points = points;
        this.timeCodesPerSecond = timeCodesPerSecond;
    }

    public int vertexCount() { return points[0].length / 3; }

    /**
     * The mesh at {@code primPath} of the file, or, when that is null, its one Mesh whose points are
     * time-sampled (a recording's cloth; its planes are Meshes too, but still).
     */
    public static UsdMeshAnimation read(Path path, String primPath) {
        return of(UsdaReader.read(path), primPath);
    }

    /** The same from a stage already read. */
    public static UsdMeshAnimation of(UsdaReader.Stage stage, String primPath) {
        String file = stage.file;
        UsdaReader.Prim mesh = primPath != null ? find(stage, primPath) : theAnimatedMesh(stage);
        if (!"Mesh".equals(mesh.type))
            throw new MeshFileException(file, mesh.line, "prim " + mesh.path + " is a " + (mesh.type.isEmpty() ? "typeless prim" : mesh.type) + ", not a Mesh: only a Mesh's points are read");
        for (UsdaReader.Prim p : stage.prims)
            if ((mesh.path + "/").startsWith(p.path + "/") && p.attributes.containsKey("xformOpOrder"))
                throw new MeshFileException(file, p.line, "prim " + p.path + " has a transform (xformOpOrder), which this reader does not apply to " + mesh.path
                        + "'s points; bake it into the points (in Blender: Object → Apply → All Transforms) and export again");
        int[] counts = ints(file, mesh, "faceVertexCounts"), indices = ints(file, mesh, "faceVertexIndices");
        long corners = 0;
        for (int c : counts) {
            if (c < 3) throw new MeshFileException(file, mesh.line, "faceVertexCounts of " + mesh.path + " must be 3 or more per face, was " + c);
            corners += c;
        }
        if (corners != indices.length)
            throw new MeshFileException(file, mesh.line, "faceVertexCounts of " + mesh.path + " add up to " + corners + " corners but faceVertexIndices has " + indices.length);
        UsdaReader.Attribute points = mesh.attributes.get("points");
        if (points == null) throw new MeshFileException(file, mesh.line, "prim " + mesh.path + " has no points");
        double scale = stage.number("metersPerUnit", 0.01); // USD's default unit is the centimetre
        List<Double> codes = new ArrayList<>();
        List<double[]> frames = new ArrayList<>();
        if (points.samples.isEmpty()) { codes.add(0.0); frames.add(coordinates(file, mesh, 0, points.value)); }
        for (Map.Entry<Double, Object> e : points.samples.entrySet()) { codes.add(e.getKey()); frames.add(coordinates(file, mesh, e.getKey(), e.getValue())); }
        int n = frames.get(0).length / 3;
        if (n > MAX_VERTICES) throw new MeshFileException(file, mesh.line, mesh.path + " has " + n + " points, more than the " + MAX_VERTICES + " read here");
        for (int f = 0; f < frames.size(); f++) {
            double[] x = frames.get(f);
            if (x.length != 3 * n)
                throw new MeshFileException(file, mesh.line, "points of " + mesh.path + " at time code " + codes.get(f) + " are " + x.length / 3 + ", at " + codes.get(0) + " they were " + n + ": the count must not change");
            for (int i = 0; i < x.length; i++) {
                x[i] *= scale;
                if (!(Math.abs(x[i]) <= ObjReader.MAX_COORDINATE))
                    throw new MeshFileException(file, mesh.line, "point " + i / 3 + " of " + mesh.path + " at time code " + codes.get(f) + " must be finite and within ±1e12 m, was " + x[i]);
            }
        }
        for (int v : indices)
            if (v < 0 || v >= n) throw new MeshFileException(file, mesh.line, "faceVertexIndices of " + mesh.path + " must be in [0, " + (n - 1) + "], has " + v);
        double[] c = new double[codes.size()];
        for (int i = 0; i < c.length; i++) c[i] = codes.get(i);
        return new UsdMeshAnimation(file, mesh.path, counts, indices, c, frames.toArray(new double[0][]), stage.number("timeCodesPerSecond", 24));
    }

    private static UsdaReader.Prim find(UsdaReader.Stage stage, String path) {
        for (UsdaReader.Prim p : stage.prims) if (p.path.equals(path)) return p;
        List<String> meshes = new ArrayList<>();
        for (UsdaReader.Prim p : stage.prims) if ("Mesh".equals(p.type)) meshes.add(p.path);
        throw new MeshFileException(stage.file, 0, "has no prim " + path + "; its meshes: " + (meshes.isEmpty() ? "none" : String.join(", ", meshes)));
    }

    private static UsdaReader.Prim theAnimatedMesh(UsdaReader.Stage stage) {
        List<UsdaReader.Prim> meshes = new ArrayList<>(), animated = new ArrayList<>();
        for (UsdaReader.Prim p : stage.prims)
            if ("Mesh".equals(p.type)) {
                meshes.add(p);
                UsdaReader.Attribute a = p.attributes.get("points");
                if (a != null && !a.samples.isEmpty()) animated.add(p);
            }
        if (animated.size() == 1) return animated.get(0);
        if (animated.isEmpty() && meshes.size() == 1) return meshes.get(0);
        List<String> names = new ArrayList<>();
        for (UsdaReader.Prim p : animated.isEmpty() ? meshes : animated) names.add(p.path);
        throw new MeshFileException(stage.file, 0, names.isEmpty() ? "has no Mesh prim" : "has " + names.size() + " " + (animated.isEmpty() ? "meshes" : "animated meshes")
                + " (" + String.join(", ", names) + "); name the one to read");
    }

    private static int[] ints(String file, UsdaReader.Prim mesh, String name) {
        UsdaReader.Attribute a = mesh.attributes.get(name);
        if (a == null || !(a.value instanceof double[]))
            throw new MeshFileException(file, mesh.line, "prim " + mesh.path + " must have " + name + " as an array of integers (not time-sampled), " + (a == null ? "it has none" : "it is " + a.type));
        double[] v = (double[]) a.value;
        int[] out = new int[v.length];
        for (int i = 0; i < v.length; i++) {
            if (v[i] != Math.rint(v[i]) || Math.abs(v[i]) > Integer.MAX_VALUE) throw new MeshFileException(file, mesh.line, name + " of " + mesh.path + " must be integers, has " + v[i]);
            out[i] = (int) v[i];
        }
        return out;
    }

    private static double[] coordinates(String file, UsdaReader.Prim mesh, double code, Object value) {
        if (!(value instanceof double[]) || ((double[]) value).length % 3 != 0)
            throw new MeshFileException(file, mesh.line, "points of " + mesh.path + " at time code " + code + " must be an array of (x, y, z)");
        return (double[]) value;
    }
}
