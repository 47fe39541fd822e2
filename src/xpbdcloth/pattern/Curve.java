package xpbdcloth.pattern;

/**
 * One edge of a panel's outline, from its start corner to the next corner: a straight line, a circular arc
 * or a cubic Bézier curve (armholes and necklines are curved). Points are taken by arc length, so a seam
 * resampled at equal fractions of its length puts equal stitches on both of its sides.
 */
public abstract class Curve {
    /** The point at fraction s ∈ [0, 1] of the edge's arc length, into out[0..1]. */
    public abstract void point(double s, double[] out);

    /** Arc length in metres. */
    public abstract double length();

    /** The straight edge from a to b. */
    public static Curve line(double[] a, double[] b) { return new Line(a, b); }

    /**
     * The circular arc from a to b whose middle lies {@code bulge} metres from the chord, to the right of
     * the direction of travel (outward on a counter-clockwise outline); negative bulges to the left.
     */
    public static Curve arc(double[] a, double[] b, double bulge) { return new Arc(a, b, bulge); }

    /** The cubic Bézier curve from a to b with control points c1 and c2. */
    public static Curve bezier(double[] a, double[] c1, double[] c2, double[] b) { return new Bezier(a, c1, c2, b); }

    private static final class Line extends Curve {
        final double ax, ay, bx, by;

        Line(double[] a, double[] b) { ax = a[0]; ay = a[1]; bx = b[0]; by = b[1]; }

        @Override public void point(double s, double[] out) { out[0] = ax + s * (bx - ax); out[1] = ay + s * (by - ay); }

        @Override public double length() { return Math.hypot(bx - ax, by - ay); }
    }

    /** Centre, radius and the swept angle follow from the chord c and the sagitta b: r = (c²/4 + b²) / 2b. */
    private static final class Arc extends Curve {
        final double cx, cy, radius, start, sweep;

        Arc(double[] a, double[] b, double bulge) {
            double mx = (a[0] + b[0]) / 2, my = (a[1] + b[1]) / 2;
            double dx = b[0] - a[0], dy = b[1] - a[1], chord = Math.hypot(dx, dy);
            // The unit normal to the right of travel; the arc's middle is at m + bulge·n.
            double nx = dy / chord, ny = -dx / chord;
            double r = (chord * chord / 4 + bulge * bulge) / (2 * bulge);  // signed: negative bulges left
            cx = mx + (bulge - r) * nx;
            cy = my + (bulge - r) * ny;
            radius = Math.abs(r);
            start = Math.atan2(a[1] - cy, a[0] - cx);
            double half = Math.atan2(chord / 2, Math.abs(r - bulge));
            double swept = Math.abs(bulge) > Math.abs(r) ? 2 * Math.PI - 2 * half : 2 * half;
            // Bulging right of travel, the centre lies to the left and the arc turns counter-clockwise about it.
            sweep = bulge > 0 ? swept : -swept;
        }

        @Override public void point(double s, double[] out) {
            double t = start + s * sweep;
            out[0] = cx + radius * Math.cos(t);
            out[1] = cy + radius * Math.sin(t);
        }

        @Override public double length() { return radius * Math.abs(sweep); }
    }

    /** Arc length by a table of chords (a Bézier curve has no closed form for it), inverted by interpolation. */
    private static final class Bezier extends Curve {
        static final int PIECES = 256;
        final double[] p;
        final double[] cumulative = new double[PIECES + 1];

        Bezier(double[] a, double[] c1, double[] c2, double[] b) {
            p = new double[] {a[0], a[1], c1[0], c1[1], c2[0], c2[1], b[0], b[1]};
            double[] q = new double[2], r = new double[2];
            at(0, q);
            for (int i = 1; i <= PIECES; i++) {
                at((double) i / PIECES, r);
                cumulative[i] = cumulative[i - 1] + Math.hypot(r[0] - q[0], r[1] - q[1]);
                q[0] = r[0]; q[1] = r[1];
            }
        }

        void at(double t, double[] out) {
            double u = 1 - t, b0 = u * u * u, b1 = 3 * u * u * t, b2 = 3 * u * t * t, b3 = t * t * t;
            out[0] = b0 * p[0] + b1 * p[2] + b2 * p[4] + b3 * p[6];
            out[1] = b0 * p[1] + b1 * p[3] + b2 * p[5] + b3 * p[7];
        }

        @Override public void point(double s, double[] out) {
            double target = s * length();
            int lo = 0, hi = PIECES;
            while (hi - lo > 1) {
                int mid = (lo + hi) >>> 1;
                if (cumulative[mid] <= target) lo = mid; else hi = mid;
            }
            double piece = cumulative[hi] - cumulative[lo];
            double f = piece > 0 ? (target - cumulative[lo]) / piece : 0;
            at((lo + Math.max(0, Math.min(1, f))) / PIECES, out);
        }

        @Override public double length() { return cumulative[PIECES]; }
    }
}
