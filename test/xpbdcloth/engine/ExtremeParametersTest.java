package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import java.util.function.Consumer;
import org.junit.jupiter.api.Test;

/**
 * Extreme but legal parameters keep a hanging 8×8 cloth finite and bounded: no position leaves a 50 m
 * box around the pins (gravity alone moves a free particle 4.9 m in the 1 s these runs last) and no
 * structural edge stretches beyond 200× its rest length, in both modes. The strain bound is loose on
 * purpose: with dt = 0.1 s and 2 sweeps, or a 1e9 mass ratio, PBD and XPBD legitimately stretch edges
 * 27× and 67× (Gauss–Seidel cannot hold them); what must not happen is a blow-up.
 */
class ExtremeParametersTest {
    static void check(String what, Consumer<ClothBuilder> cloth, Consumer<SolverSettings> solver, Consumer<Simulation> extra, double seconds) {
        for (ConstraintMode mode : ConstraintMode.values()) {
            ClothBuilder b = new ClothBuilder().family(ConstraintFamily.STRUCTURAL, 1, 0).resolution(8, 8).size(0.5, 0.5).origin(0, 1, 0).pinTopCorners()
                    .family(ConstraintFamily.SHEAR, 0.5, 1e-3).family(ConstraintFamily.BEND, 0.2, 1e-2);
            cloth.accept(b);
            Cloth c = b.build();
            SolverSettings s = new SolverSettings().withMode(mode);
            solver.accept(s);
            Simulation sim = c.simulation(s);
            extra.accept(sim);
            int steps = Math.max(1, (int) Math.round(seconds / s.timestep()));
            for (int i = 0; i < steps; i++) sim.step();
            Particles p = sim.particles();
            assertTrue(Metrics.allFinite(p), what + " " + mode + ": finite");
            for (int i = 0; i < p.count(); i++)
                assertTrue(Math.abs(p.x(i)) < 50 && Math.abs(p.y(i) - 1) < 50 && Math.abs(p.z(i)) < 50, what + " " + mode + ": bounded, particle " + i);
            assertTrue(Metrics.maxStrain(sim, ConstraintFamily.STRUCTURAL) < 200, what + " " + mode + ": strain " + Metrics.maxStrain(sim, ConstraintFamily.STRUCTURAL));
        }
    }

    static final Consumer<ClothBuilder> NONE_B = b -> {};
    static final Consumer<SolverSettings> NONE_S = s -> {};
    static final Consumer<Simulation> NONE_X = x -> {};

    @Test void complianceZeroAndHuge() {
        check("alpha 0", b -> b.family(ConstraintFamily.STRUCTURAL, 1, 0), NONE_S, NONE_X, 1);
        check("alpha 1e3", b -> b.family(ConstraintFamily.STRUCTURAL, 1, 1e3), NONE_S, NONE_X, 0.5);
    }

    @Test void stiffnessZeroAndOne() {
        check("k 0", b -> b.family(ConstraintFamily.STRUCTURAL, 0, 1e-6), NONE_S, NONE_X, 0.5);
        check("k 1", b -> b.family(ConstraintFamily.STRUCTURAL, 1, 1e-6), NONE_S, NONE_X, 1);
    }

    @Test void iterationsAndSubsteps() {
        check("iterations 1", NONE_B, s -> s.withIterations(1), NONE_X, 1);
        check("iterations 1000", NONE_B, s -> s.withIterations(1000), NONE_X, 0.2);
        check("substeps 100", NONE_B, s -> s.withSubsteps(100), NONE_X, 0.2);
    }

    @Test void timesteps() {
        check("dt 1e-5", NONE_B, s -> s.withTimestep(1e-5), NONE_X, 0.01);
        check("dt 0.1", NONE_B, s -> s.withTimestep(0.1), NONE_X, 1);
    }

    @Test void massesFromMicrogramsToTonnes() {
        check("mass 1e-6..1e3", NONE_B, NONE_S, sim -> {
            Particles p = sim.particles();
            for (int i = 0; i < p.count(); i++) p.setMass(i, Math.pow(10, -6 + 9.0 * i / (p.count() - 1)));
        }, 1);
    }

    @Test void fastAndSpinningSpheres() {
        // 0.6 s: the sphere reaches the cloth at 0.5 s and, since it no longer passes through, carries what
        // it hits (a kinematic sphere against a cloth that cannot tear): 10 m on by the end, inside the bounds.
        check("sphere 100 m/s", NONE_B, NONE_S, sim -> sim.add(new Sphere(SpherePath.linear(0, 0.8, -50, 0, 0, 100), 0.2, 0.01, 0.5, 0.4)), 0.6);
        check("sphere 100 rad/s", NONE_B, NONE_S, sim -> sim.add(new Sphere(SpherePath.fixed(0, 0.6, 0.05), 0.2, 0.01, 1, 1).spin(100, 0, 100)), 1);
    }
}
