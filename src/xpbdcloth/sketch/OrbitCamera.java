package xpbdcloth.sketch;

import java.util.function.Predicate;
import processing.core.PApplet;
import processing.core.PConstants;
import processing.core.PGraphics;
import processing.event.MouseEvent;
import processing.opengl.PGraphicsOpenGL;

/**
 * An orbit camera with PeasyCam's hands (PeasyCam itself is not on Maven Central): left-drag rotates
 * about the look-at point, right-drag and the wheel zoom, middle-drag (or Meta + left-drag) pans,
 * Shift-drag locks to the dominant axis, double-click glides back to the start view. Every gesture feeds
 * a velocity that is applied each frame and damped, so the camera coasts to a stop.
 *
 * <p>World space is y-up metres. The camera looks from eye = centre + R·(0,0,1)·distance with up R·(0,1,0),
 * R a unit quaternion (no gimbal lock). {@link #apply} converts to Processing's y-down space in the one
 * place the sketch flips y. The maths (rotate, zoom, pan, reset, rays) needs no window and is tested.
 */
public final class OrbitCamera {
    static final double DAMPING = 0.84, STOP_BELOW = 0.001;
    static final double RESET_SECONDS = 0.3;
    static final double FOV = Math.PI / 3;

    private Quaternion rotation;
    private double distance;
    private final double[] centre = new double[3];
    private final double minDistance, maxDistance;
    private Quaternion startRotation;
    private double startDistance;
    private final double[] startCentre;

    // Velocities fed by gestures: rotation about the view's x and y axes (rad/frame), zoom (fraction of
    // distance per frame), pan (view-plane units of distance per frame).
    private double pitchVelocity, yawVelocity, zoomVelocity, panXVelocity, panYVelocity;

    // Double-click glide.
    private boolean resetting;
    private double resetStart;
    private Quaternion resetFrom;
    private double resetFromDistance;
    private final double[] resetFromCentre = new double[3];

    // Drag bookkeeping.
    private boolean dragging;
    private int dragButton;
    private boolean dragShift, dragMeta;
    private int axisLock; // 0 undecided, 1 yaw (x motion), 2 pitch (y motion)
    private Predicate<MouseEvent> ignore = e -> false;
    private PApplet applet;
    private double viewportWidth = 800, viewportHeight = 600;
    private final double[] tmp = new double[3], eyeS = new double[3], rightS = new double[3], upS = new double[3], fwdS = new double[3];

    public OrbitCamera(double cx, double cy, double cz, double distance, double minDistance, double maxDistance) {
        if (!(minDistance > 0 && maxDistance >= minDistance))
            throw new IllegalArgumentException("minDistance must be > 0 and <= maxDistance, was " + minDistance);
        this.minDistance = minDistance;
        this.maxDistance = maxDistance;
        centre[0] = cx; centre[1] = cy; centre[2] = cz;
        this.distance = clampDistance(distance);
        rotation = Quaternion.axisAngle(1, 0, 0, -0.15); // a little from above
        startRotation = rotation;
        startDistance = this.distance;
        startCentre = centre.clone();
    }

    /** Makes (cx, cy, cz) at {@code distance}, pitched by {@code pitch} rad (negative: from above), the start view, and jumps there. */
    public void setStartView(double cx, double cy, double cz, double distance, double pitch) {
        startRotation = Quaternion.axisAngle(1, 0, 0, pitch);
        startCentre[0] = cx; startCentre[1] = cy; startCentre[2] = cz;
        startDistance = clampDistance(distance);
        rotation = startRotation;
        this.distance = startDistance;
        System.arraycopy(startCentre, 0, centre, 0, 3);
        resetting = false;
        pitchVelocity = yawVelocity = zoomVelocity = panXVelocity = panYVelocity = 0;
    }

    /** Hooks the camera into a sketch (its mouse events and its frame), like a Processing library. */
    public OrbitCamera attach(PApplet app) {
        applet = app;
        app.registerMethod("mouseEvent", this);
        return this;
    }

    /** Events for which the camera does nothing (e.g. while the user grabs the cloth). */
    public void ignoreWhen(Predicate<MouseEvent> p) { ignore = p; }

    public double distance() { return distance; }
    public double[] centre() { return centre.clone(); }
    public Quaternion rotation() { return rotation; }

    private double clampDistance(double d) { return Math.max(minDistance, Math.min(maxDistance, d)); }

    // ---- gestures (pixels in, velocities out) ----

    /** Left-drag: trackball rotation whose gain shrinks slowly (logarithmically) with distance. */
    public void dragRotate(double dx, double dy) {
        double gain = 0.004 / (1 + 0.15 * Math.log1p(distance));
        yawVelocity += -dx * gain;
        pitchVelocity += -dy * gain;
    }

    /** Right-drag or wheel: dragging down (positive dy) zooms out, by a fraction of the distance. */
    public void dragZoom(double dy) { zoomVelocity += dy * 0.0015; }

    public void wheel(double count) { zoomVelocity += count * 0.02; }

    /** Middle-drag: moves the centre in the view plane, scaled by distance. */
    public void dragPan(double dx, double dy) {
        double gain = 0.0012 * distance;
        panXVelocity += -dx * gain;
        panYVelocity += dy * gain;
    }

    /** Starts the glide back to the start view (double-click). */
    public void reset(double nowSeconds) {
        resetting = true;
        resetStart = nowSeconds;
        resetFrom = rotation;
        resetFromDistance = distance;
        System.arraycopy(centre, 0, resetFromCentre, 0, 3);
        pitchVelocity = yawVelocity = zoomVelocity = panXVelocity = panYVelocity = 0;
    }

    /** Applies and damps the velocities (call once per frame); runs the reset glide. */
    public void update(double nowSeconds) {
        if (resetting) {
            double u = Math.min(1, (nowSeconds - resetStart) / RESET_SECONDS);
            double s = u * u * (3 - 2 * u);
            rotation = Quaternion.slerp(resetFrom, startRotation, s);
            distance = resetFromDistance + (startDistance - resetFromDistance) * s;
            for (int i = 0; i < 3; i++) centre[i] = resetFromCentre[i] + (startCentre[i] - resetFromCentre[i]) * s;
            if (u >= 1) resetting = false;
            return;
        }
        if (yawVelocity != 0 || pitchVelocity != 0) {
            // Rotate about the camera's own up and right axes (local frame): R ← R · q.
            rotation = rotation.times(Quaternion.axisAngle(0, 1, 0, yawVelocity)).times(Quaternion.axisAngle(1, 0, 0, pitchVelocity));
        }
        if (zoomVelocity != 0) distance = clampDistance(distance * (1 + zoomVelocity));
        if (panXVelocity != 0 || panYVelocity != 0) {
            rotation.rotate(1, 0, 0, tmp);
            for (int i = 0; i < 3; i++) centre[i] += tmp[i] * panXVelocity;
            rotation.rotate(0, 1, 0, tmp);
            for (int i = 0; i < 3; i++) centre[i] += tmp[i] * panYVelocity;
        }
        yawVelocity = damp(yawVelocity);
        pitchVelocity = damp(pitchVelocity);
        zoomVelocity = damp(zoomVelocity);
        panXVelocity = damp(panXVelocity);
        panYVelocity = damp(panYVelocity);
    }

    private static double damp(double v) {
        v *= DAMPING;
        return Math.abs(v) < STOP_BELOW ? 0 : v;
    }

    /** True while any velocity or the reset glide is still moving the camera. */
    public boolean moving() {
        return resetting || yawVelocity != 0 || pitchVelocity != 0 || zoomVelocity != 0 || panXVelocity != 0 || panYVelocity != 0;
    }

    /** The eye position (world, y up). */
    public void eye(double[] out) {
        rotation.rotate(0, 0, 1, out);
        for (int i = 0; i < 3; i++) out[i] = centre[i] + out[i] * distance;
    }

    // ---- rays and projection for picking (world space, y up) ----

    public void setViewport(double width, double height) {
        viewportWidth = width;
        viewportHeight = height;
    }

    /**
     * Projects a world point to pixels (x right, y down) into out[0..1]; out[2] is the depth along the
     * view direction (negative behind the eye).
     */
    public void project(double px, double py, double pz, double[] out) {
        double[] e = eyeS, r = rightS, u = upS, f = fwdS;
        eye(e);
        rotation.rotate(1, 0, 0, r);
        rotation.rotate(0, 1, 0, u);
        rotation.rotate(0, 0, -1, f);
        double dx = px - e[0], dy = py - e[1], dz = pz - e[2];
        double depth = dx * f[0] + dy * f[1] + dz * f[2];
        double t = Math.tan(FOV / 2);
        double aspect = viewportWidth / viewportHeight;
        double sx = (dx * r[0] + dy * r[1] + dz * r[2]) / (depth * t * aspect);
        double sy = (dx * u[0] + dy * u[1] + dz * u[2]) / (depth * t);
        out[0] = (sx + 1) * 0.5 * viewportWidth;
        out[1] = (1 - sy) * 0.5 * viewportHeight;
        out[2] = depth;
    }

    /**
     * The point under pixel (mx, my) on the plane through (px, py, pz) facing the camera: where a dragged
     * particle goes.
     */
    public void unprojectOnViewPlane(double mx, double my, double px, double py, double pz, double[] out) {
        double[] e = eyeS, r = rightS, u = upS, f = fwdS;
        eye(e);
        rotation.rotate(1, 0, 0, r);
        rotation.rotate(0, 1, 0, u);
        rotation.rotate(0, 0, -1, f);
        double t = Math.tan(FOV / 2), aspect = viewportWidth / viewportHeight;
        double sx = (2 * mx / viewportWidth - 1) * t * aspect, sy = (1 - 2 * my / viewportHeight) * t;
        double depth = (px - e[0]) * f[0] + (py - e[1]) * f[1] + (pz - e[2]) * f[2];
        // The ray e + s·d with d = f + sx·r + sy·u has d·f = 1, so it meets the plane at s = depth.
        for (int i = 0; i < 3; i++) out[i] = e[i] + (f[i] + sx * r[i] + sy * u[i]) * depth;
    }

    // ---- Processing glue ----

    /**
     * Sets the perspective and the camera on g and flips y: the one place where the world's y-up metres
     * become Processing's y-down space. After this, draw in world coordinates.
     */
    public void apply(PGraphics g) {
        setViewport(g.width, g.height);
        eye(tmp);
        double ex = tmp[0], ey = tmp[1], ez = tmp[2];
        double[] up = upS;
        rotation.rotate(0, 1, 0, up);
        float near = (float) (distance * 0.01), far = (float) (distance * 100 + 100);
        g.perspective((float) FOV, (float) g.width / g.height, near, far);
        // Processing shows the up vector it is given pointing down the screen (its y grows downwards), so
        // the world's up, flipped into Processing space as (ux, −uy, uz), is passed negated.
        g.camera((float) ex, (float) -ey, (float) ez, (float) centre[0], (float) -centre[1], (float) centre[2],
                (float) -up[0], (float) up[1], (float) -up[2]);
        g.scale(1, -1, 1);
    }

    /** Begins drawing in screen pixels on top of the 3D view (no depth test, no lights, orthographic). */
    public static void beginHud(PGraphics g) {
        g.hint(PConstants.DISABLE_DEPTH_TEST);
        g.noLights();
        g.pushMatrix();
        if (g instanceof PGraphicsOpenGL) ((PGraphicsOpenGL) g).pushProjection();
        g.resetMatrix();
        g.ortho(0, g.width, -g.height, 0);
    }

    /** Restores the 3D view after {@link #beginHud}. */
    public static void endHud(PGraphics g) {
        if (g instanceof PGraphicsOpenGL) ((PGraphicsOpenGL) g).popProjection();
        g.popMatrix();
        g.hint(PConstants.ENABLE_DEPTH_TEST);
    }

    /** Processing mouse events (registered by {@link #attach}). */
    public void mouseEvent(MouseEvent e) {
        if (applet == null) return;
        int action = e.getAction();
        if (action == MouseEvent.PRESS) {
            boolean inView = e.getX() >= 0 && e.getY() >= 0 && e.getX() < applet.width && e.getY() < applet.height;
            dragging = inView && !ignore.test(e);
            dragButton = e.getButton();
            dragShift = e.isShiftDown();
            dragMeta = e.isMetaDown();
            axisLock = 0;
            if (dragging && e.getCount() == 2 && dragButton == PConstants.LEFT) reset(applet.millis() / 1000.0);
            return;
        }
        if (action == MouseEvent.RELEASE) { dragging = false; return; }
        if (action == MouseEvent.WHEEL) {
            if (!ignore.test(e)) wheel(e.getCount());
            return;
        }
        if (action != MouseEvent.DRAG || !dragging) return;
        double dx = applet.mouseX - applet.pmouseX, dy = applet.mouseY - applet.pmouseY;
        if (dragShift) {
            if (axisLock == 0 && (dx != 0 || dy != 0)) axisLock = Math.abs(dx) >= Math.abs(dy) ? 1 : 2;
            if (axisLock == 1) dy = 0;
            if (axisLock == 2) dx = 0;
        }
        if (dragButton == PConstants.CENTER || (dragButton == PConstants.LEFT && dragMeta)) dragPan(dx, dy);
        else if (dragButton == PConstants.RIGHT) dragZoom(dy);
        else if (dragButton == PConstants.LEFT) dragRotate(dx, dy);
    }
}
