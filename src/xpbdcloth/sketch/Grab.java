package xpbdcloth.sketch;

import java.util.List;
import xpbdcloth.engine.AttachmentConstraint;
import xpbdcloth.engine.Particles;
import xpbdcloth.scene.Scene;

/**
 * A particle held by the mouse: the one drawn nearest the pointer, held in every running scene (the pair
 * side by side holds the same particle), each following the same displacement of the pointer. Shared by
 * the sketch and the library, which differ only in how they map the world to the screen.
 */
public final class Grab {
    /** World (x, y, z) → out = {screen x, screen y, depth, w}; w ≤ 0 means behind the eye. */
    @FunctionalInterface
    public interface Projection { void project(double x, double y, double z, double[] out); }

    private final Scene[] scenes;
    private final AttachmentConstraint[] held;
    private final double[][] start;
    /** The particle held. */
    public final int particle;
    /** Where it was drawn when picked (world, with its scene's side-by-side offset), and its depth on screen. */
    public final double x, y, z, depth;

    private Grab(SketchState state, int scene, int particle, double depth) {
        this.scenes = state.running().toArray(new Scene[0]);
        this.particle = particle;
        this.depth = depth;
        Particles p = scenes[scene].cloth().particles();
        x = p.x(particle) + state.offsetX(scene);
        y = p.y(particle);
        z = p.z(particle);
        held = new AttachmentConstraint[scenes.length];
        start = new double[scenes.length][];
        for (int s = 0; s < scenes.length; s++) {
            Particles q = scenes[s].cloth().particles();
            start[s] = new double[] {q.x(particle), q.y(particle), q.z(particle)};
            held[s] = scenes[s].simulation().attach(particle, q.x(particle), q.y(particle), q.z(particle));
        }
    }

    /** Holds the particle drawn nearest screen point (sx, sy), within {@code radius} px, or returns null if none is. */
    public static Grab pick(SketchState state, Projection view, double sx, double sy, double radius) {
        List<Scene> running = state.running();
        double[] out = new double[4];
        double bestD2 = radius * radius, bestDepth = 0;
        int best = -1, bestScene = 0;
        for (int s = 0; s < running.size(); s++) {
            Particles p = running.get(s).cloth().particles();
            double ox = state.offsetX(s);
            for (int i = 0; i < p.count(); i++) {
                view.project(p.x(i) + ox, p.y(i), p.z(i), out);
                if (out[3] <= 0) continue;
                double d2 = (out[0] - sx) * (out[0] - sx) + (out[1] - sy) * (out[1] - sy);
                if (d2 < bestD2) { bestD2 = d2; best = i; bestScene = s; bestDepth = out[2]; }
            }
        }
        return best < 0 ? null : new Grab(state, bestScene, best, bestDepth);
    }

    /** The pointer is over world point (px, py, pz): every held particle moves by its displacement from where it was picked. */
    public void moveTo(double px, double py, double pz) {
        dx = px - x;
        dy = py - y;
        dz = pz - z;
        for (int s = 0; s < held.length; s++) held[s].moveTarget(start[s][0] + dx, start[s][1] + dy, start[s][2] + dz);
    }

    /** The pointer's displacement from where the particle was picked. */
    private double dx, dy, dz;

    /**
     * Keeps holding the particle in a scene that replaced the one it was held in (a cloth that tore goes on as
     * a new scene; its particles keep their indices), at the same target.
     */
    public void follow(SketchState state) {
        List<Scene> running = state.running();
        if (running.size() != scenes.length) return;
        for (int s = 0; s < scenes.length; s++)
            if (running.get(s) != scenes[s]) {
                scenes[s] = running.get(s);
                held[s] = scenes[s].simulation().attach(particle, start[s][0] + dx, start[s][1] + dy, start[s][2] + dz);
            }
    }

    /** Lets go in every scene it holds (scenes replaced since are not touched). */
    public void release() {
        for (int s = 0; s < held.length; s++) scenes[s].simulation().release(held[s]);
    }
}
