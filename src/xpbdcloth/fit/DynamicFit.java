package xpbdcloth.fit;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.Simulation;

/**
 * Fits compliances and the damping rate so the simulated trajectory matches an observed one.
 *
 * <pre>
 *   loss   L(θ) = ½ Σ_frames Σᵢ |xᵢ(t_f; θ) − x̂ᵢ(t_f)|²     (free particles; x(t; θ) simulated from the scene's start)
 *   grad   ∂L/∂θ by reverse-mode differentiation of every substep ({@link TrajectoryAdjoint})
 *   step   BFGS on θ = (ln s_f…, ln c/c⁰), Armijo backtracking, each component of a step at most 3
 * </pre>
 * Why BFGS and not Gauss–Newton as the static fit: reverse mode gives Jᵀr, the whole gradient, for the
 * price of about eight simulations (two forward passes and the reverse one), but not J itself (that would be one reverse pass per observed
 * coordinate); with four parameters BFGS rebuilds their curvature from gradients in a few steps.
 * Differentiated: the trajectory as the solver ran it (its fixed sweep count, not a converged solve),
 * so the fit recovers the parameters of this simulator at these settings; the observation is taken at the
 * scene's own dt, from the scene's start state, every step.
 */
public final class DynamicFit implements MaterialFit {
    /** A step in a log-parameter larger than this (a factor of e³ ≈ 20) is scaled down to it. */
    static final double MAX_LOG_STEP = 3;
    /** Converged when no log-parameter moves by more than this. */
    static final double STEP_TOLERANCE = 1e-7;
    /** Armijo's sufficient decrease. */
    private static final double ARMIJO = 1e-4;

    private final TrajectoryAdjoint adjoint;
    private final double[][] observed;
    private final int freeParticles;
    private double[] theta, gradient;
    private double loss;
    /** The inverse-Hessian estimate, null until the first step has measured the curvature. */
    private double[][] inverse;
    private boolean converged;
    private int simulations;
    private final List<FitIteration> history = new ArrayList<>();

    /**
     * A fit of {@code families} (and the damping rate, if {@code fitsDamping}) of the simulation's cloth to
     * {@code observed}: the positions after each of the first observed.length steps, 3 per particle in the
     * scene's order. Starts from the scene's values times {@code startFactor}.
     */
    public DynamicFit(Simulation sim, List<ConstraintFamily> families, boolean fitsDamping, double[][] observed, double startFactor) {
        this(sim, families, fitsDamping, observed, filled(families.size() + (fitsDamping ? 1 : 0), startFactor));
    }

    /** Starts from the scene's values times a factor per parameter (families in order, then the damping). */
    public DynamicFit(Simulation sim, List<ConstraintFamily> families, boolean fitsDamping, double[][] observed, double[] startFactors) {
        if (observed.length == 0) throw new IllegalArgumentException("observed must hold at least one frame, was empty");
        adjoint = new TrajectoryAdjoint(sim, families, fitsDamping);
        int n = adjoint.particles();
        for (int f = 0; f < observed.length; f++)
            if (observed[f].length != 3 * n)
                throw new IllegalArgumentException("observed frame " + (f + 1) + " must have " + n + " vertices (the scene's), was " + observed[f].length / 3);
        this.observed = observed;
        int free = 0;
        for (int i = 0; i < n; i++) if (!adjoint.isPinned(i)) free++;
        freeParticles = free;
        if (startFactors.length != adjoint.parameters()) throw new IllegalArgumentException("startFactors must have " + adjoint.parameters() + " values, was " + startFactors.length);
        theta = new double[adjoint.parameters()];
        for (int p = 0; p < theta.length; p++) {
            if (!(startFactors[p] > 0) || !Double.isFinite(startFactors[p])) throw new IllegalArgumentException("start factor must be a positive number, was " + startFactors[p]);
            theta[p] = Math.log(startFactors[p]);
        }
        evaluate(theta);
        history.add(record());
    }

    private static double[] filled(int length, double value) {
        double[] a = new double[length];
        java.util.Arrays.fill(a, value);
        return a;
    }

    @Override public List<ConstraintFamily> families() { return adjoint.families; }
    @Override public boolean fitsDamping() { return adjoint.fitsDamping; }
    @Override public String kind() { return "dynamic"; }
    @Override public String solvesName() { return "simulations"; }
    @Override public List<FitIteration> history() { return Collections.unmodifiableList(history); }
    @Override public boolean converged() { return converged; }
    @Override public double[] scale() {
        double[] s = new double[adjoint.families.size()];
        for (int f = 0; f < s.length; f++) s[f] = Math.exp(theta[f]);
        return s;
    }

    /** Frames observed, each one step of the scene's dt. */
    public int frames() { return observed.length; }

    private void evaluate(double[] th) {
        double[] l = new double[1];
        gradient = adjoint.gradient(th, observed, l);
        loss = l[0];
        simulations += 3;
    }

    private double lossAt(double[] th) {
        simulations++;
        return adjoint.loss(th, observed);
    }

    @Override public boolean iterate() {
        if (converged) return false;
        int p = theta.length;
        double[] direction = new double[p];
        if (inverse != null) {
            for (int a = 0; a < p; a++) for (int b = 0; b < p; b++) direction[a] -= inverse[a][b] * gradient[b];
        }
        if (inverse == null || dot(direction, gradient) >= 0) {
            // No curvature yet (or it lost positive definiteness): steepest descent, at most ½ in ln.
            double scale = 0.5 / Math.max(maxAbs(gradient), 1e-300);
            for (int a = 0; a < p; a++) direction[a] = -scale * gradient[a];
            inverse = null;
        }
        double cap = maxAbs(direction);
        if (cap > MAX_LOG_STEP) for (int a = 0; a < p; a++) direction[a] *= MAX_LOG_STEP / cap;
        double slope = dot(gradient, direction);
        double t = 1;
        double[] next = new double[p];
        for (int attempt = 0; attempt < 40; attempt++) {
            for (int a = 0; a < p; a++) next[a] = theta[a] + t * direction[a];
            double trial = lossAt(next);
            if (Double.isFinite(trial) && trial <= loss + ARMIJO * t * slope) {
                if (attempt == 0) {
                    // The full step was taken: try longer ones while they keep lowering L. Along a flat valley (a family
                    // the trajectory hardly sees) BFGS's early curvature estimate is far too steep, and without this it
                    // crawls: on drape's 1 s fit from (0.1, 10, 0.1, 10) × the truth, 42 iterations to converge instead of 29.
                    while (t * 2 * maxAbs(direction) <= MAX_LOG_STEP) {
                        double[] longer = new double[p];
                        for (int a = 0; a < p; a++) longer[a] = theta[a] + 2 * t * direction[a];
                        double l = lossAt(longer);
                        if (!(l < trial)) break;
                        trial = l;
                        next = longer;
                        t *= 2;
                    }
                }
                double[] oldTheta = theta, oldGradient = gradient;
                double oldLoss = loss;
                theta = next;
                evaluate(theta);
                update(sub(theta, oldTheta), sub(gradient, oldGradient));
                converged = t * maxAbs(direction) < STEP_TOLERANCE || loss == 0 || oldLoss - loss <= 1e-15 * oldLoss;
                history.add(record());
                return !converged;
            }
            if (t * maxAbs(direction) < STEP_TOLERANCE) break;
            t /= 2;
        }
        converged = true; // no step along the descent direction lowers L: at its minimum to round-off
        history.add(record());
        return false;
    }

    /** The BFGS update of the inverse Hessian (Nocedal & Wright 2006, eq. 6.17), scaled by yᵀs/yᵀy the first time (eq. 6.20). */
    private void update(double[] s, double[] y) {
        double ys = dot(y, s);
        if (!(ys > 1e-300)) return; // no positive curvature measured: keep the estimate
        int p = s.length;
        if (inverse == null) {
            inverse = new double[p][p];
            double scale = ys / dot(y, y);
            for (int a = 0; a < p; a++) inverse[a][a] = scale;
        }
        double rho = 1 / ys;
        double[] hy = new double[p];
        for (int a = 0; a < p; a++) for (int b = 0; b < p; b++) hy[a] += inverse[a][b] * y[b];
        double yhy = dot(y, hy);
        for (int a = 0; a < p; a++)
            for (int b = 0; b < p; b++)
                inverse[a][b] += -rho * (hy[a] * s[b] + s[a] * hy[b]) + (rho * rho * yhy + rho) * s[a] * s[b];
    }

    private FitIteration record() {
        double[] values = adjoint.values(theta);
        int nf = adjoint.families.size();
        double[] alpha = java.util.Arrays.copyOf(values, nf);
        double damping = adjoint.fitsDamping ? values[nf] : Double.NaN;
        double rms = Math.sqrt(2 * loss / ((double) freeParticles * observed.length));
        return new FitIteration(history.size(), loss, rms, Math.sqrt(dot(gradient, gradient)), alpha, damping, simulations);
    }

    private static double[] sub(double[] a, double[] b) {
        double[] d = new double[a.length];
        for (int i = 0; i < a.length; i++) d[i] = a[i] - b[i];
        return d;
    }

    private static double dot(double[] a, double[] b) {
        double s = 0;
        for (int i = 0; i < a.length; i++) s += a[i] * b[i];
        return s;
    }

    private static double maxAbs(double[] a) {
        double m = 0;
        for (double v : a) m = Math.max(m, Math.abs(v));
        return m;
    }
}
