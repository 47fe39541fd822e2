package xpbdcloth.pattern;

import java.util.Arrays;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.Polygon;
import org.locationtech.jts.operation.valid.IsValidOp;
import org.locationtech.jts.operation.valid.TopologyValidationError;

/**
 * A panel's closed outline in its pattern plane (metres): corners 0 … n−1 and the edge from each corner to
 * the next (the last back to the first). A place on it is an <em>outline position</em> t ∈ [0, n): the edge
 * ⌊t⌋, at the fraction t − ⌊t⌋ of its arc length; corner k is t = k. Seams name their stretches this way.
 * Validated: at least two edges, finite corners, no edge of zero length, an outline that does not cross
 * itself and encloses an area.
 */
public final class Outline {
    /** Pieces a curved edge is cut into to test the outline for crossings (and to measure its area). */
    private static final int PIECES_PER_CURVE = 64;

    private final double[][] corners;
    private final Curve[] edges;
    /** Arc length from corner 0 to each corner, the last entry the whole length. */
    private final double[] along;
    private final double area;

    /**
     * @param corners the corners (x, y) in order
     * @param edges   edge k from corner k to corner k+1 (mod n); its end points must be those corners
     * @throws IllegalArgumentException naming what is wrong and where
     */
    public Outline(double[][] corners, Curve[] edges) {
        if (corners.length < 2 || edges.length != corners.length)
            throw new IllegalArgumentException("an outline needs at least 2 corners and one edge from each, had " + corners.length + " corners and " + edges.length + " edges");
        this.corners = new double[corners.length][];
        for (int k = 0; k < corners.length; k++) {
            if (corners[k].length != 2 || !Double.isFinite(corners[k][0]) || !Double.isFinite(corners[k][1]))
                throw new IllegalArgumentException("corner " + k + " must be two finite numbers (x, y), was " + Arrays.toString(corners[k]));
            this.corners[k] = corners[k].clone();
        }
        this.edges = edges.clone();
        along = new double[edges.length + 1];
        for (int k = 0; k < edges.length; k++) {
            double l = edges[k].length();
            if (!(l > 1e-9)) throw new IllegalArgumentException("edge " + k + " (corner " + k + " to " + (k + 1) % edges.length + ") has no length");
            along[k + 1] = along[k] + l;
        }
        Polygon ring = polygon(PIECES_PER_CURVE);
        TopologyValidationError crossing = new IsValidOp(ring).getValidationError();
        if (crossing != null) {
            Coordinate c = crossing.getCoordinate();
            throw new IllegalArgumentException("the outline crosses itself" + (c == null ? "" : String.format(" near (%.4g, %.4g) m", c.x, c.y)));
        }
        area = ring.getArea();
        if (!(area > 0)) throw new IllegalArgumentException("the outline encloses no area");
    }

    public int cornerCount() { return corners.length; }

    public double[] corner(int k) { return corners[k].clone(); }

    /** Length of the whole outline (m). */
    public double length() { return along[edges.length]; }

    /** The enclosed area (m²), of the outline with each curve cut into 64 chords. */
    public double area() { return area; }

    /** Arc length from corner 0 to outline position t ∈ [0, n]. */
    public double arcLength(double t) {
        int k = Math.min((int) Math.floor(t), edges.length - 1);
        return along[k] + (t - k) * (along[k + 1] - along[k]);
    }

    /** The point at arc length s from corner 0 (taken modulo the length), into out[0..1]. */
    public void pointAt(double s, double[] out) {
        double total = length();
        if (s < 0 || s >= total) s = ((s % total) + total) % total;  // (s + total) % total would round an s inside
        int k = Arrays.binarySearch(along, s);
        if (k < 0) k = -k - 2;
        k = Math.min(k, edges.length - 1);
        edges[k].point((s - along[k]) / (along[k + 1] - along[k]), out);
    }

    /** Arc length of each corner from corner 0 (n numbers). */
    public double[] cornerArcLengths() { return Arrays.copyOf(along, edges.length); }

    /** True when the corners run counter-clockwise (the pattern plane's normal, +z, is the panel's face). */
    public boolean counterClockwise() {
        double[] p = samples(edges.length * PIECES_PER_CURVE);
        double twice = 0;
        for (int i = 0, n = p.length / 2; i < n; i++) {
            int j = (i + 1) % n;
            twice += p[2 * i] * p[2 * j + 1] - p[2 * j] * p[2 * i + 1];
        }
        return twice > 0;
    }

    /** {@code count} points at equal arc lengths round the outline from corner 0, in its order: x, y each. */
    public double[] samples(int count) {
        if (count < 3) throw new IllegalArgumentException("count must be at least 3, was " + count);
        double[] out = new double[2 * count], p = new double[2];
        for (int i = 0; i < count; i++) {
            pointAt(length() * i / count, p);
            out[2 * i] = p[0]; out[2 * i + 1] = p[1];
        }
        return out;
    }

    /** The outline as a polygon, each edge cut into {@code pieces} chords of equal arc length. */
    Polygon polygon(int pieces) {
        Coordinate[] ring = new Coordinate[edges.length * pieces + 1];
        double[] p = new double[2];
        for (int k = 0; k < edges.length; k++)
            for (int i = 0; i < pieces; i++) {
                edges[k].point((double) i / pieces, p);
                ring[k * pieces + i] = new Coordinate(p[0], p[1]);
            }
        ring[ring.length - 1] = ring[0];
        return new GeometryFactory().createPolygon(ring);
    }
}
