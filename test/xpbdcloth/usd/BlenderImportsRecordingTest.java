package xpbdcloth.usd;

import static org.junit.jupiter.api.Assertions.*;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Optional: Blender (its Python module bpy 5.0.1, about 1 GB, which {@code scripts/deps --blender} puts in
 * .venv-blender) imports a recording as File → Import → USD does, and sees the animation: the cloth a mesh
 * driven by a cache whose vertices at three frames are the simulation's (in Blender's z-up frame, USD's
 * (x, y, z) is (x, −z, y)), and each collider an object that moves with the engine's pose. Skipped where
 * Blender is not installed.
 */
class BlenderImportsRecordingTest {
    static final Path BLENDER_PYTHON = Path.of(".venv-blender/bin/python");

    @Test
    void blenderSeesTheAnimation(@TempDir Path dir) throws Exception {
        Assumptions.assumeTrue(Files.isExecutable(BLENDER_PYTHON), "Blender's Python module is not installed (scripts/deps --blender)");
        UsdRecordingTest.Recorded rec = new UsdRecordingTest.Recorded(dir);
        List<String> cmd = new ArrayList<>(List.of(BLENDER_PYTHON.toString(), "scripts/blender_read.py", rec.file.toString()));
        for (int c : UsdRecordingTest.CHECKED) cmd.add(String.valueOf(c));
        Process p = new ProcessBuilder(cmd).redirectError(ProcessBuilder.Redirect.DISCARD).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(0, p.waitFor(), out);
        String line = out.lines().filter(l -> l.startsWith("BLENDER-JSON ")).findFirst().orElseThrow(() -> new AssertionError("no result: " + out));
        JsonNode b = new ObjectMapper().readTree(line.substring("BLENDER-JSON ".length()));
        assertEquals("[\"FINISHED\"]", b.get("result").toString());
        assertEquals(0, b.get("frameStart").asInt());
        assertEquals(UsdRecordingTest.FRAMES, b.get("frameEnd").asInt(), "the stage's time codes are Blender's frame range");
        JsonNode cloth = b.get("objects").get("Cloth");
        assertEquals("MESH", cloth.get("type").asText());
        assertTrue(cloth.get("modifiers").toString().contains("MESH_SEQUENCE_CACHE"), "the points are played from the file: " + cloth.get("modifiers"));
        for (int k = 0; k < UsdRecordingTest.CHECKED.length; k++) {
            JsonNode v = cloth.get("at").get(String.valueOf(UsdRecordingTest.CHECKED[k])).get("vertices");
            double[] x = rec.positions[k];
            assertEquals(x.length / 3, v.size());
            for (int i = 0; i < x.length / 3; i++) {
                assertEquals(x[3 * i], v.get(i).get(0).asDouble(), 1e-6, "frame " + UsdRecordingTest.CHECKED[k] + ", vertex " + i + ", x");
                assertEquals(-x[3 * i + 2], v.get(i).get(1).asDouble(), 1e-6, "frame " + UsdRecordingTest.CHECKED[k] + ", vertex " + i + ", Blender's y = −z");
                assertEquals(x[3 * i + 1], v.get(i).get(2).asDouble(), 1e-6, "frame " + UsdRecordingTest.CHECKED[k] + ", vertex " + i + ", Blender's z = y");
            }
        }
        String[] colliders = {"Sphere0", "Box0", "Capsule0"};
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < UsdRecordingTest.CHECKED.length; k++) {
                double[] m = rec.poses[k][j];
                JsonNode t = b.get("objects").get(colliders[j]).get("at").get(String.valueOf(UsdRecordingTest.CHECKED[k])).get("translation");
                assertEquals(m[12], t.get(0).asDouble(), 1e-5, colliders[j]);
                assertEquals(-m[14], t.get(1).asDouble(), 1e-5, colliders[j]);
                assertEquals(m[13], t.get(2).asDouble(), 1e-5, colliders[j]);
            }
    }
}
