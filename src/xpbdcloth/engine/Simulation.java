package xpbdcloth.engine;

import java.util.ArrayList;
import java.util.List;

/**
 * A set of particles, their constraints, kinematic spheres and scripts, stepped by a sequential
 * Gauss–Seidel solver.
 *
 * <p>{@code step(dt)} gathers external forces once ({@link Stage#FORCES}) and runs, for each of s substeps
 * of h = dt/s (Macklin et al. 2019, "Small Steps"):
 * <ol>
 *   <li><b>predict</b>: semi-implicit Euler, v += h·(g + w·f), x_prev = x, x += h·v (free particles);</li>
 *   <li><b>kinematics</b>: scripted pins and spheres move to their place at the substep's end;</li>
 *   <li><b>reset</b>: λ = 0 for every constraint (once per substep, never per sweep);</li>
 *   <li><b>solve</b>: n sweeps, each projecting every constraint in order with the newest positions;</li>
 *   <li><b>update velocities</b>: v = (x − x_prev)/h.</li>
 * </ol>
 * External forces are gathered once per step and act on all of its substeps. The constraint order is
 * cloth constraints as added, then attachments, then contacts, so hard contacts have the last word.
 *
 * <p>Last line of defence: the state is copied before every step (into arrays made once) and checked
 * after it; a step that leaves a non-finite number is undone and reported, never kept.
 */
public final class Simulation {
    private final Particles particles;
    private final SolverSettings settings;
    private final List<Constraint> body = new ArrayList<>();
    private final List<AttachmentConstraint> attachments = new ArrayList<>();
    private final List<Sphere> spheres = new ArrayList<>();
    private final List<SphereCollisionConstraint> contacts = new ArrayList<>();
    private final List<Kinematics> kinematics = new ArrayList<>();
    private final List<ExternalForce> forces = new ArrayList<>();
    private final SolverContext ctx = new SolverContext();
    private final StepSnapshot snapshot;
    /** The solve order, rebuilt only when the set of constraints changes. */
    private Constraint[] order = new Constraint[0];
    /** The coloured order, built on first use after a change of the constraint set. */
    private Colouring colouring;
    private ParallelSweeps parallel;
    /** The global solver for the body constraints, built on first use after a change of them. */
    private GlobalSolver global;
    private Constraint[] afterGlobal;
    private double time;
    private long stepCount;
    private SweepListener sweepListener;

    public Simulation(Particles particles, SolverSettings settings) {
        if (particles == null) throw new IllegalArgumentException("particles must not be null, was null");
        if (settings == null) throw new IllegalArgumentException("settings must not be null, was null");
        this.particles = particles;
        this.settings = settings;
        this.snapshot = new StepSnapshot(particles.count());
    }

    public Particles particles() { return particles; }
    public SolverSettings settings() { return settings; }
    public double time() { return time; }
    public long stepCount() { return stepCount; }
    public List<Sphere> spheres() { return java.util.Collections.unmodifiableList(spheres); }

    /** The constraints in solve order (a live view; do not modify). */
    public Constraint[] constraints() { return order; }

    /** Adds a constraint on particles that exist. */
    public Simulation add(Constraint c) {
        if (c == null) throw new IllegalArgumentException("constraint must not be null, was null");
        for (int i : c.particles()) Check.index("constraint particle", i, particles.count());
        body.add(c);
        rebuildOrder();
        return this;
    }

    public Simulation addAll(List<? extends Constraint> cs) {
        for (Constraint c : cs) for (int i : c.particles()) Check.index("constraint particle", i, particles.count());
        body.addAll(cs);
        rebuildOrder();
        return this;
    }

    /** Adds a sphere and a contact with every particle (brute force, O(particles × spheres)). */
    public Simulation add(Sphere s) {
        if (s == null) throw new IllegalArgumentException("sphere must not be null, was null");
        spheres.add(s);
        for (int i = 0; i < particles.count(); i++) contacts.add(new SphereCollisionConstraint(i, s));
        rebuildOrder();
        return this;
    }

    public Simulation add(Kinematics k) {
        if (k == null) throw new IllegalArgumentException("kinematics must not be null, was null");
        kinematics.add(k);
        return this;
    }

    public Simulation add(ExternalForce f) {
        if (f == null) throw new IllegalArgumentException("force must not be null, was null");
        forces.add(f);
        return this;
    }

    public Simulation remove(ExternalForce f) {
        forces.remove(f);
        return this;
    }

    /** Holds particle i at (x, y, z) until {@link #release}; returns the attachment to move its target. */
    public AttachmentConstraint attach(int i, double x, double y, double z) {
        Check.index("particle", i, particles.count());
        AttachmentConstraint a = new AttachmentConstraint(i, x, y, z);
        attachments.add(a);
        rebuildOrder();
        return a;
    }

    public void release(AttachmentConstraint a) {
        if (attachments.remove(a)) rebuildOrder();
    }

    /** Sets PBD stiffness k for every constraint of a family. */
    public void setStiffness(ConstraintFamily family, double k) {
        Check.inRange("stiffness", k, 0, 1);
        for (Constraint c : body) if (c.family() == family) c.setStiffness(k);
    }

    /** Sets XPBD compliance α (m/N) for every constraint of a family. */
    public void setCompliance(ConstraintFamily family, double alpha) {
        Check.nonNegative("compliance", alpha);
        for (Constraint c : body) if (c.family() == family) c.setCompliance(alpha);
    }

    private void rebuildOrder() {
        Constraint[] next = new Constraint[body.size() + attachments.size() + contacts.size()];
        int n = 0;
        for (Constraint c : body) next[n++] = c;
        for (Constraint c : attachments) next[n++] = c;
        for (Constraint c : contacts) next[n++] = c;
        order = next;
        colouring = null;
        global = null;
    }

    private Colouring colouring() {
        if (colouring == null) {
            List<Colouring> parts = new ArrayList<>();
            parts.add(Colouring.of(body.toArray(new Constraint[0]), particles.count()));
            parts.add(Colouring.of(attachments.toArray(new Constraint[0]), particles.count()));
            parts.add(Colouring.of(contacts.toArray(new Constraint[0]), particles.count()));
            colouring = Colouring.concat(parts);
        }
        return colouring;
    }

    /** Number of colours of the coloured order (built if needed): the barriers per sweep when parallel. */
    public int colourCount() { return colouring().colours(); }

    /** One step of the settings' timestep. */
    public void step() { step(settings.timestep()); }

    /**
     * One step of dt seconds, split into the settings' substeps. If it leaves any position or velocity
     * non-finite, the state from before the step is restored and a {@link SimulationDivergedException}
     * names the stage and constraint family that produced the first non-finite number.
     */
    public void step(double dt) {
        Check.positive("dt", dt);
        snapshot.save(particles, spheres, time, stepCount);
        run(dt, null);
        if (!Metrics.allFinite(particles)) throw diverged(dt);
    }

    /**
     * The stages of one step (see {@link Stage}). With a probe (only when replaying a step that
     * diverged) the state is checked after every stage and every projection; without one, the loop
     * pays one null test per stage.
     */
    private void run(double dt, Probe probe) {
        final int substeps = settings.substeps(), iterations = settings.iterations();
        final double h = dt / substeps;
        for (int f = 0, nf = forces.size(); f < nf; f++) forces.get(f).apply(particles, time, dt);
        if (probe != null) probe.check(Stage.FORCES);
        ctx.load(settings, h);
        final boolean coloured = settings.order() == ConstraintOrder.COLOURED;
        final Colouring col = coloured ? colouring() : null;
        final Constraint[] cs = coloured ? col.ordered : order;
        final ParallelSweeps team = probe == null ? parallelFor(settings.threads()) : null;
        for (int s = 0; s < substeps; s++) {
            predict(h);
            if (probe != null) probe.check(Stage.PREDICT);
            final double t = time + h;
            for (int k = 0, nk = kinematics.size(); k < nk; k++) kinematics.get(k).apply(particles, t);
            for (int k = 0, nk = spheres.size(); k < nk; k++) spheres.get(k).advance(t, h);
            if (probe != null) probe.check(Stage.KINEMATICS);
            for (Constraint c : cs) c.beginSubstep(ctx);
            if (sweepListener != null) sweepListener.afterSweep(this, s, -1);
            if (settings.solver() != SolverType.GAUSS_SEIDEL) {
                GlobalSolver g = globalSolver();
                for (int it = 0; it < iterations; it++) {
                    g.iterate(particles, ctx);
                    if (probe != null) probe.checkBody(g);
                    project(afterGlobal, probe);
                    if (sweepListener != null) sweepListener.afterSweep(this, s, it);
                }
            } else if (team != null && sweepListener == null) {
                team.sweep(col, particles, ctx, iterations);
            } else {
                for (int it = 0; it < iterations; it++) {
                    project(cs, probe);
                    if (sweepListener != null) sweepListener.afterSweep(this, s, it);
                }
            }
            updateVelocities(h);
            if (probe != null) probe.check(Stage.UPDATE_VELOCITIES);
            time = t;
        }
        java.util.Arrays.fill(particles.force, 0);
        stepCount++;
    }

    /** One Gauss–Seidel sweep over {@code cs}; with a probe, each projection is checked. */
    private void project(Constraint[] cs, Probe probe) {
        if (probe == null) { for (Constraint c : cs) c.project(particles, ctx); return; }
        for (Constraint c : cs) {
            c.project(particles, ctx);
            probe.check(c);
        }
    }

    /** Restores the state before the step, replays it with a probe to find the culprit, restores again. */
    private SimulationDivergedException diverged(double dt) {
        restoreSnapshot();
        Probe probe = new Probe();
        try {
            run(dt, probe);
        } catch (Probe.Found found) {
            // the probe has recorded where
        }
        restoreSnapshot();
        // A step whose replay stays finite cannot happen in a deterministic engine; say "solve" if it does.
        return new SimulationDivergedException(stepCount + 1, probe.stage == null ? Stage.SOLVE : probe.stage, probe.family);
    }

    private void restoreSnapshot() {
        snapshot.restore(particles, spheres);
        time = snapshot.time;
        stepCount = snapshot.stepCount;
    }

    /** Finds the first stage and constraint family of a replayed step that leave a non-finite number. */
    private final class Probe {
        final class Found extends RuntimeException {
            Found() { super(null, null, false, false); }
        }

        Stage stage;
        ConstraintFamily family;

        void check(Stage st) {
            boolean finite = Metrics.allFinite(particles);
            if (st == Stage.FORCES) for (double f : particles.force) finite &= Double.isFinite(f);
            if (!finite) found(st, null);
        }

        void check(Constraint c) {
            for (int i : c.particles())
                for (int k = 3 * i; k < 3 * i + 3; k++)
                    if (!Double.isFinite(particles.x[k])) found(Stage.SOLVE, c.family());
        }

        /** After a global iteration: the first body constraint on a non-finite particle names the family. */
        void checkBody(GlobalSolver g) {
            for (Constraint c : g.constraints()) check(c);
        }

        private void found(Stage st, ConstraintFamily f) {
            stage = st;
            family = f;
            throw new Found();
        }
    }

    private GlobalSolver globalSolver() {
        boolean mg = settings.solver() == SolverType.MULTIGRID_PCG;
        if (global == null || global.multigrid() != mg || global.tolerance() != settings.pcgTolerance() || global.maxIterations() != settings.pcgMaxIterations()) {
            global = new GlobalSolver(body.toArray(new Constraint[0]), particles.count(), mg, settings.pcgTolerance(), settings.pcgMaxIterations());
            Constraint[] rest = new Constraint[attachments.size() + contacts.size()];
            int n = 0;
            for (Constraint c : attachments) rest[n++] = c;
            for (Constraint c : contacts) rest[n++] = c;
            afterGlobal = rest;
        }
        return global;
    }

    /** Conjugate-gradient iterations of the last global iteration (0 with Gauss–Seidel). */
    public int lastPcgIterations() { return global == null ? 0 : global.lastIterations(); }

    /** Global iterations whose step was not taken (see {@link GlobalSolver#iterate}), 0 with Gauss–Seidel. */
    public int rejectedGlobalSteps() { return global == null ? 0 : global.rejectedSteps(); }

    /** Conjugate-gradient iterations since the global solver was built. */
    public int totalPcgIterations() { return global == null ? 0 : global.totalIterations(); }

    /** Multigrid levels and setup time (ns) of the global solver, {0, 0} if none. */
    public long[] multigridSetup() { return global == null ? new long[2] : new long[] {global.multigridLevels(), global.multigridSetupNanos()}; }

    /** The helper threads for {@code threads} (made once per thread count), or null for one thread. */
    private ParallelSweeps parallelFor(int threads) {
        if (threads <= 1) return null;
        if (parallel == null || parallel.threads() != threads) {
            if (parallel != null) parallel.close();
            parallel = new ParallelSweeps(threads);
        }
        return parallel;
    }

    /** Stops helper threads, if any (they are daemons, so this is only needed to free them early). */
    public void close() {
        if (parallel != null) parallel.close();
        parallel = null;
    }

    private void predict(double h) {
        final double[] x = particles.x, prev = particles.prev, v = particles.v, w = particles.w, f = particles.force;
        final double gx = settings.gravityX(), gy = settings.gravityY(), gz = settings.gravityZ();
        for (int i = 0, n = particles.count(); i < n; i++) {
            final int k = 3 * i;
            prev[k] = x[k]; prev[k + 1] = x[k + 1]; prev[k + 2] = x[k + 2];
            final double wi = w[i];
            if (wi == 0) continue;
            v[k] += h * (gx + wi * f[k]);
            v[k + 1] += h * (gy + wi * f[k + 1]);
            v[k + 2] += h * (gz + wi * f[k + 2]);
            x[k] += h * v[k]; x[k + 1] += h * v[k + 1]; x[k + 2] += h * v[k + 2];
        }
    }

    private void updateVelocities(double h) {
        final double[] x = particles.x, prev = particles.prev, v = particles.v;
        final double inv = 1.0 / h;
        for (int k = 0, n = 3 * particles.count(); k < n; k++) v[k] = (x[k] - prev[k]) * inv;
    }

    /** Observes the solver after every sweep (convergence experiments); null for none. */
    public void setSweepListener(SweepListener listener) { sweepListener = listener; }

    /** The substep h of the step in progress (or of the last step), seconds. */
    public double substep() { return ctx.h; }

    /**
     * ‖C + α̃λ‖₂ over the equality constraints (contacts and attachments left out): the residual of
     * XPBD's constraint equation, zero when every constraint holds at its compliant equilibrium. In PBD
     * mode α̃ is taken as 0, so it is ‖C‖₂.
     */
    public double residual() {
        double sum = 0;
        double inverseH2 = ctx.inverseH2;
        boolean xpbd = settings.mode() == ConstraintMode.XPBD;
        for (Constraint c : order) {
            ConstraintFamily f = c.family();
            if (f == ConstraintFamily.COLLISION || f == ConstraintFamily.ATTACHMENT) continue;
            double r = c.evaluate(particles) + (xpbd ? c.compliance() * inverseH2 * c.lambda() : 0);
            sum += r * r;
        }
        return Math.sqrt(sum);
    }

    /** Places every sphere at its path's start and sets the clock to 0 (scene reset). */
    public void resetClock() {
        time = 0;
        stepCount = 0;
        for (Sphere s : spheres) s.moveTo(0);
    }
}
