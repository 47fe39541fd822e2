package xpbdcloth.engine;

/**
 * Holds particle i at a movable target point t (the mouse grab, or any art-directed handle).
 *
 * <pre>
 *   C(x) = |x − t|,   ∇C = (x − t)/|x − t|,   Σ wᵢ|∇ᵢC|² = w
 * </pre>
 * Source: the attachment constraint of Müller et al. 2007 §4.4, as a zero-length distance constraint to
 * a point of infinite mass. It uses the simulation's mode like every other constraint, so a grabbed PBD
 * cloth and a grabbed XPBD cloth respond to the hand in their own way. Degenerate case: at the target
 * (C = 0) there is no direction and nothing to do.
 */
public final class AttachmentConstraint extends Constraint {
    final int i;
    double tx, ty, tz;

    public AttachmentConstraint(int particle, double x, double y, double z) {
        super(ConstraintFamily.ATTACHMENT);
        this.i = Check.atLeast("particle", particle, 0);
        moveTarget(x, y, z);
    }

    public int particle() { return i; }
    public double targetX() { return tx; }
    public double targetY() { return ty; }
    public double targetZ() { return tz; }

    public void moveTarget(double x, double y, double z) {
        EngineRange.vector("target", x, y, z, EngineRange.MAX_POSITION);
        tx = x; ty = y; tz = z;
    }

    @Override public int[] particles() { return new int[] {i}; }

    @Override public double evaluate(Particles p) {
        double dx = p.x[3 * i] - tx, dy = p.x[3 * i + 1] - ty, dz = p.x[3 * i + 2] - tz;
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    @Override public void gradient(Particles p, double[] out) {
        double dx = p.x[3 * i] - tx, dy = p.x[3 * i + 1] - ty, dz = p.x[3 * i + 2] - tz;
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double s = len < DistanceConstraint.MIN_LENGTH ? 0 : 1 / len;
        out[0] = dx * s; out[1] = dy * s; out[2] = dz * s;
    }

    @Override protected void project(Particles p, SolverContext ctx) {
        final double[] x = p.x;
        final int k = 3 * i;
        double dx = x[k] - tx, dy = x[k + 1] - ty, dz = x[k + 2] - tz;
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        if (len < DistanceConstraint.MIN_LENGTH) return;
        double w = p.w[i];
        double s = w * deltaLambda(len, w, ctx) / len;
        x[k] += s * dx; x[k + 1] += s * dy; x[k + 2] += s * dz;
    }
}
