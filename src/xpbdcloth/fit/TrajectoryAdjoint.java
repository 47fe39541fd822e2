package xpbdcloth.fit;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.ConstraintOrder;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SolverSettings;
import xpbdcloth.engine.SolverType;

/**
 * A scene's XPBD trajectory as a function of its compliances and damping, and the gradient of a
 * trajectory loss by reverse-mode differentiation of the substep loop as it ran.
 *
 * <p>Forward, per substep h (the engine's stages, {@code Simulation}): predict v₁ = v + h·g, p = x + h·v₁;
 * n Gauss–Seidel sweeps, each constraint j in order
 * <pre>
 *   Δλ = (−C(p) − α̃ⱼλⱼ) / (Σᵢ wᵢ|∇ᵢC|² + α̃ⱼ),   pᵢ += wᵢ ∇ᵢC Δλ,   λⱼ += Δλ      (α̃ⱼ = αⱼ/h², λ = 0 per substep)
 * </pre>
 * then v' = (p − x)/h, v'' = v'·e^(−c·h), x = p. C and ∇C are each block's own {@code evaluate} and
 * {@code gradient}, the functions its {@code project} is written with; the replay is checked against the
 * engine's trajectory ({@link #replayGap}), because the engine's safety limits (a shear's trust region, a
 * degenerate edge skipped) are not differentiated here.
 *
 * <p>Reverse, one projection (adjoints x̄ of p, λ̄ of λ; D = Σwᵢ|∇ᵢC|² + α̃, N = −C − α̃λ, Δλ = N/D):
 * <pre>
 *   Δλ̄ = λ̄ + Σᵢ wᵢ∇ᵢC·x̄ᵢ,   N̄ = Δλ̄/D,   D̄ = −Δλ̄·Δλ/D
 *   x̄ ← x̄ − N̄·∇C + ∇²C·ḡ,    ḡᵢ = wᵢΔλ·x̄ᵢ + 2D̄·wᵢ∇ᵢC,    λ̄ ← λ̄ − N̄α̃,    θ̄ += (D̄ − N̄λ)·α̃
 * </pre>
 * where ∇²C·ḡ is the central difference of the block's own ∇C along ḡ ({@link DirectionalDifference}, the step
 * shrunk until two levels agree: near a flat triangle bend ∇²C grows as 1/|d| and a fixed step would miss it).
 * Predict, velocity update and damping are linear and reversed by hand.
 *
 * <p>Memory: the state (x, v) at the start of every frame (6 doubles per particle per frame, growing
 * linearly with the frames: 12 KB a frame for a 16² cloth) and one frame's tape (the particles' positions
 * and λ before each projection of its substeps, 4.6 MB with the other working arrays for the 16² drape at 5 substeps
 * × 10 sweeps, made once), re-made from the frame's checkpoint when the frame is reversed. A frame is simulated twice per
 * gradient: the pass that stores the checkpoints and the taped one.
 *
 * <p>Parameters θ: ln s_f per fitted family (αⱼ = s_f·αⱼ⁰, the scene's αⱼ⁰), then ln(c/c⁰) for the damping
 * rate c if it is fitted. Assumed: no contacts, attachments, scripted pins or external forces (refused),
 * XPBD, Gauss–Seidel in the order built on one thread.
 */
final class TrajectoryAdjoint {
    private final Particles scratch;
    private final double[] x0, v0, w;
    private final double h, gx, gy, gz, damping0;
    private final int substeps, iterations, n;
    private final ConstraintBlock[] blocks;
    /** Parameter of each block (−1 when its family is not fitted) and the offset of its first λ. */
    private final int[] parameterOf, lambdaOffset;
    /** αⱼ⁰ per constraint, flat over the blocks. */
    private final double[] alpha0;
    final List<ConstraintFamily> families;
    final boolean fitsDamping;
    private final int parameters;
    /** The first step of ∇²C·ḡ's differences (1e-5 of the shortest edge), and how often it may be quartered. */
    private final double fdStep;
    private static final int SHRINKS = 8;

    // Working state, made once.
    /** The velocity at the end of each substep of the frame being reversed (the damping's derivative needs it). */
    private final double[][] endV;
    /** Tape entries of one substep (the projections' inputs over its sweeps). */
    private final int substepTape;
    private final double[] v, prev, lambda, alphaTilde, tape, hu = new double[3 * ConstraintBlock.MAX_ARITY];
    /** A unit's rows (at most {@link #ROWS}): their ∇C, adjoints of ∇C, C, the matrix A and the Δλ and adjoints solved with it. */
    private static final int ROWS = 3;
    private final double[][] grad = new double[ROWS][3 * ConstraintBlock.MAX_ARITY], gBar = new double[ROWS][3 * ConstraintBlock.MAX_ARITY];
    private final double[] cOf = new double[ROWS], rhs = new double[ROWS], dLambda = new double[ROWS], nBar = new double[ROWS], dLambdaBar = new double[ROWS];
    private final double[][] matrix = new double[ROWS][ROWS], aBar = new double[ROWS][ROWS], factor = new double[ROWS][ROWS];
    private final double[] pivot = new double[ROWS], forward = new double[ROWS], lambdaBefore = new double[ROWS], lambdaAfterBar = new double[ROWS];
    private final DirectionalDifference difference = new DirectionalDifference();
    private double decay, dampingRate;

    TrajectoryAdjoint(Simulation sim, List<ConstraintFamily> families, boolean fitsDamping) {
        SolverSettings s = sim.settings();
        if (s.mode() != ConstraintMode.XPBD)
            throw new IllegalArgumentException("mode must be XPBD for a fit (PBD's stiffness depends on the sweep count), was " + s.mode());
        if (s.solver() != SolverType.GAUSS_SEIDEL || s.order() != ConstraintOrder.AS_BUILT)
            throw new IllegalArgumentException("solver must be gauss-seidel in the order built on one thread for a dynamic fit (the fit replays and differentiates those sweeps), was "
                    + s.solver().label() + (s.order() == ConstraintOrder.AS_BUILT ? "" : " in the " + s.order().name().toLowerCase(java.util.Locale.ROOT) + " order"));
        if (sim.colliderCount() > 0 || sim.selfCollision() != null)
            throw new IllegalArgumentException("scene must have no colliders or self-collision for a dynamic fit (contacts are not differentiated), has "
                    + sim.colliderCount() + " colliders" + (sim.selfCollision() != null ? " and self-collision" : ""));
        if (!sim.forces().isEmpty() || sim.hasKinematics())
            throw new IllegalArgumentException("scene must have no wind, forces or scripted pins for a dynamic fit, has "
                    + sim.forces().size() + " forces" + (sim.hasKinematics() ? " and scripted motion" : ""));
        int total = 0;
        List<ConstraintBlock> used = new ArrayList<>();
        for (ConstraintBlock b : sim.blocks()) {
            if (b.count() == 0) continue;
            if (b.family() == ConstraintFamily.TETHER)
                throw new IllegalArgumentException("scene must have no tethers for a dynamic fit (an inequality is not differentiated), has " + b.count());
            used.add(b);
            total += b.count();
        }
        if (sim.constraintCount() != total)
            throw new IllegalArgumentException("scene must have no attachments for a dynamic fit, has " + (sim.constraintCount() - total));
        for (ConstraintFamily f : families)
            if (used.stream().noneMatch(b -> b.family() == f))
                throw new IllegalArgumentException("params names " + ClothEnergy.name(f) + ", which this scene does not have");
        if (fitsDamping && !(s.damping() > 0))
            throw new IllegalArgumentException("solver.damping must be > 0 to fit damping (it is fitted as a factor on the scene's rate), was " + s.damping());
        if (families.isEmpty() && !fitsDamping) throw new IllegalArgumentException("params must name at least one parameter, was empty");
        this.families = List.copyOf(families);
        this.fitsDamping = fitsDamping;
        parameters = families.size() + (fitsDamping ? 1 : 0);
        blocks = used.toArray(new ConstraintBlock[0]);
        parameterOf = new int[blocks.length];
        lambdaOffset = new int[blocks.length];
        alpha0 = new double[total];
        int tapeLength = 0;
        for (int k = 0, j = 0; k < blocks.length; k++) {
            ConstraintBlock b = blocks[k];
            parameterOf[k] = families.indexOf(b.family());
            lambdaOffset[k] = j;
            for (int i = 0; i < b.count(); i++, j++) {
                alpha0[j] = b.compliance(i);
                if (!(alpha0[j] > 0))
                    throw new IllegalArgumentException("families." + ClothEnergy.name(b.family()) + ".compliance must be > 0 for a fit (a hard constraint has no compliance to scale), was " + alpha0[j]);
            }
            tapeLength += b.units() * (3 * b.arity() + b.rowsPerUnit());
        }
        Particles p = sim.particles();
        n = p.count();
        scratch = new Particles(n);
        scratch.copyFrom(p);
        x0 = p.positions().clone();
        v0 = new double[3 * n];
        w = new double[n];
        for (int i = 0; i < n; i++) {
            v0[3 * i] = p.vx(i); v0[3 * i + 1] = p.vy(i); v0[3 * i + 2] = p.vz(i);
            w[i] = p.inverseMass(i);
        }
        substeps = s.substeps();
        iterations = s.iterations();
        h = s.timestep() / substeps;
        gx = s.gravityX(); gy = s.gravityY(); gz = s.gravityZ();
        damping0 = s.damping();
        v = new double[3 * n];
        prev = new double[3 * n];
        lambda = new double[total];
        alphaTilde = new double[total];
        substepTape = iterations * tapeLength;
        tape = new double[substeps * substepTape];
        endV = new double[substeps][3 * n];
        fdStep = 1e-5 * shortestEdge();
    }

    int parameters() { return parameters; }
    int particles() { return n; }
    boolean isPinned(int i) { return w[i] == 0; }

    /** α per fitted family and, last, the damping rate (1/s) at θ, for reports. */
    double[] values(double[] theta) {
        double[] out = new double[parameters];
        for (int f = 0; f < families.size(); f++) out[f] = familyCompliance(f) * Math.exp(theta[f]);
        if (fitsDamping) out[parameters - 1] = damping0 * Math.exp(theta[parameters - 1]);
        return out;
    }

    /** The scene's α of family f (its first constraint's, for a family with per-constraint values). */
    private double familyCompliance(int f) {
        for (int k = 0; k < blocks.length; k++) if (parameterOf[k] == f) return alpha0[lambdaOffset[k]];
        throw new IllegalStateException();
    }

    private void load(double[] theta) {
        for (int k = 0; k < blocks.length; k++) {
            double scale = parameterOf[k] < 0 ? 1 : Math.exp(theta[parameterOf[k]]);
            for (int i = 0, j = lambdaOffset[k]; i < blocks[k].count(); i++, j++) alphaTilde[j] = alpha0[j] * scale / (h * h);
        }
        dampingRate = fitsDamping ? damping0 * Math.exp(theta[parameters - 1]) : damping0;
        decay = Math.exp(-dampingRate * h);
    }

    /** Positions after each of {@code frames} steps at θ, [frame][3·particle + axis]. */
    double[][] simulate(double[] theta, int frames) {
        load(theta);
        double[] x = scratch.positions();
        System.arraycopy(x0, 0, x, 0, x.length);
        System.arraycopy(v0, 0, v, 0, v.length);
        double[][] out = new double[frames][];
        for (int f = 0; f < frames; f++) {
            for (int s = 0; s < substeps; s++) substep(-1);
            out[f] = x.clone();
        }
        return out;
    }

    /**
     * The largest distance (m) of a particle between the engine's trajectory and this replay's at the
     * scene's own parameters, over {@code frames} steps of {@code sim} (which it advances: pass a fresh one).
     */
    double replayGap(Simulation sim, int frames) {
        double[][] replay = simulate(new double[parameters], frames);
        double gap = 0;
        for (int f = 0; f < frames; f++) {
            sim.step();
            double[] x = sim.particles().positions();
            for (int i = 0; i < n; i++)
                gap = Math.max(gap, Math.sqrt(sq(x[3 * i] - replay[f][3 * i]) + sq(x[3 * i + 1] - replay[f][3 * i + 1]) + sq(x[3 * i + 2] - replay[f][3 * i + 2])));
        }
        return gap;
    }

    /** L = ½ Σ_frames Σ_free |x − x̂|² at θ. */
    double loss(double[] theta, double[][] observed) {
        double[][] x = simulate(theta, observed.length);
        double l = 0;
        for (int f = 0; f < observed.length; f++) l += frameLoss(x[f], observed[f]);
        return l;
    }

    private double frameLoss(double[] x, double[] observed) {
        double l = 0;
        for (int i = 0; i < n; i++) {
            if (w[i] == 0) continue;
            for (int a = 0; a < 3; a++) l += 0.5 * sq(x[3 * i + a] - observed[3 * i + a]);
        }
        return l;
    }

    /** ∂L/∂θ by the adjoint of every substep, frames reversed from their checkpoints; also returns L in {@code lossOut[0]}. */
    double[] gradient(double[] theta, double[][] observed, double[] lossOut) {
        int frames = observed.length;
        load(theta);
        double[] x = scratch.positions();
        // Pass 1: the checkpoints (the state at each frame's start; checkX[f + 1] is where frame f ends) and the loss.
        double[][] checkX = new double[frames + 1][], checkV = new double[frames][];
        System.arraycopy(x0, 0, x, 0, x.length);
        System.arraycopy(v0, 0, v, 0, v.length);
        double l = 0;
        for (int f = 0; f < frames; f++) {
            checkX[f] = x.clone();
            checkV[f] = v.clone();
            for (int s = 0; s < substeps; s++) substep(-1);
            l += frameLoss(x, observed[f]);
        }
        checkX[frames] = x.clone();
        if (lossOut != null) lossOut[0] = l;
        double[] xBar = new double[3 * n], vBar = new double[3 * n], thetaBar = new double[parameters];
        for (int f = frames - 1; f >= 0; f--) {
            for (int i = 0; i < n; i++)
                if (w[i] != 0) for (int a = 0; a < 3; a++) xBar[3 * i + a] += checkX[f + 1][3 * i + a] - observed[f][3 * i + a];
            // Pass 2: the frame taped from its checkpoint, then its substeps reversed, last first.
            System.arraycopy(checkX[f], 0, x, 0, x.length);
            System.arraycopy(checkV[f], 0, v, 0, v.length);
            for (int s = 0; s < substeps; s++) {
                substep(s * substepTape);
                System.arraycopy(v, 0, endV[s], 0, v.length);
            }
            for (int s = substeps - 1; s >= 0; s--) reverseSubstep(s, xBar, vBar, thetaBar);
        }
        return thetaBar;
    }

    /** One substep on (scratch positions, v), the projections' inputs recorded from tape[record] on (none if record &lt; 0). */
    private void substep(int record) {
        final double[] x = scratch.positions();
        for (int i = 0; i < n; i++) {
            int k = 3 * i;
            prev[k] = x[k]; prev[k + 1] = x[k + 1]; prev[k + 2] = x[k + 2];
            if (w[i] == 0) continue;
            v[k] += h * gx; v[k + 1] += h * gy; v[k + 2] += h * gz;
            x[k] += h * v[k]; x[k + 1] += h * v[k + 1]; x[k + 2] += h * v[k + 2];
        }
        Arrays.fill(lambda, 0);
        int t = record;
        for (int it = 0; it < iterations; it++)
            for (int k = 0; k < blocks.length; k++) {
                ConstraintBlock b = blocks[k];
                int arity = b.arity(), m = b.rowsPerUnit();
                for (int u = 0, j = lambdaOffset[k]; u < b.units(); u++, j += m) {
                    int i = u * m;
                    if (record >= 0) {
                        for (int q = 0; q < arity; q++) {
                            int c = 3 * b.particle(i, q);
                            tape[t++] = x[c]; tape[t++] = x[c + 1]; tape[t++] = x[c + 2];
                        }
                        for (int r = 0; r < m; r++) tape[t++] = lambda[j + r];
                    }
                    if (!solveUnit(b, i, j)) continue;
                    for (int q = 0; q < arity; q++) {
                        int p = b.particle(i, q);
                        for (int r = 0; r < m; r++) {
                            double s = w[p] * dLambda[r];
                            x[3 * p] += s * grad[r][3 * q]; x[3 * p + 1] += s * grad[r][3 * q + 1]; x[3 * p + 2] += s * grad[r][3 * q + 2];
                        }
                    }
                    for (int r = 0; r < m; r++) lambda[j + r] += dLambda[r];
                }
            }
        final double inv = 1.0 / h;
        for (int c = 0; c < 3 * n; c++) v[c] = (x[c] - prev[c]) * inv;
        for (int i = 0; i < n; i++)
            if (w[i] != 0) { v[3 * i] *= decay; v[3 * i + 1] *= decay; v[3 * i + 2] *= decay; }
    }

    /**
     * The XPBD projection of one unit of b (rows i …, flat λ index j …) at the scratch positions, as the
     * blocks solve it: its rows' C and ∇C into {@link #cOf} and {@link #grad}, A = Σ w ∇Cᵣ·∇Cₛ + α̃ᵣδᵣₛ and
     * A Δλ = −C − α̃λ by LDLᵀ into {@link #dLambda} (a pivot at round-off drops its row, as the blocks do).
     * False when nothing can move.
     */
    private boolean solveUnit(ConstraintBlock b, int i, int j) {
        int m = b.rowsPerUnit(), arity = b.arity();
        for (int r = 0; r < m; r++) {
            cOf[r] = b.evaluate(i + r, scratch);
            b.gradient(i + r, scratch, grad[r]);
        }
        double trace = 0;
        for (int r = 0; r < m; r++) {
            for (int c = 0; c <= r; c++) {
                double sum = 0;
                for (int q = 0; q < arity; q++) {
                    double wq = w[b.particle(i, q)];
                    sum += wq * (grad[r][3 * q] * grad[c][3 * q] + grad[r][3 * q + 1] * grad[c][3 * q + 1] + grad[r][3 * q + 2] * grad[c][3 * q + 2]);
                }
                matrix[r][c] = matrix[c][r] = sum;
            }
            matrix[r][r] += alphaTilde[j + r];
            rhs[r] = -cOf[r] - alphaTilde[j + r] * lambda[j + r];
            trace += matrix[r][r];
        }
        if (!(trace > 0)) return false;
        solve(m, 1e-14 * trace, rhs, dLambda);
        return true;
    }

    /**
     * A x = b for the symmetric m × m {@link #matrix} by LDLᵀ, pivots at or below {@code tiny} dropped (their
     * component 0): the blocks' rule, so a replay follows them.
     */
    private void solve(int m, double tiny, double[] b, double[] out) {
        final double[][] l = factor;
        final double[] d = pivot, y = forward;
        for (int r = 0; r < m; r++) {
            for (int c = 0; c < r; c++) {
                double sum = matrix[r][c];
                for (int k = 0; k < c; k++) sum -= l[r][k] * l[c][k] * d[k];
                l[r][c] = d[c] > 0 ? sum / d[c] : 0;
            }
            double diag = matrix[r][r];
            for (int k = 0; k < r; k++) diag -= l[r][k] * l[r][k] * d[k];
            d[r] = diag > tiny ? diag : 0;
        }
        for (int r = 0; r < m; r++) {
            y[r] = b[r];
            for (int k = 0; k < r; k++) y[r] -= l[r][k] * y[k];
        }
        for (int r = m - 1; r >= 0; r--) {
            double v = d[r] > 0 ? y[r] / d[r] : 0;
            for (int k = r + 1; k < m; k++) v -= l[k][r] * out[k];
            out[r] = d[r] > 0 ? v : 0;
        }
    }

    /**
     * Turns (x̄, v̄), the adjoints of substep s's end state, into those of its start, adding ∂/∂θ to
     * thetaBar, from its tape and its end velocity.
     */
    private void reverseSubstep(int s, double[] xBar, double[] vBar, double[] thetaBar) {
        final double[] vEnd = endV[s];
        // Damping v'' = v'·e^(−ch) on free particles; v' = (x_end − prev)/h.
        for (int i = 0; i < n; i++) {
            if (w[i] == 0) continue;
            for (int a = 0; a < 3; a++) {
                int c = 3 * i + a;
                if (fitsDamping) thetaBar[parameters - 1] += vBar[c] * vEnd[c] * (-h * dampingRate);
                vBar[c] *= decay;
            }
        }
        // v' = (p − prev)/h: p̄ = x̄ + v̄/h, and prev̄ = −v̄/h (kept in vBar until the predict).
        final double inv = 1.0 / h;
        for (int c = 0; c < 3 * n; c++) {
            xBar[c] += vBar[c] * inv;
            vBar[c] = -vBar[c] * inv; // now prev̄
        }
        // The sweeps, last projection first; λ̄ starts at 0 (λ's final value is not an output).
        Arrays.fill(lambda, 0); // reused as λ̄
        int t = (s + 1) * substepTape;
        for (int it = iterations - 1; it >= 0; it--)
            for (int k = blocks.length - 1; k >= 0; k--) {
                ConstraintBlock b = blocks[k];
                int m = b.rowsPerUnit(), record = 3 * b.arity() + m;
                for (int u = b.units() - 1; u >= 0; u--) {
                    t -= record;
                    reverseUnit(k, u * m, lambdaOffset[k] + u * m, t, xBar, thetaBar);
                }
            }
        // Predict: p = x + h(v + hg) on free particles, p = x on pinned ones, prev = x.
        for (int i = 0; i < n; i++)
            for (int a = 0; a < 3; a++) {
                int c = 3 * i + a;
                double pBar = xBar[c];
                xBar[c] = pBar + vBar[c];
                vBar[c] = w[i] == 0 ? 0 : h * pBar;
            }
    }

    /**
     * The adjoint of one unit's projection (rows i … of block k, flat λ index j …, its inputs at tape[t…]).
     * Forward: Δλ = A⁻¹N with N = −C − α̃λ and A = G W Gᵀ + α̃ (G the rows' ∇C), x += W GᵀΔλ, λ += Δλ. Reverse:
     * <pre>
     *   Δλ̄ = λ̄ + G W x̄,   N̄ = A⁻¹Δλ̄,   Ā = −N̄ Δλᵀ
     *   Ḡᵣ = Δλᵣ W x̄ + Σₛ (Āᵣₛ + Āₛᵣ) W Gₛ,   x̄ ← x̄ − Σᵣ N̄ᵣ Gᵣ + Σᵣ ∇²Cᵣ·Ḡᵣ,   λ̄ ← λ̄ − N̄α̃,   θ̄ += Σᵣ (Āᵣᵣ − N̄ᵣλᵣ) α̃ᵣ
     * </pre>
     * (one row: D̄ = Ā, Ḡ = wΔλ x̄ + 2D̄ w∇C, as before).
     */
    private void reverseUnit(int k, int i, int j, int t, double[] xBar, double[] thetaBar) {
        final ConstraintBlock b = blocks[k];
        final double[] x = scratch.positions();
        int arity = b.arity(), m = b.rowsPerUnit();
        for (int q = 0; q < arity; q++) {
            int c = 3 * b.particle(i, q);
            x[c] = tape[t + 3 * q]; x[c + 1] = tape[t + 3 * q + 1]; x[c + 2] = tape[t + 3 * q + 2];
        }
        // Recompute the forward unit from its inputs (solveUnit reads λ where λ̄ is kept: swap λ before in).
        final double[] lambdaBar = lambdaAfterBar;
        for (int r = 0; r < m; r++) {
            lambdaBefore[r] = tape[t + 3 * arity + r];
            lambdaBar[r] = lambda[j + r];
            lambda[j + r] = lambdaBefore[r];
        }
        boolean moved = solveUnit(b, i, j);
        for (int r = 0; r < m; r++) lambda[j + r] = lambdaBar[r];
        if (!moved) return;
        for (int r = 0; r < m; r++) {
            double sum = lambdaBar[r];
            for (int q = 0; q < arity; q++) {
                int p = b.particle(i, q);
                double wq = w[p];
                for (int e = 0; e < 3; e++) sum += wq * grad[r][3 * q + e] * xBar[3 * p + e];
            }
            dLambdaBar[r] = sum;
        }
        double trace = 0;
        for (int r = 0; r < m; r++) trace += matrix[r][r];
        solve(m, 1e-14 * trace, dLambdaBar, nBar);
        for (int r = 0; r < m; r++) for (int c = 0; c < m; c++) aBar[r][c] = -nBar[r] * dLambda[c];
        int param = parameterOf[k];
        for (int r = 0; r < m; r++) {
            lambda[j + r] -= nBar[r] * alphaTilde[j + r];
            if (param >= 0) thetaBar[param] += (aBar[r][r] - nBar[r] * lambdaBefore[r]) * alphaTilde[j + r];
        }
        // Every Ḡᵣ from x̄ as it is after the projection, before x̄ takes any of the unit's terms.
        for (int r = 0; r < m; r++)
            for (int q = 0; q < arity; q++) {
                int p = b.particle(i, q);
                double wq = w[p];
                for (int e = 0; e < 3; e++) {
                    double g = wq * dLambda[r] * xBar[3 * p + e];
                    for (int c = 0; c < m; c++) g += (aBar[r][c] + aBar[c][r]) * wq * grad[c][3 * q + e];
                    gBar[r][3 * q + e] = g;
                }
            }
        for (int r = 0; r < m; r++) {
            double gNorm = 0;
            for (int q = 0; q < 3 * arity; q++) gNorm += sq(gBar[r][q]);
            if (gNorm > 0) difference.along(b, i + r, scratch, DirectionalDifference.GRADIENT, gBar[r], fdStep, SHRINKS, hu);
            for (int q = 0; q < arity; q++) {
                int p = b.particle(i, q);
                for (int e = 0; e < 3; e++) xBar[3 * p + e] += -nBar[r] * grad[r][3 * q + e] + (gNorm > 0 ? hu[3 * q + e] : 0);
            }
        }
    }

    private double shortestEdge() {
        double shortest = Double.POSITIVE_INFINITY;
        for (ConstraintBlock b : blocks)
            for (int i = 0; i < b.count(); i++)
                for (int q = 1; q < b.arity(); q++) {
                    int u = 3 * b.particle(i, 0), p = 3 * b.particle(i, q);
                    double d = Math.sqrt(sq(x0[u] - x0[p]) + sq(x0[u + 1] - x0[p + 1]) + sq(x0[u + 2] - x0[p + 2]));
                    if (d > 0) shortest = Math.min(shortest, d);
                }
        return Double.isFinite(shortest) ? shortest : 1e-2;
    }

    private static double sq(double v) { return v * v; }
}
