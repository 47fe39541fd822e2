package xpbdcloth.pattern;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.locationtech.jts.algorithm.locate.IndexedPointInAreaLocator;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.Location;
import org.locationtech.jts.geom.Polygon;
import org.locationtech.jts.triangulate.DelaunayTriangulationBuilder;

/**
 * A quality triangulation of a panel inside its sampled outline, with edges near a target length.
 *
 * <p>The outline's samples are kept as they are (a seam's two sides must keep matching vertices). Inside,
 * points start on a triangular lattice of the target spacing and are relaxed as Persson and Strang's
 * DistMesh does (P.-O. Persson, G. Strang, "A simple mesh generator in MATLAB", SIAM Review 46(2), 2004):
 * each Delaunay edge is a bar that only pushes, its rest length 1.2 times the edges' root-mean-square
 * length, and the points move with the bars' net force until the triangles are near equilateral. The
 * triangulation is JTS's Delaunay (a well-kept library; its conforming builder was not used because it
 * splits outline segments, which would break a seam's matching). Every outline segment stays an edge because
 * no inside point may enter a segment's diametral circle (a segment with its circle empty is an edge of
 * every Delaunay triangulation: the Gabriel property), and a triangle is kept when its centroid is inside.
 */
public final class PanelMesher {
    private static final int ITERATIONS = 80;
    /** DistMesh's bar push: rest length over the edges' RMS length. */
    private static final double PUSH = 1.2;
    /** DistMesh's step along the net bar force. */
    private static final double STEP = 0.2;

    /** Positions (x, y per point: the outline's samples first, in order, then any fixed points, then the inside points) and triangles. */
    public static final class Result {
        public final double[] points;
        /** Three point indices per triangle, counter-clockwise. */
        public final int[] triangles;

        Result(double[] points, int[] triangles) { this.points = points; this.triangles = triangles; }

        public int pointCount() { return points.length / 2; }
    }

    private PanelMesher() {}

    /**
     * @param outline the outline's samples (x, y pairs), counter-clockwise, each segment no longer than about
     *                the target
     * @param edge    the target edge length (m)
     */
    public static Result mesh(double[] outline, double edge) { return mesh(outline, new double[0], edge); }

    /**
     * As {@link #mesh(double[], double)}, with points inside that stay where they are given and become
     * vertices (a line the cloth must have vertices on: a clamp's edge, say); they follow the outline's
     * samples in the result, in order. They should be about an edge apart and inside the outline.
     *
     * @param fixed x, y pairs, each inside the outline and not on it
     */
    public static Result mesh(double[] outline, double[] fixed, double edge) {
        int nb = outline.length / 2, nf = fixed.length / 2;
        GeometryFactory gf = new GeometryFactory();
        Coordinate[] ring = new Coordinate[nb + 1];
        for (int i = 0; i < nb; i++) ring[i] = new Coordinate(outline[2 * i], outline[2 * i + 1]);
        ring[nb] = ring[0];
        Polygon area = gf.createPolygon(ring);
        IndexedPointInAreaLocator inside = new IndexedPointInAreaLocator(area);

        List<double[]> points = new ArrayList<>();
        for (int i = 0; i < nb; i++) points.add(new double[] {outline[2 * i], outline[2 * i + 1]});
        for (int i = 0; i < nf; i++) {
            if (inside.locate(new Coordinate(fixed[2 * i], fixed[2 * i + 1])) != Location.INTERIOR)
                throw new IllegalArgumentException("fixed point " + i + " (" + fixed[2 * i] + ", " + fixed[2 * i + 1] + ") must lie inside the outline");
            points.add(new double[] {fixed[2 * i], fixed[2 * i + 1]});
        }
        var env = area.getEnvelopeInternal();
        double rowHeight = edge * Math.sqrt(3) / 2;
        // Jittered by a hundredth of an edge (seeded: the same mesh every time): a perfect lattice against
        // straight outline segments makes exactly collinear and cocircular sites, which JTS's point location
        // can walk round without end ("Locate failed to converge").
        java.util.Random jitter = new java.util.Random(1);
        for (int row = 0; env.getMinY() + row * rowHeight <= env.getMaxY(); row++) {
            double y = env.getMinY() + row * rowHeight;
            for (double x = env.getMinX() + (row % 2) * edge / 2; x <= env.getMaxX(); x += edge) {
                double jx = x + 0.01 * edge * (jitter.nextDouble() - 0.5), jy = y + 0.01 * edge * (jitter.nextDouble() - 0.5);
                if (allowed(jx, jy, outline, inside, edge) && clearOf(fixed, jx, jy, 0.6 * edge)) points.add(new double[] {jx, jy});
            }
        }

        double[] inward = inwardNudges(outline, edge);
        int[] triangles = triangulate(points, inward, inside, edge);
        double[] force = new double[2 * points.size()];
        for (int iteration = 0; iteration < ITERATIONS; iteration++) {
            java.util.Arrays.fill(force, 0);
            long[] edges = edges(triangles);
            double squares = 0;
            for (long e : edges) squares += length2(points, (int) (e >>> 32), (int) e);
            double rest = PUSH * Math.sqrt(squares / edges.length);
            for (long e : edges) {
                int a = (int) (e >>> 32), b = (int) e;
                double[] pa = points.get(a), pb = points.get(b);
                double dx = pa[0] - pb[0], dy = pa[1] - pb[1], l = Math.sqrt(dx * dx + dy * dy);
                double push = Math.max(rest - l, 0) / l;
                force[2 * a] += push * dx; force[2 * a + 1] += push * dy;
                force[2 * b] -= push * dx; force[2 * b + 1] -= push * dy;
            }
            for (int i = nb + nf; i < points.size(); i++) {
                double[] p = points.get(i);
                double x = p[0] + STEP * force[2 * i], y = p[1] + STEP * force[2 * i + 1];
                if (allowed(x, y, outline, inside, edge)) { p[0] = x; p[1] = y; }
            }
            triangles = triangulate(points, inward, inside, edge);
        }
        double[] xy = new double[2 * points.size()];
        for (int i = 0; i < points.size(); i++) { xy[2 * i] = points.get(i)[0]; xy[2 * i + 1] = points.get(i)[1]; }
        return new Result(xy, triangles);
    }

    /**
     * Whether an inside point may stand at (x, y): inside the outline, outside every outline segment's
     * diametral circle (so the segment stays a Delaunay edge) and not nearer than a fifth of an edge to it.
     */
    private static boolean allowed(double x, double y, double[] outline, IndexedPointInAreaLocator inside, double edge) {
        if (inside.locate(new Coordinate(x, y)) != Location.INTERIOR) return false;
        int n = outline.length / 2;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double ax = outline[2 * i] - x, ay = outline[2 * i + 1] - y, bx = outline[2 * j] - x, by = outline[2 * j + 1] - y;
            // (a − p)·(b − p) < 0: p sees the segment under more than a right angle, inside its diametral circle.
            double dot = ax * bx + ay * by, margin = 0.1 * ((ax - bx) * (ax - bx) + (ay - by) * (ay - by));
            if (dot < margin || ax * ax + ay * ay < 0.04 * edge * edge) return false;
        }
        return true;
    }

    /** Whether (x, y) is at least {@code distance} from every fixed point. */
    private static boolean clearOf(double[] fixed, double x, double y, double distance) {
        for (int i = 0; i < fixed.length; i += 2) {
            double dx = fixed[i] - x, dy = fixed[i + 1] - y;
            if (dx * dx + dy * dy < distance * distance) return false;
        }
        return true;
    }

    /**
     * Per outline sample, a move of 1e-7 edges inward (along the bisector of its two segments' inward
     * normals). An outline's samples along a straight slanted edge are collinear only to rounding, and JTS's
     * Delaunay decides orientation in plain doubles, so it can take such points either way and loop ("Locate
     * failed to converge"). Triangulating with each sample nudged inward makes every three consecutive samples
     * a clear, outward-convex turn (the sliver they span lies outside, its centroid on the outline, and is
     * dropped); the mesh keeps the exact positions.
     */
    private static double[] inwardNudges(double[] outline, double edge) {
        int n = outline.length / 2;
        double[] out = new double[2 * n];
        for (int i = 0; i < n; i++) {
            int prev = (i + n - 1) % n, next = (i + 1) % n;
            double ax = outline[2 * i] - outline[2 * prev], ay = outline[2 * i + 1] - outline[2 * prev + 1];
            double bx = outline[2 * next] - outline[2 * i], by = outline[2 * next + 1] - outline[2 * i + 1];
            double la = Math.hypot(ax, ay), lb = Math.hypot(bx, by);
            // Left of travel is inside a counter-clockwise outline.
            double nx = -ay / la - by / lb, ny = ax / la + bx / lb, l = Math.hypot(nx, ny);
            if (l < 1e-12) { nx = -by / lb; ny = bx / lb; l = 1; }  // a cusp: the next segment's normal
            out[2 * i] = 1e-7 * edge * nx / l;
            out[2 * i + 1] = 1e-7 * edge * ny / l;
        }
        return out;
    }

    /** Delaunay triangles of the points whose centroid is inside, counter-clockwise (outline samples nudged in while triangulating). */
    private static int[] triangulate(List<double[]> points, double[] inward, IndexedPointInAreaLocator inside, double edge) {
        Map<Coordinate, Integer> index = new HashMap<>();
        List<Coordinate> sites = new ArrayList<>();
        int nb = inward.length / 2;
        for (int i = 0; i < points.size(); i++) {
            double[] p = points.get(i);
            Coordinate c = i < nb ? new Coordinate(p[0] + inward[2 * i], p[1] + inward[2 * i + 1]) : new Coordinate(p[0], p[1]);
            if (index.putIfAbsent(c, i) == null) sites.add(c);
        }
        DelaunayTriangulationBuilder builder = new DelaunayTriangulationBuilder();
        builder.setSites(sites);
        Geometry all = builder.getTriangles(new GeometryFactory());
        int[] out = new int[3 * all.getNumGeometries()];
        int k = 0;
        for (int g = 0; g < all.getNumGeometries(); g++) {
            Coordinate[] c = all.getGeometryN(g).getCoordinates();
            int a = index.get(c[0]), b = index.get(c[1]), d = index.get(c[2]);
            double[] pa = points.get(a), pb = points.get(b), pd = points.get(d);
            double twice = (pb[0] - pa[0]) * (pd[1] - pa[1]) - (pd[0] - pa[0]) * (pb[1] - pa[1]);
            if (Math.abs(twice) < 1e-9 * edge * edge) continue;
            Coordinate centroid = new Coordinate((pa[0] + pb[0] + pd[0]) / 3, (pa[1] + pb[1] + pd[1]) / 3);
            if (inside.locate(centroid) != Location.INTERIOR) continue;
            out[k++] = a;
            out[k++] = twice > 0 ? b : d;
            out[k++] = twice > 0 ? d : b;
        }
        return java.util.Arrays.copyOf(out, k);
    }

    /** Each edge once, as (smaller index) << 32 | larger. */
    private static long[] edges(int[] triangles) {
        Set<Long> set = new HashSet<>();
        for (int t = 0; t < triangles.length; t += 3)
            for (int k = 0; k < 3; k++) {
                int a = triangles[t + k], b = triangles[t + (k + 1) % 3];
                set.add((long) Math.min(a, b) << 32 | Math.max(a, b));
            }
        long[] out = new long[set.size()];
        int i = 0;
        for (long e : set) out[i++] = e;
        java.util.Arrays.sort(out);
        return out;
    }

    private static double length2(List<double[]> points, int a, int b) {
        double dx = points.get(a)[0] - points.get(b)[0], dy = points.get(a)[1] - points.get(b)[1];
        return dx * dx + dy * dy;
    }
}
