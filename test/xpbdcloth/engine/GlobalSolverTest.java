package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/** The global (PCG) solve of XPBD's constraint system. */
class GlobalSolverTest {

    static Cloth smallCloth() {
        return new ClothBuilder().resolution(6, 5).size(0.5, 0.4).arealDensity(0.2).pinTopCorners()
                .family(ConstraintFamily.STRUCTURAL, 1, 1e-6).family(ConstraintFamily.SHEAR, 1, 1e-3).family(ConstraintFamily.BEND, 1, 1e-2).build();
    }

    /** Gaussian elimination with partial pivoting: the dense reference. */
    static double[] denseSolve(double[][] a0, double[] b0) {
        int n = b0.length;
        double[][] a = new double[n][];
        for (int i = 0; i < n; i++) a[i] = a0[i].clone();
        double[] b = b0.clone();
        for (int k = 0; k < n; k++) {
            int piv = k;
            for (int i = k + 1; i < n; i++) if (Math.abs(a[i][k]) > Math.abs(a[piv][k])) piv = i;
            double[] tr = a[k]; a[k] = a[piv]; a[piv] = tr;
            double tb = b[k]; b[k] = b[piv]; b[piv] = tb;
            for (int i = k + 1; i < n; i++) {
                double f = a[i][k] / a[k][k];
                for (int j = k; j < n; j++) a[i][j] -= f * a[k][j];
                b[i] -= f * b[k];
            }
        }
        double[] x = new double[n];
        for (int i = n - 1; i >= 0; i--) {
            double s = b[i];
            for (int j = i + 1; j < n; j++) s -= a[i][j] * x[j];
            x[i] = s / a[i][i];
        }
        return x;
    }

    /** On a small cloth (all three families), PCG's Δλ matches a dense direct solve of the same system to 1e-8. */
    @Test
    void pcgMatchesDenseDirectSolve() {
        for (boolean multigrid : new boolean[] {false, true}) {
            Cloth c = smallCloth();
            Particles p = c.particles();
            for (int i = 0; i < p.count(); i++) if (!p.isPinned(i)) p.setPosition(i, p.x(i) + 0.01 * Math.sin(i), p.y(i) - 0.02 * Math.cos(3 * i), 0.015 * Math.sin(7 * i));
            Constraint[] cs = c.constraints().toArray(new Constraint[0]);
            GlobalSolver g = new GlobalSolver(ConstraintRows.of(cs), p.count(), multigrid, 1e-13, 10_000);
            SolverContext ctx = new SolverContext();
            ctx.load(new SolverSettings().withMode(ConstraintMode.XPBD), 1 / 60.0);
            double[][][] sys = g.linearSystemForTest(p, ctx);
            double[] direct = denseSolve(sys[0], sys[1][0]), pcg = sys[2][0];
            double scale = 0;
            for (double v : direct) scale = Math.max(scale, Math.abs(v));
            for (int i = 0; i < direct.length; i++)
                assertEquals(direct[i], pcg[i], 1e-8 * scale, (multigrid ? "multigrid" : "jacobi") + " Δλ[" + i + "]");
        }
    }

    /** Largest relative error of a 40-link chain's links against α·g·(mass below), after quasi-static loading. */
    static double chainError(SolverType type, int iterations) {
        int links = 40;
        double alpha = 1e-4, m = 0.01, L = 0.05;
        SolverSettings s = new SolverSettings().withMode(ConstraintMode.XPBD).withIterations(iterations).withTimestep(1 / 60.0).withSolver(type).withPcgTolerance(1e-10).withPcgMaxIterations(500);
        Simulation sim = Rigs.chain(links, m, L, s, 1, alpha);
        int steps = 1200;
        for (int k = 0; k < steps; k++) {
            double u = Math.min(1, (k + 1.0) / (0.6 * steps));
            sim.settings(s.withGravity(0, -Rigs.G * u * u * (3 - 2 * u), 0));
            sim.step();
        }
        Particles p = sim.particles();
        double worst = 0;
        for (int i = 0; i < links; i++) {
            double expected = alpha * Rigs.G * m * (links - i);
            worst = Math.max(worst, Math.abs(p.y(i) - p.y(i + 1) - L - expected) / expected);
        }
        return worst;
    }

    /**
     * A stiff 40-link chain (α = 1e-4 m/N): one global iteration per step puts every link within 1e-9 of
     * Hooke, with or without the geometric stiffness the taut links bring into the system (it changes the
     * step, not the equilibrium), and 4 iterations give the same stretch: XPBD's stiffness does not depend
     * on the iteration count. Gauss–Seidel with 20 sweeps per step is far off.
     */
    @Test
    void chainReachesHookeInOneGlobalIteration() {
        double mg1 = chainError(SolverType.MULTIGRID_PCG, 1), mg4 = chainError(SolverType.MULTIGRID_PCG, 4);
        double jacobi1 = chainError(SolverType.JACOBI_PCG, 1), gs = chainError(SolverType.GAUSS_SEIDEL, 20);
        System.out.printf("40-link chain, worst link error against Hooke: multigrid-PCG n=1 %.2e, n=4 %.2e, Jacobi-PCG n=1 %.2e, Gauss-Seidel n=20 %.2e%n", mg1, mg4, jacobi1, gs);
        assertTrue(mg1 < 1e-9, "multigrid-PCG, 1 iteration: " + mg1);
        assertTrue(mg4 < 1e-9, "multigrid-PCG, 4 iterations: " + mg4);
        assertTrue(jacobi1 < 1e-9, "Jacobi-PCG, 1 iteration: " + jacobi1);
        assertTrue(gs > 0.01, "Gauss-Seidel, 20 sweeps: " + gs);
    }

    /**
     * Converged Gauss–Seidel and converged global solves reach the same hanging cloth, within 0.1 mm.
     * Gravity is ramped in (quasi-static loading) so neither run is left swinging when compared, and
     * the cloth hangs from its whole top edge: hung from two corners its top edge is compressed and
     * may buckle either way out of plane, so the equilibrium would not be unique.
     */
    @Test
    void convergedGlobalAndGaussSeidelAgree() {
        double[][] out = new double[2][];
        SolverType[] types = {SolverType.GAUSS_SEIDEL, SolverType.MULTIGRID_PCG};
        for (int k = 0; k < 2; k++) {
            ClothBuilder b = new ClothBuilder().resolution(10, 10).size(0.5, 0.5).arealDensity(0.2)
                    .family(ConstraintFamily.STRUCTURAL, 1, 1e-4).family(ConstraintFamily.SHEAR, 1, 1e-3);
            for (int col = 0; col < 10; col++) b.pin(0, col);
            Cloth c = b.build();
            Simulation sim = c.simulation(new SolverSettings().withMode(ConstraintMode.XPBD).withTimestep(1 / 60.0)
                    .withSolver(types[k]).withIterations(k == 0 ? 300 : 4).withPcgTolerance(1e-10).withPcgMaxIterations(500));
            for (int s = 0; s < 1200; s++) {
                double u = Math.min(1, (s + 1.0) / 720);
                sim.settings(sim.settings().withGravity(0, -Rigs.G * u * u * (3 - 2 * u), 0));
                sim.step();
            }
            out[k] = c.particles().positions().clone();
        }
        double worst = 0;
        for (int i = 0; i < out[0].length; i++) worst = Math.max(worst, Math.abs(out[0][i] - out[1][i]));
        System.out.printf("hanging 10x10 cloth: converged Gauss-Seidel vs multigrid-PCG differ by at most %.2e m%n", worst);
        assertTrue(worst < 1e-4, "max position difference " + worst);
    }

    /**
     * A sphere that starts inside a hanging 32² cloth (all families, 2 × 10): Gauss–Seidel pushes the
     * pierced particles out and holds the rest (peak strain about 11, mean below 0.15). A global solver
     * used to fight the contacts with Newton steps that do not see them (peak strain 88 in the first
     * step, 230 later, 9 kJ of kinetic energy): now it stays within twice Gauss–Seidel's peak, and its
     * mean strain stays below 2 (the cloth is not pulled apart as a whole).
     */
    @Test
    void aSphereStartingInsideTheClothHoldsUnderAGlobalSolver() {
        double[] peak = new double[2], worstMean = new double[2];
        SolverType[] solvers = {SolverType.GAUSS_SEIDEL, SolverType.JACOBI_PCG};
        for (int k = 0; k < 2; k++) {
            Cloth c = new ClothBuilder().resolution(32, 32).arealDensity(0.2).size(1, 1).origin(0, 1.6, 0).pinTopCorners()
                    .family(ConstraintFamily.STRUCTURAL, 1.0, 1e-6).family(ConstraintFamily.SHEAR, 0.5, 1e-3).family(ConstraintFamily.BEND, 0.1, 1e-2).build();
            Simulation sim = c.simulation(new SolverSettings().withSubsteps(10).withSolver(solvers[k]));
            sim.add(new Sphere(SpherePath.fixed(0, 1.1, 0), 0.2, 0.01, 0.5, 0.35));
            for (int s = 0; s < 16; s++) {
                sim.step();
                peak[k] = Math.max(peak[k], Metrics.maxStrain(sim, ConstraintFamily.STRUCTURAL));
                worstMean[k] = Math.max(worstMean[k], Metrics.meanStrain(sim, ConstraintFamily.STRUCTURAL));
            }
        }
        System.out.printf("sphere inside the cloth, 16 steps: peak strain %.2f (Gauss-Seidel) vs %.2f (Jacobi-PCG), worst mean %.3f vs %.3f%n",
                peak[0], peak[1], worstMean[0], worstMean[1]);
        assertTrue(peak[1] < 2 * peak[0], "global peak strain " + peak[1] + " vs Gauss-Seidel " + peak[0]);
        assertTrue(worstMean[1] < 2, "global mean strain " + worstMean[1]);
    }

    /**
     * Particles of 1e-9 kg (a 32² cloth of 1 µg): the global solvers used to reach strain 2e4 where
     * Gauss–Seidel stayed at 0.024. The weight is negligible against α = 1e-6 m/N, so the cloth must
     * barely stretch.
     */
    @Test
    void featherweightParticlesDoNotTearUnderAGlobalSolver() {
        Cloth c = new ClothBuilder().resolution(32, 32).arealDensity(0.2).size(1, 1).origin(0, 1.6, 0).pinTopCorners()
                .family(ConstraintFamily.STRUCTURAL, 1.0, 1e-6).family(ConstraintFamily.SHEAR, 0.5, 1e-3).family(ConstraintFamily.BEND, 0.1, 1e-2).build();
        for (int i = 0; i < c.particles().count(); i++) c.particles().setMass(i, 1e-9);
        Simulation sim = c.simulation(new SolverSettings().withSubsteps(10).withSolver(SolverType.JACOBI_PCG));
        double peak = 0;
        for (int s = 0; s < 10; s++) {
            sim.step();
            peak = Math.max(peak, Metrics.maxStrain(sim, ConstraintFamily.STRUCTURAL));
        }
        assertTrue(peak < 0.01, "peak strain " + peak);
    }

    /** CG iterations of one linear solve to 1e-6 on experiment 7's state: a res² cloth turning about its pinned edge, α = 1e-10. */
    static int iterationsOfOneSolve(int res, SolverType type) { return iterationsOfOneSolve(res, type, 0); }

    /** The same, with every free particle first moved up or down by up to crumple/2 edge lengths (seeded). */
    static int iterationsOfOneSolve(int res, SolverType type, double crumple) {
        Cloth c = new ClothBuilder().resolution(res, res).size(1, 1).plane(ClothBuilder.Plane.HORIZONTAL).origin(0, 1, 0)
                .arealDensity(0.2).family(ConstraintFamily.STRUCTURAL, 1, 1e-10).build();
        Particles p = c.particles();
        for (int col = 0; col < res; col++) p.pin(c.index(0, col));
        java.util.Random random = new java.util.Random(1);
        for (int i = 0; i < p.count(); i++)
            if (!p.isPinned(i)) p.setPosition(i, p.x(i), p.y(i) + crumple / (res - 1) * (random.nextDouble() - 0.5), p.z(i));
        for (int i = 0; i < p.count(); i++) if (!p.isPinned(i)) p.setVelocity(i, 0, 3 * (p.z(i) + 0.5), -3 * (p.y(i) - 1));
        Simulation sim = c.simulation(new SolverSettings().withMode(ConstraintMode.XPBD).withIterations(1).withSubsteps(1).withTimestep(1 / 60.0)
                .withSolver(type).withPcgTolerance(1e-6).withPcgMaxIterations(5000));
        sim.step();
        return sim.profile().lastPcgIterations();
    }

    /**
     * Mesh independence: on experiment 7's state Jacobi-PCG needs N − 1 iterations (the error travels
     * one row per iteration along each grid line), multigrid-PCG with its line smoother the same small
     * number at every size (at most 1.3× growth from 32² to 128² is the target; it is 1 at each).
     */
    @Test
    void multigridIterationsDoNotGrowWithResolution() {
        int[] sizes = {32, 64, 128};
        int[] mg = new int[3], jacobi = new int[3];
        for (int k = 0; k < 3; k++) {
            mg[k] = iterationsOfOneSolve(sizes[k], SolverType.MULTIGRID_PCG);
            jacobi[k] = iterationsOfOneSolve(sizes[k], SolverType.JACOBI_PCG);
        }
        System.out.printf("one solve to 1e-6 at 32², 64², 128²: multigrid-PCG %s, Jacobi-PCG %s CG iterations%n", java.util.Arrays.toString(mg), java.util.Arrays.toString(jacobi));
        assertTrue(mg[2] <= 1.3 * mg[0] && mg[2] <= 5, "multigrid-PCG iterations " + java.util.Arrays.toString(mg));
        assertTrue(jacobi[2] >= 3 * jacobi[0], "Jacobi-PCG iterations " + java.util.Arrays.toString(jacobi));
    }

    /**
     * On the flat grid the rows of perpendicular edges do not couple, so the line smoother alone solves
     * the system and the count above says little about the coarse levels. Crumpled (particles moved off
     * the plane by up to ±0.15 of an edge) the lines couple, and the count must still not grow.
     */
    @Test
    void multigridIterationsDoNotGrowOnACrumpledGrid() {
        int[] sizes = {32, 64, 128};
        int[] mg = new int[3];
        for (int k = 0; k < 3; k++) mg[k] = iterationsOfOneSolve(sizes[k], SolverType.MULTIGRID_PCG, 0.3);
        int jacobi = iterationsOfOneSolve(128, SolverType.JACOBI_PCG, 0.3);
        System.out.printf("one solve to 1e-6 on a crumpled grid at 32², 64², 128²: multigrid-PCG %s CG iterations (Jacobi-PCG %d at 128²)%n", java.util.Arrays.toString(mg), jacobi);
        assertTrue(mg[0] > 1, "the crumpled grid must couple its lines (more than one iteration): " + mg[0]);
        assertTrue(mg[2] <= 1.3 * mg[0] && mg[2] <= 10, "multigrid-PCG iterations " + java.util.Arrays.toString(mg));
        assertTrue(jacobi >= 10 * mg[2], "Jacobi-PCG " + jacobi + " against multigrid-PCG " + mg[2]);
    }
}
