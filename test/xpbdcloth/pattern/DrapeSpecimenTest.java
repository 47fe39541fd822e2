package xpbdcloth.pattern;

import static org.junit.jupiter.api.Assertions.*;

import java.util.HashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;
import xpbdcloth.mesh.ClothMesh;

/**
 * The drape test's specimen is a quality mesh of its circle whose clamp ends exactly on the support's edge:
 * a ring of vertices at r, no triangle across it (the clamp holds the cloth to r, not to a ragged line
 * near it), the clamp group the vertices within r, the triangles tiling the sampled circle, every angle at
 * least 20° and the texture's u along +x (the warp).
 */
class DrapeSpecimenTest {
    static final double R = 0.15, SUPPORT = 0.09, EDGE = 0.0075;

    @Test
    void theClampEndsOnTheSupportsEdgeAndTheMeshTilesTheCircle() {
        ClothMesh m = DrapeSpecimen.generate(R, SUPPORT, EDGE);
        int n = m.vertexCount();
        double[] x = m.positions();
        int onRing = 0;
        for (int i = 0; i < n; i++) if (Math.abs(Math.hypot(x[3 * i], x[3 * i + 2]) - SUPPORT) < 1e-12) onRing++;
        assertEquals(Math.round(2 * Math.PI * SUPPORT / EDGE), onRing, "a ring of vertices on the support's edge, an edge apart");
        int[] clamp = m.group("clamp");
        int within = 0;
        for (int i = 0; i < n; i++) if (Math.hypot(x[3 * i], x[3 * i + 2]) <= SUPPORT * (1 + 1e-9)) within++;
        assertEquals(within, clamp.length, "the clamp holds every vertex within r");
        for (int v : clamp) assertTrue(Math.hypot(x[3 * v], x[3 * v + 2]) <= SUPPORT * (1 + 1e-9));

        int[] t = m.triangles();
        double area = 0, smallest = 180;
        Map<Long, Integer> uses = new HashMap<>();
        for (int i = 0; i < t.length; i += 3) {
            boolean inside = false, outside = false;
            for (int k = 0; k < 3; k++) {
                double rho = Math.hypot(x[3 * t[i + k]], x[3 * t[i + k] + 2]);
                inside |= rho < SUPPORT - 1e-9;
                outside |= rho > SUPPORT + 1e-9;
                int a = t[i + k], b = t[i + (k + 1) % 3];
                uses.merge((long) Math.min(a, b) << 32 | Math.max(a, b), 1, Integer::sum);
            }
            assertFalse(inside && outside, "triangle " + i / 3 + " crosses the support's edge");
            double ax = x[3 * t[i]], az = x[3 * t[i] + 2], bx = x[3 * t[i + 1]], bz = x[3 * t[i + 1] + 2], cx = x[3 * t[i + 2]], cz = x[3 * t[i + 2] + 2];
            // Counter-clockwise seen from +y: (b − a) × (c − a) has a positive y, −[(bx−ax)(cz−az) − (cx−ax)(bz−az)].
            double up = -((bx - ax) * (cz - az) - (cx - ax) * (bz - az)) / 2;
            assertTrue(up > 0, "triangle " + i / 3 + " faces up");
            area += up;
            smallest = Math.min(smallest, smallestAngle(ax, az, bx, bz, cx, cz));
        }
        int hem = m.group("hem").length;
        assertEquals(hem * R * R / 2 * Math.sin(2 * Math.PI / hem), area, 1e-12, "the triangles tile the sampled circle, a regular polygon");
        long boundary = uses.values().stream().filter(u -> u == 1).count();
        assertEquals(hem, boundary, "the only open edges are the hem's");
        assertTrue(uses.values().stream().allMatch(u -> u <= 2), "no edge is shared by three triangles");
        assertTrue(smallest >= 20, "smallest angle " + smallest + "°");

        double[] uv = m.triangleUVs();
        for (int i = 0; i < t.length; i++) {
            assertEquals(x[3 * t[i]], uv[2 * i], 1e-15, "u is x: the warp runs along +x");
            assertEquals(-x[3 * t[i] + 2], uv[2 * i + 1], 1e-15, "v is −z");
        }
    }

    @Test
    void aSpecimenTooCoarseForItsOverhangIsRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> DrapeSpecimen.generate(R, SUPPORT, 0.04));
        assertTrue(e.getMessage().contains("edge") && e.getMessage().contains("0.04"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> DrapeSpecimen.generate(R, R, EDGE));
    }

    private static double smallestAngle(double ax, double ay, double bx, double by, double cx, double cy) {
        double a = Math.hypot(bx - cx, by - cy), b = Math.hypot(ax - cx, ay - cy), c = Math.hypot(ax - bx, ay - by);
        double alpha = Math.acos((b * b + c * c - a * a) / (2 * b * c)), beta = Math.acos((a * a + c * c - b * b) / (2 * a * c));
        return Math.toDegrees(Math.min(Math.min(alpha, beta), Math.PI - alpha - beta));
    }
}
