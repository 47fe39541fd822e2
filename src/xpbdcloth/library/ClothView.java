package xpbdcloth.library;

import java.io.File;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import processing.core.PApplet;
import processing.core.PConstants;
import processing.event.KeyEvent;
import processing.event.MouseEvent;
import processing.opengl.PGraphicsOpenGL;
import xpbdcloth.engine.Check;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SolverType;
import xpbdcloth.scene.Limits;
import xpbdcloth.scene.PresetLoader;
import xpbdcloth.scene.Scene;
import xpbdcloth.sketch.ClothRenderer;
import xpbdcloth.sketch.FramePacer;
import xpbdcloth.sketch.Grab;
import xpbdcloth.sketch.KeyBinding;
import xpbdcloth.sketch.KeyBindings;
import xpbdcloth.sketch.SketchState;

/**
 * A simulated cloth in your own Processing sketch. It registers itself with the sketch the way PeasyCam
 * does ({@code pre} to step in real time, {@code keyEvent}, {@code mouseEvent}); you call {@link #draw()}
 * where you want the cloth, under whatever camera and transforms your sketch sets:
 *
 * <pre>
 * import xpbdcloth.library.*;
 *
 * ClothView cloth;
 *
 * void setup() {
 *   size(800, 600, P3D);
 *   cloth = new ClothView(this, "hanging");
 * }
 *
 * void draw() {
 *   background(30);
 *   lights();
 *   translate(width / 2, height * 0.85);  // the world's origin: the floor under the cloth
 *   cloth.draw();
 * }
 * </pre>
 *
 * The cloth lives in metres with y up; {@link #draw()} scales it by {@link #pixelsPerMetre()} and turns
 * it half a turn about x, so that up is up on screen and the scene's +z points away from Processing's
 * default camera (add {@code rotateY(PI)} to see it from its +z side, as the xpbd-cloth sketch does). Drag the cloth with the left mouse button (it is thrown when released);
 * the sketch's keys (m for PBD/XPBD, i/I iterations, b side by side, space pause, r reset, …) work as in
 * the xpbd-cloth sketch unless {@link #keys(boolean)} turns them off; the same controls are methods here
 * ({@link #iterations(int)}, {@link #mode(ConstraintMode)}, {@link #wind(boolean)}, …). The engine is yours
 * too: {@link #simulation()}, {@link #simulations()}.
 */
public final class ClothView {
    /** Pixels per metre when the sketch does not choose: a 1 m cloth a little under half of an 800 px window. */
    public static final float DEFAULT_PIXELS_PER_METRE = 300;
    /** How near (px) the pointer must be to a particle to grab it. */
    public static final double GRAB_PIXELS = 30;
    /** Keys of the full sketch that need its window (file chooser, OBJ export, help, quit, floor): ignored here. */
    static final String SKETCH_ONLY_KEYS = "lOhqg";

    private final PApplet app;
    private final SketchState state;
    private final ClothRenderer renderer = new ClothRenderer();
    private final FramePacer pacer = new FramePacer();
    private final ScreenMapping screen = new ScreenMapping();
    private float pixelsPerMetre = DEFAULT_PIXELS_PER_METRE;
    private boolean autoStep = true, keys = true, mouse = true, grabNeedsControl;
    private long lastNanos;
    private double lastStepMs;

    /** The particle the mouse holds, or null. */
    private Grab grab;
    private final double[] scratch = new double[4];

    /**
     * A cloth from a built-in scene ("hanging", "corners", "flag", …) or a preset file; a relative path is
     * looked up in the sketch's data folder, then in the sketch folder. The sketch must use P3D.
     *
     * @throws IllegalStateException if the sketch's renderer is not P3D
     * @throws IllegalArgumentException if there is no such scene, or the preset is broken (the message
     *         names the file, the field and the problem)
     */
    public ClothView(PApplet app, String sceneNameOrPath) {
        if (!(app.g instanceof PGraphicsOpenGL) || !app.g.is3D())
            throw new IllegalStateException("ClothView draws in 3D: call size(width, height, P3D) in settings() or setup()");
        this.app = app;
        state = new SketchState(PresetLoader.byNameOrPath(resolve(app, sceneNameOrPath)));
        app.registerMethod("pre", this);
        app.registerMethod("keyEvent", this);
        app.registerMethod("mouseEvent", this);
        app.registerMethod("dispose", this);
        lastNanos = System.nanoTime();
    }

    /** Called by Processing when the sketch closes: a USD recording that runs is ended and its file written. */
    public void dispose() { state.stopUsd(); }

    /** A built-in name as it is; a relative file name from the sketch's data folder, else its folder. */
    private static String resolve(PApplet app, String nameOrPath) {
        if (PresetLoader.BUILT_IN.contains(nameOrPath) || new File(nameOrPath).isAbsolute()) return nameOrPath;
        for (String candidate : new String[] {app.dataPath(nameOrPath), app.sketchPath(nameOrPath)})
            if (new File(candidate).isFile()) return candidate;
        return nameOrPath;
    }

    // ---- Stepping -------------------------------------------------------------------------------------

    /** Called by Processing before each frame's draw(): advances the simulation by the wall-clock time. */
    public void pre() {
        long now = System.nanoTime();
        double frameSeconds = Math.min(0.25, (now - lastNanos) / 1e9);
        lastNanos = now;
        state.advanceFit();
        if (state.takeUsdRequest()) // the R key
            state.toggleUsd(java.nio.file.Path.of(app.sketchPath(state.usdFileName())));
        if (!autoStep) return;
        if (state.paused()) {
            pacer.reset();
            if (state.stepRequested()) state.advance();
            return;
        }
        int steps = pacer.steps(frameSeconds, state.dt(), lastStepMs);
        long t0 = System.nanoTime();
        int done = 0;
        while (done < steps && state.advance()) done++;
        if (done > 0) lastStepMs = (System.nanoTime() - t0) / 1e6 / done;
    }

    /** Advances every running cloth by one step of dt (for sketches that step themselves: see {@link #autoStep}). */
    public void step() { state.advance(); }

    /**
     * Records the running cloth and its colliders as one USD stage (text, .usda) from now on, a frame per
     * 1/60 s of simulated time (or per step when dt is longer), until {@link #stopUsd()} or the sketch closes;
     * relative paths are in the sketch's folder. Blender, Houdini and usdview open the file.
     */
    public ClothView recordUsd(String file) {
        state.stopUsd();
        state.toggleUsd(java.nio.file.Path.of(new File(file).isAbsolute() ? file : app.sketchPath(file)));
        return this;
    }

    /** Ends the USD recording and writes its file (nothing when none runs). */
    public ClothView stopUsd() {
        state.stopUsd();
        return this;
    }

    /** Whether {@code pre()} steps in real time (default) or only {@link #step()} does. */
    public ClothView autoStep(boolean on) { autoStep = on; return this; }

    // ---- Drawing --------------------------------------------------------------------------------------

    /**
     * Draws the cloth (and its colliders) at the current origin, in metres × {@link #pixelsPerMetre()},
     * y up, +z away from the default camera. Uses the sketch's lights: call {@code lights()} first.
     */
    public void draw() {
        PGraphicsOpenGL g = (PGraphicsOpenGL) app.g;
        g.pushMatrix();
        // Half a turn about x: y up on screen. A rotation, not a mirror (scaling y alone would be one, and
        // OpenGL would then take the faces towards the viewer for back faces and light them from behind).
        g.scale(pixelsPerMetre, -pixelsPerMetre, -pixelsPerMetre);
        screen.capture(g);
        ScreenMapping.eye(g, scratch);
        renderer.strokeUnit(1 / pixelsPerMetre);
        renderer.drawScenes(g, state, scratch[0], scratch[1], scratch[2]);
        g.popMatrix();
    }

    public float pixelsPerMetre() { return pixelsPerMetre; }

    /** How big the cloth draws: pixels per metre of the simulation (finite, > 0). */
    public ClothView pixelsPerMetre(float pixels) {
        pixelsPerMetre = checkedScale(pixels);
        return this;
    }

    static float checkedScale(float pixels) {
        if (!(pixels > 0) || Float.isInfinite(pixels))
            throw new IllegalArgumentException("pixelsPerMetre must be finite and > 0, was " + pixels);
        return pixels;
    }

    /** Draw the cloth as a wireframe coloured by strain (red stretched, blue compressed) instead of shaded. */
    public ClothView wireframe(boolean on) { state.wireframe(on); return this; }

    // ---- Input ----------------------------------------------------------------------------------------

    /** Whether the sketch's keys act on this cloth (default on). */
    public ClothView keys(boolean on) { keys = on; return this; }

    /** Whether the mouse grabs the cloth (default on). */
    public ClothView mouse(boolean on) { mouse = on; return this; }

    /**
     * Grab only with Ctrl held, leaving plain drags to a camera library such as PeasyCam, whose
     * rotation is on the left button too.
     */
    public ClothView grabWithControl(boolean on) { grabNeedsControl = on; return this; }

    /** Called by Processing for each key. */
    public void keyEvent(KeyEvent e) {
        if (!keys || e.getAction() != KeyEvent.PRESS || e.getKey() == PConstants.CODED) return;
        if (SKETCH_ONLY_KEYS.indexOf(e.getKey()) >= 0) return;
        KeyBinding b = KeyBindings.forKey(e.getKey());
        if (b != null) b.press(state);
    }

    /** Called by Processing for each mouse event. */
    public void mouseEvent(MouseEvent e) {
        if (!mouse) return;
        int action = e.getAction();
        if (action == MouseEvent.PRESS && e.getButton() == PConstants.LEFT && (e.isControlDown() || !grabNeedsControl))
            grab(e.getX(), e.getY());
        else if (action == MouseEvent.DRAG) dragTo(e.getX(), e.getY());
        else if (action == MouseEvent.RELEASE) release();
    }

    /**
     * Holds the particle drawn nearest to screen point (x, y), within {@link #GRAB_PIXELS}, as the cloth was
     * last drawn; every running cloth holds the same particle. Returns whether one was grabbed.
     */
    public boolean grab(double x, double y) {
        release();
        if (!screen.ready()) return false;
        grab = Grab.pick(state, screen::toScreen, x, y, GRAB_PIXELS);
        return grab != null;
    }

    /** Moves the held particle under screen point (x, y), at the depth where it was grabbed. */
    public void dragTo(double x, double y) {
        if (grab == null) return;
        screen.toWorld(x, y, grab.depth, scratch);
        grab.moveTo(scratch[0], scratch[1], scratch[2]);
    }

    /** Lets go: the particle keeps the velocity the drag gave it, so a quick drag throws the cloth. */
    public void release() {
        if (grab == null) return;
        grab.release();
        grab = null;
    }

    /** The particle held by the mouse, or -1. */
    public int grabbed() { return grab == null ? -1 : grab.particle; }

    // ---- The engine -----------------------------------------------------------------------------------

    /** The (first) running simulation: add forces, colliders, read positions. */
    public Simulation simulation() { return state.first(); }

    /** The (first) running cloth. */
    public Cloth cloth() { return state.running().get(0).cloth(); }

    /** Every running simulation: the one cloth, or side by side the PBD one (left) and the XPBD one (right). */
    public List<Simulation> simulations() {
        List<Simulation> out = new ArrayList<>();
        for (Scene s : state.running()) out.add(s.simulation());
        return Collections.unmodifiableList(out);
    }

    // ---- The sketch's controls, as methods (the keys call the same) ----------------------------------

    public ConstraintMode mode() { return state.mode(); }
    public int iterations() { return state.iterations(); }
    public int substeps() { return state.substeps(); }
    /** The timestep, s. */
    public double dt() { return state.dt(); }
    public SolverType solver() { return state.solverType(); }
    public boolean paused() { return state.paused(); }
    public boolean windOn() { return state.windOn(); }
    /** The wind's speed, m/s (e / E change it by 0.5). */
    public double windSpeed() { return state.windSpeed(); }

    /**
     * PBD or XPBD for the running cloth, as the m key; refused with a {@link #message()} side by side (it
     * shows both) or for PBD under a global solver.
     */
    public ClothView mode(ConstraintMode m) {
        if (m == null) throw new IllegalArgumentException("mode must be PBD or XPBD, was null");
        if (state.mode() != m) state.toggleMode();
        return this;
    }

    /** Solver iterations per substep, in [1, 1000]; refused with a {@link #message()} beyond the presets' work limit. */
    public ClothView iterations(int n) {
        Check.inRange("iterations", n, (long) Limits.ITERATIONS.lo, (long) Limits.ITERATIONS.hi);
        state.changeIterations(n - state.iterations());
        return this;
    }

    /** Substeps per step, in [1, 100]; refused with a {@link #message()} beyond the presets' work limit. */
    public ClothView substeps(int n) {
        Check.inRange("substeps", n, (long) Limits.SUBSTEPS.lo, (long) Limits.SUBSTEPS.hi);
        state.changeSubsteps(n - state.substeps());
        return this;
    }

    public ClothView paused(boolean on) {
        if (state.paused() != on) state.togglePause();
        return this;
    }

    /** The wind on or off, as the w key (a scene without wind gets the sketch's breeze). */
    public ClothView wind(boolean on) {
        if (state.windOn() != on) state.toggleWind();
        return this;
    }

    /** The scene back at its start, as the r key. */
    public ClothView reset() {
        release();
        state.reset();
        return this;
    }

    /** PBD on the left and XPBD on the right, the same cloth otherwise. */
    public ClothView sideBySide(boolean on) {
        if (state.sideBySide() != on) {
            release();
            state.toggleSideBySide();
        }
        return this;
    }

    /** A fabric scene's cloth becomes the named measured fabric (see data/fabrics.json), without a reset. */
    public ClothView fabric(String name) { state.useFabric(name); return this; }

    /**
     * Fits the cloth's spring compliances to an observed rest shape (an OBJ with the scene's vertices in
     * its order, e.g. from {@code xpbd-cloth fit --make-observation}), one iteration a frame, the
     * observation drawn as a ghost; when it ends the cloth takes the fitted α. False (see
     * {@link #message()}) when the file is not an observation of this scene.
     */
    public boolean fit(String objPath) { return state.startFit(java.nio.file.Path.of(objPath)); }

    /** The last notice (a refused key, a paused divergence), or "". */
    public String message() { return state.message(); }
}
