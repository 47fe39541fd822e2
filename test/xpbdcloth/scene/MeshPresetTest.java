package xpbdcloth.scene;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import xpbdcloth.engine.Metrics;
import xpbdcloth.engine.Particles;
import xpbdcloth.mesh.ClothMesh;
import xpbdcloth.mesh.ObjReader;
import xpbdcloth.tools.ShippedMeshes;

/** Presets that name a mesh file: placement, pins by index, group and box, and every mistake named. */
class MeshPresetTest {
    static final String OBJ = "# two quads\nv 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 -1 0\nv 1 -1 0\nv 2 -1 0\n"
            + "g top\np 1 2 3\ng left\nf 1 4 5 2\ng right\nf 2 5 6 3\n";

    static String preset(String mesh, String pins) {
        return "{ \"name\": \"m\", \"cloth\": { \"mesh\": " + mesh + ", \"arealDensity\": 0.2, \"pins\": " + pins + " },"
                + " \"families\": { \"structural\": { \"stiffness\": 1, \"compliance\": 1e-6 } },"
                + " \"solver\": { \"mode\": \"XPBD\", \"iterations\": 2, \"dt\": 0.02 } }";
    }

    static Preset load(Path dir, String text) throws IOException {
        Files.writeString(dir.resolve("two.obj"), OBJ);
        Path p = dir.resolve("m.json");
        Files.writeString(p, text);
        return PresetLoader.load(p);
    }

    /** A built-in preset copied elsewhere (cp data/flag.json .) finds its shipped mesh in the jar; a missing mesh of another name is still an error. */
    @Test
    void aCopiedBuiltInPresetFindsItsMesh(@TempDir Path dir) throws IOException {
        Path copy = Files.writeString(dir.resolve("flag.json"), Files.readString(Path.of("data/flag.json")));
        Preset p = PresetLoader.load(copy);
        assertEquals(622, Scene.of(p).cloth().particles().count());
        Path other = Files.writeString(dir.resolve("other.json"), Files.readString(Path.of("data/flag.json")).replace("flag-with-hole.obj", "no-such-mesh.obj"));
        assertThrows(IllegalArgumentException.class, () -> PresetLoader.load(other));
    }

    @Test
    void meshIsPlacedAndPinnedByIndexGroupAndBox(@TempDir Path dir) throws IOException {
        Preset p = load(dir, preset("{ \"file\": \"two.obj\", \"scale\": 2, \"rotation\": [0, 90, 0], \"translation\": [0, 3, 0] }",
                "[5, { \"group\": \"top\" }, { \"box\": { \"min\": [-1, 0, -0.1], \"max\": [1, 2.5, 0.1] } }]"));
        ClothMesh m = p.cloth.mesh;
        assertEquals(6, m.vertexCount());
        // (2, 0, 0) scaled by 2 → (4, 0, 0), turned 90° about y → (0, 0, −4), moved up by 3.
        assertEquals(0, m.x(2), 1e-12);
        assertEquals(3, m.y(2), 1e-12);
        assertEquals(-4, m.z(2), 1e-12);
        // Index 5; the group "top" (0, 1, 2); the box around x = z = 0 below y = 2.5 holds vertex 3 (at y = 1).
        assertArrayEquals(new int[] {0, 1, 2, 3, 5}, p.cloth.pinnedVertices);
        Scene s = Scene.of(p);
        Particles x = s.cloth().particles();
        for (int i : p.cloth.pinnedVertices) assertTrue(x.isPinned(i));
        assertFalse(x.isPinned(4));
        double mass = 0;
        for (int i = 0; i < x.count(); i++) mass += x.mass(i);
        assertEquals(0.2 * 4 * 2, mass, 1e-12, "areal density × the scaled area (4 m × 2 m)");
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
        "missing file      | { \"file\": \"none.obj\" }                      | [0]                      | cloth.mesh.file   | ",
        "broken obj        | { \"file\": \"broken.obj\" }                    | [0]                      | cloth.mesh.file   | broken.obj:2: vertex index 2 is out of range",
        "unknown group     | { \"file\": \"two.obj\" }                       | [{ \"group\": \"hem\" }] | cloth.pins[0].group | must be one of top, left, right, was \"hem\"",
        "empty box         | { \"file\": \"two.obj\" }                       | [{ \"box\": { \"min\": [5, 5, 5], \"max\": [6, 6, 6] } }] | cloth.pins[0].box | contains no vertex",
        "inverted box      | { \"file\": \"two.obj\" }                       | [{ \"box\": { \"min\": [1, 0, 0], \"max\": [0, 1, 1] } }] | cloth.pins[0].box.max[0] | must be >= min[0]",
        "index too large   | { \"file\": \"two.obj\" }                       | [6]                      | cloth.pins[0]     | must be a vertex index in [0, 5], was 6",
        "grid pin name     | { \"file\": \"two.obj\" }                       | [\"top-left\"]          | cloth.pins[0]     | must be a vertex index",
        "bad scale         | { \"file\": \"two.obj\", \"scale\": 0 }         | [0]                      | cloth.mesh.scale  | must be in [1.0e-4, 10000]",
        "unknown field     | { \"file\": \"two.obj\", \"size\": 1 }          | [0]                      | cloth.mesh.size   | unknown field",
        "placed too far    | { \"file\": \"two.obj\", \"scale\": 9000 }      | [0]                      | cloth.mesh        | vertex 1 lands at (9000.0",
    })
    void mistakesAreNamed(String what, String mesh, String pins, String field, String problem, @TempDir Path dir) throws IOException {
        Files.writeString(dir.resolve("broken.obj"), "v 0 0 0\nf 1 2 9\n");
        PresetException e = assertThrows(PresetException.class, () -> load(dir, preset(mesh, pins)), what);
        assertEquals(field.trim(), e.field(), e.getMessage());
        if (problem != null) assertTrue(e.problem().contains(problem.trim()), what + ": " + e.getMessage());
        assertTrue(e.getMessage().startsWith(dir.resolve("m.json").toString()), "names the preset: " + e.getMessage());
    }

    @Test
    void pinMotionOnAMeshNamesAPinnedVertex(@TempDir Path dir) throws IOException {
        String text = preset("{ \"file\": \"two.obj\" }", "[0]").replace("\"dt\": 0.02 } }",
                "\"dt\": 0.02 }, \"pinMotions\": [{ \"pin\": 3, \"displacement\": [0, 1, 0], \"duration\": 1 }] }");
        PresetException e = assertThrows(PresetException.class, () -> load(dir, text));
        assertEquals("pinMotions[0].pin", e.field());
        assertTrue(e.problem().startsWith("vertex 3 must also be pinned"), e.getMessage());
        Preset ok = load(dir, text.replace("\"pins\": [0]", "\"pins\": [0, 3]"));
        assertEquals(3, ok.pinMotions.get(0).vertex);
    }

    /** The mesh files in data/ are the generators' output, byte for byte (made here, not downloaded). */
    @Test
    void shippedMeshesAreTheGeneratorsOutput() throws IOException {
        for (Map.Entry<String, String> f : ShippedMeshes.files().entrySet())
            assertEquals(f.getValue(), Files.readString(Path.of("data", f.getKey())), f.getKey() + " differs from its generator: run gradle meshes");
        ClothMesh flag = ObjReader.read(Path.of("data/flag-with-hole.obj"), 0);
        assertEquals(21, flag.group("hoist").length);
    }

    /**
     * The flag scene: a mesh cloth held by its hoist group flies in the wind. The hoist never moves, the
     * cloth stays finite and barely stretched (mean edge strain under 0.2 %, the worst edge, at the top of
     * the hoist where the whole flag hangs, under 8 %) and the wind pushes it: after
     * 4 s its mean position has moved downwind (+z) of where it hangs without wind.
     */
    @Test
    void flagFliesFromItsHoist() {
        Scene windy = Scene.builtIn("flag"), still = Scene.builtIn("flag");
        still.setWind(false);
        Particles p = windy.cloth().particles();
        int[] hoist = windy.preset().cloth.mesh.group("hoist");
        double[] start = p.positions().clone();
        for (int s = 0; s < 200; s++) { windy.simulation().step(); still.simulation().step(); }
        for (int i : hoist)
            for (int d = 0; d < 3; d++) assertEquals(start[3 * i + d], p.positions()[3 * i + d], 0.0, "hoist vertex " + i);
        assertTrue(Metrics.allFinite(p));
        double strain = Metrics.maxStrain(windy.simulation(), xpbdcloth.engine.ConstraintFamily.STRUCTURAL);
        double mean = Metrics.meanStrain(windy.simulation(), xpbdcloth.engine.ConstraintFamily.STRUCTURAL);
        assertTrue(strain < 0.08, "max strain " + strain);
        assertTrue(mean < 0.002, "mean strain " + mean);
        double zWindy = meanZ(p), zStill = meanZ(still.cloth().particles());
        System.out.printf("flag after 4 s: mean z %.3f m in the wind, %.3f m without, max strain %.4f%n", zWindy, zStill, strain);
        assertTrue(zWindy > zStill + 0.05, "the wind pushes the flag downwind");
    }

    static double meanZ(Particles p) {
        double z = 0;
        for (int i = 0; i < p.count(); i++) z += p.z(i);
        return z / p.count();
    }

    /** The tablecloth scene drapes over its sphere: nothing inside it, the hem fallen well below the sphere's top. */
    @Test
    void tableclothDrapesOverTheSphere() {
        Scene s = Scene.builtIn("tablecloth");
        for (int i = 0; i < 150; i++) s.simulation().step();
        Particles p = s.cloth().particles();
        xpbdcloth.engine.Sphere sphere = s.simulation().spheres().get(0);
        double deepest = 0, rimY = 0;
        for (int i = 0; i < p.count(); i++) {
            double dx = p.x(i) - sphere.centreX(), dy = p.y(i) - sphere.centreY(), dz = p.z(i) - sphere.centreZ();
            deepest = Math.max(deepest, sphere.radius() - Math.sqrt(dx * dx + dy * dy + dz * dz));
        }
        for (int v : s.preset().cloth.mesh.group("hem")) rimY += p.y(v) / s.preset().cloth.mesh.group("hem").length;
        System.out.printf("tablecloth after 3 s: deepest penetration %.4f m, mean hem height %.3f m (sphere top %.3f m)%n", deepest, rimY, sphere.centreY() + sphere.radius());
        assertTrue(deepest < 0.005, "no vertex more than 5 mm inside the sphere: " + deepest);
        assertTrue(rimY < sphere.centreY() + sphere.radius() - 0.25, "the hem hangs more than 0.25 m below the sphere's top: " + rimY);
        assertTrue(Metrics.allFinite(p));
    }
}
