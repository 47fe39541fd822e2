package xpbdcloth.fit;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import xpbdcloth.scene.PresetLoader;
import xpbdcloth.scene.Scene;

/** An observation is the scene's vertices in the scene's order, read as written: nothing welded, nothing dropped. */
class ObservationTest {
    @Test
    void twoCoincidentVerticesAreTwoObservedVertices(@TempDir Path dir) throws IOException {
        Scene scene = Scene.of(PresetLoader.builtIn("drape"));
        double[] x = scene.simulation().particles().positions().clone();
        // Two free neighbours observed at one point (a crumpled cloth can be): still two vertices.
        int a = 100, b = 101;
        assertFalse(scene.simulation().particles().isPinned(a) || scene.simulation().particles().isPinned(b));
        System.arraycopy(x, 3 * b, x, 3 * a, 3);
        Path obj = dir.resolve("shape.obj");
        Observation.write(obj, scene, x, "two vertices at one point");
        double[] read = Observation.read(obj, scene);
        assertArrayEquals(x, read, 0.0, "the positions as written, in order");
    }
}
