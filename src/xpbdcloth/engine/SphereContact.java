package xpbdcloth.engine;

/**
 * Contact between particle i and a kinematic sphere (centre c, radius r, margin m), with Coulomb friction
 * against the moving, spinning surface.
 *
 * <pre>
 *   C(x) = |x − c| − (r + m) ≥ 0        (an inequality: projected only while violated)
 *   ∇C   = n = (x − c)/|x − c|,         Σ wᵢ|∇ᵢC|² = w   (the sphere is kinematic: w = 0)
 * </pre>
 * The contact is hard in both modes (k = 1, α = 0): Δx_n = −C n. Friction then acts on the particle's
 * displacement over the substep relative to the surface, Δx_rel = (x − x_prev) − h·v_s, where the surface
 * velocity at the contact point is v_s = v_sphere + ω × (r n). With Δx_t its part tangent to the sphere and
 * d = |Δx_n| the normal correction just applied:
 * static friction removes Δx_t entirely while |Δx_t| &lt; μₛ d; otherwise kinetic friction removes
 * Δx_t · min(μₖ d / |Δx_t|, 1) ({@link CoulombFriction}, shared with the plane contacts).
 * Source: Müller et al. 2007 §4.3 (collision constraints); friction as position-level Coulomb friction in
 * Macklin et al. 2014, "Unified Particle Physics for Real-Time Applications", eq. (24)–(25).
 * Degenerate case: a particle exactly at the centre has no normal; it is pushed out along +y (up), a fixed
 * choice so the result is deterministic.
 *
 * <p>A simulation does not keep one of these per particle and sphere: its contacts are found anew each
 * substep ({@link ContactSet}, the flat store of this family, which accumulates no λ: a hard inequality
 * needs none) and projected by the same {@link #project(Particles, int, Sphere, double)}. An object of
 * this class is one contact to look at (its C, its gradient), not a {@link Constraint}: it has no
 * stiffness or compliance to set.
 */
public final class SphereContact {
    final int i;
    final Sphere sphere;

    public SphereContact(int particle, Sphere sphere) {
        if (sphere == null) throw new IllegalArgumentException("sphere must not be null, was null");
        this.i = Check.atLeast("particle", particle, 0);
        this.sphere = sphere;
    }

    public Sphere sphere() { return sphere; }
    public ConstraintFamily family() { return ConstraintFamily.COLLISION; }

    public int[] particles() { return new int[] {i}; }

    /** C(x) = |x − c| − (r + m), negative inside. */
    public double evaluate(Particles p) {
        double dx = p.x[3 * i] - sphere.cx, dy = p.x[3 * i + 1] - sphere.cy, dz = p.x[3 * i + 2] - sphere.cz;
        return Math.sqrt(dx * dx + dy * dy + dz * dz) - (sphere.radius + sphere.margin);
    }

    /** ∇C = n (up, +y, at the centre). */
    public void gradient(Particles p, double[] out) {
        double dx = p.x[3 * i] - sphere.cx, dy = p.x[3 * i + 1] - sphere.cy, dz = p.x[3 * i + 2] - sphere.cz;
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        if (len < DistanceBlock.MIN_LENGTH) { out[0] = 0; out[1] = 1; out[2] = 0; return; }
        out[0] = dx / len; out[1] = dy / len; out[2] = dz / len;
    }

    /**
     * The contact's projection, written once, used by the transient contacts of {@link ContactSet}.
     * Moves particle i out of the sphere and applies friction; returns the Δλ of the
     * normal correction (0 when not in contact).
     */
    static double project(Particles p, int i, Sphere s, double h) {
        final double[] x = p.x;
        final int k = 3 * i;
        double dx = x[k] - s.cx, dy = x[k + 1] - s.cy, dz = x[k + 2] - s.cz;
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double C = len - (s.radius + s.margin);
        double w = p.w[i];
        if (w == 0) return 0;
        if (C >= 0) return s.isFast(h) ? sweptContact(p, i, s, h) : 0;
        // Out no faster than the depenetration speed from where it started inside (the sphere then at c − h v).
        double ax = p.prev[k] - (s.cx - h * s.vx), ay = p.prev[k + 1] - (s.cy - h * s.vy), az = p.prev[k + 2] - (s.cz - h * s.vz);
        C += s.leftInside(p, i, s.radius + s.margin - Math.sqrt(ax * ax + ay * ay + az * az), h);
        if (C >= 0) return 0;
        double nx, ny, nz;
        if (len < DistanceBlock.MIN_LENGTH) { nx = 0; ny = 1; nz = 0; }
        else { nx = dx / len; ny = dy / len; nz = dz / len; }
        double dLambda = Constraint.hardDeltaLambda(C, w);
        double normalCorrection = w * dLambda; // = −C > 0
        if (s.isFast(h) && startedInFront(p, i, s, h)) {
            // A fast sphere carries what it meets: a particle that was in front of it at the substep's
            // start and is found in its back half (pulled there by its neighbours) leaves through the
            // front, mirrored across the plane normal to the motion, not out of the back where the next
            // substep would leave it behind. One that has slid to the back over earlier substeps may go.
            double v = Math.sqrt(s.vx * s.vx + s.vy * s.vy + s.vz * s.vz), along = (nx * s.vx + ny * s.vy + nz * s.vz) / v;
            if (along < 0) {
                nx -= 2 * along * s.vx / v; ny -= 2 * along * s.vy / v; nz -= 2 * along * s.vz / v;
                // Out to the surface along the mirrored normal: from the centre, not from x.
                double R = s.radius + s.margin;
                x[k] = s.cx + R * nx; x[k + 1] = s.cy + R * ny; x[k + 2] = s.cz + R * nz;
                return dLambda;
            }
        }
        x[k] += normalCorrection * nx; x[k + 1] += normalCorrection * ny; x[k + 2] += normalCorrection * nz;

        // Surface velocity at the contact point r n: v_sphere + ω × (r n).
        double rx = s.radius * nx, ry = s.radius * ny, rz = s.radius * nz;
        double vsx = s.vx + s.omegaY * rz - s.omegaZ * ry;
        double vsy = s.vy + s.omegaZ * rx - s.omegaX * rz;
        double vsz = s.vz + s.omegaX * ry - s.omegaY * rx;
        CoulombFriction.apply(p, i, nx, ny, nz, normalCorrection, vsx, vsy, vsz, h, s.staticFriction, s.kineticFriction);
        return dLambda;
    }

    /** Whether particle i was ahead of the sphere (along its motion) at the substep's start. */
    private static boolean startedInFront(Particles p, int i, Sphere s, double h) {
        int k = 3 * i;
        double ax = p.prev[k] - (s.cx - h * s.vx), ay = p.prev[k + 1] - (s.cy - h * s.vy), az = p.prev[k + 2] - (s.cz - h * s.vz);
        return ax * s.vx + ay * s.vy + az * s.vz > 0;
    }

    /**
     * Continuous contact for a sphere that moves more than {@link Sphere#isFast a quarter of its radius}
     * in the substep, which a test of the end positions alone lets pass through the cloth (at 20 m/s and
     * dt = 1/60 s a 5 cm sphere jumps 33 cm, farther than its own diameter). In the sphere's frame the
     * particle moved from a = x_prev − c_prev to b = x − c; if that segment entered the ball |q| &lt; R
     * (R = radius + margin) from outside, the particle is put where it met the surface, q₀ = a + t₀(b − a)
     * with t₀ the first root of |a + t(b − a)| = R, carried with the sphere: x = c + q₀; a particle that
     * was already touching (carried since an earlier substep) rides on at R·â. Returns the
     * distance moved. Slow spheres never come here, so the shipped scenes' trajectories are unchanged.
     * Source: the ray–sphere intersection of any ray tracer (e.g. Ericson 2005, "Real-Time Collision
     * Detection", §5.3.2), in the moving sphere's frame.
     */
    static double sweptContact(Particles p, int i, Sphere s, double h) {
        final double[] x = p.x;
        final int k = 3 * i;
        double R = s.radius + s.margin;
        double ax = p.prev[k] - (s.cx - h * s.vx), ay = p.prev[k + 1] - (s.cy - h * s.vy), az = p.prev[k + 2] - (s.cz - h * s.vz);
        double dx = x[k] - s.cx - ax, dy = x[k + 1] - s.cy - ay, dz = x[k + 2] - s.cz - az;
        double aa = ax * ax + ay * ay + az * az, ad = ax * dx + ay * dy + az * dz, dd = dx * dx + dy * dy + dz * dz;
        if (dd == 0) return 0; // no relative motion
        double qx, qy, qz;
        if (aa <= R * R * (1 + 1e-9)) {
            // Touching at the start (carried since an earlier substep): it rides on, unless the sphere is
            // moving away from it.
            if (ax * s.vx + ay * s.vy + az * s.vz <= 0) return 0;
            double f = R / Math.sqrt(aa);
            qx = f * ax; qy = f * ay; qz = f * az;
        } else {
            double disc = ad * ad - dd * (aa - R * R);
            if (disc <= 0) return 0; // the segment's line misses the ball
            double t0 = (-ad - Math.sqrt(disc)) / dd;
            if (t0 < 0 || t0 > 1) return 0; // the ball is behind the start, or beyond the end of the motion
            qx = ax + t0 * dx; qy = ay + t0 * dy; qz = az + t0 * dz;
        }
        double mx = s.cx + qx - x[k], my = s.cy + qy - x[k + 1], mz = s.cz + qz - x[k + 2];
        x[k] += mx; x[k + 1] += my; x[k + 2] += mz;
        return Math.sqrt(mx * mx + my * my + mz * mz);
    }
}
