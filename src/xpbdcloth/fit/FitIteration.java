package xpbdcloth.fit;

/** One iteration of a fit: the loss, its gradient and the parameters it reached. */
public final class FitIteration {
    public final int index;
    /** L (m²) and the RMS distance of the free particles to the observation (m; over every observed frame). */
    public final double loss, rms;
    /** |∂L/∂θ| (m², per unit of ln α or ln c). */
    public final double gradientNorm;
    /** α per fitted family (m/N), in the fit's family order. */
    public final double[] compliance;
    /** The damping rate c (1/s), or NaN when it is not fitted. */
    public final double damping;
    /** Forward solves so far: equilibria (static fit) or simulated trajectories (dynamic fit). */
    public final int solves;

    FitIteration(int index, double loss, double rms, double gradientNorm, double[] compliance, double damping, int solves) {
        this.index = index;
        this.loss = loss;
        this.rms = rms;
        this.gradientNorm = gradientNorm;
        this.compliance = compliance;
        this.damping = damping;
        this.solves = solves;
    }
}
