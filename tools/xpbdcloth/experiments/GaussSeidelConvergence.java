package xpbdcloth.experiments;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.Metrics;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SolverSettings;

/**
 * Experiment 5: the residual ‖C + α̃λ‖ after each sweep within one step, for cloths of 16² … 128²
 * at three compliances. The survey (section 7) says local Gauss–Seidel stalls on fine and stiff meshes.
 *
 * <p>The state is a flat 1 m cloth pinned along one edge and turning about it (see {@link #swungCloth}),
 * the same at every resolution; one step of dt = 1/60 s is taken with many sweeps and the residual
 * recorded after each.
 */
final class GaussSeidelConvergence implements Experiment {
    @Override public String name() { return "gauss-seidel-convergence"; }

    @Override public String claim() { return "Gauss-Seidel's residual reduction per sweep stalls as resolution and stiffness grow"; }

    /**
     * A 1 m cloth of res² particles lying flat, pinned along its top edge (z = −0.5 m) and turning about
     * that edge at 3 rad/s, as if swinging down: velocities v = ω × r. The state is the same function of
     * position at every resolution, and the error a step must remove (the stretch of a rigid turn, plus
     * gravity) is smooth, the low-frequency kind local sweeps are slow to remove.
     */
    static Simulation swungCloth(int res, double compliance) {
        Cloth c = new ClothBuilder().resolution(res, res).size(1, 1).plane(ClothBuilder.Plane.HORIZONTAL).origin(0, 1, 0)
                .arealDensity(0.2).family(ConstraintFamily.STRUCTURAL, 1, compliance).build();
        for (int col = 0; col < res; col++) c.particles().pin(c.index(0, col));
        xpbdcloth.engine.Particles p = c.particles();
        double omega = 3;
        for (int i = 0; i < p.count(); i++) {
            if (p.isPinned(i)) continue;
            // ω along −x about the axis through (·, 1, −0.5): r = (0, y − 1, z + 0.5), v = ω × r.
            double ry = p.y(i) - 1, rz = p.z(i) + 0.5;
            p.setVelocity(i, 0, omega * rz, -omega * ry);
        }
        return c.simulation(new SolverSettings().withMode(ConstraintMode.XPBD).withIterations(1).withSubsteps(1).withTimestep(1 / 60.0));
    }

    /** Residual after each of {@code sweeps} sweeps of one step, relative to before the first (index 0). */
    static double[] residuals(int res, double compliance, int sweeps) {
        Simulation sim = swungCloth(res, compliance);
        sim.settings(sim.settings().withIterations(sweeps).withSubsteps(1));
        double[] r = new double[sweeps + 1];
        sim.setSweepListener((substep, sweep) -> r[sweep + 1] = Metrics.residual(sim));
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
