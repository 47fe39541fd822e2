package xpbdcloth.mesh;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;

/**
 * A body for the cloth to collide with, as files give it: triangles, and its vertices at rest and (when it
 * moves) per frame at a rate. From an OBJ (still), a folder of OBJs with one topology (frame-0001.obj, …
 * in name order, at a rate the preset gives), or a USD text file whose Mesh has time-sampled points (at
 * the stage's timeCodesPerSecond). Polygons are split as fans.
 */
public final class BodyMesh {
    /** The most frames a body may have: a minute at 60 fps. */
    public static final int MAX_FRAMES = 3600;
    /** The most vertices a body may have. */
    public static final int MAX_VERTICES = 200_000;

    public final String file;
    /** Vertex positions at rest (the first frame when animated), 3 per vertex. */
    public final double[] vertices;
    public final int[] triangles;
    /** Vertices per frame (null when still). */
    public final double[][] frames;
    /** Frames per second (0 when still). */
    public final double fps;

    BodyMesh(String file, double[] vertices, int[] triangles, double[][] frames, double fps) {
        if (triangles.length == 0) throw new MeshFileException(file, 0, "has no triangles: a body to collide with needs faces");
        if (vertices.length / 3 > MAX_VERTICES) throw new MeshFileException(file, 0, "has " + vertices.length / 3 + " vertices, more than the " + MAX_VERTICES + " a body may have");
        if (frames != null && frames.length > MAX_FRAMES) throw new MeshFileException(file, 0, "has " + frames.length + " frames, more than the " + MAX_FRAMES + " a body may have");
        this.file = file;
        this.vertices = vertices;
        this.triangles = triangles;
        this.frames = frames;
        this.fps = fps;
    }

    public int vertexCount() { return vertices.length / 3; }
    public int triangleCount() { return triangles.length / 3; }
    public boolean animated() { return frames != null; }

    /** A still body from a mesh read from OBJ. */
    public static BodyMesh of(String file, ClothMesh mesh) {
        return new BodyMesh(file, mesh.positions(), mesh.triangles(), null, 0);
    }

    /** A body from a USD mesh: animated when it has more than one time sample, at the stage's rate. */
    public static BodyMesh of(UsdMeshAnimation usd) {
        List<Integer> t = new ArrayList<>();
        int corner = 0;
        for (int count : usd.faceVertexCounts) {
            for (int j = 1; j + 1 < count; j++) { t.add(usd.faceVertexIndices[corner]); t.add(usd.faceVertexIndices[corner + j]); t.add(usd.faceVertexIndices[corner + j + 1]); }
            corner += count;
        }
        int[] triangles = t.stream().mapToInt(Integer::intValue).toArray();
        boolean moves = usd.points.length > 1;
        if (moves && usd.timeCodes[0] != 0)
            throw new MeshFileException(usd.file, 0, usd.prim + "'s first time sample is at time code " + usd.timeCodes[0] + ": an animated body starts at time code 0");
        for (int f = 1; moves && f < usd.timeCodes.length; f++)
            if (usd.timeCodes[f] != f)
                throw new MeshFileException(usd.file, 0, usd.prim + " must have a time sample at every time code 0, 1, 2, …; the " + (f + 1) + "th is at " + usd.timeCodes[f]);
        return new BodyMesh(usd.file + " " + usd.prim, usd.points[0], triangles, moves ? usd.points : null, moves ? usd.timeCodesPerSecond : 0);
    }

    /** An animated body from a folder of OBJ files, one frame each in name order, at fps; each must have the first one's topology. */
    public static BodyMesh ofFrames(Path folder, double fps, double weld) {
        List<Path> files;
        try (Stream<Path> s = Files.list(folder)) {
            files = s.filter(p -> p.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".obj")).sorted().toList();
        } catch (IOException e) {
            throw new MeshFileException(folder.toString(), 0, "cannot be listed: " + e.getMessage());
        }
        if (files.isEmpty()) throw new MeshFileException(folder.toString(), 0, "holds no .obj frames");
        if (files.size() > MAX_FRAMES) throw new MeshFileException(folder.toString(), 0, "holds " + files.size() + " frames, more than the " + MAX_FRAMES + " a body may have");
        ClothMesh first = ObjReader.read(files.get(0), weld);
        double[][] frames = new double[files.size()][];
        frames[0] = first.positions();
        for (int f = 1; f < frames.length; f++) {
            ClothMesh m = ObjReader.read(files.get(f), weld);
            if (m.vertexCount() != first.vertexCount() || !java.util.Arrays.equals(m.triangles(), first.triangles()))
                throw new MeshFileException(files.get(f).toString(), 0, "is not the same mesh as " + files.get(0).getFileName() + " (" + m.vertexCount() + " vertices and "
                        + m.triangles().length / 3 + " triangles, against " + first.vertexCount() + " and " + first.triangles().length / 3 + "): the frames of a body share one topology");
            frames[f] = m.positions();
        }
        return new BodyMesh(folder.toString(), frames[0], first.triangles(), frames, fps);
    }

    /** This body scaled by s, rotated by (rx, ry, rz) degrees about x, then y, then z, then moved by t: as a preset places it. */
    public BodyMesh transformed(double s, double[] rotationDegrees, double[] t) {
        double[][] f = null;
        if (frames != null) {
            f = new double[frames.length][];
            for (int k = 0; k < f.length; k++) f[k] = ClothMesh.place(frames[k], s, rotationDegrees, t);
        }
        return new BodyMesh(file, ClothMesh.place(vertices, s, rotationDegrees, t), triangles, f, fps);
    }

    /** The same body played at another rate (a folder of OBJs has none of its own). */
    public BodyMesh at(double framesPerSecond) {
        return new BodyMesh(file, vertices, triangles, frames, framesPerSecond);
    }
}
