package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/** Position-based projection must not inject energy. */
class EnergyHonestyTest {
    /**
     * A hanging cloth released from horizontal (pinned at two corners, no damping term anywhere) starts
     * at rest with no elastic energy, so without injection KE + U_gravity ≤ E₀ − U_elastic ≤ E₀ at every
     * step. Asserted with a margin of 1 % of the energy scale m·g·L (0.2 kg · 9.81 m/s² · 1 m, so 0.02 J).
     * (XPBD's C²/2α is left out: for a stiff α it measures the solver's unconverged residual, not the
     * energy the constraints hold.)
     */
    @Test
    void hangingClothNeverGainsEnergy() {
        for (ConstraintMode mode : ConstraintMode.values()) {
            Cloth c = new ClothBuilder().resolution(16, 16).size(1, 1).plane(ClothBuilder.Plane.HORIZONTAL).origin(0, 1, 0.5)
                    .arealDensity(0.2).family(ConstraintFamily.STRUCTURAL, 1, 1e-4).pinTopCorners().build();
            Simulation sim = c.simulation(new SolverSettings().withMode(mode).withIterations(10).withSubsteps(5).withTimestep(1 / 60.0));
            double e0 = energy(sim), worst = -Double.MAX_VALUE;
            double scale = 0.2 * 9.81 * 1.0;
            for (int s = 0; s < 600; s++) {
                sim.step();
                worst = Math.max(worst, energy(sim) - e0);
            }
            System.out.printf("%s: largest energy rise over 10 s %.2e J (bound %.2e J)%n", mode, worst, 0.01 * scale);
            assertTrue(worst < 0.01 * scale, mode + ": energy rose by " + worst + " J");
        }
    }

    static double energy(Simulation sim) {
        return Metrics.kineticEnergy(sim.particles()) + Metrics.gravitationalEnergy(sim.particles(), sim.settings());
    }
}
