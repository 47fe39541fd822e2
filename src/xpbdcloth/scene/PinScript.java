package xpbdcloth.scene;

import xpbdcloth.engine.Kinematics;
import xpbdcloth.engine.Particles;

/**
 * Moves pinned particles by a displacement over a time window with smoothstep easing, then holds them:
 * x(t) = x₀ + d·s(u), u = clamp((t − start)/duration), s(u) = u²(3 − 2u). Smoothstep starts and ends with
 * zero velocity, so the pins themselves never jerk the cloth (the seed's "opening the corners").
 */
final class PinScript implements Kinematics {
    private final int[] particles;
    private final double[] base, displacement, start, duration;

    PinScript(Particles p, int[] particles, double[][] displacements, double[] start, double[] duration) {
        this.particles = particles.clone();
        this.base = new double[3 * particles.length];
        this.displacement = new double[3 * particles.length];
        this.start = start.clone();
        this.duration = duration.clone();
        for (int j = 0; j < particles.length; j++) {
            base[3 * j] = p.x(particles[j]);
            base[3 * j + 1] = p.y(particles[j]);
            base[3 * j + 2] = p.z(particles[j]);
            System.arraycopy(displacements[j], 0, displacement, 3 * j, 3);
        }
    }

    @Override public void apply(Particles p, double t) {
        for (int j = 0; j < particles.length; j++) {
            double u = Math.max(0, Math.min(1, (t - start[j]) / duration[j]));
            double s = u * u * (3 - 2 * u);
            p.moveKinematic(particles[j], base[3 * j] + s * displacement[3 * j],
                    base[3 * j + 1] + s * displacement[3 * j + 1], base[3 * j + 2] + s * displacement[3 * j + 2]);
        }
    }

    /** The time after which every pin holds still. */
    double endTime() {
        double end = 0;
        for (int j = 0; j < start.length; j++) end = Math.max(end, start[j] + duration[j]);
        return end;
    }
}
