package xpbdcloth.scene;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import xpbdcloth.engine.Particles;

/**
 * A strip of fabric pulled at both ends tears where and when its strain reaches the breaking strain, into
 * exactly two pieces whose masses sum to the strip's; the same tears, the same bits on one thread and two.
 */
class TearingTest {
    static final double BREAKING = 0.1, HEIGHT = 0.3, PULL = 0.3, DURATION = 3;

    /**
     * A 6 × 31 strip 5 cm × 30 cm, hanging by its top edge, its bottom edge pulled down 30 cm over 3 s (eased);
     * Poisson's ratio 0, so the pull stretches it uniformly: its edges along the pull are strained as the strip is.
     */
    static String strip() {
        return "{ \"name\": \"tear\", \"cloth\": { \"columns\": 6, \"rows\": 31, \"width\": 0.05, \"height\": " + HEIGHT + ", \"plane\": \"vertical\","
                + " \"origin\": [0, 1, 0], \"pins\": [\"top-edge\", \"bottom-edge\"], \"arealDensity\": 0.2 },"
                + " \"fabric\": { \"warpModulus\": 2000, \"weftModulus\": 2000, \"poisson\": 0, \"shearModulus\": 500, \"bendingStiffness\": 1e-5,"
                + " \"warp\": [0, 1, 0], \"breakingStrain\": " + BREAKING + " },"
                + " \"solver\": { \"mode\": \"XPBD\", \"type\": \"vertex-block-descent\", \"iterations\": 2, \"substeps\": 10, \"dt\": 0.01, \"damping\": 1 },"
                + " \"pinMotions\": [ { \"pin\": \"bottom-edge\", \"displacement\": [0, -" + PULL + ", 0], \"start\": 0, \"duration\": " + DURATION + " } ] }";
    }

    /** The strip's nominal strain at time t: the eased pull over the rest height. */
    static double nominal(double t) {
        double u = Math.max(0, Math.min(1, t / DURATION));
        return PULL * u * u * (3 - 2 * u) / HEIGHT;
    }

    /** Pieces: triangles joined through shared vertices (union–find over the vertices). */
    static int pieces(int[] triangles, int vertices) {
        int[] parent = new int[vertices];
        for (int i = 0; i < vertices; i++) parent[i] = i;
        boolean[] used = new boolean[vertices];
        for (int t = 0; t < triangles.length; t += 3)
            for (int k = 0; k < 3; k++) {
                used[triangles[t + k]] = true;
                int a = find(parent, triangles[t]), b = find(parent, triangles[t + k]);
                parent[a] = b;
            }
        int count = 0;
        for (int i = 0; i < vertices; i++) if (used[i] && find(parent, i) == i) count++;
        return count;
    }

    private static int find(int[] parent, int i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    }

    static double totalMass(Scene s) {
        Particles p = s.cloth().particles();
        double m = 0;
        for (int i = 0; i < p.count(); i++) m += p.mass(i);
        return m;
    }

    /** Runs the strip 1.8 s; returns the last scene and records the first tear's step. */
    static final class Run {
        Scene scene;
        int firstTear = -1, triangles;
        double massBefore, strainBeforeTear;

        Run(int threads) {
            scene = Scene.of(PresetLoader.parse("tear.json", strip()));
            scene.simulation().settings(scene.simulation().settings().withThreads(threads));
            massBefore = totalMass(scene);
            triangles = scene.cloth().triangles().length;
            for (int step = 1; step <= 180; step++) {
                Scene next = scene.step();
                if (next != scene && firstTear < 0) firstTear = step;
                if (firstTear < 0) strainBeforeTear = scene.breaking().largestStrain();
                scene = next;
            }
        }
    }

    @Test
    void aStripPulledTearsAtItsBreakingStrainIntoTwoPiecesOfItsMass() {
        Run run = new Run(1);
        assertTrue(run.firstTear > 0, "it tore");
        double dt = 0.01, atTear = nominal(run.firstTear * dt), before = nominal((run.firstTear - 1) * dt);
        System.out.printf("first tear at step %d: the strip's strain %.5f (a step before %.5f), breaking strain %.3f; largest edge strain before %.5f%n",
                run.firstTear, atTear, before, BREAKING, run.strainBeforeTear);
        // When the strip's own strain reaches the breaking strain, within one step's worth of pull (and the
        // quasi-static lag of a cloth pulled at 10 cm/s).
        assertTrue(before <= BREAKING + 0.002 && atTear >= BREAKING - 0.002, "strip strain " + before + " → " + atTear + " across " + BREAKING);
        Scene s = run.scene;
        int[] triangles = s.cloth().triangles();
        assertEquals(run.triangles, triangles.length, "no triangle lost or made");
        assertEquals(2, pieces(triangles, s.cloth().particles().count()), "two pieces");
        assertTrue(s.cloth().particles().count() > 6 * 31, "vertices split along the tear");
        assertEquals(run.massBefore, totalMass(s), 1e-12 * run.massBefore, "the pieces' masses sum to the strip's");
        System.out.printf("after 1.8 s: %d particles, largest edge strain %.4f%n", s.cloth().particles().count(), s.breaking().largestStrain());
    }

    /**
     * The shipped `tear` scene: a ball of radius 12 cm falling at 0.5 m/s through a sheet held by its edges tears
     * it where it passes (every split vertex within the ball's radius and two grid spacings of its path, rest
     * coordinates), and falls on through the hole: 3 s in, the ball is 1.3 m below the sheet and no particle of
     * the sheet has gone with it.
     */
    @Test
    void aBallFallingThroughASheetTearsItWhereItPasses() {
        Scene s = Scene.builtIn("tear");
        int before = s.cloth().particles().count();
        double mass = totalMass(s);
        for (int step = 0; step < 150; step++) s = s.step();
        int after = s.cloth().particles().count();
        assertTrue(after - before >= 8, "torn: " + (after - before) + " vertices split");
        double reach = 0.12 + 2 * 1.0 / 39, farthest = 0;
        for (int v = before; v < after; v++)
            farthest = Math.max(farthest, Math.hypot(s.cloth().mesh().x(v) - 0.05, s.cloth().mesh().z(v) - 0.03));
        System.out.printf("%d vertices split, the farthest %.3f m from the ball's path (reach %.3f)%n", after - before, farthest, reach);
        assertTrue(farthest < reach, "a split " + farthest + " m from the path");
        xpbdcloth.engine.Sphere ball = s.simulation().spheres().get(0);
        double lowest = Double.MAX_VALUE;
        for (int i = 0; i < after; i++) lowest = Math.min(lowest, s.cloth().particles().y(i));
        assertEquals(1.2 - 0.5 * 3.0, ball.centreY(), 1e-9, "the ball on its path");
        assertTrue(lowest > 0.6, "the sheet stayed up while the ball fell through: lowest particle at " + lowest);
        assertEquals(mass, totalMass(s), 1e-12 * mass);
    }

    /**
     * Recorded, a cloth that tears is written as it is at each moment: an OBJ sequence frame by frame with the
     * topology of its time (more vertices once torn, the same triangles); a USD stage, which holds one topology,
     * ends at the frame before the first tear and is written all the same.
     */
    @Test
    void recordingsFollowOrEndAtATear(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir) throws Exception {
        Scene last = ObjExport.recordSequence(Scene.builtIn("tear"), 50, dir.resolve("obj"), 1);
        long first = vertexLines(dir.resolve("obj").resolve("frame-0001.obj")), end = vertexLines(dir.resolve("obj").resolve("frame-0050.obj"));
        assertEquals(40 * 40, first, "untorn at the first frame");
        assertEquals(last.cloth().particles().count(), end, "the last frame has the torn cloth's vertices");
        assertTrue(end > first, "torn by frame 50: " + end);
        int codes = xpbdcloth.usd.UsdRecording.record(Scene.builtIn("tear"), 50, dir.resolve("tear.usda"), 1);
        assertTrue(codes > 1 && codes < 51, "ends at the first tear: " + codes + " time codes");
        assertTrue(java.nio.file.Files.readString(dir.resolve("tear.usda")).contains("points"), "written");
    }

    private static long vertexLines(java.nio.file.Path obj) throws java.io.IOException {
        try (java.util.stream.Stream<String> lines = java.nio.file.Files.lines(obj)) {
            return lines.filter(l -> l.startsWith("v ")).count();
        }
    }

    @Test
    void theSameTearsAndTheSameBitsOnOneThreadAndTwo() {
        Run one = new Run(1), two = new Run(2);
        assertEquals(one.firstTear, two.firstTear);
        assertArrayEquals(one.scene.cloth().triangles(), two.scene.cloth().triangles());
        assertArrayEquals(one.scene.cloth().particles().positions(), two.scene.cloth().particles().positions());
        assertNotSame(one.scene, two.scene);
    }

    @Test
    void aBreakingStrainOutOfRangeOrWithPlasticityIsRefusedByName() {
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.parse("t.json", strip().replace("\"breakingStrain\": 0.1", "\"breakingStrain\": 0")));
        assertEquals("fabric.breakingStrain", e.field());
        assertTrue(e.problem().contains("must be in"), e.getMessage());
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("t.json",
                strip().replace("\"breakingStrain\": 0.1", "\"breakingStrain\": 0.1, \"plasticity\": { \"yieldCurvature\": 20, \"rate\": 2 }")));
        assertEquals("fabric.breakingStrain", e.field());
        assertTrue(e.problem().contains("plasticity"), e.getMessage());
    }
}
