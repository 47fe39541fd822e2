package xpbdcloth.mesh;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * A 1 m square of res × res vertices lying flat at height y = 1 (x and z from −0.5 to 0.5), meshed as
 * quads or as right triangles: the same vertices as the grid cloth, so the solvers can be compared on
 * the grid and on triangulations of it. Vertex (row r, column c) is r·res + c, row 0 at z = −0.5.
 * Group "edge": row 0.
 */
public final class SquareSheet {
    private SquareSheet() {}

    /** How each cell is meshed. */
    public enum Cells {
        /** One quad (a grid: four structural edges, no diagonal). */
        QUADS,
        /** Two triangles split along the same diagonal everywhere. */
        DIAGONAL,
        /** Two triangles, the diagonal alternating from cell to cell (a "union jack" pattern). */
        ALTERNATING
    }

    public static ClothMesh generate(int res, Cells cells) {
        if (res < 2 || res > 1024) throw new IllegalArgumentException("res must be in [2, 1024], was " + res);
        double[] x = new double[3 * res * res];
        double h = 1.0 / (res - 1);
        for (int r = 0; r < res; r++)
            for (int c = 0; c < res; c++) {
                int i = r * res + c;
                x[3 * i] = -0.5 + c * h;
                x[3 * i + 1] = 1;
                x[3 * i + 2] = -0.5 + r * h;
            }
        int cellCount = (res - 1) * (res - 1);
        int[][] faces = new int[cells == Cells.QUADS ? cellCount : 2 * cellCount][];
        int k = 0;
        for (int r = 0; r + 1 < res; r++)
            for (int c = 0; c + 1 < res; c++) {
                int a = r * res + c, b = a + 1, d = a + res, e = d + 1;
                if (cells == Cells.QUADS) faces[k++] = new int[] {a, b, e, d};
                else if (cells == Cells.DIAGONAL || ((r + c) & 1) == 0) { faces[k++] = new int[] {a, b, e}; faces[k++] = new int[] {a, e, d}; }
                else { faces[k++] = new int[] {a, b, d}; faces[k++] = new int[] {b, e, d}; }
            }
        int[] edge = new int[res];
        for (int c = 0; c < res; c++) edge[c] = c;
        Map<String, int[]> groups = new LinkedHashMap<>();
        groups.put("edge", edge);
        return ClothMesh.of(x, faces, null, null, groups);
    }
}
