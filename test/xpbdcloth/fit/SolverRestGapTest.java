package xpbdcloth.fit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import xpbdcloth.scene.Preset;
import xpbdcloth.scene.PresetLoader;

/**
 * A static fit assumes the observed shape is the energy's minimum; the simulator at the drape's step with 10 × 20
 * sweeps rests millimetres from it (Gauss–Seidel stops short), so the fit says so, with the number, and finds the
 * substeps at which the simulator's rest comes within the tolerance: the gap shrinks as the substep does.
 */
@Tag("slow")
class SolverRestGapTest {
    @Test
    void anUnconvergedSolveIsMeasuredAndTheSubstepsThatConvergeItAreFound() throws Exception {
        String text = Files.readString(Path.of("data/drape.json")).replace("\"iterations\": 10, \"substeps\": 5", "\"iterations\": 20, \"substeps\": 10");
        Preset preset = PresetLoader.parse("drape-20-sweeps.json", text);
        double tolerance = 1e-4;
        SolverRestGap gap = SolverRestGap.of(preset, tolerance);
        assertTrue(gap.atOwnSettings > 10 * tolerance, "10 substeps × 20 sweeps rest " + gap.atOwnSettings + " m from the equilibrium");
        assertFalse(gap.withinAtOwnSettings());
        assertTrue(gap.substepsWithin >= 20 && gap.substepsWithin <= 160, "substeps found: " + gap.substepsWithin);
        assertTrue(gap.gapWithin <= tolerance && gap.gapWithin < gap.atOwnSettings / 10, "the gap at " + gap.substepsWithin + " substeps: " + gap.gapWithin + " m");
        String said = gap.say(5e-4);
        assertTrue(said.startsWith("note: at its own settings (dt 20.00 ms, 10 substeps × 20 sweeps) the simulator rests "), said);
        assertTrue(said.contains(String.format(java.util.Locale.ROOT, "At %d substeps it rests", gap.substepsWithin)), said);
        // A converged rest at the scene's own settings: within the tolerance there, said as such.
        SolverRestGap loose = SolverRestGap.of(preset, 2 * gap.atOwnSettings);
        assertTrue(loose.withinAtOwnSettings());
        assertEquals(gap.atOwnSettings, loose.atOwnSettings, 1e-12, "the same simulation measured twice");
    }
}
