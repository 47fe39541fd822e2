package xpbdcloth.scene;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import xpbdcloth.pattern.MeshQuality;
import xpbdcloth.pattern.PatternMesh;
import xpbdcloth.pattern.Seam;

/** Pattern files load strictly (each problem named by field, and by panel or seam), and the shipped ones mesh well. */
class PatternLoaderTest {
    static final String RECTANGLES = String.join("\n",
            "{\"name\": \"tube\", \"edge\": 0.05, \"panels\": [",
            "{\"name\": \"front\", \"fabric\": \"denim\", \"grain\": [0, 1], \"outline\": [{\"at\": [0, 0]}, {\"at\": [0.4, 0]}, {\"at\": [0.4, 0.5]}, {\"at\": [0, 0.5]}]},",
            "{\"name\": \"back\", \"fabric\": \"denim\", \"grain\": [0, 1], \"outline\": [{\"at\": [0, 0]}, {\"at\": [0.4, 0]}, {\"at\": [0.4, 0.5]}, {\"at\": [0, 0.5]}],",
            "\"position\": [0, 0, -0.2], \"rotation\": [0, 180, 0]}],",
            "\"seams\": [{\"name\": \"side\", \"a\": {\"panel\": \"front\", \"from\": 1, \"to\": 2}, \"b\": {\"panel\": \"back\", \"from\": 0, \"to\": 3, \"backward\": true}}]}");


    static String problem(String text) {
        return assertThrows(PresetException.class, () -> PatternLoader.parse("p.json", text)).getMessage();
    }

    @Test
    void everyShippedPatternLoadsAndMeshesWithinTheQualityBounds() throws IOException {
        long n;
        try (var files = Files.list(Path.of("data", PatternLoader.FOLDER))) {
            n = files.filter(f -> f.toString().endsWith(".json")).peek(f -> {
                String name = f.getFileName().toString().replace(".json", "");
                PatternLoader.Loaded p;
                p = PatternLoader.byNameOrPath(name);
                assertEquals(name, p.pattern.name, "file name matches pattern name");
                PatternMesh m = p.mesh(p.edge);
                int triangles = 0;
                for (int i = 0; i < p.pattern.panels().size(); i++) {
                    MeshQuality q = MeshQuality.ofPanel(m, i);
                    assertTrue(q.smallestAngle >= 20 && q.smallestSize >= 0.7 && q.largestSize <= 1.3, name + " panel " + i + ": " + q);
                    assertEquals(p.pattern.panels().get(i).outline.area(), q.area, 0.01 * q.area, "the mesh covers the outline (to its chords)");
                    triangles += m.panelTriangleRange(i)[1] - m.panelTriangleRange(i)[0];
                }
                assertEquals(m.triangleCount(), triangles);
                for (Seam s : p.pattern.seams()) assertTrue(m.stitches(s.name).length >= 4, "every seam has stitches at both ends");
            }).count();
        }
        assertTrue(n >= 1);
    }

    @Test
    void aPatternReadsIntoPanelsAndSeams() {
        PatternLoader.Loaded p = PatternLoader.parse("tube.json", RECTANGLES);
        assertEquals(2, p.pattern.panels().size());
        assertEquals(0.05, p.edge);
        int[] s = p.mesh(p.edge).stitches("side");
        assertEquals(2 * 11, s.length, "0.5 m at 0.05 m: 10 segments, 11 stitches");
        double[] x = p.mesh(p.edge).positions();
        // The back is turned half round and moved back: its corner 0 lies at x = 0.2, its corner 3 at (0.2, 0.25, −0.2).
        assertArrayEquals(new double[] {0.2, -0.25, 0}, new double[] {x[3 * s[0]], x[3 * s[0] + 1], x[3 * s[0] + 2]}, 1e-12);
        assertArrayEquals(new double[] {0.2, -0.25, -0.2}, new double[] {x[3 * s[1]], x[3 * s[1] + 1], x[3 * s[1] + 2]}, 1e-12);
    }

    /** The README's worked example, its comments taken out, is a pattern that loads and meshes. */
    @Test
    void theReadmeExampleLoads() throws IOException {
        String readme = Files.readString(Path.of("README.md"));
        int section = readme.indexOf("## Patterns"), start = readme.indexOf("```json", section) + 7, end = readme.indexOf("```", start);
        String json = readme.substring(start, end).replaceAll("//[^\n]*", "");
        PatternLoader.Loaded p = PatternLoader.parse("README.md", json);
        assertEquals(List.of("front", "back"), p.pattern.panels().stream().map(x -> x.name).collect(java.util.stream.Collectors.toList()));
        assertEquals(2 * 26, p.mesh(p.edge).stitches("side").length, "0.5 m at 0.02 m: 25 segments");
    }

    /**
     * A pattern meshed too coarsely for its seams is refused when the preset loads, naming the edge and the
     * seam: at 15 cm the T-shirt's 36 cm sleeve is one triangle from one side of its underarm seam to the other
     * (closed, the two triangles there would be one, face to face); at 10.65 cm a side of the skirt's front gore
     * meshes without one of its outline edges between two stitches. The built-in edges sew (GarmentTest).
     */
    @Test
    void aPatternTooCoarseForItsSeamsIsRefusedNamingTheEdgeAndTheSeam() {
        String preset = "{ \"name\": \"g\", \"description\": \"x\", \"cloth\": { \"pattern\": \"%s\", \"edge\": %s },"
                + " \"solver\": { \"mode\": \"XPBD\", \"iterations\": 3, \"substeps\": 5, \"dt\": 0.02, \"mullerCorrection\": true, \"gravity\": [0, -9.81, 0] } }";
        PresetException shirt = assertThrows(PresetException.class, () -> PresetLoader.parse("g.json", String.format(preset, "tshirt", "0.15")));
        assertEquals("cloth.edge", shirt.field());
        assertTrue(shirt.problem().startsWith("tshirt: at an edge of 0.150 m, seam \"right underarm\" would close two triangles into one"), shirt.problem());
        PresetException skirt = assertThrows(PresetException.class, () -> PresetLoader.parse("g.json", String.format(preset, "skirt", "0.1065")));
        assertEquals("cloth.edge", skirt.field());
        assertTrue(skirt.problem().startsWith("skirt: at an edge of 0.107 m, seam \"front–left side\": stitches 1 and 2 are not joined by an outline edge"), skirt.problem());
        assertDoesNotThrow(() -> PresetLoader.parse("g.json", String.format(preset, "tshirt", "0.05")));
    }

    @Test
    void badPatternsAreNamedByFieldAndByPanelOrSeam() {
        assertEquals("p.json: panels[1].fabric: is missing", problem(RECTANGLES.replace("{\"name\": \"back\", \"fabric\": \"denim\",", "{\"name\": \"back\",")));
        assertTrue(problem(RECTANGLES.replace("\"fabric\": \"denim\", \"grain\": [0, 1], \"outline\": [{\"at\": [0, 0]}, {\"at\": [0.4, 0]}, {\"at\": [0.4, 0.5]}, {\"at\": [0, 0.5]}]},",
                "\"fabric\": \"denin\", \"grain\": [0, 1], \"outline\": [{\"at\": [0, 0]}, {\"at\": [0.4, 0]}, {\"at\": [0.4, 0.5]}, {\"at\": [0, 0.5]}]},"))
                .startsWith("p.json: panels[0].fabric: panel \"front\": no fabric \"denin\" in fabrics.json; one of denim,"));
        assertEquals("p.json: panels[0].outline: panel \"front\": the outline crosses itself near (0.2000, 0.2500) m",
                problem(RECTANGLES.replaceFirst("\\{\"at\": \\[0.4, 0.5\\]\\}, \\{\"at\": \\[0, 0.5\\]\\}", "{\"at\": [0, 0.5]}, {\"at\": [0.4, 0.5]}")));
        assertEquals("p.json: seams: seam \"side\": stretch \"front\" 1 to 5 runs past the outline's end (positions on panel \"front\" are 0 to 4, its corner count), was 5.0",
                problem(RECTANGLES.replace("\"from\": 1, \"to\": 2", "\"from\": 1, \"to\": 5")));
        assertEquals("p.json: seams: seam \"hem\": stretch \"front\" 1.5 to 2 is sewn twice (it overlaps seam \"side\")",
                problem(RECTANGLES.replace("\"backward\": true}}]", "\"backward\": true}}, {\"name\": \"hem\", \"a\": {\"panel\": \"front\", \"from\": 1.5, \"to\": 2}, \"b\": {\"panel\": \"back\", \"from\": 0, \"to\": 1}}]")));
        assertEquals("p.json: panels[0].outline[1]: panel \"front\": an edge is an arc (\"bulge\") or a Bézier curve (\"controls\"), not both",
                problem(RECTANGLES.replaceFirst("\\{\"at\": \\[0.4, 0\\]\\}", "{\"at\": [0.4, 0], \"bulge\": 0.1, \"controls\": [[0.5, 0.1], [0.5, 0.4]]}")));
        assertTrue(problem(RECTANGLES.replace("\"edge\": 0.05", "\"edge\": 0.001")).startsWith("p.json: edge: an edge of 0.00100 m would mesh the panels' 0.400 m² into about 461880 vertices; at most 50000 are allowed"));
        assertEquals("p.json: panels[1].around.axis: must not be (almost) zero, had length 0.0",
                problem(RECTANGLES.replace("\"position\": [0, 0, -0.2], \"rotation\": [0, 180, 0]", "\"around\": {\"centre\": [0, 1, 0], \"radii\": [0.1, 0.1], \"axis\": [0, 0, 0]}")));
        // Every problem of a file at once, a line each.
        String two = problem(RECTANGLES.replace("\"grain\": [0, 1], \"outline\": [{\"at\": [0, 0]}, {\"at\": [0.4, 0]}, {\"at\": [0.4, 0.5]}, {\"at\": [0, 0.5]}]},",
                "\"grain\": [0, 0], \"outline\": [{\"at\": [0, 0]}, {\"at\": [0.4, 0]}, {\"at\": [0.4, 0.5]}, {\"at\": [0, 0.5]}]},").replace("\"wrap\"", "\"wrap\"").replace("\"rotation\": [0, 180, 0]", "\"rotation\": [0, 720, 0]"));
        assertTrue(two.contains("panels[0].grain: panel \"front\": must be a direction, was [0, 0]") && two.contains("panels[1].rotation[1]: must be in [-360, 360] degrees, was 720"), two);
    }
}
