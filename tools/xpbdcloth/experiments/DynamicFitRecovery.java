package xpbdcloth.experiments;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.fit.DynamicFit;
import xpbdcloth.fit.FitIteration;
import xpbdcloth.fit.Trajectory;
import xpbdcloth.scene.Scene;

/**
 * Experiment 10: compliance and damping from motion. The observation is `drape`'s first second as the
 * engine runs it (50 steps of 20 ms; α* = 1e-4, 0.2, 0.05 m/N, c* = 0.5/s), clean or with 0.5 mm of
 * Gaussian noise on every coordinate of every frame. {@link DynamicFit} (reverse-mode gradient, BFGS)
 * starts from five sets of factors on the truth and, with noise, from (0.5, 2, 0.5, 2) for five seeds;
 * each iteration's worst relative error over the four parameters is recorded.
 */
final class DynamicFitRecovery implements Experiment {
    static final List<ConstraintFamily> FAMILIES = List.of(ConstraintFamily.STRUCTURAL, ConstraintFamily.SHEAR, ConstraintFamily.BEND);
    static final int FRAMES = 50;
    static final double NOISE = 0.5e-3;
    static final double[][] STARTS = {{0.5, 2, 0.5, 2}, {0.1, 10, 0.1, 10}, {2, 0.5, 2, 0.5}, {10, 10, 10, 10}, {0.1, 0.1, 0.1, 0.1}};

    @Override public String name() { return "dynamic-fit"; }

    @Override public String claim() { return "compliances and damping are recovered within 2 % from one second of a 16² cloth's motion"; }

    @Override public List<String> run(Context ctx) throws IOException {
        double[] truth = new double[4];
        Scene drape = Scene.builtIn("drape");
        for (int f = 0; f < 3; f++) truth[f] = drape.preset().families.get(FAMILIES.get(f)).compliance;
        truth[3] = drape.preset().solver.damping();
        Table t = new Table(name(), "run", "iteration", "loss_m2", "rms_m", "alpha_structural", "alpha_shear", "alpha_bend", "damping_per_s", "worst_relative_error", "simulations");
        Plot plot = new Plot("Dynamic fit of drape's first second: worst parameter error per iteration", "BFGS iteration", "worst relative error of α and c", false, true).legendRight();
        List<String> out = new ArrayList<>();
        double[][] clean = Trajectory.simulate(drape, FRAMES, 0, 1);
        int starts = ctx.quick ? 2 : STARTS.length, seeds = ctx.quick ? 1 : 5;
        for (int k = 0; k < starts + seeds; k++) {
            boolean noisy = k >= starts;
            double[] start = noisy ? STARTS[0] : STARTS[k];
            String label = noisy ? "noise 0.5 mm, seed " + (k - starts + 1) : "start " + Arrays.toString(start) + " × truth";
            double[][] observed = noisy ? Trajectory.simulate(Scene.builtIn("drape"), FRAMES, NOISE, 1000L * (k - starts + 1)) : clean;
            long t0 = System.nanoTime();
            DynamicFit fit = new DynamicFit(Scene.builtIn("drape").simulation(), FAMILIES, true, observed, start);
            fit.run(80, null);
            double seconds = (System.nanoTime() - t0) / 1e9;
            List<Double> xs = new ArrayList<>(), ys = new ArrayList<>();
            int within = -1;
            for (FitIteration it : fit.history()) {
                double worst = worstError(it, truth);
                if (within < 0 && worst < 0.02) within = it.index;
                t.add(label, it.index, it.loss, it.rms, it.compliance[0], it.compliance[1], it.compliance[2], it.damping, worst, it.solves);
                xs.add((double) it.index);
                ys.add(Math.max(worst, 1e-16));
            }
            plot.line(label, xs, ys);
            FitIteration last = fit.last();
            String line = String.format("%s: %s after %d iterations (within 2 %% at %d), %.0f s; errors %+.3f %%, %+.3f %%, %+.3f %%, %+.3f %%; RMS %.3f mm",
                    label, fit.converged() ? "converged" : "NOT converged", last.index, within, seconds,
                    100 * (last.compliance[0] / truth[0] - 1), 100 * (last.compliance[1] / truth[1] - 1), 100 * (last.compliance[2] / truth[2] - 1),
                    100 * (last.damping / truth[3] - 1), last.rms * 1e3);
            ctx.progress(name(), line);
            out.add(line);
        }
        ctx.save(t);
        ctx.save(plot, name());
        return out;
    }

    static double worstError(FitIteration it, double[] truth) {
        double worst = Math.abs(it.damping / truth[3] - 1);
        for (int p = 0; p < 3; p++) worst = Math.max(worst, Math.abs(it.compliance[p] / truth[p] - 1));
        return worst;
    }
}
