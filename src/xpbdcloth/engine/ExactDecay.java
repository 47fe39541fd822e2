package xpbdcloth.engine;

import java.util.Arrays;

/**
 * Air forces on a cloth's triangles ({@link Wind}, {@link Aerodynamics}) integrated over a whole step
 * with the exact decay of a linear drag: each particle's forces are gathered with its drag rate k (kg/s,
 * summed over its triangles), then scaled by (1 − e^(−x))/x with x = w·k·dt, so the air relaxes a
 * particle's velocity towards its own and never past it (the explicit force overshoots once x &gt; 2).
 * Also the one place a triangle's unit normal and area are taken for them.
 */
final class ExactDecay {
    private double[] rate = new double[0], pending = new double[0];

    /** Starts a step's gathering for n particles (grows the arrays only when n changes). */
    void begin(int n) {
        if (rate.length != n) { rate = new double[n]; pending = new double[3 * n]; }
        Arrays.fill(rate, 0);
        Arrays.fill(pending, 0);
    }

    /** Adds drag rate k (kg/s) to particle i. */
    void addRate(int i, double k) { rate[i] += k; }

    /** Adds a force (N) to the particle whose x index is i3 = 3i. */
    void addForce(int i3, double fx, double fy, double fz) {
        pending[i3] += fx; pending[i3 + 1] += fy; pending[i3 + 2] += fz;
    }

    /**
     * Hands every free particle its gathered force, scaled by the exact decay over dt. Pinned particles get
     * none (their script moves them; a force would do nothing). Added past {@link Particles#addForce}'s range,
     * which bounds what a caller may push: the decay already bounds what this force does, w·scale·|F|·dt ≤ the
     * flow's speed past the particle, while the force itself on a heavy particle in a dense, fast flow can
     * rightly exceed any such range (the fuzzer found a 500 m flag in 140 m/s air at
     * 1.4e9 N on one component, about 1e10 N at a corner).
     */
    void apply(Particles p, double dt) {
        final double[] force = p.force, w = p.w;
        for (int i = 0, n = rate.length; i < n; i++) {
            if (w[i] == 0) continue;
            double xi = dt * w[i] * rate[i];
            double scale = xi < 1e-6 ? 1 - 0.5 * xi : -Math.expm1(-xi) / xi;
            final int k = 3 * i;
            force[k] += scale * pending[k];
            force[k + 1] += scale * pending[k + 1];
            force[k + 2] += scale * pending[k + 2];
        }
    }

    /**
     * Twice the area of triangle (a, b, c) (x indices 3i), and its unit normal (b − a) × (c − a) into
     * normal[0..2] unless the area is below 5e-19 m² (then the normal is left as it was).
     */
    static double twiceAreaAndNormal(double[] x, int a, int b, int c, double[] normal) {
        double e1x = x[b] - x[a], e1y = x[b + 1] - x[a + 1], e1z = x[b + 2] - x[a + 2];
        double e2x = x[c] - x[a], e2y = x[c + 1] - x[a + 1], e2z = x[c + 2] - x[a + 2];
        double nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
        double twiceArea = Math.sqrt(nx * nx + ny * ny + nz * nz);
        if (twiceArea < 1e-18) return twiceArea;
        normal[0] = nx / twiceArea; normal[1] = ny / twiceArea; normal[2] = nz / twiceArea;
        return twiceArea;
    }
}
