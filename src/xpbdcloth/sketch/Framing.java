package xpbdcloth.sketch;

/**
 * The start view that shows the whole cloth in the part of the window the HUD's parameter panel leaves
 * free: its rest bounding box, projected, lies between the panel's foot and the window's bottom edge.
 * The view is moved up (the cloth down on screen) and, if the box is too tall for that band, back.
 */
final class Framing {
    /** Pixels the HUD's parameter panel takes at the top: its 13 lines, a notice and the margins. */
    static final double HUD_RESERVE = HudLayout.MARGIN + HudLayout.LINE * 14 + 12 + 6;
    /** Pixels kept clear at the bottom. */
    static final double BOTTOM = 12;

    private Framing() {}

    /**
     * Adjusts {@code camera}'s start view (centre cx, cy, cz at distance, pitch) until the box
     * {min x, min y, min z, max x, max y, max z} projects between the HUD's reserve and the bottom.
     */
    static void belowHud(OrbitCamera camera, double[] box, double width, double height, double cx, double cy, double cz, double distance, double pitch) {
        camera.setViewport(width, height);
        double top = Math.min(HUD_RESERVE, 0.45 * height), bottom = height - BOTTOM;
        double[] p = new double[3];
        for (int k = 0; k < 60; k++) {
            camera.setStartView(cx, cy, cz, distance, pitch);
            double minY = Double.MAX_VALUE, maxY = -Double.MAX_VALUE;
            for (int c = 0; c < 8; c++) {
                camera.project(box[(c & 1) == 0 ? 0 : 3], box[(c & 2) == 0 ? 1 : 4], box[(c & 4) == 0 ? 2 : 5], p);
                minY = Math.min(minY, p[1]);
                maxY = Math.max(maxY, p[1]);
            }
            if (minY >= top - 0.5 && maxY <= bottom + 0.5) return;
            if (maxY - minY > bottom - top) { distance *= 1.08; continue; }
            // Move the cloth's screen middle to the band's: up in the world is down on the screen.
            double pixelsPerMetre = height / (2 * distance * Math.tan(OrbitCamera.FOV / 2));
            cy += ((top + bottom) / 2 - (minY + maxY) / 2) / pixelsPerMetre;
        }
    }
}
