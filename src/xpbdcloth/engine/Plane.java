package xpbdcloth.engine;

/**
 * A fixed, infinite plane, the solid on the side opposite its normal: a floor (normal up), a wall, or a
 * slope at any angle. The surface is n·x = d with n a unit normal; particles keep {@code margin} (the
 * cloth's half thickness) above it, and slide on it by Coulomb friction. Infinite mass: never pushed back.
 */
public final class Plane extends Collider {
    final double nx, ny, nz, offset;

    /**
     * @param point           a point of the surface, m
     * @param normal          the side the cloth stays on; any length &gt; 0 (normalised here)
     * @param margin          m, ≥ 0: the cloth's half thickness
     * @param staticFriction  μₛ ≥ 0
     * @param kineticFriction μₖ ≥ 0
     */
    public Plane(double[] point, double[] normal, double margin, double staticFriction, double kineticFriction) {
        super(margin, staticFriction, kineticFriction);
        if (point == null || point.length != 3) throw new IllegalArgumentException("point must have 3 components, was " + (point == null ? "null" : point.length));
        if (normal == null || normal.length != 3) throw new IllegalArgumentException("normal must have 3 components, was " + (normal == null ? "null" : normal.length));
        EngineRange.vector("point", point[0], point[1], point[2], EngineRange.MAX_POSITION);
        Check.finite3("normal", normal[0], normal[1], normal[2]);
        double len = Math.sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
        if (!(len > 1e-9 && len < 1e9))
            throw new IllegalArgumentException("normal must have a length in (1e-9, 1e9), was " + len);
        nx = normal[0] / len; ny = normal[1] / len; nz = normal[2] / len;
        offset = nx * point[0] + ny * point[1] + nz * point[2];
    }

    /** A horizontal floor at height y (normal up, +y). */
    public static Plane floor(double y, double margin, double staticFriction, double kineticFriction) {
        return new Plane(new double[] {0, y, 0}, new double[] {0, 1, 0}, margin, staticFriction, kineticFriction);
    }

    /** The signed distance of (x, y, z) from the surface along the normal, m (negative below). */
    public double distance(double x, double y, double z) { return nx * x + ny * y + nz * z - offset; }

    /** Particles within margin + {@link ContactSet#PLANE_SLACK} + their own motion of the surface (or below it). */
    @Override void findContacts(Particles p, double h, ContactSet contacts) {
        final double[] x = p.x, prev = p.prev, w = p.w;
        for (int i = 0, n = p.count(); i < n; i++) {
            if (w[i] == 0) continue;
            int k = 3 * i;
            double mx = x[k] - prev[k], my = x[k + 1] - prev[k + 1], mz = x[k + 2] - prev[k + 2];
            double reach = margin + ContactSet.PLANE_SLACK + Math.sqrt(mx * mx + my * my + mz * mz);
            if (distance(x[k], x[k + 1], x[k + 2]) < reach) contacts.add(i, this);
        }
    }

    @Override void project(Particles p, int i, double h) { PlaneContact.project(p, i, this, h); }

    @Override double clearance(Particles p, int i) { return clearanceAt(p.x[3 * i], p.x[3 * i + 1], p.x[3 * i + 2]); }

    @Override public double clearanceAt(double x, double y, double z) { return distance(x, y, z) - margin; }

    public double normalX() { return nx; }
    public double normalY() { return ny; }
    public double normalZ() { return nz; }
}
