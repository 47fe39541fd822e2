package xpbdcloth.pattern;

import static org.junit.jupiter.api.Assertions.*;

import java.util.List;
import org.junit.jupiter.api.Test;
import xpbdcloth.mesh.ClothMesh;

/**
 * Both sides of a seam get matching stitches: the same number, start with start and end with end, at equal
 * fractions of each side's length (so an eased side is stretched evenly), with a corner inside a stretch
 * kept as a stitch; and the panels' meshes keep their quality around them.
 */
class SeamStitchesTest {
    static final double EDGE = 0.02;

    /** Fraction of the way along a stretch of the stitch at flat position (x, y), by arc length, walking its polyline of stitches. */
    static double[] fractions(PatternMesh m, int[] stitches, int side) {
        double[] xy = m.flatPositions();
        int n = stitches.length / 2;
        double[] along = new double[n];
        for (int k = 1; k < n; k++) {
            int a = stitches[2 * (k - 1) + side], b = stitches[2 * k + side];
            along[k] = along[k - 1] + Math.hypot(xy[2 * b] - xy[2 * a], xy[2 * b + 1] - xy[2 * a + 1]);
        }
        for (int k = 0; k < n; k++) along[k] /= along[n - 1];
        return along;
    }

    @Test
    void anEasedSeamPutsEqualFractionsOnBothSidesFromStartToEnd() {
        // A gore's side (0.30 m, corner 1 to 2) eased into a shorter band's side (0.25 m, walked back from corner 3 to 2).
        Panel gore = Patterns.panel("gore", Patterns.rectangle(0.2, 0.3));
        Panel band = Patterns.panel("band", Patterns.polygon(0, 0, 0.25, 0, 0.25, 0.25, 0, 0.25));
        Seam seam = new Seam("side", new Stretch("gore", 1, 2, false), new Stretch("band", 3, 2, true));
        PatternMesh m = PatternMesh.of(new Pattern("eased", List.of(gore, band), List.of(seam)), EDGE);
        int[] s = m.stitches("side");
        assertEquals(2 * (int) Math.round(0.275 / EDGE), s.length - 2, "round(mean length / edge) segments");
        double[] xy = m.flatPositions();
        assertArrayEquals(new double[] {0.2, 0}, new double[] {xy[2 * s[0]], xy[2 * s[0] + 1]}, 1e-12, "gore starts at corner 1");
        assertArrayEquals(new double[] {0, 0.25}, new double[] {xy[2 * s[1]], xy[2 * s[1] + 1]}, 1e-12, "band starts at corner 3");
        int last = s.length - 2;
        assertArrayEquals(new double[] {0.2, 0.3}, new double[] {xy[2 * s[last]], xy[2 * s[last] + 1]}, 1e-12, "gore ends at corner 2");
        assertArrayEquals(new double[] {0.25, 0.25}, new double[] {xy[2 * s[last + 1]], xy[2 * s[last + 1] + 1]}, 1e-12, "band ends at corner 2, walked backward");
        assertArrayEquals(fractions(m, s, 0), fractions(m, s, 1), 1e-12);
        for (int p = 0; p < 2; p++) {
            MeshQuality q = MeshQuality.ofPanel(m, p);
            assertTrue(q.smallestAngle >= 20 && q.smallestSize >= 0.7 && q.largestSize <= 1.3, q.toString());
        }
        PanelMeshingTest.assertTiles(m);
    }

    @Test
    void aCornerInsideAStretchIsAStitchAndFractionalEndsLieOnTheirEdges() {
        // An L-shaped walk: from halfway along edge 0 over corner 1 to halfway up edge 1, sewn to a straight edge.
        Panel a = Patterns.panel("a", Patterns.rectangle(0.3, 0.2));
        Panel b = Patterns.panel("b", Patterns.rectangle(0.25, 0.1));
        Seam seam = new Seam("l", new Stretch("a", 0.5, 1.5, false), new Stretch("b", 1, 0, true));
        PatternMesh m = PatternMesh.of(new Pattern("corner", List.of(a, b), List.of(seam)), EDGE);
        int[] s = m.stitches("l");
        double[] xy = m.flatPositions();
        assertArrayEquals(new double[] {0.15, 0}, new double[] {xy[2 * s[0]], xy[2 * s[0] + 1]}, 1e-12);
        assertArrayEquals(new double[] {0.3, 0.1}, new double[] {xy[2 * s[s.length - 2]], xy[2 * s[s.length - 2] + 1]}, 1e-12);
        boolean corner = false;
        for (int k = 0; k < s.length; k += 2) corner |= xy[2 * s[k]] == 0.3 && xy[2 * s[k] + 1] == 0;
        assertTrue(corner, "corner 1 of a, at (0.3, 0), is a stitch");
        // The straight side takes the corner's fraction (0.15 of 0.25 m) too: fractions match on both sides.
        assertArrayEquals(fractions(m, s, 0), fractions(m, s, 1), 1e-12);
    }

    @Test
    void theClothMeshKeepsEveryTriangleTheFabricCoordinatesAndTheGroups() {
        Panel gore = new Panel("gore", Patterns.rectangle(0.2, 0.3), new double[] {1, 1}, "denim", Placement.IDENTITY);
        Panel band = Patterns.panel("band", Patterns.rectangle(0.25, 0.25));
        Seam seam = new Seam("side", new Stretch("gore", 1, 2, false), new Stretch("band", 3, 2, true));
        PatternMesh m = PatternMesh.of(new Pattern("eased", List.of(gore, band), List.of(seam)), EDGE);
        ClothMesh c = m.toClothMesh();
        assertArrayEquals(m.triangles(), c.triangles());
        double[] uv = c.triangleUVs(), xy = m.flatPositions();
        int[] t = m.triangles();
        int goreEnd = m.panelTriangleRange(0)[1];
        for (int i = 0; i < t.length; i++) {
            double x = xy[2 * t[i]], y = xy[2 * t[i] + 1];
            // The gore is cut on the bias (grain at 45°): u = (x + y)/√2, v = (y − x)/√2; the band on the straight grain (0, 1).
            double u = i / 3 < goreEnd ? (x + y) / Math.sqrt(2) : y, v = i / 3 < goreEnd ? (y - x) / Math.sqrt(2) : -x;
            assertEquals(u, uv[2 * i], 1e-12);
            assertEquals(v, uv[2 * i + 1], 1e-12);
        }
        assertEquals(m.panelVertexRange(0)[1] - m.panelVertexRange(0)[0], c.group("gore").length);
        assertEquals(m.stitches("side").length, c.group("seam_side").length);
    }

    @Test
    void aWrappedPanelLiesOnItsCylinderWithNothingStretchedAlongIt() {
        double r = 0.15;
        Placement around = new Placement(new double[] {0, 1, r}, new double[] {0, 0, 0}, r);
        PatternMesh m = PatternMesh.of(Patterns.single(Patterns.panel("front", Patterns.rectangle(0.3, 0.2), around)), EDGE);
        double[] p = m.positions(), xy = m.flatPositions();
        for (int i = 0; i < m.vertexCount(); i++) {
            // The axis is vertical through (0, ·, 0): the panel's centre went to z = r, the axis r behind it.
            assertEquals(r, Math.hypot(p[3 * i], p[3 * i + 2]), 1e-12, "on the cylinder");
            assertEquals(1 + xy[2 * i + 1] - 0.1, p[3 * i + 1], 1e-12, "heights kept");
            assertEquals((xy[2 * i] - 0.15) / r, Math.atan2(p[3 * i], p[3 * i + 2]), 1e-12, "x is arc length round the axis");
        }
    }

    /**
     * A sleeve round an arm slanted 45° out and down: wrapped round the axis (−1, 1, 0) through c, every vertex
     * lies r from the axis, at y − cy along it, and at the angle 90° + (x − cx)/r from the front (+z) towards the
     * side, side = axis × front, here (1, 1, 0)/√2, the top of a right arm; the pattern's y (the grain) runs
     * along the axis. A vertical axis is the three-argument placement, bit for bit.
     */
    @Test
    void aPanelWrappedRoundASlantedAxisLiesOnItsTube() {
        double r = 0.06, s = Math.sqrt(0.5);
        double[] c = {0.31, 1.28, 0}, axis = {-s, s, 0}, side = {s, s, 0}, front = {0, 0, 1};
        Placement sleeve = Placement.around(c, new double[] {r, r}, 90, new double[] {-1, 1, 0});
        PatternMesh m = PatternMesh.of(Patterns.single(Patterns.panel("sleeve", Patterns.rectangle(0.3, 0.2), sleeve)), EDGE);
        double[] p = m.positions(), xy = m.flatPositions();
        for (int i = 0; i < m.vertexCount(); i++) {
            double[] d = {p[3 * i] - c[0], p[3 * i + 1] - c[1], p[3 * i + 2] - c[2]};
            double along = dot(d, axis), across = dot(d, side), out = dot(d, front);
            assertEquals(xy[2 * i + 1] - 0.1, along, 1e-12, "along the axis");
            assertEquals(r, Math.hypot(across, out), 1e-12, "on the tube");
            // (to 1e-6: the placement reads arc length off a table of 4096 chords round the ellipse)
            double angle = Math.toRadians(90) + (xy[2 * i] - 0.15) / r;
            assertEquals(Math.sin(angle), across / r, 1e-6, "arc length round the axis (side)");
            assertEquals(Math.cos(angle), out / r, 1e-6, "arc length round the axis (front)");
        }
        double[] o = new double[6];
        sleeve.place(0.1, 0.05, 0.15, 0.1, 0, 1, o);
        assertArrayEquals(axis, new double[] {o[3], o[4], o[5]}, 1e-15, "the grain runs along the axis");
        double[] v1 = new double[6], v2 = new double[6];
        double[] centre = {0.02, 0.9, -0.01}, radii = {0.2, 0.13};
        for (double x = 0; x <= 0.6; x += 0.05) {
            Placement.around(centre, radii, 35).place(x, 0.3 * x, 0.25, 0.1, 0.6, 0.8, v1);
            Placement.around(centre, radii, 35, new double[] {0, 2, 0}).place(x, 0.3 * x, 0.25, 0.1, 0.6, 0.8, v2);
            assertArrayEquals(v1, v2, "vertical axis at x = " + x);
        }
    }

    private static double dot(double[] a, double[] b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

    @Test
    void badPatternsAreRefusedNamingThePanelOrSeam() {
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new Outline(new double[][] {{0, 0}, {0.2, 0.2}, {0.2, 0}, {0, 0.2}}, bowTieEdges()))
                .getMessage().contains("crosses itself near (0.1000, 0.1000)"));
        Panel a = Patterns.panel("front", Patterns.rectangle(0.3, 0.2)), b = Patterns.panel("back", Patterns.rectangle(0.3, 0.2));
        assertEquals("seam \"side\": stretch \"front\" 1 to 4.5 runs past the outline's end (positions on panel \"front\" are 0 to 4, its corner count), was 4.5",
                refused(a, b, new Seam("side", new Stretch("front", 1, 4.5, false), new Stretch("back", 3, 2, true))));
        assertEquals("seam \"hem\": stretch \"front\" 1.5 to 2 is sewn twice (it overlaps seam \"side\")",
                refused(a, b, new Seam("side", new Stretch("front", 1, 2, false), new Stretch("back", 3, 2, true)),
                        new Seam("hem", new Stretch("front", 1.5, 2, false), new Stretch("back", 0, 1, false))));
        assertEquals("seam \"side\" sews panel \"sleeve\", which the pattern does not have (it has front, back)",
                refused(a, b, new Seam("side", new Stretch("sleeve", 1, 2, false), new Stretch("back", 3, 2, true))));
        assertEquals("seam \"side\": stretch \"back\" 2 to 2 is empty",
                refused(a, b, new Seam("side", new Stretch("front", 1, 2, false), new Stretch("back", 2, 2, false))));
        assertEquals("seam \"side\" sews the face of one panel to the back of the other (both stretches run the same way round their panels' outlines): walk one of them the other way (\"backward\")",
                refused(a, b, new Seam("side", new Stretch("front", 1, 2, false), new Stretch("back", 0, 1, false))));
        // Two seams meeting at a corner share an end, which is allowed.
        assertDoesNotThrow(() -> new Pattern("ok", List.of(a, b), List.of(new Seam("side", new Stretch("front", 1, 2, false), new Stretch("back", 3, 2, true)),
                new Seam("top", new Stretch("front", 2, 3, false), new Stretch("back", 2, 1, true)))));
        assertEquals("panel \"front\" has no fabric",
                assertThrows(IllegalArgumentException.class, () -> new Panel("front", Patterns.rectangle(0.3, 0.2), new double[] {0, 1}, "", Placement.IDENTITY)).getMessage());
        assertEquals("two panels are named \"front\"",
                assertThrows(IllegalArgumentException.class, () -> new Pattern("x", List.of(a, a), List.of())).getMessage());
    }

    static Curve[] bowTieEdges() {
        double[][] c = {{0, 0}, {0.2, 0.2}, {0.2, 0}, {0, 0.2}};
        Curve[] e = new Curve[4];
        for (int k = 0; k < 4; k++) e[k] = Curve.line(c[k], c[(k + 1) % 4]);
        return e;
    }

    static String refused(Panel a, Panel b, Seam... seams) {
        return assertThrows(IllegalArgumentException.class, () -> new Pattern("p", List.of(a, b), List.of(seams))).getMessage();
    }
}
