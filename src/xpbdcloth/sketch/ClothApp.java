package xpbdcloth.sketch;

import java.io.File;
import java.nio.file.Path;
import java.util.List;
import processing.core.PApplet;
import processing.core.PConstants;
import processing.core.PGraphics;
import processing.event.KeyEvent;
import processing.event.MouseEvent;
import xpbdcloth.engine.Sphere;
import xpbdcloth.mesh.ClothMesh;
import xpbdcloth.scene.ObjExport;
import xpbdcloth.scene.Preset;
import xpbdcloth.scene.PresetLoader;
import xpbdcloth.scene.Scene;

/**
 * The sketch: hooks itself into any PApplet (the Processing IDE's .pde or the launcher) through
 * {@code registerMethod}, like a Processing library, so the .pde stays three lines long.
 *
 * <p>Interactive runs step the simulation in real time ({@link FramePacer}: as many steps of dt as the
 * wall clock asks for, slow motion when steps are too costly), which is what makes the frame-rate trap
 * reproducible: dt = 1/120 s means two PBD steps per 60 Hz frame. Recording runs a fixed number of
 * steps per frame, so frames are deterministic.
 */
public final class ClothApp {
    /** Where and how long to record; null for an interactive session. */
    public static final class Recording {
        final File folder;
        final int frames;
        /** Where to write the frames as one animated GIF too, or null. */
        final File gif;
        /** Where to write the frames as an MP4 video too, or null; and its frames per second (30 or 60). */
        final File mp4;
        final int fps;

        public Recording(File folder, int frames, File gif) { this(folder, frames, gif, null, 60); }

        public Recording(File folder, int frames, File gif, File mp4, int fps) {
            if (frames < 1) throw new IllegalArgumentException("frames must be >= 1, was " + frames);
            this.folder = folder;
            this.frames = frames;
            this.gif = gif;
            this.mp4 = mp4;
            this.fps = Mp4Video.checkedFps(fps);
        }

        /** Frame i (from 1) of the recording: frame-0001.png, … */
        File frame(int i) { return new File(folder, String.format("frame-%04d.png", i)); }
    }

    static final double GRAB_PIXELS = 30;

    private final PApplet app;
    private final SketchState state;
    private final OrbitCamera camera;
    private final ClothRenderer renderer = new ClothRenderer();
    private final Hud hud = new Hud();
    private final Recording recording;
    private int recorded;
    private final FramePacer pacer = new FramePacer();
    /** Cost of one step in the last frame that stepped, ms (reacts at once, unlike the HUD's average). */
    private double lastStepMs;
    private long lastNanos;
    private double simMs, renderMs, allocatedPerFrame, meshAllocated, hudAllocated;
    private final com.sun.management.ThreadMXBean threadBean =
            (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
    private Preset framedPreset;
    private boolean framedSideBySide;

    /** The particle the mouse holds, or null. */
    private Grab grab;
    private final double[] scratch = new double[3];

    public ClothApp(PApplet app) { this(app, "hanging", false, null); }

    public ClothApp(PApplet app, String sceneNameOrPath, boolean sideBySide, Recording recording) {
        this.app = app;
        this.recording = recording;
        state = new SketchState(PresetLoader.byNameOrPath(sceneNameOrPath));
        if (sideBySide) state.toggleSideBySide();
        if (recording != null) {
            state.showHelp = false;
            recording.folder.mkdirs();
        }
        camera = new OrbitCamera(0, 1, 0, 3, 0.3, 30).attach(app);
        camera.ignoreWhen(e -> e.isControlDown() || grab != null);
        frame();
        app.textFont(app.createFont("DejaVu Sans Mono", 13, true));
        app.registerMethod("draw", this);
        app.registerMethod("keyEvent", this);
        app.registerMethod("mouseEvent", this);
        app.registerMethod("dispose", this);
        lastNanos = System.nanoTime();
    }

    /** Called by Processing when the window closes: a USD recording that runs is ended and its file written. */
    public void dispose() { state.stopUsd(); }

    public SketchState state() { return state; }

    /** Smoothed timings for reports: {sim ms per step, render ms per frame, bytes allocated per frame}. */
    public double[] timings() { return new double[] {simMs, renderMs, allocatedPerFrame}; }

    /** Centres the camera on the scene (or the pair) when the scene or the layout changes. */
    private void frame() {
        framedPreset = state.preset();
        framedSideBySide = state.sideBySide();
        Preset.Cloth c = framedPreset.cloth;
        if (c.isMesh()) { frameMesh(c.mesh); return; }
        double size = Math.max(Math.max(c.width, c.height), 0.6);
        double cx = c.origin[0], cy;
        if (c.rows == 1) { cx -= 0.5 * c.width; cy = c.origin[1] - 0.5 * c.width; } // a rope swings below its pin
        else if (c.plane == xpbdcloth.engine.ClothBuilder.Plane.VERTICAL) cy = c.origin[1] - 0.5 * c.height;
        else cy = c.origin[1] - 0.3 * size;
        double distance = size * (framedSideBySide ? 2.6 : 1.5) + 0.4;
        // Horizontal cloths are seen from higher up, so their surface shows.
        double pitch = c.plane == xpbdcloth.engine.ClothBuilder.Plane.HORIZONTAL && c.rows > 1 ? -0.55 : -0.15;
        Framing.belowHud(camera, restBox(), app.width, app.height, cx, cy, c.origin[2], distance, pitch);
    }

    /** The smallest cloth the camera frames as it is (m), the drape tester's 30 cm specimen; smaller ones are seen as this size. */
    static final double SMALLEST_FRAMED = 0.3;

    /** The running cloths' rest box {min x, y, z, max x, y, z}, side by side both (each at its offset). */
    private double[] restBox() {
        double[] box = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        List<Scene> running = state.running();
        for (int i = 0; i < running.size(); i++) {
            double[] x = running.get(i).cloth().mesh().positions();
            double ox = state.offsetX(i);
            for (int k = 0; k < x.length; k += 3)
                for (int a = 0; a < 3; a++) {
                    double v = x[k + a] + (a == 0 ? ox : 0);
                    box[a] = Math.min(box[a], v);
                    box[3 + a] = Math.max(box[3 + a], v);
                }
        }
        return box;
    }

    /**
     * A mesh cloth is framed by its rest bounding box, seen as if it were at least {@link #SMALLEST_FRAMED}
     * across; a flat-lying one (it will fall and drape) from higher up.
     */
    private void frameMesh(ClothMesh m) {
        double height = m.max(1) - m.min(1), extent = Math.max(Math.max(m.max(0) - m.min(0), height), m.max(2) - m.min(2));
        double size = Math.max(extent, SMALLEST_FRAMED);
        boolean lying = height < 0.2 * size;
        double cy = lying ? m.max(1) - 0.3 * size : 0.5 * (m.min(1) + m.max(1));
        double distance = size * (framedSideBySide ? 2.6 : 1.5) + 0.4;
        Framing.belowHud(camera, restBox(), app.width, app.height, 0.5 * (m.min(0) + m.max(0)), cy, 0.5 * (m.min(2) + m.max(2)), distance, lying ? -0.55 : -0.15);
    }

    /**
     * Writes each running cloth's current shape as an OBJ beside the sketch (the sketch folder in the
     * Processing IDE, the working directory otherwise) and says where; a failure is a red notice.
     */
    private void exportMeshes() {
        List<Scene> running = state.running();
        StringBuilder written = new StringBuilder();
        for (int i = 0; i < running.size(); i++) {
            Scene sc = running.get(i);
            String side = running.size() == 1 ? "" : (i == 0 ? "-pbd" : "-xpbd");
            String name = String.format(java.util.Locale.ROOT, "xpbd-cloth-%s%s-t%.2f.obj", state.preset().name, side, sc.simulation().time());
            File file = new File(app.sketchPath(name));
            try {
                ObjExport.write(file.toPath(), sc);
                written.append(written.length() == 0 ? "" : ", ").append(file);
            } catch (java.io.IOException | RuntimeException e) {
                state.error("could not write " + file + ": " + e.getMessage());
                return;
            }
        }
        state.say("wrote " + written);
    }

    public void draw() {
        long allocatedBefore = threadBean.getCurrentThreadAllocatedBytes();
        long now = System.nanoTime();
        double frameSeconds = Math.min(0.25, (now - lastNanos) / 1e9);
        lastNanos = now;
        long t0 = System.nanoTime();
        int steps = stepsThisFrame(frameSeconds);
        for (int i = 0; i < steps; i++) {
            if (!state.advance()) break;
            if (grab != null) grab.follow(state);  // the held cloth may have torn into a new scene
            hud.record(state.running());
        }
        long t1 = System.nanoTime();
        if (steps > 0) {
            lastStepMs = (t1 - t0) / 1e6 / steps;
            simMs = 0.9 * simMs + 0.1 * lastStepMs;
        }
        if (state.preset() != framedPreset || state.sideBySide() != framedSideBySide) {
            frame();
            hud.clear();
        }
        if (state.quitRequested) {
            state.stopUsd();
            app.exit();
            return;
        }
        if (state.exportRequested) {
            state.exportRequested = false;
            exportMeshes();
        }
        if (state.takeUsdRequest())
            state.toggleUsd(new File(app.sketchPath(state.usdFileName())).toPath());
        if (state.fitRequested) {
            state.fitRequested = false;
            if (!choosing) {
                choosing = true;
                FileChooser.open("Fit to an observed rest shape (OBJ, the scene's vertex order)", new File(app.sketchPath()), "Wavefront OBJ", "obj", this::observationSelected);
            }
        }
        state.advanceFit();
        if (state.loadRequested) {
            state.loadRequested = false;
            // One chooser at a time, and the sketch ignores keys while it is open (they are meant for it).
            if (!choosing) {
                choosing = true;
                FileChooser.open("Load a scene preset (JSON)", new File(app.sketchPath()), "Scene presets", "json", this::presetSelected);
            }
        }

        PGraphics g = app.g;
        g.background(34, 36, 42);
        camera.update(app.millis() / 1000.0);
        camera.apply(g);
        List<Scene> running = state.running();
        // The floor and the shadows first, unlit: they are flat colours, and drawn before the lights are set.
        if (state.showGrid) {
            GroundShadow.drawFloor(g, 0);
            for (int i = 0; i < running.size(); i++) {
                Scene sc = running.get(i);
                g.pushMatrix();
                g.translate((float) state.offsetX(i), 0, 0);
                GroundShadow.drawMesh(g, sc.cloth().particles().positions(), sc.cloth().triangles());
                if (state.showSpheres) for (Sphere s : sc.simulation().spheres()) GroundShadow.drawSphere(g, s);
                if (state.showSpheres) for (xpbdcloth.engine.RigidCollider s : sc.simulation().solids()) {
                    SolidMesh m = renderer.placed(s);
                    GroundShadow.drawMesh(g, m.world, m.triangles);
                }
                g.popMatrix();
            }
        }
        g.ambientLight(78, 80, 88);
        // World directions of travel (y up): a key light from above, front and left (the shadows' light),
        // and a dim fill from behind. Under the camera's mirrored y-up transform Processing lights along
        // the opposite of the direction it is given, so each is passed negated; the rendered frames show
        // the key light's side lit and its shadow on the far side. Only the key light makes highlights
        // (Processing's lights have none unless given), and only on the colliders: fabric is matte.
        g.lightSpecular(210, 206, 198);
        g.directionalLight(200, 197, 190, -GroundShadow.LIGHT_X, -GroundShadow.LIGHT_Y, -GroundShadow.LIGHT_Z);
        g.lightSpecular(0, 0, 0);
        g.directionalLight(55, 58, 66, 0.4f, -0.3f, -0.8f);
        camera.eye(scratch);
        if (state.showGrid) renderer.drawGround(g, 0);
        long m0 = threadBean.getCurrentThreadAllocatedBytes();
        renderer.floorShown = state.showGrid;
        renderer.drawScenes(g, state, scratch[0], scratch[1], scratch[2]);
        meshAllocated = 0.9 * meshAllocated + 0.1 * (threadBean.getCurrentThreadAllocatedBytes() - m0);
        long h0 = threadBean.getCurrentThreadAllocatedBytes();
        OrbitCamera.beginHud(g);
        hud.draw(g, state, simMs, renderMs, allocatedPerFrame, app.frameRate, pacer.slowMotion(), recording != null);
        OrbitCamera.endHud(g);
        hudAllocated = 0.9 * hudAllocated + 0.1 * (threadBean.getCurrentThreadAllocatedBytes() - h0);
        renderMs = 0.9 * renderMs + 0.1 * ((System.nanoTime() - t1) / 1e6);
        allocatedPerFrame = 0.9 * allocatedPerFrame + 0.1 * (threadBean.getCurrentThreadAllocatedBytes() - allocatedBefore);

        if (recording != null) {
            app.saveFrame(recording.frame(++recorded).getPath());
            // A line every 60 frames, so a long recording is seen to move (each frame waits for its steps).
            if (recorded % 60 == 0 && recorded < recording.frames) System.out.printf("  %d of %d frames%n", recorded, recording.frames);
            if (recorded >= recording.frames) {
                System.out.printf(java.util.Locale.ROOT, "recorded %d frames: sim %.2f ms/step, render %.2f ms/frame, %.0f bytes allocated/frame (smoothed), of which %.0f in the scenes (cloth, particles, colliders) and %.0f in the HUD (text)%n",
                        recorded, simMs, renderMs, allocatedPerFrame, meshAllocated, hudAllocated);
                if (recording.gif != null) writeGif();
                if (recording.mp4 != null) writeMp4();
                app.exit();
            }
        }
    }

    private void writeGif() {
        try {
            int used = AnimatedGif.write(recording, recorded);
            System.out.printf("wrote %s (%d frames, %d bytes)%n", recording.gif, used, recording.gif.length());
        } catch (java.io.IOException e) {
            System.err.println("no GIF: " + e.getMessage() + " (the PNG frames are in " + recording.folder + ")");
        }
    }

    /** Simulated seconds between two recorded frames: the steps each frame takes, times dt. */
    double recordedFrameSeconds() {
        return ObjExport.stepsPerFrame(state.dt()) * state.dt();
    }

    private void writeMp4() {
        try {
            double frameSeconds = recordedFrameSeconds();
            int used = Mp4Video.write(recording, recorded, frameSeconds);
            System.out.printf("wrote %s (%d frames at %d fps, real time; %d bytes)%n", recording.mp4, used,
                    Math.round(1 / (frameSeconds * (60 / recording.fps))), recording.mp4.length());
        } catch (java.io.IOException | RuntimeException e) {
            System.err.println("no MP4: " + e.getMessage() + " (the PNG frames are in " + recording.folder + ")");
        }
    }

    /** Real time (slow motion if steps cost too much) when interactive; a fixed count (60 Hz frames) when recording. */
    private int stepsThisFrame(double frameSeconds) {
        double dt = state.dt();
        if (recording != null) return ObjExport.stepsPerFrame(dt);
        if (state.paused) {
            pacer.reset();
            return state.pendingSteps > 0 ? 1 : 0;
        }
        return pacer.steps(frameSeconds, dt, lastStepMs);
    }

    /** File chooser callback ('l'); a broken file keeps the current scene and shows why. */
    private void presetSelected(File file) {
        choosing = false;
        if (file != null) state.load(Path.of(file.getPath()));
    }

    /** File chooser callback ('p'): the fit starts against the chosen shape. */
    private void observationSelected(File file) {
        choosing = false;
        if (file != null) state.startFit(Path.of(file.getPath()));
    }

    /** True while the preset file chooser is open. */
    private volatile boolean choosing;

    public void keyEvent(KeyEvent e) {
        // Keep Esc from closing the sketch by accident, also while a file chooser is open (its Esc closes
        // the chooser, and Processing would see it too).
        if (e.getAction() == KeyEvent.PRESS && e.getKey() == PConstants.ESC) app.key = 0;
        if (choosing || e.getAction() != KeyEvent.PRESS || e.getKey() == PConstants.CODED) return;
        KeyBinding b = KeyBindings.forKey(e.getKey());
        if (b != null) b.press(state);
    }

    public void mouseEvent(MouseEvent e) {
        int action = e.getAction();
        if (action == MouseEvent.PRESS && e.getButton() == PConstants.LEFT && e.isControlDown()) grab(e.getX(), e.getY());
        else if (action == MouseEvent.DRAG && grab != null) drag(e.getX(), e.getY());
        else if (action == MouseEvent.RELEASE && grab != null) release();
    }

    /** Picks the particle nearest the pointer on screen (within 30 px) and holds it in every running scene. */
    private void grab(int mx, int my) {
        camera.setViewport(app.width, app.height);
        grab = Grab.pick(state, (x, y, z, out) -> { camera.project(x, y, z, out); out[3] = out[2]; }, mx, my, GRAB_PIXELS);
    }

    private void drag(int mx, int my) {
        camera.unprojectOnViewPlane(mx, my, grab.x, grab.y, grab.z, scratch);
        grab.moveTo(scratch[0], scratch[1], scratch[2]);
    }

    private void release() {
        grab.release();
        grab = null;
    }
}
