package xpbdcloth.sketch;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;
import xpbdcloth.scene.PresetLoader;
import xpbdcloth.scene.Scene;

/**
 * The start view shows every built-in scene's cloth below the HUD's parameter panel: the projected rest
 * box lies between the panel's foot and the window's bottom at 1280 × 800 and 800 × 600 (the panel used
 * to end at the pinned edge, and a notice pushed it over the pins).
 */
class FramingTest {
    @Test
    void everySceneStartsBelowTheHud() {
        // The reserve holds the panel as laid out: its longest state (13 lines and a notice).
        for (int[] size : new int[][] {{1280, 800}, {800, 600}}) {
            HudLayout l = new HudLayout(size[0], size[1], 7.8f, 13, 100, 80, null, false, null, null);
            assertTrue(l.panel.y + l.panel.h <= Framing.HUD_RESERVE, "the reserve holds the panel: " + l.panel);
        }
        double[] p = new double[3];
        for (String name : PresetLoader.BUILT_IN) {
            double[] x = Scene.of(PresetLoader.builtIn(name)).cloth().mesh().positions();
            double[] box = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
            for (int k = 0; k < x.length; k += 3)
                for (int a = 0; a < 3; a++) { box[a] = Math.min(box[a], x[k + a]); box[3 + a] = Math.max(box[3 + a], x[k + a]); }
            for (int[] size : new int[][] {{1280, 800}, {800, 600}}) {
                OrbitCamera camera = new OrbitCamera(0, 0, 0, 2, 0.2, 50);
                double cx = (box[0] + box[3]) / 2, cy = (box[1] + box[4]) / 2, cz = (box[2] + box[5]) / 2;
                Framing.belowHud(camera, box, size[0], size[1], cx, cy, cz, 2, -0.15);
                for (int c = 0; c < 8; c++) {
                    camera.project(box[(c & 1) == 0 ? 0 : 3], box[(c & 2) == 0 ? 1 : 4], box[(c & 4) == 0 ? 2 : 5], p);
                    String at = name + " at " + size[0] + "x" + size[1] + ", corner " + c + " at y " + p[1];
                    assertTrue(p[1] >= Framing.HUD_RESERVE - 1, "below the panel: " + at);
                    assertTrue(p[1] <= size[1] - Framing.BOTTOM + 1, "inside the window: " + at);
                }
            }
        }
    }
}
