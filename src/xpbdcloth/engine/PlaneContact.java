package xpbdcloth.engine;

/**
 * Contact between particle i and a fixed plane n·x = d (unit n, margin m), with Coulomb friction.
 *
 * <pre>
 *   C(x) = n·x − d − m ≥ 0        (an inequality: projected only while violated)
 *   ∇C   = n,                    Σ wᵢ|∇ᵢC|² = w   (the plane is fixed: w = 0)
 * </pre>
 * Hard in both modes (k = 1, α = 0): Δx_n = −C n; then {@link CoulombFriction} against the surface,
 * whose velocity is 0. Source: Müller et al. 2007 §4.3 (collision constraints); friction as for the
 * sphere (Macklin et al. 2014, eq. 24–25). No degenerate case: n is fixed and unit.
 * Found each substep by {@link ContactSet} like the sphere contacts, and projected after them.
 */
final class PlaneContact {
    private PlaneContact() {}

    /** Moves particle i out of the plane and applies friction; returns the Δλ of the normal correction. */
    static double project(Particles p, int i, Plane s, double h) {
        final double[] x = p.x;
        final int k = 3 * i;
        double startDepth = s.margin - s.distance(p.prev[k], p.prev[k + 1], p.prev[k + 2]);
        double C = s.distance(x[k], x[k + 1], x[k + 2]) - s.margin + s.leftInside(p, i, startDepth, h);
        double w = p.w[i];
        if (C >= 0 || w == 0) return 0;
        double dLambda = Constraint.hardDeltaLambda(C, w);
        double normalCorrection = w * dLambda; // = −C > 0
        x[k] += normalCorrection * s.nx; x[k + 1] += normalCorrection * s.ny; x[k + 2] += normalCorrection * s.nz;
        s.depenetrateWithoutVelocity(p, k, s.nx, s.ny, s.nz, normalCorrection, startDepth, h);
        CoulombFriction.apply(p, i, s.nx, s.ny, s.nz, normalCorrection, 0, 0, 0, h, s.staticFriction, s.kineticFriction);
        return dLambda;
    }
}
