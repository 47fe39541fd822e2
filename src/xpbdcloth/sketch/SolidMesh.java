package xpbdcloth.sketch;

import processing.core.PConstants;
import processing.core.PGraphics;
import xpbdcloth.engine.Box;
import xpbdcloth.engine.Capsule;
import xpbdcloth.engine.MeshCollider;
import xpbdcloth.engine.RigidCollider;
import xpbdcloth.mesh.VertexNormals;

/**
 * A box or a capsule as triangles with normals, in the solid's own frame, placed in the world each frame
 * into arrays kept between frames: drawn lit, and handed to {@link GroundShadow} for its shadow, from the
 * same triangles. A capsule is two hemispheres joined by a cylinder, in rings of latitude. A triangle mesh
 * is its own triangles where the engine has put them now, with smooth vertex normals.
 */
final class SolidMesh {
    static final int SEGMENTS = 24, CAP_RINGS = 8;

    final RigidCollider solid;
    private final double[] local, localNormals;
    final int[] triangles;
    /** World positions and normals, refreshed by {@link #place}. */
    final double[] world, normals;
    private final double[] rotation = new double[9];

    SolidMesh(RigidCollider solid) {
        this.solid = solid;
        if (solid instanceof MeshCollider) {
            MeshCollider m = (MeshCollider) solid;
            local = localNormals = null;
            triangles = m.triangles();
        } else if (solid instanceof Box) {
            Box b = (Box) solid;
            double[][] built = box(b.halfExtentX(), b.halfExtentY(), b.halfExtentZ());
            local = built[0];
            localNormals = built[1];
            triangles = boxTriangles();
        } else {
            Capsule c = (Capsule) solid;
            local = new double[3 * SEGMENTS * (2 * CAP_RINGS + 2)];
            localNormals = new double[local.length];
            capsule(c.halfLength(), c.radius(), local, localNormals);
            triangles = ringTriangles(2 * CAP_RINGS + 2);
        }
        int size = local == null ? 3 * ((MeshCollider) solid).vertexCount() : local.length;
        world = new double[size];
        normals = new double[size];
    }

    /** Puts the mesh where the solid is now. */
    void place() {
        if (local == null) {
            System.arraycopy(((MeshCollider) solid).vertices(), 0, world, 0, world.length);
            VertexNormals.compute(world, triangles, normals);
            return;
        }
        solid.rotation(rotation);
        double[] r = rotation;
        for (int k = 0; k < local.length; k += 3) {
            double x = local[k], y = local[k + 1], z = local[k + 2];
            world[k] = solid.centreX() + r[0] * x + r[1] * y + r[2] * z;
            world[k + 1] = solid.centreY() + r[3] * x + r[4] * y + r[5] * z;
            world[k + 2] = solid.centreZ() + r[6] * x + r[7] * y + r[8] * z;
            x = localNormals[k]; y = localNormals[k + 1]; z = localNormals[k + 2];
            normals[k] = r[0] * x + r[1] * y + r[2] * z;
            normals[k + 1] = r[3] * x + r[4] * y + r[5] * z;
            normals[k + 2] = r[6] * x + r[7] * y + r[8] * z;
        }
    }

    /** The solid, lit, as {@link #place} left it. */
    void draw(PGraphics g) {
        g.beginShape(PConstants.TRIANGLES);
        for (int t : triangles) {
            int k = 3 * t;
            g.normal((float) normals[k], (float) normals[k + 1], (float) normals[k + 2]);
            g.vertex((float) world[k], (float) world[k + 1], (float) world[k + 2]);
        }
        g.endShape();
    }

    /** Six faces of four corners each, with the face's normal. */
    private static double[][] box(double ex, double ey, double ez) {
        double[] p = new double[72], n = new double[72];
        int v = 0;
        for (int axis = 0; axis < 3; axis++)
            for (int sign = -1; sign <= 1; sign += 2)
                for (int corner = 0; corner < 4; corner++, v++) {
                    // The two in-face coordinates go round the face's corners.
                    double a = (corner == 1 || corner == 2) ? 1 : -1, b = corner >= 2 ? 1 : -1;
                    double[] q = new double[3];
                    q[axis] = sign;
                    q[(axis + 1) % 3] = sign * a;
                    q[(axis + 2) % 3] = b;
                    p[3 * v] = q[0] * ex; p[3 * v + 1] = q[1] * ey; p[3 * v + 2] = q[2] * ez;
                    n[3 * v + axis] = sign;
                }
        return new double[][] {p, n};
    }

    private static int[] boxTriangles() {
        int[] t = new int[36];
        for (int f = 0; f < 6; f++) {
            int o = 4 * f;
            int[] two = {o, o + 1, o + 2, o, o + 2, o + 3};
            System.arraycopy(two, 0, t, 6 * f, 6);
        }
        return t;
    }

    /** Rings from the top pole to the bottom one: the upper cap about +L, the lower about −L. */
    private static void capsule(double halfLength, double radius, double[] p, double[] n) {
        int rings = 2 * CAP_RINGS + 2, v = 0;
        for (int ring = 0; ring < rings; ring++) {
            boolean upper = ring <= CAP_RINGS;
            double theta = upper ? 0.5 * Math.PI * ring / CAP_RINGS : 0.5 * Math.PI * (1 + (double) (ring - CAP_RINGS - 1) / CAP_RINGS);
            double centre = upper ? halfLength : -halfLength;
            for (int s = 0; s < SEGMENTS; s++, v++) {
                double phi = 2 * Math.PI * s / SEGMENTS;
                double nx = Math.sin(theta) * Math.cos(phi), ny = Math.cos(theta), nz = Math.sin(theta) * Math.sin(phi);
                n[3 * v] = nx; n[3 * v + 1] = ny; n[3 * v + 2] = nz;
                p[3 * v] = radius * nx; p[3 * v + 1] = centre + radius * ny; p[3 * v + 2] = radius * nz;
            }
        }
    }

    private static int[] ringTriangles(int rings) {
        int[] t = new int[6 * SEGMENTS * (rings - 1)];
        int k = 0;
        for (int ring = 0; ring + 1 < rings; ring++)
            for (int s = 0; s < SEGMENTS; s++) {
                int a = ring * SEGMENTS + s, b = ring * SEGMENTS + (s + 1) % SEGMENTS, c = a + SEGMENTS, d = b + SEGMENTS;
                t[k++] = a; t[k++] = b; t[k++] = c;
                t[k++] = b; t[k++] = d; t[k++] = c;
            }
        return t;
    }
}
