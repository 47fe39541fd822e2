package xpbdcloth.sketch;

import processing.core.PApplet;

/**
 * The sketch outside the Processing IDE ({@code gradle run}, the installed launcher): the same three
 * steps as {@code xpbd_cloth/xpbd_cloth.pde}: a resizable P3D window and a {@link ClothApp}.
 */
public final class Launcher extends PApplet {
    private final String scene;
    private final boolean sideBySide;
    private final ClothApp.Recording recording;
    private final int width0, height0;
    private ClothApp clothApp;
    private static volatile boolean opened;

    /** Whether {@link #open} has started a sketch in this JVM. */
    public static boolean opened() { return opened; }

    public Launcher(String scene, boolean sideBySide, ClothApp.Recording recording, int width, int height) {
        this.scene = scene;
        this.sideBySide = sideBySide;
        this.recording = recording;
        this.width0 = width;
        this.height0 = height;
    }

    @Override public void settings() {
        size(width0, height0, P3D);
        smooth(4);
    }

    @Override public void setup() {
        surface.setResizable(true);
        surface.setTitle("xpbd-cloth");
        frameRate(60);
        clothApp = new ClothApp(this, scene, sideBySide, recording);
    }

    @Override public void draw() {
        // ClothApp draws through registerMethod("draw"), exactly as in the Processing IDE.
    }

    public ClothApp clothApp() { return clothApp; }

    /** Opens the window; returns at once (Processing runs its own animation thread). */
    public static void open(String scene, boolean sideBySide, ClothApp.Recording recording, int width, int height) {
        opened = true;
        QuietJogl.install();
        // The sketch's folder is where the user runs it from: `O` writes there, as the README says, not
        // into the install folder Processing would otherwise take from the class path.
        PApplet.runSketch(new String[] {PApplet.ARGS_SKETCH_FOLDER + "=" + System.getProperty("user.dir"), "xpbd-cloth"}, new Launcher(scene, sideBySide, recording, width, height));
    }
}
