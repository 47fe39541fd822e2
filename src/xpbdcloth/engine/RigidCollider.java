package xpbdcloth.engine;

/**
 * A kinematic solid of fixed shape (a {@link Box}, a {@link Capsule}): its centre moves along a
 * {@link SpherePath}, it turns at a constant angular velocity ω about its centre, and it is never pushed
 * back. The pose is a function of time alone, R(t) = rot(ω, |ω| t) R₀ and c(t) from the path, so a
 * step that is rolled back needs no collider state restored. A kind gives only its shape, in its own
 * frame: the signed distance to its surface and that distance's gradient ({@link #distance}); the
 * contact, with friction and the continuous test against tunnelling, is {@link ShapeContact}.
 */
public abstract class RigidCollider extends Collider {
    private final SpherePath path;
    private final double[] rest;
    double omegaX, omegaY, omegaZ;
    /** Centre and rotation now, at the substep's start, and the centre's velocity over the substep. */
    double cx, cy, cz, vx, vy, vz, pcx, pcy, pcz;
    final double[] rotation = new double[9], previous = new double[9];
    private final double[] spin = new double[9], centre = new double[3];
    /**
     * Scratch of the contact's maths, one per thread (a local point, a normal, a second normal): vertex block
     * descent projects the contacts of one colour's particles on several threads at once.
     */
    final ThreadLocal<double[][]> work = ThreadLocal.withInitial(() -> new double[][] {new double[3], new double[3], new double[3]});

    RigidCollider(SpherePath path, double[] rotation, double margin, double staticFriction, double kineticFriction) {
        super(margin, staticFriction, kineticFriction);
        if (path == null) throw new IllegalArgumentException("path must not be null, was null");
        this.path = path;
        this.rest = rotation.clone();
        moveTo(0);
    }

    /** Turns the solid about its centre at angular velocity (wx, wy, wz), rad/s. */
    public RigidCollider spin(double wx, double wy, double wz) {
        Check.finite3("angularVelocity", wx, wy, wz);
        omegaX = wx; omegaY = wy; omegaZ = wz;
        moveTo(0);
        return this;
    }

    /** The signed distance from local point q to the surface (negative inside), and its gradient, a unit local normal, into n. */
    abstract double distance(double qx, double qy, double qz, double[] n);

    /** The radius of a ball about the centre that holds the solid. */
    abstract double boundingRadius();

    /** Half the solid's thinnest size, m: a relative motion of more than a quarter of it in a substep is followed continuously. */
    abstract double halfThickness();

    /** Places the solid at time t at rest (scene start or reset). */
    public void moveTo(double t) {
        pose(t);
        pcx = cx; pcy = cy; pcz = cz;
        System.arraycopy(rotation, 0, previous, 0, 9);
        vx = vy = vz = 0;
    }

    /** Moves the solid to its pose at time t, h seconds after the last; the last becomes the substep's start. */
    void advance(double t, double h) {
        pcx = cx; pcy = cy; pcz = cz;
        System.arraycopy(rotation, 0, previous, 0, 9);
        pose(t);
        vx = (cx - pcx) / h; vy = (cy - pcy) / h; vz = (cz - pcz) / h;
    }

    @Override boolean moving() { return vx != 0 || vy != 0 || vz != 0 || omegaX != 0 || omegaY != 0 || omegaZ != 0; }

    private void pose(double t) {
        path.centreAt(t, centre);
        cx = centre[0]; cy = centre[1]; cz = centre[2];
        double w = Math.sqrt(omegaX * omegaX + omegaY * omegaY + omegaZ * omegaZ);
        if (w == 0) { System.arraycopy(rest, 0, rotation, 0, 9); return; }
        Rotation.axisAngle(omegaX / w, omegaY / w, omegaZ / w, w * t, spin);
        Rotation.multiply(spin, rest, rotation);
    }

    /** Particles within reach of the solid's path over the substep: bounding radius + margin + slack + their own motion. */
    @Override void findContacts(Particles p, double h, ContactSet contacts) {
        final double[] x = p.x, prev = p.prev, w = p.w;
        double reach = boundingRadius() + margin + ContactSet.SLACK * halfThickness() + ContactSet.PLANE_SLACK;
        double ux = cx - pcx, uy = cy - pcy, uz = cz - pcz, uu = ux * ux + uy * uy + uz * uz;
        for (int i = 0, count = p.count(); i < count; i++) {
            if (w[i] == 0) continue;
            int k = 3 * i;
            double dx = x[k] - pcx, dy = x[k + 1] - pcy, dz = x[k + 2] - pcz;
            double t = uu == 0 ? 0 : Math.max(0, Math.min(1, (dx * ux + dy * uy + dz * uz) / uu));
            dx -= t * ux; dy -= t * uy; dz -= t * uz;
            double mx = x[k] - prev[k], my = x[k + 1] - prev[k + 1], mz = x[k + 2] - prev[k + 2];
            double r = reach + Math.sqrt(mx * mx + my * my + mz * mz);
            if (dx * dx + dy * dy + dz * dz < r * r) contacts.add(i, this);
        }
    }

    @Override void project(Particles p, int i, double h) { ShapeContact.project(p, i, this, h); }

    @Override double clearance(Particles p, int i) { return clearanceAt(p.x[3 * i], p.x[3 * i + 1], p.x[3 * i + 2]); }

    @Override public double clearanceAt(double x, double y, double z) {
        double[][] w = work.get();
        double[] q = w[0];
        toLocal(x, y, z, q);
        return distance(q[0], q[1], q[2], w[1]) - margin;
    }

    /** World (x, y, z) in the solid's frame now, into out: Rᵀ(x − c). */
    final void toLocal(double x, double y, double z, double[] out) { inFrame(x - cx, y - cy, z - cz, rotation, out); }

    /** World (x, y, z) in the solid's frame at the substep's start, into out. */
    final void toLocalAtStart(double x, double y, double z, double[] out) { inFrame(x - pcx, y - pcy, z - pcz, previous, out); }

    private static void inFrame(double dx, double dy, double dz, double[] r, double[] out) {
        out[0] = r[0] * dx + r[3] * dy + r[6] * dz;
        out[1] = r[1] * dx + r[4] * dy + r[7] * dz;
        out[2] = r[2] * dx + r[5] * dy + r[8] * dz;
    }

    /** The solid's own direction (a local vector) in the world now: R v. */
    final double worldX(double[] v) { return rotation[0] * v[0] + rotation[1] * v[1] + rotation[2] * v[2]; }
    final double worldY(double[] v) { return rotation[3] * v[0] + rotation[4] * v[1] + rotation[5] * v[2]; }
    final double worldZ(double[] v) { return rotation[6] * v[0] + rotation[7] * v[1] + rotation[8] * v[2]; }

    public double centreX() { return cx; }
    public double centreY() { return cy; }
    public double centreZ() { return cz; }
    /** The rotation now, row-major, into out[0..8]. */
    public void rotation(double[] out) { System.arraycopy(rotation, 0, out, 0, 9); }
}
