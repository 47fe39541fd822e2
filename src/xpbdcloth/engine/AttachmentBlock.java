package xpbdcloth.engine;

import java.util.Arrays;

/**
 * Attachments: each holds a particle i at a movable target point t (the mouse grab, or any art-directed
 * handle).
 *
 * <pre>
 *   C(x) = |x − t|,   ∇C = (x − t)/|x − t|,   Σ wᵢ|∇ᵢC|² = w
 * </pre>
 * Source: the attachment constraint of Müller et al. 2007 §4.4, as a zero-length distance constraint to
 * a point of infinite mass. It uses the simulation's mode like every other constraint, so a grabbed PBD
 * cloth and a grabbed XPBD cloth respond to the hand in their own way. Degenerate case: at the target
 * (C = 0) there is no direction and nothing to do.
 *
 * <p>The target glides: moved between steps ({@link #moveTarget}), it travels there along a straight line
 * over the step's substeps, as a hand moves continuously. A target that jumped at the step's start was
 * reached in the first substep and then held still, so a particle let go after a fast drag left at rest
 * instead of with the hand's velocity: the cloth could not be thrown.
 *
 * <p>A moving target does work on the cloth: the force F its projections exerted on the particle in a
 * substep (each correction δx is an impulse m δx/h, so F = Σ m δx/h²) times the particle's move in that
 * substep, W += F·Δx, which bounds what the force gave: implicit Euler's m(v' − v)/h = F makes the kinetic
 * energy change F·Δx − h²|F|²/2m. {@link #work} sums it, so an energy balance can count what a hand put in.
 */
public final class AttachmentBlock extends ConstraintBlock {
    /** t per constraint, xyz interleaved, m: where the target is in this substep. */
    double[] target;
    /** Where the target was when the step began, and where it is asked to be when the step ends. */
    private double[] start, goal;
    /** The force on each attachment's particle in this substep (N), xyz interleaved. */
    private double[] force;
    /** The work the moving targets have done on the cloth so far, J. */
    private double work;

    public AttachmentBlock(int capacity) {
        super(ConstraintFamily.ATTACHMENT, 1, capacity);
        target = new double[3 * lambda.length];
        start = new double[3 * lambda.length];
        goal = new double[3 * lambda.length];
        force = new double[3 * lambda.length];
    }

    /** Adds an attachment of particle i to (x, y, z); returns its index. */
    public int add(int particle, double x, double y, double z) {
        Check.atLeast("particle", particle, 0);
        EngineRange.vector("target", x, y, z, EngineRange.MAX_POSITION);
        int i = newSlot();
        particles[i] = particle;
        target[3 * i] = x; target[3 * i + 1] = y; target[3 * i + 2] = z;
        System.arraycopy(target, 3 * i, start, 3 * i, 3);
        System.arraycopy(target, 3 * i, goal, 3 * i, 3);
        return i;
    }

    /** The target as last asked for (reached by the end of the next step). */
    public double targetX(int i) { return goal[3 * i]; }
    public double targetY(int i) { return goal[3 * i + 1]; }
    public double targetZ(int i) { return goal[3 * i + 2]; }

    public void moveTarget(int i, double x, double y, double z) {
        EngineRange.vector("target", x, y, z, EngineRange.MAX_POSITION);
        goal[3 * i] = x; goal[3 * i + 1] = y; goal[3 * i + 2] = z;
    }

    /** Puts every target the given fraction (0, 1] of the way from where the step began to its goal. */
    void glide(double fraction) {
        for (int k = 0, n = 3 * count; k < n; k++)
            target[k] = fraction >= 1 ? goal[k] : start[k] + fraction * (goal[k] - start[k]);
    }

    /** The step is over: every target is at its goal, where the next step begins. */
    void arrive() {
        System.arraycopy(goal, 0, target, 0, 3 * count);
        System.arraycopy(goal, 0, start, 0, 3 * count);
    }

    /** Adds to attachment i's force in this substep (N): a solver that holds the particle on the target rather than projecting it there says what the hold cost. */
    void addForce(int i, double fx, double fy, double fz) {
        force[3 * i] += fx; force[3 * i + 1] += fy; force[3 * i + 2] += fz;
    }

    /** Forgets this substep's forces so far (a solve that is redone). */
    void forgetForces() { Arrays.fill(force, 0, 3 * count, 0); }

    /** After a substep's solve: adds F·Δx (Δx = x − x_prev, the particle's move in the substep) to the work, and starts the next substep's force at 0. */
    void countWork(Particles p) {
        double w = 0;
        for (int i = 0; i < count; i++) {
            int k = 3 * particles[i];
            for (int a = 0; a < 3; a++) {
                w += force[3 * i + a] * (p.x[k + a] - p.prev[k + a]);
                force[3 * i + a] = 0;
            }
        }
        work += w;
    }

    /**
     * The work the attachments have done on the cloth since this block was made, J: positive
     * where a hand pulled the cloth along, negative where it held the cloth back (a hard one held still does none).
     */
    public double work() { return work; }

    @Override public double evaluate(int i, Particles p) {
        int k = 3 * particles[i];
        double dx = p.x[k] - target[3 * i], dy = p.x[k + 1] - target[3 * i + 1], dz = p.x[k + 2] - target[3 * i + 2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    @Override public void gradient(int i, Particles p, double[] out) {
        int k = 3 * particles[i];
        double dx = p.x[k] - target[3 * i], dy = p.x[k + 1] - target[3 * i + 1], dz = p.x[k + 2] - target[3 * i + 2];
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double s = len < DistanceBlock.MIN_LENGTH ? 0 : 1 / len;
        out[0] = dx * s; out[1] = dy * s; out[2] = dz * s;
    }

    @Override void project(int i, Particles p, SolverContext ctx) {
        final double[] x = p.x;
        final int particle = particles[i], k = 3 * particle;
        double dx = x[k] - target[3 * i], dy = x[k + 1] - target[3 * i + 1], dz = x[k + 2] - target[3 * i + 2];
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        if (len < DistanceBlock.MIN_LENGTH) return;
        double w = p.w[particle];
        double s = w * deltaLambda(i, len, w, ctx) / len;
        x[k] += s * dx; x[k + 1] += s * dy; x[k + 2] += s * dz;
        if (w > 0) { // F += m δx / h²
            double f = s * ctx.inverseH2 / w;
            force[3 * i] += f * dx; force[3 * i + 1] += f * dy; force[3 * i + 2] += f * dz;
        }
    }

    @Override void projectRange(int from, int to, Particles p, SolverContext ctx) {
        for (int i = from; i < to; i++) project(i, p, ctx);
    }

    @Override void projectListed(int[] order, int from, int to, Particles p, SolverContext ctx) {
        for (int k = from; k < to; k++) project(order[k], p, ctx);
    }

    @Override AttachmentConstraint view(int i) { return new AttachmentConstraint(this, i); }

    @Override AttachmentBlock emptyLike(int capacity) { return new AttachmentBlock(capacity); }

    @Override void copyRest(int i, ConstraintBlock from, int j) {
        AttachmentBlock a = (AttachmentBlock) from;
        System.arraycopy(a.target, 3 * j, target, 3 * i, 3);
        System.arraycopy(a.start, 3 * j, start, 3 * i, 3);
        System.arraycopy(a.goal, 3 * j, goal, 3 * i, 3);
        System.arraycopy(a.force, 3 * j, force, 3 * i, 3);
    }

    @Override void grow(int capacity) {
        super.grow(capacity);
        target = Arrays.copyOf(target, 3 * capacity);
        start = Arrays.copyOf(start, 3 * capacity);
        goal = Arrays.copyOf(goal, 3 * capacity);
        force = Arrays.copyOf(force, 3 * capacity);
    }

    @Override void remove(int i) {
        for (double[] a : new double[][] {target, start, goal, force}) System.arraycopy(a, 3 * (i + 1), a, 3 * i, 3 * (count - i - 1));
        super.remove(i);
    }
}
