package xpbdcloth.sketch;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;
import xpbdcloth.engine.Box;
import xpbdcloth.engine.Capsule;
import xpbdcloth.engine.RigidCollider;
import xpbdcloth.engine.SpherePath;

/**
 * The drawn box and capsule are the colliders the cloth meets: every vertex on the surface, every normal
 * outward, and every triangle wound so that its own normal agrees (P3D lights a face that OpenGL finds
 * turned away with the negated normal, so a triangle wound the wrong way is drawn dark).
 */
class SolidMeshTest {
    static void assertOnSurfaceAndWoundOutward(RigidCollider solid, double surfaceTolerance, java.util.function.ToDoubleFunction<double[]> distance) {
        SolidMesh m = new SolidMesh(solid);
        m.place();
        double[] x = m.world, n = m.normals;
        for (int k = 0; k < x.length; k += 3)
            assertEquals(0, distance.applyAsDouble(new double[] {x[k], x[k + 1], x[k + 2]}), surfaceTolerance, "vertex " + k / 3 + " on the surface");
        for (int t = 0; t < m.triangles.length; t += 3) {
            int a = 3 * m.triangles[t], b = 3 * m.triangles[t + 1], c = 3 * m.triangles[t + 2];
            double e1x = x[b] - x[a], e1y = x[b + 1] - x[a + 1], e1z = x[b + 2] - x[a + 2];
            double e2x = x[c] - x[a], e2y = x[c + 1] - x[a + 1], e2z = x[c + 2] - x[a + 2];
            double gx = e1y * e2z - e1z * e2y, gy = e1z * e2x - e1x * e2z, gz = e1x * e2y - e1y * e2x;
            double area2 = Math.sqrt(gx * gx + gy * gy + gz * gz);
            if (area2 < 1e-12) continue; // a pole's sliver
            for (int v : new int[] {a, b, c})
                assertTrue(gx * n[v] + gy * n[v + 1] + gz * n[v + 2] > 0, "triangle " + t / 3 + " wound against its normals");
        }
    }

    @Test
    void aTurnedBoxIsDrawnOnItsSurfaceWoundOutward() {
        Box box = new Box(SpherePath.fixed(0.1, 0.4, -0.2), new double[] {0.3, 0.2, 0.1}, new double[] {10, 30, 50}, 0, 0.5, 0.4);
        double[] r = new double[9];
        box.rotation(r);
        assertOnSurfaceAndWoundOutward(box, 1e-12, p -> {
            double dx = p[0] - 0.1, dy = p[1] - 0.4, dz = p[2] + 0.2;
            double qx = r[0] * dx + r[3] * dy + r[6] * dz, qy = r[1] * dx + r[4] * dy + r[7] * dz, qz = r[2] * dx + r[5] * dy + r[8] * dz;
            return Math.max(Math.abs(qx) - 0.3, Math.max(Math.abs(qy) - 0.2, Math.abs(qz) - 0.1));
        });
    }

    @Test
    void aCapsuleIsDrawnOnItsSurfaceWoundOutward() {
        Capsule c = new Capsule(SpherePath.fixed(0, 1, 0), new double[] {1, 1, 0}, 0.25, 0.05, 0, 0.5, 0.4);
        double s = Math.sqrt(0.5);
        assertOnSurfaceAndWoundOutward(c, 1e-12, p -> {
            double t = Math.max(-0.25, Math.min(0.25, s * p[0] + s * (p[1] - 1)));
            return Math.sqrt(Math.pow(p[0] - t * s, 2) + Math.pow(p[1] - 1 - t * s, 2) + p[2] * p[2]) - 0.05;
        });
    }
}
