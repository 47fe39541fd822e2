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
 * <pre>  KE(t) ≤ U_g(0) − U_g(t) + max(0, W_hand + W_colliders) + E_switches + ½ M (2 V)² + 1 % of the terms' sizes and 1 mJ  </pre>
 * is what a solver that neither creates nor amplifies energy keeps to, whatever its sweeps and steps, with
 * E_switches the strain found at solver switches (below; 0 in a run that keeps its solver).
 *
 * <p>Why a switch's strain is credited ({@link #switchedSolver}): a few Gauss–Seidel sweeps of XPBD leave a
 * stiff cloth stretched far past what its load holds, and that stretch, ½ Σ C²/α, is the material's energy at
 * that shape, which the sweeps never paid for and never let go (they leave it alike every step). A solver that
 * converges further, switched to, solves the same cloth stiffer and lets the stretch go. As with the mode
 * switch, a loaded spring is made stiffer, and the speed comes from the strain the switch found, not from
 * nowhere. A mode switch is not credited so but ends the judging ({@code Fuzz}): it changes the energy function
 * itself (PBD's k has none), so there is no strain in common to credit, where a solver switch keeps ½ Σ C²/α.
 * Fuzz seed 1002797: 1.9 MJ of strain and 94 J of kinetic energy after six steps under Gauss–Seidel, 8.2 kJ of
 * kinetic energy after the first step under Jacobi-PCG.
 */
final class Plausibility {
    private final Simulation sim;
    private final double startPotential, startHandWork, startColliderWork;
    /** The strain the solver switches so far found in the cloth, J. */
    private double strainAtSwitches;

    Plausibility(Simulation sim) {
        this.sim = sim;
        this.startPotential = Metrics.gravitationalEnergy(sim.particles(), sim.settings());
        this.startHandWork = sim.workByAttachments();
        this.startColliderWork = sim.workByColliders();
    }

    /** Credits the cloth's strain now, before a step under another solver, as energy it may release. */
    void switchedSolver() { strainAtSwitches += Metrics.elasticEnergy(sim); }

    /** Null if the state is within the bound for drivers other than hands no faster than {@code drive} m/s, else what exceeds it. */
    String check(double drive) {
        Particles particles = sim.particles();
        double mass = 0;
        for (int i = 0; i < particles.count(); i++) if (particles.inverseMass(i) != 0) mass += 1 / particles.inverseMass(i);
        double kinetic = Metrics.kineticEnergy(particles);
        double gravity = startPotential - Metrics.gravitationalEnergy(particles, sim.settings());
        // Negative counted work (a hand or a floor held the cloth back) is not subtracted: the uncounted drivers'
        // credit is a bound on what they can give the cloth, not their work, and the wind a hand holds back keeps giving.
        double given = Math.max(0, sim.workByAttachments() - startHandWork + sim.workByColliders() - startColliderWork) + strainAtSwitches;
        double drivers = 0.5 * mass * 4 * drive * drive;
        double bound = Math.max(0, gravity + given + drivers) + 0.01 * (Math.abs(gravity) + Math.abs(given) + drivers) + 1e-3;
        if (kinetic <= bound || !Double.isFinite(kinetic)) return null; // a non-finite state is reported as such
        return String.format(Locale.ROOT, "implausible: kinetic energy %.3g J above what gravity (%.3g J), hands, colliders and switches (%.3g J) and drivers of %.3g m/s"
                + " can give, %.3g J", kinetic, gravity, given, drive, bound);
    }
}
