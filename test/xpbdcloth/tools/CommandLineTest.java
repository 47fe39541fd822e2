package xpbdcloth.tools;

import static org.junit.jupiter.api.Assertions.*;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/** The command line as a new user types it: options in the wrong place are an error, not ignored. */
class CommandLineTest {

    static String refusal(String... args) {
        CommandLine cli = new CommandLine(new Main());
        StringWriter err = new StringWriter();
        cli.setErr(new PrintWriter(err, true));
        return Main.optionsBeforeCommand(cli, args) ? err.toString() : null;
    }

    @Test
    void optionsBeforeTheCommandAreRefusedWithTheFix() {
        String says = refusal("--scene", "rope", "record", "--frames", "2");
        assertNotNull(says, "refused");
        assertTrue(says.contains("--scene is written before 'record'"), says);
        assertTrue(says.contains("xpbd-cloth record --scene rope ..."), says);
        assertNotNull(refusal("--size", "0x0", "record"));
    }

    /** `check` validates presets headless: ok lines, the problem for a broken one, exit code 2. */
    @Test
    void checkReportsEachPreset(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir) throws Exception {
        java.nio.file.Path bad = java.nio.file.Files.writeString(dir.resolve("bad.json"), "{ \"name\": \"x\" } trailing");
        CommandLine cli = new CommandLine(new Main());
        StringWriter out = new StringWriter();
        cli.setOut(new PrintWriter(out, true));
        assertEquals(0, cli.execute("check", "hanging", "flag"));
        assertTrue(out.toString().contains("hanging: ok (1024 particles"), out.toString());
        assertTrue(out.toString().contains("flag: ok (622 particles"), out.toString());
        StringWriter err = new StringWriter();
        cli.setErr(new PrintWriter(err, true));
        out.getBuffer().setLength(0);
        assertEquals(2, cli.execute("check", "hanging", bad.toString()));
        assertTrue(err.toString().contains(bad + ": (syntax): not valid JSON"), "problems go to standard error: " + err);
        assertFalse(out.toString().contains("not valid JSON"), out.toString());
        // Every problem of a file, not the first only: a broken pin and a negative compliance are both said.
        java.nio.file.Path two = java.nio.file.Files.writeString(dir.resolve("two.json"),
                "{ \"name\": \"t\", \"cloth\": { \"columns\": 4, \"rows\": 4, \"width\": 1, \"height\": 1, \"arealDensity\": 0.2, \"pins\": [\"top\"] },"
                + " \"families\": { \"structural\": { \"stiffness\": 1, \"compliance\": -1 } }, \"solver\": { \"mode\": \"XPBD\", \"iterations\": 2, \"dt\": 0.02 } }");
        err.getBuffer().setLength(0);
        assertEquals(2, cli.execute("check", two.toString()));
        assertTrue(err.toString().contains(two + ": cloth.pins[0]: must be [row, col] or one of") && err.toString().contains(two + ": families.structural.compliance: must be in"), err.toString());
        out.getBuffer().setLength(0);
        assertEquals(0, cli.execute("check", "data/fabrics.json", "data/hanging.json"), "the shipped catalogue is recognised, not refused as a scene");
        assertTrue(out.toString().contains("data/fabrics.json: ok (a fabric catalogue: 9 fabrics)"), out.toString());
    }

    /**
     * `check` says whether each scene's solve converges, against the tolerance the HUD uses: Gauss–Seidel at two
     * sweeps leaves a near-inextensible hanging cloth off balance by millions of its particles' weights; the
     * table's cloth lying on its box is balanced. A note, not a problem: the exit code stays 0.
     */
    @Test
    void checkSaysWhetherTheSolveConverged() {
        CommandLine cli = new CommandLine(new Main());
        StringWriter out = new StringWriter();
        cli.setOut(new PrintWriter(out, true));
        assertEquals(0, cli.execute("check", "--steps", "10", "hanging", "table"));
        String[] lines = out.toString().split("\\R");
        assertTrue(lines[1].startsWith("  after 10 steps: NOT CONVERGED: worst particle off balance by") && lines[1].contains("converged is under 0.010"), out.toString());
        assertTrue(lines[3].startsWith("  after 10 steps: converged"), out.toString());
        out.getBuffer().setLength(0);
        assertEquals(0, cli.execute("check", "--steps", "0", "hanging"));
        assertFalse(out.toString().contains("after"), "--steps 0 builds only: " + out);
    }

    /** --help shows each option's default, and the command list says fit takes a motion too. */
    @Test
    void helpShowsTheDefaults() {
        StringWriter out = new StringWriter();
        CommandLine cli = new CommandLine(new Main());
        cli.setOut(new PrintWriter(out, true));
        assertEquals(0, cli.execute("record", "--help"));
        assertTrue(out.toString().contains("Default: 120") && out.toString().contains("Default: 1280x800") && out.toString().contains("Default: hanging"), out.toString());
        out.getBuffer().setLength(0);
        assertEquals(0, cli.execute("--help"));
        assertTrue(out.toString().contains("rest") && out.toString().contains("motion"), out.toString());
    }

    @Test
    void optionsInTheirPlaceAreFine() {
        assertNull(refusal("record", "--scene", "rope", "--frames", "2"));
        assertNull(refusal("--scene", "rope"), "options alone open the window with them");
        assertNull(refusal("bench"));
    }

    /**
     * `pattern` says when a mesh is too coarse for a seam to close, as the loader would refuse a preset sewing
     * it (exit 2, the seam named); at the pattern's own edge the T-shirt's seams close (exit 0).
     */
    @Test
    void patternSaysWhenASeamCannotClose() {
        CommandLine cli = new CommandLine(new Main());
        StringWriter out = new StringWriter(), err = new StringWriter();
        cli.setOut(new PrintWriter(out, true));
        cli.setErr(new PrintWriter(err, true));
        assertEquals(2, cli.execute("pattern", "tshirt", "--edge", "0.15"));
        assertTrue(err.toString().contains("at an edge of 0.150 m, seam \"") && err.toString().contains("would close two triangles into one"), err.toString());
        assertTrue(out.toString().contains("tshirt: 4 panels, 10 seams"), "the report is still printed: " + out);
        err.getBuffer().setLength(0);
        assertEquals(0, cli.execute("pattern", "tshirt"));
        assertEquals("", err.toString());
    }
}
