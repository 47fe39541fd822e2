package xpbdcloth.sketch;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import xpbdcloth.scene.ObjExport;
import xpbdcloth.scene.PresetLoader;
import xpbdcloth.mesh.UsdMeshAnimation;

/**
 * The R key's recording: a frame every 1/60 s of simulated time (or every step when dt is longer), whatever
 * the window does, the frames the cloth's states; a reset ends it and writes the file; a file that cannot be
 * written is a notice and the scene runs on.
 */
class UsdCaptureTest {
    @Test
    void theKeyRecordsTheRunningClothAndAResetEndsIt(@TempDir Path dir) {
        SketchState s = new SketchState(PresetLoader.builtIn("arm"));
        KeyBindings.forKey('R').press(s);
        assertTrue(s.takeUsdRequest(), "R asks the sketch (which knows the folder) to start a recording");
        Path file = dir.resolve(s.usdFileName());
        s.toggleUsd(file);
        assertTrue(s.recordingUsd(), s.message());
        int steps = 7;
        double[] last = null;
        for (int i = 0; i < steps; i++) {
            assertTrue(s.advance());
            last = s.first().particles().positions().clone();
        }
        assertEquals(1 + steps / ObjExport.stepsPerFrame(s.dt()), s.usdFrames(), "the start, then a frame a step (dt 20 ms is longer than 1/60 s)");
        s.reset();
        assertTrue(s.advance());
        assertFalse(s.recordingUsd(), "a reset scene is not the one recorded");
        assertTrue(s.message().startsWith("wrote " + file) && s.message().contains("the scene changed"), s.message());
        UsdMeshAnimation m = UsdMeshAnimation.read(file, null);
        assertEquals(steps + 1, m.timeCodes.length);
        for (int i = 0; i < last.length; i++) assertEquals(last[i], m.points[steps][i], 1e-6, "the last frame is the state before the reset");
    }

    @Test
    void aFolderThatCannotBeWrittenIsANoticeAndTheSceneRunsOn(@TempDir Path dir) throws Exception {
        Path blocked = dir.resolve("not-a-folder");
        Files.writeString(blocked, "a file where the folder should be");
        SketchState s = new SketchState(PresetLoader.builtIn("hanging"));
        s.toggleUsd(blocked.resolve("x.usda"));
        assertFalse(s.recordingUsd());
        assertTrue(s.messageIsError() && s.message().startsWith("USD recording stopped: "), s.message());
        assertTrue(s.advance(), "the scene steps on");
    }
}
