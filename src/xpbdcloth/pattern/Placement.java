package xpbdcloth.pattern;

/**
 * Where a panel starts around the body, as garment CAD's arrangement points put it: the centre of the
 * panel's bounding box goes to {@code position}, its pattern plane (x right, y up, face towards +z) turned by
 * {@code rotation} (degrees about x, then y, then z, as presets place meshes). With a {@code wrap} radius the
 * panel is first rolled onto a cylinder of that radius about a vertical axis behind its face (x measured
 * along the cylinder, so the wrap stretches nothing): a front panel wraps around a torso instead of standing
 * flat before it.
 */
public final class Placement {
    public static final Placement IDENTITY = new Placement(new double[3], new double[3], 0);

    private final double[] position, rotation;
    /** Radius of the cylinder the panel is rolled onto (m), or 0 for flat. */
    private final double wrap;
    private final double[][] turn;

    public Placement(double[] position, double[] rotationDegrees, double wrap) {
        if (position.length != 3 || rotationDegrees.length != 3) throw new IllegalArgumentException("position and rotation must be [x, y, z]");
        for (int i = 0; i < 3; i++)
            if (!Double.isFinite(position[i]) || !Double.isFinite(rotationDegrees[i]))
                throw new IllegalArgumentException("position and rotation must be finite, were " + java.util.Arrays.toString(position) + " and " + java.util.Arrays.toString(rotationDegrees));
        if (!(wrap >= 0) || Double.isInfinite(wrap)) throw new IllegalArgumentException("wrap must be a radius ≥ 0 m (0: flat), was " + wrap);
        this.position = position.clone();
        this.rotation = rotationDegrees.clone();
        this.wrap = wrap;
        double ax = Math.toRadians(rotationDegrees[0]), ay = Math.toRadians(rotationDegrees[1]), az = Math.toRadians(rotationDegrees[2]);
        double[][] rx = {{1, 0, 0}, {0, Math.cos(ax), -Math.sin(ax)}, {0, Math.sin(ax), Math.cos(ax)}};
        double[][] ry = {{Math.cos(ay), 0, Math.sin(ay)}, {0, 1, 0}, {-Math.sin(ay), 0, Math.cos(ay)}};
        double[][] rz = {{Math.cos(az), -Math.sin(az), 0}, {Math.sin(az), Math.cos(az), 0}, {0, 0, 1}};
        turn = times(rz, times(ry, rx));
    }

    public double[] position() { return position.clone(); }

    public double[] rotation() { return rotation.clone(); }

    public double wrap() { return wrap; }

    /**
     * The 3D point of the pattern point (x, y) of a panel whose bounding box is centred on (cx, cy), into
     * out[0..2]; {@code direction} (dx, dy) in the pattern plane at that point goes to out[3..5] (a grain).
     */
    public void place(double x, double y, double cx, double cy, double dx, double dy, double[] out) {
        double u = x - cx, v = y - cy, lx, ly = v, lz, tx, ty = dy, tz;
        if (wrap > 0) {
            double a = u / wrap;
            lx = wrap * Math.sin(a); lz = wrap * (Math.cos(a) - 1);
            tx = dx * Math.cos(a); tz = -dx * Math.sin(a);
        } else {
            lx = u; lz = 0; tx = dx; tz = 0;
        }
        for (int i = 0; i < 3; i++) {
            out[i] = position[i] + turn[i][0] * lx + turn[i][1] * ly + turn[i][2] * lz;
            out[3 + i] = turn[i][0] * tx + turn[i][1] * ty + turn[i][2] * tz;
        }
    }

    private static double[][] times(double[][] a, double[][] b) {
        double[][] c = new double[3][3];
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                for (int k = 0; k < 3; k++) c[i][j] += a[i][k] * b[k][j];
        return c;
    }
}
