package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/** Sphere contact and Coulomb friction against a moving surface. */
class SphereContactTest {
    static final double R = 0.5;

    /**
     * A particle resting on a unit-friction sphere 10° from its top: gravity's tangential part is
     * g·sin 10° ≈ 0.17 g, below μₛ·g·cos 10° for μₛ = 1, so static friction holds it; with μ = 0 it
     * slides off.
     */
    static double slideAfterTwoSeconds(double mu) {
        Particles p = new Particles(1);
        double a = Math.toRadians(10);
        p.setPosition(0, R * Math.sin(a), R * Math.cos(a), 0);
        Simulation sim = new Simulation(p, new SolverSettings().withTimestep(1 / 60.0).withSubsteps(4));
        sim.add(new Sphere(SpherePath.fixed(0, 0, 0), R, 0, mu, mu));
        for (int s = 0; s < 120; s++) sim.step();
        return Math.atan2(p.x(0), p.y(0)) - a;
    }

    @Test
    void staticFrictionHoldsAndNoFrictionSlides() {
        double held = slideAfterTwoSeconds(1.0), slid = slideAfterTwoSeconds(0.0);
        System.out.printf("on the sphere after 2 s: mu=1 moved %.2e rad, mu=0 moved %.3f rad%n", held, slid);
        assertTrue(Math.abs(held) < 1e-3, "static friction holds the particle: moved " + held + " rad");
        assertTrue(slid > 0.5, "without friction it slides away: moved " + slid + " rad");
    }

    /**
     * On top of a sphere spinning with ω = (0, 0, 3) rad/s, the surface at r = (0, R, 0) moves with
     * ω × r = (−1.5, 0, 0) m/s. The particle slips, so kinetic friction accelerates it at μₖ·g in −x
     * (Coulomb: friction force μₖ·N with N = m·g): after 0.1 s its speed is μₖ·g·0.1 = 0.785 m/s.
     */
    @Test
    void spinningSphereCarriesParticleAlongOmegaCrossR() {
        Particles p = new Particles(1);
        p.setPosition(0, 0, R, 0);
        double muK = 0.8;
        Simulation sim = new Simulation(p, new SolverSettings().withTimestep(1 / 60.0).withSubsteps(4));
        sim.add(new Sphere(SpherePath.fixed(0, 0, 0), R, 0, 1.0, muK).spin(0, 0, 3));
        for (int s = 0; s < 6; s++) sim.step();
        double expected = -muK * 9.81 * 0.1;
        System.out.printf("spinning sphere: particle vx %.4f m/s after 0.1 s, Coulomb %.4f m/s%n", p.vx(0), expected);
        assertTrue(p.x(0) < 0, "carried towards -x, x = " + p.x(0));
        assertEquals(expected, p.vx(0), 0.03 * -expected, "accelerates at mu_k g");
        assertEquals(0.0, p.z(0), 1e-12, "no motion along ω");
    }

    /** A particle exactly at the centre has no normal: it leaves along +y, finite. */
    @Test
    void particleAtCentreIsPushedOutUp() {
        Particles p = new Particles(1);
        Simulation sim = new Simulation(p, new SolverSettings().withGravity(0, 0, 0));
        sim.add(new Sphere(SpherePath.fixed(0, 0, 0), R, 0.01, 0.5, 0.5));
        sim.step();
        assertTrue(Metrics.allFinite(p));
        // Deep inside, it comes out no faster than the depenetration speed (0.2 m in a 20 ms step) …
        assertEquals(Collider.MAX_DEPENETRATION_SPEED * 0.02, p.y(0), 1e-12);
        sim.step();
        sim.step();
        // … and leaves with that speed, not faster: out of the ball (R + margin = 0.51 m) after three steps.
        assertEquals(3 * Collider.MAX_DEPENETRATION_SPEED * 0.02, p.y(0), 1e-12);
        assertTrue(p.y(0) > R + 0.01);
    }
}
