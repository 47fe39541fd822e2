package xpbdcloth.engine;

/**
 * A kinematic oriented box (a table, a step, a thin board): half extents (eₓ, e_y, e_z) in its own frame,
 * turned by a rotation, moving along a path and spinning like any {@link RigidCollider}.
 *
 * <pre>
 *   d = |q| − e (per axis, q local),   φ(q) = |max(d, 0)| + min(max(dₓ, d_y, d_z), 0)
 *   ∇φ = max(d, 0)·sign(q) / |max(d, 0)| outside;  ± the axis of the largest dᵢ inside
 * </pre>
 * φ is the exact signed distance (Quílez, "distance functions", the box); it is convex, as the contact's
 * continuous test needs. At a corner or edge inside, the face of least depth wins (ties: x, then y, then z).
 */
public final class Box extends RigidCollider {
    final double ex, ey, ez;

    /**
     * @param halfExtents     (eₓ, e_y, e_z), m, each &gt; 0
     * @param rotationDegrees about x, then y, then z (as a preset's mesh rotation)
     */
    public Box(SpherePath path, double[] halfExtents, double[] rotationDegrees, double margin, double staticFriction, double kineticFriction) {
        super(path, rotationOf(rotationDegrees), margin, staticFriction, kineticFriction);
        if (halfExtents == null || halfExtents.length != 3)
            throw new IllegalArgumentException("halfExtents must have 3 components, was " + (halfExtents == null ? "null" : halfExtents.length));
        ex = Check.inRange("halfExtents[0]", halfExtents[0], Double.MIN_NORMAL, EngineRange.MAX_RADIUS);
        ey = Check.inRange("halfExtents[1]", halfExtents[1], Double.MIN_NORMAL, EngineRange.MAX_RADIUS);
        ez = Check.inRange("halfExtents[2]", halfExtents[2], Double.MIN_NORMAL, EngineRange.MAX_RADIUS);
    }

    private static double[] rotationOf(double[] degrees) {
        if (degrees == null || degrees.length != 3)
            throw new IllegalArgumentException("rotation must have 3 components, was " + (degrees == null ? "null" : degrees.length));
        Check.finite3("rotation", degrees[0], degrees[1], degrees[2]);
        return Rotation.eulerDegrees(degrees[0], degrees[1], degrees[2]);
    }

    @Override double distance(double qx, double qy, double qz, double[] n) {
        double dx = Math.abs(qx) - ex, dy = Math.abs(qy) - ey, dz = Math.abs(qz) - ez;
        double ox = Math.max(dx, 0), oy = Math.max(dy, 0), oz = Math.max(dz, 0);
        double outside = Math.sqrt(ox * ox + oy * oy + oz * oz);
        if (outside > 0) {
            n[0] = Math.copySign(ox, qx) / outside; n[1] = Math.copySign(oy, qy) / outside; n[2] = Math.copySign(oz, qz) / outside;
            return outside;
        }
        n[0] = n[1] = n[2] = 0;
        if (dx >= dy && dx >= dz) { n[0] = Math.copySign(1, qx); return dx; }
        if (dy >= dz) { n[1] = Math.copySign(1, qy); return dy; }
        n[2] = Math.copySign(1, qz);
        return dz;
    }

    @Override double boundingRadius() { return Math.sqrt(ex * ex + ey * ey + ez * ez); }
    @Override double halfThickness() { return Math.min(ex, Math.min(ey, ez)); }

    public double halfExtentX() { return ex; }
    public double halfExtentY() { return ey; }
    public double halfExtentZ() { return ez; }
}
