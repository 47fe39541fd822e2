package xpbdcloth.scene;

import static org.junit.jupiter.api.Assertions.*;

import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import xpbdcloth.engine.MeshCollider;
import xpbdcloth.engine.RigidCollider;
import xpbdcloth.engine.Simulation;
import xpbdcloth.pattern.PatternMesh;
import xpbdcloth.pattern.Seam;

/**
 * Each garment, sewn from its pattern (the skirt and the T-shirt onto the dress form, the bordered
 * tablecloth over the table): every seam closed to under a millimetre by the end of the sewing time; the sewn garment's
 * triangles are the panels' (none lost, none twice); no two of its triangles cross at any step, on one
 * thread and on two (the coloured order); no particle inside the body.
 */
@Tag("slow")
class GarmentTest {
    @Test
    void theSkirtIsSewnShutWithoutCrossingItselfOrTheBody() {
        for (int threads : new int[] {1, 2}) sewsShutOnTheDressForm("skirt", threads);
    }

    /** Front and back round the torso, a sleeve round each slanted arm: ten seams, four of them eased 7.9 %. */
    @Test
    void theTshirtIsSewnShutWithoutCrossingItselfOrTheBody() {
        for (int threads : new int[] {1, 2}) sewsShutOnTheDressForm("tshirt", threads);
    }

    /**
     * The T-shirt sewn onto the A-pose body while it stands, then the body turns on the spot (45° to each side
     * and back every 4 s, from 3 s on). A tube round the torso and one round each arm is carried by the arms'
     * contacts and the torso's friction, so the shirt turns as the body does: its mean angle about the body's
     * axis within 3° of the body's at each turn's extreme and in between, while nothing crosses and no particle
     * enters the moving triangles.
     */
    @Test
    void theTshirtTurnsWithTheBodyWithoutCrossingItOrItself() {
        Scene scene = Scene.builtIn("tshirt-turn");
        MeshCollider body = theBody(scene);
        Simulation sim = scene.simulation();
        double dt = sim.settings().timestep(), start = scene.preset().bodies.get(0).start;
        int n = sim.particles().count();
        double[] angle = new double[n], turned = new double[n];
        int steps = (int) Math.round((start + 4) / dt);
        for (int step = 1; step <= steps; step++) {
            sim.step();
            assertEquals(0, scene.crossingPairs(), "tshirt-turn: crossing triangle pairs after step " + step);
            double[] x = sim.particles().positions();
            double mean = 0;
            for (int i = 0; i < n; i++) {
                assertTrue(body.signedDistance(x[3 * i], x[3 * i + 1], x[3 * i + 2]) >= 0, "tshirt-turn: particle " + i + " inside the body after step " + step);
                double a = Math.atan2(x[3 * i], x[3 * i + 2]), d = a - angle[i];
                if (step > 1) turned[i] += d - 2 * Math.PI * Math.rint(d / (2 * Math.PI));
                angle[i] = a;
                mean += turned[i] / n;
            }
            double t = step * dt - start;
            if (t > 0 && Math.abs(t - Math.rint(t)) < 1e-9) {
                double bodyDegrees = 45 * Math.sin(2 * Math.PI * t / 4);
                assertEquals(bodyDegrees, Math.toDegrees(mean), 3, "tshirt-turn: the shirt's mean turn " + t + " s into the body's");
            }
        }
    }

    static MeshCollider theBody(Scene scene) {
        MeshCollider body = null;
        for (RigidCollider c : scene.simulation().solids()) if (c instanceof MeshCollider) body = (MeshCollider) c;
        assertNotNull(body);
        return body;
    }

    static void sewsShutOnTheDressForm(String garment, int threads) {
        Scene scene = Scene.builtIn(garment);
        MeshCollider form = theBody(scene);
        sewsShut(scene, threads, 50, (x, y, z) -> form.signedDistance(x, y, z) < 0);
    }

    @Test
    void theBorderedTableclothIsSewnShutWithoutCrossingItselfOrTheTable() {
        for (int threads : new int[] {1, 2}) {
            Scene scene = Scene.builtIn("bordered-tablecloth");
            Preset.SolidSpec table = scene.preset().solids.get(0);
            double[] c = table.path.centre, h = table.halfExtents;
            // 150 steps: it lands on the table, its corners fold over the table's and its border hangs.
            sewsShut(scene, threads, 150, (x, y, z) -> Math.abs(x - c[0]) < h[0] && Math.abs(y - c[1]) < h[1] && Math.abs(z - c[2]) < h[2]);
        }
    }

    interface Inside { boolean at(double x, double y, double z); }

    static void sewsShut(Scene scene, int threads, int stepsAfter, Inside body) {
        Simulation sim = scene.simulation();
        sim.settings(sim.settings().withThreads(threads));
        String name = scene.preset().name + " on " + threads + " thread" + (threads == 1 ? "" : "s");
        PatternMesh pattern = scene.preset().cloth.garment.pattern;
        assertArrayEquals(pattern.triangles(), scene.cloth().triangles(), "the cloth is the panels' triangles");
        Set<String> distinct = new HashSet<>();
        int[] t = pattern.triangles();
        for (int k = 0; k < t.length; k += 3) {
            int[] c = {t[k], t[k + 1], t[k + 2]};
            java.util.Arrays.sort(c);
            assertTrue(distinct.add(java.util.Arrays.toString(c)), "triangle " + k / 3 + " once");
        }
        int panels = 0;
        for (int i = 0; i < pattern.pattern.panels().size(); i++) panels += pattern.panelTriangleRange(i)[1] - pattern.panelTriangleRange(i)[0];
        assertEquals(panels, scene.cloth().triangles().length / 3);

        double time = scene.preset().cloth.garment.sewingTime, dt = sim.settings().timestep();
        int sewingSteps = (int) Math.ceil(time / dt - 1e-9);
        for (int step = 1; step <= sewingSteps + stepsAfter; step++) {
            sim.step();
            assertEquals(0, scene.crossingPairs(), name + ": crossing triangle pairs after step " + step);
            if (step == sewingSteps) {
                assertTrue(scene.sewing().closed(), name + ": closed by the sewing time");
                double[] x = sim.particles().positions();
                for (Seam s : pattern.pattern.seams()) {
                    int[] st = pattern.stitches(s.name);
                    for (int k = 0; k < st.length; k += 2) {
                        double gap = Math.sqrt(sq(x[3 * st[k]] - x[3 * st[k + 1]]) + sq(x[3 * st[k] + 1] - x[3 * st[k + 1] + 1]) + sq(x[3 * st[k] + 2] - x[3 * st[k + 1] + 2]));
                        assertTrue(gap < 1e-3, name + ": seam \"" + s.name + "\" stitch " + k / 2 + " is " + gap + " m apart");
                    }
                }
            }
            if (step % 5 == 0) {
                double[] x = sim.particles().positions();
                for (int i = 0; i < x.length / 3; i++)
                    assertFalse(body.at(x[3 * i], x[3 * i + 1], x[3 * i + 2]), name + ": particle " + i + " inside the body after step " + step);
            }
        }
    }

    static double sq(double v) { return v * v; }
}
