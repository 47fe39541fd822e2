package xpbdcloth.library;

import static org.junit.jupiter.api.Assertions.*;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The library's mouse under a camera it does not own: {@link GrabProbe} sets its own eye and rotations
 * (what PeasyCam does), grabs a particle where Processing projects it, drags it 6 px a frame and lets go.
 * The right particle is taken, it stays under the pointer, and it leaves with the drag's speed. Then the
 * sketch's controls through the library's own methods reach the engine, and a bad value is refused by name.
 */
class ClothViewTest {
    @Test
    void grabsTheParticleUnderThePointerFollowsItAndThrows(@TempDir Path out) throws Exception {
        xpbdcloth.sketch.RecordingSmokeTest.requireDisplay();
        Path log = out.resolve("log.txt");
        Process p = new ProcessBuilder(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), GrabProbe.class.getName()))
                .redirectErrorStream(true).redirectOutput(log.toFile()).start();
        boolean finished = p.waitFor(120, TimeUnit.SECONDS);
        if (!finished) p.destroyForcibly();
        String text = Files.readString(log);
        assertTrue(finished && p.exitValue() == 0, "probe ran and quit; log:\n" + text);
        Map<String, String> m = new HashMap<>();
        for (String line : text.split("\n")) {
            for (String field : line.trim().split(" ")) {
                int eq = field.indexOf('=');
                if (eq > 0) m.put(field.substring(0, eq), field.substring(eq + 1));
            }
            if (line.startsWith("throw_px_per_s=")) m.put("throw_y", line.trim().split(" ")[1]);
        }
        System.out.println("ClothView grab under the sketch's camera: " + m);
        assertEquals("true", m.get("grab"), text);
        assertEquals(m.get("expected"), m.get("grabbed"), "the particle drawn under the pointer");
        double error = Double.parseDouble(m.get("follow_error_px"));
        assertTrue(error < 2, "the dragged particle stays under the pointer: " + error + " px off");
        double drag = Double.parseDouble(m.get("drag_px_per_s"));
        double vx = Double.parseDouble(m.get("throw_px_per_s")), vy = Double.parseDouble(m.get("throw_y"));
        assertEquals(drag, vx, 0.25 * drag, "thrown along the drag at its speed (px/s on screen)");
        assertTrue(Math.abs(vy) < 0.25 * drag, "not up or down the screen: " + vy + " px/s");
        assertEquals("-1", m.get("held_after_release"), "let go");
        assertEquals("7", m.get("iterations"), text);
        assertEquals("7", m.get("engine_iterations"), "the running simulation's settings");
        assertEquals("3", m.get("substeps"), text);
        assertEquals("iterations_must_be_in_[1,_1000],_was_0", m.get("refused"));
        assertEquals("true", m.get("wind"));
        assertEquals("1", m.get("forces_added"), "the wind is a force on the running simulation");
        assertEquals("2", m.get("simulations"), "side by side");
        assertEquals("PBD", m.get("left"));
        assertEquals("XPBD", m.get("right"));
        assertEquals("true", m.get("paused"));
    }

    @Test
    void aScaleThatCannotDrawIsRefusedByName() {
        // Checked before any window exists: the setter validates without touching Processing.
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> ClothView.checkedScale(0f));
        assertEquals("pixelsPerMetre must be finite and > 0, was 0.0", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> ClothView.checkedScale(Float.NaN));
        assertThrows(IllegalArgumentException.class, () -> ClothView.checkedScale(Float.POSITIVE_INFINITY));
        assertEquals(250f, ClothView.checkedScale(250f));
    }
}
