package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * A grab is a hand that moves continuously: its target glides over a step's substeps, so a particle let
 * go after a drag leaves with the hand's velocity (before, the target jumped at the step's start, the
 * particle reached it in the first substep and stood still for the rest: it left at 0 m/s and a cloth
 * could not be thrown).
 */
class AttachmentGlideTest {
    static final double DT = 0.02, STEP_MOVE = 0.01; // the hand at 0.5 m/s

    @Test
    void aParticleLetGoLeavesWithTheHandsVelocity() {
        Particles p = new Particles(1);
        Simulation sim = new Simulation(p, new SolverSettings().withGravity(0, 0, 0).withTimestep(DT).withSubsteps(10).withIterations(1));
        AttachmentConstraint hand = sim.attach(0, 0, 0, 0);
        for (int step = 1; step <= 5; step++) {
            hand.moveTarget(step * STEP_MOVE, 0, 0);
            sim.step();
            assertEquals(step * STEP_MOVE, p.x(0), 1e-12, "at the hand at the end of each step");
        }
        double hand_v = STEP_MOVE / DT;
        assertEquals(hand_v, p.vx(0), 1e-9, "moving with the hand when let go (m/s)");
        assertEquals(STEP_MOVE, hand.targetX() - 4 * STEP_MOVE, 1e-15, "the target reads as asked");
        sim.release(hand);
        sim.step();
        assertEquals(6 * STEP_MOVE, p.x(0), 1e-9, "thrown: it carries on at the hand's speed");
    }

    /** A target that is not moved stays put in every substep: attachments held still are as before. */
    @Test
    void aStillTargetHoldsItsParticleWhereItWas() {
        Particles p = new Particles(1);
        p.setPosition(0, 0.3, -0.2, 0.1);
        Simulation sim = new Simulation(p, new SolverSettings().withTimestep(DT).withSubsteps(4).withIterations(2));
        sim.attach(0, 0.3, -0.2, 0.1);
        for (int step = 0; step < 50; step++) sim.step();
        assertEquals(-0.2, p.y(0), 1e-12, "held against gravity by a hard attachment");
    }

    /**
     * The work a hand does, counted as force times the target's move in each substep, against the closed form:
     * lifting a particle of mass m at speed v against gravity g for a height Δh takes m g Δh, and catching it
     * up from rest takes m v² (half of it the kinetic energy ½ m v² it leaves with, half what implicit Euler's
     * inelastic catch dissipates). A hand held still does none. Every solver: vertex block descent holds the
     * particle on the target and charges the hand the force that takes, the others project it there.
     */
    @ParameterizedTest
    @EnumSource(SolverType.class)
    void aHandLiftingAParticleDoesTheWorkOfTheLiftAndTheCatch(SolverType solver) {
        Particles p = new Particles(1);
        p.setMass(0, 0.5);
        Simulation sim = new Simulation(p, new SolverSettings().withSolver(solver).withTimestep(DT).withSubsteps(10).withIterations(2));
        AttachmentConstraint hand = sim.attach(0, 0, 0, 0);
        for (int step = 0; step < 10; step++) sim.step();
        assertEquals(0, sim.workByAttachments(), 1e-15, "a still hand holding the particle up does no work");
        int steps = 40;
        for (int step = 1; step <= steps; step++) {
            hand.moveTarget(0, step * STEP_MOVE, 0);
            sim.step();
        }
        double m = 0.5, g = 9.81, v = STEP_MOVE / DT, lift = steps * STEP_MOVE;
        assertEquals(m * g * lift + m * v * v, sim.workByAttachments(), 1e-9 * (m * g * lift), "W = m g Δh + m v² (J)");
        assertEquals(0.5 * m * v * v, 0.5 * m * p.vy(0) * p.vy(0), 1e-9, "it leaves with ½ m v²");
    }
}
