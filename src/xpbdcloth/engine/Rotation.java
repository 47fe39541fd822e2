package xpbdcloth.engine;

/**
 * Rotations as row-major 3 × 3 matrices in {@code double[9]}, for the poses of the rigid colliders. Written
 * into arrays the caller keeps, so that moving a collider allocates nothing.
 */
final class Rotation {
    private Rotation() {}

    /** The identity. */
    static double[] identity() { return new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1}; }

    /**
     * Turned about x, then y, then z by the given angles in degrees (R = R_z R_y R_x): the order a preset's
     * mesh rotation uses, so a box and a mesh given the same rotation turn alike.
     */
    static double[] eulerDegrees(double rx, double ry, double rz) {
        double[] x = new double[9], y = new double[9], z = new double[9], zy = new double[9], out = new double[9];
        axisAngle(1, 0, 0, Math.toRadians(rx), x);
        axisAngle(0, 1, 0, Math.toRadians(ry), y);
        axisAngle(0, 0, 1, Math.toRadians(rz), z);
        multiply(z, y, zy);
        multiply(zy, x, out);
        return out;
    }

    /** The shortest rotation taking local +y onto the direction (ax, ay, az) (any length > 0). */
    static double[] yOnto(double ax, double ay, double az) {
        double len = Math.sqrt(ax * ax + ay * ay + az * az);
        ax /= len; ay /= len; az /= len;
        // Axis y × a, angle acos(y·a); a = −y has no shortest way: half a turn about x.
        double kx = az, kz = -ax, s = Math.sqrt(kx * kx + kz * kz), c = ay;
        double[] out = new double[9];
        if (s < 1e-12) axisAngle(1, 0, 0, c > 0 ? 0 : Math.PI, out);
        else axisAngle(kx / s, 0, kz / s, Math.atan2(s, c), out);
        return out;
    }

    /** The rotation by {@code angle} radians about the unit axis (ux, uy, uz) (Rodrigues' formula). */
    static void axisAngle(double ux, double uy, double uz, double angle, double[] out) {
        double c = Math.cos(angle), s = Math.sin(angle), t = 1 - c;
        out[0] = t * ux * ux + c;      out[1] = t * ux * uy - s * uz; out[2] = t * ux * uz + s * uy;
        out[3] = t * ux * uy + s * uz; out[4] = t * uy * uy + c;      out[5] = t * uy * uz - s * ux;
        out[6] = t * ux * uz - s * uy; out[7] = t * uy * uz + s * ux; out[8] = t * uz * uz + c;
    }

    /** out = a b (out must be neither). */
    static void multiply(double[] a, double[] b, double[] out) {
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++)
                out[3 * r + c] = a[3 * r] * b[c] + a[3 * r + 1] * b[3 + c] + a[3 * r + 2] * b[6 + c];
    }
}
