package xpbdcloth.sketch;

import java.nio.file.Path;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.Material;
import xpbdcloth.engine.SelfCollision;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SolverSettings;
import xpbdcloth.engine.SolverType;
import xpbdcloth.fabric.Fabric;
import xpbdcloth.scene.FabricCatalogue;
import xpbdcloth.scene.Limits;
import xpbdcloth.scene.Preset;
import xpbdcloth.scene.PresetException;
import xpbdcloth.scene.PresetLoader;
import xpbdcloth.scene.Scene;

/**
 * Everything the sketch's controls change, without Processing: the running scene (or the PBD and XPBD
 * pair side by side), solver parameters, per-family materials, wind and view toggles. Keys act on this
 * class through {@link KeyBindings}, so every control can be tested without a window.
 */
public final class SketchState {
    /** The timesteps the 't' key cycles through: 30, 50 (the original's 20 ms), 60 and 120 steps/s. */
    static final double[] TIMESTEPS = {1 / 30.0, 1 / 50.0, 1 / 60.0, 1 / 120.0};
    /** Compliance changes by a factor √10 (half a decade) per key press. */
    static final double COMPLIANCE_FACTOR = Math.sqrt(10);
    static final double STIFFNESS_STEP = 0.05;
    /**
     * Solver threads for the sketch's scenes (the launcher's --threads). Two by default where the machine
     * has two cores: the fabric scenes' solve takes about 0.6 of its one-thread time on two. Under a software
     * renderer (Xvfb/Mesa) drawing takes a core too, and {@code --threads 1} may then be as fast. The result
     * is the same bits for any count.
     */
    private static int threads = Math.min(2, Runtime.getRuntime().availableProcessors());

    public static void setThreads(int n) {
        threads = new SolverSettings().withThreads(n).threads(); // the engine's range check, not a copy of it
    }
    static final double MIN_COMPLIANCE = Limits.SMALLEST_NONZERO_COMPLIANCE, MAX_COMPLIANCE = Limits.COMPLIANCE.hi;
    /** The families a material key acts on: null means all three. */
    static final ConstraintFamily[] FAMILY_CHOICES = {null, ConstraintFamily.STRUCTURAL, ConstraintFamily.SHEAR, ConstraintFamily.BEND};

    private Preset preset;
    private Scene main, left, right;
    private boolean sideBySide;

    /**
     * The solver parameters every running scene shares: the preset's, as the keys have replaced them (a
     * value, validated when made; each running simulation is given it whole, the side-by-side pair with
     * its own mode).
     */
    private SolverSettings shared = new SolverSettings();
    /** The spring families' materials now: the preset's, as the keys and a fit have changed them (values, never edited in place). */
    private final Map<ConstraintFamily, Material> materials = new EnumMap<>(ConstraintFamily.class);
    private int familyChoice;

    // Wind: on/off, direction angle about y (rad), speed (m/s).
    private boolean windOn;
    private double windAngle, windSpeed;

    // View toggles.
    boolean paused, wireframe, showParticles, showSpheres = true, showGrid = true, showHelp, loadRequested, exportRequested, quitRequested, fitRequested, usdRequested;
    /** The USD recording of the running scene, while one runs. */
    private final UsdCapture usd = new UsdCapture();
    /** The fit the p key started, or null. */
    private LiveFit fit;
    int pendingSteps;

    /** The running cloths' fabric (null: springs): the preset's until the fabric key changes it. */
    private Fabric fabric;
    private String message = "";
    private boolean messageIsError;

    public SketchState(Preset preset) {
        use(preset);
    }

    /** Switches to a preset's scene with the preset's own parameters (scene select, reset, load). */
    private void use(Preset p) {
        Scene fresh = Scene.of(p); // builds or throws before anything here changes
        preset = p;
        shared = p.solver.withThreads(threads);
        fabric = p.fabric == null ? null : p.fabric.fabric;
        materials.clear();
        materials.putAll(p.families);
        windOn = p.wind != null;
        selfCollisionOn = p.selfCollision != null;
        continuousOn = p.selfCollision != null && p.selfCollision.continuous;
        pointTriangleOn = p.selfCollision != null && p.selfCollision.pointTriangle;
        double[] u = p.wind == null ? new double[] {2, 0, 1.5} : p.wind.velocity;
        windAngle = Math.atan2(u[2], u[0]);
        windSpeed = Math.hypot(u[0], u[2]);
        closeRunning();
        fit = null;
        tearingSaid = false;
        main = fresh;
        left = right = null;
        if (sideBySide) buildPair();
        applyAll();
    }

    private void buildPair() {
        left = Scene.of(preset);
        right = Scene.of(preset);
    }

    /** Gives every running scene the shared settings and the keys' materials, wind and contacts (the pair: PBD left, XPBD right). */
    private void applyAll() {
        for (Scene s : running()) {
            s.simulation().settings(s == left ? shared.withModeAndSolver(ConstraintMode.PBD, SolverType.GAUSS_SEIDEL)
                    : s == right ? shared.withMode(ConstraintMode.XPBD) : shared);
            materials.forEach(s.simulation()::setMaterial);
            if (fabric != null && s.fabric() != fabric) s.useFabric(fabric);
            s.setWind(windOn);
            SelfCollision self = s.simulation().selfCollision();
            if (selfCollisionOn != (self != null) || (self != null && (continuousOn != (self.guard() != null) || pointTriangleOn != self.pointTriangle())))
                s.simulation().selfCollision(selfCollisionOn ? Scene.selfCollision(s.cloth(), selfCollisionSpec(), s.preset().cloth.garment) : null);
            s.wind().setVelocity(windSpeed * Math.cos(windAngle), 0, windSpeed * Math.sin(windAngle));
        }
    }

    /** Frees the solver threads of the scenes about to be replaced (a no-op on one thread). */
    private void closeRunning() {
        for (Scene s : new Scene[] {main, left, right}) if (s != null) s.simulation().close();
    }

    /** The scenes being stepped and drawn: one, or PBD and XPBD side by side. */
    public List<Scene> running() { return sideBySide ? List.of(left, right) : List.of(main); }

    public boolean sideBySide() { return sideBySide; }
    public Preset preset() { return preset; }
    public ConstraintMode mode() { return shared.mode(); }
    public int iterations() { return shared.iterations(); }
    public int substeps() { return shared.substeps(); }
    public double dt() { return shared.timestep(); }
    public boolean mullerCorrection() { return shared.mullerCorrection(); }
    public SolverType solverType() { return shared.solver(); }
    public boolean windOn() { return windOn; }
    public double windSpeed() { return windSpeed; }
    public double windAngle() { return windAngle; }
    public String message() { return message; }
    public boolean messageIsError() { return messageIsError; }

    /** The family the material keys act on, or null for all. */
    public ConstraintFamily family() { return FAMILY_CHOICES[familyChoice]; }

    /** k and α of a family, or null if the scene does not have it. */
    public Material material(ConstraintFamily f) { return materials.get(f); }

    /** The family shown in the HUD for material values: the chosen one, or structural for "all". */
    public ConstraintFamily shownFamily() {
        ConstraintFamily f = family();
        return f == null || !materials.containsKey(f) ? ConstraintFamily.STRUCTURAL : f;
    }

    // ---- the actions the keys call ----

    public void toggleMode() {
        if (sideBySide) { say("side by side shows both: PBD left, XPBD right"); return; }
        try {
            shared = shared.withMode(shared.mode() == ConstraintMode.PBD ? ConstraintMode.XPBD : ConstraintMode.PBD);
        } catch (IllegalArgumentException refused) { // the engine's rule: PBD needs Gauss–Seidel
            error("PBD runs on Gauss-Seidel only (its k is defined per projection): press v for gauss-seidel first");
            return;
        }
        applyAll();
        say("mode " + shared.mode());
    }

    public void toggleMuller() {
        shared = shared.withMullerCorrection(!shared.mullerCorrection());
        applyAll();
        say(shared.mullerCorrection() ? "PBD: Müller's k' = 1-(1-k)^(1/n)" : "PBD: raw k every sweep");
    }

    /** Gauss–Seidel → Jacobi-PCG → multigrid-PCG → Gauss–Seidel, for the running scenes. */
    public void cycleSolver() {
        String unchanged = ", which needs Gauss-Seidel: the solver is unchanged (press m for XPBD)";
        // Side by side, the left cloth is PBD whatever the shared mode.
        if (sideBySide) { error("side by side runs PBD on the left" + unchanged); return; }
        SolverType[] all = SolverType.values();
        SolverType next = all[(shared.solver().ordinal() + 1) % all.length];
        if (refusedAsTooMuchWork(shared.iterations(), shared.substeps(), next, "solver " + next.label())) return;
        try {
            shared = shared.withSolver(next);
        } catch (IllegalArgumentException refused) { // the engine's rule: a global solve needs XPBD
            error("PBD mode" + unchanged);
            return;
        }
        applyAll();
        SolverType now = shared.solver();
        say("solver " + now.label() + (now == SolverType.GAUSS_SEIDEL ? ""
                : now == SolverType.VERTEX_BLOCK_DESCENT ? ": each iteration is one Newton step per particle; the rest is the material's at any sweep count"
                : ": each iteration is one global Newton step; contacts stay Gauss-Seidel"));
    }

    public void changeIterations(int delta) {
        int next = (int) Limits.ITERATIONS.clamp(shared.iterations() + delta);
        if (refusedAsTooMuchWork(next, shared.substeps(), shared.solver(), next + " iterations")) return;
        shared = shared.withIterations(next);
        applyAll();
    }

    public void changeSubsteps(int delta) {
        int next = (int) Limits.SUBSTEPS.clamp(shared.substeps() + delta);
        if (refusedAsTooMuchWork(shared.iterations(), next, shared.solver(), next + " substeps")) return;
        shared = shared.withSubsteps(next);
        applyAll();
    }

    /**
     * The presets' work limit ({@link Limits#workProblem}) for the running cloths: a key that would ask
     * more of a step than a preset may (a 512² cloth switched to a global solver would take minutes a
     * step and freeze the window) is refused with a notice, and nothing changes.
     */
    private boolean refusedAsTooMuchWork(int iterations, int substeps, SolverType solver, String what) {
        for (Scene s : running()) {
            long particles = s.cloth().particles().count();
            if (Limits.workProblem(particles, iterations, substeps, s.simulation().colliderCount(), solver.isGlobal()) == null) continue;
            error(what + " would ask too much of a step for " + particles + " particles (the presets' work limit): unchanged");
            return true;
        }
        return false;
    }

    public void cycleTimestep() {
        int next = 0;
        for (int i = 0; i < TIMESTEPS.length; i++) if (Math.abs(TIMESTEPS[i] - shared.timestep()) < 1e-12) next = (i + 1) % TIMESTEPS.length;
        shared = shared.withTimestep(TIMESTEPS[next]);
        applyAll();
        say(String.format("dt = 1/%.0f s", 1 / shared.timestep()));
    }

    public void cycleFamily() {
        familyChoice = (familyChoice + 1) % FAMILY_CHOICES.length;
        say("keys k/K and a/A act on " + (family() == null ? "all families" : family().name().toLowerCase()));
    }

    /** PBD stiffness ± 0.05, clamped to [0, 1], for the chosen family or all. */
    public void changeStiffness(int direction) {
        forChosen(m -> new Material(Math.max(0, Math.min(1, Math.round((m.stiffness + direction * STIFFNESS_STEP) * 1000) / 1000.0)), m.compliance));
    }

    /** XPBD compliance ×/÷ √10; below 1e-10 m/N it becomes 0 (hard), and up from 0 starts at 1e-10. */
    public void changeCompliance(int direction) {
        forChosen(m -> {
            double a = m.compliance;
            if (direction > 0) a = a == 0 ? MIN_COMPLIANCE : Math.min(MAX_COMPLIANCE, a * COMPLIANCE_FACTOR);
            else a = a / COMPLIANCE_FACTOR < MIN_COMPLIANCE ? 0 : a / COMPLIANCE_FACTOR;
            return new Material(m.stiffness, a);
        });
    }

    private void forChosen(java.util.function.UnaryOperator<Material> change) {
        if (materials.isEmpty()) {
            error("this cloth is a fabric (" + (fabric == null ? "no spring families" : fabric.name)
                    + "): k and α belong to spring families, and it has none; F changes its fabric");
            return;
        }
        ConstraintFamily f = family();
        materials.replaceAll((family, m) -> f == null || family == f ? change.apply(m) : m);
        applyAll();
    }

    /** The running cloth becomes the catalogue's next fabric (no reset); a cloth of springs says it has none. */
    public void cycleFabric() {
        if (fabric == null) {
            error("this cloth is springs, not a fabric: F works on the fabric scenes (fabric, flag-fabric) and presets with a \"fabric\" block");
            return;
        }
        fabric = FabricCatalogue.after(fabric);
        applyAll();
        say(String.format(java.util.Locale.ROOT, "fabric %s (%s): %.0f / %.0f N/m, %.0f g/m²", fabric.name, fabric.description,
                fabric.membrane.warpModulus, fabric.membrane.weftModulus, 1000 * fabric.arealDensity));
    }

    /**
     * Pumps gas into (direction > 0) or out of the running closed cloths, ×1.25 or ÷1.25 a press (a held volume
     * grows or shrinks the same), within a thousand times the preset's amount (a held volume, its ratio's range).
     */
    public void inflate(int direction) {
        xpbdcloth.engine.EnclosedGas gas = running().get(0).gas();
        if (gas == null) {
            error("this cloth encloses nothing: j/J work on a closed cloth with a \"pressure\" block (pillow, balloon)");
            return;
        }
        double factor = direction > 0 ? 1.25 : 1 / 1.25;
        boolean changed = false;
        for (Scene s : running()) changed |= s.inflate(factor);
        if (!changed) error("the gas is at its " + (direction > 0 ? "most" : "least") + ": the keys pump within a thousand times the preset's amount (a held volume, within its ratios 0.01 to 100)");
        else if (gas.isGas()) say(String.format(java.util.Locale.ROOT, "gas nRT %.4g J: %.4g kPa at the rest volume", gas.amount(), gas.amount() / gas.restVolume() / 1000));
        else say(String.format(java.util.Locale.ROOT, "held volume %.4g L (%.2f × rest)", 1000 * gas.targetVolume(), gas.targetVolume() / gas.restVolume()));
    }

    /** The breaking strain's multiples of the preset's that the y key steps through. */
    static final double[] BREAKING_FACTORS = {1, 1.5, 2, 0.5, 0.75};

    /**
     * Steps the running cloths' breaking strain to the next of {@link #BREAKING_FACTORS} times the preset's,
     * live: edges are checked against it from the next step. A cloth whose fabric has no breaking strain says so.
     */
    public void cycleBreakingStrain() {
        xpbdcloth.engine.BreakingEdges first = running().get(0).breaking();
        if (first == null) {
            error("this cloth does not tear: y works on a fabric with a \"breakingStrain\" (tear, rip)");
            return;
        }
        double own = preset.fabric.breakingStrain;
        int now = 0;
        for (int k = 0; k < BREAKING_FACTORS.length; k++)
            if (Math.abs(first.breakingStrain() - BREAKING_FACTORS[k] * own) < 1e-9 * own) now = k;
        double next = Math.max(Limits.BREAKING_STRAIN.lo, Math.min(Limits.BREAKING_STRAIN.hi, BREAKING_FACTORS[(now + 1) % BREAKING_FACTORS.length] * own));
        for (Scene s : running()) if (s.breaking() != null) s.breaking().setBreakingStrain(next);
        say(String.format(java.util.Locale.ROOT, "breaking strain %.3g: an edge stretched %.1f %% tears", next, 100 * next));
    }

    /** The running cloth's breaking strain; NaN for a cloth that does not tear. */
    public double breakingStrain() {
        xpbdcloth.engine.BreakingEdges b = running().get(0).breaking();
        return b == null ? Double.NaN : b.breakingStrain();
    }

    /** The gas's nRT (J), or the held volume (m³); NaN for a cloth that encloses nothing. */
    public double gasAmount() {
        xpbdcloth.engine.EnclosedGas gas = running().get(0).gas();
        return gas == null ? Double.NaN : gas.isGas() ? gas.amount() : gas.targetVolume();
    }

    /**
     * The running cloths become the named catalogue fabric (no reset), for code (the library's
     * {@code ClothView.fabric}); an unknown name or a cloth of springs is refused by name.
     */
    public void useFabric(String name) {
        Fabric next = FabricCatalogue.named(name);
        if (next == null)
            throw new IllegalArgumentException("fabric must be one of " + String.join(", ", FabricCatalogue.names()) + ", was \"" + name + "\"");
        if (fabric == null) throw new IllegalArgumentException("fabric: this cloth is springs, not a fabric; load a scene with a \"fabric\" block (fabric, flag-fabric)");
        fabric = next;
        applyAll();
    }

    /** The fabric the cloths are now, or null for cloths of springs. */
    public Fabric fabric() { return fabric; }

    public void selectScene(int index) {
        List<String> names = PresetLoader.BUILT_IN;
        if (index < 0 || index >= names.size()) return;
        use(PresetLoader.builtIn(names.get(index)));
        say("scene " + preset.name);
    }

    public void reset() {
        use(preset);
        say("reset " + preset.name);
    }

    /**
     * Loads a preset file. A broken file leaves the running scene exactly as it was and shows the
     * loader's message (file, field, problem). Returns whether it loaded.
     */
    public boolean load(Path file) {
        try {
            use(PresetLoader.load(file));
            say("loaded " + file);
            return true;
        } catch (PresetException e) {
            error(e.getMessage());
            return false;
        } catch (IllegalArgumentException e) {
            error(file + ": " + e.getMessage());
            return false;
        }
    }

    /** The running fit (p), or null. */
    LiveFit fit() { return fit; }

    /**
     * Starts fitting the running cloth's spring compliances to an observed rest shape (an OBJ in the
     * scene's vertex order), from the α it has now; one iteration runs each frame ({@link #advanceFit}).
     * A file that is not an observation of this scene is refused with its reason and changes nothing.
     */
    public boolean startFit(Path obj) {
        if (sideBySide) { error("fit: one cloth at a time; b leaves side by side"); return false; }
        if (mode() != ConstraintMode.XPBD) { error("fit: a fit finds XPBD's compliance α; m switches to XPBD"); return false; }
        try {
            double[] observed = xpbdcloth.fit.Observation.read(obj, main);
            fit = new LiveFit(preset, materials, observed, obj.getFileName().toString());
            say("fitting " + fitted() + " to " + obj.getFileName() + ": one iteration a frame, the observation drawn as a ghost");
            return true;
        } catch (xpbdcloth.fit.FitException | IllegalArgumentException e) {
            error(e.getMessage());
            return false;
        }
    }

    /** One iteration of the running fit; when it ends, the running cloth takes the fitted compliances. */
    public void advanceFit() {
        if (fit == null || fit.finished) return;
        try {
            if (fit.iterate()) return;
        } catch (xpbdcloth.fit.FitException e) {
            fit.finished = true;
            error("fit stopped: " + e.getMessage());
            return;
        }
        double[] alpha = fit.fit.compliance();
        for (int f = 0; f < alpha.length; f++) {
            double fitted = alpha[f];
            materials.computeIfPresent(fit.fit.families().get(f), (family, m) -> new Material(m.stiffness, fitted));
        }
        applyAll();
        say(String.format(java.util.Locale.ROOT, "%s after %d iterations, RMS %.3f mm: the cloth now has %s",
                fit.fit.converged() ? "fitted" : "fit not converged", fit.fit.last().index, 1e3 * fit.fit.last().rms, fitted()));
    }

    private String fitted() {
        StringBuilder b = new StringBuilder();
        for (ConstraintFamily f : LiveFit.SPRINGS)
            if (materials.containsKey(f)) b.append(b.length() == 0 ? "" : ", ").append(f.name().toLowerCase(java.util.Locale.ROOT))
                    .append(String.format(java.util.Locale.ROOT, " α %.3g", materials.get(f).compliance));
        return b.toString();
    }

    public void toggleSideBySide() {
        if (sideBySide) closeRunning();
        sideBySide = !sideBySide;
        if (sideBySide) buildPair();
        else { left = right = null; }
        applyAll();
        say(sideBySide ? "side by side: PBD left, XPBD right, same n and dt" : "single scene");
    }

    public void togglePause() { paused = !paused; }

    private boolean selfCollisionOn;
    private boolean continuousOn;
    private boolean pointTriangleOn;

    /**
     * Self-collision off, then particle pairs (the cloth keeps its thickness from itself), then pairs and
     * point–triangle contacts (each vertex kept from the faces too), then pairs and the continuous triangle
     * guard (no triangle passes through another in a substep; slowest), then off again; no reset.
     */
    public void cycleSelfCollision() {
        if (!selfCollisionOn) { selfCollisionOn = true; pointTriangleOn = false; continuousOn = false; }
        else if (!pointTriangleOn && !continuousOn) pointTriangleOn = true;
        else if (!continuousOn) { pointTriangleOn = false; continuousOn = true; }
        else { selfCollisionOn = false; continuousOn = false; }
        applyAll();
        say(!selfCollisionOn ? "self-collision off"
                : String.format(java.util.Locale.ROOT, "self-collision on: thickness %.1f mm, %s", 1000 * selfCollisionSpec().thickness,
                        continuousOn ? "particle pairs and the continuous triangle guard (slower)"
                                : pointTriangleOn ? "particle pairs and point-triangle contacts" : "particle pairs"));
    }

    /** What z has chosen: off, particle pairs, pairs and point–triangle contacts, or pairs and the continuous guard. */
    public String selfCollisionState() {
        return !selfCollisionOn ? "off" : continuousOn ? "continuous" : pointTriangleOn ? "point-triangle" : "particle pairs";
    }

    /** The preset's self-collision (its untangling too), or half the cloth's shortest edge with layers' friction 0.3 / 0.2; the guard and point–triangle contacts as the keys set them. */
    Preset.SelfCollisionSpec selfCollisionSpec() {
        Preset.SelfCollisionSpec p = preset.selfCollision;
        return p != null ? new Preset.SelfCollisionSpec(p.thickness, p.staticFriction, p.kineticFriction, continuousOn, p.untangle, pointTriangleOn)
                : new Preset.SelfCollisionSpec(0.5 * preset.cloth.shortestEdge(), 0.3, 0.2, continuousOn, false, pointTriangleOn);
    }

    public boolean paused() { return paused; }

    /** Whether a single step was asked for while paused ('n'). */
    public boolean stepRequested() { return pendingSteps > 0; }

    /** Draw the cloth as a wireframe coloured by strain instead of shaded. */
    public void wireframe(boolean on) { wireframe = on; }

    public void requestStep() { pendingSteps++; paused = true; }

    public void toggleWind() {
        windOn = !windOn;
        applyAll();
    }

    public void rotateWind() {
        windAngle = (windAngle + Math.PI / 4) % (2 * Math.PI);
        applyAll();
    }

    public void changeWindSpeed(int direction) {
        windSpeed = Math.max(0, Math.min(20, windSpeed + direction * 0.5));
        applyAll();
    }

    /** Advances the running scenes by one step each, unless paused (a requested single step still runs). */
    public boolean advance() {
        if (paused && pendingSteps == 0) return false;
        if (pendingSteps > 0) pendingSteps--;
        boolean tore = false;
        try {
            // A scene whose cloth tore goes on as the scene cut there (Scene.step): same state, new topology.
            // Each side's scene is kept as soon as its step returns: a torn scene's old simulation is closed, so
            // if the other side's step then throws, the sketch must already hold the cut one.
            if (sideBySide) {
                Scene l = left.step();
                tore = l != left;
                left = l;
                Scene r = right.step();
                tore |= r != right;
                right = r;
            } else {
                Scene m = main.step();
                tore = m != main;
                main = m;
            }
        } catch (RuntimeException e) {
            // The engine has already put the scene back as it was before the step (a SimulationDivergedException,
            // whatever the step threw); anything else still must not close the sketch: stop there and say why.
            paused = true;
            pendingSteps = 0;
            if (tore) applyAll();
            error("paused: " + e.getMessage());
            return false;
        }
        if (tore) applyAll();  // the keys' settings, materials, wind and contacts on the cut scene too
        warnIfTearing();
        try {
            String ended = tore && usd.on() ? usd.stop("the cloth tore, and a recording holds one topology") : usd.afterStep(running().get(0));
            if (ended != null) say(ended);
        } catch (java.io.IOException | RuntimeException e) {
            usdFailed(e);
        }
        return true;
    }

    /** Whether the R key asked for a USD recording to start or stop since the last call (and clears the request). */
    public boolean takeUsdRequest() {
        boolean asked = usdRequested;
        usdRequested = false;
        return asked;
    }

    /** The name a USD recording of the running scene gets: the preset and the simulated time it starts at. */
    public String usdFileName() {
        return String.format(java.util.Locale.ROOT, "xpbd-cloth-%s-t%.2f.usda", preset().name, first().time());
    }

    /** Whether a USD recording runs, and its frames so far. */
    public boolean recordingUsd() { return usd.on(); }
    public int usdFrames() { return usd.frames(); }

    /**
     * Starts recording the running scene (the left one side by side) as USD into file, or, when one runs,
     * ends it and writes the file. Says which; a file that cannot be written is a red notice, the scene runs on.
     */
    public void toggleUsd(java.nio.file.Path file) {
        try {
            if (usd.on()) {
                say(usd.stop(null));
            } else {
                usd.start(file, running().get(0));
                say("recording USD into " + file + " (R again ends it and writes the file)");
            }
        } catch (java.io.IOException | RuntimeException e) {
            usdFailed(e);
        }
    }

    /** Ends a USD recording that runs (the sketch closing), writing its file. */
    public void stopUsd() {
        try {
            String m = usd.stop("the sketch closed");
            if (m != null) say(m);
        } catch (java.io.IOException | RuntimeException e) {
            usdFailed(e);
        }
    }

    private void usdFailed(Exception e) {
        error("USD recording stopped: " + e.getMessage());
        try {
            usd.stop(null);
        } catch (java.io.IOException | RuntimeException again) {
            // the first failure is the one to say
        }
    }

    /** Above this structural strain the cloth is no longer cloth: the solver cannot hold it at these settings. */
    static final double TEARING_STRAIN = 1.0;
    private int stepsSinceTearCheck;
    private boolean tearingSaid;

    /**
     * Says once per scene when a cloth stretches past {@link #TEARING_STRAIN}: Gauss–Seidel carries a
     * stiff cloth's weight to its pins only as far as its sweeps reach, so a big cloth hanging from two
     * corners pulls apart there (docs/solvers.md, "What a big cloth needs"). The notice says what helps:
     * more sweeps while the work limit allows them, pins along an edge, or a smaller cloth.
     */
    private void warnIfTearing() {
        if (tearingSaid || ++stepsSinceTearCheck < 30) return;
        stepsSinceTearCheck = 0;
        for (Scene s : running()) {
            if (s.breaking() != null) continue; // it is meant to tear, and does, at its breaking strain
            double strain = xpbdcloth.engine.Metrics.maxClothStrain(s.simulation());
            if (strain > TEARING_STRAIN) {
                tearingSaid = true;
                int particles = s.cloth().particles().count();
                error(String.format(java.util.Locale.ROOT, "the cloth stretches %.0f %%: %d sweeps x %d substeps cannot hold %d particles; %s",
                        100 * strain, shared.iterations(), shared.substeps(), particles,
                        tearingAdvice(particles, shared.iterations(), shared.substeps(), s.simulation().colliderCount(), shared.solver())));
                return;
            }
        }
    }

    /** What helps a tearing cloth: more sweeps while twice as many stay within the work limit, else pins or size. */
    static String tearingAdvice(long particles, int iterations, int substeps, int spheres, SolverType solver) {
        boolean moreAllowed = Limits.workProblem(particles, 2 * iterations, substeps, spheres, solver.isGlobal()) == null;
        return moreAllowed ? "press u or i for more, pin an edge instead of corners, or load a smaller cloth"
                : "the work limit allows no more sweeps: pin an edge instead of corners, or load a smaller cloth";
    }

    /** Seconds of simulated time of the first running scene. */
    /** World offset along x of running scene i: the pair stands side by side, PBD on the left. */
    public double offsetX(int i) {
        if (!sideBySide()) return 0;
        Preset.Cloth c = preset().cloth;
        double width = c.isMesh() ? c.mesh.max(0) - c.mesh.min(0) : c.width;
        double gap = Math.max(width, 0.6) * 0.65 + 0.15;
        for (Preset.SphereSpec s : preset().spheres) gap = Math.max(gap, s.radius * 2.2);
        return i == 0 ? -gap : gap;
    }

    public double time() { return running().get(0).simulation().time(); }

    public Simulation first() { return running().get(0).simulation(); }

    void say(String m) { message = m; messageIsError = false; }

    void error(String m) { message = m; messageIsError = true; }
}
