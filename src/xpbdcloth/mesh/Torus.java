package xpbdcloth.mesh;

/**
 * A torus, the classic test surface of genus one (a hole through it: no simple inside test by direction
 * works on it, and a cloth can hang through it): the points at distance r from a circle of radius R in the
 * x-z plane about the origin, as {@code segments} × {@code sides} quads split into triangles, wound outwards.
 * Generated, so its provenance is this code.
 */
public final class Torus {
    private Torus() {}

    public static ClothMesh generate(double majorRadius, double minorRadius, int segments, int sides) {
        if (!(minorRadius > 0 && minorRadius < majorRadius)) throw new IllegalArgumentException("minorRadius must be in (0, majorRadius), was " + minorRadius);
        if (segments < 3 || sides < 3) throw new IllegalArgumentException("segments and sides must be at least 3, were " + segments + " and " + sides);
        double[] p = new double[3 * segments * sides];
        for (int i = 0; i < segments; i++)
            for (int j = 0; j < sides; j++) {
                double u = 2 * Math.PI * i / segments, v = 2 * Math.PI * j / sides, ring = majorRadius + minorRadius * Math.cos(v);
                int k = 3 * (i * sides + j);
                p[k] = ring * Math.cos(u); p[k + 1] = minorRadius * Math.sin(v); p[k + 2] = ring * Math.sin(u);
            }
        int[][] faces = new int[2 * segments * sides][];
        int f = 0;
        for (int i = 0; i < segments; i++)
            for (int j = 0; j < sides; j++) {
                int a = i * sides + j, b = ((i + 1) % segments) * sides + j, c = ((i + 1) % segments) * sides + (j + 1) % sides, d = i * sides + (j + 1) % sides;
                // (∂/∂v) × (∂/∂u) points away from the tube's core: a → d → c and a → c → b.
                faces[f++] = new int[] {a, d, c};
                faces[f++] = new int[] {a, c, b};
            }
        return ClothMesh.of(p, faces, null, null, null);
    }
}
