package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import xpbdcloth.linalg.AggregationMultigrid;
import xpbdcloth.linalg.SparseMatrix;
import xpbdcloth.mesh.ClothMesh;
import xpbdcloth.mesh.SquareSheet;

/**
 * The multigrid preconditioner on triangle meshes, where edges meet at 45° and 90° and a chain of
 * strong couplings can run around a triangle. Conjugate gradients need the preconditioner symmetric and
 * positive definite; a chain whose rows couple other than to their neighbours broke that (the V-cycle
 * had a negative eigenvalue and multigrid-PCG stalled at its iteration cap on every triangle mesh).
 */
class MultigridOnTriangleMeshesTest {

    /** A res² sheet of right triangles ({@link SquareSheet}), structural edges only, row 0 pinned, free vertices jittered by 5 % of an edge. */
    static Cloth triangleSheet(int res, boolean alternatingDiagonals, double compliance, long seed) {
        ClothMesh mesh = SquareSheet.generate(res, alternatingDiagonals ? SquareSheet.Cells.ALTERNATING : SquareSheet.Cells.DIAGONAL);
        double[] pos = mesh.positions();
        double jitter = 0.05 / (res - 1);
        Random rnd = new Random(seed);
        for (int i = 3 * res; i < pos.length; i++) pos[i] += jitter * (rnd.nextDouble() - 0.5);
        int[][] faces = new int[mesh.faceCount()][];
        for (int k = 0; k < faces.length; k++) faces[k] = mesh.face(k);
        return new MeshClothBuilder(ClothMesh.of(pos, faces, null, null, mesh.groups())).arealDensity(0.2)
                .family(ConstraintFamily.STRUCTURAL, 1, compliance)
                .pin(mesh.group("edge")).build();
    }

    static GlobalSolver solver(Cloth c, boolean multigrid, double tolerance, int maxIterations) {
        return new GlobalSolver(ConstraintRows.of(c.constraints().toArray(new Constraint[0])), c.particles().count(), multigrid, tolerance, maxIterations);
    }

    static SolverContext context() {
        SolverContext ctx = new SolverContext();
        ctx.load(new SolverSettings().withMode(ConstraintMode.XPBD), 1 / 60.0);
        return ctx;
    }

    /** The V-cycle as a dense matrix M (z = M r), built from the dense A of a small sheet. */
    static double[][] vCycleMatrix(double[][] a) {
        int n = a.length;
        int[] rowStart = new int[n + 1];
        List<Integer> cols = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) if (a[i][j] != 0 || i == j) cols.add(j);
            rowStart[i + 1] = cols.size();
        }
        int[] col = cols.stream().mapToInt(Integer::intValue).toArray();
        SparseMatrix s = new SparseMatrix(n, rowStart, col);
        for (int i = 0; i < n; i++) for (int k = rowStart[i]; k < rowStart[i + 1]; k++) s.val[k] = a[i][col[k]];
        AggregationMultigrid mg = new AggregationMultigrid(s);
        double[][] m = new double[n][n];
        double[] e = new double[n], z = new double[n];
        for (int j = 0; j < n; j++) {
            Arrays.fill(e, 0);
            e[j] = 1;
            mg.apply(e, z);
            for (int i = 0; i < n; i++) m[i][j] = z[i];
        }
        return m;
    }

    /** The smallest pivot of a dense Cholesky factorisation relative to the largest diagonal (≤ 0: not positive definite). */
    static double smallestCholeskyPivot(double[][] m0) {
        int n = m0.length;
        double[][] m = new double[n][];
        double largest = 0;
        for (int i = 0; i < n; i++) { m[i] = m0[i].clone(); largest = Math.max(largest, m[i][i]); }
        double smallest = Double.POSITIVE_INFINITY;
        for (int j = 0; j < n; j++) {
            double d = m[j][j];
            for (int k = 0; k < j; k++) d -= m[j][k] * m[j][k];
            smallest = Math.min(smallest, d / largest);
            if (d <= 0) return smallest;
            d = Math.sqrt(d);
            m[j][j] = d;
            for (int i = j + 1; i < n; i++) {
                double s = m[i][j];
                for (int k = 0; k < j; k++) s -= m[i][k] * m[j][k];
                m[i][j] = s / d;
            }
        }
        return smallest;
    }

    @Test
    void theVCycleIsSymmetricPositiveDefiniteOnTriangleMeshes() {
        for (boolean alternating : new boolean[] {false, true}) {
            Cloth c = triangleSheet(10, alternating, 1e-10, 7);
            double[][] a = solver(c, true, 1e-6, 1).linearSystemForTest(c.particles(), context())[0];
            double[][] m = vCycleMatrix(a);
            double largest = 0, asymmetry = 0;
            for (int i = 0; i < m.length; i++)
                for (int j = 0; j < m.length; j++) {
                    largest = Math.max(largest, Math.abs(m[i][j]));
                    asymmetry = Math.max(asymmetry, Math.abs(m[i][j] - m[j][i]));
                }
            double pivot = smallestCholeskyPivot(m);
            System.out.printf("V-cycle on a 10² triangle sheet (%s diagonals), %d rows: asymmetry %.1e of its largest entry, smallest Cholesky pivot %.2e of its largest diagonal%n",
                    alternating ? "alternating" : "parallel", m.length, asymmetry / largest, pivot);
            assertTrue(asymmetry <= 1e-12 * largest, "asymmetry " + asymmetry + " of " + largest);
            assertTrue(pivot > 0, "the V-cycle is not positive definite: pivot " + pivot);
        }
    }

    /** With a positive-definite V-cycle, multigrid-PCG reaches the dense direct solution (it stalled before). */
    @Test
    void multigridPcgMatchesADirectSolveOnATriangleMesh() {
        for (boolean alternating : new boolean[] {false, true}) {
            Cloth c = triangleSheet(12, alternating, 1e-6, 11);
            Particles p = c.particles();
            for (int i = 0; i < p.count(); i++) // off the rest shape, so that C ≠ 0
                if (!p.isPinned(i)) p.setPosition(i, p.x(i) + 0.004 * Math.sin(i), p.y(i) - 0.006 * Math.cos(3 * i), p.z(i) + 0.005 * Math.sin(7 * i));
            GlobalSolver g = solver(c, true, 1e-12, 2000);
            double[][][] sys = g.linearSystemForTest(c.particles(), context());
            double[] direct = GlobalSolverTest.denseSolve(sys[0], sys[1][0]), pcg = sys[2][0];
            double scale = 0, worst = 0;
            for (double v : direct) scale = Math.max(scale, Math.abs(v));
            for (int i = 0; i < direct.length; i++) worst = Math.max(worst, Math.abs(direct[i] - pcg[i]));
            System.out.printf("12² triangle sheet (%s diagonals): multigrid-PCG %d iterations to %.1e, largest Δλ error %.1e of max |Δλ|%n",
                    alternating ? "alternating" : "parallel", g.lastIterations(), g.lastRelativeResidual(), worst / scale);
            assertTrue(scale > 1e-3, "the sheet must be off its rest shape: max |Δλ| " + scale);
            assertTrue(g.lastRelativeResidual() <= 1e-12, "relative residual " + g.lastRelativeResidual() + " after " + g.lastIterations());
            assertTrue(worst <= 1e-8 * scale, "Δλ error " + worst + " of " + scale);
        }
    }

    /**
     * Coarse levels are aggregated by their values: from a pattern alone every coupling looked strong, a
     * triangle mesh's second level hardly coarsened, and a 128² sheet was left with 4517 unknowns for
     * the dense Cholesky (a minute to factor, and every cycle paid 20 M multiplications for it).
     */
    @Test
    void aTriangleMeshCoarsensToASmallDenseLevel() {
        Cloth c = triangleSheet(128, true, 1e-10, 3);
        GlobalSolver g = solver(c, true, 1e-6, 1);
        g.linearSolveForTest(c.particles(), context());
        System.out.printf("128² triangle sheet, %d rows: %d multigrid levels, coarsest %d%n", c.constraints().size(), g.multigridLevels(), g.multigridCoarsestSize());
        assertTrue(g.multigridCoarsestSize() <= AggregationMultigrid.COARSEST, "coarsest level " + g.multigridCoarsestSize());
    }
}
