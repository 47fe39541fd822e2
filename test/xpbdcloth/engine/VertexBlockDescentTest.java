package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/**
 * Vertex block descent solves XPBD's implicit Euler step in positions: one particle on a spring follows the
 * closed form of that step, and a hanging cloth's rest does not depend on the sweep count (where Gauss–Seidel's
 * does), on the thread count, or on the solver's lag while it moves.
 */
class VertexBlockDescentTest {
    static SolverSettings vbd(int substeps, int iterations) {
        return new SolverSettings().withMode(ConstraintMode.XPBD).withSolver(SolverType.VERTEX_BLOCK_DESCENT).withSubsteps(substeps).withIterations(iterations)
                .withTimestep(0.02).withGravity(0, -Rigs.G, 0);
    }

    /**
     * A mass m on a spring of stiffness k = 1/α below a pin, moving along the spring: the step's energy is
     * quadratic in the length, so one Newton step solves it, and the length follows implicit Euler's
     * x' = (m y/h² + k L)/(m/h² + k), y = x + h v − h² g (lengths grow downward), v' = (x' − x)/h. The
     * spring's compliance becomes α₂ before step {@code change}; every step is checked against the closed
     * form to 1e-12, and the final length is returned.
     */
    static double followsImplicitEuler(double alpha, double alpha2, int change, int steps) {
        double m = SPRING_MASS, L = SPRING_LENGTH, h = 0.02 / 4, k = 1 / alpha;
        Simulation sim = Rigs.spring(m, L, vbd(4, 1), 1, alpha);
        Particles p = sim.particles();
        double x = L, v = 0;
        for (int step = 0; step < steps; step++) {
            if (step == change) { sim.setCompliance(ConstraintFamily.STRUCTURAL, alpha2); k = 1 / alpha2; }
            sim.step();
            for (int s = 0; s < 4; s++) {
                double y = x + h * v + h * h * Rigs.G;
                double next = (m * y / (h * h) + k * L) / (m / (h * h) + k);
                v = (next - x) / h;
                x = next;
            }
            assertEquals(x, -p.y(1), 1e-12, "length after step " + step);
        }
        return x;
    }

    static final double SPRING_MASS = 0.05, SPRING_LENGTH = 0.3;

    @Test
    void aSpringFollowsImplicitEulerInOneIteration() {
        double alpha = 1e-3, x = followsImplicitEuler(alpha, alpha, -1, 50);
        // It hangs at L + mg/k, the spring's static stretch.
        assertEquals(SPRING_LENGTH + SPRING_MASS * Rigs.G * alpha, x, 1e-2 * SPRING_MASS * Rigs.G * alpha);
    }

    /**
     * The solver keeps the stiffnesses it derives from the compliances while the material is unchanged; a
     * compliance changed between steps (a key, a fit) is the new spring from the next step on: the same
     * closed form, continued with k = 1/α₂, settling at the new static stretch.
     */
    @Test
    void aComplianceChangedBetweenStepsIsTheNewSpring() {
        double alpha2 = 4e-3, x = followsImplicitEuler(1e-3, alpha2, 20, 100);
        assertEquals(SPRING_LENGTH + SPRING_MASS * Rigs.G * alpha2, x, 1e-2 * SPRING_MASS * Rigs.G * alpha2);
    }

    /** A net of stiff springs hanging from two corners, its weight carried to them through n edges. */
    static Cloth hangingSheet(int n) {
        return new ClothBuilder().resolution(n, n).size(1, 1).origin(0, 2, 0).arealDensity(0.3).pinTopCorners()
                .family(ConstraintFamily.STRUCTURAL, 1, 2e-5).build();
    }

    /** The middle of the top edge below the pinned corners, after {@code seconds} of damped hanging. */
    static double sag(int n, SolverSettings settings, double seconds) {
        Cloth cloth = hangingSheet(n);
        Simulation sim = cloth.simulation(settings.withDamping(3));
        for (int s = 0; s < Math.round(seconds / 0.02); s++) sim.step();
        Particles p = sim.particles();
        sim.close();
        return p.y(cloth.index(0, 0)) - 0.5 * (p.y(cloth.index(0, (n - 1) / 2)) + p.y(cloth.index(0, n / 2)));
    }

    /**
     * At rest every particle's step is already balanced when the iteration starts, so the rest is the
     * energy's minimum at one sweep a substep as at twelve. Gauss–Seidel rebuilds the forces from λ = 0
     * every substep and its rest sags more the fewer its sweeps (a 16² net of stiff springs: 3× the
     * converged sag at twelve sweeps).
     */
    @Test
    void theRestDoesNotDependOnTheSweepCount() {
        int n = 16;
        double one = sag(n, vbd(10, 1), 12), twelve = sag(n, vbd(10, 12), 12);
        assertEquals(twelve, one, 1e-6 * twelve, "vertex block descent, 1 vs 12 sweeps a substep");
        SolverSettings gs = new SolverSettings().withMode(ConstraintMode.XPBD).withSubsteps(10).withTimestep(0.02).withGravity(0, -Rigs.G, 0);
        double gsOne = sag(n, gs.withIterations(1), 12), gsTwelve = sag(n, gs.withIterations(12), 12);
        assertTrue(gsOne > 1.3 * gsTwelve, "Gauss-Seidel's rest sags more with fewer sweeps: " + gsOne + " vs " + gsTwelve);
        assertTrue(gsTwelve > 1.5 * twelve, "and even at twelve it is far from the converged rest: " + gsTwelve + " vs " + twelve);
    }

    /**
     * The step's balance tells the two rests apart: vertex block descent's settled net leaves every particle
     * balanced to well under 1 % of its weight, Gauss–Seidel's (one sweep a substep) leaves its particles
     * off by more than their weight: what holds it up is the solver's lag, not the material.
     */
    @Test
    void theBalanceTellsAConvergedRestFromAnUnconvergedOne() {
        for (SolverType type : new SolverType[] {SolverType.VERTEX_BLOCK_DESCENT, SolverType.GAUSS_SEIDEL}) {
            Cloth cloth = hangingSheet(16);
            Simulation sim = cloth.simulation(new SolverSettings().withMode(ConstraintMode.XPBD).withSolver(type).withSubsteps(10).withIterations(1)
                    .withTimestep(0.02).withGravity(0, -Rigs.G, 0).withDamping(3));
            for (int s = 0; s < 600; s++) sim.step();
            double balance = sim.balance();
            if (type == SolverType.VERTEX_BLOCK_DESCENT) assertTrue(balance < 1e-3, "vertex block descent's rest off balance by " + balance);
            else assertTrue(balance > 1, "Gauss-Seidel's rest off balance by " + balance + " weights");
        }
    }

    /** Particles of one colour share no energy term: two threads give the first thread's bits. */
    @Test
    void twoThreadsGiveTheSameBits() {
        double[][] x = new double[2][];
        for (int threads = 1; threads <= 2; threads++) {
            Cloth cloth = hangingSheet(12);
            Simulation sim = cloth.simulation(vbd(5, 2).withThreads(threads));
            sim.add(new Sphere(SpherePath.linear(0, 1.6, 0.6, 0, 0, -0.5), 0.2, 0.01, 0.5, 0.3));
            for (int s = 0; s < 60; s++) sim.step();
            sim.close();
            x[threads - 1] = sim.particles().positions().clone();
        }
        assertArrayEquals(x[0], x[1]);
    }

    /** A cloth dropped flat on a floor comes to rest on it, its particles the margin above it. */
    @Test
    void aClothComesToRestOnAFloor() {
        Cloth cloth = new ClothBuilder().resolution(12, 12).size(0.6, 0.6).plane(ClothBuilder.Plane.HORIZONTAL).origin(0, 0.2, 0).arealDensity(0.3)
                .family(ConstraintFamily.STRUCTURAL, 1, 1e-5).build();
        Simulation sim = cloth.simulation(vbd(5, 2).withDamping(0.5));
        double margin = 0.005;
        sim.add(new Plane(new double[] {0, 0, 0}, new double[] {0, 1, 0}, margin, 0.6, 0.4));
        for (int s = 0; s < 200; s++) sim.step();
        Particles p = sim.particles();
        double kinetic = 0, lowest = Double.POSITIVE_INFINITY;
        for (int i = 0; i < p.count(); i++) {
            kinetic += 0.5 * p.mass(i) * (p.vx(i) * p.vx(i) + p.vy(i) * p.vy(i) + p.vz(i) * p.vz(i));
            lowest = Math.min(lowest, p.y(i));
        }
        assertTrue(kinetic < 1e-10, "kinetic energy after 4 s: " + kinetic);
        assertEquals(margin, lowest, 1e-6, "lowest particle");
    }

    @Test
    void pbdIsRefusedByName() {
        SolverSettings s = new SolverSettings().withMode(ConstraintMode.PBD);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> s.withSolver(SolverType.VERTEX_BLOCK_DESCENT));
        assertTrue(e.getMessage().contains("PBD") && e.getMessage().contains("vertex-block-descent"), e.getMessage());
    }
}
