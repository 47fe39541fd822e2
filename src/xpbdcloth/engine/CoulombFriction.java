package xpbdcloth.engine;

/**
 * Position-level Coulomb friction for a contact that has just pushed particle i out along the unit normal
 * n by d = normalCorrection ≥ 0: the particle's displacement over the substep relative to the collider's
 * surface, Δx_rel = (x − x_prev) − h·v_s, loses its tangential part Δx_t entirely while |Δx_t| &lt; μₛ d
 * (static: it sticks), otherwise by min(μₖ d / |Δx_t|, 1) of it (kinetic: it slides, slowed).
 * Source: Macklin et al. 2014, "Unified Particle Physics for Real-Time Applications", eq. (24)–(25). The
 * normal correction d plays the normal force's part: d = λ w, and λ/h² is the normal force.
 * Shared by every collider's contact, so the friction law is written once.
 */
final class CoulombFriction {
    private CoulombFriction() {}

    static void apply(Particles p, int i, double nx, double ny, double nz, double normalCorrection,
                      double vsx, double vsy, double vsz, double h, double staticFriction, double kineticFriction) {
        final double[] x = p.x;
        final int k = 3 * i;
        double rdx = x[k] - p.prev[k] - h * vsx, rdy = x[k + 1] - p.prev[k + 1] - h * vsy, rdz = x[k + 2] - p.prev[k + 2] - h * vsz;
        double along = rdx * nx + rdy * ny + rdz * nz;
        double tx = rdx - along * nx, ty = rdy - along * ny, tz = rdz - along * nz;
        double slip = Math.sqrt(tx * tx + ty * ty + tz * tz);
        if (slip == 0) return;
        double removed = slip < staticFriction * normalCorrection
                ? 1.0
                : Math.min(kineticFriction * normalCorrection / slip, 1.0);
        x[k] -= removed * tx; x[k + 1] -= removed * ty; x[k + 2] -= removed * tz;
    }
}
