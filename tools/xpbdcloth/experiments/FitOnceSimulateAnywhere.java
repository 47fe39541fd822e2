package xpbdcloth.experiments;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.Simulation;
import xpbdcloth.fit.RestShape;
import xpbdcloth.fit.StaticFit;
import xpbdcloth.scene.Scene;

/**
 * Experiment 9: fit once, simulate anywhere. The observation is the `drape` scene's exact rest shape at
 * α* (structural 1e-4, shear 0.2, bend 0.05 m/N). Four parameter sets are fitted to it:
 * (1) XPBD's α by the static fit (the equilibrium's own energy, no solver in it);
 * (2) XPBD's α, (3) PBD's k with Müller's k', (4) PBD's k without it, each by simulating the cloth to rest
 * at n = 10 sweeps and dt = 1/60 s (one substep, damping 2/s, 8 s) and minimising the RMS distance to the
 * observation with {@link NelderMead} (ln α, or the logit of k, per family): a simulated rest has no
 * derivative this project computes, and three parameters are few enough to search without one.
 * Each set is then simulated to rest at n = 2 … 1000 (dt = 1/60 s) and at dt = 1/30 … 1/960 s
 * (n = 10), and its distance to the observation measured. The claim under test: α fitted once reproduces
 * the drape wherever the solver converges; a k fitted at one setting does not.
 */
final class FitOnceSimulateAnywhere implements Experiment {
    static final List<ConstraintFamily> FAMILIES = List.of(ConstraintFamily.STRUCTURAL, ConstraintFamily.SHEAR, ConstraintFamily.BEND);
    static final int[] SWEEPS = {2, 5, 10, 20, 50, 200, 1000};
    static final double[] STEPS = {1 / 30.0, 1 / 60.0, 1 / 120.0, 1 / 240.0, 1 / 960.0};
    static final int FIT_SWEEPS = 10;
    static final double FIT_STEP = 1 / 60.0, SETTLE_SECONDS = 8;

    @Override public String name() { return "fit-once"; }

    @Override public String claim() { return "a compliance fitted once reproduces the drape at any sweep count and timestep; a PBD stiffness does not"; }

    /** A way of simulating the drape from three numbers: the mode and how the numbers become k or α. */
    enum Model {
        XPBD("XPBD α"), PBD_MULLER("PBD k with Müller's k'"), PBD("PBD k, no Müller");
        final String label;
        Model(String label) { this.label = label; }
    }

    /** RMS distance (m) to the observation of the drape simulated to rest with these parameters. */
    static double restDistance(Model model, double[] params, int sweeps, double dt, double[] observed, double seconds) {
        Scene scene = Scene.builtIn("drape");
        Simulation sim = scene.simulation();
        sim.settings(sim.settings().withIterations(sweeps).withSubsteps(1).withTimestep(dt).withDamping(2));
        if (model == Model.XPBD) {
            for (int f = 0; f < 3; f++) sim.setCompliance(FAMILIES.get(f), params[f]);
        } else {
            sim.settings(sim.settings().withMode(ConstraintMode.PBD).withMullerCorrection(model == Model.PBD_MULLER));
            for (int f = 0; f < 3; f++) sim.setStiffness(FAMILIES.get(f), params[f]);
        }
        try {
            for (int s = 0, n = (int) Math.round(seconds / dt); s < n; s++) sim.step();
        } catch (RuntimeException diverged) {
            return Double.POSITIVE_INFINITY;
        }
        double[] x = sim.particles().positions();
        double sum = 0;
        for (int c = 0; c < x.length; c++) sum += (x[c] - observed[c]) * (x[c] - observed[c]);
        return Math.sqrt(sum / (x.length / 3));
    }

    static double[] toParams(Model model, double[] u) {
        double[] p = new double[3];
        for (int f = 0; f < 3; f++) p[f] = model == Model.XPBD ? Math.exp(u[f]) : 1 / (1 + Math.exp(-u[f]));
        return p;
    }

    @Override public List<String> run(Context ctx) throws IOException {
        double[] observed = RestShape.of(Scene.builtIn("drape")).positions;
        double seconds = ctx.quick ? 4 : SETTLE_SECONDS;
        int evaluations = ctx.quick ? 40 : 150;
        double[] truth = new double[3];
        Scene drape = Scene.builtIn("drape");
        for (int f = 0; f < 3; f++) truth[f] = drape.preset().families.get(FAMILIES.get(f)).compliance;

        StaticFit staticFit = new StaticFit(drape.simulation(), FAMILIES, observed, 0.1);
        staticFit.run(30, null);
        List<String> labels = new ArrayList<>();
        List<Model> models = new ArrayList<>();
        List<double[]> fitted = new ArrayList<>();
        labels.add("XPBD α, static fit (no solver)");
        models.add(Model.XPBD);
        fitted.add(staticFit.compliance());
        ctx.progress(name(), "static fit: α = " + fmt(staticFit.compliance()));
        for (Model m : Model.values()) {
            double[] u0 = new double[3];
            for (int f = 0; f < 3; f++) u0[f] = m == Model.XPBD ? Math.log(truth[f] * 0.1) : 0; // α from a tenth, k from ½
            double[] u = NelderMead.minimise(x -> restDistance(m, toParams(m, x), FIT_SWEEPS, FIT_STEP, observed, seconds), u0, evaluations);
            labels.add(m.label + ", fitted at n = 10, dt = 1/60 s");
            models.add(m);
            fitted.add(toParams(m, u));
            ctx.progress(name(), m.label + " fitted by simulation: " + fmt(toParams(m, u)) + ", RMS "
                    + String.format("%.2f mm", 1e3 * restDistance(m, toParams(m, u), FIT_SWEEPS, FIT_STEP, observed, seconds)));
        }

        Table t = new Table(name(), "parameters", "p_structural", "p_shear", "p_bend", "sweeps", "dt_s", "rms_to_observation_m");
        Plot bySweeps = new Plot("Fit once (n = 10, dt = 1/60 s), simulate at other sweep counts", "Gauss–Seidel sweeps per step", "RMS distance to the observed drape (m)", true, true).legendRight();
        Plot bySteps = new Plot("Fit once (n = 10, dt = 1/60 s), simulate at other timesteps", "timestep (s)", "RMS distance to the observed drape (m)", true, true).legendRight();
        List<String> out = new ArrayList<>();
        for (int k = 0; k < labels.size(); k++) {
            double[] p = fitted.get(k);
            List<Double> xs = new ArrayList<>(), ys = new ArrayList<>(), xt = new ArrayList<>(), yt = new ArrayList<>();
            StringBuilder line = new StringBuilder(labels.get(k) + " " + fmt(p) + ": RMS mm at n =");
            for (int n : SWEEPS) {
                double d = restDistance(models.get(k), p, n, FIT_STEP, observed, seconds);
                t.add(labels.get(k), p[0], p[1], p[2], n, FIT_STEP, d);
                xs.add((double) n);
                ys.add(d);
                line.append(String.format(" %d: %.1f", n, 1e3 * d));
            }
            line.append("; at dt =");
            for (double dt : STEPS) {
                double d = restDistance(models.get(k), p, FIT_SWEEPS, dt, observed, seconds);
                t.add(labels.get(k), p[0], p[1], p[2], FIT_SWEEPS, dt, d);
                xt.add(dt);
                yt.add(d);
                line.append(String.format(" 1/%.0f: %.1f", 1 / dt, 1e3 * d));
            }
            bySweeps.line(labels.get(k), xs, ys);
            bySteps.line(labels.get(k), xt, yt);
            ctx.progress(name(), line.toString());
            out.add(line.toString());
        }
        ctx.save(t);
        ctx.save(bySweeps, name());
        ctx.save(bySteps, name() + "-timestep");
        return out;
    }

    private static String fmt(double[] p) { return String.format("(%.4g, %.4g, %.4g)", p[0], p[1], p[2]); }
}
