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
public final class SphereCollisionConstraint {
    final int i;
    final Sphere sphere;

    public SphereCollisionConstraint(int particle, Sphere sphere) {
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
        if (C >= 0 || w == 0) return 0;
        double nx, ny, nz;
        if (len < DistanceBlock.MIN_LENGTH) { nx = 0; ny = 1; nz = 0; }
        else { nx = dx / len; ny = dy / len; nz = dz / len; }
        double dLambda = Constraint.hardDeltaLambda(C, w);
        double normalCorrection = w * dLambda; // = −C > 0
        x[k] += normalCorrection * nx; x[k + 1] += normalCorrection * ny; x[k + 2] += normalCorrection * nz;

        // Surface velocity at the contact point r n: v_sphere + ω × (r n).
        double rx = s.radius * nx, ry = s.radius * ny, rz = s.radius * nz;
        double vsx = s.vx + s.omegaY * rz - s.omegaZ * ry;
        double vsy = s.vy + s.omegaZ * rx - s.omegaX * rz;
        double vsz = s.vz + s.omegaX * ry - s.omegaY * rx;
        CoulombFriction.apply(p, i, nx, ny, nz, normalCorrection, vsx, vsy, vsz, h, s.staticFriction, s.kineticFriction);
        return dLambda;
    }
}
