package xpbdcloth.fit;

import static org.junit.jupiter.api.Assertions.*;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.Simulation;
import xpbdcloth.scene.Scene;

/**
 * The static fit on the `drape` scene (16², held at three corners; α* = 1e-4, 2e-1, 5e-2 m/N for
 * structural, shear, bend): its gradient against central differences and a Taylor test, the recovery of
 * α* from a tenth and from ten times it, with and without observation noise, and the equilibrium it
 * differentiates checked against the simulator itself.
 */
class StaticFitTest {
    static final List<ConstraintFamily> ALL = List.of(ConstraintFamily.STRUCTURAL, ConstraintFamily.SHEAR, ConstraintFamily.BEND);
    static final double[] TRUE_ALPHA = {1e-4, 2e-1, 5e-2};
    static double[] observed;

    @BeforeAll
    static void observe() {
        observed = RestShape.of(Scene.builtIn("drape")).positions;
    }

    static StaticFit fit(double[] shape, double startFactor) {
        return new StaticFit(Scene.builtIn("drape").simulation(), ALL, shape, startFactor);
    }

    @Test
    void adjointGradientMatchesCentralDifferencesOfTheLoss() {
        for (double start : new double[] {0.1, 10}) {
            StaticFit fit = fit(observed, start);
            double[] g = fit.gradient(), theta = fit.theta();
            for (int p = 0; p < theta.length; p++) {
                double h = 1e-5;
                double[] up = theta.clone(), down = theta.clone();
                up[p] += h;
                down[p] -= h;
                double fd = (fit.lossAt(up) - fit.lossAt(down)) / (2 * h);
                assertEquals(fd, g[p], 1e-5 * Math.abs(fd), "∂L/∂ln α of " + ALL.get(p) + " starting at " + start + " α*");
            }
        }
    }

    /** L(θ + εd) − L(θ) − ε ∇L·d shrinks as ε²: each halving of ε divides it by 4 (slope 2 on log–log). */
    @Test
    void taylorRemainderHasSlopeTwo() {
        StaticFit fit = fit(observed, 0.5);
        double[] theta = fit.theta(), g = fit.gradient(), d = {0.6, -0.3, 0.74};
        double l0 = fit.lossAt(theta), slopeTerm = 0;
        for (int p = 0; p < 3; p++) slopeTerm += g[p] * d[p];
        double previous = Double.NaN;
        for (double eps = 4e-2; eps > 4e-3; eps /= 2) {
            double[] t = theta.clone();
            for (int p = 0; p < 3; p++) t[p] += eps * d[p];
            double remainder = Math.abs(fit.lossAt(t) - l0 - eps * slopeTerm);
            if (!Double.isNaN(previous)) assertEquals(2.0, Math.log(previous / remainder) / Math.log(2), 0.1, "Taylor slope at ε = " + eps);
            previous = remainder;
        }
    }

    @Test
    void recoversEveryComplianceWithinHalfAPercentInTenIterationsFromBothSides() {
        for (double start : new double[] {0.1, 10}) {
            StaticFit fit = fit(observed, start);
            fit.run(10, null);
            List<FitIteration> h = fit.history();
            int within = -1;
            for (FitIteration it : h)
                if (within < 0 && maxRelativeError(it.compliance) < 0.005) within = it.index;
            assertTrue(within >= 0 && within <= 10, "within 0.5 % of α* by iteration 10 from " + start + " α*; reached " + maxRelativeError(fit.last().compliance));
            assertTrue(maxRelativeError(fit.last().compliance) < 1e-6, "and it keeps going to the exact α*: " + maxRelativeError(fit.last().compliance));
        }
    }

    /** 0.5 mm Gaussian noise on every coordinate of every vertex, 20 seeds: the median error of each α under 3 %. */
    @Test
    void withHalfAMillimetreOfNoiseTheMedianErrorIsUnderThreePercent() {
        List<List<Double>> errors = new ArrayList<>();
        for (int p = 0; p < 3; p++) errors.add(new ArrayList<>());
        for (long seed = 1; seed <= 20; seed++) {
            StaticFit fit = fit(Observation.withNoise(observed, 0.5e-3, seed), 1);
            assertTrue(fit.run(20, null), "converges with noise, seed " + seed);
            for (int p = 0; p < 3; p++) errors.get(p).add(Math.abs(fit.compliance()[p] / TRUE_ALPHA[p] - 1));
            // The residual left is the noise's: √3 · 0.5 mm RMS per vertex, give or take its spread.
            assertEquals(0.5e-3 * Math.sqrt(3), fit.last().rms, 0.1e-3, "RMS left is the noise's, seed " + seed);
        }
        for (int p = 0; p < 3; p++) {
            Collections.sort(errors.get(p));
            double median = (errors.get(p).get(9) + errors.get(p).get(10)) / 2;
            assertTrue(median < 0.03, ALL.get(p) + ": median error " + median);
        }
    }

    /**
     * The equilibrium the fit differentiates is the simulator's, up to XPBD's own approximation: one step
     * from it at rest, solved to convergence (the global solver), moves the cloth by an amount that falls
     * at least as h³ (XPBD applies each Δλ along the gradient of the iterate it was computed at, so where
     * it stops depends on the path: h⁴ for a Newton solve of every family at once, h³ for Gauss–Seidel
     * and for the global solver, which sweeps shear and bend between its Newton steps), where a force F
     * left over would move it by Fh²/m, falling only as h².
     */
    @Test
    void aConvergedStepFromTheEquilibriumMovesItOnlyByXpbdsOwnHigherOrderError() {
        double[] moved = new double[2], h = {1e-3, 1e-4};
        for (int k = 0; k < 2; k++) {
            Simulation sim = Scene.builtIn("drape").simulation();
            sim.settings(sim.settings().withSolver(xpbdcloth.engine.SolverType.JACOBI_PCG).withIterations(100).withSubsteps(1).withTimestep(h[k]).withPcgTolerance(1e-10).withPcgMaxIterations(5000));
            for (int i = 0; i < sim.particles().count(); i++)
                sim.particles().setPosition(i, observed[3 * i], observed[3 * i + 1], observed[3 * i + 2]);
            sim.step();
            double[] x = sim.particles().positions();
            for (int c = 0; c < x.length; c++) moved[k] = Math.max(moved[k], Math.abs(x[c] - observed[c]));
        }
        assertTrue(moved[0] / moved[1] > 700, "a tenth of the step moves " + moved[0] / moved[1] + " times less (h³: 1000, a force: 100)");
        assertTrue(moved[1] < 1e-8, "at h = 0.1 ms a step moves it " + moved[1] + " m");
    }

    @Test
    void badInputIsRefusedWithItsName() {
        Scene drape = Scene.builtIn("drape");
        FitException count = assertThrows(FitException.class, () -> Observation.check("shape.obj", new double[30], drape));
        assertTrue(count.getMessage().contains("10 vertices") && count.getMessage().contains("256"), count.getMessage());
        double[] nan = observed.clone();
        nan[3 * 7 + 1] = Double.NaN;
        assertTrue(assertThrows(FitException.class, () -> Observation.check("shape.obj", nan, drape)).getMessage().contains("vertex 8 is not finite"));
        double[] moved = observed.clone();
        moved[0] += 0.5; // vertex 1 is pinned
        assertTrue(assertThrows(FitException.class, () -> Observation.check("shape.obj", moved, drape)).getMessage().contains("vertex 1 is pinned"));
        IllegalArgumentException absent = assertThrows(IllegalArgumentException.class,
                () -> new StaticFit(Scene.builtIn("curtain").simulation(), List.of(ConstraintFamily.BEND), new double[3 * 32 * 32], 1));
        assertTrue(absent.getMessage().contains("params names bend") && absent.getMessage().contains("structural"), absent.getMessage());
        Simulation pbd = Scene.builtIn("drape").simulation();
        pbd.settings(pbd.settings().withMode(ConstraintMode.PBD));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new StaticFit(pbd, ALL, observed, 1)).getMessage().startsWith("mode must be XPBD"));
        Simulation hard = Scene.builtIn("drape").simulation();
        hard.setCompliance(ConstraintFamily.SHEAR, 0);
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new StaticFit(hard, ALL, observed, 1)).getMessage().startsWith("families.shear.compliance must be > 0"));
    }

    static double maxRelativeError(double[] alpha) {
        double e = 0;
        for (int p = 0; p < 3; p++) e = Math.max(e, Math.abs(alpha[p] / TRUE_ALPHA[p] - 1));
        return e;
    }
}
