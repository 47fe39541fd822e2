package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The coloured order and its parallel solve. */
class ColouredOrderTest {

    @Test
    void noTwoConstraintsOfAColourShareAParticle() {
        Simulation sim = Rigs.clothWithSphere(false);
        Colouring c = Colouring.of(sim.blocks(), sim.particles().count());
        int coloured = 0;
        for (int k = 0; k < c.colours; k++) {
            Set<Integer> seen = new HashSet<>();
            for (int b = 0; b < c.blocks.size(); b++)
                for (int j = c.start[b][k]; j < c.start[b][k + 1]; j++, coloured++)
                    for (int a = 0; a < c.blocks.get(b).arity(); a++) {
                        int p = c.blocks.get(b).particle(c.order[b][j], a);
                        assertTrue(seen.add(p), "colour " + k + " shares particle " + p);
                    }
        }
        assertEquals(sim.constraints().length, coloured, "every constraint has a colour");
        System.out.printf("32x32 cloth and a sphere: %d constraints in %d colours%n", coloured, c.colours);
    }

    /** Within a colour nothing interacts, so 2 and 3 threads give the very bits of 1 thread. */
    @Test
    void parallelIsBitwiseTheColouredSequentialSolve() {
        double[][] out = new double[3][];
        for (int t = 1; t <= 3; t++) {
            Simulation sim = Rigs.clothWithSphere(true);
            sim.settings(sim.settings().withOrder(ConstraintOrder.COLOURED).withThreads(t));
            for (int s = 0; s < 200; s++) sim.step();
            sim.close();
            out[t - 1] = sim.particles().positions().clone();
        }
        assertArrayEquals(out[0], out[1], 0.0, "2 threads");
        assertArrayEquals(out[0], out[2], 0.0, "3 threads");
    }

    /** Colouring changes the path, not the physics: the XPBD chain still settles on Hooke's law. */
    @Test
    void colouredOrderKeepsTheClosedForm() {
        SolverSettings s = new SolverSettings().withMode(ConstraintMode.XPBD).withIterations(50).withTimestep(1 / 60.0).withOrder(ConstraintOrder.COLOURED);
        Simulation sim = Rigs.chain(10, 0.01, 0.1, s, 1, 1e-2);
        Rigs.settle(sim, 1e-10, 100_000);
        Particles p = sim.particles();
        for (int i = 0; i < 10; i++) {
            double expected = 1e-2 * Rigs.G * 0.01 * (10 - i);
            assertEquals(expected, p.y(i) - p.y(i + 1) - 0.1, 0.01 * expected, "link " + i);
        }
    }

    @Test
    void threadCountIsValidated() {
        SolverSettings s = new SolverSettings();
        ValidationTest.rejects("threads", "0", () -> s.withThreads(0));
        ValidationTest.rejects("threads", "65", () -> s.withThreads(65));
        assertEquals(ConstraintOrder.COLOURED, s.withThreads(2).order(), "more than one thread implies the coloured order");
    }
}
