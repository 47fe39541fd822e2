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
        int steps = ObjExport.stepsPerFrame(preset.solver.dt);
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

    @Test
    void stepsPerFrameFollowTheSketchsRecorder() {
        assertEquals(2, ObjExport.stepsPerFrame(1 / 120.0));
        assertEquals(1, ObjExport.stepsPerFrame(0.05));
        assertEquals(4, ObjExport.stepsPerFrame(1 / 240.0));
    }
}
