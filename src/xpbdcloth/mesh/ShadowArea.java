package xpbdcloth.mesh;

/**
 * The area of the shadow a triangle mesh casts straight down: the union of its triangles projected onto the
 * x–z plane, each point counted once however many layers cover it (a fold is one shadow, not two). Measured
 * on a square grid of cells, a cell counted when its centre is covered; the error is of the order of the
 * shadow's perimeter times half a cell, and unbiased along a smooth boundary. This is what a drape tester's
 * light and paper ring measure.
 */
public final class ShadowArea {
    private ShadowArea() {}

    /**
     * @param positions x, y, z per vertex
     * @param triangles three vertex indices per triangle
     * @param cell      the grid's cell size (m)
     */
    public static double of(double[] positions, int[] triangles, double cell) {
        if (!(cell > 0) || !Double.isFinite(cell)) throw new IllegalArgumentException("cell must be > 0, was " + cell);
        if (triangles.length == 0) return 0;
        double minX = Double.MAX_VALUE, minZ = Double.MAX_VALUE, maxX = -Double.MAX_VALUE, maxZ = -Double.MAX_VALUE;
        for (int t = 0; t < triangles.length; t++) {
            int v = triangles[t];
            minX = Math.min(minX, positions[3 * v]); maxX = Math.max(maxX, positions[3 * v]);
            minZ = Math.min(minZ, positions[3 * v + 2]); maxZ = Math.max(maxZ, positions[3 * v + 2]);
        }
        long columnsLong = (long) Math.ceil((maxX - minX) / cell) + 1, rowsLong = (long) Math.ceil((maxZ - minZ) / cell) + 1;
        if (columnsLong * rowsLong > 100_000_000L)
            throw new IllegalArgumentException("cell " + cell + " m makes a grid of " + columnsLong + " x " + rowsLong + " cells over the shadow; take a larger cell");
        int columns = (int) columnsLong, rows = (int) rowsLong;
        boolean[] covered = new boolean[columns * rows];
        long count = 0;
        for (int t = 0; t < triangles.length; t += 3) {
            double ax = positions[3 * triangles[t]], az = positions[3 * triangles[t] + 2];
            double bx = positions[3 * triangles[t + 1]], bz = positions[3 * triangles[t + 1] + 2];
            double cx = positions[3 * triangles[t + 2]], cz = positions[3 * triangles[t + 2] + 2];
            double twice = (bx - ax) * (cz - az) - (cx - ax) * (bz - az);
            if (twice == 0) continue;  // seen edge on: it casts no area
            int c0 = (int) Math.floor((Math.min(ax, Math.min(bx, cx)) - minX) / cell), c1 = (int) Math.floor((Math.max(ax, Math.max(bx, cx)) - minX) / cell);
            int r0 = (int) Math.floor((Math.min(az, Math.min(bz, cz)) - minZ) / cell), r1 = (int) Math.floor((Math.max(az, Math.max(bz, cz)) - minZ) / cell);
            for (int r = Math.max(r0, 0); r <= Math.min(r1, rows - 1); r++) {
                double pz = minZ + (r + 0.5) * cell;
                for (int c = Math.max(c0, 0); c <= Math.min(c1, columns - 1); c++) {
                    int k = r * columns + c;
                    if (covered[k]) continue;
                    double px = minX + (c + 0.5) * cell;
                    // Barycentric signs, taken with the triangle's own orientation (either winding casts a shadow).
                    double u = ((bx - px) * (cz - pz) - (cx - px) * (bz - pz)) / twice;
                    double v = ((cx - px) * (az - pz) - (ax - px) * (cz - pz)) / twice;
                    if (u >= 0 && v >= 0 && u + v <= 1) { covered[k] = true; count++; }
                }
            }
        }
        return count * cell * cell;
    }
}
