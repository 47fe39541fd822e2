package xpbdcloth.experiments;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.MeshClothBuilder;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SolverSettings;
import xpbdcloth.engine.SolverType;
import xpbdcloth.mesh.ClothMesh;
import xpbdcloth.mesh.SquareSheet;

/**
 * Experiment 12: one linear solve of experiment 7's state (a 1 m cloth, α = 1e-10 m/N, pinned along
 * one edge and turning about it at 3 rad/s, one 1/60 s step) to 1e-6 relative residual, on the grid, on
 * the grid with its particles moved off the plane (so that its lines couple), and on two triangulations
 * of the same square: every quad split along one diagonal, or along alternating ones. A flat grid's
 * stretch rows are chains that do not couple across at all; a triangle sheet's edges meet at
 * 45°, and a hard triangulated sheet has about res² more edges than in-plane degrees of freedom, so
 * its A = J W Jᵀ + α̃ equals α̃ on a whole subspace of self-stresses (Δλ with Jᵀ Δλ = 0).
 */
final class MultigridOnTriangles implements Experiment {
    static final double COMPLIANCE = 1e-10;

    @Override public String name() { return "multigrid-on-triangles"; }

    @Override public String claim() { return "multigrid-PCG is mesh-independent on a grid cloth and no better than Jacobi-PCG on a hard triangle mesh"; }

    /**
     * The swung res² cloth as a mesh: "grid" (quads), "crumpled" (the grid with every free particle
     * moved up or down by up to 0.15 edge lengths, seeded, so that rows of perpendicular edges couple),
     * "diagonal" (every quad split along one diagonal) or "alternating".
     */
    static Simulation swung(String kind, int res, SolverType type) {
        SquareSheet.Cells cells = kind.equals("diagonal") ? SquareSheet.Cells.DIAGONAL : kind.equals("alternating") ? SquareSheet.Cells.ALTERNATING : SquareSheet.Cells.QUADS;
        ClothMesh mesh = SquareSheet.generate(res, cells);
        Cloth cloth = new MeshClothBuilder(mesh).arealDensity(0.2)
                .family(ConstraintFamily.STRUCTURAL, 1, COMPLIANCE)
                .pin(mesh.group("edge")).build();
        double h = 1.0 / (res - 1);
        Particles p = cloth.particles();
        java.util.Random random = new java.util.Random(1);
        if (kind.equals("crumpled")) for (int i = res; i < p.count(); i++) p.setPosition(i, p.x(i), p.y(i) + 0.3 * h * (random.nextDouble() - 0.5), p.z(i));
        for (int i = 0; i < p.count(); i++) if (!p.isPinned(i)) p.setVelocity(i, 0, 3 * (p.z(i) + 0.5), -3 * (p.y(i) - 1));
        return cloth.simulation(new SolverSettings().withMode(ConstraintMode.XPBD).withIterations(1).withSubsteps(1).withTimestep(1 / 60.0)
                .withSolver(type).withPcgTolerance(1e-6).withPcgMaxIterations(5000));
    }

    /** {CG iterations, solve ms (setup excluded), setup ms, rows}. */
    static double[] solveOnce(String kind, int res, SolverType type) {
        Simulation sim = swung(kind, res, type);
        long t0 = System.nanoTime();
        sim.step();
        double total = (System.nanoTime() - t0) / 1e6, setup = sim.profile().globalSetupNanos() / 1e6;
        double[] r = {sim.profile().lastPcgIterations(), total - setup, setup, sim.constraintCount()};
        sim.close();
        return r;
    }

    @Override public List<String> run(Context ctx) throws IOException {
        // 256² only for the grids: a triangle sheet's multigrid solve there would take minutes.
        int[] gridSizes = ctx.quick ? new int[] {32} : new int[] {32, 64, 128, 256}, sheetSizes = ctx.quick ? new int[] {32} : new int[] {32, 64, 128};
        Table t = new Table(name(), "mesh", "resolution", "rows", "solver", "cg_iterations", "solve_ms", "setup_ms");
        List<String> out = new ArrayList<>();
        for (SolverType type : new SolverType[] {SolverType.JACOBI_PCG, SolverType.MULTIGRID_PCG}) solveOnce("diagonal", 32, type); // JIT warm-up
        for (String kind : new String[] {"grid", "crumpled", "diagonal", "alternating"})
            for (int res : kind.equals("grid") || kind.equals("crumpled") ? gridSizes : sheetSizes) {
                StringBuilder line = new StringBuilder(String.format("%s %d^2:", kind, res));
                for (SolverType type : new SolverType[] {SolverType.JACOBI_PCG, SolverType.MULTIGRID_PCG}) {
                    ctx.progress(name(), kind + " " + res + "^2 " + type);
                    double[] r = solveOnce(kind, res, type);
                    t.add(kind, res, r[3], type.name(), r[0], r[1], r[2]);
                    line.append(String.format(" %s %.0f it %.1f ms (+ setup %.1f ms);", type.name(), r[0], r[1], r[2]));
                }
                out.add(line.toString());
            }
        ctx.save(t);
        return out;
    }
}
