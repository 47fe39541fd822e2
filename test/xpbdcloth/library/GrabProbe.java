package xpbdcloth.library;

import processing.core.PApplet;
import xpbdcloth.engine.Particles;

/**
 * A sketch for {@link ClothViewTest}: the library's cloth under a camera of the sketch's own (moved eye,
 * rotations, as PeasyCam would set), grabbed where Processing itself projects a particle, dragged across
 * the screen and let go while moving. Prints what it measured as key=value lines and quits.
 */
public class GrabProbe extends PApplet {
    static final int GRAB_FRAME = 20, RELEASE_FRAME = 40;
    static final float DRAG_PX_PER_FRAME = 6;

    ClothView cloth;
    int particle;
    float startX, startY;

    @Override public void settings() { size(640, 480, P3D); }

    @Override public void setup() {
        cloth = new ClothView(this, "hanging").autoStep(false);
        particle = cloth.cloth().particles().count() / 2 + 3;
    }

    /** The sketch's view: an eye off to the side and above, then the world turned and tilted. */
    void view() {
        camera(width / 2f + 250, height / 2f - 180, 850, width / 2f, height / 2f, 0, 0, 1, 0);
        translate(width / 2f, height * 0.9f);
        rotateY(0.6f);
        rotateX(-0.25f);
    }

    /** Where Processing draws a world point of the cloth, in screen pixels. */
    float[] screenOf(int i) {
        Particles p = cloth.cloth().particles();
        pushMatrix();
        scale(cloth.pixelsPerMetre(), -cloth.pixelsPerMetre(), -cloth.pixelsPerMetre());  // ClothView's documented world transform
        float[] s = {screenX((float) p.x(i), (float) p.y(i), (float) p.z(i)), screenY((float) p.x(i), (float) p.y(i), (float) p.z(i))};
        popMatrix();
        return s;
    }

    @Override public void draw() {
        background(30);
        lights();
        view();
        cloth.draw();
        if (frameCount == GRAB_FRAME) {
            float[] s = screenOf(particle);
            startX = s[0];
            startY = s[1];
            println("grab=" + cloth.grab(s[0], s[1]));
            println("grabbed=" + cloth.grabbed() + " expected=" + particle);
        } else if (frameCount > GRAB_FRAME && frameCount <= RELEASE_FRAME) {
            int k = frameCount - GRAB_FRAME;
            if (frameCount == RELEASE_FRAME) {
                float[] s = screenOf(particle);
                // The target at this frame is where the mouse was one frame ago.
                println("follow_error_px=" + dist(s[0], s[1], startX + (k - 1) * DRAG_PX_PER_FRAME, startY));
                // Its velocity as it is let go, on screen: where it would be 10 ms on.
                Particles p = cloth.cloth().particles();
                double dt = 0.01;
                pushMatrix();
                scale(cloth.pixelsPerMetre(), -cloth.pixelsPerMetre(), -cloth.pixelsPerMetre());  // ClothView's documented world transform
                float ax = (float) (p.x(particle) + dt * p.vx(particle)), ay = (float) (p.y(particle) + dt * p.vy(particle)), az = (float) (p.z(particle) + dt * p.vz(particle));
                float sx = screenX(ax, ay, az), sy = screenY(ax, ay, az);
                popMatrix();
                cloth.release();
                println("throw_px_per_s=" + (sx - s[0]) / dt + " " + (sy - s[1]) / dt);
                println("drag_px_per_s=" + DRAG_PX_PER_FRAME / cloth.dt());
                println("held_after_release=" + cloth.grabbed());
                controls();
                exit();
            } else cloth.dragTo(startX + k * DRAG_PX_PER_FRAME, startY);
        }
        cloth.step();
    }

    /** The sketch's controls as the library's methods, reported as key=value (no spaces in values). */
    void controls() {
        cloth.iterations(7).substeps(3);
        println("iterations=" + cloth.iterations() + " substeps=" + cloth.substeps() + " engine_iterations=" + cloth.simulation().settings().iterations());
        try {
            cloth.iterations(0);
            println("refused=nothing");
        } catch (IllegalArgumentException e) {
            println("refused=" + e.getMessage().replace(' ', '_'));
        }
        int forces = cloth.simulation().forces().size();
        cloth.wind(true);
        println("wind=" + cloth.windOn() + " forces_added=" + (cloth.simulation().forces().size() - forces));
        cloth.sideBySide(true).paused(true);
        java.util.List<xpbdcloth.engine.Simulation> sims = cloth.simulations();
        println("simulations=" + sims.size() + " left=" + sims.get(0).settings().mode() + " right=" + sims.get(1).settings().mode()
                + " paused=" + cloth.paused());
    }

    public static void main(String[] args) { PApplet.main(GrabProbe.class.getName()); }
}
