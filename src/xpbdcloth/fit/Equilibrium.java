package xpbdcloth.fit;

import xpbdcloth.linalg.BandedMatrix;

/**
 * The rest shape ∇E(x) = 0 of a {@link ClothEnergy}, found by Newton's method with a backtracking line
 * search on E and, where the Hessian is not positive definite (a buckling cloth on the way down), a
 * Levenberg shift H + μI (Nocedal &amp; Wright 2006, §3.4 and §4).
 *
 * <p>Why Newton and not the simulator: a fit compares shapes to well below the observation's noise, and a
 * few Gauss–Seidel sweeps per substep stop short of the equilibrium (the residual the HUD shows); Newton
 * reaches |∇E| at round-off in a handful of iterations. The simulator's own rest shape is where it starts.
 * The converged Hessian's factor is kept: the fit's sensitivities and adjoint solve with it.
 */
final class Equilibrium {
    /** Stop when no free particle is off balance by more than this fraction of the heaviest particle's weight. */
    static final double FORCE_TOLERANCE = 1e-9;
    static final int MAX_ITERATIONS = 200;
    /**
     * A stall: this many iterations in a row whose Hessian was not positive definite (shifted as little as the
     * step before allowed, it failed to factor and took a larger shift) and that
     * together took less than half off the force residual. The state is then no minimum of E (its Hessian is
     * indefinite: a compressed membrane's negative geometric stiffness, a cloth that would wrinkle) and the
     * shifted steps cross that region at the pace of gradient descent: measured on hanging denim at 32 and 64
     * segments, the residual fell by 0.2–0.6 % an iteration for all 200 iterations and reached none of the
     * tolerance. Stopping there gives the same verdict (not converged, no factor) without the iterations.
     */
    static final int STALL_ITERATIONS = 20;

    final double[] positions;
    /** The factor of ∇²E at {@link #positions}, or null if it was not positive definite there. */
    BandedMatrix factor;
    int iterations;
    double forceResidual;
    boolean converged;

    private Equilibrium(double[] positions) { this.positions = positions; }

    /** The rest shape nearest {@code start} (full positions; pinned particles stay where start has them). */
    static Equilibrium solve(ClothEnergy energy, double[] start, double weight) {
        Equilibrium eq = new Equilibrium(start.clone());
        double[] x = eq.positions, g = new double[energy.freeDofs], gTrial = new double[energy.freeDofs], trial = new double[x.length];
        double tolerance = FORCE_TOLERANCE * weight, shift = 0;
        double e = energy.energy(x);
        // The force residual at the start of each of the last STALL_ITERATIONS iterations, and how many in a row were shifted.
        double[] recent = new double[STALL_ITERATIONS];
        int shiftedInARow = 0;
        for (eq.iterations = 0; eq.iterations < MAX_ITERATIONS; eq.iterations++) {
            energy.gradient(x, g);
            eq.forceResidual = maxAbs(g);
            BandedMatrix h = energy.hessian(x);
            if (eq.forceResidual <= tolerance) {
                eq.factor = h.factor() ? h : null;
                eq.converged = true;
                return eq;
            }
            if (shiftedInARow >= STALL_ITERATIONS && eq.forceResidual > 0.5 * recent[eq.iterations % STALL_ITERATIONS]) {
                eq.factor = h.factor() ? h : null;
                eq.converged = eq.forceResidual <= 1e3 * tolerance;
                return eq;
            }
            recent[eq.iterations % STALL_ITERATIONS] = eq.forceResidual;
            double[] delta = null;
            boolean definite = true;
            for (int tries = 0; tries < 60 && delta == null; tries++) {
                BandedMatrix shifted = h.copy();
                if (shift > 0) for (int i = 0; i < shifted.n; i++) shifted.add(i, i, shift);
                if (shifted.factor()) {
                    delta = g.clone();
                    shifted.solve(delta);
                    for (int i = 0; i < delta.length; i++) delta[i] = -delta[i];
                } else {
                    definite = false;
                    shift = shift == 0 ? 1e-8 * maxDiagonal(h) : 10 * shift;
                }
            }
            if (delta == null) return eq;
            shiftedInARow = definite ? 0 : shiftedInARow + 1;
            double slope = dot(g, delta), t = 1;
            boolean moved = false;
            while (t > 1e-12) {
                System.arraycopy(x, 0, trial, 0, x.length);
                energy.addFree(trial, t, delta);
                double et = energy.energy(trial);
                // Near the minimum E changes by ½gᵀH⁻¹g, below E's round-off: there the force residual decides.
                boolean belowRoundOff = -slope * t < 1e-13 * Math.max(Math.abs(e), 1e-300);
                boolean accept = et <= e + 1e-4 * t * slope;
                if (!accept && belowRoundOff) {
                    energy.gradient(trial, gTrial);
                    accept = maxAbs(gTrial) < eq.forceResidual;
                }
                if (accept) {
                    System.arraycopy(trial, 0, x, 0, x.length);
                    moved = true;
                    e = et;
                    break;
                }
                t /= 2;
            }
            if (!moved || t * maxAbs(delta) < 1e-15) {
                // Round-off: no step lowers E or the force residual; what was reached is what there is.
                energy.gradient(x, g);
                eq.forceResidual = maxAbs(g);
                BandedMatrix last = energy.hessian(x);
                eq.factor = last.factor() ? last : null;
                eq.converged = eq.forceResidual <= 1e3 * tolerance;
                return eq;
            }
            shift = t == 1 ? shift / 10 : Math.max(shift, 1e-8 * maxDiagonal(h));
            if (shift < 1e-14 * maxDiagonal(h)) shift = 0;
        }
        return eq;
    }

    static double maxAbs(double[] v) {
        double m = 0;
        for (double d : v) m = Math.max(m, Math.abs(d));
        return m;
    }

    static double dot(double[] a, double[] b) {
        double s = 0;
        for (int i = 0; i < a.length; i++) s += a[i] * b[i];
        return s;
    }

    private static double maxDiagonal(BandedMatrix h) {
        double m = 0;
        for (int i = 0; i < h.n; i++) m = Math.max(m, h.get(i, i));
        return m;
    }
}
