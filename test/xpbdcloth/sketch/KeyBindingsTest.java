package xpbdcloth.sketch;

import static org.junit.jupiter.api.Assertions.*;

import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.scene.PresetLoader;

/** Every key in the one table changes the state it claims; the table drives the help and the handler. */
class KeyBindingsTest {

    /** A state where every key has room to act: bend family chosen (k = 0.1, α = 1e-2), stepped a little. */
    static SketchState fresh() {
        SketchState s = new SketchState(PresetLoader.builtIn("hanging"));
        s.cycleFamily(); s.cycleFamily(); s.cycleFamily(); // all -> structural -> shear -> bend
        for (int i = 0; i < 3; i++) s.advance();
        return s;
    }

    @Test
    void everyKeyChangesWhatItClaims() {
        Set<Character> seen = new HashSet<>();
        for (KeyBinding b : KeyBindings.all()) {
            assertTrue(seen.add(b.key), "key '" + b.key + "' is bound once");
            assertFalse(b.help.isBlank(), "key '" + b.key + "' has help text");
            SketchState s = fresh();
            if (b.key == '1') s.selectScene(1); // '1' selects hanging, which is already running
            if (b.key == 'F') s.selectScene(PresetLoader.BUILT_IN.indexOf("fabric")); // the fabric key needs a fabric
            if (b.key == 'j' || b.key == 'J') s.selectScene(PresetLoader.BUILT_IN.indexOf("balloon")); // the gas keys need a gas
            if (b.key == 'y') s.selectScene(PresetLoader.BUILT_IN.indexOf("tear")); // the breaking strain needs a cloth that tears
            Object before = b.observe(s);
            b.press(s);
            Object after = b.observe(s);
            assertNotEquals(before, after, "key '" + b.key + "' (" + b.help + ") changes its state");
            assertSame(b, KeyBindings.forKey(b.key), "the handler finds the binding");
        }
    }

    /** The README's key table lists every line of the help (a key and its capital on one row), with the same text. */
    @Test
    void readmeListsEveryKey() throws Exception {
        String readme = java.nio.file.Files.readString(java.nio.file.Path.of("README.md"));
        int listed = 0;
        for (KeyBindings.HelpLine line : KeyBindings.helpLines()) {
            if (Character.isDigit(line.keys.get(0))) continue; // listed as one row, 1–N
            String keys = "`" + line.keyLabel().replace("/", "` / `") + "`";
            assertTrue(readme.contains("| " + keys + " | " + line.help + " |"), "README lists " + keys);
            listed += line.keys.size();
        }
        long digits = KeyBindings.all().stream().filter(b -> Character.isDigit(b.key)).count();
        assertEquals(KeyBindings.all().size(), listed + digits, "every key is on one of the README's rows");
        java.util.List<String> keyed = xpbdcloth.scene.PresetLoader.BUILT_IN.subList(0, Math.min(10, xpbdcloth.scene.PresetLoader.BUILT_IN.size()));
        String keys = keyed.size() <= 9 ? "`1`–`" + keyed.size() + "`" : "`1`–`9`, `0`";
        assertTrue(readme.contains("| " + keys + " | scenes: " + String.join(", ", keyed) + " |"), "README's scene keys row");
    }

    @Test
    void modeToggleKeepsTheRunningScene() {
        SketchState s = fresh();
        var sim = s.first();
        double y = sim.particles().y(500);
        KeyBindings.forKey('m').press(s);
        assertSame(sim, s.first(), "no reset");
        assertEquals(y, sim.particles().y(500), 0.0);
        assertEquals(ConstraintMode.PBD, sim.settings().mode());
    }

    @Test
    void timestepCycleCoversTheFrameRateTrap() {
        SketchState s = fresh();
        Set<Double> dts = new HashSet<>();
        for (int i = 0; i < 4; i++) { KeyBindings.forKey('t').press(s); dts.add(s.dt()); assertEquals(s.dt(), s.first().settings().timestep(), 0.0); }
        assertEquals(Set.of(1 / 30.0, 1 / 50.0, 1 / 60.0, 1 / 120.0), dts);
    }

    @Test
    void complianceKeysMoveHalfADecadeAndReachTheSimulation() {
        SketchState s = fresh();
        KeyBindings.forKey('a').press(s);
        assertEquals(1e-2 * Math.sqrt(10), s.material(ConstraintFamily.BEND).compliance, 1e-15);
        for (var c : s.first().constraints())
            if (c.family() == ConstraintFamily.BEND) assertEquals(1e-2 * Math.sqrt(10), c.compliance(), 1e-15);
        assertEquals(1e-6, s.material(ConstraintFamily.STRUCTURAL).compliance, 0.0, "other families untouched");
    }

    @Test
    void sideBySideRunsPbdLeftXpbdRightInLockstep() {
        SketchState s = fresh();
        KeyBindings.forKey('b').press(s);
        assertEquals(2, s.running().size());
        assertEquals(ConstraintMode.PBD, s.running().get(0).simulation().settings().mode());
        assertEquals(ConstraintMode.XPBD, s.running().get(1).simulation().settings().mode());
        KeyBindings.forKey('i').press(s);
        s.advance();
        for (var sc : s.running()) {
            assertEquals(s.iterations(), sc.simulation().settings().iterations());
            assertEquals(s.first().stepCount(), sc.simulation().stepCount(), "lockstep");
        }
    }

    @Test
    void brokenPresetKeepsTheRunningScene(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir) throws Exception {
        SketchState s = fresh();
        var before = s.first();
        double[] positions = before.particles().positions().clone();
        var bad = java.nio.file.Files.writeString(dir.resolve("bad.json"), "{ \"name\": 3 }");
        assertFalse(s.load(bad));
        assertSame(before, s.first(), "the same simulation keeps running");
        assertArrayEquals(positions, before.particles().positions(), 0.0, "untouched, bit for bit");
        assertTrue(s.messageIsError());
        assertTrue(s.message().contains("bad.json: name: must be a string"), s.message());
        s.advance();
        assertEquals(4, before.stepCount());
    }
}
