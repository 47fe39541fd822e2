package xpbdcloth.engine;

/**
 * A scalar constraint C(x) = 0 (or C(x) ≥ 0 for contacts) on a few particles, with both projections in
 * one place so a whole simulation can switch formulation while it runs.
 *
 * <p>For a constraint with gradients ∇ᵢC and inverse masses wᵢ, one projection moves each particle by
 * Δxᵢ = wᵢ ∇ᵢC Δλ, where
 * <ul>
 *   <li>PBD (Müller et al. 2007, eq. 5): Δλ = −k'·C / Σ wᵢ|∇ᵢC|², with k' = 1 − (1 − k)^(1/n) for n
 *       sweeps, so that n sweeps of one isolated constraint remove the fraction k of its error (or the raw
 *       k when the correction is switched off);</li>
 *   <li>XPBD (Macklin et al. 2016, eq. 18): Δλ = (−C − α̃λ) / (Σ wᵢ|∇ᵢC|² + α̃), α̃ = α/h², λ += Δλ,
 *       with λ reset to 0 once per substep, never per sweep. λ is then the constraint's impulse over the
 *       substep times h, so the force it applies is λ/h².</li>
 * </ul>
 * Limiting cases: α → 0 gives PBD with k = 1 (a hard constraint); α → ∞ gives Δλ → 0 (no constraint).
 * Subclasses compute C and its gradient inline and call {@link #deltaLambda}.
 */
public abstract class Constraint {
    private final ConstraintFamily family;
    /** PBD stiffness k ∈ [0, 1], dimensionless. */
    private double stiffness = 1.0;
    /** XPBD compliance α ≥ 0, m/N (the inverse of stiffness). */
    private double compliance = 0.0;
    /** XPBD Lagrange multiplier accumulated over the current substep. */
    protected double lambda;

    private double stiffnessPerSweep = 1.0;
    private long preparedRevision = -1;

    protected Constraint(ConstraintFamily family) {
        if (family == null) throw new IllegalArgumentException("family must not be null, was null");
        this.family = family;
    }

    public final ConstraintFamily family() { return family; }
    public final double stiffness() { return stiffness; }
    public final double compliance() { return compliance; }

    /** PBD stiffness k ∈ [0, 1]. */
    public final void setStiffness(double k) {
        stiffness = Check.inRange("stiffness", k, 0, 1);
        preparedRevision = -1;
    }

    /** XPBD compliance α ≥ 0 in m/N. */
    public final void setCompliance(double alpha) {
        compliance = Check.inRange("compliance", alpha, 0, EngineRange.MAX_COMPLIANCE);
    }

    /** The λ accumulated so far in this substep (XPBD; in PBD mode, the sum of the Δλ applied). */
    public final double lambda() { return lambda; }

    /** The force magnitude this constraint applied over the last substep of length h: |λ| / h² (N). */
    public final double force(double h) { return Math.abs(lambda) / (h * h); }

    /** The particles this constraint acts on, in the order {@link #gradient} reports them. */
    public abstract int[] particles();

    /** C(x) at the current positions. */
    public abstract double evaluate(Particles p);

    /**
     * ∇C at the current positions, three components per particle of {@link #particles()}, written into
     * {@code out}. Where C has no gradient (a degenerate configuration) writes zeros.
     */
    public abstract void gradient(Particles p, double[] out);

    /** One projection of this constraint in the current mode. */
    protected abstract void project(Particles p, SolverContext ctx);

    /** Called once per substep before the sweeps: resets λ and refreshes k' if n or k changed. */
    void beginSubstep(SolverContext ctx) {
        lambda = 0;
        if (preparedRevision != ctx.revision) {
            stiffnessPerSweep = ctx.mullerCorrection && ctx.iterations > 1
                    ? 1.0 - Math.pow(1.0 - stiffness, 1.0 / ctx.iterations)
                    : stiffness;
            preparedRevision = ctx.revision;
        }
    }

    /** k' for the current iteration count (or k without Müller's correction). */
    public final double stiffnessPerSweep() { return stiffnessPerSweep; }

    /**
     * Δλ for an equality constraint with value C and Σ wᵢ|∇ᵢC|² = {@code wGradSq}, accumulated into λ.
     * Returns 0 when nothing can move (all particles pinned and α = 0).
     */
    protected final double deltaLambda(double C, double wGradSq, SolverContext ctx) {
        double dLambda;
        if (ctx.mode == ConstraintMode.XPBD) {
            double alphaTilde = compliance * ctx.inverseH2;
            double denominator = wGradSq + alphaTilde;
            if (denominator <= 0) return 0;
            dLambda = (-C - alphaTilde * lambda) / denominator;
        } else {
            if (wGradSq <= 0) return 0;
            dLambda = -stiffnessPerSweep * C / wGradSq;
        }
        lambda += dLambda;
        return dLambda;
    }

    /**
     * Takes back the part (1 − scale) of a Δλ just returned by {@link #deltaLambda}, for a constraint
     * that shortens its own step (a trust region) and still wants λ to be the sum of what it applied.
     */
    protected final void shortenLastStep(double dLambda, double scale) {
        lambda -= dLambda * (1 - scale);
    }

    /**
     * Δλ for a hard constraint (k = 1, α = 0, the same in both modes); static, because transient contacts
     * have no constraint object to accumulate it in. 0 when nothing can move.
     */
    static double hardDeltaLambda(double C, double wGradSq) {
        return wGradSq <= 0 ? 0 : -C / wGradSq;
    }
}
