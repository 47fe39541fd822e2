package xpbdcloth.scene;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import xpbdcloth.engine.Simulation;
import xpbdcloth.mesh.ObjWriter;

/**
 * A scene's cloth as Wavefront OBJ, for rendering the motion elsewhere (Blender and most 3D tools read an
 * OBJ sequence as an animation): one file per frame, the same vertices in the same order and the same
 * faces every frame, only the positions and normals change.
 */
public final class ObjExport {
    /** Recordings are 60 Hz frames, as the sketch's recorder takes them. */
    public static final double FRAME_SECONDS = 1 / 60.0;

    private ObjExport() {}

    /** Steps per recorded frame at timestep dt: at least one, else the nearest whole number to 1/60 s. */
    public static int stepsPerFrame(double dt) {
        return Math.max(1, (int) Math.round(FRAME_SECONDS / dt));
    }

    /** The frame rate of a sequence taken every {@link #stepsPerFrame(double)} steps of dt, in frames per simulated second. */
    public static double naturalFps(double dt) {
        return 1 / (dt * stepsPerFrame(dt));
    }

    /**
     * Steps per frame for a sequence at {@code fps} frames per simulated second: 1/fps must be a whole number
     * of steps of dt (a frame between two steps would be a shape the simulation never had).
     */
    public static int stepsPerFrame(double dt, double fps) {
        if (!(fps > 0) || fps > 1000) throw new IllegalArgumentException("fps must be in (0, 1000], was " + fps);
        double k = 1 / (fps * dt);
        long whole = Math.round(k);
        if (whole < 1 || Math.abs(k - whole) > 1e-6 * k)
            throw new IllegalArgumentException(String.format(Locale.ROOT,
                    "fps: %s frames a second put a frame every %.4g ms, not a whole number of the scene's %.4g ms steps; rates it can give: %s",
                    fps == Math.rint(fps) ? String.valueOf((long) fps) : String.valueOf(fps), 1000 / fps, 1000 * dt, ratesFor(dt)));
        return (int) whole;
    }

    /** The first few frame rates a timestep can give: 1/(k dt) for k = 1, 2, 3, 4, 5. */
    static String ratesFor(double dt) {
        StringBuilder b = new StringBuilder();
        for (int k = 1; k <= 5; k++) b.append(k == 1 ? "" : ", ").append(String.format(Locale.ROOT, "%.4g", 1 / (k * dt)).replaceAll("(\\.\\d*?)0+$", "$1").replaceAll("\\.$", ""));
        return b.append(", …").toString();
    }

    /** frame-0001.obj, … in the folder: how a sequence is named, so tools that read OBJ sequences take it in order. */
    public static Path frameFile(Path folder, int frame) {
        return folder.resolve(String.format(Locale.ROOT, "frame-%04d.obj", frame));
    }

    /** The cloth's current shape. */
    public static void write(Path file, Scene scene) throws IOException {
        Simulation sim = scene.simulation();
        String comment = String.format(Locale.ROOT, "xpbd-cloth scene %s, t = %.4f s, step %d", scene.preset().name, sim.time(), sim.stepCount());
        ObjWriter.write(file, scene.cloth().mesh(), sim.particles().positions(), comment);
    }

    /**
     * Runs a fresh scene of the preset for {@code frames} frames of {@link #stepsPerFrame(double)} steps each
     * (60 Hz frames where dt divides 1/60 s; 1/dt frames a second where dt is longer) and writes frame-0001.obj, … into
     * {@code folder} (created if missing), frame 1 being the state after the first frame's steps.
     * Headless: no window, no display. Returns the number of files written.
     */
    public static int recordSequence(Preset preset, int frames, Path folder) throws IOException {
        return recordSequence(preset, frames, folder, stepsPerFrame(preset.solver.timestep()));
    }

    /** The same with a frame every {@code steps} steps of the preset's dt. */
    public static int recordSequence(Preset preset, int frames, Path folder, int steps) throws IOException {
        recordSequence(Scene.of(preset), frames, folder, steps);
        return frames;
    }

    /**
     * The same from a scene already built; returns the scene it ended with, to ask how its last step went (a
     * cloth that tears goes on as the cut scene, and each OBJ frame has the topology of its moment).
     */
    public static Scene recordSequence(Scene scene, int frames, Path folder, int steps) throws IOException {
        if (frames < 1) throw new IllegalArgumentException("frames must be >= 1, was " + frames);
        if (steps < 1) throw new IllegalArgumentException("steps per frame must be >= 1, was " + steps);
        Files.createDirectories(folder);
        for (int f = 1; f <= frames; f++) {
            for (int s = 0; s < steps; s++) scene = scene.step();
            write(frameFile(folder, f), scene);
        }
        return scene;
    }
}
