package xpbdcloth.sketch;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/** The orbit camera's maths, without a window. */
class OrbitCameraTest {

    static OrbitCamera camera() { return new OrbitCamera(0, 1, 0, 3, 0.5, 10); }

    static void settle(OrbitCamera c) {
        for (int i = 0; i < 200 && c.moving(); i++) c.update(0);
        assertFalse(c.moving(), "the camera coasts to a stop");
    }

    static double eyeDistance(OrbitCamera c) {
        double[] e = new double[3];
        c.eye(e);
        double[] m = c.centre();
        return Math.sqrt((e[0] - m[0]) * (e[0] - m[0]) + (e[1] - m[1]) * (e[1] - m[1]) + (e[2] - m[2]) * (e[2] - m[2]));
    }

    @Test
    void rotatingKeepsDistanceAndCentre() {
        OrbitCamera c = camera();
        double[] e0 = new double[3], e1 = new double[3];
        c.eye(e0);
        c.dragRotate(120, 0);
        settle(c);
        c.eye(e1);
        assertEquals(3, eyeDistance(c), 1e-9);
        assertArrayEquals(new double[] {0, 1, 0}, c.centre(), 1e-12);
        assertTrue(Math.abs(e1[0] - e0[0]) > 0.3, "a horizontal drag swings the eye sideways");
        double[] up1 = new double[3];
        c.rotation().rotate(0, 1, 0, up1);
        assertEquals(0, up1[0] * (e1[0] - e0[0]) + up1[1] * (e1[1] - e0[1]) + up1[2] * (e1[2] - e0[2]), 1e-9,
                "a horizontal drag turns about the view's own up axis (trackball), so the eye moves across it");
    }

    @Test
    void zoomIsMultiplicativeDownIsOutAndClamped() {
        OrbitCamera c = camera();
        c.dragZoom(40);
        settle(c);
        assertTrue(c.distance() > 3, "dragging down zooms out: " + c.distance());
        for (int i = 0; i < 50; i++) { c.wheel(10); c.update(0); }
        settle(c);
        assertEquals(10, c.distance(), 1e-12, "clamped at max");
        for (int i = 0; i < 50; i++) { c.wheel(-10); c.update(0); }
        settle(c);
        assertEquals(0.5, c.distance(), 1e-12, "clamped at min");
    }

    @Test
    void panMovesCentreInTheViewPlane() {
        OrbitCamera c = camera();
        double[] e0 = new double[3];
        c.eye(e0);
        double[] f = {-e0[0], 1 - e0[1], -e0[2]};
        c.dragPan(50, 0);
        settle(c);
        double[] m = c.centre();
        double moved = Math.sqrt(m[0] * m[0] + (m[1] - 1) * (m[1] - 1) + m[2] * m[2]);
        assertTrue(moved > 0.05, "pan moved the centre by " + moved);
        double along = (m[0] * f[0] + (m[1] - 1) * f[1] + m[2] * f[2]) / 3;
        assertEquals(0, along, 1e-9, "pan stays in the view plane");
        assertEquals(3, eyeDistance(c), 1e-9);
    }

    @Test
    void doubleClickResetGlidesBackInAboutThreeHundredMilliseconds() {
        OrbitCamera c = camera();
        double[] start = new double[3];
        c.eye(start);
        c.dragRotate(200, 80);
        c.dragZoom(30);
        settle(c);
        c.reset(10.0);
        c.update(10.15);
        assertTrue(c.moving(), "half way through the glide");
        c.update(10.31);
        assertFalse(c.moving());
        double[] e = new double[3];
        c.eye(e);
        assertArrayEquals(start, e, 1e-9);
    }

    @Test
    void projectAndUnprojectAgree() {
        OrbitCamera c = camera();
        c.dragRotate(60, 30);
        settle(c);
        c.setViewport(1280, 800);
        double[] px = new double[3], back = new double[3];
        c.project(0.3, 0.7, -0.2, px);
        assertTrue(px[2] > 0, "in front of the eye");
        c.unprojectOnViewPlane(px[0], px[1], 0.3, 0.7, -0.2, back);
        assertArrayEquals(new double[] {0.3, 0.7, -0.2}, back, 1e-9);
        c.project(0, 1, 0, px);
        assertEquals(640, px[0], 1e-6, "the centre projects to the middle of the view");
        assertEquals(400, px[1], 1e-6);
    }
}
