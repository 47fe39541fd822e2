package xpbdcloth.experiments;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SolverSettings;

/**
 * Experiment 5: the residual ‖C + α̃λ‖ after each sweep within one step, for cloths of 16² … 128²
 * at three compliances. The survey (section 7) says local Gauss–Seidel stalls on fine and stiff meshes.
 *
 * <p>The state is a 1 m cloth pinned along its top edge, released horizontally and swung for 0.5 s
 * (4 substeps × 10 sweeps), so the error is the smooth, low-frequency kind a real step leaves; then
 * one step of dt = 1/60 s is taken with many sweeps and the residual recorded after each.
 */
final class GaussSeidelConvergence implements Experiment {
    @Override public String name() { return "gauss-seidel-convergence"; }

    @Override public String claim() { return "Gauss-Seidel's residual reduction per sweep stalls as resolution and stiffness grow"; }

    static Simulation swungCloth(int res, double compliance) {
        Cloth c = new ClothBuilder().resolution(res, res).size(1, 1).plane(ClothBuilder.Plane.HORIZONTAL).origin(0, 1, 0)
                .arealDensity(0.2).family(ConstraintFamily.STRUCTURAL, 1, compliance).build();
        for (int col = 0; col < res; col++) c.particles().pin(c.index(0, col));
        Simulation sim = c.simulation(new SolverSettings().mode(ConstraintMode.XPBD).iterations(10).substeps(4).timestep(1 / 60.0));
        for (int s = 0; s < 30; s++) sim.step();
        return sim;
    }

    /** Residual after each of {@code sweeps} sweeps of one step, relative to before the first (index 0). */
    static double[] residuals(int res, double compliance, int sweeps) {
        Simulation sim = swungCloth(res, compliance);
        sim.settings().iterations(sweeps).substeps(1);
        double[] r = new double[sweeps + 1];
        sim.setSweepListener((s, substep, sweep) -> r[sweep + 1] = s.residual());
        sim.step();
        double initial = r[0];
        for (int i = 0; i <= sweeps; i++) r[i] /= initial;
        return r;
    }

    @Override public List<String> run(Context ctx) throws IOException {
        int[] resolutions = ctx.quick ? new int[] {16, 32} : new int[] {16, 32, 64, 128};
        double[] compliances = {1e0, 1e-3, 1e-8};
        int sweeps = ctx.quick ? 50 : 400;
        Table t = new Table(name(), "resolution", "compliance_m_per_N", "sweep", "residual_relative");
        Plot p = new Plot("Gauss-Seidel residual within one step (1 m cloth, dt = 1/60 s)", "sweep", "||C + alpha~ lambda|| / value before sweep 1", true, true).legendRight();
        List<String> out = new ArrayList<>();
        for (double alpha : compliances) {
            StringBuilder line = new StringBuilder(String.format("alpha %.0e: residual after %d sweeps:", alpha, sweeps));
            for (int res : resolutions) {
                ctx.progress(name(), res + "x" + res + ", alpha " + alpha);
                double[] r = residuals(res, alpha, sweeps);
                List<Double> xs = new ArrayList<>(), ys = new ArrayList<>();
                for (int i = 1; i <= sweeps; i++) {
                    t.add(res, alpha, i, r[i]);
                    xs.add((double) i);
                    ys.add(Math.max(r[i], 1e-16));
                }
                p.line(String.format("%d^2, alpha %.0e", res, alpha), xs, ys);
                line.append(String.format(" %d^2 %.2e", res, r[sweeps]));
            }
            out.add(line.toString());
        }
        ctx.save(t);
        ctx.save(p, name());
        return out;
    }
}
