package xpbdcloth.pattern;

/**
 * Where a panel starts around the body, as garment CAD's arrangement points put it. Either the centre of the
 * panel's bounding box goes to {@code position}, its pattern plane (x right, y up, face towards +z) turned
 * by {@code rotation} (degrees about x, then y, then z, as presets place meshes), optionally first rolled
 * onto a cylinder of radius {@code wrap} about a vertical axis behind its face; or the panel is wrapped
 * {@linkplain #around around} a body part: onto an elliptic cylinder about an axis (vertical for a torso or
 * a leg, slanted along an arm for a sleeve), its centre at an angle round it, its face outwards. Either way
 * x is measured along the surface (the wrap stretches nothing) and y runs along the axis (vertical unless
 * the axis is slanted).
 */
public final class Placement {
    public static final Placement IDENTITY = new Placement(new double[3], new double[3], 0);

    private final double[] position, rotation;
    /** Radius of the cylinder the panel is rolled onto (m), or 0 for flat. */
    private final double wrap;
    private final double[][] turn;
    /** Around a body part: the axis's point, the ellipse's half widths along x and z, and arc length by angle (null otherwise). */
    private final double[] centre, radii, arcAt;
    /**
     * Around a body part: the cylinder's frame, unit and right-handed, side × axis = front: the pattern's y
     * runs along {@code axis}, the angle is measured from {@code front} (the world's +z made square to the
     * axis) towards {@code side}. A vertical axis gives x, y and z.
     */
    private final double[] side, axis, front;
    private final double startAngle;
    private static final int ARC_STEPS = 4096;

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
        centre = radii = arcAt = side = axis = front = null;
        startAngle = 0;
    }

    private Placement(double[] centre, double[] radii, double angleDegrees, double[] axis) {
        for (int i = 0; i < 3; i++)
            if (!Double.isFinite(centre[i])) throw new IllegalArgumentException("centre must be finite, was " + java.util.Arrays.toString(centre));
        double length = Math.sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
        if (!(length > 0) || Double.isInfinite(length) || Double.isNaN(length))
            throw new IllegalArgumentException("axis must be a direction (finite, not [0, 0, 0]), was " + java.util.Arrays.toString(axis));
        this.axis = new double[] {axis[0] / length, axis[1] / length, axis[2] / length};
        // Front: +z without its part along the axis; an axis along z has no such front, so +y is used.
        double[] towards = Math.abs(this.axis[2]) > 0.999 ? new double[] {0, 1, 0} : new double[] {0, 0, 1};
        double along = dot(towards, this.axis);
        double[] f = {towards[0] - along * this.axis[0], towards[1] - along * this.axis[1], towards[2] - along * this.axis[2]};
        double fl = Math.sqrt(dot(f, f));
        this.front = new double[] {f[0] / fl, f[1] / fl, f[2] / fl};
        this.side = cross(this.axis, this.front);
        if (!(radii[0] > 0 && radii[1] > 0) || Double.isInfinite(radii[0]) || Double.isInfinite(radii[1]))
            throw new IllegalArgumentException("radii must be two half widths > 0 m (x, z), was " + java.util.Arrays.toString(radii));
        if (!Double.isFinite(angleDegrees)) throw new IllegalArgumentException("angle must be finite, was " + angleDegrees);
        this.centre = centre.clone();
        this.radii = radii.clone();
        this.startAngle = Math.toRadians(angleDegrees);
        position = centre.clone();
        rotation = new double[] {0, angleDegrees, 0};
        wrap = 0;
        turn = null;
        // An ellipse has no closed-form arc length: a table of chords over a turn, the angle found by interpolation.
        arcAt = new double[ARC_STEPS + 1];
        double[] q = ellipse(0), r;
        for (int k = 1; k <= ARC_STEPS; k++) {
            r = ellipse(2 * Math.PI * k / ARC_STEPS);
            arcAt[k] = arcAt[k - 1] + Math.hypot(r[0] - q[0], r[1] - q[1]);
            q = r;
        }
    }

    /**
     * A panel wrapped round a body part: onto the elliptic cylinder about the vertical axis through
     * {@code centre} with half widths {@code radii} (x, z), the centre of its bounding box at {@code centre}'s
     * height and at {@code angleDegrees} round the axis (0 in front, +z; 90 at +x), its x running round the
     * axis the way the angle grows, its face outwards.
     */
    public static Placement around(double[] centre, double[] radii, double angleDegrees) {
        return around(centre, radii, angleDegrees, new double[] {0, 1, 0});
    }

    /**
     * As {@link #around(double[], double[], double)}, about the axis through {@code centre} along
     * {@code axis} (any length; the pattern's y runs along it): a sleeve round a slanted arm. The ellipse's
     * half widths are along the frame's side (for a vertical axis, x) and front (+z made square to the axis;
     * +y for an axis along z); angle 0 is the front and 90 the side, side = axis × front.
     */
    public static Placement around(double[] centre, double[] radii, double angleDegrees, double[] axis) {
        if (centre.length != 3 || radii.length != 2 || axis.length != 3) throw new IllegalArgumentException("centre must be [x, y, z], radii [x, z] and axis [x, y, z]");
        return new Placement(centre, radii, angleDegrees, axis);
    }

    /** Whether the panel is wrapped round a body part ({@link #around}). */
    public boolean isAround() { return arcAt != null; }

    private double[] ellipse(double angle) { return new double[] {radii[0] * Math.sin(angle), radii[1] * Math.cos(angle)}; }

    /** The angle at arc length s from angle 0 round the ellipse (any s: whole turns wrap). */
    private double angleAt(double s) {
        double perimeter = arcAt[ARC_STEPS], turns = Math.floor(s / perimeter), rest = s - turns * perimeter;
        int k = java.util.Arrays.binarySearch(arcAt, rest);
        if (k < 0) k = -k - 2;
        k = Math.max(0, Math.min(k, ARC_STEPS - 1));
        double f = (rest - arcAt[k]) / (arcAt[k + 1] - arcAt[k]);
        return 2 * Math.PI * (turns + (k + f) / ARC_STEPS);
    }

    /** Arc length round the ellipse from angle 0 to the given angle. */
    private double arcLengthTo(double angle) {
        double turns = Math.floor(angle / (2 * Math.PI)), t = (angle / (2 * Math.PI) - turns) * ARC_STEPS;
        int k = Math.min((int) t, ARC_STEPS - 1);
        return turns * arcAt[ARC_STEPS] + arcAt[k] + (t - k) * (arcAt[k + 1] - arcAt[k]);
    }

    public double[] position() { return position.clone(); }

    public double[] rotation() { return rotation.clone(); }

    public double wrap() { return wrap; }

    /**
     * The 3D point of the pattern point (x, y) of a panel whose bounding box is centred on (cx, cy), into
     * out[0..2]; {@code direction} (dx, dy) in the pattern plane at that point goes to out[3..5] (a grain).
     */
    public void place(double x, double y, double cx, double cy, double dx, double dy, double[] out) {
        if (arcAt != null) {
            double a = angleAt(arcLengthTo(startAngle) + x - cx), c = Math.cos(a), s = Math.sin(a);
            // In the cylinder's frame: (radii₀ sin a, y − cy, radii₁ cos a), its tangent round the ellipse (tx, ·, tz)
            // (y and cy added apart, in this order, as the vertical-only placement did: the same bits for it)
            double lx = radii[0] * s, lz = radii[1] * c;
            double tx = radii[0] * c, tz = -radii[1] * s, l = Math.hypot(tx, tz), gx = dx * tx / l, gz = dx * tz / l;
            for (int i = 0; i < 3; i++) {
                out[i] = centre[i] + side[i] * lx + axis[i] * y - axis[i] * cy + front[i] * lz;
                out[3 + i] = side[i] * gx + axis[i] * dy + front[i] * gz;
            }
            return;
        }
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

    private static double dot(double[] a, double[] b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    private static double[][] times(double[][] a, double[][] b) {
        double[][] c = new double[3][3];
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                for (int k = 0; k < 3; k++) c[i][j] += a[i][k] * b[k][j];
        return c;
    }
}
