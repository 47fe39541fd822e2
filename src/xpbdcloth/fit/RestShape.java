package xpbdcloth.fit;

import java.util.List;
import xpbdcloth.engine.Metrics;
import xpbdcloth.engine.Simulation;
import xpbdcloth.scene.Scene;

/**
 * A scene's cloth at rest: simulated until it stops swinging, then polished by Newton to the equilibrium
 * XPBD converges to ({@link ClothEnergy}), so an observation made here is what the scene's α hold exactly,
 * not what a few sweeps per substep happened to reach.
 */
public final class RestShape {
    /** Full positions in the scene's vertex order, m. */
    public final double[] positions;
    /** How far (largest distance of one particle, m) the simulator's own rest was from the equilibrium. */
    public final double simulatorGap;
    /** The same as a root mean square over the free particles' coordinates, m (the fit's residual's measure). */
    public final double simulatorGapRms;
    public final double simulatedSeconds;

    private RestShape(double[] positions, double simulatorGap, double simulatorGapRms, double simulatedSeconds) {
        this.positions = positions;
        this.simulatorGap = simulatorGap;
        this.simulatorGapRms = simulatorGapRms;
        this.simulatedSeconds = simulatedSeconds;
    }

    /** Steps the scene (with its own solver, damped at 2/s so it settles) for at most 20 s, then Newton. */
    public static RestShape of(Scene scene) {
        Simulation sim = scene.simulation();
        double keep = sim.settings().damping();
        sim.settings(sim.settings().withDamping(Math.max(keep, 2.0)));
        double t0 = sim.time();
        try {
            while (sim.time() - t0 < 20) {
                for (int s = 0; s < 25; s++) sim.step();
                if (sim.time() - t0 > 3 && Metrics.kineticEnergy(sim.particles()) < 1e-9) break;
            }
        } finally {
            sim.settings(sim.settings().withDamping(keep));
        }
        double[] simulated = sim.particles().positions().clone();
        ClothEnergy energy = new ClothEnergy(sim, List.of());
        Equilibrium eq = Equilibrium.solve(energy, simulated, heaviestWeight(sim));
        if (!eq.converged)
            throw new FitException("no rest shape found for " + scene.preset().name + ": after " + eq.iterations
                    + " Newton iterations a particle is still off balance by " + String.format(java.util.Locale.ROOT, "%.2e N", eq.forceResidual));
        if (eq.factor == null)
            throw new FitException("the rest shape of " + scene.preset().name + " is not a stable equilibrium (its Hessian is not positive definite:"
                    + " the cloth lies in a plane it would buckle out of, e.g. a vertical cloth whose weight is all in its plane)");
        double gap = 0, sum = 0;
        int free = 0;
        for (int i = 0; i < simulated.length; i += 3) {
            double d2 = sq(simulated[i] - eq.positions[i]) + sq(simulated[i + 1] - eq.positions[i + 1]) + sq(simulated[i + 2] - eq.positions[i + 2]);
            gap = Math.max(gap, Math.sqrt(d2));
            if (!sim.particles().isPinned(i / 3)) { sum += d2; free++; }
        }
        if (energy.activeTethers(eq.positions) > 0)
            throw new FitException("the rest shape of " + scene.preset().name + " stretches " + energy.activeTethers(eq.positions) + " tethers, which a fit leaves out");
        return new RestShape(eq.positions, gap, Math.sqrt(sum / Math.max(1, 3 * free)), sim.time() - t0);
    }

    static double heaviestWeight(Simulation sim) {
        double heaviest = 0;
        for (int i = 0; i < sim.particles().count(); i++) heaviest = Math.max(heaviest, sim.particles().mass(i));
        double g = Math.sqrt(sq(sim.settings().gravityX()) + sq(sim.settings().gravityY()) + sq(sim.settings().gravityZ()));
        return heaviest * Math.max(g, 1e-3);
    }

    private static double sq(double v) { return v * v; }
}
