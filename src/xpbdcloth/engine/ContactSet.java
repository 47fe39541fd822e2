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
 * trajectories are unchanged bit for bit.
 */
final class ContactSet {
    /** Candidate distance beyond the surface, as a fraction of the sphere's radius. */
    static final double SLACK = 0.25;

    private int[] particle = new int[0];
    private Sphere[] sphere = new Sphere[0];
    private int count;

    int count() { return count; }
    int particle(int k) { return particle[k]; }

    /** Makes room for every particle against every sphere (when spheres are added, never during a step). */
    void reserve(int particles, int spheres) {
        int n = particles * spheres;
        if (particle.length < n) { particle = new int[n]; sphere = new Sphere[n]; }
    }

    /** The collide stage: this substep's candidates, from the predicted positions and placed spheres. */
    void collide(Particles p, List<Sphere> spheres) {
        count = 0;
        final double[] x = p.x, prev = p.prev, w = p.w;
        for (int s = 0, ns = spheres.size(); s < ns; s++) {
            Sphere sp = spheres.get(s);
            double reach = sp.radius + sp.margin + SLACK * sp.radius;
            for (int i = 0, n = p.count(); i < n; i++) {
                if (w[i] == 0) continue;
                int k = 3 * i;
                double dx = x[k] - sp.cx, dy = x[k + 1] - sp.cy, dz = x[k + 2] - sp.cz;
                double mx = x[k] - prev[k], my = x[k + 1] - prev[k + 1], mz = x[k + 2] - prev[k + 2];
                double r = reach + Math.sqrt(mx * mx + my * my + mz * mz);
                if (dx * dx + dy * dy + dz * dz < r * r) { particle[count] = i; sphere[count] = sp; count++; }
            }
        }
    }

    /** One Gauss–Seidel pass over the contacts. */
    void project(Particles p, SolverContext ctx) {
        final double h = ctx.h;
        for (int k = 0; k < count; k++) SphereCollisionConstraint.project(p, particle[k], sphere[k], h);
    }

    /** Contact k alone (the probe's replay checks after each). */
    void project(Particles p, SolverContext ctx, int k) {
        SphereCollisionConstraint.project(p, particle[k], sphere[k], ctx.h);
    }
}
