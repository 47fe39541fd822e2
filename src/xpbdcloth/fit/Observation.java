package xpbdcloth.fit;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Random;
import xpbdcloth.engine.Particles;
import xpbdcloth.mesh.ObjReader;
import xpbdcloth.mesh.ObjWriter;
import xpbdcloth.scene.Scene;

/**
 * An observed cloth shape: one position per particle of a scene, in the scene's vertex order, read from
 * an OBJ (the project's own export writes them so; another tool must keep the order) and checked against
 * the scene before any fit starts.
 */
public final class Observation {
    /** A pinned vertex observed farther than this from where the scene pins it means another scene or frame. */
    static final double PIN_TOLERANCE = 0.01;

    private Observation() {}

    /** The observed positions, or a {@link FitException} saying why this file is not an observation of this scene. */
    public static double[] read(Path obj, Scene scene) {
        return check(obj.toString(), ObjReader.vertices(obj), scene);
    }

    static double[] check(String file, double[] observed, Scene scene) {
        Particles p = scene.simulation().particles();
        if (observed.length != 3 * p.count())
            throw new FitException(file + " has " + observed.length / 3 + " vertices and scene " + scene.preset().name + " has " + p.count()
                    + ": an observation lists the scene's vertices in the scene's order (write one with `xpbd-cloth fit --make-observation`)");
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (int c = 0; c < observed.length; c++) {
            if (!Double.isFinite(observed[c])) throw new FitException(file + ": vertex " + (c / 3 + 1) + " is not finite");
            lo = Math.min(lo, observed[c]);
            hi = Math.max(hi, observed[c]);
        }
        if (hi - lo < 1e-9) throw new FitException(file + ": every vertex is at one point; that is no cloth shape to fit");
        for (int i = 0; i < p.count(); i++) {
            if (!p.isPinned(i)) continue;
            double d = Math.sqrt(sq(observed[3 * i] - p.x(i)) + sq(observed[3 * i + 1] - p.y(i)) + sq(observed[3 * i + 2] - p.z(i)));
            if (d > PIN_TOLERANCE)
                throw new FitException(String.format(Locale.ROOT, "%s: vertex %d is pinned by scene %s at (%.3f, %.3f, %.3f) but observed %.3f m away,"
                        + " farther than %.0f mm: is this an observation of another scene, or in another frame?", file, i + 1, scene.preset().name,
                        p.x(i), p.y(i), p.z(i), d, PIN_TOLERANCE * 1e3));
        }
        return observed.clone();
    }

    /** Each coordinate plus Gaussian noise of standard deviation sigma (m), reproducibly from seed. */
    public static double[] withNoise(double[] positions, double sigma, long seed) {
        if (!(sigma >= 0) || !Double.isFinite(sigma)) throw new IllegalArgumentException("noise must be >= 0 and finite, was " + sigma);
        Random r = new Random(seed);
        double[] out = positions.clone();
        for (int c = 0; c < out.length; c++) out[c] += sigma * r.nextGaussian();
        return out;
    }

    /** Writes positions as an OBJ of the scene's mesh (its faces, its vertex order). */
    public static void write(Path obj, Scene scene, double[] positions, String comment) throws IOException {
        ObjWriter.write(obj, scene.cloth().mesh(), positions, comment);
    }

    private static double sq(double v) { return v * v; }
}
