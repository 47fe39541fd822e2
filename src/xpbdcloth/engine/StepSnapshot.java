package xpbdcloth.engine;

import java.util.List;

/**
 * The state a step changes, copied before the step so a step that goes non-finite can be undone bit for
 * bit: particle positions, previous positions, velocities and pending forces, each kinematic sphere's
 * centre, velocity and spin angle, the clock and the step count. Scripts and force fields are functions
 * of time, constraints reset λ every substep, so nothing else needs keeping. Arrays are made once and
 * grow only when spheres are added, so saving allocates nothing per step.
 */
final class StepSnapshot {
    private final double[] x, prev, v, force;
    private double[] spheres = new double[0];
    double time;
    long stepCount;

    StepSnapshot(int particleCount) {
        x = new double[3 * particleCount];
        prev = new double[3 * particleCount];
        v = new double[3 * particleCount];
        force = new double[3 * particleCount];
    }

    void save(Particles p, List<Sphere> ss, double time, long stepCount) {
        System.arraycopy(p.x, 0, x, 0, x.length);
        System.arraycopy(p.prev, 0, prev, 0, prev.length);
        System.arraycopy(p.v, 0, v, 0, v.length);
        System.arraycopy(p.force, 0, force, 0, force.length);
        if (spheres.length < 7 * ss.size()) spheres = new double[7 * ss.size()];
        for (int k = 0, n = ss.size(); k < n; k++) {
            Sphere s = ss.get(k);
            int o = 7 * k;
            spheres[o] = s.cx; spheres[o + 1] = s.cy; spheres[o + 2] = s.cz;
            spheres[o + 3] = s.vx; spheres[o + 4] = s.vy; spheres[o + 5] = s.vz;
            spheres[o + 6] = s.spinAngle;
        }
        this.time = time;
        this.stepCount = stepCount;
    }

    void restore(Particles p, List<Sphere> ss) {
        System.arraycopy(x, 0, p.x, 0, x.length);
        System.arraycopy(prev, 0, p.prev, 0, prev.length);
        System.arraycopy(v, 0, p.v, 0, v.length);
        System.arraycopy(force, 0, p.force, 0, force.length);
        for (int k = 0, n = ss.size(); k < n; k++) {
            Sphere s = ss.get(k);
            int o = 7 * k;
            s.cx = spheres[o]; s.cy = spheres[o + 1]; s.cz = spheres[o + 2];
            s.vx = spheres[o + 3]; s.vy = spheres[o + 4]; s.vz = spheres[o + 5];
            s.spinAngle = spheres[o + 6];
        }
    }
}
