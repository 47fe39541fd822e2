package xpbdcloth.sketch;

import java.util.List;
import java.util.Locale;
import processing.core.PConstants;
import processing.core.PGraphics;
import xpbdcloth.mesh.TriangleIntersections;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.Material;
import xpbdcloth.engine.Metrics;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.StepBalance;
import xpbdcloth.fabric.Fabric;
import xpbdcloth.scene.Preset;
import xpbdcloth.scene.Scene;

/** The heads-up display: parameters, timings, strain and energy, live plots, help, side-by-side labels. */
final class Hud {
    static final int PLOT_W = 260, PLOT_H = 60;

    /** Per running scene: max strain (%) and kinetic energy (J) over the last seconds. */
    final History[] strain = {new History(300), new History(300)};
    final History[] kinetic = {new History(300), new History(300)};

    void record(List<Scene> running) {
        for (int i = 0; i < running.size() && i < 2; i++) {
            Simulation sim = running.get(i).simulation();
            strain[i].add(100 * Metrics.maxClothStrain(sim));
            kinetic[i].add(Metrics.kineticEnergy(sim.particles()));
        }
    }

    void clear() {
        for (History h : strain) h.clear();
        for (History h : kinetic) h.clear();
    }

    static String fmt(String f, Object... a) { return String.format(Locale.ROOT, f, a); }

    /** "name numbers;  name numbers" for each fabric a garment is cut from. */
    static String eachFabric(java.util.List<Fabric> fabrics, java.util.function.Function<Fabric, String> numbers) {
        java.util.StringJoiner out = new java.util.StringJoiner(";  ");
        for (Fabric f : fabrics) out.add(f.name + " " + numbers.apply(f));
        return out.toString();
    }

    /** The text lines, formatted a few times a second rather than every frame: formatting allocates. */
    private String[] lines = new String[0];
    private int framesSinceFormat = Integer.MAX_VALUE;
    private SketchState formattedFor;
    static final int FORMAT_EVERY = 10;

    /**
     * Draws the panels. While recording, the wall-clock timings are left out (they differ from run to
     * run), so recorded frames are byte-identical between runs.
     */
    void draw(PGraphics g, SketchState s, double simMs, double renderMs, double bytesPerFrame, double fps, boolean slowMotion, boolean recording) {
        if (++framesSinceFormat >= FORMAT_EVERY || formattedFor != s || s.message() != lastMessage) {
            lines = format(s, simMs, renderMs, bytesPerFrame, fps, slowMotion, recording);
            framesSinceFormat = 0;
            formattedFor = s;
            lastMessage = s.message();
        }
        drawLines(g, s);
    }

    private String lastMessage;

    /**
     * The worst particle's force imbalance in the step's own equation as a fraction of its weight
     * ({@link StepBalance}): under {@link StepBalance#CONVERGED} the shape is the material's, over it the solver's.
     */
    static String balance(Simulation sim) {
        return StepBalance.verdict(sim.balance());
    }

    /** Whether the simulation keeps up with the clock: a step's cost against the time it simulates. */
    static String realTime(double stepMs, double dtMs, boolean slowMotion) {
        return stepMs <= dtMs && !slowMotion ? "real time" : fmt("%.1f× slower than real time%s", stepMs / dtMs, slowMotion ? ", SLOW MOTION" : "");
    }

    private static double kPrime(SketchState s, double k) { return s.mullerCorrection() ? 1 - Math.pow(1 - k, 1.0 / s.iterations()) : k; }

    private String[] format(SketchState s, double simMs, double renderMs, double bytesPerFrame, double fps, boolean slowMotion, boolean recording) {
        List<Scene> running = s.running();
        Simulation sim = running.get(0).simulation();
        ConstraintFamily fam = s.shownFamily();
        Material km = s.material(fam);
        String famName = s.family() == null ? "all (showing " + fam.name().toLowerCase(Locale.ROOT) + ")" : fam.name().toLowerCase(Locale.ROOT);
        Fabric fabric = s.fabric();
        // A garment of several fabrics: each one's numbers, not only the first panel's.
        java.util.List<Fabric> cut = running.get(0).fabrics();
        boolean tethered = s.preset().fabric != null && s.preset().fabric.tethers;
        int constraints = 0;
        for (Scene sc : running) constraints += sc.simulation().constraintCount();
        String[] lines = {
                s.preset().name + "  —  " + (s.sideBySide() ? "side by side: PBD | XPBD" : s.mode().toString()) + (s.paused ? "   [paused]" : ""),
                fmt("iterations %d   substeps %d   dt 1/%.0f s (%.1f ms)", s.iterations(), s.substeps(), 1 / s.dt(), 1000 * s.dt()),
                fmt("solver %s%s   %s%s", s.solverType().label(), sim.solverInUse() == null || sim.solverInUse() == s.solverType() ? ""
                                : " (solved by " + sim.solverInUse().label() + ": it has no gas term)", balance(sim),
                        sim.profile().lastPcgIterations() > 0 ? fmt("   CG iterations %d", sim.profile().lastPcgIterations()) : ""),
                km == null ? (running.get(0).cutFrom() != null ? fmt("fabrics %s   (F: all one fabric)", running.get(0).cutFrom())
                        : fmt("fabric %s%s%s   (F: next fabric)", fabric == null ? "(none)" : fabric.name, fabric == null || fabric.description.isEmpty() ? "" : " — " + fabric.description,
                        tethered ? ", tethered" : "") + (Double.isNaN(s.breakingStrain()) ? "" : fmt(", tears past %.1f %% (y)", 100 * s.breakingStrain())))
                        : fmt("family %s", famName),
                km == null ? (fabric == null ? "" : cut.size() > 1 ? "  membrane warp / weft / shear N/m: " + eachFabric(cut, f -> fmt("%.0f / %.0f / %.0f", f.membrane.warpModulus, f.membrane.weftModulus, f.membrane.shearModulus))
                        : fmt("  membrane warp %.0f N/m  weft %.0f N/m  ν12 %.2f  shear %.0f N/m", fabric.membrane.warpModulus,
                        fabric.membrane.weftModulus, fabric.membrane.poisson, fabric.membrane.shearModulus))
                        : fmt("  PBD  k %.2f  →  k' %.4f %s", km.stiffness, kPrime(s, km.stiffness), s.mullerCorrection() ? "(Müller, n=" + s.iterations() + ")" : "(raw k)"),
                km == null ? (fabric == null ? "" : cut.size() > 1 ? "  bending N·m, g/m²: " + eachFabric(cut, f -> fmt("%.1e, %.0f", f.bendingStiffness, 1000 * f.arealDensity)) + ", " + running.get(0).bendingModel()
                        : fmt("  bending %.1e N·m, %s%s", fabric.bendingStiffness, running.get(0).bendingModel(),
                        Double.isNaN(fabric.arealDensity) ? "" : fmt("   %.0f g/m²", 1000 * fabric.arealDensity)))
                        : fmt("  XPBD α %.2e m/N  →  1/α %s", km.compliance, km.compliance == 0 ? "infinite (hard)" : fmt("%.2e N/m", 1 / km.compliance)),
                recording ? fmt("recording: %.4g frames per simulated second (wall-clock timings not drawn)", 1 / (xpbdcloth.scene.ObjExport.stepsPerFrame(s.dt()) * s.dt()))
                        : fmt("step %.1f ms for %.0f ms of motion (%s)   render %.1f ms   %.0f fps   %.1f kB allocated/frame", simMs, 1000 * s.dt(),
                        realTime(simMs, 1000 * s.dt(), slowMotion), renderMs, fps, bytesPerFrame / 1024),
                fmt("particles %d   constraints %d   contacts %d touching of %d%s%s%s", sim.particles().count() * running.size(), constraints,
                        sim.profile().touchingContacts(), sim.profile().contactCount(), pinched(sim), crossingsText(running.get(0)), recording ? "" : fmt("   contacts %.2f ms, constraints %.2f ms", sim.profile().contactMs(), sim.profile().constraintSolveMs())),
                (s.sideBySide() ? "strain: under each cloth" : fmt("strain mean %.2f %%  max %.2f %%",
                        100 * Metrics.meanClothStrain(sim), 100 * Metrics.maxClothStrain(sim)))
                        + fmt("   KE %.2e J", Metrics.kineticEnergy(sim.particles()))
                        + (fabric != null ? "   (strain: the membrane's largest principal stretch)"
                                : fmt("   max link force %.3f N%s", Metrics.maxForce(sim, ConstraintFamily.STRUCTURAL), s.sideBySide() ? " (PBD)" : "")),
                (s.windOn() ? fmt("wind %.1f m/s towards %.0f°", s.windSpeed(), Math.toDegrees(s.windAngle())) : "wind off")
                        + (s.recordingUsd() ? fmt("   USD recording: %d frames (R ends it)", s.usdFrames()) : "")
                        + (sim.selfCollision() == null ? "   self-collision off" : fmt("   self-collision %.1f mm, %d pairs near", 1000 * sim.selfCollision().thickness(), sim.selfCollision().pairCount()))
                        + (sim.selfCollision() == null || sim.selfCollision().guard() == null ? "" : fmt(", continuous (%d cut-backs)", sim.selfCollision().guard().events()))
                        + gas(running.get(0).gas(), sim),
                s.showHelp ? "h: hide the keys" : "h: keys   q: quit",
        };
        LiveFit fit = s.fit();
        if (fit == null) return lines;
        StringBuilder f = new StringBuilder(fmt("fit to %s: iteration %d   RMS %.3f mm  ", fit.source, fit.fit.last().index, 1e3 * fit.fit.last().rms));
        for (int k = 0; k < fit.fit.families().size(); k++)
            f.append(fmt("  %s α %.3g", fit.fit.families().get(k).name().toLowerCase(Locale.ROOT), fit.fit.last().compliance[k]));
        f.append(fit.finished ? (fit.fit.converged() ? "   converged" : "   stopped") : "");
        String[] with = java.util.Arrays.copyOf(lines, lines.length + 1);
        with[lines.length] = lines[lines.length - 1];
        with[lines.length - 1] = f.toString();
        return with;
    }

    private HudLayout layout;
    private float charWidth = -1;
    private String[] laidLines;
    private String laidMessage;
    private boolean laidHelp, laidLegend;
    private int laidLabelChars;

    /** The layout, recomputed only when what it depends on changes (it allocates). */
    private HudLayout layout(PGraphics g, SketchState s, String[] labels) {
        if (charWidth < 0) charWidth = g.textWidth("M");
        int labelChars = labels == null ? -1 : HudLayout.steps(labels[0].length()) * 1000 + HudLayout.steps(labels[1].length());
        if (layout == null || layout.width != g.width || layout.height != g.height || laidLines != lines || laidMessage != s.message()
                || laidHelp != s.showHelp || laidLegend != s.wireframe || laidLabelChars != labelChars) {
            int longest = 0;
            for (String line : lines) longest = Math.max(longest, line.length());
            layout = new HudLayout(g.width, g.height, charWidth, lines.length, longest, s.message().length(),
                    labels == null ? null : new int[] {labels[0].length(), labels[1].length()}, s.wireframe,
                    s.showHelp ? HELP_TEXTS : null, HELP_HEADINGS);
            laidLines = lines;
            laidMessage = s.message();
            laidHelp = s.showHelp;
            laidLegend = s.wireframe;
            laidLabelChars = labelChars;
        }
        return layout;
    }

    private void drawLines(PGraphics g, SketchState s) {
        List<Scene> running = s.running();
        String[] labels = s.sideBySide() ? labels(s, running) : null;
        HudLayout l = layout(g, s, labels);
        g.textAlign(PConstants.LEFT, PConstants.TOP);
        if (l.help != null) { help(g, l); return; }
        g.noStroke();
        g.fill(0, 150);
        g.rect(l.panel.x, l.panel.y, l.panel.w, l.panel.h, 6);
        g.fill(235);
        for (int i = 0; i < lines.length; i++) g.text(HudLayout.cut(lines[i], l.panelChars), l.panel.x + HudLayout.PAD, l.panel.y + 6 + HudLayout.LINE * i);
        if (l.noticeY >= 0) {
            if (s.messageIsError()) g.fill(255, 110, 100);
            else g.fill(170, 230, 170);
            g.text(HudLayout.cut(s.message(), l.panelChars), l.panel.x + HudLayout.PAD, l.noticeY);
        }

        plot(g, l.strainPlot.x + 4, l.strainPlot.y + 18, "max strain %", strain, running.size());
        if (s.fit() != null) plot(g, l.energyPlot.x + 4, l.energyPlot.y + 18, "fit: loss as RMS to the observation, mm", s.fit().plotted, 1);
        else plot(g, l.energyPlot.x + 4, l.energyPlot.y + 18, "kinetic energy J", kinetic, running.size());

        if (labels != null) {
            g.noStroke();
            for (int i = 0; i < 2; i++) {
                HudLayout.Rect r = l.labels[i];
                g.fill(0, 150);
                g.rect(r.x, r.y, r.w, r.h, 6);
                g.fill(i == 0 ? 255 : 170, i == 0 ? 200 : 220, i == 0 ? 120 : 255);
                g.text(HudLayout.cut(labels[i], (int) ((r.w - 20) / charWidth)), r.x + 10, r.y + 4);
            }
        }
        if (l.legend != null) legend(g, l.legend);
    }

    /** The side-by-side labels: each cloth's material and its strain. */
    private static String[] labels(SketchState s, List<Scene> running) {
        Material km = s.material(s.shownFamily());
        String[] out = new String[2];
        for (int i = 0; i < 2; i++) {
            Simulation si = running.get(i).simulation();
            out[i] = (i == 0 ? "left: PBD  k " + fmt("%.2f", km.stiffness) : "right: XPBD  α " + fmt("%.1e", km.compliance))
                    + fmt("   strain mean %.2f %%  max %.2f %%", 100 * Metrics.meanClothStrain(si), 100 * Metrics.maxClothStrain(si));
        }
        return out;
    }

    private final float[] rgb = new float[3];

    /** The wireframe's colour scale: blue compressed, white at rest, red stretched, full at ±FULL_COLOUR_STRAIN. */
    private void legend(PGraphics g, HudLayout.Rect r) {
        g.noStroke();
        g.fill(0, 150);
        g.rect(r.x, r.y, r.w, r.h, 6);
        float x0 = r.x + 10, w = r.w - 20, y = r.y + 6;
        for (int k = 0; k < (int) w; k++) {
            double strain = (2.0 * k / (w - 1) - 1) * ClothRenderer.FULL_COLOUR_STRAIN;
            ClothRenderer.strainColour(strain, rgb);
            g.fill(rgb[0], rgb[1], rgb[2]);
            g.rect(x0 + k, y, 1, 12);
        }
        g.fill(230);
        int pct = (int) Math.round(100 * ClothRenderer.FULL_COLOUR_STRAIN);
        g.textAlign(PConstants.LEFT, PConstants.TOP);
        g.text("-" + pct + " %", x0, y + 16);
        g.textAlign(PConstants.CENTER, PConstants.TOP);
        g.text("strain 0", x0 + w / 2, y + 16);
        g.textAlign(PConstants.RIGHT, PConstants.TOP);
        g.text("+" + pct + " %", x0 + w, y + 16);
        g.textAlign(PConstants.LEFT, PConstants.TOP);
    }

    private void plot(PGraphics g, float x, float y, String title, History[] h, int series) {
        g.noStroke();
        g.fill(0, 150);
        g.rect(x - 4, y - 18, PLOT_W + 8, PLOT_H + 22, 6);
        float max = 1e-12f;
        for (int i = 0; i < series; i++) max = Math.max(max, h[i].max());
        g.fill(220);
        g.textAlign(PConstants.LEFT, PConstants.TOP);
        g.text(title + fmt("  (top %.3g)", max), x, y - 16);
        g.noFill();
        for (int i = 0; i < series; i++) {
            if (series == 2) g.stroke(i == 0 ? 255 : 170, i == 0 ? 200 : 220, i == 0 ? 120 : 255);
            else g.stroke(120, 220, 255);
            g.strokeWeight(1.5f);
            g.beginShape();
            for (int k = 0; k < h[i].size(); k++)
                g.vertex(x + PLOT_W * k / (float) (h[i].capacity() - 1), y + PLOT_H - PLOT_H * h[i].get(k) / max);
            g.endShape();
        }
    }

    static final int HELP_KEY_CHARS = 7;
    static final String[] MOUSE_HELP = {"left-drag  rotate", "right-drag / wheel  zoom", "middle-drag (Meta+left)  pan",
            "Shift+drag  lock axis", "double-click  reset view", "Ctrl+left-drag  grab the cloth"};

    /** The help's texts in order (headings, the key table, a blank, the mouse), and which are headings. */
    static final String[] HELP_TEXTS;
    static final boolean[] HELP_HEADINGS;
    static {
        List<String> texts = new java.util.ArrayList<>();
        texts.add("keys (h hides this)");
        for (KeyBindings.HelpLine line : KeyBindings.helpLines()) {
            String key = line.keyLabel();
            texts.add(key + "       ".substring(key.length()) + line.help);
        }
        texts.add("");
        texts.add("mouse");
        java.util.Collections.addAll(texts, MOUSE_HELP);
        HELP_TEXTS = texts.toArray(new String[0]);
        HELP_HEADINGS = new boolean[HELP_TEXTS.length];
        HELP_HEADINGS[0] = true;
        HELP_HEADINGS[texts.indexOf("mouse")] = true;
    }

    /** The keys and mouse controls, in the columns the layout chose, long lines wrapped. */
    private void help(PGraphics g, HudLayout l) {
        g.noStroke();
        g.fill(0, 185);
        g.rect(l.help.x, l.help.y, l.help.w, l.help.h, 6);
        float columnW = l.help.w / l.helpColumns;
        for (int i = 0; i < HELP_TEXTS.length; i++) {
            if (l.helpRowOf[i] < 0) continue; // a blank line at a column's top is left out
            if (HELP_HEADINGS[i]) g.fill(255, 220, 140);
            else g.fill(230);
            List<String> rows = l.helpWrapped.get(i);
            for (int k = 0; k < rows.size(); k++)
                g.text(rows.get(k), l.help.x + l.helpColumnOf[i] * columnW + HudLayout.PAD, l.help.y + 6 + HudLayout.HELP_LINE * (l.helpRowOf[i] + k));
        }
    }

    /**
     * The held and crossing counts' text, counted every {@link #CROSSINGS_EVERY} formats: a crossing count costs
     * milliseconds on the shipped cloths (measured in docs/contacts.md), and the held count a millisecond on the
     * drape tester's clamped ring over its pedestal mesh: too much for every frame.
     */
    private String crossings = "";
    private int formatsSinceCrossings = Integer.MAX_VALUE;
    private xpbdcloth.scene.Scene crossingsCountedFor;
    static final int CROSSINGS_EVERY = 3;

    private String crossingsText(xpbdcloth.scene.Scene scene) {
        if (++formatsSinceCrossings >= CROSSINGS_EVERY || scene != crossingsCountedFor) {
            crossings = held(scene.simulation()) + crossings(scene);
            formatsSinceCrossings = 0;
            crossingsCountedFor = scene;
        }
        return crossings;
    }

    /**
     * ", N crossing triangle pairs": how many pairs of the cloth's triangles pass through each other now
     * ({@link TriangleIntersections}, the measure self-collision must hold at 0); nothing for a rope.
     */
    static String crossings(xpbdcloth.scene.Scene scene) {
        if (scene.cloth().triangles().length == 0) return "";
        return fmt(", %d crossing triangle pairs", scene.crossingPairs());
    }

    /** The gas inside a closed cloth: its pressure over the air and its volume (j/J pump it), or nothing. */
    static String gas(xpbdcloth.engine.EnclosedGas gas, Simulation sim) {
        if (gas == null) return "";
        double v = gas.volume(sim.particles());
        // A gas's pressure is its law's at the volume it has (what a gauge would read); a held volume's, the push holding it.
        String what = gas.isGas() ? fmt("   gas %+.3g kPa over the air", (gas.amount() / v - gas.ambient()) / 1000) : fmt("   held volume, %.3g kPa to hold it", gas.pressure() / 1000);
        return what + fmt(", %.3g L (rest %.3g L)", 1000 * v, 1000 * gas.restVolume());
    }

    /** ", N pinched" when colliders have closed on particles and one had to give (they are inside it), else nothing. */
    static String pinched(Simulation sim) {
        int n = sim.profile().pinchedParticles();
        return n == 0 ? "" : fmt(", %d pinched inside a collider", n);
    }

    /**
     * ", N held inside a collider" when a pin or a grab holds cloth inside a solid, where the two fight through the
     * cloth (Simulation.heldInsideColliders), else nothing.
     */
    static String held(Simulation sim) {
        int n = sim.heldInsideColliders();
        return n == 0 ? "" : fmt(", %d held inside a collider", n);
    }
}
