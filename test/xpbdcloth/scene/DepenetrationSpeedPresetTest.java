package xpbdcloth.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import xpbdcloth.engine.Simulation;

/**
 * A collider's depenetration speed is a preset field (PhysX's maximum depenetration velocity, per
 * collider): a cloth found under a floor placed 5 m above it rises at that speed, not faster and not
 * slower, and a speed outside its range is refused naming the field.
 */
class DepenetrationSpeedPresetTest {
    static String floorAbove(String speed) {
        return "{ \"name\": \"under\", \"cloth\": { \"columns\": 8, \"rows\": 8, \"width\": 1, \"height\": 1, \"origin\": [0, 1.6, 0], \"arealDensity\": 0.2 },"
                + " \"families\": { \"structural\": { \"stiffness\": 1, \"compliance\": 1e-6 } },"
                + " \"solver\": { \"mode\": \"XPBD\", \"iterations\": 2, \"substeps\": 10, \"dt\": 0.02 },"
                + " \"colliders\": [{ \"type\": \"plane\", \"point\": [0, 6, 0], \"normal\": [0, 1, 0], \"margin\": 0.005,"
                + " \"staticFriction\": 0.5, \"kineticFriction\": 0.4" + (speed == null ? "" : ", \"depenetrationSpeed\": " + speed) + " }] }";
    }

    /** How far the cloth's lowest particle rose in 1 s, m (it is under the floor all that second at 2 m/s or less). */
    static double riseInOneSecond(String speed) {
        Simulation sim = Scene.of(PresetLoader.parse("under.json", floorAbove(speed))).simulation();
        double start = lowest(sim);
        for (int s = 0; s < 50; s++) sim.step();
        return lowest(sim) - start;
    }

    static double lowest(Simulation sim) {
        double[] x = sim.particles().positions();
        double low = Double.MAX_VALUE;
        for (int i = 1; i < x.length; i += 3) low = Math.min(low, x[i]);
        return low;
    }

    @Test
    void theClothRisesAtTheFloorsDepenetrationSpeed() {
        // 2 m/s for 1 s, at two sweeps a substep (each sweep measured the depth afresh, and it rose 4 m).
        assertEquals(2.0, riseInOneSecond("2"), 1e-9);
        assertEquals(0.5, riseInOneSecond("0.5"), 1e-9);
        // The default, 10 m/s: the lowest particle, 4.4 m under, is out within the half second.
        assertTrue(riseInOneSecond(null) > 4.4);
    }

    @Test
    void aSpeedOutsideItsRangeIsRefusedNamingTheField() {
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.parse("under.json", floorAbove("0")));
        assertEquals("colliders[0].depenetrationSpeed", e.field());
        assertTrue(e.problem().contains("[0.01, 1000] m/s"), e.problem());
    }
}
