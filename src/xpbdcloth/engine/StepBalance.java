package xpbdcloth.engine;

/**
 * How far the last substep's positions are from solving its step: the force left over on each free
 * particle, whatever the solver,
 * <pre>
 *   rᵢ = mᵢ (xᵢ − yᵢ) / h²  +  Σⱼ (Cⱼ/αⱼ) ∇ᵢCⱼ  +  Σ_gas (p₀ − nRT/V) ∇ᵢV
 *        (y the substep's prediction, j the compliant constraints; a gas's term is its energy's gradient)
 * </pre>
 * — zero when the step's implicit Euler equation holds (XPBD converged), and for a cloth at rest the
 * difference between its weight and what its material holds up. Reported as the worst particle's |rᵢ| over
 * its weight mᵢ|g|: a cloth that reads more than {@link #CONVERGED} is not yet the material's shape (a few
 * Gauss–Seidel sweeps leave a hanging fabric off by tens of percent at its pins), one that reads less is.
 * Particles held by something without an energy (a contact, an attachment, a stretched tether, a hard
 * constraint) are left out: what holds them is not in rᵢ.
 */
public final class StepBalance {
    /** Scratch, made once per simulation (the HUD asks every few frames). */
    private final double[] residual, gradient = new double[3 * ConstraintBlock.MAX_ARITY];
    private final boolean[] excluded;

    StepBalance(int particles) {
        residual = new double[3 * particles];
        excluded = new boolean[particles];
    }

    /** Below this worst imbalance (a fraction of a particle's weight) the solve is called converged. */
    public static final double CONVERGED = 0.01;

    /** What a worst imbalance means, in words: the HUD's and the commands' one sentence. */
    public static String verdict(double worst) {
        return worst < CONVERGED
                ? String.format(java.util.Locale.ROOT, "converged: worst particle off balance by %.2g of its weight", worst)
                : String.format(java.util.Locale.ROOT, "NOT CONVERGED: worst particle off balance by %.2g × its weight, converged is under %.2g "
                        + "(the shape is the solver's, not the material's)", worst, CONVERGED);
    }

    /**
     * The worst |rᵢ|/(mᵢ|g|) over the free particles held only by compliant constraints, after the last
     * step (0 when there are none, or no gravity); {@link Simulation#balance()} is how it is asked.
     */
    double worst(Simulation sim) {
        Particles p = sim.particles();
        double[] prediction = sim.lastPrediction();
        double h = sim.substep(), g = Math.sqrt(sq(sim.settings().gravityX()) + sq(sim.settings().gravityY()) + sq(sim.settings().gravityZ()));
        int n = p.count();
        if (prediction == null || !(g > 0) || !(h > 0)) return 0;
        final double[] r = residual, grad = gradient;
        java.util.Arrays.fill(excluded, false);
        for (int i = 0; i < n; i++) {
            if (p.w[i] == 0) { excluded[i] = true; continue; }
            double m = p.mass[i] / (h * h);
            for (int a = 0; a < 3; a++) r[3 * i + a] = m * (p.x[3 * i + a] - prediction[3 * i + a]);
        }
        for (ConstraintBlock b : sim.blocks())
            for (int i = 0; i < b.count(); i++) {
                double alpha = b.compliance(i), C = b.evaluate(i, p);
                boolean held = b.family() == ConstraintFamily.TETHER ? C > 0 : !(alpha > 0);
                if (held) {
                    for (int k = 0; k < b.arity(); k++) excluded[b.particle(i, k)] = true;
                    continue;
                }
                if (b.family() == ConstraintFamily.TETHER || C == 0) continue;
                b.gradient(i, p, grad);
                for (int k = 0; k < b.arity(); k++) {
                    int q = b.particle(i, k);
                    for (int a = 0; a < 3; a++) r[3 * q + a] += C / alpha * grad[3 * k + a];
                }
            }
        for (EnclosedGas gas : sim.gases()) gas.addForceTerm(p, r, excluded);
        sim.markHeld(excluded);
        double worst = 0;
        for (int i = 0; i < n; i++) {
            if (excluded[i]) continue;
            double f = Math.sqrt(sq(r[3 * i]) + sq(r[3 * i + 1]) + sq(r[3 * i + 2]));
            worst = Math.max(worst, f / (p.mass[i] * g));
        }
        return worst;
    }

    private static double sq(double v) { return v * v; }
}
