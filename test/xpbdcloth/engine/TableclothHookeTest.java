package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;
import xpbdcloth.mesh.ClothMesh;
import xpbdcloth.mesh.RoundTablecloth;

/**
 * A cloth that is not a grid obeys Hooke's law per edge. A round tablecloth held by its hem sags under
 * gravity like a drum skin; once it is still, XPBD's static solution is the equilibrium of springs of
 * stiffness 1/α: every edge of rest length L at length ℓ pulls with T = (ℓ − L)/α, and at every free
 * vertex these pulls balance its weight, Σₑ Tₑ ûₑ + m g = 0. Summed over the whole cloth, the hem edges
 * carry the weight of everything inside the hem: Σ_hem Tₑ sin θₑ = W. Both are closed forms the
 * simulation must meet whatever the mesh, with no fitted number.
 *
 * <p>Measured: a global solver (Jacobi-PCG, which re-linearises every constraint at the current positions)
 * meets the balance to 0.14 % of a vertex's weight. Gauss–Seidel settles 1.6 % off, whatever its
 * iteration count (20 or 100 sweeps give the same): XPBD's update assumes the constraint gradients do not
 * turn during a step (Macklin et al. 2016, §4: the g(x) = 0 simplification), and every step turns them by
 * the ~h²g the solve must undo. The error shrinks with h², so substeps, not sweeps, reduce it: with one
 * substep of 1/60 s the same cloth was off by 69× a vertex's weight at rest (the edge tensions of a
 * taut membrane are many times a vertex's weight, so a turn of a few hundredths of a radian unbalances
 * them).
 */
class TableclothHookeTest {
    static final double G = 9.81, ALPHA = 1e-3;

    @Test
    void underAGlobalSolverEveryVertexBalancesWithinOnePercent() {
        assertTrue(worstResidual(SolverType.JACOBI_PCG, 4) < 0.01);
    }

    @Test
    void underGaussSeidelEveryVertexBalancesWithinFivePercent() {
        assertTrue(worstResidual(SolverType.GAUSS_SEIDEL, 20) < 0.05);
    }

    /** The worst free vertex's force residual over its weight, after the hem-held cloth came to rest. */
    static double worstResidual(SolverType solver, int iterations) {
        ClothMesh mesh = RoundTablecloth.generate(0.4, 4);
        Cloth cloth = new MeshClothBuilder(mesh).arealDensity(0.2).family(ConstraintFamily.STRUCTURAL, 1, ALPHA)
                .pin(mesh.group("hem")).build();
        Simulation sim = cloth.simulation(new SolverSettings().withSolver(solver).withIterations(iterations).withSubsteps(20)
                .withTimestep(1 / 60.0).withGravity(0, -G, 0));
        Particles p = cloth.particles();
        for (int s = 0; s < 1500; s++) sim.step();
        assertTrue(Metrics.kineticEnergy(p) < 1e-10, "at rest, KE " + Metrics.kineticEnergy(p));
        assertTrue(p.y(0) < -0.005, "the centre sags: " + p.y(0));

        int n = p.count();
        double[] f = new double[3 * n];
        double hemLift = 0, freeWeight = 0, worst = 0;
        for (Constraint c : cloth.constraints()) {
            DistanceConstraint d = (DistanceConstraint) c;
            int a = d.a(), b = d.b();
            double dx = p.x(b) - p.x(a), dy = p.y(b) - p.y(a), dz = p.z(b) - p.z(a);
            double l = Math.sqrt(dx * dx + dy * dy + dz * dz), tension = (l - d.restLength()) / ALPHA;
            f[3 * a] += tension * dx / l; f[3 * a + 1] += tension * dy / l; f[3 * a + 2] += tension * dz / l;
            f[3 * b] -= tension * dx / l; f[3 * b + 1] -= tension * dy / l; f[3 * b + 2] -= tension * dz / l;
            if (p.isPinned(a) != p.isPinned(b)) hemLift += tension * Math.abs(dy) / l;
        }
        for (int i = 0; i < n; i++) {
            if (p.isPinned(i)) continue;
            double weight = p.mass(i) * G;
            freeWeight += weight;
            double rx = f[3 * i], ry = f[3 * i + 1] - weight, rz = f[3 * i + 2];
            worst = Math.max(worst, Math.sqrt(rx * rx + ry * ry + rz * rz) / weight);
        }
        System.out.printf("tablecloth held by its hem, %s: centre sag %.4f m, worst vertex force residual %.2e of its weight, hem lift %.6f N vs weight %.6f N%n",
                solver.label(), -p.y(0), worst, hemLift, freeWeight);
        assertEquals(freeWeight, hemLift, 0.01 * freeWeight, solver.label() + ": the hem carries the cloth's weight");
        return worst;
    }
}
