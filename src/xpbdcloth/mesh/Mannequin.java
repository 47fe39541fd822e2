package xpbdcloth.mesh;

import java.util.ArrayList;
import java.util.List;

/**
 * A dress form to drape cloth on, generated, so its provenance is this code: a standing figure 1.78 m
 * tall, y up, facing +z, feet on y = 0. Seven closed surfaces overlap where a body's parts join: a torso of
 * revolution with elliptical sections (hips 33 cm wide, waist 28, chest 34, shoulders 38), a neck, a head,
 * two arms and two legs as capsules. Every part is closed and wound outwards, so the whole mesh is closed
 * and a collider knows its inside. The arms hang from the shoulder joints at an angle from the vertical;
 * {@link #turning} gives the same triangles turning on the spot, frame by frame.
 */
public final class Mannequin {
    private Mannequin() {}

    /** The shoulder joints' height and distance from the middle, m, and the arms' length and radius. */
    static final double SHOULDER_Y = 1.40, SHOULDER_X = 0.19, ARM_LENGTH = 0.56, ARM_RADIUS = 0.042;

    /** Torso profile: height, half width (x) and half depth (z) of its elliptical section; the ends are poles. */
    private static final double[][] TORSO = {
        {0.84, 0, 0}, {0.86, 0.12, 0.08}, {0.90, 0.165, 0.105}, {1.00, 0.16, 0.10}, {1.08, 0.14, 0.09}, {1.18, 0.155, 0.105},
        {1.28, 0.17, 0.11}, {1.35, 0.185, 0.105}, {1.40, 0.19, 0.095}, {1.44, 0.16, 0.08}, {1.47, 0.10, 0.06}, {1.485, 0, 0},
    };

    /** The figure with its arms at {@code armDegrees} from hanging straight down, outwards. */
    public static ClothMesh generate(double armDegrees) {
        Builder b = new Builder();
        b.torso();
        b.capsule(new double[] {0, 1.43, 0}, new double[] {0, 1.58, 0}, 0.05, 16, 4);
        b.ellipsoid(new double[] {0, 1.68, 0.01}, new double[] {0.085, 0.11, 0.10}, 24, 14);
        for (int side = -1; side <= 1; side += 2) b.arm(side, armDegrees);
        for (int side = -1; side <= 1; side += 2)
            b.capsule(new double[] {side * 0.09, 0.88, 0}, new double[] {side * 0.10, 0.08, 0.01}, 0.065, 16, 4);
        return b.mesh();
    }

    /**
     * The figure with its arms at {@code armDegrees} turning on the spot, {@code turnDegrees} to its left and to
     * its right and back, in {@code frames} frames (a loop: the frame after the last is the first): vertex
     * positions per frame, the triangles of {@link #generate}'s mesh. A turn and not a raising of the arms: an
     * arm closing on the torso, or rising against the shoulder, pinches cloth between two overlapping parts of
     * the body, which the contact cannot yet resolve (docs/contacts.md).
     */
    public static double[][] turning(double armDegrees, double turnDegrees, int frames) {
        double[] rest = generate(armDegrees).positions();
        double[][] out = new double[frames][];
        for (int f = 0; f < frames; f++) {
            double a = Math.toRadians(turnDegrees) * Math.sin(2 * Math.PI * f / frames), c = Math.cos(a), s = Math.sin(a);
            double[] p = rest.clone();
            for (int i = 0; i < p.length; i += 3) {
                double x = rest[i], z = rest[i + 2];
                p[i] = c * x + s * z;
                p[i + 2] = -s * x + c * z;
            }
            out[f] = p;
        }
        return out;
    }

    private static final class Builder {
        final List<Double> v = new ArrayList<>();
        final List<int[]> faces = new ArrayList<>();

        int vertex(double x, double y, double z) {
            v.add(x); v.add(y); v.add(z);
            return v.size() / 3 - 1;
        }

        void triangle(int a, int b, int c) { faces.add(new int[] {a, b, c}); }

        /**
         * A closed surface of rings between two poles (rings[r][j] the j-th vertex of ring r), its triangles
         * then turned, if need be, so that the part encloses a positive volume: wound outwards.
         */
        void rings(int south, int[][] rings, int north) {
            int segments = rings[0].length, first = faces.size();
            for (int j = 0; j < segments; j++) {
                int k = (j + 1) % segments;
                triangle(south, rings[0][j], rings[0][k]);
                triangle(north, rings[rings.length - 1][k], rings[rings.length - 1][j]);
                for (int r = 0; r + 1 < rings.length; r++) {
                    triangle(rings[r][j], rings[r + 1][j], rings[r + 1][k]);
                    triangle(rings[r][j], rings[r + 1][k], rings[r][k]);
                }
            }
            double volume = 0;
            for (int f = first; f < faces.size(); f++) {
                int[] t = faces.get(f);
                double ax = v.get(3 * t[0]), ay = v.get(3 * t[0] + 1), az = v.get(3 * t[0] + 2);
                double bx = v.get(3 * t[1]), by = v.get(3 * t[1] + 1), bz = v.get(3 * t[1] + 2);
                double cx = v.get(3 * t[2]), cy = v.get(3 * t[2] + 1), cz = v.get(3 * t[2] + 2);
                volume += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
            }
            if (volume < 0)
                for (int f = first; f < faces.size(); f++) { int[] t = faces.get(f); int s = t[1]; t[1] = t[2]; t[2] = s; }
        }

        void torso() {
            int segments = 32;
            int south = vertex(0, TORSO[0][0], 0), north;
            int[][] rings = new int[TORSO.length - 2][segments];
            for (int r = 1; r + 1 < TORSO.length; r++)
                for (int j = 0; j < segments; j++) {
                    double phi = -2 * Math.PI * j / segments;
                    rings[r - 1][j] = vertex(TORSO[r][1] * Math.cos(phi), TORSO[r][0], TORSO[r][2] * Math.sin(phi));
                }
            north = vertex(0, TORSO[TORSO.length - 1][0], 0);
            rings(south, rings, north);
        }

        void ellipsoid(double[] c, double[] radii, int segments, int ringCount) {
            int south = vertex(c[0], c[1] - radii[1], c[2]);
            int[][] rings = new int[ringCount - 1][segments];
            for (int r = 1; r < ringCount; r++) {
                double theta = Math.PI * r / ringCount - Math.PI / 2;
                for (int j = 0; j < segments; j++) {
                    double phi = -2 * Math.PI * j / segments;
                    rings[r - 1][j] = vertex(c[0] + radii[0] * Math.cos(theta) * Math.cos(phi), c[1] + radii[1] * Math.sin(theta), c[2] + radii[2] * Math.cos(theta) * Math.sin(phi));
                }
            }
            int north = vertex(c[0], c[1] + radii[1], c[2]);
            rings(south, rings, north);
        }

        /** A capsule from a to b of radius r: hemispheres of {@code capRings} rings at both ends and the cylinder between. */
        void capsule(double[] a, double[] b, double r, int segments, int capRings) {
            double[] axis = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
            double len = Math.sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
            for (int d = 0; d < 3; d++) axis[d] /= len;
            // Two unit vectors across the axis, u × w = axis.
            double[] u = Math.abs(axis[0]) < 0.9 ? new double[] {1, 0, 0} : new double[] {0, 1, 0};
            double dot = u[0] * axis[0] + u[1] * axis[1] + u[2] * axis[2];
            for (int d = 0; d < 3; d++) u[d] -= dot * axis[d];
            double lu = Math.sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
            for (int d = 0; d < 3; d++) u[d] /= lu;
            double[] w = {axis[1] * u[2] - axis[2] * u[1], axis[2] * u[0] - axis[0] * u[2], axis[0] * u[1] - axis[1] * u[0]};
            int south = vertex(a[0] - r * axis[0], a[1] - r * axis[1], a[2] - r * axis[2]);
            int[][] rings = new int[2 * capRings][segments];
            for (int r0 = 0; r0 < 2 * capRings; r0++) {
                boolean lower = r0 < capRings;
                double theta = lower ? -Math.PI / 2 + Math.PI / 2 * (r0 + 1) / capRings : Math.PI / 2 * (r0 - capRings) / capRings;
                double[] centre = lower ? a : b;
                double along = r * Math.sin(theta), across = r * Math.cos(theta);
                for (int j = 0; j < segments; j++) {
                    double phi = 2 * Math.PI * j / segments, cu = across * Math.cos(phi), cw = across * Math.sin(phi);
                    rings[r0][j] = vertex(centre[0] + along * axis[0] + cu * u[0] + cw * w[0], centre[1] + along * axis[1] + cu * u[1] + cw * w[1],
                            centre[2] + along * axis[2] + cu * u[2] + cw * w[2]);
                }
            }
            int north = vertex(b[0] + r * axis[0], b[1] + r * axis[1], b[2] + r * axis[2]);
            rings(south, rings, north);
        }

        /** An arm from its shoulder joint, {@code degrees} out from hanging straight down, on side −1 (right) or +1 (left). */
        void arm(int side, double degrees) {
            double a = Math.toRadians(degrees);
            double[] shoulder = {side * SHOULDER_X, SHOULDER_Y, 0};
            double[] hand = {shoulder[0] + side * ARM_LENGTH * Math.sin(a), shoulder[1] - ARM_LENGTH * Math.cos(a), 0};
            capsule(shoulder, hand, ARM_RADIUS, 16, 4);
        }

        ClothMesh mesh() {
            double[] p = new double[v.size()];
            for (int i = 0; i < p.length; i++) p[i] = v.get(i);
            return ClothMesh.of(p, faces.toArray(new int[0][]), null, null, null);
        }
    }
}
