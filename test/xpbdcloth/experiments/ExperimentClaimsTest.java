package xpbdcloth.experiments;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import xpbdcloth.engine.ConstraintMode;

/**
 * The physics the experiments rest on, at small sizes (the full experiments run by `gradle experiments`).
 * Bounds stated here are the ones the README quotes.
 */
class ExperimentClaimsTest {
    static double rope(ConstraintMode mode, double k, double alpha, int n, boolean muller) {
        return StiffnessVsIterations.ropeStretch(new Rigs.Solver(mode, k, alpha, n, 1, 1 / 60.0, muller), 6);
    }

    /** XPBD rope (20 links, α = 1e-2 m/N): once converged (n ≥ 30) the stretch spreads by under 1 % across n. */
    @Test
    void xpbdStretchIsFlatAcrossIterationsOnceConverged() {
        double lo = Double.MAX_VALUE, hi = 0;
        for (int n : new int[] {30, 50, 100}) {
            double s = rope(ConstraintMode.XPBD, 1, StiffnessVsIterations.ALPHA_ROPE, n, true);
            lo = Math.min(lo, s);
            hi = Math.max(hi, s);
        }
        assertTrue((hi - lo) / lo < 0.01, "XPBD spread " + (hi - lo) / lo);
        double closed = StiffnessVsIterations.ALPHA_ROPE * Rigs.G * StiffnessVsIterations.MASS * 20 * 21 / 2 / (20 * 0.05);
        assertEquals(closed, hi, 0.01 * closed, "and equals the closed form");
    }

    /** PBD rope with the raw k = 0.5: n = 1 stretches over 20x more than n = 50. */
    @Test
    void pbdRawStiffensWithIterations() {
        double s1 = rope(ConstraintMode.PBD, 0.5, 0, 1, false), s50 = rope(ConstraintMode.PBD, 0.5, 0, 50, false);
        assertTrue(s1 > 20 * s50, s1 + " vs " + s50);
    }

    /** Müller's k' holds the rope's stretch across n = 1..50 within 5 % at k = 0.5, but not at k = 0.99 (over 50 %). */
    @Test
    void mullerCompensatesForSoftKAndSaturatesNearOne() {
        int[] ns = {1, 5, 50};
        double soft = MullerSaturation.spread(0.5, ns, true, 12, null), stiff = MullerSaturation.spread(0.99, ns, true, 12, null);
        assertTrue(soft < 0.05, "k=0.5 spread " + soft);
        assertTrue(stiff > 0.5, "k=0.99 spread " + stiff);
    }

    /** Each 20-link chain link within 1 % of α·g·(mass below) at 30 sweeps (the experiment finds 15 suffice). */
    @Test
    void chainMatchesHookeAtStatedSweeps() {
        assertTrue(ClosedForm.chainError(20, 30, 20, null) < 0.01);
    }

    /**
     * Gauss–Seidel stalls with resolution: at α = 1e-3 m/N, 400 sweeps take a 16² cloth's residual below
     * 1 % of its start, but leave a 64² cloth's above 30 % of it.
     */
    @Test
    void gaussSeidelStallsOnFinerCloth() {
        double coarse = GaussSeidelConvergence.residuals(16, 1e-3, 400)[400], fine = GaussSeidelConvergence.residuals(64, 1e-3, 400)[400];
        assertTrue(coarse < 1e-2, "16^2 residual " + coarse);
        assertTrue(fine > 0.3, "64^2 residual " + fine);
    }

    /** The experiments command is deterministic: the same run writes the same CSV, byte for byte. */
    @Test
    void sameCommandSameCsv(@TempDir Path a, @TempDir Path b) throws Exception {
        for (Path out : new Path[] {a, b}) {
            Experiments e = new Experiments();
            e.quick = true;
            e.out = out;
            e.only = java.util.List.of("substeps-vs-iterations");
            assertEquals(0, e.call());
        }
        String csv = Files.readString(a.resolve("substeps-vs-iterations.csv"));
        assertTrue(csv.startsWith("substeps,iterations,mean_strain_relative,mechanical_energy_lost_J\n"));
        assertEquals(csv, Files.readString(b.resolve("substeps-vs-iterations.csv")));
        assertTrue(Files.size(a.resolve("substeps-vs-iterations.png")) > 10_000, "a plot was drawn");
    }
}
