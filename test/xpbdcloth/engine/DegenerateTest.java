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
}
