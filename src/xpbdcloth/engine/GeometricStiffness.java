package xpbdcloth.engine;

/**
 * The geometric stiffness of tensioned length constraints ({@link LinearLength}), written as compliant
 * rows that the global solver's Schur complement can take in.
 *
 * <pre>
 *   C = |d| − r,  d = Σₖ cₖ x_k:     ∇²_{kl} C = cₖ c_l (I − n nᵀ) / |d|
 *   −λ ∇²C = κ Σ_{t ∈ {t₁, t₂}} g_t g_tᵀ,   κ = −λ / |d|,   (g_t)_k = cₖ t
 * </pre>
 * with t₁, t₂ orthonormal and perpendicular to n. λ &lt; 0 is tension (C &gt; 0 makes λ = −C/α̃), so κ ≥ 0
 * there; under compression the term is negative, makes the system indefinite, and is dropped, as Tournier
 * et al. do for the same reason.
 *
 * <p>Why rows: Newton's step on XPBD's KKT system with the geometric stiffness (Tournier, Nesme, Gilles,
 * Faure 2015, "Stable Constrained Dynamics", eq. 9) is
 * <pre>
 *   [ M − Σλ∇²C   −Jᵀ ] [Δx]   [     0     ]
 *   [ J            α̃  ] [Δλ] = [ −C − α̃λ  ]
 * </pre>
 * and M − Σλ∇²C is no longer diagonal, so its Schur complement J (M − Σλ∇²C)⁻¹ Jᵀ cannot be formed. But
 * a stiffness κ g gᵀ added to M is the same as one more constraint row g with compliance 1/κ and a
 * multiplier μ of its own: g Δx + Δμ/κ = 0 eliminates to Δμ = −κ g Δx, and M Δx = JᵀΔλ + gᵀΔμ becomes
 * (M + κ g gᵀ) Δx = JᵀΔλ. So the Schur complement keeps M⁻¹ = W diagonal and gains two rows per
 * tensioned constraint, [J; G] W [J; G]ᵀ + diag(α̃, 1/κ), whose right-hand side is 0; μ is thrown away
 * after the step. The step changes, the solution does not: where C + α̃λ = 0 the right-hand side is 0
 * and so is the step, so XPBD's equilibria stay exact.
 *
 * <p>Which λ: at a substep's first iteration λ is 0 and the step would see no tension, the case that went
 * unstable (a converged solve builds a hanging chain's whole tension in one iteration, and its sideways
 * pull then acts explicitly). So κ uses the more tensile of the current λ and the λ left by the previous
 * global iteration, which at a substep's start is the previous substep's (Andrews, Teichmann, Kry 2017,
 * "Geometric Stiffness for Real-time Constrained Multibody Dynamics", lag λ the same way).
 */
final class GeometricStiffness {
    /** Indices (into the solver's constraints) of the constraints given geometric stiffness. */
    final int[] constraint;
    private final double[] coefficients;
    private final int[] coefficientStart;
    /** λ after the previous global iteration, per listed constraint. */
    private final double[] lagged;

    GeometricStiffness(ConstraintRows rows) {
        final ConstraintBlock[] blocks = rows.block;
        int n = 0, coeffs = 0;
        for (ConstraintBlock b : blocks) if (b instanceof LinearLength) { n++; coeffs += b.arity(); }
        constraint = new int[n];
        coefficientStart = new int[n + 1];
        coefficients = new double[coeffs];
        lagged = new double[n];
        int j = 0;
        for (int i = 0; i < blocks.length; i++) {
            if (!(blocks[i] instanceof LinearLength)) continue;
            LinearLength form = (LinearLength) blocks[i];
            int arity = blocks[i].arity();
            constraint[j] = i;
            coefficientStart[j + 1] = coefficientStart[j] + arity;
            for (int k = 0; k < arity; k++) coefficients[coefficientStart[j] + k] = form.coefficient(k);
            j++;
        }
    }

    int count() { return constraint.length; }

    /**
     * Fills the two rows of listed constraint j: their gradients (3 per particle, from {@code at1} and
     * {@code at2} in {@code grad}) and returns their compliance 1/κ in α̃'s units (1/kg), or +∞ when the
     * constraint is not in tension or has no direction (the rows are then zero).
     */
    double fill(int j, Particles p, ConstraintBlock block, int index, double[] grad, int at1, int at2) {
        int arity = coefficientStart[j + 1] - coefficientStart[j];
        double dx = 0, dy = 0, dz = 0;
        for (int k = 0; k < arity; k++) {
            int q = 3 * block.particle(index, k);
            double ck = coefficients[coefficientStart[j] + k];
            dx += ck * p.x[q]; dy += ck * p.x[q + 1]; dz += ck * p.x[q + 2];
        }
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double tension = -Math.min(block.lambda[index], lagged[j]);
        if (!(tension > 0) || len < DistanceBlock.MIN_LENGTH) {
            java.util.Arrays.fill(grad, at1, at1 + 3 * arity, 0);
            java.util.Arrays.fill(grad, at2, at2 + 3 * arity, 0);
            return Double.POSITIVE_INFINITY;
        }
        // n up to sign: its largest component made positive, so that in-line edges, whichever way their
        // particles are listed, get the same t₁ and t₂, and their rows couple t₁ to t₁ (the multigrid
        // preconditions them along chains of in-line edges).
        double ax = Math.abs(dx), ay = Math.abs(dy), az = Math.abs(dz);
        double up = (ax >= ay && ax >= az ? dx : ay >= az ? dy : dz) < 0 ? -1 / len : 1 / len;
        double nx = dx * up, ny = dy * up, nz = dz * up;
        // An orthonormal basis around n without a branch on its direction (Duff et al. 2017, "Building an
        // Orthonormal Basis, Revisited", listing 2): any pair ⊥ n serves, only t₁t₁ᵀ + t₂t₂ᵀ matters.
        double sign = Math.copySign(1.0, nz), a = -1 / (sign + nz), b = nx * ny * a;
        double t1x = 1 + sign * nx * nx * a, t1y = sign * b, t1z = -sign * nx;
        double t2x = b, t2y = sign + ny * ny * a, t2z = -ny;
        for (int k = 0; k < arity; k++) {
            double ck = coefficients[coefficientStart[j] + k];
            grad[at1 + 3 * k] = ck * t1x; grad[at1 + 3 * k + 1] = ck * t1y; grad[at1 + 3 * k + 2] = ck * t1z;
            grad[at2 + 3 * k] = ck * t2x; grad[at2 + 3 * k + 1] = ck * t2y; grad[at2 + 3 * k + 2] = ck * t2z;
        }
        return len / tension;
    }

    /** Records each listed constraint's λ after a global iteration, for the next one's κ. */
    void remember(ConstraintBlock[] block, int[] index) {
        for (int j = 0; j < constraint.length; j++) lagged[j] = block[constraint[j]].lambda[index[constraint[j]]];
    }
}
