package xpbdcloth.mesh;

/**
 * A sphere of radius r about the origin as a closed surface to inflate: {@code slices} meridians and
 * {@code stacks} bands between the poles (a latitude–longitude sphere, two poles and stacks − 1 rings of
 * slices vertices), wound outwards. Each face carries texture coordinates u = longitude/2π and
 * v = colatitude/π, so a fabric's warp runs along the parallels (the pole's fan takes u at its middle).
 * Generated, so its provenance is this code.
 */
public final class Balloon {
    private Balloon() {}

    public static ClothMesh generate(double radius, int slices, int stacks) {
        if (!(radius > 0 && radius < 1e3)) throw new IllegalArgumentException("radius must be in (0, 1000) m, was " + radius);
        if (slices < 3 || stacks < 2 || slices > 1024 || stacks > 1024)
            throw new IllegalArgumentException("slices must be in [3, 1024] and stacks in [2, 1024], were " + slices + " and " + stacks);
        int rings = stacks - 1, north = 0, south = 1 + rings * slices;
        double[] p = new double[3 * (south + 1)];
        p[1] = radius;
        p[3 * south + 1] = -radius;
        for (int j = 1; j <= rings; j++)
            for (int i = 0; i < slices; i++) {
                double colatitude = Math.PI * j / stacks, longitude = 2 * Math.PI * i / slices, ring = radius * Math.sin(colatitude);
                int k = 3 * vertex(j, i, slices);
                p[k] = ring * Math.cos(longitude); p[k + 1] = radius * Math.cos(colatitude); p[k + 2] = ring * Math.sin(longitude);
            }
        int[][] faces = new int[2 * slices * (stacks - 1)][];
        double[][] uv = new double[faces.length][];
        int f = 0;
        for (int i = 0; i < slices; i++) {
            double u0 = i / (double) slices, u1 = (i + 1) / (double) slices, um = 0.5 * (u0 + u1), v1 = 1.0 / stacks, vn = 1 - v1;
            int a = vertex(1, i, slices), b = vertex(1, (i + 1) % slices, slices);
            // East (∂/∂u) × south (∂/∂v) points outwards: N → b → a at the north, a → b → S at the south.
            faces[f] = new int[] {north, b, a};
            uv[f++] = new double[] {um, 0, u1, v1, u0, v1};
            int c = vertex(rings, i, slices), d = vertex(rings, (i + 1) % slices, slices);
            faces[f] = new int[] {c, d, south};
            uv[f++] = new double[] {u0, vn, u1, vn, um, 1};
            for (int j = 1; j < rings; j++) {
                int q0 = vertex(j, i, slices), q1 = vertex(j, (i + 1) % slices, slices);
                int q2 = vertex(j + 1, (i + 1) % slices, slices), q3 = vertex(j + 1, i, slices);
                double va = j / (double) stacks, vb = (j + 1) / (double) stacks;
                faces[f] = new int[] {q0, q1, q2};
                uv[f++] = new double[] {u0, va, u1, va, u1, vb};
                faces[f] = new int[] {q0, q2, q3};
                uv[f++] = new double[] {u0, va, u1, vb, u0, vb};
            }
        }
        return ClothMesh.withTextureCoordinates(p, faces, uv, null, null);
    }

    private static int vertex(int ring, int slice, int slices) { return 1 + (ring - 1) * slices + slice; }
}
