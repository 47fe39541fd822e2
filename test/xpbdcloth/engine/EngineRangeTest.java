package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;

/**
 * The engine's API refuses, where it enters, what used to be accepted and end in NaN or a raw exception
 * inside a step (each case from the hostile-input report), and stays finite at the edges of its ranges.
 */
class EngineRangeTest {

    static void refused(String parameter, Executable call) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, call, parameter);
        assertTrue(e.getMessage().startsWith(parameter + " must") || e.getMessage().startsWith(parameter + "."), "names " + parameter + ": " + e.getMessage());
    }

    @Test
    void particlesRefuseWhatWouldOverflow() {
        Particles p = new Particles(64);
        refused("force", () -> p.addForce(0, Double.NaN, 0, 0));
        refused("force", () -> p.addForce(0, Double.POSITIVE_INFINITY, 0, 0));
        refused("particle", () -> p.addForce(-1, 0, 0, 0));
        refused("position", () -> p.moveKinematic(0, Double.NaN, 0, 0));
        refused("particle", () -> p.moveKinematic(64, 0, 0, 0));
        refused("mass", () -> p.setMass(0, 1e-310));
        refused("position", () -> p.setPosition(0, 1e308, 0, 0));
        refused("velocity", () -> p.setVelocity(0, 0, 1e308, 0));
        refused("particleCount", () -> new Particles(Integer.MAX_VALUE));
    }

    @Test
    void buildersAndSettingsRefuseOutOfRange() {
        refused("columns*rows", () -> new ClothBuilder().resolution(30000, 30000));
        refused("columns*rows", () -> new ClothBuilder().resolution(46341, 46341));
        SolverSettings s = new SolverSettings();
        refused("dt", () -> s.withTimestep(1e-300));
        refused("dt", () -> s.withTimestep(1e-155));
        refused("gravity", () -> s.withGravity(0, -1e200, 0));
        refused("iterations", () -> s.withIterations(Integer.MAX_VALUE));
        refused("substeps", () -> s.withSubsteps(Integer.MAX_VALUE));
        refused("pcgMaxIterations", () -> s.withPcgMaxIterations(Integer.MAX_VALUE));
        Constraint c = new DistanceConstraint(ConstraintFamily.STRUCTURAL, 0, 1, 1);
        refused("compliance", () -> c.setCompliance(1e308));
        refused("radius", () -> new Sphere(SpherePath.fixed(0, 0, 0), 1e300, 0, 0, 0));
        refused("target", () -> new AttachmentConstraint(0, 1e308, 0, 0));
        Simulation sim = new Simulation(new Particles(64), new SolverSettings());
        refused("triangle 0 corner", () -> sim.add(new Wind(new int[] {0, 1, 99}, 1, 0, 0, 1, 0)));
    }

    /**
     * At the edges of the ranges the engine stays finite: the smallest dt with the largest compliance
     * (α/h² = 1e18), and the lightest particles under the strongest gravity at the longest step.
     */
    @Test
    void theEdgesOfTheRangesStayFinite() {
        for (double[] edge : new double[][] {{EngineRange.MIN_DT, EngineRange.MAX_COMPLIANCE, 1e-4, 9.81}, {EngineRange.MAX_DT, 0, EngineRange.MIN_MASS, EngineRange.MAX_GRAVITY}}) {
            Cloth cloth = new ClothBuilder().resolution(6, 6).size(0.5, 0.5).totalMass(200 * edge[2]).pinTopCorners()
                    .family(ConstraintFamily.STRUCTURAL, 1, edge[1]).family(ConstraintFamily.SHEAR, 1, edge[1]).family(ConstraintFamily.BEND, 1, edge[1]).build();
            for (SolverType type : SolverType.values()) {
                Simulation sim = cloth.simulation(new SolverSettings().withTimestep(edge[0]).withGravity(0, -edge[3], 0).withSolver(type));
                for (int i = 0; i < 20; i++) sim.step();
                assertTrue(Metrics.allFinite(cloth.particles()), type.label() + " at dt " + edge[0]);
            }
        }
    }
}
