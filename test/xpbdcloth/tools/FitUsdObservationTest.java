package xpbdcloth.tools;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import xpbdcloth.fit.Trajectory;
import xpbdcloth.scene.Scene;

/** The fit command's observations as USD. */
class FitUsdObservationTest {
    /** `fit --make-observation motion.usda --frames N --noise-mm s` writes the trajectory a fit of it reads: the steps with the noise of the OBJ route. */
    @Test
    void makeObservationWritesANoisyTrajectoryAsUsd(@TempDir Path dir) {
        Path file = dir.resolve("motion.usda");
        int code = new picocli.CommandLine(new FitCommand()).execute("--scene", "drape", "--make-observation", file.toString(), "--frames", "6", "--noise-mm", "0.5");
        assertEquals(0, code);
        double[][] read = Trajectory.read(file, Scene.builtIn("drape")), simulated = Trajectory.simulate(Scene.builtIn("drape"), 6, 0.5e-3, 1);
        assertEquals(6, read.length);
        for (int f = 0; f < read.length; f++)
            for (int i = 0; i < read[f].length; i++) assertEquals((float) simulated[f][i], (float) read[f][i], 0f, "frame " + (f + 1) + ", coordinate " + i);
    }

}
