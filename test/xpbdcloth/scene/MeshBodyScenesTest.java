package xpbdcloth.scene;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import xpbdcloth.engine.MeshCollider;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.RigidCollider;
import xpbdcloth.engine.Simulation;

/**
 * The scenes with triangle-mesh bodies, for 10 s at the sketch's two threads: in every step no particle is
 * inside the body by more than a tenth of the cloth's thickness (signed distance by winding number, so a
 * particle caught where the body's parts overlap counts as inside); and the parallel solve gives the bits
 * of the sequential one (a contact's scratch shared between threads once made the poncho explode).
 */
@Tag("slow")
class MeshBodyScenesTest {
    static MeshCollider body(Simulation sim) {
        for (RigidCollider s : sim.solids()) if (s instanceof MeshCollider) return (MeshCollider) s;
        throw new AssertionError("no mesh collider");
    }

    @ParameterizedTest
    @ValueSource(strings = {"mannequin-poncho", "mannequin-turn", "torus-spin"})
    void noParticleIsEverInsideTheBody(String name) {
        Scene scene = Scene.builtIn(name);
        Simulation sim = scene.simulation();
        sim.settings(sim.settings().withThreads(2));
        MeshCollider body = body(sim);
        Particles p = scene.cloth().particles();
        double thickness = 2 * body.margin(), worst = Double.MAX_VALUE;
        int worstStep = -1;
        for (int step = 0; step < 500; step++) {
            sim.step();
            for (int i = 0; i < p.count(); i++) {
                double d = body.signedDistance(p.x(i), p.y(i), p.z(i));
                if (d < worst) { worst = d; worstStep = step; }
            }
        }
        System.out.printf("%s, 10 s: closest particle %.2f mm from the body (margin %.1f mm; step %d)%n", name, 1e3 * worst, 1e3 * body.margin(), worstStep);
        assertTrue(worst >= -thickness / 10, name + ": a particle " + (-worst) + " m inside the body at step " + worstStep);
    }

    @Test
    void twoThreadsGiveTheBitsOfOne() {
        Scene one = Scene.builtIn("mannequin-poncho"), two = Scene.builtIn("mannequin-poncho");
        two.simulation().settings(two.simulation().settings().withThreads(2));
        for (int step = 0; step < 60; step++) { one.simulation().step(); two.simulation().step(); }
        assertArrayEquals(one.cloth().particles().positions(), two.cloth().particles().positions(), 0.0);
    }
}
