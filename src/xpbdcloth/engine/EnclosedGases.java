package xpbdcloth.engine;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * A simulation's enclosed gases and held volumes ({@link EnclosedGas}): linearised once per substep, projected
 * once after every sweep of any solve stage, before the contacts (so hard contacts keep the last word), on the
 * thread that runs the contacts. Empty, it costs a size check per sweep.
 */
final class EnclosedGases {
    private final List<EnclosedGas> gases = new ArrayList<>();

    void add(EnclosedGas g) { gases.add(g); }

    boolean remove(EnclosedGas g) { return gases.remove(g); }

    int count() { return gases.size(); }

    List<EnclosedGas> view() { return Collections.unmodifiableList(gases); }

    void beginSubstep(Particles p, double h) {
        for (int k = 0, n = gases.size(); k < n; k++) gases.get(k).beginSubstep(p, h);
    }

    void project(Particles p) {
        for (int k = 0, n = gases.size(); k < n; k++) gases.get(k).project(p);
    }

    /** The same projections, the state checked after each. */
    void project(Particles p, StepProbe probe) {
        for (int k = 0, n = gases.size(); k < n; k++) {
            EnclosedGas g = gases.get(k);
            g.project(p);
            for (int l = 0, m = g.particleCount(); l < m; l++) probe.check(g.particle(l), ConstraintFamily.PRESSURE);
        }
    }
}
