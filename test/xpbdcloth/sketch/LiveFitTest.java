package xpbdcloth.sketch;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.fit.Observation;
import xpbdcloth.fit.RestShape;
import xpbdcloth.scene.PresetLoader;
import xpbdcloth.scene.Scene;

/** The p key's fit, as the sketch runs it: one iteration a frame, then the running cloth takes the fitted α. */
class LiveFitTest {
    static final ConstraintFamily[] SPRINGS = {ConstraintFamily.STRUCTURAL, ConstraintFamily.SHEAR, ConstraintFamily.BEND};

    @Test
    void aSoftenedClothIsFittedBackToTheObservedAlphaOneIterationAFrame(@TempDir Path dir) throws Exception {
        Scene drape = Scene.builtIn("drape");
        Path obj = dir.resolve("observed.obj");
        Observation.write(obj, drape, RestShape.of(drape).positions, "test");
        SketchState s = new SketchState(PresetLoader.builtIn("drape"));
        KeyBindings.forKey('a').press(s); // every family √10 softer: the fit starts from there
        assertEquals(1e-4 * Math.sqrt(10), s.material(ConstraintFamily.STRUCTURAL).compliance, 1e-12);
        var running = s.first();
        assertTrue(s.startFit(obj), s.message());
        assertNotNull(s.fit(), "the ghost and the HUD line need the fit");
        int frames = 0;
        while (!s.fit().finished && frames < 40) { s.advanceFit(); frames++; }
        assertTrue(s.fit().fit.converged(), s.message());
        assertTrue(frames <= LiveFit.MAX_ITERATIONS, "one iteration a frame: " + frames);
        assertSame(running, s.first(), "no reset: the running cloth takes the α");
        double[] truth = {1e-4, 2e-1, 5e-2};
        for (int f = 0; f < 3; f++) {
            assertEquals(truth[f], s.material(SPRINGS[f]).compliance, 1e-6 * truth[f], SPRINGS[f] + " α in the sketch");
            ConstraintFamily family = SPRINGS[f];
            assertEquals(truth[f], running.blocks().stream().filter(b -> b.family() == family).findFirst().get().compliance(0), 1e-6 * truth[f], "and in its simulation");
        }
        assertTrue(s.message().startsWith("fitted after"), s.message());
        assertTrue(s.fit().rmsMm.size() == s.fit().fit.history().size(), "the HUD plot has a point per iteration");
    }

    @Test
    void anObservationOfAnotherSceneIsRefusedAndChangesNothing(@TempDir Path dir) throws Exception {
        Scene rope = Scene.builtIn("rope");
        Path obj = dir.resolve("rope.obj");
        Observation.write(obj, rope, rope.simulation().particles().positions(), "test");
        SketchState s = new SketchState(PresetLoader.builtIn("drape"));
        var running = s.first();
        assertFalse(s.startFit(obj));
        assertTrue(s.messageIsError() && s.message().contains("vertices and scene drape has 256"), s.message());
        assertNull(s.fit());
        assertSame(running, s.first());
        KeyBindings.forKey('m').press(s); // PBD
        Path drapeObj = dir.resolve("drape.obj");
        Observation.write(drapeObj, Scene.builtIn("drape"), Scene.builtIn("drape").simulation().particles().positions(), "test");
        assertFalse(s.startFit(drapeObj));
        assertTrue(s.message().contains("m switches to XPBD"), s.message());
    }
}
