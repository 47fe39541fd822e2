package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/**
 * The colliders' work on the cloth (Simulation.workByColliders: each substep, the force of their projections on
 * a particle times its move) is what an energy balance needs to credit a moving solid. Implicit Euler's kinetic
 * energy change is F·Δx − h²|F|²/2m, so the counted work bounds what the solid gave from above: a sphere that
 * sweeps a resting cloth along has done at least the kinetic energy the cloth has, a fixed floor that stops a
 * falling cloth has taken energy out (negative work), and gravity plus the counted work bound the cloth's energy.
 */
class ColliderWorkTest {
    static Simulation cloth(double gravity) {
        Cloth c = new ClothBuilder().resolution(6, 6).size(0.5, 0.5).plane(ClothBuilder.Plane.HORIZONTAL).origin(0, 1, 0).arealDensity(0.2)
                .family(ConstraintFamily.STRUCTURAL, 1, 1e-6).build();
        return c.simulation(new SolverSettings().withIterations(5).withSubsteps(5).withTimestep(0.01).withGravity(0, gravity, 0));
    }

    @Test
    void aSphereSweepingARestingClothAlongHasDoneAtLeastTheKineticEnergyItGaveAndNoMoreThanTwice() {
        Simulation sim = cloth(0);
        Particles p = sim.particles();
        double cx = 0, cz = 0;
        for (int i = 0; i < p.count(); i++) { cx += p.x(i) / p.count(); cz += p.z(i) / p.count(); }
        // A sphere coming up from under the cloth's centre at 2 m/s, without friction: it lifts the cloth and carries it up.
        double v = 2;
        sim.add(new Sphere(SpherePath.linear(cx, 1 - 0.3, cz, 0, v, 0), 0.25, 0.005, 0, 0));
        for (int s = 0; s < 30; s++) sim.step();
        double kinetic = Metrics.kineticEnergy(p), work = sim.workByColliders();
        double mass = 0.2 * 0.25;
        assertTrue(kinetic > 0.05 * 0.5 * mass * v * v, "the sphere set the cloth moving: " + kinetic + " J");
        assertTrue(work >= kinetic, "the counted work " + work + " J covers the kinetic energy " + kinetic + " J");
        // What it gives beyond the kinetic energy is the contact's own loss in each push (h²|F|²/2m): a carried
        // particle is pushed from the sphere's speed minus what it lost back up to it, never more than twice.
        assertTrue(work <= 2 * mass * v * v + 1e-9, "no more than twice what the cloth carried at v could hold: " + work + " J");
        sim.close();
    }

    @Test
    void aFixedFloorStoppingAFallingClothTakesEnergyOutAndTheBalanceHolds() {
        Simulation sim = cloth(-9.81);
        Particles p = sim.particles();
        sim.add(Plane.floor(0.8, 0.005, 0.5, 0.4));
        double start = Metrics.gravitationalEnergy(p, sim.settings());
        double given = 0;
        for (int s = 0; s < 60; s++) {
            sim.step();
            given = start - Metrics.gravitationalEnergy(p, sim.settings());
            double kinetic = Metrics.kineticEnergy(p), work = sim.workByColliders();
            assertTrue(work <= 1e-12, "step " + s + ": a floor that does not move gives nothing: " + work + " J");
            assertTrue(kinetic <= given + work + 1e-3 * given + 1e-9,
                    "step " + s + ": kinetic " + kinetic + " J within gravity's " + given + " J less what the floor took, " + work + " J");
        }
        // Landed and at rest, the cloth has lost the fall's energy: a part of it to the floor's stop (the rest to
        // its own inelastic landing, each particle's stiff springs taking up its neighbours' impact).
        assertTrue(Metrics.kineticEnergy(p) < 0.01 * given, "at rest on the floor: " + Metrics.kineticEnergy(p) + " J");
        assertTrue(sim.workByColliders() < -0.2 * given, "the floor took energy out: " + sim.workByColliders() + " J of " + given + " J");
        sim.close();
    }
}
