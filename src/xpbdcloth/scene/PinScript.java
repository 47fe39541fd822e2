package xpbdcloth.scene;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import xpbdcloth.engine.Kinematics;
import xpbdcloth.engine.Particles;

/**
 * Moves pinned particles over time windows with smoothstep easing, then holds them. Each motion of a particle
 * turns it about an axis through a centre by an angle and moves it by a displacement, both eased by
 * s(u) = u²(3 − 2u), u = clamp((t − start)/duration); a particle's motions apply in order from its rest place:
 * <pre>
 *   x ← c + R(â, θ·s(u)) (x − c) + d·s(u)   for each motion (â, c, θ, d) of the particle, starting from x₀
 * </pre>
 * (R by Rodrigues' formula). Displacements alone add up, so a pin can move in, wait and move out; a turn
 * with them twists a held edge (ARCSim's and Bridson et al. 2002's twisted-cloth test). Smoothstep starts
 * and ends with zero velocity, so the pins never jerk the cloth (the seed's "opening the corners").
 */
final class PinScript implements Kinematics {
    private final Preset.PinMotion[] motions;
    /** Each motion's particle's rest place (the same for a particle's every motion). */
    private final double[] base;
    /** The next motion of the same particle after motion j, or −1; the first motion of a particle is where its chain starts. */
    private final int[] nextOfSameParticle;
    private final boolean[] firstOfItsParticle;

    PinScript(Particles p, List<Preset.PinMotion> motions) {
        this.motions = motions.toArray(new Preset.PinMotion[0]);
        base = new double[3 * this.motions.length];
        for (int j = 0; j < this.motions.length; j++) {
            int i = this.motions[j].vertex;
            base[3 * j] = p.x(i);
            base[3 * j + 1] = p.y(i);
            base[3 * j + 2] = p.z(i);
        }
        nextOfSameParticle = new int[this.motions.length];
        firstOfItsParticle = new boolean[this.motions.length];
        Map<Integer, Integer> lastOfParticle = new HashMap<>();
        for (int j = 0; j < this.motions.length; j++) {
            nextOfSameParticle[j] = -1;
            Integer last = lastOfParticle.put(this.motions[j].vertex, j);
            if (last == null) firstOfItsParticle[j] = true;
            else nextOfSameParticle[last] = j;
        }
    }

    @Override public void apply(Particles p, double t) {
        for (int j = 0; j < motions.length; j++) {
            if (!firstOfItsParticle[j]) continue; // applied along the particle's chain from its first motion
            double px = base[3 * j], py = base[3 * j + 1], pz = base[3 * j + 2];
            for (int k = j; k >= 0; k = nextOfSameParticle[k]) {
                Preset.PinMotion m = motions[k];
                double u = Math.max(0, Math.min(1, (t - m.start) / m.duration));
                double s = u * u * (3 - 2 * u);
                if (m.angle != 0) {
                    double[] a = m.axis, c = m.centre;
                    double rx = px - c[0], ry = py - c[1], rz = pz - c[2], angle = m.angle * s;
                    double cos = Math.cos(angle), sin = Math.sin(angle), along = (a[0] * rx + a[1] * ry + a[2] * rz) * (1 - cos);
                    px = c[0] + rx * cos + (a[1] * rz - a[2] * ry) * sin + a[0] * along;
                    py = c[1] + ry * cos + (a[2] * rx - a[0] * rz) * sin + a[1] * along;
                    pz = c[2] + rz * cos + (a[0] * ry - a[1] * rx) * sin + a[2] * along;
                }
                px += s * m.displacement[0];
                py += s * m.displacement[1];
                pz += s * m.displacement[2];
            }
            p.moveKinematic(motions[j].vertex, px, py, pz);
        }
    }

    /** The time after which every pin holds still. */
    double endTime() {
        double end = 0;
        for (Preset.PinMotion m : motions) end = Math.max(end, m.start + m.duration);
        return end;
    }
}
