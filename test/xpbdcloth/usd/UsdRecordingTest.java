package xpbdcloth.usd;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import xpbdcloth.engine.Box;
import xpbdcloth.engine.RigidCollider;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.Sphere;
import xpbdcloth.mesh.UsdMeshAnimation;
import xpbdcloth.mesh.UsdaReader;
import xpbdcloth.scene.Scene;

/**
 * A USD recording is the simulation, frame by frame, read back with the project's own .usda reader (Pixar's
 * reader checks the same file in {@link PixarReadsRecordingTest}): the stage's clock and units, the cloth's
 * topology once and its points per time code as the floats nearest the simulated doubles, and every
 * collider's pose as a row-vector matrix.
 */
class UsdRecordingTest {
    static final int FRAMES = 12;
    static final int[] CHECKED = {0, 5, 12};

    /** A recording of {@link UsdRigs#everyCollider()}, one frame per step, with what the engine held at the checked frames. */
    static final class Recorded {
        final Path file;
        final Scene scene;
        final double[][] positions = new double[CHECKED.length][];
        /** Per checked frame, per collider (sphere, box, capsule): the row-vector matrix p_world = [p, 1] M, 16 numbers. */
        final double[][][] poses = new double[CHECKED.length][3][];

        Recorded(Path dir) throws IOException {
            file = dir.resolve("every-collider.usda");
            scene = Scene.of(UsdRigs.everyCollider());
            Simulation sim = scene.simulation();
            try (UsdRecording r = UsdRecording.start(file, scene, 50)) {
                capture(0);
                for (int f = 1; f <= FRAMES; f++) {
                    sim.step();
                    r.frame();
                    capture(f);
                }
                assertEquals(FRAMES + 1, r.frames());
            }
        }

        private void capture(int frame) {
            for (int k = 0; k < CHECKED.length; k++)
                if (CHECKED[k] == frame) {
                    Simulation sim = scene.simulation();
                    positions[k] = sim.particles().positions().clone();
                    double[] r = new double[9];
                    Sphere s = sim.spheres().get(0);
                    s.rotation(r);
                    poses[k][0] = rowMatrix(r, s.centreX(), s.centreY(), s.centreZ());
                    for (int j = 0; j < 2; j++) {
                        RigidCollider c = sim.solids().get(j);
                        c.rotation(r);
                        poses[k][1 + j] = rowMatrix(r, c.centreX(), c.centreY(), c.centreZ());
                    }
                }
        }
    }

    static double[] rowMatrix(double[] r, double cx, double cy, double cz) {
        double[] m = new double[16];
        for (int row = 0; row < 3; row++)
            for (int col = 0; col < 3; col++) m[4 * row + col] = r[3 * col + row];
        m[12] = cx; m[13] = cy; m[14] = cz; m[15] = 1;
        return m;
    }

    @Test
    void theStageIsTheSimulation(@TempDir Path dir) throws IOException {
        Recorded rec = new Recorded(dir);
        UsdaReader.Stage stage = UsdaReader.read(rec.file);
        assertEquals(50.0, stage.number("timeCodesPerSecond", 0));
        assertEquals(50.0, stage.number("framesPerSecond", 0));
        assertEquals(0.0, stage.number("startTimeCode", -1));
        assertEquals(FRAMES, stage.number("endTimeCode", -1));
        assertEquals(1.0, stage.number("metersPerUnit", 0));
        assertEquals("Y", stage.metadata.get("upAxis"));
        assertEquals("World", stage.metadata.get("defaultPrim"));

        UsdMeshAnimation cloth = UsdMeshAnimation.read(rec.file, null);
        assertEquals("/World/Cloth", cloth.prim);
        assertEquals(13 * 9, cloth.faceVertexCounts.length, "the grid's quads as authored");
        assertEquals(14 * 10, cloth.vertexCount(), "columns × rows vertices");
        assertEquals(FRAMES + 1, cloth.timeCodes.length);
        for (int k = 0; k < CHECKED.length; k++) {
            double[] expected = rec.positions[k], got = cloth.points[CHECKED[k]];
            assertEquals(CHECKED[k], cloth.timeCodes[CHECKED[k]]);
            for (int i = 0; i < expected.length; i++) {
                assertEquals((float) expected[i], (float) got[i], 0f, "time code " + CHECKED[k] + ", coordinate " + i + ": the float nearest the simulated double");
                assertEquals(expected[i], got[i], 1e-6, "time code " + CHECKED[k] + ", coordinate " + i);
            }
        }
        double[] moved = cloth.points[FRAMES];
        assertNotEquals(rec.positions[0][1], moved[1], "the cloth fell between the first and last frame");

        UsdaReader.Prim mesh = prim(stage, "/World/Cloth");
        double[] st = (double[]) mesh.attributes.get("primvars:st").value;
        assertEquals(2 * 4 * 13 * 9, st.length, "one (u, v) per face corner");
        for (double u : st) assertTrue(u >= 0 && u <= 1, "the rest shape projected onto the unit square");
        double[] n = (double[]) mesh.attributes.get("normals").samples.get(5.0);
        for (int i = 0; i < n.length; i += 3) assertEquals(1, Math.sqrt(n[i] * n[i] + n[i + 1] * n[i + 1] + n[i + 2] * n[i + 2]), 1e-6, "unit normals");
        assertEquals("denim", mesh.attributes.get("xpbd:fabric:name").value);
        assertEquals(rec.scene.fabric().membrane.warpModulus, (Double) mesh.attributes.get("xpbd:fabric:warpModulus").value, 0.0);
        assertEquals(rec.scene.fabric().bendingStiffness, (Double) mesh.attributes.get("xpbd:fabric:bendingStiffness").value, 0.0);

        String[] colliders = {"/World/Sphere0", "/World/Box0", "/World/Capsule0"};
        for (int j = 0; j < 3; j++) {
            UsdaReader.Prim p = prim(stage, colliders[j]);
            for (int k = 0; k < CHECKED.length; k++)
                assertArrayEquals(rec.poses[k][j], (double[]) p.attributes.get("xformOp:transform").samples.get((double) CHECKED[k]), 0.0,
                        colliders[j] + " at time code " + CHECKED[k]);
        }
        assertEquals("Sphere", prim(stage, "/World/Sphere0").type);
        assertEquals(0.15, (Double) prim(stage, "/World/Sphere0").attributes.get("radius").value);
        Box box = (Box) rec.scene.simulation().solids().get(0);
        assertArrayEquals(new double[] {box.halfExtentX(), box.halfExtentY(), box.halfExtentZ()}, (double[]) prim(stage, "/World/Box0").attributes.get("xformOp:scale").value, 1e-7);
        assertEquals(0.4, (Double) prim(stage, "/World/Capsule0").attributes.get("height").value, 1e-15, "the capsule's segment, 2L");
        assertEquals("Y", prim(stage, "/World/Capsule0").attributes.get("axis").value);

        double[] plane = (double[]) prim(stage, "/World/Plane0").attributes.get("points").value;
        for (int c = 0; c < 4; c++) {
            double signed = (plane[3 * c + 1] - 0.1 + 0.2 * plane[3 * c + 2]) / Math.sqrt(1.04);
            assertEquals(0, signed, 1e-6, "the plane's square lies in the plane");
        }
        assertTrue(Files.list(dir).allMatch(p -> p.equals(rec.file)), "the spill files are gone");
    }

    @Test
    void aRopeIsCurvesAndEveryOtherBuiltInSceneRecords(@TempDir Path dir) throws IOException {
        for (String name : xpbdcloth.scene.PresetLoader.BUILT_IN) {
            Path file = dir.resolve(name + ".usda");
            assertEquals(3, UsdRecording.record(xpbdcloth.scene.PresetLoader.builtIn(name), 2, file, 1));
            UsdaReader.Stage stage = UsdaReader.read(file);
            UsdaReader.Prim cloth = prim(stage, "/World/Cloth");
            Scene scene = Scene.builtIn(name);
            if (name.equals("rope")) {
                assertEquals("BasisCurves", cloth.type);
                int segments = scene.cloth().mesh().segmentCount();
                assertEquals(2 * 3 * segments, ((double[]) cloth.attributes.get("points").samples.get(1.0)).length, "two points a segment");
            } else {
                assertEquals("Mesh", cloth.type, name);
                assertEquals(3 * scene.cloth().particles().count(), ((double[]) cloth.attributes.get("points").samples.get(2.0)).length, name);
            }
        }
    }

    @Test
    void tooManyFramesAreRefusedBeforeAnythingIsWritten(@TempDir Path dir) {
        Path file = dir.resolve("long.usda");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> UsdRecording.record(UsdRigs.everyCollider(), UsdRecording.MAX_FRAMES, file, 1));
        assertTrue(e.getMessage().startsWith("frames must be in [1, " + (UsdRecording.MAX_FRAMES - 1) + "]"), e.getMessage());
        assertFalse(Files.exists(file));
        e = assertThrows(IllegalArgumentException.class, () -> UsdRecording.record(UsdRigs.everyCollider(), 3, dir.resolve("x.usdc"), 1));
        assertTrue(e.getMessage().contains("must end in .usda"), e.getMessage());
    }

    static UsdaReader.Prim prim(UsdaReader.Stage stage, String path) {
        for (UsdaReader.Prim p : stage.prims) if (p.path.equals(path)) return p;
        throw new AssertionError("no prim " + path);
    }
}
