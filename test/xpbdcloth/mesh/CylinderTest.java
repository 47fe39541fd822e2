package xpbdcloth.mesh;

import static org.junit.jupiter.api.Assertions.*;

import java.util.HashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The pedestal is closed (every edge on two triangles, once each way) and wound outwards (its signed volume is the prism's). */
class CylinderTest {
    @Test
    void closedAndWoundOutwards() {
        int n = 64;
        double r = 0.09, h = 0.5;
        ClothMesh m = Cylinder.generate(r, h, n);
        double[] x = m.positions();
        int[] t = m.triangles();
        Map<Long, Integer> directed = new HashMap<>();
        double volume = 0;
        for (int i = 0; i < t.length; i += 3) {
            for (int k = 0; k < 3; k++) assertNull(directed.put((long) t[i + k] << 32 | t[i + (k + 1) % 3], i), "each directed edge once");
            int a = 3 * t[i], b = 3 * t[i + 1], c = 3 * t[i + 2];
            // Divergence theorem: V = Σ a · (b × c) / 6.
            volume += (x[a] * (x[b + 1] * x[c + 2] - x[b + 2] * x[c + 1]) - x[a + 1] * (x[b] * x[c + 2] - x[b + 2] * x[c]) + x[a + 2] * (x[b] * x[c + 1] - x[b + 1] * x[c])) / 6;
        }
        for (long e : directed.keySet()) assertTrue(directed.containsKey((e & 0xffffffffL) << 32 | e >>> 32), "every edge is shared, once each way: closed");
        assertEquals(n * r * r / 2 * Math.sin(2 * Math.PI / n) * h, volume, 1e-15, "the prism's volume, positive: wound outwards");
        assertThrows(IllegalArgumentException.class, () -> Cylinder.generate(r, h, 2));
    }
}
