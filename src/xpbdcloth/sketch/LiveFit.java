package xpbdcloth.sketch;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.Material;
import xpbdcloth.fit.StaticFit;
import xpbdcloth.scene.Preset;
import xpbdcloth.scene.Scene;

/**
 * A fit of the running cloth's spring compliances to an observed rest shape, stepped one Gauss–Newton
 * iteration a frame so its progress shows: the observation drawn as a ghost, the loss in the HUD plot.
 * It fits a fresh copy of the scene with the sketch's current α (the a/A keys move the start), so the
 * running cloth is not touched until the fit ends and hands over its α.
 */
final class LiveFit {
    static final int MAX_ITERATIONS = 30;
    static final List<ConstraintFamily> SPRINGS = List.of(ConstraintFamily.STRUCTURAL, ConstraintFamily.SHEAR, ConstraintFamily.BEND);

    final String source;
    final double[] observed;
    /** The mesh's edges, each once, as vertex pairs: the ghost wireframe. */
    final int[] edges;
    final StaticFit fit;
    /** The loss of each iteration as the RMS distance to the observation, mm (the HUD plot). */
    final History rmsMm = new History(MAX_ITERATIONS + 1);
    /** The same, as the HUD's plot takes its series (made once, not per frame). */
    final History[] plotted = {rmsMm};
    boolean finished;

    LiveFit(Preset preset, Map<ConstraintFamily, Material> materials, double[] observed, String source) {
        Scene copy = Scene.of(preset);
        List<ConstraintFamily> families = new ArrayList<>();
        for (ConstraintFamily f : SPRINGS)
            if (materials.containsKey(f)) {
                families.add(f);
                copy.simulation().setMaterial(f, materials.get(f));
            }
        if (families.isEmpty()) throw new IllegalArgumentException("fit: this cloth has no spring families (structural, shear, bend) whose compliance a fit could find");
        this.fit = new StaticFit(copy.simulation(), families, observed, 1);
        this.observed = observed;
        this.source = source;
        edges = xpbdcloth.mesh.MeshTopology.of(copy.cloth().mesh()).edges();
        rmsMm.add(1e3 * fit.last().rms);
    }

    /** One iteration; false once converged or out of iterations. */
    boolean iterate() {
        if (finished) return false;
        boolean more = fit.iterate() && fit.last().index < MAX_ITERATIONS;
        rmsMm.add(1e3 * fit.last().rms);
        finished = !more;
        return more;
    }
}
