package xpbdcloth.engine;

import java.util.Arrays;
import java.util.Objects;

/**
 * The solver's parameters with their defaults and units: an immutable value. Each {@code withX} returns a
 * new value, validated at the edge (an invalid value throws {@link IllegalArgumentException} naming the
 * parameter and the value it was, and the old value is left as it was); a simulation takes a whole value
 * at once ({@link Simulation#settings(SolverSettings)}), so there is no order to set parameters in and
 * nothing to count changes with.
 *
 * <p>Defaults follow the original simulator: XPBD, 2 Gauss–Seidel iterations, dt = 20 ms, one substep,
 * gravity 9.81 m/s² along −y (y is up).
 */
public final class SolverSettings {
    private final ConstraintMode mode;
    private final int iterations;
    private final int substeps;
    private final double timestep;
    private final boolean mullerCorrection;
    private final double gravityX, gravityY, gravityZ;
    /** Velocity damping c, 1/s: v decays as e^(−c·t) in the velocity pass; 0 = none (the original's). */
    private final double damping;
    private final ConstraintOrder order;
    private final int threads;
    private final SolverType solver;
    /** Relative residual at which conjugate gradients stop (see {@link #withPcgTolerance}). */
    private final double pcgTolerance;
    /** A cap that keeps a global iteration's cost bounded when the system is badly conditioned. */
    private final int pcgMaxIterations;

    /**
     * The defaults. Inexact Newton's PCG tolerance is 1e-1: each global iteration is only a linearisation, so
     * its linear system need not be solved tightly; of 1e-1, 1e-3 and 1e-5, 1e-1 reached a 1e-6 nonlinear
     * residual soonest (experiment 7).
     */
    public SolverSettings() {
        this(ConstraintMode.XPBD, 2, 1, 0.020, true, 0, -9.81, 0, 0, ConstraintOrder.AS_BUILT, 1, SolverType.GAUSS_SEIDEL, 1e-1, 300);
    }

    private SolverSettings(ConstraintMode mode, int iterations, int substeps, double timestep, boolean mullerCorrection,
                           double gravityX, double gravityY, double gravityZ, double damping, ConstraintOrder order,
                           int threads, SolverType solver, double pcgTolerance, int pcgMaxIterations) {
        this.mode = mode;
        this.iterations = iterations;
        this.substeps = substeps;
        this.timestep = timestep;
        this.mullerCorrection = mullerCorrection;
        this.gravityX = gravityX; this.gravityY = gravityY; this.gravityZ = gravityZ;
        this.damping = damping;
        this.order = order;
        this.threads = threads;
        this.solver = solver;
        this.pcgTolerance = pcgTolerance;
        this.pcgMaxIterations = pcgMaxIterations;
    }

    public ConstraintMode mode() { return mode; }

    /**
     * Every constraint of a simulation given these settings switches formulation at its next projection;
     * state is kept. PBD needs the Gauss–Seidel solver (see {@link #withSolver}); PBD while a global solver is
     * chosen is refused ({@link #withModeAndSolver} sets both at once).
     */
    public SolverSettings withMode(ConstraintMode m) {
        if (m == null) throw new IllegalArgumentException("mode must be PBD or XPBD, was null");
        if (m == ConstraintMode.PBD && solver != SolverType.GAUSS_SEIDEL)
            throw new IllegalArgumentException("mode must be XPBD while the solver is " + solver.label()
                    + " (PBD's stiffness k is defined per Gauss-Seidel projection), was PBD");
        return new SolverSettings(m, iterations, substeps, timestep, mullerCorrection, gravityX, gravityY, gravityZ, damping, order, threads, solver, pcgTolerance, pcgMaxIterations);
    }

    /** Gauss–Seidel sweeps per substep, n ≥ 1. */
    public int iterations() { return iterations; }

    public SolverSettings withIterations(int n) {
        Check.inRange("iterations", n, 1, EngineRange.MAX_ITERATIONS);
        return new SolverSettings(mode, n, substeps, timestep, mullerCorrection, gravityX, gravityY, gravityZ, damping, order, threads, solver, pcgTolerance, pcgMaxIterations);
    }

    /** Substeps per step, s ≥ 1: the step dt is split into s substeps of h = dt/s (Macklin et al. 2019). */
    public int substeps() { return substeps; }

    public SolverSettings withSubsteps(int s) {
        Check.inRange("substeps", s, 1, EngineRange.MAX_SUBSTEPS);
        return new SolverSettings(mode, iterations, s, timestep, mullerCorrection, gravityX, gravityY, gravityZ, damping, order, threads, solver, pcgTolerance, pcgMaxIterations);
    }

    /** The step dt in seconds, &gt; 0 (the frame's simulated time). */
    public double timestep() { return timestep; }

    public SolverSettings withTimestep(double dt) {
        Check.inRange("dt", dt, EngineRange.MIN_DT, EngineRange.MAX_DT);
        return new SolverSettings(mode, iterations, substeps, dt, mullerCorrection, gravityX, gravityY, gravityZ, damping, order, threads, solver, pcgTolerance, pcgMaxIterations);
    }

    /**
     * Whether PBD applies Müller's per-iteration stiffness k' = 1 − (1 − k)^(1/n), which makes n sweeps
     * compound to k on a single constraint; off applies the raw k every sweep.
     */
    public boolean mullerCorrection() { return mullerCorrection; }

    public SolverSettings withMullerCorrection(boolean on) {
        return new SolverSettings(mode, iterations, substeps, timestep, on, gravityX, gravityY, gravityZ, damping, order, threads, solver, pcgTolerance, pcgMaxIterations);
    }

    /** Gravity as an acceleration, m/s². */
    public double gravityX() { return gravityX; }
    public double gravityY() { return gravityY; }
    public double gravityZ() { return gravityZ; }

    public SolverSettings withGravity(double gx, double gy, double gz) {
        EngineRange.vector("gravity", gx, gy, gz, EngineRange.MAX_GRAVITY);
        return new SolverSettings(mode, iterations, substeps, timestep, mullerCorrection, gx, gy, gz, damping, order, threads, solver, pcgTolerance, pcgMaxIterations);
    }

    /** Velocity damping c (1/s), applied after each substep as v ← v·e^(−c·h). */
    public double damping() { return damping; }

    /**
     * Velocity damping c ∈ [0, {@link EngineRange#MAX_DAMPING}] per second. Multiplying by e^(−c·h) each
     * substep makes the decay e^(−c·t) whatever dt and the substep count are (a per-step factor would make
     * the cloth's damping depend on the frame rate).
     */
    public SolverSettings withDamping(double perSecond) {
        Check.inRange("damping", perSecond, 0, EngineRange.MAX_DAMPING);
        return new SolverSettings(mode, iterations, substeps, timestep, mullerCorrection, gravityX, gravityY, gravityZ, perSecond, order, threads, solver, pcgTolerance, pcgMaxIterations);
    }

    /** The order of each sweep (default as built); more than one thread always uses the coloured order. */
    public ConstraintOrder order() { return threads > 1 ? ConstraintOrder.COLOURED : order; }

    public SolverSettings withOrder(ConstraintOrder o) {
        if (o == null) throw new IllegalArgumentException("order must be AS_BUILT or COLOURED, was null");
        return new SolverSettings(mode, iterations, substeps, timestep, mullerCorrection, gravityX, gravityY, gravityZ, damping, o, threads, solver, pcgTolerance, pcgMaxIterations);
    }

    /** Threads for the sweeps, 1 to 64; above 1 the coloured order is split across them. */
    public int threads() { return threads; }

    public SolverSettings withThreads(int t) {
        Check.inRange("threads", t, 1, 64);
        return new SolverSettings(mode, iterations, substeps, timestep, mullerCorrection, gravityX, gravityY, gravityZ, damping, order, t, solver, pcgTolerance, pcgMaxIterations);
    }

    /** Gauss–Seidel (default), a global PCG solve per iteration, or vertex block descent. */
    public SolverType solver() { return solver; }

    /**
     * Chooses the solver. Every solver but Gauss–Seidel needs XPBD mode, and is refused in PBD mode: PBD's k is "the
     * fraction of its error one Gauss–Seidel projection removes" (with Müller's k', the fraction n
     * sweeps remove), a statement about one constraint solved alone that has no counterpart in a
     * simultaneous solve. The first version set α̃ = 0 there, which silently made every PBD constraint
     * hard, and the redundant hard system (4865 constraints on 3066 degrees of freedom at 32²) is
     * singular: conjugate gradients diverged and the shipped scenes went NaN within one or two steps.
     */
    public SolverSettings withSolver(SolverType t) {
        return withModeAndSolver(mode, t);
    }

    /**
     * Mode and solver at once, the pair checked together: what the two withers above check one at a time,
     * without an order to call them in (PBD with a global solver is refused, naming the solver).
     */
    public SolverSettings withModeAndSolver(ConstraintMode m, SolverType t) {
        if (m == null) throw new IllegalArgumentException("mode must be PBD or XPBD, was null");
        if (t == null) throw new IllegalArgumentException("solver must be one of " + Arrays.toString(SolverType.values()) + ", was null");
        if (m == ConstraintMode.PBD && t != SolverType.GAUSS_SEIDEL)
            throw new IllegalArgumentException("solver must be gauss-seidel in PBD mode (the other solvers need XPBD's compliance), was " + t.label());
        return new SolverSettings(m, iterations, substeps, timestep, mullerCorrection, gravityX, gravityY, gravityZ, damping, order, threads, t, pcgTolerance, pcgMaxIterations);
    }

    /** Relative residual at which conjugate gradients stop, in (0, 1). */
    public double pcgTolerance() { return pcgTolerance; }

    public SolverSettings withPcgTolerance(double tol) {
        if (!(tol > 0 && tol < 1)) throw new IllegalArgumentException("pcgTolerance must be in (0, 1), was " + tol);
        return new SolverSettings(mode, iterations, substeps, timestep, mullerCorrection, gravityX, gravityY, gravityZ, damping, order, threads, solver, tol, pcgMaxIterations);
    }

    /** Most conjugate-gradient iterations per global iteration, ≥ 1. */
    public int pcgMaxIterations() { return pcgMaxIterations; }

    public SolverSettings withPcgMaxIterations(int n) {
        Check.inRange("pcgMaxIterations", n, 1, EngineRange.MAX_PCG_ITERATIONS);
        return new SolverSettings(mode, iterations, substeps, timestep, mullerCorrection, gravityX, gravityY, gravityZ, damping, order, threads, solver, pcgTolerance, n);
    }

    @Override public boolean equals(Object o) {
        if (!(o instanceof SolverSettings)) return false;
        SolverSettings s = (SolverSettings) o;
        return mode == s.mode && iterations == s.iterations && substeps == s.substeps && timestep == s.timestep
                && mullerCorrection == s.mullerCorrection && gravityX == s.gravityX && gravityY == s.gravityY && gravityZ == s.gravityZ
                && damping == s.damping && order == s.order && threads == s.threads && solver == s.solver
                && pcgTolerance == s.pcgTolerance && pcgMaxIterations == s.pcgMaxIterations;
    }

    @Override public int hashCode() {
        return Objects.hash(mode, iterations, substeps, timestep, mullerCorrection, gravityX, gravityY, gravityZ, damping, order, threads, solver,
                pcgTolerance, pcgMaxIterations);
    }

    @Override public String toString() {
        return mode + " " + solver.label() + ", " + iterations + " iterations × " + substeps + " substeps, dt " + timestep + " s"
                + (mode == ConstraintMode.PBD ? ", Müller's k' " + (mullerCorrection ? "on" : "off") : "")
                + ", gravity (" + gravityX + ", " + gravityY + ", " + gravityZ + ") m/s², damping " + damping + "/s, " + threads + " thread(s)";
    }
}
