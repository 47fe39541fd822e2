package xpbdcloth.scene;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import xpbdcloth.mesh.ClothMesh;
import xpbdcloth.mesh.ObjReader;

/** An OBJ sequence is the simulation, frame by frame: same vertices and faces every frame, the positions exact. */
class ObjExportTest {

    @Test
    void sequenceHoldsTheSimulatedPositions(@TempDir Path dir) throws IOException {
        Preset preset = PresetLoader.builtIn("hanging");
        assertEquals(4, ObjExport.recordSequence(preset, 4, dir));
        Scene replay = Scene.of(preset);
        int steps = ObjExport.stepsPerFrame(preset.solver.timestep());
        assertEquals(1, steps, "dt = 20 ms: one step per 60 Hz frame");
        ClothMesh first = null;
        for (int f = 1; f <= 4; f++) {
            for (int s = 0; s < steps; s++) replay.simulation().step();
            Path file = dir.resolve(String.format("frame-%04d.obj", f));
            ClothMesh frame = ObjReader.read(file, 0);
            assertArrayEquals(replay.simulation().particles().positions(), frame.positions(), 0.0, "frame " + f + " is the simulation's state, bit for bit");
            if (first == null) first = frame;
            assertEquals(first.faceCount(), frame.faceCount());
            for (int k = 0; k < frame.faceCount(); k++) assertArrayEquals(first.face(k), frame.face(k));
            assertTrue(Files.readString(file).contains("\nvn "), "normals are written");
        }
        assertEquals(31 * 31, first.faceCount(), "the grid's quads, not its triangles");
    }

    /** Each file's header time is its frame number over the stated rate: played at that rate, the motion is real time. */
    @Test
    void headerTimesMatchTheStatedRate(@TempDir Path dir) throws IOException {
        Preset preset = PresetLoader.builtIn("flag"); // dt = 20 ms: one step is 1/50 s, not a 60 Hz frame
        assertEquals(50.0, ObjExport.naturalFps(preset.solver.timestep()), 1e-9);
        for (double fps : new double[] {50, 25, 10}) {
            int steps = ObjExport.stepsPerFrame(preset.solver.timestep(), fps);
            Path folder = dir.resolve("fps" + (int) fps);
            ObjExport.recordSequence(preset, 3, folder, steps);
            for (int f = 1; f <= 3; f++) {
                String header = Files.readString(ObjExport.frameFile(folder, f)).lines().filter(l -> l.contains("t = ")).findFirst().orElseThrow();
                double t = Double.parseDouble(header.replaceAll(".*t = ([0-9.]+) s.*", "$1"));
                assertEquals(f / fps, t, 1e-4, "frame " + f + " at " + fps + " fps: " + header);
            }
        }
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> ObjExport.stepsPerFrame(0.02, 60));
        assertTrue(e.getMessage().startsWith("fps: 60") && e.getMessage().contains("50, 25"), e.getMessage());
    }

    @Test
    void stepsPerFrameFollowTheSketchsRecorder() {
        assertEquals(2, ObjExport.stepsPerFrame(1 / 120.0));
        assertEquals(1, ObjExport.stepsPerFrame(0.05));
        assertEquals(4, ObjExport.stepsPerFrame(1 / 240.0));
    }
}
