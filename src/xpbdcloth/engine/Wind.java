package xpbdcloth.engine;

/**
 * Wind on a triangle mesh: each triangle of area A and unit normal n̂ feels a linear drag
 * (c·A/3)·((u − vᵢ)·n̂) n̂ on each corner i along its normal, where u is the wind velocity, vᵢ the corner's
 * own velocity and c the drag coefficient (kg/(m²·s)). Only the normal part pushes, so
 * cloth edge-on to the wind feels nothing. A slow gust modulates |u| by 1 + gust·sin(0.7t)·sin(1.9t),
 * two incommensurate frequencies so the motion does not look periodic.
 *
 * <p>The force acts for a whole step dt, so it is integrated exactly rather than explicitly: a particle
 * of inverse mass w whose triangles give it the drag rate k = Σ c·A/3 (kg/s) has its normal relative
 * velocity decay by the factor e^(−w·k·dt) over the step, so its force is scaled by (1 − e^(−x))/x,
 * x = w·k·dt (1 for small x). The explicit force overshoots once x &gt; 2, and because a stretched cloth
 * catches more wind (A grows) the overshoot fed itself: a random preset with a soft cloth in a
 * 100 m/s wind reached infinite velocity in 8 steps. Exact decay can never push a particle past the
 * wind's own speed.
 *
 * <p>Each corner is dragged by its own relative velocity, not the triangle's mean: the drag on particle i is
 * then M(u − vᵢ) with M = Σ (c·A/3) n̂n̂ᵀ symmetric and no larger than k, a pure relaxation of vᵢ towards u
 * that the exact-decay scale keeps from overshooting. With the mean velocity a particle was pushed by its
 * neighbours' motion, which its own decay does not bound: a random preset (a 3 × 225 cloth stretched 87×
 * by gravity at dt = 0.1 s, in a 100 m/s wind) gained energy every step until it overflowed at step 18.
 */
public final class Wind implements ExternalForce {
    private final int[] triangles;
    private double ux, uy, uz;
    private final double drag, gust;
    private final ExactDecay decay = new ExactDecay();
    private final double[] normal = new double[3];

    public Wind(int[] triangles, double ux, double uy, double uz, double drag, double gust) {
        if (triangles == null || triangles.length % 3 != 0)
            throw new IllegalArgumentException("triangles must be a multiple of 3 indices, was " + (triangles == null ? "null" : triangles.length));
        Check.finite3("wind", ux, uy, uz);
        this.triangles = triangles;
        this.ux = ux; this.uy = uy; this.uz = uz;
        this.drag = Check.nonNegative("drag", drag);
        this.gust = Check.inRange("gust", gust, 0, 1);
    }

    public double velocityX() { return ux; }
    public double velocityY() { return uy; }
    public double velocityZ() { return uz; }
    public double drag() { return drag; }
    public double gust() { return gust; }

    public void setVelocity(double x, double y, double z) {
        Check.finite3("wind", x, y, z);
        ux = x; uy = y; uz = z;
    }

    @Override public void check(Particles p) {
        for (int k = 0; k < triangles.length; k++) Check.index("triangle " + k / 3 + " corner", triangles[k], p.count());
    }

    @Override public void apply(Particles p, double t, double dt) {
        decay.begin(p.count());
        final double[] x = p.x, v = p.v;
        final double g = 1 + gust * Math.sin(0.7 * t) * Math.sin(1.9 * t);
        final double wx = ux * g, wy = uy * g, wz = uz * g;
        for (int k = 0; k < triangles.length; k += 3) {
            int ia = triangles[k], ib = triangles[k + 1], ic = triangles[k + 2];
            int a = 3 * ia, b = 3 * ib, c = 3 * ic;
            double twiceArea = ExactDecay.twiceAreaAndNormal(x, a, b, c, normal);
            if (twiceArea < 1e-18) continue;
            double nx = normal[0], ny = normal[1], nz = normal[2];
            double perCorner = drag * 0.5 * twiceArea / 3; // kg/s
            decay.addRate(ia, perCorner); decay.addRate(ib, perCorner); decay.addRate(ic, perCorner);
            push(a, perCorner, nx, ny, nz, wx - v[a], wy - v[a + 1], wz - v[a + 2]);
            push(b, perCorner, nx, ny, nz, wx - v[b], wy - v[b + 1], wz - v[b + 2]);
            push(c, perCorner, nx, ny, nz, wx - v[c], wy - v[c + 1], wz - v[c + 2]);
        }
        decay.apply(p, dt);
    }

    /** Adds one triangle's normal drag on one corner, from that corner's own relative velocity (rx, ry, rz). */
    private void push(int i3, double perCorner, double nx, double ny, double nz, double rx, double ry, double rz) {
        double f = perCorner * (rx * nx + ry * ny + rz * nz);
        decay.addForce(i3, f * nx, f * ny, f * nz);
    }
}
