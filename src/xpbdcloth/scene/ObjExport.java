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
     * Runs a fresh scene of the preset for {@code frames} 60 Hz frames and writes frame-0001.obj, … into
     * {@code folder} (created if missing), frame 1 being the state after the first frame's steps.
     * Headless: no window, no display. Returns the number of files written.
     */
    public static int recordSequence(Preset preset, int frames, Path folder) throws IOException {
        if (frames < 1) throw new IllegalArgumentException("frames must be >= 1, was " + frames);
        Files.createDirectories(folder);
        Scene scene = Scene.of(preset);
        int steps = stepsPerFrame(preset.solver.dt);
        for (int f = 1; f <= frames; f++) {
            for (int s = 0; s < steps; s++) scene.simulation().step();
            write(frameFile(folder, f), scene);
        }
        return frames;
    }
}
