package xpbdcloth.pattern;

/**
 * The quality of a flat triangle mesh against a target edge length: its angles (degrees), each triangle's
 * size (the side of the equilateral triangle of the same area) and each edge, both over the target, and
 * the signed area.
 */
public final class MeshQuality {
    public double smallestAngle = 180, largestAngle = 0;
    public double smallestSize = Double.MAX_VALUE, largestSize = 0;
    public double shortestEdge = Double.MAX_VALUE, longestEdge = 0;
    public double area;

    /** Of the i-th panel of a meshed pattern, in its pattern plane. */
    public static MeshQuality ofPanel(PatternMesh m, int panel) {
        int[] t = m.panelTriangleRange(panel);
        return new MeshQuality(m.flatPositions(), m.triangles(), t[0], t[1], m.edge);
    }

    /** Of the triangles [first, last) of a flat (x, y per vertex) mesh. */
    public MeshQuality(double[] xy, int[] triangles, int first, int last, double target) {
        for (int t = first; t < last; t++) {
            int[] v = {triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]};
            double[] len = new double[3];
            for (int k = 0; k < 3; k++) {
                int a = v[k], b = v[(k + 1) % 3];
                len[k] = Math.hypot(xy[2 * b] - xy[2 * a], xy[2 * b + 1] - xy[2 * a + 1]);
                shortestEdge = Math.min(shortestEdge, len[k] / target);
                longestEdge = Math.max(longestEdge, len[k] / target);
            }
            for (int k = 0; k < 3; k++) {
                double a = len[(k + 1) % 3], b = len[(k + 2) % 3], c = len[k];  // angle opposite c
                double angle = Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, (a * a + b * b - c * c) / (2 * a * b)))));
                smallestAngle = Math.min(smallestAngle, angle);
                largestAngle = Math.max(largestAngle, angle);
            }
            double twice = (xy[2 * v[1]] - xy[2 * v[0]]) * (xy[2 * v[2] + 1] - xy[2 * v[0] + 1])
                    - (xy[2 * v[2]] - xy[2 * v[0]]) * (xy[2 * v[1] + 1] - xy[2 * v[0] + 1]);
            area += twice / 2;
            double size = Math.sqrt(2 * Math.abs(twice) / Math.sqrt(3)) / target;
            smallestSize = Math.min(smallestSize, size);
            largestSize = Math.max(largestSize, size);
        }
    }

    @Override public String toString() {
        return String.format("angles %.1f–%.1f°, sizes %.2f–%.2f, edges %.2f–%.2f of target", smallestAngle, largestAngle, smallestSize, largestSize, shortestEdge, longestEdge);
    }
}
