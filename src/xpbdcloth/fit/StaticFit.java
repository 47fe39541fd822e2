package xpbdcloth.fit;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.Simulation;

/**
 * Fits the compliances of chosen families so the cloth's rest shape matches an observed one.
 *
 * <pre>
 *   loss     L(θ) = ½ Σᵢ |xᵢ(θ) − x̂ᵢ|²               (free particles; x(θ) solves ∇E(x; θ) = 0, θ_f = ln s_f)
 *   IFT      H ∂x/∂θ_f = F_f,   H = ∇²E,   F_f = Σ_{j∈f} Cⱼ∇Cⱼ/αⱼ      ({@link ClothEnergy})
 *   adjoint  H μ = x − x̂,       ∂L/∂θ_f = F_f · μ                     (one solve for the whole gradient)
 *   step     (JᵀJ + λ diag JᵀJ) δ = −Jᵀr,   J = [∂x/∂θ_f],  r = x − x̂  (Levenberg–Marquardt on Gauss–Newton)
 * </pre>
 * Differentiated: the converged equilibrium, through the implicit function theorem (∇E = 0 holds at every
 * θ, so dx/dθ = H⁻¹F). Assumed: the observation is at rest, no contact touches the cloth, no tether is
 * stretched, and the equilibrium found is the one observed (Newton starts from the observation itself).
 * Why log space: compliances of one cloth span ten decades (1e-8 for a stiff structure, 1e-2 for a soft
 * bend); a step in ln α is a relative change, the same size for each. Why Gauss–Newton: the parameters are
 * few (one per family), so J costs a back-substitution each with the factor the equilibrium already made,
 * and near a fit with small residual JᵀJ is the Hessian of L; Levenberg's λ keeps steps where it is not.
 */
public final class StaticFit implements MaterialFit {
    /** A step in ln α larger than this (a factor of e³ ≈ 20) is cut to it: the linearisation is not trusted further. */
    static final double MAX_LOG_STEP = 3;
    /** Converged when no ln α moves by more than this (a relative change of 1e-7). */
    static final double STEP_TOLERANCE = 1e-7;

    private final ClothEnergy energy;
    private final double[] observed;
    private final double weight;
    private final List<ConstraintFamily> families;
    private double[] theta;
    private Equilibrium current;
    private double loss;
    private double lambda = 1e-3;
    private boolean converged;
    private int solves;
    private final List<FitIteration> history = new ArrayList<>();

    /**
     * A fit of {@code families} of the simulation's cloth to {@code observed} (3 per particle, the scene's
     * vertex order), starting from the scene's compliances times {@code startFactor} (1 for as they are).
     */
    public StaticFit(Simulation sim, List<ConstraintFamily> families, double[] observed, double startFactor) {
        if (families.isEmpty()) throw new IllegalArgumentException("params must name at least one family, was empty");
        if (!(startFactor > 0) || !Double.isFinite(startFactor)) throw new IllegalArgumentException("startFactor must be a positive number, was " + startFactor);
        this.energy = new ClothEnergy(sim, families);
        this.families = List.copyOf(families);
        double[] scene = sim.particles().positions();
        if (observed.length != scene.length)
            throw new IllegalArgumentException("observed must have " + scene.length / 3 + " vertices (the scene's), was " + observed.length / 3);
        // The observation's free particles; the pinned ones are where the scene holds them.
        this.observed = scene.clone();
        for (int c = 0; c < scene.length; c++) if (energy.dofOf[c] >= 0) this.observed[c] = observed[c];
        weight = RestShape.heaviestWeight(sim);
        theta = new double[families.size()];
        java.util.Arrays.fill(theta, Math.log(startFactor));
        current = equilibrium(theta, this.observed);
        loss = lossAt(current);
        history.add(record());
    }

    private static double sq(double v) { return v * v; }

    @Override public List<ConstraintFamily> families() { return families; }
    @Override public boolean fitsDamping() { return false; }
    @Override public String kind() { return "static"; }
    @Override public String solvesName() { return "equilibrium_solves"; }
    @Override public List<FitIteration> history() { return Collections.unmodifiableList(history); }
    @Override public boolean converged() { return converged; }
    @Override public double[] compliance() { return compliance(theta); }
    @Override public double[] scale() {
        double[] s = new double[theta.length];
        for (int f = 0; f < s.length; f++) s[f] = Math.exp(theta[f]);
        return s;
    }

    /** α per fitted family at θ: the scene's α times e^θ. */
    private double[] compliance(double[] th) {
        double[] a = new double[th.length];
        for (int f = 0; f < a.length; f++) a[f] = energy.sceneCompliance(f) * Math.exp(th[f]);
        return a;
    }

    private Equilibrium equilibrium(double[] th, double[] start) {
        energy.setLogScales(th);
        Equilibrium eq = Equilibrium.solve(energy, start, weight);
        solves++;
        if (!eq.converged)
            throw new FitException("no rest shape found at α = " + java.util.Arrays.toString(compliance(th)) + " (after " + eq.iterations
                    + " Newton iterations a particle is still off balance by " + String.format(java.util.Locale.ROOT, "%.2e", eq.forceResidual) + " N)");
        if (eq.factor == null)
            throw new FitException("the rest shape at α = " + java.util.Arrays.toString(compliance(th))
                    + " is not a stable equilibrium (its Hessian is not positive definite: the cloth would buckle away from it)");
        return eq;
    }

    private double lossAt(Equilibrium eq) {
        double s = 0;
        for (int c = 0; c < observed.length; c++) if (energy.dofOf[c] >= 0) s += sq(eq.positions[c] - observed[c]);
        return s / 2;
    }

    private double[] residual(Equilibrium eq) {
        double[] r = new double[energy.freeDofs];
        for (int c = 0; c < observed.length; c++) if (energy.dofOf[c] >= 0) r[energy.dofOf[c]] = eq.positions[c] - observed[c];
        return r;
    }

    /** L at θ (a fresh equilibrium from the current one; the fit's state is unchanged). For checks. */
    double lossAt(double[] th) {
        Equilibrium eq = equilibrium(th, current.positions);
        energy.setLogScales(theta);
        return lossAt(eq);
    }

    /** ∂L/∂θ at the current θ by the adjoint: one solve H μ = r, then F_f · μ per family. */
    double[] gradient() {
        energy.setLogScales(theta);
        double[] mu = residual(current);
        current.factor.solve(mu);
        double[] g = new double[theta.length], force = new double[energy.freeDofs];
        for (int f = 0; f < g.length; f++) {
            energy.familyForce(current.positions, f, force);
            g[f] = Equilibrium.dot(force, mu);
        }
        return g;
    }

    /** ∂x/∂θ_f on the free coordinates, one column per family (a back-substitution each). */
    double[][] sensitivities() {
        energy.setLogScales(theta);
        double[][] j = new double[theta.length][];
        for (int f = 0; f < j.length; f++) {
            j[f] = new double[energy.freeDofs];
            energy.familyForce(current.positions, f, j[f]);
            current.factor.solve(j[f]);
        }
        return j;
    }

    double[] theta() { return theta.clone(); }

    /** The largest force (N) left on a free particle at the current rest shape. */
    double forceResidual() { return current.forceResidual; }

    /** One Levenberg–Marquardt iteration; false once converged (then it does nothing). */
    @Override public boolean iterate() {
        if (converged) return false;
        double[][] jac = sensitivities();
        double[] r = residual(current);
        int p = theta.length;
        double[][] jtj = new double[p][p];
        double[] jtr = new double[p];
        for (int a = 0; a < p; a++) {
            jtr[a] = Equilibrium.dot(jac[a], r);
            for (int b = 0; b < p; b++) jtj[a][b] = Equilibrium.dot(jac[a], jac[b]);
        }
        double growth = 2;
        for (int attempt = 0; attempt < 40; attempt++) {
            double[] delta = solveDamped(jtj, jtr, lambda);
            // Each ln α moves at most MAX_LOG_STEP: a poorly seen family must not drag the others' step along.
            for (int a = 0; a < p; a++) delta[a] = Math.max(-MAX_LOG_STEP, Math.min(MAX_LOG_STEP, delta[a]));
            double predicted = 0; // the Gauss–Newton model's decrease, −(Jᵀr·δ + ½ δᵀJᵀJδ)
            for (int a = 0; a < p; a++) {
                predicted -= jtr[a] * delta[a];
                for (int b = 0; b < p; b++) predicted -= 0.5 * delta[a] * jtj[a][b] * delta[b];
            }
            double[] next = theta.clone();
            for (int a = 0; a < p; a++) next[a] += delta[a];
            Equilibrium eq = null;
            try {
                eq = equilibrium(next, current.positions);
            } catch (FitException unstable) {
                // a step into a buckled or unconverged rest shape: shorter steps
            }
            double l = eq == null ? Double.POSITIVE_INFINITY : lossAt(eq);
            double gain = predicted > 0 ? (loss - l) / predicted : -1;
            if (eq != null && l < loss && gain > 1e-4) {
                theta = next;
                current = eq;
                energy.setLogScales(theta);
                loss = l;
                // Nielsen's update (Madsen, Nielsen, Tingleff 2004, §3.2): trust the model as far as it predicted.
                lambda = Math.max(lambda * Math.max(1.0 / 3, 1 - Math.pow(2 * gain - 1, 3)), 1e-12);
                converged = Equilibrium.maxAbs(delta) < STEP_TOLERANCE || l == 0;
                history.add(record());
                return !converged;
            }
            if (Equilibrium.maxAbs(delta) < STEP_TOLERANCE) break; // no smaller step lowers L: at the minimum to round-off
            lambda *= growth;
            growth *= 2;
        }
        converged = true;
        energy.setLogScales(theta);
        history.add(record());
        return false;
    }

    private FitIteration record() {
        double[] g = gradient();
        double norm = Math.sqrt(Equilibrium.dot(g, g));
        return new FitIteration(history.size(), loss, Math.sqrt(2 * loss / (energy.freeDofs / 3.0)), norm, compliance(), Double.NaN, solves);
    }

    /** (A + λ diag A) δ = −b for a small dense A (one row per family), by Gaussian elimination with pivoting. */
    static double[] solveDamped(double[][] a, double[] b, double lambda) {
        int n = b.length;
        double[][] m = new double[n][n + 1];
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) m[i][j] = a[i][j];
            m[i][i] += lambda * Math.max(a[i][i], 1e-300);
            m[i][n] = -b[i];
        }
        for (int c = 0; c < n; c++) {
            int piv = c;
            for (int r = c + 1; r < n; r++) if (Math.abs(m[r][c]) > Math.abs(m[piv][c])) piv = r;
            double[] t = m[c]; m[c] = m[piv]; m[piv] = t;
            if (m[c][c] == 0) continue;
            for (int r = c + 1; r < n; r++) {
                double f = m[r][c] / m[c][c];
                for (int k = c; k <= n; k++) m[r][k] -= f * m[c][k];
            }
        }
        double[] x = new double[n];
        for (int i = n - 1; i >= 0; i--) {
            double s = m[i][n];
            for (int k = i + 1; k < n; k++) s -= m[i][k] * x[k];
            x[i] = m[i][i] == 0 ? 0 : s / m[i][i];
        }
        return x;
    }
}
