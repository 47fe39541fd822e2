package xpbdcloth.scene;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SimulationDivergedException;
import xpbdcloth.engine.SolverType;

/**
 * Lift is bounded by the flow that makes it: a plate cannot be pushed faster than the air moves past it.
 * The hostile-input report's reproducer (no drag, C_L = 1, a 30 m/s flow) flung a 16² cloth 319 m away at
 * 2.9e4 m/s in 21 steps and then threw from inside the forces stage; now every particle stays within the
 * air's speed plus what gravity alone can add, under every solver.
 */
class LiftBoundTest {
    static final String LIFT = "{\"name\":\"lift\",\"cloth\":{\"columns\":16,\"rows\":16,\"width\":1.0,\"height\":1.0,\"plane\":\"vertical\","
            + "\"origin\":[0,1.6,0],\"arealDensity\":0.2,\"pins\":[\"top-left\",\"top-right\"]},\"families\":{\"structural\":{\"stiffness\":1,\"compliance\":1e-6}},"
            + "\"solver\":{\"mode\":\"XPBD\",\"iterations\":2,\"substeps\":10,\"dt\":0.02,\"mullerCorrection\":true,\"gravity\":[0,-9.81,0],\"type\":\"%s\"},"
            + "\"aerodynamics\":{\"density\":1.2,\"drag\":0,\"lift\":1.0,\"air\":[30,0,10]}}";

    @Test
    void liftCannotFlingTheCloth() {
        double air = Math.sqrt(30 * 30 + 10 * 10);
        for (SolverType type : SolverType.values()) {
            Simulation sim = Scene.of(PresetLoader.parse("lift.json", String.format(LIFT, type.label()))).simulation();
            int steps = 150;
            double fastest = 0;
            double[] last = sim.particles().positions().clone();
            for (int s = 0; s < steps; s++) {
                sim.step();
                double[] x = sim.particles().positions();
                for (int i = 0; i < x.length; i += 3) { // each particle's mean speed over the step
                    double dx = x[i] - last[i], dy = x[i + 1] - last[i + 1], dz = x[i + 2] - last[i + 2];
                    fastest = Math.max(fastest, Math.sqrt(dx * dx + dy * dy + dz * dz) / 0.02);
                }
                System.arraycopy(x, 0, last, 0, x.length);
            }
            // Pinned at two corners, the cloth is driven by the flow and by gravity only. A whipping hem may
            // outrun them somewhat (as a flag's does); explicit lift had it at 2.9e4 m/s within 21 steps.
            double bound = 2 * (air + 9.81 * steps * 0.02);
            assertTrue(fastest < bound, type.label() + ": fastest particle " + fastest + " m/s, bound " + bound);
        }
    }

    @Test
    void aStepThatThrowsIsRolledBack() {
        Simulation sim = Scene.of(PresetLoader.builtIn("hanging")).simulation();
        for (int s = 0; s < 3; s++) sim.step();
        double[] before = sim.particles().positions().clone();
        double t = sim.time();
        sim.add(new xpbdcloth.engine.ExternalForce() {
            @Override public void apply(Particles p, double time, double dt) {
                p.addForce(0, 1, 0, 0);          // half a force stage done …
                throw new IllegalArgumentException("a force past the engine's range");
            }
        });
        SimulationDivergedException e = assertThrows(SimulationDivergedException.class, sim::step);
        assertTrue(e.getMessage().contains("a force past the engine's range") && e.getMessage().contains("restored"), e.getMessage());
        assertArrayEquals(before, sim.particles().positions(), 0.0, "the state before the step, bit for bit");
        assertEquals(t, sim.time(), 0.0);
    }
}
