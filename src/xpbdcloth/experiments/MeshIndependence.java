package xpbdcloth.experiments;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.OrthotropicMaterial;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SolverSettings;
import xpbdcloth.fabric.FabricConstraints;

/**
 * Experiment 8: is the cloth the same material at every resolution? The same 1 m square (0.2 kg/m²)
 * hung by its two top corners settles at 16², 32², 64² and 96² with (a) the seed's edge families at the
 * hanging scene's fixed α (structural 1e-6, shear 1e-3, bend 1e-2) and (b) one fabric's moduli as a
 * membrane per triangle and dihedral bending (the fabric scene's: 2000/800 N/m, ν 0.25, shear 30 N/m,
 * B 1e-5 N·m; no tethers, which would hide the membrane). Measured at rest: the sag, how far the
 * middle of the top edge, free between the two pins, hangs below them. Each cloth steps 6 s of 20 ms
 * with 10 substeps and damping 2/s, at 20 and at 40 sweeps a substep: where the two differ, the
 * solver, not the material, set the sag.
 */
final class MeshIndependence implements Experiment {
    static final int[] RESOLUTIONS = {16, 32, 64, 96};
    static final OrthotropicMaterial FABRIC = new OrthotropicMaterial(2000, 800, 0.25, 30);
    static final double BENDING = 1e-5;

    @Override public String name() { return "mesh-independence"; }

    @Override public String claim() { return "a fabric's moduli give the same cloth at every resolution; the seed's fixed α does not"; }

    /** The sag (m) of the settled cloth: how far the middle of the top edge hangs below the pinned corners. */
    static double sag(int n, boolean fabric, double seconds, int iterations) {
        ClothBuilder b = new ClothBuilder().resolution(n, n).size(1, 1).origin(0, 2, 0).arealDensity(0.2).pinTopCorners();
        if (fabric) b.withoutFamily(ConstraintFamily.STRUCTURAL);
        else b.family(ConstraintFamily.STRUCTURAL, 1, 1e-6).family(ConstraintFamily.SHEAR, 0.5, 1e-3).family(ConstraintFamily.BEND, 0.1, 1e-2);
        Cloth cloth = b.build();
        Particles p = cloth.particles();
        Simulation sim = cloth.simulation(new SolverSettings().mode(ConstraintMode.XPBD).iterations(iterations).substeps(10).timestep(0.02)
                .gravity(0, -9.81, 0).damping(2));
        if (fabric)
            for (ConstraintBlock block : FabricConstraints.build(p, cloth.triangles(), new double[] {1, 0, 0}, FABRIC, BENDING, false)) sim.add(block);
        for (int s = 0; s < Math.round(seconds / 0.02); s++) sim.step();
        double middle = 0.5 * (p.y(cloth.index(0, (n - 1) / 2)) + p.y(cloth.index(0, n / 2)));
        sim.close();
        return p.y(cloth.index(0, 0)) - middle;
    }

    @Override public List<String> run(Context ctx) throws IOException {
        Table t = new Table(name(), "resolution", "sag_springs_20_sweeps_m", "sag_springs_40_sweeps_m", "sag_fabric_20_sweeps_m", "sag_fabric_40_sweeps_m");
        int[] ns = ctx.quick ? new int[] {16, 32} : RESOLUTIONS;
        double seconds = ctx.quick ? 3 : 6;
        List<Double> xs = new ArrayList<>(), springs = new ArrayList<>(), fabric = new ArrayList<>(), springs20 = new ArrayList<>(), fabric20 = new ArrayList<>();
        for (int n : ns) {
            ctx.progress(name(), n + "²");
            // Each at 20 and 40 sweeps a substep: where the two differ, Gauss–Seidel had not converged.
            double a20 = sag(n, false, seconds, 20), a40 = sag(n, false, seconds, 40);
            double f20 = sag(n, true, seconds, 20), f40 = sag(n, true, seconds, 40);
            t.add(n, a20, a40, f20, f40);
            ctx.progress(name(), String.format("%d²: sag springs %.4f / %.4f m, fabric %.4f / %.4f m (20 / 40 sweeps)", n, a20, a40, f20, f40));
            xs.add((double) n);
            springs.add(a40);
            fabric.add(f40);
            springs20.add(a20);
            fabric20.add(f20);
        }
        ctx.save(t);
        Plot p = new Plot("The same 1 m cloth hung by two corners, at rest", "particles along a side", "sag of the top edge below the corners (m)", false, false);
        p.line("edge families, fixed α, 40 sweeps", xs, springs).line("edge families, fixed α, 20 sweeps", xs, springs20)
                .line("membrane + dihedral, 40 sweeps", xs, fabric).line("membrane + dihedral, 20 sweeps", xs, fabric20);
        ctx.save(p, name());
        List<String> out = new ArrayList<>();
        out.add(String.format("edge families at fixed α (40 sweeps): sag %s m, spread %.0f %% across resolutions", list(springs), 100 * spread(springs)));
        out.add(String.format("membrane + dihedral from one fabric's moduli (40 sweeps): sag %s m, spread %.0f %% across resolutions", list(fabric), 100 * spread(fabric)));
        return out;
    }

    static double spread(List<Double> v) {
        double lo = Double.MAX_VALUE, hi = -Double.MAX_VALUE;
        for (double x : v) { lo = Math.min(lo, x); hi = Math.max(hi, x); }
        return (hi - lo) / lo;
    }

    private static String list(List<Double> v) {
        StringBuilder b = new StringBuilder();
        for (double x : v) b.append(b.length() == 0 ? "" : ", ").append(String.format("%.4f", x));
        return b.toString();
    }
}
