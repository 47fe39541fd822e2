package xpbdcloth.experiments;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/** The simplex search experiment 9 fits PBD's k with, against minima known in closed form. */
class NelderMeadTest {
    @Test
    void findsTheMinimumOfAScaledShiftedQuadraticInThreeDimensions() {
        int[] calls = {0};
        double[] u = NelderMead.minimise(x -> {
            calls[0]++;
            return 3 * Math.pow(x[0] - 1, 2) + 0.5 * Math.pow(x[1] + 2, 2) + 10 * Math.pow(x[2] - 0.5, 2) + (x[0] - 1) * (x[1] + 2);
        }, new double[] {0, 0, 0}, 2000);
        assertArrayEquals(new double[] {1, -2, 0.5}, u, 1e-3);
        assertTrue(calls[0] <= 2000, "evaluations within the budget: " + calls[0]);
    }

    /** Rosenbrock's banana, min at (1, 1), from the classic start (−1.2, 1): a curved valley that defeats naive steps. */
    @Test
    void followsRosenbrocksValleyToItsMinimum() {
        double[] u = NelderMead.minimise(x -> 100 * Math.pow(x[1] - x[0] * x[0], 2) + Math.pow(1 - x[0], 2), new double[] {-1.2, 1}, 4000);
        assertArrayEquals(new double[] {1, 1}, u, 1e-2);
    }

    @Test
    void stopsAtItsBudget() {
        int[] calls = {0};
        NelderMead.minimise(x -> { calls[0]++; return -x[0]; }, new double[] {0, 0}, 50); // unbounded below
        assertTrue(calls[0] <= 50 + 2, "at most the budget (plus a shrink's extra points): " + calls[0]);
    }
}
