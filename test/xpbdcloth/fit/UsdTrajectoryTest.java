package xpbdcloth.fit;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import xpbdcloth.scene.PresetLoader;
import xpbdcloth.scene.Scene;
import xpbdcloth.usd.UsdRecording;

/** A motion recorded as USD, a time code per step, is the trajectory a fit reads: the engine's steps to float precision, or a refusal naming the rate. */
class UsdTrajectoryTest {
    @Test
    void aRecordingAtOneFramePerStepIsTheEnginesTrajectory(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("drape.usda");
        UsdRecording.record(PresetLoader.builtIn("drape"), 20, file, 1);
        double[][] read = Trajectory.read(file, Scene.builtIn("drape")), simulated = Trajectory.simulate(Scene.builtIn("drape"), 20, 0, 1);
        assertEquals(simulated.length, read.length, "time code 0 (the start) is not a frame; codes 1 … 20 are");
        for (int f = 0; f < read.length; f++)
            for (int i = 0; i < read[f].length; i++) assertEquals((float) simulated[f][i], (float) read[f][i], 0f, "frame " + (f + 1) + ", coordinate " + i);
    }

    @Test
    void aRecordingAtAnotherRateOrOfAnotherClothIsRefused(@TempDir Path dir) throws IOException {
        Path every2 = dir.resolve("every-second-step.usda");
        UsdRecording.record(PresetLoader.builtIn("drape"), 4, every2, 2);
        FitException e = assertThrows(FitException.class, () -> Trajectory.read(every2, Scene.builtIn("drape")));
        assertTrue(e.getMessage().contains("timeCodesPerSecond is 25.0") && e.getMessage().contains("--fps 50"), e.getMessage());
        Path other = dir.resolve("hanging.usda");
        UsdRecording.record(PresetLoader.builtIn("hanging"), 2, other, 1);
        e = assertThrows(FitException.class, () -> Trajectory.read(other, Scene.builtIn("drape")));
        assertTrue(e.getMessage().contains("/World/Cloth has 1024 points, the scene drape has"), e.getMessage());
    }
}
