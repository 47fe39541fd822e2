package xpbdcloth.sketch;

import java.util.List;
import java.util.Locale;
import processing.core.PConstants;
import processing.core.PGraphics;
import xpbdcloth.engine.Constraint;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.Metrics;
import xpbdcloth.engine.Simulation;
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
            strain[i].add(100 * Metrics.maxStrain(sim, ConstraintFamily.STRUCTURAL));
            kinetic[i].add(Metrics.kineticEnergy(sim.particles()));
        }
    }

    void clear() {
        for (History h : strain) h.clear();
        for (History h : kinetic) h.clear();
    }

    static String fmt(String f, Object... a) { return String.format(Locale.ROOT, f, a); }

    /** The largest |λ|/h² over the structural constraints: the force the stiffest link carries (N). */
    static double maxForce(Simulation sim) {
        double h = sim.settings().timestep() / sim.settings().substeps(), max = 0;
        for (Constraint c : sim.constraints()) if (c.family() == ConstraintFamily.STRUCTURAL) max = Math.max(max, c.force(h));
        return max;
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
            linesWidth = -1;
            framesSinceFormat = 0;
            formattedFor = s;
            lastMessage = s.message();
        }
        drawLines(g, s);
    }

    private String lastMessage;
    /** Widths of the text panels in pixels, measured when their text changes (-1: not yet). */
    private float linesWidth = -1, helpWidth = -1;

    private String[] format(SketchState s, double simMs, double renderMs, double bytesPerFrame, double fps, boolean slowMotion, boolean recording) {
        List<Scene> running = s.running();
        Simulation sim = running.get(0).simulation();
        ConstraintFamily fam = s.shownFamily();
        double[] km = s.material(fam);
        String famName = s.family() == null ? "all (showing " + fam.name().toLowerCase(Locale.ROOT) + ")" : fam.name().toLowerCase(Locale.ROOT);
        double kPrime = s.mullerCorrection() ? 1 - Math.pow(1 - km[0], 1.0 / s.iterations()) : km[0];
        int constraints = 0;
        for (Scene sc : running) constraints += sc.simulation().constraints().length;
        String[] lines = {
                s.preset().name + "  —  " + (s.sideBySide() ? "side by side: PBD | XPBD" : s.mode().toString()) + (s.paused ? "   [paused]" : ""),
                fmt("iterations %d   substeps %d   dt 1/%.0f s (%.1f ms)", s.iterations(), s.substeps(), 1 / s.dt(), 1000 * s.dt()),
                fmt("solver %s   residual |C + a~l| %.2e%s", s.solverType().name().toLowerCase(Locale.ROOT).replace('_', '-'), sim.residual(),
                        sim.lastPcgIterations() > 0 ? fmt("   CG iterations %d", sim.lastPcgIterations()) : ""),
                fmt("family %s", famName),
                fmt("  PBD  k %.2f  ->  k' %.4f %s", km[0], kPrime, s.mullerCorrection() ? "(Müller, n=" + s.iterations() + ")" : "(raw k)"),
                fmt("  XPBD alpha %.2e m/N  ->  1/alpha %s", km[1], km[1] == 0 ? "infinite (hard)" : fmt("%.2e N/m", 1 / km[1])),
                recording ? "recording: 60 frames per simulated second (wall-clock timings not drawn)"
                        : fmt("sim %.2f ms/step   render %.2f ms   %.0f fps   %.1f kB allocated/frame%s", simMs, renderMs, fps, bytesPerFrame / 1024,
                        slowMotion ? "   SLOW MOTION" : ""),
                fmt("particles %d   constraints %d", sim.particles().count() * running.size(), constraints),
                (s.sideBySide() ? "strain: under each cloth" : fmt("strain mean %.2f %%  max %.2f %%",
                        100 * Metrics.meanStrain(sim, ConstraintFamily.STRUCTURAL), 100 * Metrics.maxStrain(sim, ConstraintFamily.STRUCTURAL)))
                        + fmt("   KE %.2e J   max link force %.3f N%s", Metrics.kineticEnergy(sim.particles()), maxForce(sim), s.sideBySide() ? " (PBD)" : ""),
                s.windOn() ? fmt("wind %.1f m/s towards %.0f°", s.windSpeed(), Math.toDegrees(s.windAngle())) : "wind off",
                s.showHelp ? "h: hide the keys" : "h: keys   q: quit",
        };
        return lines;
    }

    private void drawLines(PGraphics g, SketchState s) {
        List<Scene> running = s.running();
        ConstraintFamily fam = s.shownFamily();
        double[] km = s.material(fam);
        g.noStroke();
        g.fill(0, 150);
        if (linesWidth < 0) {
            for (String line : lines) linesWidth = Math.max(linesWidth, g.textWidth(line));
            linesWidth = 40 * (float) Math.ceil(linesWidth / 40); // steps, so the panel does not twitch with the numbers
        }
        g.rect(8, 8, linesWidth + 16, 18 * lines.length + 12, 6);
        g.textAlign(PConstants.LEFT, PConstants.TOP);
        g.fill(235);
        for (int i = 0; i < lines.length; i++) g.text(lines[i], 16, 14 + 18 * i);
        int y = 18 * lines.length + 28;
        if (!s.message().isEmpty()) {
            g.fill(0, 150);
            g.rect(8, y - 4, Math.min(g.width - 16, g.textWidth(s.message()) + 16), 24, 6);
            if (s.messageIsError()) g.fill(255, 110, 100);
            else g.fill(170, 230, 170);
            g.text(s.message(), 16, y);
        }

        int py = g.height - 2 * (PLOT_H + 26) - 6;
        plot(g, 12, py, "max strain %", strain, running.size());
        plot(g, 12, py + PLOT_H + 26, "kinetic energy J", kinetic, running.size());

        if (s.sideBySide()) {
            g.textAlign(PConstants.CENTER, PConstants.TOP);
            for (int i = 0; i < 2; i++) {
                Simulation si = running.get(i).simulation();
                String label = (i == 0 ? "PBD  k " + fmt("%.2f", km[0]) : "XPBD  alpha " + fmt("%.1e", km[1]))
                        + fmt("   strain mean %.2f %%  max %.2f %%", 100 * Metrics.meanStrain(si, ConstraintFamily.STRUCTURAL),
                                100 * Metrics.maxStrain(si, ConstraintFamily.STRUCTURAL));
                float cx = g.width * (i == 0 ? 0.3f : 0.7f);
                g.fill(0, 150);
                g.rect(cx - g.textWidth(label) / 2 - 10, g.height - 40, g.textWidth(label) + 20, 26, 6);
                g.fill(i == 0 ? 255 : 170, i == 0 ? 200 : 220, i == 0 ? 120 : 255);
                g.text(label, cx, g.height - 36);
            }
        }
        if (s.showHelp) help(g);
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

    private void help(PGraphics g) {
        List<KeyBinding> keys = KeyBindings.all();
        String[] mouse = {"left-drag  rotate", "right-drag / wheel  zoom", "middle-drag (Meta+left)  pan",
                "Shift+drag  lock axis", "double-click  reset view", "Ctrl+left-drag  grab the cloth"};
        if (helpWidth < 0) {
            for (KeyBinding k : keys) helpWidth = Math.max(helpWidth, 50 + g.textWidth(k.help));
            for (String m : mouse) helpWidth = Math.max(helpWidth, g.textWidth(m));
        }
        int lineH = 16, h = lineH * (keys.size() + mouse.length + 3) + 12;
        float w = helpWidth + 20;
        float x = g.width - w - 10, y = 10;
        g.noStroke();
        g.fill(0, 160);
        g.rect(x, y, w, h, 6);
        g.textAlign(PConstants.LEFT, PConstants.TOP);
        g.fill(255, 220, 140);
        g.text("keys (h hides this)", x + 10, y + 6);
        g.fill(230);
        int row = 1;
        for (KeyBinding k : keys) {
            g.text((k.key == ' ' ? "space" : String.valueOf(k.key)), x + 10, y + 6 + lineH * row);
            g.text(k.help, x + 60, y + 6 + lineH * row);
            row++;
        }
        row++;
        g.fill(255, 220, 140);
        g.text("mouse", x + 10, y + 6 + lineH * row++);
        g.fill(230);
        for (String m : mouse) g.text(m, x + 10, y + 6 + lineH * row++);
    }
}
