package xpbdcloth.mesh;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * A pillow: two square panels, width w, sewn together along their four sides (the sides' vertices are shared,
 * so the surface is closed), lying in the x-z plane about the origin. Each panel is a grid of n × n cells
 * puffed away from the other by h·sin(πs)·sin(πt) (s, t the panel's coordinates in [0, 1]), the shape a
 * filled pillow's panels take, so it encloses about 0.81·h·w² (2h·w²·(2/π)²). Wound outwards; texture
 * coordinates (u, v) = (s, t) on both panels, so a fabric's warp runs along x. Group "seam": the sewn sides.
 * Generated, so its provenance is this code.
 */
public final class Pillow {
    private Pillow() {}

    public static ClothMesh generate(double width, double puff, int cells) {
        if (!(width > 0 && width < 1e3)) throw new IllegalArgumentException("width must be in (0, 1000) m, was " + width);
        if (!(puff > 0 && puff <= width)) throw new IllegalArgumentException("puff must be in (0, width], was " + puff);
        if (cells < 2 || cells > 1024) throw new IllegalArgumentException("cells must be in [2, 1024], was " + cells);
        int n = cells, side = n + 1, top = side * side, inner = (n - 1) * (n - 1);
        double[] p = new double[3 * (top + inner)];
        int[][] index = new int[2][top];
        int next = 0;
        for (int panel = 0; panel < 2; panel++)
            for (int i = 0; i <= n; i++)
                for (int j = 0; j <= n; j++) {
                    boolean seam = i == 0 || j == 0 || i == n || j == n;
                    if (panel == 1 && seam) { index[1][i * side + j] = index[0][i * side + j]; continue; }
                    double s = i / (double) n, t = j / (double) n, lift = seam ? 0 : puff * Math.sin(Math.PI * s) * Math.sin(Math.PI * t);
                    int k = next++;
                    index[panel][i * side + j] = k;
                    p[3 * k] = width * (s - 0.5); p[3 * k + 1] = panel == 0 ? lift : -lift; p[3 * k + 2] = width * (t - 0.5);
                }
        int[][] faces = new int[4 * n * n][];
        double[][] uv = new double[faces.length][];
        int f = 0;
        for (int panel = 0; panel < 2; panel++)
            for (int i = 0; i < n; i++)
                for (int j = 0; j < n; j++) {
                    int a = index[panel][i * side + j], b = index[panel][(i + 1) * side + j];
                    int c = index[panel][(i + 1) * side + j + 1], d = index[panel][i * side + j + 1];
                    double s0 = i / (double) n, s1 = (i + 1) / (double) n, t0 = j / (double) n, t1 = (j + 1) / (double) n;
                    double[] ua = {s0, t0}, ub = {s1, t0}, uc = {s1, t1}, ud = {s0, t1};
                    // The diagonal a–c, except where it would join two seam vertices (two corner cells), which both
                    // panels would then share: there b–d.
                    boolean acOnSeam = (i == 0 || j == 0) && (i + 1 == n || j + 1 == n);
                    int[][] tris = acOnSeam ? new int[][] {{a, b, d}, {b, c, d}} : new int[][] {{a, b, c}, {a, c, d}};
                    double[][][] uvs = acOnSeam ? new double[][][] {{ua, ub, ud}, {ub, uc, ud}} : new double[][][] {{ua, ub, uc}, {ua, uc, ud}};
                    // +x × +z points down: the bottom panel keeps that turn, the top turns each triangle round.
                    for (int k = 0; k < 2; k++) {
                        int[] tri = tris[k];
                        double[][] tuv = uvs[k];
                        int second = panel == 0 ? 2 : 1, third = panel == 0 ? 1 : 2;
                        faces[f] = new int[] {tri[0], tri[second], tri[third]};
                        uv[f++] = new double[] {tuv[0][0], tuv[0][1], tuv[second][0], tuv[second][1], tuv[third][0], tuv[third][1]};
                    }
                }
        int[] seam = new int[4 * n];
        int k = 0;
        for (int i = 0; i < n; i++) {
            seam[k++] = index[0][i * side]; seam[k++] = index[0][n * side + i];
            seam[k++] = index[0][(n - i) * side + n]; seam[k++] = index[0][(n - i)];
        }
        Map<String, int[]> groups = new LinkedHashMap<>();
        groups.put("seam", seam);
        return ClothMesh.withTextureCoordinates(p, faces, uv, null, groups);
    }
}
