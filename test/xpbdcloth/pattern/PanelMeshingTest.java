package xpbdcloth.pattern;

import static org.junit.jupiter.api.Assertions.*;

import java.util.HashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * A panel's triangulation is a quality mesh of exactly its outline: every angle at least 20°, every triangle's
 * size within ±30 % of the target, the triangles tiling the sampled outline with no gap or overlap (their
 * signed areas sum to the outline polygon's, each outline segment on one triangle, each inside edge on two).
 */
class PanelMeshingTest {
    static final double EDGE = 0.025;

    @Test
    void straightArcAndBezierOutlinesMeshWithinTheQualityBounds() {
        for (Outline o : new Outline[] {Patterns.rectangle(0.5, 0.4), Patterns.disc(0.2), Patterns.shirtBody(),
                Patterns.rectangle(0.6, 0.05), Patterns.polygon(0, 0, 0.4, 0, 0.4, 0.3, 0.2, 0.1, 0, 0.3)}) {
            PatternMesh m = PatternMesh.of(Patterns.single(Patterns.panel("p", o)), EDGE);
            MeshQuality q = MeshQuality.ofPanel(m, 0);
            assertTrue(q.smallestAngle >= 20, "smallest angle " + q);
            assertTrue(q.smallestSize >= 0.7 && q.largestSize <= 1.3, "sizes " + q);
            assertTiles(m);
        }
    }

    /** The triangles' signed areas add up to the sampled outline's, outline edges are used once and inside ones twice. */
    static void assertTiles(PatternMesh m) {
        double[] xy = m.flatPositions();
        int[] t = m.triangles();
        Map<Long, Integer> uses = new HashMap<>();
        double area = 0;
        for (int i = 0; i < t.length; i += 3) {
            int a = t[i], b = t[i + 1], c = t[i + 2];
            double twice = (xy[2 * b] - xy[2 * a]) * (xy[2 * c + 1] - xy[2 * a + 1]) - (xy[2 * c] - xy[2 * a]) * (xy[2 * b + 1] - xy[2 * a + 1]);
            assertTrue(twice > 0, "triangle " + i / 3 + " is counter-clockwise in its pattern plane");
            area += twice / 2;
            for (int k = 0; k < 3; k++) uses.merge(key(t[i + k], t[i + (k + 1) % 3]), 1, Integer::sum);
        }
        // The outline: edges used once form one closed loop per panel, and its shoelace area is the triangles'.
        Map<Integer, Integer> next = new HashMap<>();
        for (int i = 0; i < t.length; i += 3)
            for (int k = 0; k < 3; k++) {
                int a = t[i + k], b = t[i + (k + 1) % 3];
                int n = uses.get(key(a, b));
                assertTrue(n == 1 || n == 2, "edge " + a + "–" + b + " is used by " + n + " triangles");
                if (n == 1) assertNull(next.put(a, b), "the outline passes vertex " + a + " once");
            }
        double outline = 0;
        for (Map.Entry<Integer, Integer> e : next.entrySet()) {
            int a = e.getKey(), b = e.getValue();
            outline += (xy[2 * a] * xy[2 * b + 1] - xy[2 * b] * xy[2 * a + 1]) / 2;
        }
        assertEquals(outline, area, 1e-12, "the triangles cover the outline exactly");
        int edges = uses.size(), vertices = m.vertexCount(), faces = t.length / 3;
        assertEquals(m.pattern.panels().size(), vertices - edges + faces, "each panel is a disc (Euler characteristic 1)");
    }

    static long key(int a, int b) { return (long) Math.min(a, b) << 32 | Math.max(a, b); }

    @Test
    void curvedEdgesHaveTheirClosedFormLengthsAndAreas() {
        double r = 0.2;
        Outline disc = Patterns.disc(r);
        assertEquals(2 * Math.PI * r, disc.length(), 1e-12);
        // 128 chords of a circle enclose (n/2) r² sin(2π/n).
        assertEquals(64 * r * r * Math.sin(2 * Math.PI / 128), disc.area(), 1e-12);
        double[] p = new double[2];
        disc.pointAt(disc.length() / 4, p);
        assertArrayEquals(new double[] {0, -r}, p, 1e-12, "a quarter of the way round from (−r, 0), counter-clockwise, is the bottom");
        // Twelve samples at equal arc lengths: on the circle, from corner 0, each a chord 2r sin(π/12) from the next.
        double[] twelve = disc.samples(12);
        assertArrayEquals(new double[] {-r, 0}, new double[] {twelve[0], twelve[1]}, 1e-15);
        for (int i = 0; i < 12; i++) {
            int j = (i + 1) % 12;
            assertEquals(r, Math.hypot(twelve[2 * i], twelve[2 * i + 1]), 1e-15);
            assertEquals(2 * r * Math.sin(Math.PI / 12), Math.hypot(twelve[2 * j] - twelve[2 * i], twelve[2 * j + 1] - twelve[2 * i + 1]), 1e-15);
        }
        assertTrue(disc.counterClockwise());
        assertThrows(IllegalArgumentException.class, () -> disc.samples(2));
        // A major arc: a chord of 2 bulging 1.5 is an arc of radius (1 + 2.25)/3 round more than half its circle.
        Curve major = Curve.arc(new double[] {0, 0}, new double[] {2, 0}, 1.5);
        double radius = 3.25 / 3, half = Math.asin(1 / radius);
        assertEquals(radius * (2 * Math.PI - 2 * half), major.length(), 1e-12);
        major.point(0.5, p);
        assertArrayEquals(new double[] {1, -1.5}, p, 1e-12, "its middle is 1.5 right of travel");
        // A Bézier curve with its controls on the chord at thirds is the straight line, traversed uniformly.
        Curve straight = Curve.bezier(new double[] {0, 0}, new double[] {1, 1}, new double[] {2, 2}, new double[] {3, 3});
        assertEquals(3 * Math.sqrt(2), straight.length(), 1e-12);
        straight.point(0.3, p);
        assertArrayEquals(new double[] {0.9, 0.9}, p, 1e-9);
        // A quarter circle's Bézier (controls at k = 4(√2 − 1)/3) is within 2.7e-4 of the circle in radius.
        double k = 4 * (Math.sqrt(2) - 1) / 3;
        Curve quarter = Curve.bezier(new double[] {1, 0}, new double[] {1, k}, new double[] {k, 1}, new double[] {0, 1});
        assertEquals(Math.PI / 2, quarter.length(), 2.7e-4 * Math.PI / 2);
        for (double s = 0; s <= 1; s += 0.125) {
            quarter.point(s, p);
            assertEquals(1, Math.hypot(p[0], p[1]), 2.8e-4);
        }
    }
}
