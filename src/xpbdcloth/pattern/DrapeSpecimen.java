package xpbdcloth.pattern;

import java.util.LinkedHashMap;
import java.util.Map;
import xpbdcloth.mesh.ClothMesh;

/**
 * The specimen of Cusick's drape test: a flat circle of fabric of radius R (G. E. Cusick, "The measurement
 * of fabric drape", J. Textile Institute 59, 1968; BS 5058: R = 15 cm on a support disc of r = 9 cm), lying
 * in the x–z plane about the origin, meshed as the patterns are ({@link PanelMesher}) with a ring of vertices
 * exactly on the support's edge, so the clamp holds the fabric up to r and not to a ragged line near it.
 * Texture coordinates are the fabric's own (u along the warp, +x); groups "clamp" (the vertices within r)
 * and "hem" (the outline's).
 */
public final class DrapeSpecimen {
    private DrapeSpecimen() {}

    public static ClothMesh generate(double radius, double supportRadius, double edge) {
        if (!(radius > 0) || !Double.isFinite(radius)) throw new IllegalArgumentException("radius must be > 0, was " + radius);
        if (!(supportRadius > 0 && supportRadius < radius)) throw new IllegalArgumentException("supportRadius must be in (0, radius " + radius + "), was " + supportRadius);
        if (!(edge >= radius / 200 && edge <= (radius - supportRadius) / 2))
            throw new IllegalArgumentException("edge must be in [" + radius / 200 + ", " + (radius - supportRadius) / 2 + "] m (at least two edges across the overhang), was " + edge);
        double[] outline = circle(radius, edge), ring = circle(supportRadius, edge);
        PanelMesher.Result m = PanelMesher.mesh(outline, ring, edge);
        int n = m.pointCount(), hemCount = outline.length / 2;
        double[] x = new double[3 * n];
        int clampCount = 0;
        for (int i = 0; i < n; i++) {
            double px = m.points[2 * i], py = m.points[2 * i + 1];
            // Pattern y → −z: counter-clockwise in the pattern stays counter-clockwise seen from +y.
            x[3 * i] = px; x[3 * i + 2] = -py + 0.0;
            if (Math.hypot(px, py) <= supportRadius * (1 + 1e-9)) clampCount++;
        }
        int[] clamp = new int[clampCount], hem = new int[hemCount];
        for (int i = 0, k = 0; i < n; i++) if (Math.hypot(m.points[2 * i], m.points[2 * i + 1]) <= supportRadius * (1 + 1e-9)) clamp[k++] = i;
        for (int i = 0; i < hemCount; i++) hem[i] = i;
        int[][] faces = new int[m.triangles.length / 3][];
        double[][] uvs = new double[faces.length][];
        for (int t = 0; t < faces.length; t++) {
            faces[t] = new int[] {m.triangles[3 * t], m.triangles[3 * t + 1], m.triangles[3 * t + 2]};
            uvs[t] = new double[6];
            for (int c = 0; c < 3; c++) { uvs[t][2 * c] = m.points[2 * faces[t][c]]; uvs[t][2 * c + 1] = m.points[2 * faces[t][c] + 1]; }
        }
        Map<String, int[]> groups = new LinkedHashMap<>();
        groups.put("clamp", clamp);
        groups.put("hem", hem);
        return ClothMesh.withTextureCoordinates(x, faces, uvs, null, groups);
    }

    /** A circle as the patterns' outlines are drawn (two half-circle arcs), sampled as near {@code edge} apart as a whole number of points allows. */
    private static double[] circle(double radius, double edge) {
        double[] east = {radius, 0}, west = {-radius, 0};
        Outline circle = new Outline(new double[][] {east, west}, new Curve[] {Curve.arc(east, west, radius), Curve.arc(west, east, radius)});
        return circle.samples(Math.max(8, (int) Math.round(circle.length() / edge)));
    }
}
