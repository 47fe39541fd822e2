package xpbdcloth.sketch;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import xpbdcloth.scene.ObjExport;
import xpbdcloth.scene.Scene;
import xpbdcloth.usd.UsdRecording;

/**
 * The sketch's USD recording of the running scene: started and stopped by a key (or the library), a frame
 * every {@link ObjExport#stepsPerFrame(double)} steps of its dt (the rate {@code record --usd} takes), in
 * simulated time whatever the window's frame rate. A new scene (reset, another preset, a timestep change)
 * ends the recording: its frames were of the scene that was.
 */
final class UsdCapture {
    private UsdRecording recording;
    private Scene scene;
    private double dt;
    private int stepsPerFrame, steps;

    boolean on() { return recording != null; }

    int frames() { return recording == null ? 0 : recording.frames(); }

    /** Starts recording the scene into file (its state now the first frame). */
    void start(Path file, Scene running) throws IOException {
        if (recording != null) throw new IllegalStateException("already recording " + recording.file());
        dt = running.simulation().settings().timestep();
        stepsPerFrame = ObjExport.stepsPerFrame(dt);
        recording = UsdRecording.start(file, running, 1 / (stepsPerFrame * dt));
        scene = running;
        steps = 0;
    }

    /**
     * After a step of the running scene: a frame when one is due. Returns a message when the recording has
     * ended because the scene is no longer the one recorded (null otherwise).
     */
    String afterStep(Scene running) throws IOException {
        if (recording == null) return null;
        if (running != scene || running.simulation().settings().timestep() != dt)
            return stop("the scene changed");
        if (++steps == stepsPerFrame) {
            steps = 0;
            recording.frame();
            if (recording.frames() == UsdRecording.MAX_FRAMES) return stop("it holds the most frames a recording may");
        }
        return null;
    }

    /** Ends the recording, writing the file; says what was written (null when nothing was recording). */
    String stop(String why) throws IOException {
        if (recording == null) return null;
        UsdRecording r = recording;
        recording = null;
        scene = null;
        r.close();
        return String.format(Locale.ROOT, "wrote %s: %d USD frames at %.4g fps%s", r.file(), r.frames(), 1 / (stepsPerFrame * dt), why == null ? "" : " (ended: " + why + ")");
    }
}
