package xpbdcloth.sketch;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.Material;

/**
 * The one table of keys: the key handler dispatches through it and the help overlay and README list it.
 * Upper case is the same letter with Shift and goes the other way (down instead of up).
 */
public final class KeyBindings {
    private KeyBindings() {}

    private static final List<KeyBinding> ALL = build();

    public static List<KeyBinding> all() { return ALL; }

    /** The binding for a typed character, or null. */
    public static KeyBinding forKey(char key) {
        for (KeyBinding b : ALL) if (b.key == key) return b;
        return null;
    }

    /**
     * The table as the help and the README list it: a key and its capital that do the same thing both ways
     * share a line ("i/I", "iterations +1; -1"); every other key is a line of its own.
     */
    public static List<HelpLine> helpLines() {
        List<HelpLine> lines = new ArrayList<>();
        for (int i = 0; i < ALL.size(); i++) {
            KeyBinding k = ALL.get(i), next = i + 1 < ALL.size() ? ALL.get(i + 1) : null;
            String shared = next == null || next.key != Character.toUpperCase(k.key) || next.key == k.key ? "" : sharedWords(k.help, next.help);
            if (shared.isEmpty()) lines.add(new HelpLine(List.of(k.key), k.help));
            else {
                lines.add(new HelpLine(List.of(k.key, next.key), k.help + "; " + next.help.substring(shared.length())));
                i++;
            }
        }
        return Collections.unmodifiableList(lines);
    }

    /** One line of the key help: its keys (one, or a key and its capital) and what they do. */
    public static final class HelpLine {
        public final List<Character> keys;
        public final String help;

        HelpLine(List<Character> keys, String help) {
            this.keys = keys;
            this.help = help;
        }

        /** The keys as the help overlay writes them: "i/I", "space". */
        public String keyLabel() {
            StringBuilder b = new StringBuilder();
            for (char k : keys) b.append(b.length() == 0 ? "" : "/").append(k == ' ' ? "space" : String.valueOf(k));
            return b.toString();
        }
    }

    /** The whole words two help texts begin with alike ("iterations " of "iterations +1" and "iterations -1"), or "". */
    static String sharedWords(String a, String b) {
        int end = 0;
        for (int i = 0; i < Math.min(a.length(), b.length()) && a.charAt(i) == b.charAt(i); i++)
            if (a.charAt(i) == ' ') end = i + 1;
        return a.substring(0, end);
    }

    /** The key of built-in scene i: 1–9, then 0 for the tenth. */
    public static char sceneKey(int i) {
        if (i < 0 || i > 9) throw new IllegalArgumentException("scene index must be in [0, 9] to have a key, was " + i);
        return i < 9 ? (char) ('1' + i) : '0';
    }

    private static Object material(SketchState s) {
        List<Object> out = new ArrayList<>();
        for (ConstraintFamily f : new ConstraintFamily[] {ConstraintFamily.STRUCTURAL, ConstraintFamily.SHEAR, ConstraintFamily.BEND})
            out.add(s.material(f) == null ? null : s.material(f).toString());
        return out;
    }

    private static List<KeyBinding> build() {
        List<KeyBinding> b = new ArrayList<>();
        b.add(new KeyBinding('m', "PBD <-> XPBD for the running scene (no reset; a fabric keeps its compliances)", SketchState::toggleMode, SketchState::mode));
        b.add(new KeyBinding('c', "Müller's k' correction on/off (PBD)", SketchState::toggleMuller, SketchState::mullerCorrection));
        b.add(new KeyBinding('v', "solver: Gauss-Seidel, Jacobi-PCG, multigrid-PCG, vertex block descent", SketchState::cycleSolver, SketchState::solverType));
        b.add(new KeyBinding('i', "iterations +1", s -> s.changeIterations(1), SketchState::iterations));
        b.add(new KeyBinding('I', "iterations -1", s -> s.changeIterations(-1), SketchState::iterations));
        b.add(new KeyBinding('u', "substeps +1", s -> s.changeSubsteps(1), SketchState::substeps));
        b.add(new KeyBinding('U', "substeps -1", s -> s.changeSubsteps(-1), SketchState::substeps));
        b.add(new KeyBinding('t', "timestep: 1/30, 1/50, 1/60, 1/120 s", SketchState::cycleTimestep, SketchState::dt));
        b.add(new KeyBinding('f', "family for k/a keys: all, structural, shear, bend", SketchState::cycleFamily, SketchState::family));
        b.add(new KeyBinding('k', "stiffness k +0.05 (PBD)", s -> s.changeStiffness(1), KeyBindings::material));
        b.add(new KeyBinding('K', "stiffness k -0.05 (PBD)", s -> s.changeStiffness(-1), KeyBindings::material));
        b.add(new KeyBinding('a', "compliance alpha x sqrt(10) (XPBD, softer)", s -> s.changeCompliance(1), KeyBindings::material));
        b.add(new KeyBinding('A', "compliance alpha / sqrt(10) (XPBD, stiffer)", s -> s.changeCompliance(-1), KeyBindings::material));
        b.add(new KeyBinding('F', "fabric: the next measured one (no reset)", SketchState::cycleFabric, s -> s.fabric() == null ? null : s.fabric().name));
        b.add(new KeyBinding('j', "gas in x1.25 (pillow, balloon)", s -> s.inflate(1), SketchState::gasAmount));
        b.add(new KeyBinding('J', "gas out /1.25", s -> s.inflate(-1), SketchState::gasAmount));
        b.add(new KeyBinding('y', "breaking strain: x1, x1.5, x2, x0.5, x0.75 the preset's (tear, rip)", SketchState::cycleBreakingStrain, SketchState::breakingStrain));
        b.add(new KeyBinding('b', "side by side: PBD left, XPBD right", SketchState::toggleSideBySide, SketchState::sideBySide));
        // Ten scenes have keys; the others load with --scene or 'l'.
        for (int i = 0; i < Math.min(10, xpbdcloth.scene.PresetLoader.BUILT_IN.size()); i++) {
            final int scene = i;
            b.add(new KeyBinding(sceneKey(i), "scene: " + xpbdcloth.scene.PresetLoader.BUILT_IN.get(i),
                    s -> s.selectScene(scene), s -> s.preset().name));
        }
        b.add(new KeyBinding('r', "reset the scene", SketchState::reset, SketchState::time));
        b.add(new KeyBinding('l', "load a preset file (a broken one keeps this scene)", s -> s.loadRequested = true, s -> s.loadRequested));
        b.add(new KeyBinding('p', "fit: load an observed rest shape (OBJ) and fit the compliances to it live", s -> s.fitRequested = true, s -> s.fitRequested));
        b.add(new KeyBinding('O', "write the cloth's current shape as an OBJ file", s -> s.exportRequested = true, s -> s.exportRequested));
        b.add(new KeyBinding('R', "record the scene as USD (.usda) / stop and write the file", s -> s.usdRequested = true, s -> s.usdRequested));
        b.add(new KeyBinding(' ', "pause / run", SketchState::togglePause, s -> s.paused));
        b.add(new KeyBinding('n', "single step (pauses)", SketchState::requestStep, s -> s.pendingSteps));
        b.add(new KeyBinding('w', "wind on/off", SketchState::toggleWind, SketchState::windOn));
        b.add(new KeyBinding('d', "wind direction +45°", SketchState::rotateWind, SketchState::windAngle));
        b.add(new KeyBinding('e', "wind speed +0.5 m/s", s -> s.changeWindSpeed(1), SketchState::windSpeed));
        b.add(new KeyBinding('E', "wind speed -0.5 m/s", s -> s.changeWindSpeed(-1), SketchState::windSpeed));
        b.add(new KeyBinding('z', "self-collision: off, pairs, + point-triangle, + guard", SketchState::cycleSelfCollision, SketchState::selfCollisionState));
        b.add(new KeyBinding('x', "wireframe coloured by strain", s -> s.wireframe = !s.wireframe, s -> s.wireframe));
        b.add(new KeyBinding('o', "particles and contacts (red)", s -> s.showParticles = !s.showParticles, s -> s.showParticles));
        b.add(new KeyBinding('s', "spheres", s -> s.showSpheres = !s.showSpheres, s -> s.showSpheres));
        b.add(new KeyBinding('g', "ground: floor, grid and shadows", s -> s.showGrid = !s.showGrid, s -> s.showGrid));
        b.add(new KeyBinding('h', "this help", s -> s.showHelp = !s.showHelp, s -> s.showHelp));
        b.add(new KeyBinding('q', "quit (as closing the window does)", s -> s.quitRequested = true, s -> s.quitRequested));
        return Collections.unmodifiableList(b);
    }
}
