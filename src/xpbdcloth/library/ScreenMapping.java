package xpbdcloth.library;

import processing.core.PMatrix3D;
import processing.opengl.PGraphicsOpenGL;

/**
 * Between world (the cloth's metres) and the window's pixels, as the sketch last drew the cloth: a copy
 * of P3D's projection × modelview taken inside {@link ClothView#draw()}. Taking it from the renderer
 * rather than from a camera of our own is what lets the cloth be grabbed under any camera the sketch
 * uses (its own {@code camera()}, PeasyCam, a rotating translate). Holds its matrices and arrays, so
 * mapping a point allocates nothing.
 */
final class ScreenMapping {
    private final PMatrix3D worldToClip = new PMatrix3D(), clipToWorld = new PMatrix3D();
    private final float[] in = new float[4], out = new float[4];
    private float width, height;
    private boolean captured;

    /** Takes the renderer's current transform (call with the cloth's world transform applied). */
    void capture(PGraphicsOpenGL g) {
        worldToClip.set(g.projmodelview);
        clipToWorld.set(worldToClip);
        captured = clipToWorld.invert();
        width = g.width;
        height = g.height;
    }

    /** Whether a transform has been taken and can be inverted. */
    boolean ready() { return captured; }

    /**
     * World point → {screen x px, screen y px, depth in [-1, 1], w}. Processing's screen y grows
     * downwards while clip y grows upwards. w ≤ 0 means the point is behind the eye.
     */
    void toScreen(double x, double y, double z, double[] screen) {
        in[0] = (float) x; in[1] = (float) y; in[2] = (float) z; in[3] = 1;
        worldToClip.mult(in, out);
        double w = out[3];
        screen[0] = 0.5 * width * (1 + out[0] / w);
        screen[1] = 0.5 * height * (1 - out[1] / w);
        screen[2] = out[2] / w;
        screen[3] = w;
    }

    /** Screen pixel at the given depth (as {@link #toScreen} gave it) → world point. */
    void toWorld(double sx, double sy, double depth, double[] world) {
        in[0] = (float) (2 * sx / width - 1);
        in[1] = (float) (1 - 2 * sy / height);
        in[2] = (float) depth;
        in[3] = 1;
        clipToWorld.mult(in, out);
        world[0] = out[0] / out[3];
        world[1] = out[1] / out[3];
        world[2] = out[2] / out[3];
    }

    /** The eye in world coordinates: where the inverse modelview takes the camera's origin. */
    static void eye(PGraphicsOpenGL g, double[] world) {
        PMatrix3D m = g.modelviewInv;
        world[0] = m.m03 / m.m33;
        world[1] = m.m13 / m.m33;
        world[2] = m.m23 / m.m33;
    }
}
