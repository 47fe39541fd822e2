package xpbdcloth.tools;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SolverSettings;

/**
 * The fuzzer's energy bound: a cloth falling under gravity alone is within it, one given speed from nowhere is
 * not, and one let go from the strain a solver switch found is, up to that strain.
 */
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

    /**
     * A cloth of stiff springs (α = 1e-8 m/N) stretched by 1 % with no work done on it, as a few Gauss–Seidel
     * sweeps leave one: speed worth half its strain is over the bound (nothing gave it), and within it once a
     * solver switch has found that strain; speed worth twice the strain is over it still.
     */
    @Test
    void speedFromTheStrainASolverSwitchFoundIsWithinTheBoundAndNoMore() {
        Simulation sim = new ClothBuilder().resolution(8, 8).size(1, 1).plane(ClothBuilder.Plane.HORIZONTAL).origin(0, 2, 0)
                .arealDensity(0.2).family(ConstraintFamily.STRUCTURAL, 1, 1e-8).build().simulation(new SolverSettings().withGravity(0, 0, 0));
        Plausibility bound = new Plausibility(sim);
        Particles p = sim.particles();
        for (int i = 0; i < p.count(); i++) p.setPosition(i, 1.01 * p.x(i), p.y(i), 1.01 * p.z(i));
        double strain = xpbdcloth.engine.Metrics.elasticEnergy(sim), mass = 0;
        for (int i = 0; i < p.count(); i++) mass += p.mass(i);
        assertTrue(strain > 1, "a 1 % stretch of springs of 1e8 N/m holds " + strain + " J");
        setSpeedWorth(p, mass, 0.5 * strain);
        assertNotNull(bound.check(0), "speed worth half the strain, before any switch found it");
        bound.switchedSolver();
        assertNull(bound.check(0), "speed worth half the strain the switch found");
        setSpeedWorth(p, mass, 2 * strain);
        assertNotNull(bound.check(0), "speed worth twice the strain the switch found");
    }

    /** Every particle at the one speed that makes the kinetic energy {@code joules}, along x. */
    private static void setSpeedWorth(Particles p, double mass, double joules) {
        double speed = Math.sqrt(2 * joules / mass);
        for (int i = 0; i < p.count(); i++) p.setVelocity(i, speed, 0, 0);
    }
}
