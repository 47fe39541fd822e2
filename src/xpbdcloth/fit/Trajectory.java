package xpbdcloth.fit;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;
import xpbdcloth.engine.Simulation;
import xpbdcloth.scene.ObjExport;
import xpbdcloth.scene.Scene;
import xpbdcloth.mesh.UsdMeshAnimation;

/**
 * An observed motion: a folder of OBJ files, one per step of the scene's dt, read in name order, the
 * first the cloth after one step from the scene's start (the format other tools export a mesh sequence
 * in; each file is checked as an {@link Observation} is); or one USD text file (.usda, as
 * {@code record --usd --fps 1/dt} writes it) whose animated mesh has a time code per step, code k the
 * cloth after k steps.
 */
public final class Trajectory {
    /**
     * The most frames a trajectory may have, read or written: a fit keeps every frame's state as a
     * checkpoint and replays each frame per gradient, so ten thousand steps (minutes of motion) is already
     * hours of fitting; more is a mistake, not a motion.
     */
    public static final int MAX_FRAMES = 10_000;

    private Trajectory() {}

    /** Whether the path is a trajectory in one USD file rather than a folder of OBJs. */
    public static boolean isUsd(Path path) {
        return path.getFileName() != null && path.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".usda");
    }

    /** The frames in a folder (or a .usda file), [frame][3·vertex + axis], or a {@link FitException} naming the file that is not a frame of this scene. */
    public static double[][] read(Path folder, Scene scene) {
        if (isUsd(folder)) return readUsd(folder, scene);
        List<Path> files;
        try (Stream<Path> s = Files.list(folder)) {
            files = s.filter(p -> p.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".obj")).sorted().toList();
        } catch (IOException e) {
            throw new FitException(folder + " cannot be listed: " + e.getMessage());
        }
        if (files.isEmpty())
            throw new FitException(folder + " holds no .obj frames: a trajectory is a folder of OBJ files, one per step (write one with `xpbd-cloth fit --make-observation DIR --frames 50`)");
        if (files.size() > MAX_FRAMES)
            throw new FitException(folder + " holds " + files.size() + " .obj frames, more than the " + MAX_FRAMES + " a trajectory may have");
        double[][] frames = new double[files.size()][];
        for (int f = 0; f < frames.length; f++) frames[f] = Observation.read(files.get(f), scene);
        return frames;
    }

    /**
     * The animated mesh of a .usda file as a trajectory of the scene: its vertices the scene's, in order (its
     * faces, when it has the scene's count of them, the scene's faces), one time code per step of dt
     * (timeCodesPerSecond = 1/dt), codes 1, 2, … N consecutive (a code 0, the start, is the scene's own start
     * and not read).
     */
    static double[][] readUsd(Path file, Scene scene) {
        UsdMeshAnimation m;
        try {
            // A recording's cloth is /World/Cloth (its bodies are meshes too); another file's one animated mesh.
            xpbdcloth.mesh.UsdaReader.Stage stage = xpbdcloth.mesh.UsdaReader.read(file);
            boolean recording = stage.prims.stream().anyMatch(p -> p.path.equals("/World/Cloth"));
            m = UsdMeshAnimation.of(stage, recording ? "/World/Cloth" : null);
        } catch (IllegalArgumentException e) {
            throw new FitException(e.getMessage());
        }
        int n = scene.cloth().particles().count();
        if (m.vertexCount() != n)
            throw new FitException(file + ": " + m.prim + " has " + m.vertexCount() + " points, the scene " + scene.preset().name + " has " + n + " particles");
        xpbdcloth.mesh.ClothMesh mesh = scene.cloth().mesh();
        int corner = 0;
        boolean same = m.faceVertexCounts.length == mesh.faceCount();
        for (int k = 0; same && k < mesh.faceCount(); k++) {
            int[] f = mesh.face(k);
            same = m.faceVertexCounts[k] == f.length;
            for (int j = 0; same && j < f.length; j++) same = m.faceVertexIndices[corner++] == f[j];
        }
        if (!same) throw new FitException(file + ": the faces of " + m.prim + " are not the scene's: its points must be the scene's vertices in the scene's order");
        double dt = scene.simulation().settings().timestep();
        if (Math.abs(m.timeCodesPerSecond * dt - 1) > 1e-9)
            throw new FitException(String.format(Locale.ROOT, "%s: timeCodesPerSecond is %s, but a trajectory has a time code per step of the scene's dt %s s (%s a second): record it with --fps %s",
                    file, m.timeCodesPerSecond, dt, 1 / dt, 1 / dt));
        int first = m.timeCodes[0] == 0 ? 1 : 0, frames = m.timeCodes.length - first;
        if (frames < 1) throw new FitException(file + ": " + m.prim + " has no frames after the start (time code 0)");
        if (frames > MAX_FRAMES) throw new FitException(file + " holds " + frames + " frames, more than the " + MAX_FRAMES + " a trajectory may have");
        double[][] out = new double[frames][];
        for (int f = 0; f < frames; f++) {
            if (m.timeCodes[first + f] != f + 1)
                throw new FitException(file + ": the time codes of " + m.prim + " must be 1, 2, 3, … one per step; the " + (f + 1) + "th is " + m.timeCodes[first + f]);
            out[f] = m.points[first + f];
        }
        return out;
    }

    /** The scene's first {@code frames} steps as the engine runs them, each with Gaussian noise sigma (m) from seed. */
    public static double[][] simulate(Scene scene, int frames, double sigma, long seed) {
        checkFrames(frames);
        Simulation sim = scene.simulation();
        double[][] out = new double[frames][];
        for (int f = 0; f < frames; f++) {
            sim.step();
            out[f] = Observation.withNoise(sim.particles().positions(), sigma, seed + f);
        }
        return out;
    }

    static void checkFrames(int frames) {
        if (frames < 1 || frames > MAX_FRAMES) throw new IllegalArgumentException("frames must be in [1, " + MAX_FRAMES + "], was " + frames);
    }

    /**
     * Simulates the scene's first {@code frames} steps and writes each as frame-0001.obj … into the folder as
     * it is made (nothing held but the current frame), each with Gaussian noise sigma (m) from seed.
     */
    public static List<Path> simulateInto(Path folder, Scene scene, int frames, double sigma, long seed, String comment) throws IOException {
        checkFrames(frames);
        Files.createDirectories(folder);
        Simulation sim = scene.simulation();
        List<Path> written = new ArrayList<>();
        for (int f = 0; f < frames; f++) {
            sim.step();
            Path file = ObjExport.frameFile(folder, f + 1);
            Observation.write(file, scene, Observation.withNoise(sim.particles().positions(), sigma, seed + f), comment + ", frame " + (f + 1));
            written.add(file);
        }
        return written;
    }

    /** Writes frame-0001.obj … into the folder (made if missing), each the scene's mesh at that frame. */
    public static List<Path> write(Path folder, Scene scene, double[][] frames, String comment) throws IOException {
        Files.createDirectories(folder);
        List<Path> written = new ArrayList<>();
        for (int f = 0; f < frames.length; f++) {
            Path file = ObjExport.frameFile(folder, f + 1);
            Observation.write(file, scene, frames[f], comment + ", frame " + (f + 1));
            written.add(file);
        }
        return written;
    }
}
