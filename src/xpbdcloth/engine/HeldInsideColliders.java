package xpbdcloth.engine;

import java.util.List;

/**
 * Particles that something holds (a pin, a pin motion, an attachment such as a grab) inside a solid
 * collider: past its surface, where a contact would push a free particle out. A contact cannot move a held
 * particle, so the solid and the hold fight through the cloth between them (a corner pinned under the
 * floor, a hand dragging cloth into a sphere): the solid keeps pushing the held particle's neighbours out
 * while the springs to it pull them back, and that work has no bound a step could keep to. The count is
 * how the engine says so (the HUD shows it; the fuzzer's energy bound stops judging a case from the
 * first step it is non-zero). A measurement after a step, allocation-free; a particle held twice counts twice.
 */
final class HeldInsideColliders {
    private HeldInsideColliders() {}

    static int count(Particles p, AttachmentBlock attachments, List<Sphere> spheres, List<Plane> planes, List<RigidCollider> solids) {
        if (spheres.isEmpty() && planes.isEmpty() && solids.isEmpty()) return 0;
        int n = 0;
        for (int i = 0, count = p.count(); i < count; i++)
            if (p.w[i] == 0 && inside(p, i, spheres, planes, solids)) n++;
        for (int a = 0, count = attachments.count(); a < count; a++) {
            int i = attachments.particle(a, 0);
            if (p.w[i] != 0 && inside(p, i, spheres, planes, solids)) n++;
        }
        return n;
    }

    private static boolean inside(Particles p, int i, List<Sphere> spheres, List<Plane> planes, List<RigidCollider> solids) {
        double x = p.x[3 * i], y = p.x[3 * i + 1], z = p.x[3 * i + 2];
        for (int s = 0, n = spheres.size(); s < n; s++) if (past(spheres.get(s), x, y, z)) return true;
        for (int s = 0, n = planes.size(); s < n; s++) if (past(planes.get(s), x, y, z)) return true;
        for (int s = 0, n = solids.size(); s < n; s++) if (past(solids.get(s), x, y, z)) return true;
        return false;
    }

    /** Past the surface itself (beyond the margin), not merely touching it. */
    private static boolean past(Collider c, double x, double y, double z) { return c.clearanceAt(x, y, z) < -c.margin(); }
}
