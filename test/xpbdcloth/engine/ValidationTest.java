package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;

/** Every rule at the API edge throws IllegalArgumentException naming the parameter and the value. */
class ValidationTest {

    static void rejects(String parameter, String value, Executable call) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, call);
        assertTrue(e.getMessage().startsWith(parameter + " "), "names " + parameter + ": " + e.getMessage());
        assertTrue(e.getMessage().endsWith(value), "names the value " + value + ": " + e.getMessage());
    }

    @Test
    void solverSettings() {
        SolverSettings s = new SolverSettings();
        rejects("iterations", "0", () -> s.withIterations(0));
        rejects("substeps", "-2", () -> s.withSubsteps(-2));
        rejects("dt", "0.0", () -> s.withTimestep(0));
        rejects("dt", "-0.01", () -> s.withTimestep(-0.01));
        rejects("dt", "NaN", () -> s.withTimestep(Double.NaN));
        rejects("dt", "Infinity", () -> s.withTimestep(Double.POSITIVE_INFINITY));
        rejects("gravity.y", "NaN", () -> s.withGravity(0, Double.NaN, 0));
        rejects("mode", "null", () -> s.withMode(null));
        assertEquals(2, s.iterations(), "a rejected call changes nothing");
        assertEquals(0.02, s.timestep());
    }

    @Test
    void constraintParameters() {
        DistanceConstraint c = new DistanceConstraint(ConstraintFamily.STRUCTURAL, 0, 1, 1);
        rejects("stiffness", "1.5", () -> c.setStiffness(1.5));
        rejects("stiffness", "-0.1", () -> c.setStiffness(-0.1));
        rejects("stiffness", "NaN", () -> c.setStiffness(Double.NaN));
        rejects("compliance", "-1.0E-6", () -> c.setCompliance(-1e-6));
        rejects("compliance", "NaN", () -> c.setCompliance(Double.NaN));
        rejects("restLength", "-1.0", () -> new DistanceConstraint(ConstraintFamily.STRUCTURAL, 0, 1, -1));
        assertEquals(1.0, c.stiffness());
        assertEquals(0.0, c.compliance());
    }

    @Test
    void particles() {
        Particles p = new Particles(3);
        rejects("mass", "-1.0", () -> p.setMass(0, -1));
        rejects("mass", "0.0", () -> p.setMass(0, 0));
        rejects("mass", "NaN", () -> p.setMass(0, Double.NaN));
        rejects("position.x", "NaN", () -> p.setPosition(0, Double.NaN, 0, 0));
        rejects("particle", "3", () -> p.setPosition(3, 0, 0, 0));
        rejects("particleCount", "0", () -> new Particles(0));
        rejects("constraint particle", "5", () -> new Simulation(p, new SolverSettings())
                .add(new DistanceConstraint(ConstraintFamily.STRUCTURAL, 0, 5, 1)));
        assertEquals(1.0, p.mass(0));
    }

    @Test
    void stepAndBuilder() {
        Simulation sim = new Simulation(new Particles(2), new SolverSettings());
        rejects("dt", "0.0", () -> sim.step(0));
        rejects("dt", "NaN", () -> sim.step(Double.NaN));
        rejects("columns", "0", () -> new ClothBuilder().resolution(0, 4));
        rejects("arealDensity", "-2.0", () -> new ClothBuilder().arealDensity(-2));
        rejects("width", "NaN", () -> new ClothBuilder().size(Double.NaN, 1));
        rejects("pin row", "9", () -> new ClothBuilder().resolution(4, 4).pin(9, 0).build());
        rejects("radius", "0.0", () -> new Sphere(SpherePath.fixed(0, 0, 0), 0, 0, 0, 0));
        rejects("staticFriction", "-1.0", () -> new Sphere(SpherePath.fixed(0, 0, 0), 1, 0, -1, 0));
        assertEquals(0.0, sim.time());
    }
}
