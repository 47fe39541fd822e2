package xpbdcloth.fit;

import java.util.Locale;
import xpbdcloth.scene.Preset;
import xpbdcloth.scene.Scene;

/**
 * How far the simulator's own rest, at a preset's settings, lies from the equilibrium a static fit assumes
 * (∇E = 0, {@link ClothEnergy}), and the fewest substeps at which it comes within a tolerance.
 *
 * <p>Why: a static fit matches the energy's minimum to the observed shape. A converged XPBD step rests there
 * at any dt, but a few sweeps per substep stop short of it by an amount that grows with the substep, so a
 * shape this simulator made at those settings carries that much solver error, and a fit puts it into the
 * compliances with a small residual that looks like success (measured in docs/fitting.md; the drape's gap
 * and the substeps that close it are {@code SolverRestGapTest}'s). The fit cannot tell that error from the
 * material's; it can measure how large it is at the fitted material and say so, with the settings that
 * would not have it.
 */
public final class SolverRestGap {
    /** RMS over the free particles' coordinates of the simulator's rest less the equilibrium, m, at the preset's settings. */
    public final double atOwnSettings;
    /** The fewest substeps (the preset's times a power of two, up to 16 times) whose gap is within the tolerance, or −1. */
    public final int substepsWithin;
    /** The gap at {@link #substepsWithin}, m (NaN if none was). */
    public final double gapWithin;
    private final Preset preset;

    private SolverRestGap(Preset preset, double atOwnSettings, int substepsWithin, double gapWithin) {
        this.preset = preset;
        this.atOwnSettings = atOwnSettings;
        this.substepsWithin = substepsWithin;
        this.gapWithin = gapWithin;
    }

    /** Measures the preset's gap and, if it is over {@code tolerance} (m), the substeps that bring it within. */
    public static SolverRestGap of(Preset preset, double tolerance) {
        double own = RestShape.of(Scene.of(preset)).simulatorGapRms; // a FitException if the fitted material has no stable rest
        if (own <= tolerance) return new SolverRestGap(preset, own, preset.solver.substeps(), own);
        for (int factor = 2; factor <= 16; factor *= 2) {
            Scene scene = Scene.of(preset);
            scene.simulation().settings(scene.simulation().settings().withSubsteps(preset.solver.substeps() * factor));
            double gap = RestShape.of(scene).simulatorGapRms;
            if (gap <= tolerance) return new SolverRestGap(preset, own, preset.solver.substeps() * factor, gap);
        }
        return new SolverRestGap(preset, own, -1, Double.NaN);
    }

    /** Whether the simulator at the preset's own settings rests within the tolerance it was measured against. */
    public boolean withinAtOwnSettings() { return substepsWithin == preset.solver.substeps(); }

    /** One paragraph for the fit's report. */
    public String say(double fitRms) {
        String settings = String.format(Locale.ROOT, "dt %.4g ms, %d substeps × %d sweeps", 1e3 * preset.solver.timestep(), preset.solver.substeps(), preset.solver.iterations());
        if (withinAtOwnSettings())
            return String.format(Locale.ROOT, "the simulator at its own settings (%s) rests %.4f mm (RMS) from the equilibrium this fit assumes: "
                    + "a shape it made there is the material's, and the fitted material simulated there rests where it was fitted", settings, atOwnSettings * 1e3);
        String within = substepsWithin > 0
                ? String.format(Locale.ROOT, "At %d substeps it rests %.4f mm from it.", substepsWithin, gapWithin * 1e3)
                : "No substep count up to 16 times the preset's brings it within: the solve needs more sweeps, or vertex block descent, whose rest is the equilibrium.";
        return String.format(Locale.ROOT, "note: at its own settings (%s) the simulator rests %.4f mm (RMS) from the equilibrium this fit assumes "
                + "(the fit's RMS: %.4f mm). A shape it made at those settings carries that much solver error, which a static fit puts into the "
                + "compliances; and the fitted material, simulated there, rests that far from the observation. %s", settings, atOwnSettings * 1e3, fitRms * 1e3, within);
    }
}
