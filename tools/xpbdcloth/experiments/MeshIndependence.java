package xpbdcloth.experiments;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.Metrics;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SolverSettings;
import xpbdcloth.engine.SolverType;
import xpbdcloth.fabric.Fabric;
import xpbdcloth.fabric.FabricConstraints;
import xpbdcloth.scene.FabricCatalogue;

/**
 * Experiment 8: is the cloth the same material at every resolution? The same 1 m square hung by its two
 * top corners settles (400 steps at the scenes' timestep, 10 substeps × 2 sweeps, damping 2/s) at 16 … 128 segments a
 * side (17² … 129² particles), as
 * <ul>
 *   <li>the seed's edge families at the hanging scene's fixed α (0.2 kg/m², Gauss–Seidel): a spring
 *       constant per edge is no material, so the cloth softens as its edges multiply;</li>
 *   <li>measured denim (the catalogue's) under Gauss–Seidel: the material is right, but a few sweeps per
 *       substep leave more of the pin's hold undelivered the finer the mesh;</li>
 *   <li>the same denim under vertex block descent: its rest is the energy's minimum at any sweep count
 *       (its balance, the worst particle's leftover force over its weight, is reported beside it);</li>
 *   <li>and held not by one particle at each corner but by a clamp 1/16 m wide (every top-edge particle
 *       within it pinned, the same width at every resolution here), so the hold has a size of its own and
 *       not the mesh's.</li>
 * </ul>
 * Measured at rest: the sag (how far the middle of the top edge hangs below the corners) and the largest
 * Green strain. A point pin carries a finite force on a vanishing area, so even the converged strain next
 * to it grows with the resolution (like 1/spacing) and the sag with it (like its logarithm); a clamp of
 * fixed width has neither.
 */
final class MeshIndependence implements Experiment {
    /** Segments a side. */
    static final int[] RESOLUTIONS = {16, 32, 64, 96, 128};
    static final double CLAMP = 1.0 / 16;

    @Override public String name() { return "mesh-independence"; }

    @Override public String claim() { return "a fabric's moduli give the same cloth at every resolution once the solve converges; the seed's fixed α does not"; }

    /** The settled cloth's sag (m), largest Green strain (fabric only) and balance, at {@code segments} a side. */
    static double[] settle(int segments, boolean fabric, SolverType solver, double clamp) {
        int n = segments + 1;
        ClothBuilder b = new ClothBuilder().resolution(n, n).size(1, 1).origin(0, 2, 0).arealDensity(fabric ? 0.324 : 0.2).pinTopCorners();
        int clamped = (int) Math.round(clamp * segments);
        for (int c = 1; c <= clamped; c++) b.pin(0, c).pin(0, n - 1 - c);
        if (!fabric) b.family(ConstraintFamily.STRUCTURAL, 1, 1e-6).family(ConstraintFamily.SHEAR, 0.5, 1e-3).family(ConstraintFamily.BEND, 0.1, 1e-2);
        Cloth cloth = b.build();
        Particles p = cloth.particles();
        Simulation sim = cloth.simulation(new SolverSettings().withMode(ConstraintMode.XPBD).withSolver(solver).withIterations(2).withSubsteps(10).withTimestep(0.02)
                .withGravity(0, -9.81, 0).withDamping(2));
        if (fabric) {
            Fabric denim = FabricCatalogue.named("denim");
            for (ConstraintBlock block : FabricConstraints.build(p, cloth.triangles(), new double[] {1, 0, 0}, denim.membrane, denim.bendingStiffness, false))
                sim.add(block);
        }
        for (int s = 0; s < 400; s++) sim.step();
        double middle = 0.5 * (p.y(cloth.index(0, (n - 1) / 2)) + p.y(cloth.index(0, n / 2)));
        double[] out = {p.y(cloth.index(0, 0)) - middle, fabric ? Metrics.largestGreenStrain(sim) : Double.NaN, sim.balance()};
        sim.close();
        return out;
    }


    @Override public List<String> run(Context ctx) throws IOException {
        Table t = new Table(name(), "resolution", "sag_springs_gauss_seidel_m", "sag_denim_gauss_seidel_m", "strain_denim_gauss_seidel",
                "sag_denim_descent_m", "strain_denim_descent", "balance_denim_descent", "sag_denim_descent_clamp_m", "strain_denim_descent_clamp");
        int[] ns = ctx.quick ? new int[] {16, 32} : RESOLUTIONS;
        String resolutionNote = "segments a side";
        List<Double> xs = new ArrayList<>(), springs = new ArrayList<>(), gs = new ArrayList<>(), descent = new ArrayList<>(), clamp = new ArrayList<>();
        double worstBalance = 0;
        for (int n : ns) {
            ctx.progress(name(), n + " " + resolutionNote);
            double[] a = settle(n, false, SolverType.GAUSS_SEIDEL, 0), g = settle(n, true, SolverType.GAUSS_SEIDEL, 0);
            double[] d = settle(n, true, SolverType.VERTEX_BLOCK_DESCENT, 0), c = settle(n, true, SolverType.VERTEX_BLOCK_DESCENT, CLAMP);
            t.add(n, a[0], g[0], g[1], d[0], d[1], d[2], c[0], c[1]);
            ctx.progress(name(), String.format("%d segments: sag springs %.4f, denim Gauss-Seidel %.4f, descent %.4f (balance %.1e), clamped %.4f m",
                    n, a[0], g[0], d[0], d[2], c[0]));
            xs.add((double) n);
            springs.add(a[0]);
            gs.add(g[0]);
            descent.add(d[0]);
            clamp.add(c[0]);
            worstBalance = Math.max(worstBalance, d[2]);
        }
        ctx.save(t);
        Plot p = new Plot("The same 1 m cloth hung by two corners, at rest (10 substeps × 2 sweeps)", "segments along a side",
                "sag of the top edge below the corners (m, log)", false, true);
        p.line("springs, fixed α, GS", xs, springs).line("denim, GS", xs, gs)
                .line("denim, VBD (converged)", xs, descent).line("denim, VBD, 1/16 m clamps", xs, clamp);
        ctx.save(p, name());
        List<String> out = new ArrayList<>();
        out.add(String.format("edge springs at fixed α: sag %s m", list(springs)));
        out.add(String.format("denim under Gauss-Seidel: sag %s m", list(gs)));
        out.add(String.format("denim under vertex block descent (worst balance %.1e of a weight): sag %s m; last two resolutions %.1f %% apart",
                worstBalance, list(descent), 100 * apart(descent)));
        out.add(String.format("denim held by 1/16 m clamps: sag %s m; last two resolutions %.1f %% apart", list(clamp), 100 * apart(clamp)));
        return out;
    }

    /** |last − second last| / last. */
    static double apart(List<Double> v) {
        int k = v.size();
        return k < 2 ? 0 : Math.abs(v.get(k - 1) - v.get(k - 2)) / v.get(k - 1);
    }

    private static String list(List<Double> v) {
        StringBuilder b = new StringBuilder();
        for (double x : v) b.append(b.length() == 0 ? "" : ", ").append(String.format("%.4f", x));
        return b.toString();
    }
}
