package xpbdcloth.engine;

/**
 * A scalar constraint C(x) = 0 on a few particles, with both projections in one place so a whole
 * simulation can switch formulation while it runs.
 *
 * <p>For a constraint with gradients ∇ᵢC and inverse masses wᵢ, one projection moves each particle by
 * Δxᵢ = wᵢ ∇ᵢC Δλ, where ({@link #deltaLambda})
 * <ul>
 *   <li>PBD (Müller et al. 2007, eq. 5): Δλ = −k'·C / Σ wᵢ|∇ᵢC|², with k' = 1 − (1 − k)^(1/n) for n
 *       sweeps, so that n sweeps of one isolated constraint remove the fraction k of its error (or the raw
 *       k when the correction is switched off);</li>
 *   <li>XPBD (Macklin et al. 2016, eq. 18): Δλ = (−C − α̃λ) / (Σ wᵢ|∇ᵢC|² + α̃), α̃ = α/h², λ += Δλ,
 *       with λ reset to 0 once per substep, never per sweep. λ is then the constraint's impulse over the
 *       substep times h, so the force it applies is λ/h².</li>
 * </ul>
 * Limiting cases: α → 0 gives PBD with k = 1 (a hard constraint); α → ∞ gives Δλ → 0 (no constraint).
 *
 * <p>An object of this class is a view of one entry of a {@link ConstraintBlock}, where the data lives
 * in flat arrays and the solvers work. A constraint made with a public constructor starts in a block of
 * its own; {@link Simulation#add(Constraint)} moves it into the simulation's, and the view follows.
 */
public abstract class Constraint {
    ConstraintBlock block;
    int index;

    Constraint(ConstraintBlock block, int index) {
        this.block = block;
        this.index = index;
    }

    /**
     * Δλ for an equality constraint with value C, Σ wᵢ|∇ᵢC|² = {@code wGradSq} and the λ accumulated so
     * far, in the context's mode (compliance α for XPBD, k' for PBD). 0 when nothing can move (all
     * particles pinned and α = 0). The one place where the two formulations differ.
     */
    static double deltaLambda(double C, double wGradSq, double lambda, double compliance, double stiffnessPerSweep, ConstraintMode mode, SolverContext ctx) {
        if (mode == ConstraintMode.XPBD) {
            double alphaTilde = compliance * ctx.inverseH2;
            double denominator = wGradSq + alphaTilde;
            if (denominator <= 0) return 0;
            return (-C - alphaTilde * lambda) / denominator;
        }
        if (wGradSq <= 0) return 0;
        return -stiffnessPerSweep * C / wGradSq;
    }

    /**
     * Δλ for a hard constraint (k = 1, α = 0, the same in both modes), for the transient contacts,
     * which accumulate no λ. 0 when nothing can move.
     */
    static double hardDeltaLambda(double C, double wGradSq) {
        return wGradSq <= 0 ? 0 : -C / wGradSq;
    }

    public final ConstraintFamily family() { return block.family(); }
    /** PBD stiffness k ∈ [0, 1], dimensionless. */
    public final double stiffness() { return block.stiffness(index); }
    /** XPBD compliance α ≥ 0, m/N (the inverse of stiffness). */
    public final double compliance() { return block.compliance(index); }

    /** PBD stiffness k ∈ [0, 1]. */
    public final void setStiffness(double k) { block.setStiffness(index, k); }

    /** XPBD compliance α ≥ 0 in m/N. */
    public final void setCompliance(double alpha) { block.setCompliance(index, alpha); }

    /** The λ accumulated so far in this substep (XPBD; in PBD mode, the sum of the Δλ applied). */
    public final double lambda() { return block.lambda[index]; }

    /** The force magnitude this constraint applied over the last substep of length h: |λ| / h² (N). */
    public final double force(double h) { return Math.abs(lambda()) / (h * h); }

    /** k' for the current iteration count (or k without Müller's correction). */
    public final double stiffnessPerSweep() { return block.stiffnessPerSweep(index); }

    /** The particles this constraint acts on, in the order {@link #gradient} reports them. */
    public final int[] particles() {
        int[] ps = new int[block.arity()];
        for (int k = 0; k < ps.length; k++) ps[k] = block.particle(index, k);
        return ps;
    }

    /** C(x) at the current positions. */
    public final double evaluate(Particles p) { return block.evaluate(index, p); }

    /**
     * ∇C at the current positions, three components per particle of {@link #particles()}, written into
     * {@code out}. Where C has no gradient (a degenerate configuration) writes zeros.
     */
    public final void gradient(Particles p, double[] out) { block.gradient(index, p, out); }

    /** One projection of this constraint (with the rows it is solved with) in the context's mode. */
    final void project(Particles p, SolverContext ctx) { block.project(index / block.rowsPerUnit(), p, ctx); }

    /** Resets the λ of this constraint's whole block and refreshes its k' (tests of a lone constraint). */
    final void beginSubstep(SolverContext ctx) { block.beginSubstep(ctx); }

    @Override public final boolean equals(Object o) {
        return o instanceof Constraint && ((Constraint) o).block == block && ((Constraint) o).index == index;
    }

    @Override public final int hashCode() { return 31 * System.identityHashCode(block) + index; }
}
