package xpbdcloth.fabric;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.Polygon;
import org.locationtech.jts.triangulate.DelaunayTriangulationBuilder;
import xpbdcloth.engine.Particles;

/**
 * Flat rectangles (x from 0 to length, z from 0 to width, y = 0) triangulated in the ways a bending model
 * must not care about: a grid split along alternating diagonals, along one diagonal direction, with cells
 * longer than wide, and an unstructured Delaunay triangulation (JTS) of scattered points.
 */
public final class StripMeshes {
    /** Positions (3 per vertex) and triangles (3 indices each) of a flat mesh. */
    public static final class Mesh {
        public final double[] positions;
        public final int[] triangles;
        public final String name;

        public Mesh(String name, double[] positions, int[] triangles) {
            this.name = name;
            this.positions = positions;
            this.triangles = triangles;
        }

        public int vertices() { return positions.length / 3; }

        /** The vertices as particles of the given areal density (kg/m²), each a third of its triangles' mass. */
        public Particles particles(double arealDensity) {
            Particles p = new Particles(vertices());
            double[] mass = new double[vertices()];
            for (int t = 0; t < triangles.length; t += 3) {
                double third = arealDensity * area(t) / 3;
                for (int k = 0; k < 3; k++) mass[triangles[t + k]] += third;
            }
            for (int i = 0; i < vertices(); i++) {
                p.setPosition(i, positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
                p.setMass(i, mass[i]);
            }
            return p;
        }

        /** Rest area of the triangle starting at index t. */
        public double area(int t) {
            int a = triangles[t], b = triangles[t + 1], c = triangles[t + 2];
            double ux = positions[3 * b] - positions[3 * a], uz = positions[3 * b + 2] - positions[3 * a + 2];
            double vx = positions[3 * c] - positions[3 * a], vz = positions[3 * c + 2] - positions[3 * a + 2];
            return 0.5 * Math.abs(ux * vz - uz * vx);
        }

        @Override public String toString() { return name; }
    }

    private StripMeshes() {}

    /** A grid of columns × rows cells; each cell split along (0,0)–(1,1), or alternating in a checkerboard. */
    public static Mesh grid(double length, double width, int columns, int rows, boolean alternating) {
        double[] x = new double[3 * (columns + 1) * (rows + 1)];
        // Numbered across the width first: a strip's band stays narrow.
        for (int i = 0; i <= columns; i++)
            for (int j = 0; j <= rows; j++) {
                int v = i * (rows + 1) + j;
                x[3 * v] = length * i / columns;
                x[3 * v + 2] = width * j / rows;
            }
        int[] t = new int[6 * columns * rows];
        int k = 0;
        for (int i = 0; i < columns; i++)
            for (int j = 0; j < rows; j++) {
                int a = i * (rows + 1) + j, b = a + rows + 1, c = b + 1, d = a + 1;
                if (!alternating || (i + j) % 2 == 0) { t[k++] = a; t[k++] = b; t[k++] = c; t[k++] = a; t[k++] = c; t[k++] = d; }
                else { t[k++] = a; t[k++] = b; t[k++] = d; t[k++] = b; t[k++] = c; t[k++] = d; }
            }
        String name = (alternating ? "alternating" : "one-diagonal") + " grid " + columns + "×" + rows
                + String.format(" (cells %.2g × %.2g mm)", 1e3 * length / columns, 1e3 * width / rows);
        return new Mesh(name, x, t);
    }

    /**
     * The Delaunay triangulation of the rectangle's boundary, sampled every {@code spacing}, and of interior
     * points on a grid of that spacing each moved at random by up to 0.3 of it (seeded), numbered along x;
     * the points on the line x = {@code straightAt} (if the grid has one) move only along it.
     */
    public static Mesh delaunay(double length, double width, double spacing, long seed) { return delaunay(length, width, spacing, seed, Double.NaN); }

    public static Mesh delaunay(double length, double width, double spacing, long seed, double straightAt) {
        Random random = new Random(seed);
        List<Coordinate> points = new ArrayList<>();
        int nx = (int) Math.round(length / spacing), nz = Math.max(1, (int) Math.round(width / spacing));
        for (int i = 0; i <= nx; i++)
            for (int j = 0; j <= nz; j++) {
                double px = length * i / nx, pz = width * j / nz;
                boolean boundary = i == 0 || i == nx || j == 0 || j == nz;
                if (!boundary) {
                    double jitter = 0.3 * spacing * (2 * random.nextDouble() - 1);
                    if (!(Math.abs(px - straightAt) < 1e-9 * length)) px += jitter;
                    pz += 0.3 * width / nz * (2 * random.nextDouble() - 1);
                }
                points.add(new Coordinate(px, pz));
            }
        points.sort((a, b) -> Double.compare(a.x, b.x) != 0 ? Double.compare(a.x, b.x) : Double.compare(a.y, b.y));
        DelaunayTriangulationBuilder builder = new DelaunayTriangulationBuilder();
        builder.setSites(points);
        Geometry triangles = builder.getTriangles(new GeometryFactory());
        double[] x = new double[3 * points.size()];
        for (int i = 0; i < points.size(); i++) { x[3 * i] = points.get(i).x; x[3 * i + 2] = points.get(i).y; }
        List<Integer> out = new ArrayList<>();
        for (int g = 0; g < triangles.getNumGeometries(); g++) {
            Coordinate[] c = ((Polygon) triangles.getGeometryN(g)).getExteriorRing().getCoordinates();
            int[] ids = new int[3];
            for (int k = 0; k < 3; k++) ids[k] = indexOf(points, c[k]);
            double area = (c[1].x - c[0].x) * (c[2].y - c[0].y) - (c[1].y - c[0].y) * (c[2].x - c[0].x);
            // Collinear boundary samples can leave a sliver of no area on the hull: it is no triangle.
            if (Math.abs(area) < 1e-9 * spacing * spacing) continue;
            for (int id : ids) out.add(id);
        }
        return new Mesh(String.format("Delaunay (spacing %.2g mm, seed %d)", 1e3 * spacing, seed), x, out.stream().mapToInt(Integer::intValue).toArray());
    }

    private static int indexOf(List<Coordinate> points, Coordinate c) {
        int lo = 0, hi = points.size() - 1;
        while (lo <= hi) {
            int mid = (lo + hi) >>> 1;
            Coordinate m = points.get(mid);
            int cmp = Double.compare(m.x, c.x) != 0 ? Double.compare(m.x, c.x) : Double.compare(m.y, c.y);
            if (cmp == 0) return mid;
            if (cmp < 0) lo = mid + 1; else hi = mid - 1;
        }
        throw new IllegalStateException("Delaunay vertex " + c + " is not one of the sites");
    }
}
