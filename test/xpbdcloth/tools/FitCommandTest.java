package xpbdcloth.tools;

import static org.junit.jupiter.api.Assertions.*;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.scene.Preset;
import xpbdcloth.scene.PresetLoader;

/** `xpbd-cloth fit` as a user runs it: make an observation, fit it from a tenth of α*, load what it wrote. */
@Tag("slow")
class FitCommandTest {
    final StringWriter out = new StringWriter(), err = new StringWriter();

    int run(String... args) {
        CommandLine cli = new CommandLine(new Main());
        cli.setOut(new PrintWriter(out, true));
        cli.setErr(new PrintWriter(err, true));
        return cli.execute(args);
    }

    /** A trajectory has at most Trajectory.MAX_FRAMES frames: a million is refused at once, and nothing is written. */
    @Test
    void frameCountsAreBounded(@TempDir Path dir) throws Exception {
        Path folder = dir.resolve("motion");
        long t0 = System.nanoTime();
        assertEquals(2, run("fit", "--scene", "drape", "--make-observation", folder.toString(), "--frames", "1000000"));
        assertTrue(err.toString().contains("frames must be in [0, " + xpbdcloth.fit.Trajectory.MAX_FRAMES + "], was 1000000"), err.toString());
        assertFalse(Files.exists(folder), "nothing written");
        assertTrue((System.nanoTime() - t0) / 1e9 < 10, "refused at once");
        // Written as it is made: the folder holds every frame it says it wrote.
        assertEquals(0, run("fit", "--scene", "drape", "--make-observation", folder.toString(), "--frames", "3"), err.toString());
        try (java.util.stream.Stream<Path> files = Files.list(folder)) { assertEquals(3, files.count()); }
    }

    @Test
    void theWholeLoopRecoversTheScenesCompliancesAndWritesAPresetThatLoads(@TempDir Path dir) throws Exception {
        Path shape = dir.resolve("drape-rest.obj");
        assertEquals(0, run("fit", "--scene", "drape", "--make-observation", shape.toString()), err.toString());
        assertTrue(out.toString().contains("drape at rest"), out.toString());
        assertEquals(0, run("fit", "--scene", "drape", "--observed", shape.toString(), "--start-factor", "0.1", "--out", dir.toString()), err.toString());
        assertTrue(out.toString().contains("converged after"), out.toString());
        assertTrue(out.toString().contains("[#"), "a progress bar: " + out);
        // A fit that converged ends with a whole bar, not one that looks cut short against the iteration cap.
        String lastBar = out.toString().lines().filter(l -> l.startsWith("[")).reduce((a, b) -> b).orElseThrow();
        assertTrue(lastBar.startsWith("[" + "#".repeat(20) + "]"), lastBar);
        Preset fitted = PresetLoader.load(dir.resolve("drape-fitted.json"));
        Preset truth = PresetLoader.builtIn("drape");
        for (ConstraintFamily f : new ConstraintFamily[] {ConstraintFamily.STRUCTURAL, ConstraintFamily.SHEAR, ConstraintFamily.BEND})
            assertEquals(truth.families.get(f).compliance, fitted.families.get(f).compliance, 1e-6 * truth.families.get(f).compliance, f + " α");
        assertEquals("drape-fitted", fitted.name);
        String csv = Files.readString(dir.resolve("iterations.csv"));
        assertTrue(csv.startsWith("iteration,loss_m2,rms_m,gradient_norm,alpha_structural_m_per_N"), csv);
        assertTrue(csv.lines().count() >= 5, "a row per iteration: " + csv);
        assertTrue(Files.size(dir.resolve("fit.png")) > 10_000, "the plot is written");
    }

    /** A trajectory: 25 frames written, fitted from 0.7 × every value, damping included, back into a preset that loads. */
    @Test
    void aFolderOfFramesIsFittedDynamicallyDampingIncluded(@TempDir Path dir) throws Exception {
        Path frames = dir.resolve("drape-motion");
        assertEquals(0, run("fit", "--scene", "drape", "--make-observation", frames.toString(), "--frames", "25"), err.toString());
        assertTrue(out.toString().contains("wrote 25 frames (0.50 s of drape"), out.toString());
        assertTrue(Files.exists(frames.resolve("frame-0025.obj")));
        assertEquals(0, run("fit", "--scene", "drape", "--observed", frames.toString(), "--start-factor", "0.7", "--out", dir.toString()), err.toString());
        assertTrue(out.toString().contains("fitting structural, shear, bend, damping of drape (256 particles) to 25 frames"), out.toString());
        Preset fitted = PresetLoader.load(dir.resolve("drape-fitted.json"));
        Preset truth = PresetLoader.builtIn("drape");
        for (ConstraintFamily f : new ConstraintFamily[] {ConstraintFamily.STRUCTURAL, ConstraintFamily.SHEAR, ConstraintFamily.BEND})
            assertEquals(truth.families.get(f).compliance, fitted.families.get(f).compliance, 0.02 * truth.families.get(f).compliance, f + " α");
        assertEquals(truth.solver.damping(), fitted.solver.damping(), 0.02 * truth.solver.damping(), "damping");
        assertTrue(Files.readString(dir.resolve("iterations.csv")).lines().findFirst().orElse("").endsWith(",damping_per_s,simulations"));
        err.getBuffer().setLength(0);
        assertEquals(2, run("fit", "--scene", "drape", "--observed", dir.resolve("drape-fitted.json").toString(), "--params", "damping"));
        assertTrue(err.toString().contains("params names damping, which a rest shape does not depend on"), err.toString());
        err.getBuffer().setLength(0);
        assertEquals(2, run("fit", "--scene", "tablecloth", "--observed", frames.toString()));
        assertTrue(err.toString().contains("vertices and scene tablecloth has"), err.toString());
    }

    /**
     * The drape as measured denim, a quarter metre square (at 1 m denim's bending is too weak for its weight
     * to shape one rest: from 0.3 × α* the fit slid to another equilibrium, no bending at all, 3.9 mm RMS away):
     * the fit recovers its moduli and bending stiffness, written as a fabric of its own. Measured: 5–7
     * iterations from 0.1, 0.3 and 3 × α*; with 0.5 mm noise, 3 seeds, within 1.1 % (membrane) and 1.7 % (dihedral).
     */
    @Test
    void aFabricsModuliAreFittedAndWrittenAsItsOwnFabric(@TempDir Path dir) throws Exception {
        Path preset = dir.resolve("denim-drape.json");
        Files.writeString(preset, xpbdcloth.fit.FitScenes.DENIM_DRAPE);
        Path shape = dir.resolve("denim-rest.obj");
        assertEquals(0, run("fit", "--scene", preset.toString(), "--make-observation", shape.toString()), err.toString());
        assertEquals(0, run("fit", "--scene", preset.toString(), "--observed", shape.toString(), "--start-factor", "0.3", "--out", dir.toString()), err.toString());
        assertTrue(out.toString().contains("fitting membrane, dihedral of denim-drape"), out.toString());
        Preset fitted = PresetLoader.load(dir.resolve("denim-drape-fitted.json"));
        xpbdcloth.fabric.Fabric denim = PresetLoader.load(preset).fabric.fabric, got = fitted.fabric.fabric;
        assertEquals(denim.membrane.warpModulus, got.membrane.warpModulus, 1e-6 * denim.membrane.warpModulus);
        assertEquals(denim.membrane.weftModulus, got.membrane.weftModulus, 1e-6 * denim.membrane.weftModulus);
        assertEquals(denim.membrane.shearModulus, got.membrane.shearModulus, 1e-6 * denim.membrane.shearModulus);
        assertEquals(denim.membrane.poisson, got.membrane.poisson, 1e-12);
        assertEquals(denim.bendingStiffness, got.bendingStiffness, 1e-6 * denim.bendingStiffness);
        assertEquals(0.324, fitted.cloth.arealDensity, 1e-12, "the catalogue's areal density moved to the cloth");
        assertEquals("denim (fitted)", got.name);
    }

    @Test
    void badInputIsAMessageAndExitCodeTwo(@TempDir Path dir) throws Exception {
        Path rope = dir.resolve("rope.obj");
        assertEquals(0, run("fit", "--scene", "rope", "--make-observation", rope.toString()));
        err.getBuffer().setLength(0);
        assertEquals(2, run("fit", "--scene", "drape", "--observed", rope.toString()));
        assertTrue(err.toString().contains("vertices and scene drape has 256"), err.toString());
        err.getBuffer().setLength(0);
        Path shape = dir.resolve("d.obj");
        assertEquals(0, run("fit", "--scene", "drape", "--make-observation", shape.toString()));
        assertEquals(2, run("fit", "--scene", "drape", "--observed", shape.toString(), "--params", "structural,wind"));
        assertTrue(err.toString().contains("params must name structural, shear, bend, membrane, dihedral or (for a trajectory) damping, was wind"), err.toString());
        err.getBuffer().setLength(0);
        assertEquals(2, run("fit", "--scene", "curtain", "--observed", shape.toString(), "--params", "bend"));
        assertTrue(err.toString().contains("params names bend, which scene curtain does not have; it has structural"), err.toString());
        err.getBuffer().setLength(0);
        Files.writeString(dir.resolve("nan.obj"), Files.readString(shape).replaceFirst("\\nv [^\\n]*", "\nv nan 0 0"));
        assertEquals(2, run("fit", "--scene", "drape", "--observed", dir.resolve("nan.obj").toString()));
        assertTrue(err.toString().contains("nan.obj:2: vertex coordinate x is not a number"), err.toString());
        assertFalse(err.toString().contains("Exception"), "no stack trace: " + err);
    }

    /** A fit stopped before it converges says so, with the last loss, exits 1 and still writes its files. */
    @Test
    void aFitThatDoesNotConvergeSaysSoAndWritesWhatItHas(@TempDir Path dir) throws Exception {
        Path shape = dir.resolve("drape-rest.obj");
        assertEquals(0, run("fit", "--scene", "drape", "--make-observation", shape.toString()));
        assertEquals(1, run("fit", "--scene", "drape", "--observed", shape.toString(), "--start-factor", "10", "--max-iterations", "2", "--out", dir.toString()));
        assertTrue(out.toString().contains("did not converge in 2 iterations; last loss"), out.toString());
        assertTrue(Files.exists(dir.resolve("drape-fitted.json")) && Files.exists(dir.resolve("iterations.csv")));
    }
}
