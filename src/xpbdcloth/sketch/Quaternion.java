package xpbdcloth.sketch;

/** A unit quaternion for camera orientation (immutable, double precision). */
public final class Quaternion {
    public static final Quaternion IDENTITY = new Quaternion(1, 0, 0, 0);
    public final double w, x, y, z;

    public Quaternion(double w, double x, double y, double z) {
        this.w = w; this.x = x; this.y = y; this.z = z;
    }

    /** Rotation by {@code angle} radians about the unit axis (ax, ay, az). */
    public static Quaternion axisAngle(double ax, double ay, double az, double angle) {
        double s = Math.sin(angle / 2);
        return new Quaternion(Math.cos(angle / 2), ax * s, ay * s, az * s);
    }

    /** this · q: apply q first, then this. */
    public Quaternion times(Quaternion q) {
        return new Quaternion(
                w * q.w - x * q.x - y * q.y - z * q.z,
                w * q.x + x * q.w + y * q.z - z * q.y,
                w * q.y - x * q.z + y * q.w + z * q.x,
                w * q.z + x * q.y - y * q.x + z * q.w).normalized();
    }

    public Quaternion normalized() {
        double n = Math.sqrt(w * w + x * x + y * y + z * z);
        return new Quaternion(w / n, x / n, y / n, z / n);
    }

    /** Rotates v (3 components) into out. */
    public void rotate(double vx, double vy, double vz, double[] out) {
        // v' = v + 2w (q × v) + 2 q × (q × v), with q the vector part.
        double tx = 2 * (y * vz - z * vy), ty = 2 * (z * vx - x * vz), tz = 2 * (x * vy - y * vx);
        out[0] = vx + w * tx + (y * tz - z * ty);
        out[1] = vy + w * ty + (z * tx - x * tz);
        out[2] = vz + w * tz + (x * ty - y * tx);
    }

    /** Spherical interpolation from a (t = 0) to b (t = 1) along the shorter arc. */
    public static Quaternion slerp(Quaternion a, Quaternion b, double t) {
        double d = a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
        double bw = b.w, bx = b.x, by = b.y, bz = b.z;
        if (d < 0) { d = -d; bw = -bw; bx = -bx; by = -by; bz = -bz; }
        double ka, kb;
        if (d > 0.9995) { ka = 1 - t; kb = t; }
        else {
            double th = Math.acos(d), s = Math.sin(th);
            ka = Math.sin((1 - t) * th) / s;
            kb = Math.sin(t * th) / s;
        }
        return new Quaternion(ka * a.w + kb * bw, ka * a.x + kb * bx, ka * a.y + kb * by, ka * a.z + kb * bz).normalized();
    }
}
