package xpbdcloth.sketch;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.Kinematics;
import xpbdcloth.engine.Metrics;
import xpbdcloth.engine.SolverType;
import xpbdcloth.scene.FabricCatalogue;
import xpbdcloth.scene.PresetLoader;
import xpbdcloth.scene.Scene;

/** The sketch says no where the engine does, and a step that diverges pauses the scene instead of losing it. */
class SketchRefusalsTest {

    /** A 128² nearly hard cloth hanging from two corners, with the given sweeps (the "solver" entries). */
    static SketchState bigCloth(String solver) {
        String text = "{ \"name\": \"big\", \"cloth\": { \"columns\": 128, \"rows\": 128, \"width\": 1, \"height\": 1, \"arealDensity\": 0.2,"
                + " \"pins\": [\"top-left\", \"top-right\"] }, \"families\": { \"structural\": { \"stiffness\": 1, \"compliance\": 1e-8 } },"
                + " \"solver\": { \"mode\": \"XPBD\", " + solver + ", \"dt\": 0.02 } }";
        return new SketchState(PresetLoader.parse("big.json", text));
    }

    /** A cloth the solver cannot hold (128² hard, one sweep, one substep) is said to be tearing, once, with the keys. */
    @Test
    void aTearingClothIsNamed() {
        SketchState s = bigCloth("\"iterations\": 1");
        for (int i = 0; i < 90; i++) s.advance();
        assertTrue(s.messageIsError(), s.message());
        assertTrue(s.message().startsWith("the cloth stretches"), s.message());
        assertTrue(s.message().contains("press u or i for more, pin an edge instead of corners, or load a smaller cloth"), s.message());
        // 512² at 8 × 16: twice the sweeps would be over the work limit, so the notice does not offer them.
        assertTrue(SketchState.tearingAdvice(512 * 512, 8, 16, 0, SolverType.GAUSS_SEIDEL).startsWith("the work limit allows no more sweeps"));
        assertTrue(SketchState.tearingAdvice(128 * 128, 1, 1, 0, SolverType.GAUSS_SEIDEL).startsWith("press u or i for more"));
        SketchState fine = new SketchState(PresetLoader.builtIn("hanging"));
        for (int i = 0; i < 90; i++) fine.advance();
        assertFalse(fine.message().startsWith("the cloth stretches"), "the shipped hanging cloth holds: " + fine.message());
    }

    /**
     * A key may not ask more of a step than a preset may: on a 128² cloth, v (a global solver) would take
     * 14 s a step and freeze the window, and iterations stop at the work limit; each is refused with a
     * notice and nothing changes.
     */
    @Test
    void aKeyThatWouldFreezeTheWindowIsRefused() {
        SketchState s = bigCloth("\"iterations\": 900, \"substeps\": 2");
        s.cycleSolver();
        assertEquals(SolverType.GAUSS_SEIDEL, s.solverType());
        assertEquals(SolverType.GAUSS_SEIDEL, s.first().settings().solver());
        assertTrue(s.messageIsError() && s.message().startsWith("solver jacobi-pcg would ask too much of a step for 16384 particles"), s.message());
        s.changeSubsteps(+1);
        assertEquals(2, s.first().settings().substeps(), "16384 × 3 × 900 is over the limit");
        assertTrue(s.message().startsWith("3 substeps would ask too much"), s.message());
        s.changeIterations(+1); // 16384 × 2 × 901 = 29.5 M: under 2²⁵ = 33.6 M, allowed
        assertEquals(901, s.first().settings().iterations());
    }

    /** On a fabric (no spring families) the k and α keys say why they do nothing, instead of doing nothing silently. */
    @Test
    void materialKeysOnAFabricSayWhy() {
        SketchState s = new SketchState(PresetLoader.builtIn("fabric"));
        s.changeCompliance(+1);
        assertTrue(s.messageIsError(), s.message());
        assertTrue(s.message().startsWith("this cloth is a fabric (denim)"), s.message());
        s.changeStiffness(-1);
        assertTrue(s.message().contains("it has none"), s.message());
    }

    /**
     * The fabric key: on springs it says so and changes nothing; on a fabric it walks the whole catalogue
     * (every running cloth, side by side too) and comes back, the cloth running on all the while.
     */
    @Test
    void theFabricKeyCyclesTheCatalogueOrSaysWhyNot() {
        SketchState springs = new SketchState(PresetLoader.builtIn("hanging"));
        springs.cycleFabric();
        assertTrue(springs.messageIsError() && springs.message().startsWith("this cloth is springs"), springs.message());
        assertNull(springs.fabric());
        SketchState s = new SketchState(PresetLoader.builtIn("fabric"));
        s.toggleSideBySide();
        s.advance();
        double t = s.time();
        java.util.List<String> seen = new java.util.ArrayList<>();
        for (int k = 0; k < FabricCatalogue.all().size(); k++) {
            s.cycleFabric();
            seen.add(s.fabric().name);
            for (Scene sc : s.running()) assertSame(s.fabric(), sc.fabric());
        }
        assertEquals("denim", seen.get(seen.size() - 1), "back to the start after the whole catalogue");
        assertEquals(FabricCatalogue.names().size(), new java.util.HashSet<>(seen).size(), "every fabric once");
        assertEquals(t, s.time(), 0.0, "no reset");
        // By name, as the library's ClothView.fabric does: a known one is used, others are named.
        s.useFabric("swimsuit");
        for (Scene sc : s.running()) assertEquals("swimsuit", sc.fabric().name);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> s.useFabric("silk"));
        assertTrue(e.getMessage().startsWith("fabric must be one of denim, interlock") && e.getMessage().endsWith("was \"silk\""), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> springs.useFabric("denim"));
        assertTrue(e.getMessage().startsWith("fabric: this cloth is springs"), e.getMessage());
    }

    @Test
    void vInPbdModeSaysSoAndKeepsGaussSeidel() {
        SketchState s = new SketchState(PresetLoader.builtIn("hanging"));
        s.toggleMode();
        assertEquals(ConstraintMode.PBD, s.mode());
        s.cycleSolver();
        assertEquals(SolverType.GAUSS_SEIDEL, s.solverType());
        assertEquals(SolverType.GAUSS_SEIDEL, s.first().settings().solver());
        assertTrue(s.messageIsError());
        assertTrue(s.message().contains("needs Gauss-Seidel"), s.message());
    }

    @Test
    void mUnderAGlobalSolverSaysSoAndKeepsXpbd() {
        SketchState s = new SketchState(PresetLoader.builtIn("hanging"));
        s.cycleSolver();
        assertEquals(SolverType.JACOBI_PCG, s.solverType());
        s.toggleMode();
        assertEquals(ConstraintMode.XPBD, s.mode());
        assertEquals(ConstraintMode.XPBD, s.first().settings().mode());
        assertTrue(s.messageIsError());
        assertTrue(s.message().startsWith("PBD runs on Gauss-Seidel only"), s.message());
    }

    @Test
    void aDivergedStepPausesTheSceneWithARedNotice() {
        SketchState s = new SketchState(PresetLoader.builtIn("hanging"));
        for (int k = 0; k < 3; k++) assertTrue(s.advance());
        double before = s.time();
        Kinematics broken = (p, t) -> p.positions()[0] = Double.NaN; // the API refuses NaN; a bug would write the array
        s.first().add(broken);
        assertFalse(s.advance(), "the step did not happen");
        assertTrue(s.paused);
        assertTrue(s.messageIsError());
        assertTrue(s.message().contains("stage 'kinematics'"), s.message());
        assertEquals(before, s.time(), 0.0, "the clock is where it was");
        assertTrue(Metrics.allFinite(s.first().particles()), "the scene is kept, finite");
    }

    /**
     * Side by side, the left scene tears in the frame where the right one's step throws: the sketch goes on
     * with the left's cut scene (its old simulation is closed by the tear), the right one as it was.
     */
    @Test
    void aSideThatToreIsKeptWhenTheOtherSideThrowsInTheSameFrame() {
        SketchState probe = new SketchState(PresetLoader.builtIn("tear"));
        probe.toggleSideBySide();
        int whole = probe.first().particles().count(), tearFrame = -1;
        for (int i = 0; i < 300 && tearFrame < 0; i++) {
            assertTrue(probe.advance());
            if (probe.first().particles().count() > whole) tearFrame = i;
        }
        assertTrue(tearFrame >= 0, "the left side tears within 6 s");
        SketchState s = new SketchState(PresetLoader.builtIn("tear"));
        s.toggleSideBySide();
        for (int i = 0; i < tearFrame; i++) assertTrue(s.advance());
        Scene rightBefore = s.running().get(1);
        double rightTime = rightBefore.simulation().time();
        rightBefore.simulation().add((Kinematics) (p, t) -> p.positions()[0] = Double.NaN);
        assertFalse(s.advance(), "the right side's step threw");
        assertTrue(s.paused);
        assertTrue(s.first().particles().count() > whole, "the left side goes on as its cut scene");
        assertSame(rightBefore, s.running().get(1));
        assertEquals(rightTime, rightBefore.simulation().time(), 0.0, "the right side is where it was");
        assertTrue(Metrics.allFinite(s.first().particles()) && Metrics.allFinite(rightBefore.simulation().particles()));
    }
}
