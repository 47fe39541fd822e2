package xpbdcloth.engine;

/**
 * A kinematic capsule (a pole, an arm, a rolling pin): the points within radius r of a segment of
 * half length L through its centre along its axis, moving and spinning like any {@link RigidCollider}.
 * In its own frame the segment runs along y from −L to L.
 *
 * <pre>
 *   s(q) = (0, clamp(q_y, −L, L), 0),   φ(q) = |q − s(q)| − r,   ∇φ = (q − s)/|q − s|
 * </pre>
 * The exact signed distance (Ericson 2005, "Real-Time Collision Detection", §4.5.1: a capsule is a swept
 * sphere); convex. Degenerate case: a point on the segment itself has no direction; it leaves along the
 * local +x, a fixed choice so the result is deterministic.
 */
public final class Capsule extends RigidCollider {
    final double halfLength, radius;

    /**
     * @param axis       the segment's direction (any length &gt; 0)
     * @param halfLength L, m, ≥ 0 (0: a sphere)
     * @param radius     r, m, &gt; 0
     */
    public Capsule(SpherePath path, double[] axis, double halfLength, double radius, double margin, double staticFriction, double kineticFriction) {
        super(path, rotationOf(axis), margin, staticFriction, kineticFriction);
        this.halfLength = Check.inRange("halfLength", halfLength, 0, EngineRange.MAX_RADIUS);
        this.radius = Check.inRange("radius", radius, Double.MIN_NORMAL, EngineRange.MAX_RADIUS);
    }

    private static double[] rotationOf(double[] axis) {
        if (axis == null || axis.length != 3)
            throw new IllegalArgumentException("axis must have 3 components, was " + (axis == null ? "null" : axis.length));
        Check.finite3("axis", axis[0], axis[1], axis[2]);
        double len = Math.sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
        if (!(len > 1e-9 && len < 1e9)) throw new IllegalArgumentException("axis must have a length in (1e-9, 1e9), was " + len);
        return Rotation.yOnto(axis[0], axis[1], axis[2]);
    }

    @Override double distance(double qx, double qy, double qz, double[] n) {
        double dy = qy - Math.max(-halfLength, Math.min(halfLength, qy));
        double len = Math.sqrt(qx * qx + dy * dy + qz * qz);
        if (len < DistanceBlock.MIN_LENGTH) { n[0] = 1; n[1] = 0; n[2] = 0; }
        else { n[0] = qx / len; n[1] = dy / len; n[2] = qz / len; }
        return len - radius;
    }

    @Override double boundingRadius() { return halfLength + radius; }
    @Override double halfThickness() { return radius; }

    public double halfLength() { return halfLength; }
    public double radius() { return radius; }
}
