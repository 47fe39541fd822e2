package xpbdcloth.usd;

import java.io.BufferedWriter;
import java.io.Closeable;
import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import xpbdcloth.engine.Box;
import xpbdcloth.engine.Capsule;
import xpbdcloth.engine.MeshCollider;
import xpbdcloth.engine.Plane;
import xpbdcloth.engine.RigidCollider;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.Sphere;
import xpbdcloth.fabric.Fabric;
import xpbdcloth.mesh.ClothMesh;
import xpbdcloth.mesh.VertexNormals;
import xpbdcloth.scene.Preset;
import xpbdcloth.scene.Scene;

/**
 * A running scene recorded as one USD stage in USD's text form (.usda), which Blender, Houdini, Maya,
 * Omniverse and Pixar's own library open (UsdGeom schemas: openusd.org, "UsdGeom: USD Geometry Schema"):
 * <ul>
 * <li>the cloth a {@code Mesh} (a rope, which has no faces, {@code BasisCurves} of one linear piece per
 *     segment) whose topology is written once and whose {@code points}, {@code normals} (per vertex) and
 *     {@code extent} are time-sampled per frame; texture coordinates as the face-varying
 *     {@code primvars:st} (the mesh's own, or the rest shape projected on its two widest axes); the fabric's
 *     name and moduli as custom {@code xpbd:} attributes;</li>
 * <li>each collider a prim with a time-sampled {@code xformOp:transform}: a sphere a {@code Sphere}, a
 *     capsule a {@code Capsule} along its local y, a box a {@code Cube} of size 2 scaled to its half
 *     extents, a plane (infinite) a square {@code Mesh} around the cloth, a triangle-mesh collider a
 *     {@code Mesh} of its vertices in the world (time-sampled when it moves);</li>
 * <li>metres ({@code metersPerUnit = 1}), y up, time code k the k-th frame after the start at the
 *     recording's rate ({@code timeCodesPerSecond = framesPerSecond = fps}); code 0 the state the
 *     recording started from.</li>
 * </ul>
 * Points are {@code point3f} as the schema has them: within 6e-8 of the simulation's doubles, relative.
 *
 * <p>Streams: each time-sampled attribute goes to its own spill file beside the output as the frames come,
 * and {@link #close} joins them in one pass, so memory does not grow with the number of frames.
 */
public final class UsdRecording implements Closeable {
    /**
     * The most frames a recording may have: ten minutes at 60 fps. A 64² cloth takes about 0.3 MB a frame,
     * so this is already some 11 GB; more is a mistake, not a recording.
     */
    public static final int MAX_FRAMES = 36_000;

    private final Path file, spillFolder;
    private final Scene scene;
    private final double fps;
    private final ClothMesh mesh;
    private final int[] triangles, segments;
    private final boolean curves;
    private final double startTime;
    private final List<Samples> streams = new ArrayList<>();
    private final Samples points, normals, extent;
    private final List<ColliderPrim> colliders = new ArrayList<>();
    private final double[] normal, rotation = new double[9], lo = new double[3], hi = new double[3];
    private final StringBuilder line = new StringBuilder(1 << 16);
    private int frames;
    private boolean closed;

    /**
     * Starts a recording of the scene at {@code fps} frames per simulated second into {@code file}, its
     * state now the first frame (time code 0). Frames are added by {@link #frame()}; nothing is readable
     * until {@link #close()}.
     */
    public static UsdRecording start(Path file, Scene scene, double fps) throws IOException {
        return new UsdRecording(file, scene, fps);
    }

    private UsdRecording(Path file, Scene scene, double fps) throws IOException {
        if (file == null) throw new IllegalArgumentException("file must not be null, was null");
        if (scene == null) throw new IllegalArgumentException("scene must not be null, was null");
        if (!(fps > 0 && fps <= 1000)) throw new IllegalArgumentException("fps must be in (0, 1000], was " + fps);
        if (!file.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".usda"))
            throw new IllegalArgumentException("usd file must end in .usda (USD's text form, which this writes), was " + file);
        this.file = file.toAbsolutePath();
        this.scene = scene;
        this.fps = fps;
        mesh = scene.cloth().mesh();
        triangles = mesh.triangles();
        segments = mesh.segments();
        curves = mesh.faceCount() == 0;
        startTime = scene.simulation().time();
        normal = new double[3 * mesh.vertexCount()];
        Files.createDirectories(this.file.getParent());
        spillFolder = Files.createTempDirectory(this.file.getParent(), ".usd-frames-");
        points = stream("point3f[] points");
        normals = curves ? null : stream("normal3f[] normals");
        extent = stream("float3[] extent");
        Simulation sim = scene.simulation();
        int k = 0;
        for (Sphere s : sim.spheres()) colliders.add(new SpherePrim("Sphere" + k++, s));
        int boxes = 0, capsules = 0, bodies = 0;
        for (RigidCollider s : sim.solids()) {
            if (s instanceof Box) colliders.add(new BoxPrim("Box" + boxes++, (Box) s));
            else if (s instanceof Capsule) colliders.add(new CapsulePrim("Capsule" + capsules++, (Capsule) s));
            else if (s instanceof MeshCollider) colliders.add(new BodyPrim("Body" + bodies++, (MeshCollider) s));
            else throw new IllegalStateException("no USD prim for a " + s.getClass().getSimpleName());
        }
        k = 0;
        for (Plane p : sim.planes()) colliders.add(new PlanePrim("Plane" + k++, p));
        frame();
    }

    /**
     * Runs a fresh scene of the preset and records its start and then {@code frames} frames of
     * {@code stepsPerFrame} steps each (time codes 0 … frames, at 1/(stepsPerFrame·dt) frames per simulated
     * second) into {@code file}. Headless. Returns the number of time codes written (frames + 1).
     */
    public static int record(Preset preset, int frames, Path file, int stepsPerFrame) throws IOException {
        if (frames < 1 || frames >= MAX_FRAMES)
            throw new IllegalArgumentException("frames must be in [1, " + (MAX_FRAMES - 1) + "] for a USD recording, was " + frames);
        return record(Scene.of(preset), frames, file, stepsPerFrame);
    }

    /**
     * The same from a scene already built (the caller keeps it, to ask how its last step went). A stage holds
     * one topology: a cloth that tears ends the recording at the frame before its first tear (fewer time codes
     * than asked; the file is written all the same).
     */
    public static int record(Scene scene, int frames, Path file, int stepsPerFrame) throws IOException {
        if (frames < 1 || frames >= MAX_FRAMES)
            throw new IllegalArgumentException("frames must be in [1, " + (MAX_FRAMES - 1) + "] for a USD recording, was " + frames);
        if (stepsPerFrame < 1) throw new IllegalArgumentException("steps per frame must be >= 1, was " + stepsPerFrame);
        try (UsdRecording r = start(file, scene, 1 / (stepsPerFrame * scene.simulation().settings().timestep()))) {
            for (int f = 1; f <= frames; f++) {
                for (int s = 0; s < stepsPerFrame; s++)
                    if (scene.step() != scene) return r.frames();  // torn: the cut cloth is another topology
                r.frame();
            }
            return r.frames();
        }
    }

    /** Adds the scene's state now as the next frame. */
    public void frame() throws IOException { frame(scene.simulation().particles().positions()); }

    /**
     * Adds the next frame with the cloth at positions {@code x} (3 per particle; an observation with noise,
     * say) and the colliders where they are now.
     */
    public void frame(double[] x) throws IOException {
        if (closed) throw new IllegalStateException("the recording of " + file + " is closed");
        if (frames >= MAX_FRAMES)
            throw new IllegalArgumentException("frames: a USD recording holds at most " + MAX_FRAMES + " frames (ten minutes at 60 fps), " + file + " has them");
        if (x.length != 3 * mesh.vertexCount())
            throw new IllegalArgumentException("positions must be 3 per particle (" + 3 * mesh.vertexCount() + " numbers), was " + x.length);
        if (curves) {
            open(points);
            for (int s = 0; s < segments.length; s++) point(x, segments[s], s == 0);
            close(points);
        } else {
            open(points);
            for (int i = 0, n = mesh.vertexCount(); i < n; i++) point(x, i, i == 0);
            close(points);
            VertexNormals.compute(x, triangles, normal);
            open(normals);
            for (int i = 0, n = mesh.vertexCount(); i < n; i++) point(normal, i, i == 0);
            close(normals);
        }
        open(extent);
        java.util.Arrays.fill(lo, Double.MAX_VALUE);
        java.util.Arrays.fill(hi, -Double.MAX_VALUE);
        for (int i = 0; i < x.length; i++) { lo[i % 3] = Math.min(lo[i % 3], x[i]); hi[i % 3] = Math.max(hi[i % 3], x[i]); }
        tuple(lo, 0, 3, true).append(", ");
        tuple(hi, 0, 3, true);
        close(extent);
        for (ColliderPrim c : colliders) c.frame();
        frames++;
    }

    /** Frames recorded so far (the start included). */
    public int frames() { return frames; }

    public Path file() { return file; }

    /** Writes the stage (header, cloth, colliders, every frame) and removes the spill files. */
    @Override public void close() throws IOException {
        if (closed) return;
        closed = true;
        try {
            for (Samples s : streams) s.out.close();
            try (Writer w = Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
                writeStage(w);
            }
        } finally {
            for (Samples s : streams) Files.deleteIfExists(s.spill);
            Files.deleteIfExists(spillFolder);
        }
    }

    private void writeStage(Writer w) throws IOException {
        Simulation sim = scene.simulation();
        String name = scene.preset().name;
        w.write("#usda 1.0\n(\n    defaultPrim = \"World\"\n");
        w.write("    doc = " + UsdaText.quoted(String.format(Locale.ROOT,
                "xpbd-cloth: scene %s, %d frames at %s frames per simulated second from t = %s s (dt = %s s, %d substeps x %d iterations)",
                name, frames, number(fps), number(startTime), number(sim.settings().timestep()), sim.settings().substeps(), sim.settings().iterations())) + "\n");
        w.write("    endTimeCode = " + (frames - 1) + "\n    framesPerSecond = " + number(fps) + "\n    metersPerUnit = 1\n    startTimeCode = 0\n");
        w.write("    timeCodesPerSecond = " + number(fps) + "\n    upAxis = \"Y\"\n)\n\n");
        w.write("def Xform \"World\"\n{\n");
        w.write("    custom string xpbd:scene = " + UsdaText.quoted(name) + "\n");
        w.write("    custom double xpbd:startTime = " + number(startTime) + " (\n        doc = \"the simulated time of time code 0, s\"\n    )\n\n");
        writeCloth(w);
        for (ColliderPrim c : colliders) c.write(w);
        w.write("}\n");
    }

    private void writeCloth(Writer w) throws IOException {
        StringBuilder b = new StringBuilder();
        if (curves) {
            w.write("    def BasisCurves \"Cloth\"\n    {\n");
            b.append("        int[] curveVertexCounts = [");
            for (int s = 0; s < segments.length / 2; s++) b.append(s == 0 ? "" : ", ").append(2);
            b.append("]\n        uniform token type = \"linear\"\n        float[] widths = [0.005] (\n            interpolation = \"constant\"\n        )\n");
            w.write(b.toString());
        } else {
            w.write("    def Mesh \"Cloth\"\n    {\n");
            b.append("        uniform bool doubleSided = 1\n        int[] faceVertexCounts = [");
            for (int k = 0; k < mesh.faceCount(); k++) b.append(k == 0 ? "" : ", ").append(mesh.face(k).length);
            b.append("]\n        int[] faceVertexIndices = [");
            boolean first = true;
            for (int k = 0; k < mesh.faceCount(); k++)
                for (int v : mesh.face(k)) { b.append(first ? "" : ", ").append(v); first = false; }
            b.append("]\n        uniform token orientation = \"rightHanded\"\n        uniform token subdivisionScheme = \"none\"\n");
            b.append("        texCoord2f[] primvars:st = [");
            double[] st = faceCornerUVs();
            for (int i = 0; i < st.length; i += 2) tuple(b, st, i, 2, i == 0);
            b.append("] (\n            interpolation = \"faceVarying\"\n        )\n");
            b.append("        normal3f[] normals (\n            interpolation = \"vertex\"\n        )\n");
            w.write(b.toString());
            normals.copyInto(w);
        }
        points.copyInto(w);
        extent.copyInto(w);
        w.write(fabricAttributes());
        w.write("    }\n\n");
    }

    /** The fabric's name, moduli (N/m), bending stiffness (N·m) and areal density (kg/m²), or "springs". */
    private String fabricAttributes() {
        Fabric f = scene.fabric();
        StringBuilder b = new StringBuilder();
        if (f == null) return b.append("        custom string xpbd:material = \"springs\"\n").toString();
        b.append("        custom string xpbd:material = \"fabric\"\n");
        b.append("        custom string xpbd:fabric:name = ").append(UsdaText.quoted(f.name)).append('\n');
        custom(b, "warpModulus", f.membrane.warpModulus, "E1 t along warp, N/m");
        custom(b, "weftModulus", f.membrane.weftModulus, "E2 t along weft, N/m");
        custom(b, "poisson", f.membrane.poisson, "nu12");
        custom(b, "shearModulus", f.membrane.shearModulus, "G12 t, N/m");
        custom(b, "bendingStiffness", f.bendingStiffness, "B, N m");
        if (!Double.isNaN(f.arealDensity)) custom(b, "arealDensity", f.arealDensity, "kg/m^2");
        return b.toString();
    }

    private static void custom(StringBuilder b, String name, double v, String doc) {
        b.append("        custom double xpbd:fabric:").append(name).append(" = ");
        UsdaText.appendDouble(b, v).append(" (\n            doc = ").append(UsdaText.quoted(doc)).append("\n        )\n");
    }

    /**
     * (u, v) per face corner in faceVertexIndices order: the mesh's own coordinates (its faces split as fans,
     * so corner 0 is the first triangle's first, corner j its (j−1)-th triangle's second, the last corner the
     * last triangle's third), else the rest positions projected on the two axes the rest shape is widest along.
     */
    private double[] faceCornerUVs() {
        double[] tri = mesh.triangleUVs();
        int corners = 0;
        for (int k = 0; k < mesh.faceCount(); k++) corners += mesh.face(k).length;
        double[] st = new double[2 * corners];
        int c = 0, t = 0;
        double[] rest = mesh.positions(), size = {mesh.max(0) - mesh.min(0), mesh.max(1) - mesh.min(1), mesh.max(2) - mesh.min(2)};
        int narrow = size[0] <= size[1] && size[0] <= size[2] ? 0 : size[1] <= size[2] ? 1 : 2;
        int a = narrow == 0 ? 1 : 0, bAxis = narrow == 2 ? 1 : 2;
        for (int k = 0; k < mesh.faceCount(); k++) {
            int[] f = mesh.face(k);
            for (int j = 0; j < f.length; j++, c += 2) {
                if (tri != null) {
                    int triangle = t + Math.max(0, Math.min(f.length - 3, j - 1)), corner = j == 0 ? 0 : j == f.length - 1 ? 2 : 1;
                    st[c] = tri[6 * triangle + 2 * corner];
                    st[c + 1] = tri[6 * triangle + 2 * corner + 1];
                } else {
                    st[c] = unit(rest[3 * f[j] + a], a);
                    st[c + 1] = unit(rest[3 * f[j] + bAxis], bAxis);
                }
            }
            t += f.length - 2;
        }
        return st;
    }

    private double unit(double v, int axis) {
        double size = mesh.max(axis) - mesh.min(axis);
        return size == 0 ? 0 : (v - mesh.min(axis)) / size;
    }

    private void open(Samples s) {
        line.setLength(0);
        line.append("            ").append(frames).append(": [");
    }

    private void close(Samples s) throws IOException {
        line.append("],\n");
        s.out.append(line);
    }

    private void point(double[] x, int i, boolean first) {
        tuple(line, x, 3 * i, 3, first);
    }

    private StringBuilder tuple(double[] x, int from, int n, boolean first) { return tuple(line, x, from, n, first); }

    private static StringBuilder tuple(StringBuilder b, double[] x, int from, int n, boolean first) {
        if (!first) b.append(", ");
        b.append('(');
        for (int j = 0; j < n; j++) UsdaText.appendFloat(j == 0 ? b : b.append(", "), x[from + j]);
        return b.append(')');
    }

    private static String number(double v) { return UsdaText.appendDouble(new StringBuilder(), v).toString(); }

    private Samples stream(String declaration) throws IOException {
        Samples s = new Samples(declaration, Files.createTempFile(spillFolder, "attribute-", ".usda"));
        streams.add(s);
        return s;
    }

    /** One time-sampled attribute: its declaration and the spill file its samples go to. */
    private static final class Samples {
        final String declaration;
        final Path spill;
        final BufferedWriter out;

        Samples(String declaration, Path spill) throws IOException {
            this.declaration = declaration;
            this.spill = spill;
            out = Files.newBufferedWriter(spill, StandardCharsets.UTF_8);
        }

        void copyInto(Writer w) throws IOException {
            w.write("        " + declaration + ".timeSamples = {\n");
            try (java.io.Reader r = Files.newBufferedReader(spill, StandardCharsets.UTF_8)) {
                r.transferTo(w);
            }
            w.write("        }\n");
        }
    }

    /** A collider's prim: its kind's attributes once, and (when it can move) its pose per frame. */
    private abstract class ColliderPrim {
        final String name, type;
        final Samples transform;
        final double margin;

        ColliderPrim(String name, String type, double margin, boolean moves) throws IOException {
            this.name = name;
            this.type = type;
            this.margin = margin;
            transform = moves ? stream("matrix4d xformOp:transform") : null;
        }

        /** The rotation (row-major, column vectors) and centre now, into rotation and the returned centre. */
        abstract double[] pose();

        /** This frame's samples: the pose, when it can move. */
        void frame() throws IOException { if (transform != null) sample(); }

        abstract void attributes(StringBuilder b);

        /**
         * USD's matrices act on row vectors (p' = p M): M's first three rows are R's columns, its last row the
         * centre.
         */
        void sample() throws IOException {
            double[] c = pose();
            line.setLength(0);
            line.append("            ").append(frames).append(": ( ");
            for (int row = 0; row < 4; row++) {
                line.append(row == 0 ? "(" : ", (");
                for (int col = 0; col < 4; col++) {
                    double v = row < 3 ? (col < 3 ? rotation[3 * col + row] : 0) : (col < 3 ? c[col] : 1);
                    UsdaText.appendDouble(col == 0 ? line : line.append(", "), v);
                }
                line.append(')');
            }
            line.append(" ),\n");
            transform.out.append(line);
        }

        void write(Writer w) throws IOException {
            StringBuilder b = new StringBuilder();
            b.append("    def ").append(type).append(' ').append(UsdaText.quoted(name)).append("\n    {\n");
            attributes(b);
            b.append("        custom double xpbd:margin = ");
            UsdaText.appendDouble(b, margin).append(" (\n            doc = \"the cloth's half thickness kept from this surface, m\"\n        )\n");
            w.write(b.toString());
            if (transform != null) {
                transform.copyInto(w);
                w.write("        uniform token[] xformOpOrder = [\"xformOp:transform\"" + (this instanceof BoxPrim ? ", \"xformOp:scale\"" : "") + "]\n");
            }
            w.write("    }\n\n");
        }
    }

    private final class SpherePrim extends ColliderPrim {
        final Sphere s;
        final double[] c = new double[3];

        SpherePrim(String name, Sphere s) throws IOException { super(name, "Sphere", s.margin(), true); this.s = s; }

        @Override double[] pose() {
            s.rotation(rotation);
            c[0] = s.centreX(); c[1] = s.centreY(); c[2] = s.centreZ();
            return c;
        }

        @Override void attributes(StringBuilder b) {
            UsdaText.appendDouble(b.append("        double radius = "), s.radius()).append('\n');
            extentOf(b, s.radius(), s.radius(), s.radius());
        }
    }

    private class SolidPrim extends ColliderPrim {
        final RigidCollider s;
        final double[] c = new double[3];

        SolidPrim(String name, String type, RigidCollider s) throws IOException { super(name, type, s.margin(), true); this.s = s; }

        @Override double[] pose() {
            s.rotation(rotation);
            c[0] = s.centreX(); c[1] = s.centreY(); c[2] = s.centreZ();
            return c;
        }

        @Override void attributes(StringBuilder b) { }
    }

    private final class CapsulePrim extends SolidPrim {
        CapsulePrim(String name, Capsule s) throws IOException { super(name, "Capsule", s); }

        @Override void attributes(StringBuilder b) {
            Capsule cap = (Capsule) s;
            b.append("        uniform token axis = \"Y\"\n");
            UsdaText.appendDouble(b.append("        double height = "), 2 * cap.halfLength()).append('\n');
            UsdaText.appendDouble(b.append("        double radius = "), cap.radius()).append('\n');
            extentOf(b, cap.radius(), cap.halfLength() + cap.radius(), cap.radius());
        }
    }

    private final class BoxPrim extends SolidPrim {
        BoxPrim(String name, Box s) throws IOException { super(name, "Cube", s); }

        @Override void attributes(StringBuilder b) {
            Box box = (Box) s;
            b.append("        double size = 2\n");
            extentOf(b, 1, 1, 1);
            b.append("        float3 xformOp:scale = (");
            UsdaText.appendFloat(b, box.halfExtentX()).append(", ");
            UsdaText.appendFloat(b, box.halfExtentY()).append(", ");
            UsdaText.appendFloat(b, box.halfExtentZ()).append(")\n");
        }
    }

    /**
     * A triangle-mesh collider as a Mesh whose points are its vertices in the world (its rigid motion and its
     * frames both baked in): time-sampled when they ever change, else written once.
     */
    private final class BodyPrim extends ColliderPrim {
        final MeshCollider body;
        final Samples points;
        final double[] first;
        boolean changed;

        BodyPrim(String name, MeshCollider body) throws IOException {
            super(name, "Mesh", body.margin(), false);
            this.body = body;
            points = stream("point3f[] points");
            first = body.vertices().clone();
        }

        @Override double[] pose() { return null; }

        @Override void frame() throws IOException {
            double[] v = body.vertices();
            changed |= !java.util.Arrays.equals(v, first);
            line.setLength(0);
            line.append("            ").append(frames).append(": [");
            for (int i = 0; i < v.length / 3; i++) tuple(line, v, 3 * i, 3, i == 0);
            line.append("],\n");
            points.out.append(line);
        }

        @Override void attributes(StringBuilder b) {
            int[] t = body.triangles();
            b.append("        uniform bool doubleSided = 1\n        int[] faceVertexCounts = [");
            for (int k = 0; k < t.length / 3; k++) b.append(k == 0 ? "" : ", ").append(3);
            b.append("]\n        int[] faceVertexIndices = [");
            for (int k = 0; k < t.length; k++) b.append(k == 0 ? "" : ", ").append(t[k]);
            b.append("]\n        uniform token subdivisionScheme = \"none\"\n");
            b.append("        custom string xpbd:collider = \"mesh\"\n");
        }

        @Override void write(Writer w) throws IOException {
            StringBuilder b = new StringBuilder();
            b.append("    def Mesh ").append(UsdaText.quoted(name)).append("\n    {\n");
            attributes(b);
            b.append("        custom double xpbd:margin = ");
            UsdaText.appendDouble(b, margin).append("\n");
            if (!changed) {
                b.append("        point3f[] points = [");
                for (int i = 0; i < first.length / 3; i++) tuple(b, first, 3 * i, 3, i == 0);
                b.append("]\n");
                w.write(b.toString());
            } else {
                w.write(b.toString());
                points.copyInto(w);
            }
            w.write("    }\n\n");
        }
    }

    private static void extentOf(StringBuilder b, double x, double y, double z) {
        b.append("        float3[] extent = [(");
        UsdaText.appendFloat(b, -x).append(", ");
        UsdaText.appendFloat(b, -y).append(", ");
        UsdaText.appendFloat(b, -z).append("), (");
        UsdaText.appendFloat(b, x).append(", ");
        UsdaText.appendFloat(b, y).append(", ");
        UsdaText.appendFloat(b, z).append(")]\n");
    }

    /**
     * A plane is infinite; what a viewer can show of it is a square of it centred under the cloth's rest
     * shape, four times as wide as the rest shape (at least 4 m), with the plane's normal as its face's.
     */
    private final class PlanePrim extends ColliderPrim {
        final Plane p;

        PlanePrim(String name, Plane p) throws IOException { super(name, "Mesh", p.margin(), false); this.p = p; }

        @Override double[] pose() { return null; }

        @Override void attributes(StringBuilder b) {
            double[] n = {p.normalX(), p.normalY(), p.normalZ()};
            double[] mid = {(mesh.min(0) + mesh.max(0)) / 2, (mesh.min(1) + mesh.max(1)) / 2, (mesh.min(2) + mesh.max(2)) / 2};
            double d = p.distance(mid[0], mid[1], mid[2]);
            double[] o = {mid[0] - d * n[0], mid[1] - d * n[1], mid[2] - d * n[2]};
            double wide = Math.hypot(Math.hypot(mesh.max(0) - mesh.min(0), mesh.max(1) - mesh.min(1)), mesh.max(2) - mesh.min(2));
            double half = Math.max(2, 2 * wide);
            // Two unit tangents u, v with u × v = n, so the square's corners run counter-clockwise seen from the normal's side.
            double[] u = Math.abs(n[0]) < 0.9 ? cross(new double[] {1, 0, 0}, n) : cross(new double[] {0, 1, 0}, n);
            double lu = Math.sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
            for (int i = 0; i < 3; i++) u[i] /= lu;
            double[] v = cross(n, u);
            double[] corners = new double[12];
            double[][] signs = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
            for (int k = 0; k < 4; k++)
                for (int i = 0; i < 3; i++) corners[3 * k + i] = o[i] + half * (signs[k][0] * u[i] + signs[k][1] * v[i]);
            b.append("        uniform bool doubleSided = 1\n        int[] faceVertexCounts = [4]\n        int[] faceVertexIndices = [0, 1, 2, 3]\n");
            b.append("        point3f[] points = [");
            for (int k = 0; k < 4; k++) tuple(b, corners, 3 * k, 3, k == 0);
            b.append("]\n        uniform token subdivisionScheme = \"none\"\n");
            b.append("        custom string xpbd:collider = \"plane\" (\n            doc = \"an infinite plane, drawn as a square of it under the cloth\"\n        )\n");
        }
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }
}
