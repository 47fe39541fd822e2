package xpbdcloth.engine;

import java.util.List;

/**
 * This substep's contacts, found by the collide stage and projected after every sweep of the solve: a
 * transient list, not one permanent object per particle and collider. Flat arrays sized once for the
 * worst case (every particle against every sphere), so finding and solving allocate nothing.
 *
 * <p>What counts as a contact: a particle closer to a sphere's surface (radius + margin) than
 * {@link #SLACK} of the radius plus the distance the particle itself moved in the prediction. Its
 * projection does nothing while the particle is outside, so a generous candidate list costs only the
 * test; it must include every particle the sweeps could push into the sphere within the substep, which a
 * particle moving farther than that in one substep's sweeps would escape (it is then caught in the next
 * substep). Order: sphere by sphere, particles ascending, the order the permanent contacts had, so
 * trajectories are unchanged bit for bit; then plane by plane, for particles within {@link #PLANE_SLACK}
 * of the surface (plus margin and their own motion).
 */
final class ContactSet {
    /** Candidate distance beyond the surface, as a fraction of the sphere's radius. */
    static final double SLACK = 0.25;
    /** Candidate distance beyond a plane's surface, m (a plane has no size to take a fraction of). */
    static final double PLANE_SLACK = 0.05;

    private int[] particle = new int[0];
    /** Contact k is with sphere[k], or, where that is null, with plane[k]. */
    private Sphere[] sphere = new Sphere[0];
    private Plane[] plane = new Plane[0];
    private int count;

    int count() { return count; }
    int particle(int k) { return particle[k]; }

    /** Makes room for every particle against every collider (when colliders are added, never during a step). */
    void reserve(int particles, int colliders) {
        int n = particles * colliders;
        if (particle.length < n) { particle = new int[n]; sphere = new Sphere[n]; plane = new Plane[n]; }
    }

    /** The collide stage: this substep's candidates, from the predicted positions and placed colliders. */
    void collide(Particles p, List<Sphere> spheres, List<Plane> planes, double h) {
        count = 0;
        final double[] x = p.x, prev = p.prev, w = p.w;
        for (int s = 0, ns = spheres.size(); s < ns; s++) {
            Sphere sp = spheres.get(s);
            double reach = sp.radius + sp.margin + SLACK * sp.radius;
            // A fast sphere's candidates lie along its path over the substep, from c − h·v to c.
            boolean fast = sp.isFast(h);
            double ux = h * sp.vx, uy = h * sp.vy, uz = h * sp.vz, uu = ux * ux + uy * uy + uz * uz;
            for (int i = 0, n = p.count(); i < n; i++) {
                if (w[i] == 0) continue;
                int k = 3 * i;
                double dx = x[k] - sp.cx, dy = x[k + 1] - sp.cy, dz = x[k + 2] - sp.cz;
                if (fast) { // distance to the path: dx, dy, dz from the path's nearest point
                    double t = Math.max(0, Math.min(1, (dx * ux + dy * uy + dz * uz) / -uu));
                    dx += t * ux; dy += t * uy; dz += t * uz;
                }
                double mx = x[k] - prev[k], my = x[k + 1] - prev[k + 1], mz = x[k + 2] - prev[k + 2];
                double r = reach + Math.sqrt(mx * mx + my * my + mz * mz);
                if (dx * dx + dy * dy + dz * dz < r * r) { particle[count] = i; sphere[count] = sp; plane[count] = null; count++; }
            }
        }
        for (int s = 0, ns = planes.size(); s < ns; s++) {
            Plane pl = planes.get(s);
            for (int i = 0, n = p.count(); i < n; i++) {
                if (w[i] == 0) continue;
                int k = 3 * i;
                double mx = x[k] - prev[k], my = x[k + 1] - prev[k + 1], mz = x[k + 2] - prev[k + 2];
                double reach = pl.margin + PLANE_SLACK + Math.sqrt(mx * mx + my * my + mz * mz);
                if (pl.distance(x[k], x[k + 1], x[k + 2]) < reach) { particle[count] = i; sphere[count] = null; plane[count] = pl; count++; }
            }
        }
    }

    /** One Gauss–Seidel pass over the contacts. */
    void project(Particles p, SolverContext ctx) {
        for (int k = 0; k < count; k++) project(p, ctx, k);
    }

    /** Contact k alone (the probe's replay checks after each). */
    void project(Particles p, SolverContext ctx, int k) {
        if (sphere[k] != null) SphereCollisionConstraint.project(p, particle[k], sphere[k], ctx.h);
        else PlaneCollisionConstraint.project(p, particle[k], plane[k], ctx.h);
    }
}
