package xpbdcloth.scene;

import java.util.List;
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

    PinScript(Particles p, List<Preset.PinMotion> motions) {
        this.motions = motions.toArray(new Preset.PinMotion[0]);
        base = new double[3 * this.motions.length];
        for (int j = 0; j < this.motions.length; j++) {
            int i = this.motions[j].vertex;
            base[3 * j] = p.x(i);
            base[3 * j + 1] = p.y(i);
            base[3 * j + 2] = p.z(i);
        }
    }

    @Override public void apply(Particles p, double t) {
        for (int j = 0; j < motions.length; j++) {
            if (firstMotionOf(j) != j) continue; // handled with the particle's first motion
            double px = base[3 * j], py = base[3 * j + 1], pz = base[3 * j + 2];
            for (int k = j; k < motions.length; k++) {
                Preset.PinMotion m = motions[k];
                if (m.vertex != motions[j].vertex) continue;
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

    private int firstMotionOf(int j) {
        for (int k = 0; k < j; k++) if (motions[k].vertex == motions[j].vertex) return k;
        return j;
    }

    /** The time after which every pin holds still. */
    double endTime() {
        double end = 0;
        for (Preset.PinMotion m : motions) end = Math.max(end, m.start + m.duration);
        return end;
    }
}
