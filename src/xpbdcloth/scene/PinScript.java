package xpbdcloth.scene;

import xpbdcloth.engine.Kinematics;
import xpbdcloth.engine.Particles;

/**
 * Moves pinned particles by displacements over time windows with smoothstep easing, then holds them:
 * x(t) = x₀ + Σⱼ dⱼ·s(uⱼ), uⱼ = clamp((t − startⱼ)/durationⱼ), s(u) = u²(3 − 2u), summed over the motions
 * of that particle, so a pin can move in, wait and move out. Smoothstep starts and ends with zero
 * velocity, so the pins never jerk the cloth (the seed's "opening the corners").
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
            if (firstMotionOf(j) != j) continue; // handled with the particle's first motion
            double px = base[3 * j], py = base[3 * j + 1], pz = base[3 * j + 2];
            for (int k = j; k < particles.length; k++) {
                if (particles[k] != particles[j]) continue;
                double u = Math.max(0, Math.min(1, (t - start[k]) / duration[k]));
                double s = u * u * (3 - 2 * u);
                px += s * displacement[3 * k];
                py += s * displacement[3 * k + 1];
                pz += s * displacement[3 * k + 2];
            }
            p.moveKinematic(particles[j], px, py, pz);
        }
    }

    private int firstMotionOf(int j) {
        for (int k = 0; k < j; k++) if (particles[k] == particles[j]) return k;
        return j;
    }

    /** The time after which every pin holds still. */
    double endTime() {
        double end = 0;
        for (int j = 0; j < start.length; j++) end = Math.max(end, start[j] + duration[j]);
        return end;
    }
}
