package xpbdcloth.mesh;

import static org.junit.jupiter.api.Assertions.*;

import java.util.HashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The families' raw material, derived from two meshes that are not grids. */
class MeshTopologyTest {

    /**
     * The tablecloth is a disc of near-equilateral triangles: Euler's V − E + F = 1 for a disc; every
     * triangle's smallest angle above 40° (the lattice's is 60°); 6·rings hem edges on the boundary; the
     * centre has the lattice's three straight lines through it, and every hem vertex its ring.
     */
    @Test
    void tableclothIsADiscOfNearEquilateralTriangles() {
        int rings = 6;
        ClothMesh m = RoundTablecloth.generate(0.7, rings);
        MeshTopology t = MeshTopology.of(m);
        int v = m.vertexCount(), e = t.edges().length / 2, f = m.faceCount();
        assertEquals(1 + 3 * rings * (rings + 1), v);
        assertEquals(6 * rings * rings, f);
        assertEquals(1, v - e + f, "Euler characteristic of a disc");
        double smallest = Math.PI;
        int[] tri = m.triangles();
        for (int k = 0; k < tri.length; k += 3)
            for (int c = 0; c < 3; c++) smallest = Math.min(smallest, angle(m, tri[k + c], tri[k + (c + 1) % 3], tri[k + (c + 2) % 3]));
        assertTrue(Math.toDegrees(smallest) > 40, "smallest angle " + Math.toDegrees(smallest));
        Map<Integer, Integer> through = new HashMap<>();
        int[] runs = t.straightRuns();
        for (int k = 0; k < runs.length; k += 3) through.merge(runs[k + 1], 1, Integer::sum);
        assertEquals(3, through.get(0), "three lattice lines through the centre");
        for (int h : m.group("hem")) assertEquals(1, through.get(h), "hem vertex " + h + " bends along its ring");
        assertEquals(Math.PI * 0.49, m.area(), 0.05 * Math.PI * 0.49, "area near πr²");
    }

    static int[][] faces(ClothMesh m) {
        int[][] f = new int[m.faceCount()][];
        for (int k = 0; k < f.length; k++) f[k] = m.face(k);
        return f;
    }

    /** The angle at corner a of triangle (a, b, c). */
    static double angle(ClothMesh m, int a, int b, int c) {
        double ux = m.x(b) - m.x(a), uy = m.y(b) - m.y(a), uz = m.z(b) - m.z(a);
        double wx = m.x(c) - m.x(a), wy = m.y(c) - m.y(a), wz = m.z(c) - m.z(a);
        return Math.acos((ux * wx + uy * wy + uz * wz) / Math.sqrt((ux * ux + uy * uy + uz * uz) * (wx * wx + wy * wy + wz * wz)));
    }

    @Test
    void everyTableclothFaceFacesUp() {
        ClothMesh m = RoundTablecloth.generate(0.7, 7);
        int[] t = m.triangles();
        for (int k = 0; k < t.length; k += 3) {
            double e1x = m.x(t[k + 1]) - m.x(t[k]), e1z = m.z(t[k + 1]) - m.z(t[k]);
            double e2x = m.x(t[k + 2]) - m.x(t[k]), e2z = m.z(t[k + 2]) - m.z(t[k]);
            assertTrue(e1z * e2x - e1x * e2z > 0, "triangle " + k / 3 + " normal points up (+y)");
        }
    }

    /**
     * The flag's hole leaves a second boundary loop: every edge is a side of one face (boundary) or two.
     * The hole's boundary edges are counted from the faces and compared with the hole's own perimeter.
     */
    @Test
    void flagWithHoleHasTwoBoundaries() {
        ClothMesh m = FlagWithHole.generate(1.5, 1.0, 31, 21, 0.95, -0.45, 0.18);
        Map<Long, Integer> sideCount = new HashMap<>();
        for (int k = 0; k < m.faceCount(); k++) {
            int[] f = m.face(k);
            for (int j = 0; j < f.length; j++) {
                int a = Math.min(f[j], f[(j + 1) % f.length]), b = Math.max(f[j], f[(j + 1) % f.length]);
                sideCount.merge((long) a << 32 | b, 1, Integer::sum);
            }
        }
        int boundary = 0;
        for (int c : sideCount.values()) { assertTrue(c <= 2); if (c == 1) boundary++; }
        int outer = 2 * (30 + 20);
        assertTrue(boundary > outer + 20, "the hole adds boundary edges: " + boundary + " vs the outer " + outer);
        assertEquals(21, m.group("hoist").length);
        assertEquals(21, m.group("fly").length);
        for (int v : m.group("hoist")) assertEquals(0, m.x(v), 0.0);
        assertEquals(1.5 * 1.0 - Math.PI * 0.18 * 0.18, m.area(), 0.02, "the hole is cut out, nearly round: area " + m.area());
        // The rim's vertices were slid onto the circle: no quad folded over, in either triangulation.
        int[] alternating = m.triangles(), fan = ClothMesh.of(m.positions(), faces(m), null, null, null).triangles();
        for (int[] t : new int[][] {alternating, fan})
            for (int k = 0; k < t.length; k += 3) {
                double e1x = m.x(t[k + 1]) - m.x(t[k]), e1y = m.y(t[k + 1]) - m.y(t[k]);
                double e2x = m.x(t[k + 2]) - m.x(t[k]), e2y = m.y(t[k + 2]) - m.y(t[k]);
                assertTrue(e1x * e2y - e1y * e2x > 1e-4, "triangle " + k / 3 + " faces +z with some area");
            }
    }

    /**
     * The shortest edge is a triangle's side (a quad's fan diagonal counts: its ends are one triangle's
     * particles) or a segment, and +∞ with neither.
     */
    @Test
    void shortestEdgeIsATrianglesSideOrASegment() {
        // A 0.5 × 0.3 quad whose fan diagonal is 0.583 m, and a 0.1 m segment hanging off it.
        double[] x = {0, 0, 0, 0.5, 0, 0, 0.5, 0.3, 0, 0, 0.3, 0, 0, -0.1, 0};
        ClothMesh quad = ClothMesh.of(x, new int[][] {{0, 1, 2, 3}}, null, new int[0], null);
        assertEquals(0.3, quad.shortestEdge(), 1e-15);
        ClothMesh withTail = ClothMesh.of(x, new int[][] {{0, 1, 2, 3}}, null, new int[] {0, 4}, null);
        assertEquals(0.1, withTail.shortestEdge(), 1e-15);
        // A kite whose fan diagonal (0 to 2) is shorter than every side.
        double[] kite = {0, 0, 0, 1, -1, 0, 0.05, 0, 0, 1, 1, 0};
        assertEquals(0.05, ClothMesh.of(kite, new int[][] {{0, 1, 2, 3}}, null, new int[0], null).shortestEdge(), 1e-15);
        assertEquals(0.1, ClothMesh.polyline(new double[] {0, 0, 0, 0, 0.1, 0, 0, 0.3, 0}).shortestEdge(), 1e-15);
        assertEquals(Double.POSITIVE_INFINITY, ClothMesh.polyline(new double[] {0, 0, 0}).shortestEdge());
    }
}
