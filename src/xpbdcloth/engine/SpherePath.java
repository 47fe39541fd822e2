package xpbdcloth.engine;

/**
 * Where a kinematic sphere's centre is at time t (seconds). Writes x, y, z into {@code out[0..2]} so that
 * moving a sphere allocates nothing.
 */
@FunctionalInterface
public interface SpherePath {
    void centreAt(double t, double[] out);

    /** Stays at (x, y, z). */
    static SpherePath fixed(double x, double y, double z) {
        Check.finite3("centre", x, y, z);
        return (t, out) -> { out[0] = x; out[1] = y; out[2] = z; };
    }

    /** Starts at (x, y, z) and moves with constant velocity (vx, vy, vz) m/s. */
    static SpherePath linear(double x, double y, double z, double vx, double vy, double vz) {
        Check.finite3("start", x, y, z);
        Check.finite3("velocity", vx, vy, vz);
        return (t, out) -> { out[0] = x + vx * t; out[1] = y + vy * t; out[2] = z + vz * t; };
    }

    /** Circles (cx, cy, cz) in the horizontal plane with the given radius (m) and angular speed (rad/s). */
    static SpherePath circle(double cx, double cy, double cz, double radius, double angularSpeed) {
        Check.finite3("centre", cx, cy, cz);
        Check.nonNegative("radius", radius);
        Check.finite("angularSpeed", angularSpeed);
        return (t, out) -> {
            out[0] = cx + radius * Math.cos(angularSpeed * t);
            out[1] = cy;
            out[2] = cz + radius * Math.sin(angularSpeed * t);
        };
    }

    /** Oscillates about (cx, cy, cz): centre + amplitude·sin(2π f t), amplitude a vector in metres. */
    static SpherePath oscillation(double cx, double cy, double cz, double ax, double ay, double az, double frequency) {
        Check.finite3("centre", cx, cy, cz);
        Check.finite3("amplitude", ax, ay, az);
        Check.nonNegative("frequency", frequency);
        return (t, out) -> {
            double s = Math.sin(2 * Math.PI * frequency * t);
            out[0] = cx + ax * s; out[1] = cy + ay * s; out[2] = cz + az * s;
        };
    }
}
