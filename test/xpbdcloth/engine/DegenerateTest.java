package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/** Degenerate geometry never produces NaN or Inf, in either mode. */
class DegenerateTest {
    static Simulation sim(Particles p, Constraint... cs) {
        Simulation s = new Simulation(p, new SolverSettings().withIterations(5));
        for (Constraint c : cs) s.add(c);
        return s;
    }

    static void stepBothModes(Simulation s, int steps) {
        for (ConstraintMode m : ConstraintMode.values()) {
            s.settings(s.settings().withMode(m));
            for (int i = 0; i < steps; i++) {
                s.step();
                assertTrue(Metrics.allFinite(s.particles()), m + " step " + i);
                for (Constraint c : s.constraints()) assertTrue(Double.isFinite(c.lambda()), m + " λ finite");
            }
        }
    }

    @Test
    void coincidentParticlesAndZeroRestLength() {
        Particles p = new Particles(3);
        p.pin(0);
        DistanceConstraint coincident = new DistanceConstraint(ConstraintFamily.STRUCTURAL, 0, 1, 0.5);
        DistanceConstraint zero = new DistanceConstraint(ConstraintFamily.STRUCTURAL, 1, 2, 0);
        zero.setCompliance(1e-3);
        stepBothModes(sim(p, coincident, zero), 50);
    }

    @Test
    void parallelAndAntiParallelShearEdges() {
        Particles p = new Particles(5);
        p.setPosition(1, 1, 0, 0);
        p.setPosition(2, 2, 0, 0);   // parallel with 0→1
        p.setPosition(3, -1, 0, 0);  // anti-parallel with 0→1
        p.setPosition(4, 0, 0, 0);   // zero-length edge
        Simulation s = sim(p, new ShearConstraint(ConstraintFamily.SHEAR, 0, 1, 2, Math.PI / 2),
                new ShearConstraint(ConstraintFamily.SHEAR, 0, 1, 3, Math.PI / 2),
                new ShearConstraint(ConstraintFamily.SHEAR, 0, 1, 4, Math.PI / 2));
        s.settings(s.settings().withGravity(0, 0, 0));
        stepBothModes(s, 50);
    }

    @Test
    void collinearAndCollapsedBendTriples() {
        Particles p = new Particles(6);
        p.setPosition(1, 1, 0, 0);
        p.setPosition(2, 2, 0, 0);   // collinear, rest 0
        // 3, 4, 5 all at the origin: collapsed
        Simulation s = sim(p, new BendConstraint(ConstraintFamily.BEND, 0, 1, 2, 0), new BendConstraint(ConstraintFamily.BEND, 3, 4, 5, 0.1));
        s.settings(s.settings().withGravity(0, 0, 0));
        stepBothModes(s, 50);
        assertEquals(0, p.y(1), 0.0, "a straight triple at rest stays straight");
    }

    @Test
    void particleAtSphereCentreAndAllPinnedConstraint() {
        Particles p = new Particles(3);
        p.pin(1);
        p.pin(2);
        p.setPosition(2, 1, 0, 0);
        DistanceConstraint pinnedPair = new DistanceConstraint(ConstraintFamily.STRUCTURAL, 1, 2, 3);
        pinnedPair.setCompliance(1e-4);
        Simulation s = sim(p, pinnedPair);
        s.add(new Sphere(SpherePath.fixed(0, 0, 0), 0.5, 0.01, 1, 1).spin(0, 100, 0));
        stepBothModes(s, 20);
        assertEquals(1.0, p.x(2), 0.0, "pinned particles of an unsatisfiable constraint stay put");
    }

    @Test
    void zeroAreaCloth() {
        Cloth c = new ClothBuilder().family(ConstraintFamily.STRUCTURAL, 1, 0).resolution(6, 6).size(0, 0).totalMass(0.1)
                .family(ConstraintFamily.SHEAR, 1, 0).family(ConstraintFamily.BEND, 1, 0).pin(0, 0).build();
        stepBothModes(c.simulation(new SolverSettings()), 50);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new ClothBuilder().family(ConstraintFamily.STRUCTURAL, 1, 0).size(0, 1).arealDensity(0.2).build());
        assertTrue(e.getMessage().startsWith("arealDensity"), e.getMessage());
    }

    /**
     * A cloth of no width (its five columns on one another, a line of rows 5 cm apart) has no angle at its corners
     * to keep, so it gets no shear rows; a grab moving one of its particles sideways by 0.1 mm a step (5 m/s, the
     * fuzzer's seed 198) then gives it no more kinetic energy than the hand's work, under every solver. With a
     * rest angle of π/2 at those corners, the angle's energy leapt from nothing to ½(θ − π/2)²/α as the grab
     * opened a side: 0.57 J from a hand that had done −0.53 J, particles at 7.7 m/s.
     */
    @Test
    void aClothOfNoWidthGetsNoShearAndAGrabGivesItOnlyTheHandsWork() {
        ClothBuilder grid = new ClothBuilder().resolution(5, 10).size(0, 0.45).plane(ClothBuilder.Plane.VERTICAL).origin(0, 1, 0).totalMass(0.3)
                .family(ConstraintFamily.STRUCTURAL, 0.05, 34).family(ConstraintFamily.SHEAR, 0.5, 1.3e-3).pin(0, 0).pin(9, 4);
        Cloth c = grid.build();
        for (ConstraintBlock b : c.simulation(new SolverSettings()).blocks())
            if (b.family() == ConstraintFamily.SHEAR) assertEquals(0, b.count(), "shear rows on a cloth of no width");
        Cloth wide = new ClothBuilder().resolution(5, 10).size(0.2, 0.45).totalMass(0.3).family(ConstraintFamily.SHEAR, 0.5, 1.3e-3).build();
        assertTrue(wide.simulation(new SolverSettings()).blocks().get(0).count() > 0, "a cloth with width keeps its corners' angles");
        for (SolverType solver : SolverType.values()) {
            Simulation sim = grid.build().simulation(new SolverSettings().withSolver(solver).withIterations(10).withSubsteps(8).withTimestep(2.4e-5));
            Particles p = sim.particles();
            AttachmentConstraint hand = sim.attach(5, p.x(5), p.y(5), p.z(5));
            java.util.Random r = new java.util.Random(198);
            double gravity = Metrics.gravitationalEnergy(p, sim.settings());
            for (int step = 0; step < 20; step++) {
                hand.moveTarget(hand.targetX() + 1.2e-4 * r.nextGaussian(), hand.targetY() + 1.2e-4 * r.nextGaussian(), hand.targetZ());
                sim.step();
                double given = gravity - Metrics.gravitationalEnergy(p, sim.settings()) + Math.max(0, sim.workByAttachments());
                assertTrue(Metrics.kineticEnergy(p) <= 1.01 * given + 1e-6,
                        solver + " step " + step + ": kinetic energy " + Metrics.kineticEnergy(p) + " J from gravity and a hand that gave " + given + " J");
            }
            sim.close();
        }
    }
}
