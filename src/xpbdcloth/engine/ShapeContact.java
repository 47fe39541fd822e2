package xpbdcloth.engine;

/**
 * Contact between particle i and a kinematic {@link RigidCollider} (a box, a capsule) whose surface is
 * the zero set of its signed distance φ, kept at margin m, with Coulomb friction against the moving,
 * spinning surface.
 *
 * <pre>
 *   C(x) = φ(Rᵀ(x − c)) − m ≥ 0     (an inequality: projected only while violated)
 *   ∇C   = n = R ∇φ,                Σ wᵢ|∇ᵢC|² = w   (the solid is kinematic: w = 0)
 * </pre>
 * Hard in both modes (k = 1, α = 0): Δx = −C n, then {@link CoulombFriction} against the surface
 * velocity v_s = v + ω × (x − c). Source: Müller et al. 2007 §4.3 (collision constraints), friction as
 * Macklin et al. 2014 eq. (24)–(25), as for the sphere and the plane.
 *
 * <p><b>No tunnelling.</b> In the solid's frame the particle moved over the substep from a (its start,
 * in the solid's start pose) to b (now). When that relative motion is more than a quarter of the solid's
 * half thickness plus margin (a fast collider, or cloth falling fast onto a thin board), the end point
 * alone can miss a solid passed through: the segment a → b is tested instead. φ of a convex solid is
 * convex along a segment, so its minimum is found by golden-section search, and if it is below the
 * margin the particle is put where the segment first met the inflated surface (bisection), carried in
 * the solid's frame: it ends on the side it came from. Slow contacts take the push and friction alone,
 * so Coulomb's law is not replaced by sticking. Source: conservative contact along the swept segment, as
 * in continuous collision detection against signed distance fields (e.g. Macklin et al. 2020, "Local
 * Optimization for Robust Signed Distance Field Collision"), reduced here to one particle and a convex
 * solid.
 */
final class ShapeContact {
    private ShapeContact() {}

    /** Relative motion (as a fraction of half thickness plus margin) above which a contact is followed continuously. */
    static final double FAST = 0.25;
    /** Golden-section and bisection steps: (0.618)⁴⁰ ≈ 4e-9 and 2⁻⁴⁰ ≈ 1e-12 of the segment. */
    static final int SEARCH_STEPS = 40;
    private static final double GOLDEN = (Math.sqrt(5) - 1) / 2;
    /** How far inside (m) a start point may be and still count as touching from outside: rounding of a pose round trip. */
    static final double TOUCHING = 1e-9;

    /** Moves particle i out of the solid (or back to where it met it) and applies friction. */
    static void project(Particles p, int i, RigidCollider s, double h) {
        final double[] x = p.x;
        final int k = 3 * i;
        if (p.w[i] == 0) return;
        final double[][] work = s.work.get();
        final double[] q = work[0], n = work[1];
        s.toLocalAtStart(p.prev[k], p.prev[k + 1], p.prev[k + 2], q);
        double ax = q[0], ay = q[1], az = q[2];
        s.toLocal(x[k], x[k + 1], x[k + 2], q);
        double bx = q[0], by = q[1], bz = q[2];
        double mx = bx - ax, my = by - ay, mz = bz - az, move = Math.sqrt(mx * mx + my * my + mz * mz);
        boolean fast = move > FAST * (s.halfThickness() + s.margin);
        double fb = s.distance(bx, by, bz, n) - s.margin;
        if (fb >= 0 && !(fast && fb < move)) return;
        if (fast) {
            // Outside at the start (within rounding: a particle carried last substep starts on the surface).
            boolean startedOutside = s.distance(ax, ay, az, n) - s.margin >= -TOUCHING;
            if (fb >= 0 && !startedOutside) return; // it has got out
            if (startedOutside) {
                double t = fb < 0 ? 1 : deepest(s, ax, ay, az, mx, my, mz, n);
                if (t < 0) return; // the segment never came within the margin
                double t0 = firstTouch(s, ax, ay, az, mx, my, mz, t, n);
                q[0] = ax + t0 * mx; q[1] = ay + t0 * my; q[2] = az + t0 * mz;
                x[k] = s.cx + s.worldX(q); x[k + 1] = s.cy + s.worldY(q); x[k + 2] = s.cz + s.worldZ(q);
                return;
            }
            s.distance(bx, by, bz, n); // inside at both ends: out by the nearest way, below
        }
        double nx = s.worldX(n), ny = s.worldY(n), nz = s.worldZ(n);
        // Out no faster than the depenetration speed from where it started inside (n is kept: the
        // distance at the start is taken into a scratch normal).
        double startDepth = -(s.distance(ax, ay, az, work[2]) - s.margin);
        double normalCorrection = -fb - s.leftInside(p, i, startDepth, h);
        if (normalCorrection <= 0) return;
        x[k] += normalCorrection * nx; x[k + 1] += normalCorrection * ny; x[k + 2] += normalCorrection * nz;
        s.depenetrateWithoutVelocity(p, k, nx, ny, nz, normalCorrection, startDepth, h);
        // Surface velocity where the particle now touches: v + ω × (x − c).
        double rx = x[k] - s.cx, ry = x[k + 1] - s.cy, rz = x[k + 2] - s.cz;
        double vsx = s.vx + s.omegaY * rz - s.omegaZ * ry;
        double vsy = s.vy + s.omegaZ * rx - s.omegaX * rz;
        double vsz = s.vz + s.omegaX * ry - s.omegaY * rx;
        CoulombFriction.apply(p, i, nx, ny, nz, normalCorrection, vsx, vsy, vsz, h, s.staticFriction, s.kineticFriction);
    }

    /** φ − m at a + t·m. */
    private static double along(RigidCollider s, double ax, double ay, double az, double mx, double my, double mz, double t, double[] n) {
        return s.distance(ax + t * mx, ay + t * my, az + t * mz, n) - s.margin;
    }

    /** Where on [0, 1] the segment goes deepest, if it goes below the margin there; −1 otherwise. */
    private static double deepest(RigidCollider s, double ax, double ay, double az, double mx, double my, double mz, double[] n) {
        double lo = 0, hi = 1;
        double t1 = hi - GOLDEN * (hi - lo), t2 = lo + GOLDEN * (hi - lo);
        double f1 = along(s, ax, ay, az, mx, my, mz, t1, n), f2 = along(s, ax, ay, az, mx, my, mz, t2, n);
        for (int it = 0; it < SEARCH_STEPS; it++) {
            if (f1 < 0) return t1;
            if (f2 < 0) return t2;
            if (f1 <= f2) { hi = t2; t2 = t1; f2 = f1; t1 = hi - GOLDEN * (hi - lo); f1 = along(s, ax, ay, az, mx, my, mz, t1, n); }
            else { lo = t1; t1 = t2; f1 = f2; t2 = lo + GOLDEN * (hi - lo); f2 = along(s, ax, ay, az, mx, my, mz, t2, n); }
        }
        return -1;
    }

    /** The last t in [0, inside] at which the segment is still outside the margin (bisection; φ − m &lt; 0 at {@code inside}). */
    private static double firstTouch(RigidCollider s, double ax, double ay, double az, double mx, double my, double mz, double inside, double[] n) {
        double lo = 0, hi = inside;
        for (int it = 0; it < SEARCH_STEPS; it++) {
            double mid = 0.5 * (lo + hi);
            if (along(s, ax, ay, az, mx, my, mz, mid, n) >= 0) lo = mid; else hi = mid;
        }
        return lo;
    }
}
