package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import java.util.stream.Stream;
import org.junit.jupiter.params.provider.Arguments;

/** XPBD makes the spring a material: its static stretch is Hooke's, whatever the solver does. */
class XpbdSpringTest {

    static Stream<Arguments> iterationsAndTimesteps() {
        Stream.Builder<Arguments> b = Stream.builder();
        for (int n : new int[] {1, 2, 5, 20})
            for (double dt : new double[] {1 / 30.0, 1 / 60.0, 1 / 120.0}) b.add(Arguments.of(n, dt));
        return b.build();
    }

    /**
     * At rest the constraint force λ/h² balances the weight m·g, and XPBD's C = −α̃λ then gives
     * C = α·m·g: Hooke's law with stiffness 1/α, independent of n and h. It holds even for n = 1,
     * because a static state is a fixed point of the per-substep update for any sweep count.
     */
    @ParameterizedTest(name = "n={0}, dt={1}")
    @MethodSource("iterationsAndTimesteps")
    void staticStretchIsComplianceTimesWeight(int iterations, double dt) {
        double m = 0.1, alpha = 1e-3, L = 1.0;
        SolverSettings s = new SolverSettings().withMode(ConstraintMode.XPBD).withIterations(iterations).withTimestep(dt);
        Simulation sim = Rigs.spring(m, L, s, 1.0, alpha);
        Rigs.settle(sim, 1e-9, 200_000);
        double extension = -sim.particles().y(1) - L;
        double expected = alpha * m * Rigs.G;
        assertEquals(expected, extension, 0.01 * expected, "extension for n=" + iterations + " dt=" + dt);
        assertEquals(m * Rigs.G, sim.constraints()[0].force(dt), 0.01 * m * Rigs.G, "force λ/h² is the weight");
        assertEquals(0.0, sim.particles().x(0), 0.0);
        assertEquals(0.0, sim.particles().y(0), 0.0, "the pin never moves");
    }

    /** α = 0 is the hard limit: a single link converges to its rest length (one projection is exact). */
    @Test
    void zeroComplianceIsInextensible() {
        SolverSettings s = new SolverSettings().withMode(ConstraintMode.XPBD).withIterations(2).withTimestep(1 / 60.0);
        Simulation sim = Rigs.spring(0.5, 0.3, s, 1.0, 0.0);
        for (int i = 0; i < 500; i++) sim.step();
        double stretch = (-sim.particles().y(1)) / 0.3 - 1;
        assertTrue(Math.abs(stretch) < 1e-6, "relative stretch " + stretch);
    }

    /** Hanging chain, per-link compliance: link i carries the weight of everything below it. */
    @Test
    void chainLinksStretchByTheWeightBelow() {
        int links = 10;
        double m = 0.01, alpha = 1e-2, L = 0.1;
        SolverSettings s = new SolverSettings().withMode(ConstraintMode.XPBD).withIterations(50).withTimestep(1 / 60.0);
        Simulation sim = Rigs.chain(links, m, L, s, 1.0, alpha);
        Rigs.settle(sim, 1e-10, 100_000);
        Particles p = sim.particles();
        for (int i = 0; i < links; i++) {
            double stretch = p.y(i) - p.y(i + 1) - L;
            double expected = alpha * Rigs.G * m * (links - i);
            assertEquals(expected, stretch, 0.01 * expected, "link " + i);
        }
    }
}
