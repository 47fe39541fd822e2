package xpbdcloth.tools;

import java.util.Locale;
import xpbdcloth.engine.Metrics;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;

/**
 * A bound a physical run respects, where "finite" is too weak (a case may fling its cloth 1e5 m away at
 * 1e7 m/s and stay finite): the cloth's kinetic energy is at most the work that gravity and its drivers can
 * have done on it. Gravity's is the potential energy it has given up. A hand (a grab's moving target) and a
 * collider (its pushes and its friction's drag) keep doing work as long as they move, so theirs is counted by
 * the engine, force times its particle's move in each substep ({@link Simulation#workByAttachments},
 * {@link Simulation#workByColliders}), and summed: a spinning box can feed a cloth that a hand holds back, and
 * the two works then nearly cancel. A driver not counted so (the wind or the air, a push out of a solid)
 * moving at most V can bring a particle to at most 2V, as a wall at V does to a ball it bounces off, so all of
 * them together give the cloth at most ½ M (2V)², M its free mass. Springs store only what was put in, and
 * damping, drag and friction take energy out. The cloth starts at rest in its rest shape, so
 * <pre>  KE(t) ≤ U_g(0) − U_g(t) + max(0, W_hand + W_colliders) + ½ M (2 V)² + 1 % of the terms' sizes and 1 mJ  </pre>
 * is what a solver that neither creates nor amplifies energy keeps to, whatever its sweeps and steps.
 */
final class Plausibility {
    private final Simulation sim;
    private final double startPotential, startHandWork, startColliderWork;

    Plausibility(Simulation sim) {
        this.sim = sim;
        this.startPotential = Metrics.gravitationalEnergy(sim.particles(), sim.settings());
        this.startHandWork = sim.workByAttachments();
        this.startColliderWork = sim.workByColliders();
    }

    /** Null if the state is within the bound for drivers other than hands no faster than {@code drive} m/s, else what exceeds it. */
    String check(double drive) {
        Particles particles = sim.particles();
        double mass = 0;
        for (int i = 0; i < particles.count(); i++) if (particles.inverseMass(i) != 0) mass += 1 / particles.inverseMass(i);
        double kinetic = Metrics.kineticEnergy(particles);
        double gravity = startPotential - Metrics.gravitationalEnergy(particles, sim.settings());
        // Negative counted work (a hand or a floor held the cloth back) is not subtracted: the uncounted drivers'
        // credit is a bound on what they can give the cloth, not their work, and the wind a hand holds back keeps giving.
        double hand = Math.max(0, sim.workByAttachments() - startHandWork + sim.workByColliders() - startColliderWork), drivers = 0.5 * mass * 4 * drive * drive;
        double bound = Math.max(0, gravity + hand + drivers) + 0.01 * (Math.abs(gravity) + Math.abs(hand) + drivers) + 1e-3;
        if (kinetic <= bound || !Double.isFinite(kinetic)) return null; // a non-finite state is reported as such
        return String.format(Locale.ROOT, "implausible: kinetic energy %.3g J above what gravity (%.3g J), hands and colliders (%.3g J) and drivers of %.3g m/s"
                + " can give, %.3g J", kinetic, gravity, hand, drive, bound);
    }
}
