package xpbdcloth.usd;

import static org.junit.jupiter.api.Assertions.*;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import xpbdcloth.engine.Box;

/**
 * The recording opens in Pixar's own USD library (usd-core, in the project's .venv that
 * {@code scripts/deps --headless} makes): no warning on opening, none of the library's validators
 * objects, the cloth's counts and topology hold, its points at three time codes are the simulation's to
 * 1e-6 m, every collider's local-to-world transform as USD composes it (the box's scale included) is the
 * engine's pose, and the texture coordinates have one value per face corner. A stage corrupted two ways is
 * caught by the same reader, so the check can fail.
 */
class PixarReadsRecordingTest {
    static final Path PYTHON = Path.of(".venv/bin/python");

    @Test
    void pixarsReaderSeesTheSimulation(@TempDir Path dir) throws Exception {
        UsdRecordingTest.Recorded rec = new UsdRecordingTest.Recorded(dir);
        Read read = read(rec.file);
        assertEquals("", read.stderr, "opening and reading the stage says nothing on standard error");
        JsonNode s = read.json;
        assertFalse(s.has("error"), () -> s.get("error").asText());
        assertTrue(s.get("validators").asInt() >= 10, "the library's validators ran");
        assertEquals(0, s.get("validationErrors").size(), () -> s.get("validationErrors").toString());
        assertEquals("Y", s.get("upAxis").asText());
        assertEquals(1.0, s.get("metersPerUnit").asDouble());
        assertEquals(50.0, s.get("timeCodesPerSecond").asDouble());
        assertEquals(50.0, s.get("framesPerSecond").asDouble());
        assertEquals(0.0, s.get("startTimeCode").asDouble());
        assertEquals(UsdRecordingTest.FRAMES, s.get("endTimeCode").asDouble());
        assertEquals("/World", s.get("defaultPrim").asText());

        JsonNode cloth = s.get("prims").get("/World/Cloth");
        assertEquals("Mesh", cloth.get("type").asText());
        assertEquals(13 * 9, cloth.get("faces").asInt());
        assertEquals(4 * 13 * 9, cloth.get("corners").asInt());
        assertEquals(rec.scene.cloth().particles().count(), cloth.get("points").asInt());
        assertTrue(cloth.get("topologyValid").asBoolean(), cloth.get("topologyProblem").asText());
        assertEquals(UsdRecordingTest.FRAMES + 1, cloth.get("pointSampleCount").asInt());
        assertEquals(4 * 13 * 9, cloth.get("st").get("count").asInt(), "one texture coordinate per face corner");
        assertEquals("faceVarying", cloth.get("st").get("interpolation").asText());
        assertEquals("vertex", cloth.get("normals").get("interpolation").asText());
        assertEquals("denim", cloth.get("custom").get("xpbd:fabric:name").asText());
        for (int k = 0; k < UsdRecordingTest.CHECKED.length; k++) {
            JsonNode points = cloth.get("pointsAt").get(code(k));
            double[] expected = rec.positions[k];
            assertEquals(expected.length / 3, points.size());
            for (int i = 0; i < expected.length; i++)
                assertEquals(expected[i], points.get(i / 3).get(i % 3).asDouble(), 1e-6, "time code " + code(k) + ", coordinate " + i);
        }

        Box box = (Box) rec.scene.simulation().solids().get(0);
        double[] scale = {box.halfExtentX(), box.halfExtentY(), box.halfExtentZ()};
        String[] colliders = {"/World/Sphere0", "/World/Box0", "/World/Capsule0"};
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < UsdRecordingTest.CHECKED.length; k++) {
                double[] m = rec.poses[k][j].clone();
                if (j == 1) for (int row = 0; row < 3; row++) for (int col = 0; col < 3; col++) m[4 * row + col] *= scale[row]; // p S M: S scales M's rows
                JsonNode t = s.get("prims").get(colliders[j]).get("transformAt").get(code(k));
                for (int i = 0; i < 16; i++)
                    assertEquals(m[i], t.get(i / 4).get(i % 4).asDouble(), 1e-6, colliders[j] + " at time code " + code(k) + ", entry " + i);
            }
        // The convention pinned from outside: the capsule's local (0, L, 0), through USD's p M, is its centre plus L along the preset's axis (1, 1, 0)/√2.
        JsonNode capsule = s.get("prims").get("/World/Capsule0").get("transformAt").get(code(2));
        double half = 0.2, c = half / Math.sqrt(2);
        double[] centre = {rec.poses[2][2][12], rec.poses[2][2][13], rec.poses[2][2][14]};
        for (int col = 0; col < 3; col++)
            assertEquals(centre[col] + (col < 2 ? c : 0), half * capsule.get(1).get(col).asDouble() + capsule.get(3).get(col).asDouble(), 1e-9, "axis end, " + "xyz".charAt(col));
        assertEquals("Capsule", s.get("prims").get("/World/Capsule0").get("type").asText());
        assertEquals("Cube", s.get("prims").get("/World/Box0").get("type").asText());
        assertEquals("Sphere", s.get("prims").get("/World/Sphere0").get("type").asText());
    }

    @Test
    void aCorruptedStageIsCaught(@TempDir Path dir) throws Exception {
        UsdRecordingTest.Recorded rec = new UsdRecordingTest.Recorded(dir);
        String text = Files.readString(rec.file, StandardCharsets.UTF_8);

        Path counts = dir.resolve("counts.usda");
        Files.writeString(counts, text.replaceFirst("faceVertexCounts = \\[4, ", "faceVertexCounts = [5, "));
        JsonNode topology = read(counts).json.get("prims").get("/World/Cloth");
        assertFalse(topology.get("topologyValid").asBoolean(), "a face count that does not add up to the indices is invalid topology");

        Path cut = dir.resolve("cut.usda");
        Files.writeString(cut, text.substring(0, text.lastIndexOf('}')));
        Read unclosed = read(cut);
        assertTrue(unclosed.json.has("error"), "a stage cut short does not open: " + unclosed.json);
    }

    private static String code(int k) { return UsdRecordingTest.CHECKED[k] + ".0"; }

    static final class Read {
        final JsonNode json;
        final String stderr;

        Read(JsonNode json, String stderr) { this.json = json; this.stderr = stderr; }
    }

    static Read read(Path file) throws IOException, InterruptedException {
        assertTrue(Files.isExecutable(PYTHON), "Pixar's USD library is not installed: run scripts/deps --headless (it makes .venv with usd-core)");
        List<String> cmd = new ArrayList<>(List.of(PYTHON.toString(), "scripts/usd_read.py", file.toString()));
        for (int c : UsdRecordingTest.CHECKED) cmd.add(String.valueOf(c));
        Path err = Files.createTempFile("usd-read", ".err");
        Process p = new ProcessBuilder(cmd).redirectError(err.toFile()).start();
        byte[] out = p.getInputStream().readAllBytes();
        assertEquals(0, p.waitFor(), () -> "usd_read.py failed: " + readQuietly(err));
        String stderr = Files.readString(err);
        Files.delete(err);
        return new Read(new ObjectMapper().readTree(out), stderr);
    }

    private static String readQuietly(Path p) {
        try { return Files.readString(p); } catch (IOException e) { return e.getMessage(); }
    }
}
