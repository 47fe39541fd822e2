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

/**
 * An observed motion: a folder of OBJ files, one per step of the scene's dt, read in name order, the
 * first the cloth after one step from the scene's start (the format other tools export a mesh sequence
 * in; each file is checked as an {@link Observation} is).
 */
public final class Trajectory {
    /**
     * The most frames a trajectory may have, read or written: a fit keeps every frame's state as a
     * checkpoint and replays each frame per gradient, so ten thousand steps (minutes of motion) is already
     * hours of fitting; more is a mistake, not a motion.
     */
    public static final int MAX_FRAMES = 10_000;

    private Trajectory() {}

    /** The frames in a folder, [frame][3·vertex + axis], or a {@link FitException} naming the file that is not a frame of this scene. */
    public static double[][] read(Path folder, Scene scene) {
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
