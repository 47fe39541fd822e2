package xpbdcloth.fabric;

import java.util.ArrayList;
import java.util.List;
import xpbdcloth.engine.AfterStep;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.MembraneBlock;
import xpbdcloth.engine.Particles;

/**
 * A membrane whose stiffness follows its strain as the measured fabric's does ({@link StretchingCurve}):
 * after every step, each triangle takes the curve's secant stiffness at the strain the step left, which the
 * next step solves with. At equilibrium the lag is gone: the stress is the data's at the cloth's own strain.
 * Serial and allocation-free (three numbers per triangle read, four written).
 */
public final class MeasuredStiffening implements AfterStep {
    private final MembraneBlock[] blocks;
    private StretchingCurve curve;
    private final double[] c = new double[3], q = new double[4];

    /** @param blocks a simulation's blocks; its {@link MembraneBlock}s follow the curve */
    public MeasuredStiffening(List<ConstraintBlock> blocks, StretchingCurve curve) {
        if (blocks == null) throw new IllegalArgumentException("blocks must not be null, was null");
        if (curve == null) throw new IllegalArgumentException("curve must not be null, was null");
        List<MembraneBlock> membranes = new ArrayList<>();
        for (ConstraintBlock b : blocks) if (b instanceof MembraneBlock) membranes.add((MembraneBlock) b);
        if (membranes.isEmpty()) throw new IllegalArgumentException("blocks have no membrane to stiffen (a cloth of springs)");
        this.blocks = membranes.toArray(new MembraneBlock[0]);
        this.curve = curve;
    }

    @Override public void check(List<ConstraintBlock> held) {
        for (MembraneBlock m : blocks)
            if (!held.contains(m)) throw new IllegalArgumentException("stiffening was made for blocks this simulation does not hold");
    }

    /**
     * Follows another fabric's curve from the next step (a fabric swapped live), or none: null leaves the membrane
     * as it is given ({@link FabricSwap} gives it the new fabric's linear moduli).
     */
    public void use(StretchingCurve next) { curve = next; }

    @Override public void afterStep(Particles p, double dt) {
        if (curve == null) return;
        for (MembraneBlock m : blocks)
            for (int t = 0, n = m.triangleCount(); t < n; t++) {
                m.rightCauchyGreen(t, p, c);
                curve.stiffness(c[0], c[1], c[2], q);
                m.setStiffness(t, q[0], q[1], q[2], q[3]);
            }
    }
}
