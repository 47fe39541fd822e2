package xpbdcloth.tools;

import java.util.Locale;
import xpbdcloth.engine.Metrics;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.SolverSettings;

/**
 * A bound a physical run respects, where "finite" is too weak (a case may fling its cloth 1e5 m away at
 * 1e7 m/s and stay finite): the cloth's kinetic energy is at most the work that gravity and its drivers can
 * have done on it. Gravity's is the potential energy it has given up. A driver (a collider's surface, a grab,
 * the wind or the air, a push out of a solid) moving at most V can bring a particle to at most 2V, as a wall at
 * V does to a ball it bounces off, so all of them together give the cloth at most ½ M (2V)², M its free mass.
 * Springs store only what was put in, and damping, drag and friction take energy out. The cloth starts at
 * rest in its rest shape, so
 * <pre>  KE(t) ≤ U_g(0) − U_g(t) + ½ M (2 V)² + 1 % of the sum and 1 mJ  </pre>
 * is what a solver that neither creates nor amplifies energy keeps to, whatever its sweeps and steps.
 */
final class Plausibility {
    private final Particles particles;
    private final SolverSettings settings;
    private final double startPotential;

    Plausibility(Particles particles, SolverSettings settings) {
        this.particles = particles;
        this.settings = settings;
        this.startPotential = Metrics.gravitationalEnergy(particles, settings);
    }

    /** Null if the state is within the bound for drivers no faster than {@code drive} m/s, else what exceeds it. */
    String check(double drive) {
        double mass = 0;
        for (int i = 0; i < particles.count(); i++) if (particles.inverseMass(i) != 0) mass += 1 / particles.inverseMass(i);
        double kinetic = Metrics.kineticEnergy(particles);
        double given = startPotential - Metrics.gravitationalEnergy(particles, settings) + 0.5 * mass * 4 * drive * drive;
        double bound = Math.max(0, given) * 1.01 + 1e-3;
        if (kinetic <= bound || !Double.isFinite(kinetic)) return null; // a non-finite state is reported as such
        return String.format(Locale.ROOT, "implausible: kinetic energy %.3g J above what gravity and drivers of %.3g m/s can give, %.3g J",
                kinetic, drive, bound);
    }
}
