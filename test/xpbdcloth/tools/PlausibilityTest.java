package xpbdcloth.tools;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SolverSettings;

/** The fuzzer's energy bound: a cloth falling under gravity alone is within it, one given speed from nowhere is not. */
class PlausibilityTest {
    @Test
    void freeFallIsWithinTheBoundAndAKickFromNowhereIsNot() {
        Simulation sim = new ClothBuilder().resolution(8, 8).size(1, 1).plane(ClothBuilder.Plane.HORIZONTAL).origin(0, 2, 0)
                .arealDensity(0.2).family(ConstraintFamily.STRUCTURAL, 1, 1e-6).build().simulation(new SolverSettings().withIterations(5).withSubsteps(4));
        Plausibility bound = new Plausibility(sim);
        for (int s = 0; s < 30; s++) {
            sim.step();
            assertNull(bound.check(0), "step " + s + ": free fall converts potential energy into kinetic, no more");
        }
        // 0.6 s of free fall: v = g t = 5.9 m/s. Every particle at 3 m/s more than gravity gave it is over
        // the bound with no driver, and within it with drivers of 2 m/s (they can give up to 4 m/s).
        Particles p = sim.particles();
        for (int i = 0; i < p.count(); i++) p.setVelocity(i, 3, p.vy(i), 0);
        assertNotNull(bound.check(0), "speed no driver gave");
        assertNull(bound.check(2), "speed drivers of 2 m/s could have given");
    }
}
