package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/**
 * Classic PBD's stiffness is a property of the solver: the same chain, same k, stretches by different
 * amounts as the iteration count or the timestep changes. These tests pin down the direction and size.
 */
class PbdStiffnessTrapTest {
    static final int LINKS = 20;
    static final double M = 0.01, L = 0.05;

    static double stretch(int iterations, double dt, boolean muller, double k) {
        SolverSettings s = new SolverSettings().withMode(ConstraintMode.PBD).withIterations(iterations).withTimestep(dt).withMullerCorrection(muller);
        Simulation sim = Rigs.chain(LINKS, M, L, s, k, 0);
        Rigs.settle(sim, 1e-9, 20_000);
        return Rigs.totalExtension(sim, LINKS, L) / (LINKS * L);
    }

    /** More Gauss–Seidel sweeps enforce the links better: the chain stiffens with n. */
    @Test
    void stretchFallsWithIterations() {
        double dt = 1 / 60.0;
        double s1 = stretch(1, dt, true, 1.0), s5 = stretch(5, dt, true, 1.0), s50 = stretch(50, dt, true, 1.0);
        System.out.printf("PBD chain k=1, dt=1/60: stretch n=1 %.5f, n=5 %.5f, n=50 %.5f%n", s1, s5, s50);
        assertTrue(s1 > s5 && s5 > s50, "monotone in n");
        assertTrue(s1 > 10 * s50, "n=1 stretches over 10x more than n=50");
    }

    /** At fixed n, the timestep alone changes how stretchy the same PBD chain is. */
    @Test
    void stretchDependsOnTimestep() {
        double s30 = stretch(2, 1 / 30.0, true, 1.0), s120 = stretch(2, 1 / 120.0, true, 1.0);
        System.out.printf("PBD chain k=1, n=2: stretch dt=1/30 %.5f, dt=1/120 %.5f%n", s30, s120);
        assertTrue(s30 > 2 * s120 || s120 > 2 * s30, "stretch changes by more than 2x with dt");
    }

    /**
     * The same chain in XPBD: once Gauss–Seidel has converged (n = 50 and n = 200 sweeps for 20 links
     * at α̃/w ≈ 0.36), the stretch is the closed form whatever n is.
     */
    @Test
    void xpbdStretchDoesNotDependOnIterationsOnceConverged() {
        double alpha = 1e-2;
        double[] out = new double[2];
        int[] ns = {50, 200};
        for (int j = 0; j < 2; j++) {
            SolverSettings s = new SolverSettings().withMode(ConstraintMode.XPBD).withIterations(ns[j]).withTimestep(1 / 60.0);
            Simulation sim = Rigs.chain(LINKS, M, L, s, 1.0, alpha);
            Rigs.settle(sim, 1e-10, 200_000);
            out[j] = Rigs.totalExtension(sim, LINKS, L);
        }
        // Closed form: Σ_i α g m (LINKS − i) = α g m LINKS (LINKS + 1)/2.
        double expected = alpha * Rigs.G * M * LINKS * (LINKS + 1) / 2;
        System.out.printf("XPBD chain: extension n=50 %.6g, n=200 %.6g, closed form %.6g%n", out[0], out[1], expected);
        assertEquals(expected, out[0], 0.01 * expected);
        assertEquals(expected, out[1], 0.01 * expected);
    }
}
