package xpbdcloth.sketch;

import processing.core.PConstants;
import processing.core.PGraphics;
import xpbdcloth.engine.Sphere;

/**
 * Shadows on the ground (y = 0) under the key light: each cloth triangle and each sphere projected along
 * the light's direction onto the floor, drawn flat and dark a millimetre above it. A planar projected
 * shadow (Blinn 1988, "Me and my (fake) shadow"): exact for a directional light and a flat floor, one
 * pass over the triangles, no shadow map. Overlapping triangles are drawn in one opaque colour, so a
 * folded cloth does not cast a darker blotch where its layers overlap.
 */
final class GroundShadow {
    /** The key light's direction of travel (world, y up): the one {@link ClothApp} lights the scene with. */
    static final float LIGHT_X = 0.35f, LIGHT_Y = -0.55f, LIGHT_Z = -0.75f;
    /** Height above the floor, m, so the shadow is drawn over the floor and under the grid lines. */
    static final float LIFT = 0.001f;
    /** The floor's and the shadow's colour (RGB). */
    static final int[] FLOOR = {52, 55, 63}, SHADOW = {30, 31, 36};

    /** A 4 m square floor centred under x = centreX, in the floor colour (drawn unlit). */
    static void drawFloor(PGraphics g, double centreX) {
        float cx = (float) (Math.round(centreX * 4) / 4.0), half = 2f;
        g.noStroke();
        g.fill(FLOOR[0], FLOOR[1], FLOOR[2]);
        g.beginShape(PConstants.QUADS);
        g.vertex(cx - half, 0, -half); g.vertex(cx + half, 0, -half);
        g.vertex(cx + half, 0, half); g.vertex(cx - half, 0, half);
        g.endShape();
    }

    /** The shadow of a triangle mesh at positions x (only points above the floor cast one). */
    static void drawMesh(PGraphics g, double[] x, int[] t) {
        g.noStroke();
        g.fill(SHADOW[0], SHADOW[1], SHADOW[2]);
        g.beginShape(PConstants.TRIANGLES);
        for (int k = 0; k < t.length; k++) vertex(g, x[3 * t[k]], x[3 * t[k] + 1], x[3 * t[k] + 2]);
        g.endShape();
    }

    /** The shadow of a sphere: an ellipse, drawn as the projection of its silhouette circle. */
    static void drawSphere(PGraphics g, Sphere s) {
        // The silhouette seen from the light is the great circle perpendicular to the light direction.
        double lx = LIGHT_X, ly = LIGHT_Y, lz = LIGHT_Z, l = Math.sqrt(lx * lx + ly * ly + lz * lz);
        lx /= l; ly /= l; lz /= l;
        double ux = -lz, uy = 0, uz = lx, ul = Math.sqrt(ux * ux + uz * uz);
        ux /= ul; uz /= ul;
        double vx = ly * uz - lz * uy, vy = lz * ux - lx * uz, vz = lx * uy - ly * ux; // v = l × u
        double r = s.radius();
        g.noStroke();
        g.fill(SHADOW[0], SHADOW[1], SHADOW[2]);
        g.beginShape();
        for (int i = 0; i < 48; i++) {
            double a = 2 * Math.PI * i / 48, c = r * Math.cos(a), sn = r * Math.sin(a);
            vertex(g, s.centreX() + c * ux + sn * vx, s.centreY() + c * uy + sn * vy, s.centreZ() + c * uz + sn * vz);
        }
        g.endShape(PConstants.CLOSE);
    }

    /** Point p moved along the light to the floor (a point below the floor stays where it is, flattened). */
    private static void vertex(PGraphics g, double px, double py, double pz) {
        double t = py > 0 ? -py / LIGHT_Y : 0;
        g.vertex((float) (px + t * LIGHT_X), LIFT, (float) (pz + t * LIGHT_Z));
    }
}
