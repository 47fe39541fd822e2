package xpbdcloth.engine;

/**
 * A kinematic sphere: it moves along a {@link SpherePath} and spins with angular velocity ω, pushes
 * particles out and drags them by Coulomb friction, and is never pushed back (infinite mass).
 */
public final class Sphere extends Collider {
    private final SpherePath path;
    final double radius;
    /** Angular velocity ω, rad/s. */
    double omegaX, omegaY, omegaZ;
    /** Centre now, and its velocity over the last substep (m/s). */
    double cx, cy, cz, vx, vy, vz;
    /** Spin angle accumulated about ω, rad, for drawing a marking that shows the spin. */
    double spinAngle;
    private final double[] scratch = new double[3];

    /**
     * @param radius          m, &gt; 0
     * @param margin          m, ≥ 0: the cloth's half thickness
     * @param staticFriction  μₛ ≥ 0
     * @param kineticFriction μₖ ≥ 0
     */
    public Sphere(SpherePath path, double radius, double margin, double staticFriction, double kineticFriction) {
        super(margin, staticFriction, kineticFriction);
        if (path == null) throw new IllegalArgumentException("path must not be null, was null");
        this.path = path;
        this.radius = Check.inRange("radius", radius, Double.MIN_NORMAL, EngineRange.MAX_RADIUS);
        moveTo(0);
    }

    public Sphere spin(double wx, double wy, double wz) {
        Check.finite3("angularVelocity", wx, wy, wz);
        omegaX = wx; omegaY = wy; omegaZ = wz;
        return this;
    }

    /** Places the centre at time t with zero velocity (scene start or reset). */
    public void moveTo(double t) {
        path.centreAt(t, scratch);
        cx = scratch[0]; cy = scratch[1]; cz = scratch[2];
        vx = vy = vz = 0;
    }

    /** Moves the centre to its place at time t, h seconds after the last place; velocity = displacement/h. */
    void advance(double t, double h) {
        path.centreAt(t, scratch);
        vx = (scratch[0] - cx) / h; vy = (scratch[1] - cy) / h; vz = (scratch[2] - cz) / h;
        cx = scratch[0]; cy = scratch[1]; cz = scratch[2];
        spinAngle += Math.sqrt(omegaX * omegaX + omegaY * omegaY + omegaZ * omegaZ) * h;
    }

    @Override boolean moving() { return vx != 0 || vy != 0 || vz != 0 || omegaX != 0 || omegaY != 0 || omegaZ != 0; }

    /**
     * Whether the centre moved more than a quarter of the radius over the last substep of length h: then
     * contacts are found and solved along the sphere's path, not only at its end (no tunnelling).
     */
    boolean isFast(double h) {
        double step2 = (vx * vx + vy * vy + vz * vz) * h * h, quarter = ContactSet.SLACK * radius;
        return step2 > quarter * quarter;
    }

    /** Particles within reach: radius + margin + {@link ContactSet#SLACK} of the radius + their own motion, from the centre (from the swept path when fast). */
    @Override void findContacts(Particles p, double h, ContactSet contacts) {
        final double[] x = p.x, prev = p.prev, w = p.w;
        double reach = radius + margin + ContactSet.SLACK * radius;
        // A fast sphere's candidates lie along its path over the substep, from c − h·v to c.
        boolean fast = isFast(h);
        double ux = h * vx, uy = h * vy, uz = h * vz, uu = ux * ux + uy * uy + uz * uz;
        for (int i = 0, n = p.count(); i < n; i++) {
            if (w[i] == 0) continue;
            int k = 3 * i;
            double dx = x[k] - cx, dy = x[k + 1] - cy, dz = x[k + 2] - cz;
            if (fast) { // distance to the path: dx, dy, dz from the path's nearest point
                double t = Math.max(0, Math.min(1, (dx * ux + dy * uy + dz * uz) / -uu));
                dx += t * ux; dy += t * uy; dz += t * uz;
            }
            double mx = x[k] - prev[k], my = x[k + 1] - prev[k + 1], mz = x[k + 2] - prev[k + 2];
            double r = reach + Math.sqrt(mx * mx + my * my + mz * mz);
            if (dx * dx + dy * dy + dz * dz < r * r) contacts.add(i, this);
        }
    }

    @Override void project(Particles p, int i, double h) { SphereContact.project(p, i, this, h); }

    @Override double clearance(Particles p, int i) { return clearanceAt(p.x[3 * i], p.x[3 * i + 1], p.x[3 * i + 2]); }

    @Override public double clearanceAt(double x, double y, double z) {
        double dx = x - cx, dy = y - cy, dz = z - cz;
        return Math.sqrt(dx * dx + dy * dy + dz * dz) - (radius + margin);
    }

    public double radius() { return radius; }
    public double centreX() { return cx; }
    public double centreY() { return cy; }
    public double centreZ() { return cz; }
    public double omegaX() { return omegaX; }
    public double omegaY() { return omegaY; }
    public double omegaZ() { return omegaZ; }
    public double spinAngle() { return spinAngle; }

    /** The sphere's turn so far (its spin angle about ω), row-major, into out[0..8]: identity when it does not spin. */
    public void rotation(double[] out) {
        double w = Math.sqrt(omegaX * omegaX + omegaY * omegaY + omegaZ * omegaZ);
        if (w == 0) { java.util.Arrays.fill(out, 0, 9, 0); out[0] = out[4] = out[8] = 1; return; }
        Rotation.axisAngle(omegaX / w, omegaY / w, omegaZ / w, spinAngle, out);
    }
}
