package xpbdcloth.mesh;

import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * A flag with a round hole: a grid of quads in the x–y plane, hoist (pole side) at x = 0 and top edge at
 * y = 0, running to x = width and down to y = −height, with every quad whose centre lies inside the hole
 * left out, the vertices no quad keeps dropped, and the rim's nearest vertices slid onto the circle. Quads are split along alternating diagonals, like a
 * grid cloth, and face +z. Groups: "hoist" (the left edge, where the flag meets its pole) and "fly" (the
 * right edge). The hole makes the mesh's boundary two loops, which a grid cannot have.
 */
public final class FlagWithHole {
    private FlagWithHole() {}

    /** The hole: centre (cx, cy) in the flag's plane (cy negative, below the top edge) and radius, metres. */
    public static ClothMesh generate(double width, double height, int columns, int rows, double cx, double cy, double holeRadius) {
        if (!(width > 0) || !(height > 0)) throw new IllegalArgumentException("width and height must be > 0, was " + width + " x " + height);
        if (columns < 2 || rows < 2) throw new IllegalArgumentException("columns and rows must be >= 2, was " + columns + " x " + rows);
        if (!(holeRadius >= 0)) throw new IllegalArgumentException("holeRadius must be >= 0, was " + holeRadius);
        double dx = width / (columns - 1), dy = height / (rows - 1);
        int[] keep = new int[columns * rows];
        Arrays.fill(keep, -1);
        boolean[] quad = new boolean[(columns - 1) * (rows - 1)];
        for (int r = 0; r + 1 < rows; r++)
            for (int c = 0; c + 1 < columns; c++) {
                double qx = (c + 0.5) * dx - cx, qy = -(r + 0.5) * dy - cy;
                if (qx * qx + qy * qy <= holeRadius * holeRadius) continue;
                quad[r * (columns - 1) + c] = true;
                int i = r * columns + c;
                keep[i] = keep[i + 1] = keep[i + columns] = keep[i + columns + 1] = 0;
            }
        int n = 0;
        for (int i = 0; i < keep.length; i++) if (keep[i] == 0) keep[i] = n++;
        double[] x = new double[3 * n];
        for (int i = 0; i < keep.length; i++)
            if (keep[i] >= 0) { x[3 * keep[i]] = (i % columns) * dx; x[3 * keep[i] + 1] = -(i / columns) * dy + 0.0; }
        // The hole's rim is a staircase of grid steps; its vertices within half a grid step of the circle
        // are slid along the radius onto it, so the hole is nearly round. (Sliding the farther ones, the
        // staircase's outer corners on the diagonals, folds their quads over: a test checks none is.)
        boolean[] onRim = new boolean[keep.length];
        for (int r = 0; r + 1 < rows; r++)
            for (int c = 0; c + 1 < columns; c++) {
                if (quad[r * (columns - 1) + c]) continue;
                int i = r * columns + c;
                onRim[i] = onRim[i + 1] = onRim[i + columns] = onRim[i + columns + 1] = true;
            }
        for (int i = 0; i < keep.length; i++) {
            if (!onRim[i] || keep[i] < 0 || holeRadius == 0) continue;
            int c = i % columns, r = i / columns;
            if (c == 0 || c == columns - 1 || r == 0 || r == rows - 1) continue; // the outer edge stays straight
            double ux = x[3 * keep[i]] - cx, uy = x[3 * keep[i] + 1] - cy, d = Math.sqrt(ux * ux + uy * uy);
            if (d - holeRadius > 0.5 * Math.min(dx, dy)) continue;
            x[3 * keep[i]] = cx + ux * holeRadius / d;
            x[3 * keep[i] + 1] = cy + uy * holeRadius / d;
        }
        int quads = 0;
        for (boolean q : quad) if (q) quads++;
        int[][] faces = new int[quads][];
        int[] tris = new int[6 * quads];
        int k = 0, t = 0;
        for (int r = 0; r + 1 < rows; r++)
            for (int c = 0; c + 1 < columns; c++) {
                if (!quad[r * (columns - 1) + c]) continue;
                int i = r * columns + c;
                int a = keep[i], b = keep[i + columns], d = keep[i + columns + 1], e = keep[i + 1];
                faces[k++] = new int[] {a, b, d, e};
                if (((r + c) & 1) == 0) { tris[t++] = a; tris[t++] = b; tris[t++] = e; tris[t++] = e; tris[t++] = b; tris[t++] = d; }
                else { tris[t++] = a; tris[t++] = b; tris[t++] = d; tris[t++] = a; tris[t++] = d; tris[t++] = e; }
            }
        Map<String, int[]> groups = new LinkedHashMap<>();
        groups.put("hoist", column(keep, columns, rows, 0));
        groups.put("fly", column(keep, columns, rows, columns - 1));
        return ClothMesh.of(x, faces, tris, null, groups);
    }

    private static int[] column(int[] keep, int columns, int rows, int c) {
        return java.util.stream.IntStream.range(0, rows).map(r -> keep[r * columns + c]).filter(v -> v >= 0).toArray();
    }
}
