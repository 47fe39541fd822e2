package xpbdcloth.mesh;

import static org.junit.jupiter.api.Assertions.*;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** The count of triangles passing through each other: right on known cases, and equal to brute force. */
class TriangleIntersectionsTest {
    @Test
    void knownPairs() {
        // A triangle in z = 0, and one standing through it, piercing it.
        double[] x = {-1, -1, 0, 1, -1, 0, 0, 1, 0, 0, 0, -1, 0, 0.2, 1, 0.1, -0.5, 1};
        assertEquals(1, TriangleIntersections.count(x, new int[] {0, 1, 2, 3, 4, 5}));
        // The same standing triangle lifted above the first: apart.
        double[] y = x.clone();
        for (int k = 9; k < 18; k += 3) y[k + 2] += 2.5;
        assertEquals(0, TriangleIntersections.count(y, new int[] {0, 1, 2, 3, 4, 5}));
        // Sharing a vertex, folded through each other: neighbours are not counted.
        assertEquals(0, TriangleIntersections.count(x, new int[] {0, 1, 2, 2, 4, 5}));
    }

    /** A 10 × 10 sheet: flat, 0; folded so that its right half passes through its left half, counted. */
    @Test
    void aSheetFoldedThroughItself() {
        int n = 10;
        double[] x = new double[3 * n * n];
        int[] t = new int[6 * (n - 1) * (n - 1)];
        int k = 0;
        for (int r = 0; r < n; r++) for (int c = 0; c < n; c++) { x[3 * (r * n + c)] = c; x[3 * (r * n + c) + 1] = r; }
        for (int r = 0; r + 1 < n; r++)
            for (int c = 0; c + 1 < n; c++) {
                int a = r * n + c;
                t[k++] = a; t[k++] = a + 1; t[k++] = a + n + 1;
                t[k++] = a; t[k++] = a + n + 1; t[k++] = a + n;
            }
        assertEquals(0, TriangleIntersections.count(x, t));
        // Fold the columns past 4 back over the left half, tilted so they cut through it.
        for (int r = 0; r < n; r++)
            for (int c = 5; c < n; c++) {
                int i = 3 * (r * n + c);
                x[i] = 9 - c;
                x[i + 2] = 0.6 - 0.3 * (c - 5) + 0.05 * r;
            }
        int crossing = TriangleIntersections.count(x, t);
        System.out.println("sheet folded through itself: " + crossing + " crossing triangle pairs");
        assertTrue(crossing > 10, "the fold's triangles cross the sheet: " + crossing);
    }

    /** Random triangles: the grid's candidates miss no crossing pair that a brute-force count finds. */
    @Test
    void agreesWithBruteForce() {
        Random r = new Random(7);
        int n = 300;
        double[] x = new double[9 * n];
        int[] t = new int[3 * n];
        for (int i = 0; i < n; i++) {
            double cx = 4 * r.nextDouble(), cy = 4 * r.nextDouble(), cz = 4 * r.nextDouble();
            for (int v = 0; v < 3; v++) {
                x[9 * i + 3 * v] = cx + 0.6 * r.nextGaussian();
                x[9 * i + 3 * v + 1] = cy + 0.6 * r.nextGaussian();
                x[9 * i + 3 * v + 2] = cz + 0.6 * r.nextGaussian();
                t[3 * i + v] = 3 * i + v;
            }
        }
        int brute = 0;
        for (int i = 0; i < n; i++) for (int j = i + 1; j < n; j++) if (TriangleIntersections.intersect(x, t, i, j)) brute++;
        assertTrue(brute > 50, "a soup with crossings: " + brute);
        assertEquals(brute, TriangleIntersections.count(x, t));
    }
}
