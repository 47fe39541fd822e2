package xpbdcloth.sketch;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;
import xpbdcloth.mesh.VertexNormals;

/** The fold darkening: a flat sheet is fully lit, a valley is darker on its hollow side only. */
class FoldShadingTest {

    /** A 3 × 3 grid of unit squares in the xz plane (normal +y), centre vertex 4 lifted by h. */
    static double[] grid(double h) {
        double[] x = new double[27];
        for (int i = 0; i < 9; i++) { x[3 * i] = i % 3; x[3 * i + 2] = -(i / 3); }
        x[3 * 4 + 1] = h;
        return x;
    }

    static final int[] TRIANGLES = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4, 3, 4, 7, 3, 7, 6, 4, 5, 8, 4, 8, 7};

    static FoldShading shade(double[] x) {
        double[] n = new double[x.length];
        VertexNormals.compute(x, TRIANGLES, n);
        FoldShading f = new FoldShading();
        f.compute(x, TRIANGLES, n);
        return f;
    }

    @Test
    void aFlatSheetIsFullyLitOnBothSides() {
        FoldShading f = shade(grid(0));
        for (int i = 0; i < 9; i++) {
            assertEquals(1f, f.front[i], "front " + i);
            assertEquals(1f, f.back[i], "back " + i);
        }
    }

    /** The centre pushed down by 0.2 of an edge: a valley seen from above (the front), a bump from below. */
    @Test
    void aValleyIsDarkerOnItsHollowSide() {
        FoldShading f = shade(grid(-0.2));
        assertTrue(f.front[4] < 0.9f && f.front[4] >= FoldShading.DARKEST, "valley floor, front: " + f.front[4]);
        assertEquals(1f, f.back[4], "the same vertex seen from the back is a ridge");
        FoldShading deep = shade(grid(-3));
        assertEquals(FoldShading.DARKEST, deep.front[4], "a deep fold is clamped at the darkest");
    }
}
