package xpbdcloth.engine;

/**
 * The substep's explicit parts around the solve: the prediction before it, the velocities and the damping
 * after it (Müller et al. 2007, "Position Based Dynamics", algorithm 1, lines 5–7 and 12–13).
 */
final class Integrator {
    private Integrator() { }

    /**
     * Semi-implicit Euler for the free particles: v += h·(g + w·f), x_prev = x, x += h·v; pinned ones keep x.
     * Gravity and h from the substep's context, where vertex block descent reads them too.
     */
    static void predict(Particles particles, SolverContext ctx) {
        final double[] x = particles.x, prev = particles.prev, v = particles.v, w = particles.w, f = particles.force;
        final double gx = ctx.gravityX, gy = ctx.gravityY, gz = ctx.gravityZ, h = ctx.h;
        for (int i = 0, n = particles.count(); i < n; i++) {
            final int k = 3 * i;
            prev[k] = x[k]; prev[k + 1] = x[k + 1]; prev[k + 2] = x[k + 2];
            final double wi = w[i];
            if (wi == 0) continue;
            v[k] += h * (gx + wi * f[k]);
            v[k + 1] += h * (gy + wi * f[k + 1]);
            v[k + 2] += h * (gz + wi * f[k + 2]);
            x[k] += h * v[k]; x[k + 1] += h * v[k + 1]; x[k + 2] += h * v[k + 2];
        }
    }

    /** v = (x − x_prev)/h. */
    static void updateVelocities(Particles particles, double h) {
        final double[] x = particles.x, prev = particles.prev, v = particles.v;
        final double inv = 1.0 / h;
        for (int k = 0, n = 3 * particles.count(); k < n; k++) v[k] = (x[k] - prev[k]) * inv;
    }

    /** Damping, v ← v·e^(−c·h) for free particles (pinned ones have v = 0 or a scripted velocity): frame-rate independent. */
    static void damp(Particles particles, double c, double h) {
        if (c == 0) return;
        final double decay = Math.exp(-c * h);
        final double[] v = particles.v, w = particles.w;
        for (int i = 0, n = particles.count(); i < n; i++) {
            if (w[i] == 0) continue;
            final int k = 3 * i;
            v[k] *= decay; v[k + 1] *= decay; v[k + 2] *= decay;
        }
    }
}
