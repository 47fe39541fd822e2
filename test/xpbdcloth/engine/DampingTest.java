package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/** The velocity pass: damping that decays as e^(−c·t) whatever the step and substeps. */
class DampingTest {

    /** A free particle in zero gravity, given v₀, after T = 1 s: v₀·e^(−c·T) for every dt and substep count. */
    @Test
    void decayIsFrameRateIndependent() {
        double c = 2.5, v0 = 3.0, T = 1.0;
        double expected = v0 * Math.exp(-c * T);
        for (double dt : new double[] {1 / 30.0, 1 / 60.0, 1 / 240.0})
            for (int substeps : new int[] {1, 4}) {
                Particles p = new Particles(1);
                p.setVelocity(0, v0, 0, 0);
                Simulation sim = new Simulation(p, new SolverSettings().withGravity(0, 0, 0).withDamping(c).withTimestep(dt).withSubsteps(substeps));
                int steps = (int) Math.round(T / dt);
                for (int s = 0; s < steps; s++) sim.step();
                assertEquals(expected, p.vx(0), 1e-11 * v0, "dt " + dt + ", substeps " + substeps); // 960 roundings at most
                // The position is the integral of the decaying velocity, as the symplectic Euler sum gives it:
                // within O(h) of the closed form v₀(1 − e^(−cT))/c.
                double h = dt / substeps;
                assertEquals(v0 * (1 - Math.exp(-c * T)) / c, p.x(0), 2 * c * v0 * h, "position, dt " + dt);
            }
    }

    /** Pinned particles keep their (scripted or zero) velocity; damping is a free particle's. */
    @Test
    void pinnedParticlesAreNotDamped() {
        Particles p = new Particles(2);
        p.setPosition(1, 0.1, 0, 0);
        p.pin(0);
        Simulation sim = new Simulation(p, new SolverSettings().withDamping(50));
        sim.add((Kinematics) (ps, t) -> ps.moveKinematic(0, t, 0, 0)); // 1 m/s along x
        for (int s = 0; s < 10; s++) sim.step();
        assertEquals(1.0, p.vx(0), 1e-9, "the scripted pin moves at its own speed");
    }

    @Test
    void dampingOutsideItsRangeIsRefusedNamingIt() {
        SolverSettings s = new SolverSettings();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> s.withDamping(-1));
        assertTrue(e.getMessage().startsWith("damping") && e.getMessage().endsWith("was -1.0"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> s.withDamping(Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> s.withDamping(2 * EngineRange.MAX_DAMPING));
        assertEquals(0, s.damping());
        assertEquals(3.0, s.withDamping(3).damping());
    }
}
