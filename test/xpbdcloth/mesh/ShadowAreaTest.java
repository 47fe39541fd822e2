package xpbdcloth.mesh;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/**
 * A shadow is the area of the union of the triangles seen from above: a flat disc's is its polygon's area,
 * two layers over each other cast one shadow, a fold's overlap counts once, and a triangle seen edge on
 * casts none; wherever it lies and whichever way it is wound.
 */
class ShadowAreaTest {
    static final double CELL = 1e-4;

    @Test
    void aFlatRegularPolygonCastsItsOwnArea() {
        double r = 0.15;
        ClothMesh disc = RoundTablecloth.generate(r, 12);
        // The mesh's outer ring is a regular 72-gon: n r²/2 sin(2π/n).
        int ring = 6 * 12;
        double exact = ring * r * r / 2 * Math.sin(2 * Math.PI / ring);
        double s = ShadowArea.of(disc.positions(), disc.triangles(), CELL);
        // The grid's error is about the perimeter times half a cell, and far smaller along a smooth boundary.
        assertEquals(exact, s, 2 * Math.PI * r * CELL / 2, "a disc's shadow");
    }

    @Test
    void overlappingLayersAndFoldsCountOnce() {
        // Cell centres on the squares' diagonals may fall to neither triangle by rounding: 10 cells of slack.
        // Two unit squares, one 0.5 m higher and shifted half a square along x: their union is 1.5 m².
        double[] x = {0, 0, 0, 1, 0, 0, 1, 0, 1, 0, 0, 1, 0.5, 0.5, 0, 1.5, 0.5, 0, 1.5, 0.5, 1, 0.5, 0.5, 1};
        int[] t = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
        assertEquals(1.5, ShadowArea.of(x, t, 1e-3), 1e-5);
        // The upper square wound the other way round (seen from below, say) casts the same shadow.
        int[] flipped = {0, 1, 2, 0, 2, 3, 4, 6, 5, 4, 7, 6};
        assertEquals(1.5, ShadowArea.of(x, flipped, 1e-3), 1e-5);
        // The same square twice: one square's shadow.
        assertEquals(1.0, ShadowArea.of(x, new int[] {0, 1, 2, 0, 2, 3, 0, 2, 1, 0, 3, 2}, 1e-3), 1e-5);
    }

    @Test
    void aTriangleSeenEdgeOnCastsNoShadowAndAnyTriangleCastsItsArea() {
        double[] vertical = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        assertEquals(0, ShadowArea.of(vertical, new int[] {0, 1, 2}, 1e-3));
        // A slanted triangle casts its projection: the x–z triangle (0,0), (0.3,0.1), (0.1,0.25), area (0.3·0.25 − 0.1·0.1)/2 = 0.0325.
        double[] slanted = {2, 5, 3, 2.3, 4, 3.1, 2.1, 7, 3.25};
        assertEquals(0.0325, ShadowArea.of(slanted, new int[] {0, 1, 2}, 1e-4), 0.9 * 1e-4 / 2, "within the perimeter times half a cell");
        assertThrows(IllegalArgumentException.class, () -> ShadowArea.of(slanted, new int[] {0, 1, 2}, 0));
    }
}
