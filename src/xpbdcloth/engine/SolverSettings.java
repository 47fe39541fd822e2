package xpbdcloth.engine;

/**
 * The solver's parameters with their defaults and units, validated at the edge (an invalid value throws
 * {@link IllegalArgumentException} naming the parameter and changes nothing).
 *
 * <p>Defaults follow the original simulator: XPBD, 2 Gauss–Seidel iterations, dt = 20 ms, one substep,
 * gravity 9.81 m/s² along −y (y is up).
 */
public final class SolverSettings {
    private ConstraintMode mode = ConstraintMode.XPBD;
    private int iterations = 2;
    private int substeps = 1;
    private double timestep = 0.020;
    private boolean mullerCorrection = true;
    private double gravityX = 0, gravityY = -9.81, gravityZ = 0;
    /** Velocity damping c, 1/s: v decays as e^(−c·t) in the velocity pass; 0 = none (the original's). */
    private double damping = 0;
    private ConstraintOrder order = ConstraintOrder.AS_BUILT;
    private int threads = 1;
    private SolverType solver = SolverType.GAUSS_SEIDEL;
    /**
     * Inexact Newton: each global iteration is only a linearisation, so its linear system need not be
     * solved tightly; of 1e-1, 1e-3 and 1e-5, 1e-1 reached a 1e-6 nonlinear residual soonest (experiment 7).
     */
    private double pcgTolerance = 1e-1;
    /** A cap that keeps a global iteration's cost bounded when the system is badly conditioned. */
    private int pcgMaxIterations = 300;
    /** Bumped on every change that invalidates a constraint's cached per-iteration stiffness. */
    private long revision;

    public SolverSettings() {}

    public SolverSettings copy() {
        SolverSettings s = new SolverSettings();
        s.mode = mode;
        s.iterations = iterations;
        s.substeps = substeps;
        s.timestep = timestep;
        s.mullerCorrection = mullerCorrection;
        s.gravityX = gravityX; s.gravityY = gravityY; s.gravityZ = gravityZ;
        s.damping = damping;
        s.order = order;
        s.threads = threads;
        s.solver = solver;
        s.pcgTolerance = pcgTolerance;
        s.pcgMaxIterations = pcgMaxIterations;
        return s;
    }

    public ConstraintMode mode() { return mode; }

    /**
     * Every constraint of the simulation switches formulation at the next projection; state is kept.
     * PBD needs the Gauss–Seidel solver (see {@link #solver(SolverType)}); asking for PBD while a global
     * solver is chosen is refused and changes nothing.
     */
    public SolverSettings mode(ConstraintMode m) {
        if (m == null) throw new IllegalArgumentException("mode must be PBD or XPBD, was null");
        if (m == ConstraintMode.PBD && solver != SolverType.GAUSS_SEIDEL)
            throw new IllegalArgumentException("mode must be XPBD while the solver is " + solver.label()
                    + " (PBD's stiffness k is defined per Gauss-Seidel projection), was PBD");
        mode = m;
        return this;
    }

    /** Gauss–Seidel sweeps per substep, n ≥ 1. */
    public int iterations() { return iterations; }

    public SolverSettings iterations(int n) {
        iterations = Check.inRange("iterations", n, 1, EngineRange.MAX_ITERATIONS);
        revision++;
        return this;
    }

    /** Substeps per step, s ≥ 1: the step dt is split into s substeps of h = dt/s (Macklin et al. 2019). */
    public int substeps() { return substeps; }

    public SolverSettings substeps(int s) {
        substeps = Check.inRange("substeps", s, 1, EngineRange.MAX_SUBSTEPS);
        return this;
    }

    /** The step dt in seconds, &gt; 0 (the frame's simulated time). */
    public double timestep() { return timestep; }

    public SolverSettings timestep(double dt) {
        timestep = Check.inRange("dt", dt, EngineRange.MIN_DT, EngineRange.MAX_DT);
        return this;
    }

    /**
     * Whether PBD applies Müller's per-iteration stiffness k' = 1 − (1 − k)^(1/n), which makes n sweeps
     * compound to k on a single constraint; off applies the raw k every sweep.
     */
    public boolean mullerCorrection() { return mullerCorrection; }

    public SolverSettings mullerCorrection(boolean on) {
        mullerCorrection = on;
        revision++;
        return this;
    }

    /** Gravity as an acceleration, m/s². */
    public double gravityX() { return gravityX; }
    public double gravityY() { return gravityY; }
    public double gravityZ() { return gravityZ; }

    public SolverSettings gravity(double gx, double gy, double gz) {
        EngineRange.vector("gravity", gx, gy, gz, EngineRange.MAX_GRAVITY);
        gravityX = gx; gravityY = gy; gravityZ = gz;
        return this;
    }

    /** Velocity damping c (1/s), applied after each substep as v ← v·e^(−c·h). */
    public double damping() { return damping; }

    /**
     * Velocity damping c ∈ [0, {@link EngineRange#MAX_DAMPING}] per second. Multiplying by e^(−c·h) each
     * substep makes the decay e^(−c·t) whatever dt and the substep count are (a per-step factor would make
     * the cloth's damping depend on the frame rate).
     */
    public SolverSettings damping(double perSecond) {
        damping = Check.inRange("damping", perSecond, 0, EngineRange.MAX_DAMPING);
        return this;
    }

    /** The order of each sweep (default as built); more than one thread always uses the coloured order. */
    public ConstraintOrder order() { return threads > 1 ? ConstraintOrder.COLOURED : order; }

    public SolverSettings order(ConstraintOrder o) {
        if (o == null) throw new IllegalArgumentException("order must be AS_BUILT or COLOURED, was null");
        order = o;
        return this;
    }

    /** Threads for the sweeps, 1 to 64; above 1 the coloured order is split across them. */
    public int threads() { return threads; }

    public SolverSettings threads(int t) {
        Check.atLeast("threads", t, 1);
        if (t > 64) throw new IllegalArgumentException("threads must be <= 64, was " + t);
        threads = t;
        return this;
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
    public SolverSettings solver(SolverType t) {
        if (t == null) throw new IllegalArgumentException("solver must be one of " + java.util.Arrays.toString(SolverType.values()) + ", was null");
        if (t != SolverType.GAUSS_SEIDEL && mode == ConstraintMode.PBD)
            throw new IllegalArgumentException("solver must be gauss-seidel in PBD mode (the other solvers need XPBD's compliance), was " + t.label());
        solver = t;
        return this;
    }

    /**
     * Mode and solver at once, the pair checked together: what the two setters above check one at a time,
     * without an order to call them in (PBD with a global solver is refused, naming the solver).
     */
    public SolverSettings modeAndSolver(ConstraintMode m, SolverType t) {
        if (m == null) throw new IllegalArgumentException("mode must be PBD or XPBD, was null");
        if (t == null) throw new IllegalArgumentException("solver must be one of " + java.util.Arrays.toString(SolverType.values()) + ", was null");
        if (m == ConstraintMode.PBD && t != SolverType.GAUSS_SEIDEL)
            throw new IllegalArgumentException("solver must be gauss-seidel in PBD mode (the other solvers need XPBD's compliance), was " + t.label());
        mode = m;
        solver = t;
        return this;
    }

    /** Relative residual at which conjugate gradients stop, in (0, 1). */
    public double pcgTolerance() { return pcgTolerance; }

    public SolverSettings pcgTolerance(double tol) {
        if (!(tol > 0 && tol < 1)) throw new IllegalArgumentException("pcgTolerance must be in (0, 1), was " + tol);
        pcgTolerance = tol;
        return this;
    }

    /** Most conjugate-gradient iterations per global iteration, ≥ 1. */
    public int pcgMaxIterations() { return pcgMaxIterations; }

    public SolverSettings pcgMaxIterations(int n) {
        pcgMaxIterations = Check.inRange("pcgMaxIterations", n, 1, EngineRange.MAX_PCG_ITERATIONS);
        return this;
    }

    long revision() { return revision; }
}
