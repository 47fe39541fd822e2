package xpbdcloth.engine;

import java.util.ArrayList;
import java.util.List;

/**
 * A set of particles, their constraints, kinematic spheres and scripts, stepped by position-based
 * dynamics.
 *
 * <p>{@code step(dt)} gathers external forces once ({@link Stage#FORCES}) and runs, for each of s substeps
 * of h = dt/s (Macklin et al. 2019, "Small Steps"), the stages of {@link Stage}, each one call in
 * {@link #run}:
 * <ol>
 *   <li><b>predict</b>: semi-implicit Euler, v += h·(g + w·f), x_prev = x, x += h·v (free particles);</li>
 *   <li><b>kinematics</b>: scripted pins, spheres, boxes and capsules move to their place at the substep's end, and
 *       attachment targets glide their share of the way to where they were last moved;</li>
 *   <li><b>collide</b>: this substep's contacts are found ({@link ContactSet});</li>
 *   <li><b>solve</b>: λ = 0 for every constraint (once per substep, never per sweep), then n sweeps or
 *       global iterations ({@link SolveStage}), each ending with the contacts;</li>
 *   <li><b>update velocities</b>: v = (x − x_prev)/h;</li>
 *   <li><b>velocity pass</b>: damping v ← v·e^(−c·h), frame-rate independent (none by default).</li>
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
    /** The cloth constraints, block by block in Gauss–Seidel order. */
    private final List<ConstraintBlock> body = new ArrayList<>();
    private final List<ConstraintBlock> bodyView = java.util.Collections.unmodifiableList(body);
    /** The last block made here for constraints added one by one (the only body block that grows). */
    private ConstraintBlock openBlock;
    private final AttachmentBlock attachments = new AttachmentBlock(4);
    /** The views handed out by {@link #attach}, re-indexed when one is released. */
    private final List<AttachmentConstraint> grabs = new ArrayList<>();
    private final List<Sphere> spheres = new ArrayList<>();
    private final List<RigidCollider> solids = new ArrayList<>();
    /** The cloth's contacts with itself, or null. */
    private SelfCollision self;
    private final List<Plane> planes = new ArrayList<>();
    private final ContactSet contacts = new ContactSet();
    private final List<Kinematics> kinematics = new ArrayList<>();
    private final List<ExternalForce> forces = new ArrayList<>();
    private final SolverContext ctx = new SolverContext();
    private final StepSnapshot snapshot;
    /** Where the last substep's prediction put each particle (y), for {@link StepBalance}. */
    private final double[] prediction;
    /** The solve order (cloth constraints, then attachments), rebuilt only when either set changes. */
    private SweepOrder order = SweepOrder.asBuilt(List.of());
    /** The cloth constraints' colouring, built on first use after they change (not when grabbing). */
    private Colouring bodyColouring;
    private SweepOrder coloured;
    /** {@link #constraints()}, made when first asked for after a change. */
    private Constraint[] views;
    private Team parallel;
    /** The global solver for the cloth constraints, built on first use after they change (not when grabbing). */
    private GlobalSolver global;
    /** The solve stage, chosen when the constraint set or the solver settings change. */
    private SolveStage solve;
    private final SolveChoice solvedFor = new SolveChoice();
    private double time;
    private long stepCount;
    private SweepListener sweepListener = NO_LISTENER;
    private static final SweepListener NO_LISTENER = (sim, substep, sweep) -> { };

    public Simulation(Particles particles, SolverSettings settings) {
        if (particles == null) throw new IllegalArgumentException("particles must not be null, was null");
        if (settings == null) throw new IllegalArgumentException("settings must not be null, was null");
        this.particles = particles;
        this.settings = settings;
        this.snapshot = new StepSnapshot(particles.count());
        this.prediction = new double[3 * particles.count()];
        attachments.owner = this;
    }

    public Particles particles() { return particles; }
    public SolverSettings settings() { return settings; }
    public double time() { return time; }
    public long stepCount() { return stepCount; }
    public List<Sphere> spheres() { return java.util.Collections.unmodifiableList(spheres); }
    public List<Plane> planes() { return java.util.Collections.unmodifiableList(planes); }
    /** The boxes and capsules. */
    public List<RigidCollider> solids() { return java.util.Collections.unmodifiableList(solids); }

    /** The cloth's self-collision, or null when it passes through itself. */
    public SelfCollision selfCollision() { return self; }

    /** Spheres, planes, boxes and capsules together. */
    public int colliderCount() { return spheres.size() + planes.size() + solids.size(); }
    public List<ExternalForce> forces() { return java.util.Collections.unmodifiableList(forces); }

    /** Whether anything moves particles by script (pin scripts, kinematic paths). */
    public boolean hasKinematics() { return !kinematics.isEmpty(); }

    /**
     * Views of the constraints in solve order (cloth constraints, then attachments), made when first
     * asked for after the set changed; do not modify. The solvers work on {@link #blocks()}.
     */
    public Constraint[] constraints() {
        if (views == null) {
            Constraint[] cloth = bodyViews();
            views = java.util.Arrays.copyOf(cloth, cloth.length + grabs.size());
            for (int k = 0; k < grabs.size(); k++) views[cloth.length + k] = grabs.get(k);
        }
        return views;
    }

    /** The number of constraints, attachments included. */
    public int constraintCount() {
        int n = attachments.count();
        for (ConstraintBlock b : body) n += b.count();
        return n;
    }

    /** The cloth constraints' blocks in solve order (attachments not included); a live view. */
    public List<ConstraintBlock> blocks() { return bodyView; }

    /**
     * Adds a constraint on particles that exist. Its data moves into this simulation's blocks and the
     * object stays its view; a constraint already in a simulation is refused.
     */
    public Simulation add(Constraint c) {
        if (c == null) throw new IllegalArgumentException("constraint must not be null, was null");
        checkAddable(c);
        addOne(c);
        bodyChanged();
        return this;
    }

    /** Adds constraints in order; all are checked before any is added. */
    public Simulation addAll(List<? extends Constraint> cs) {
        java.util.Set<Constraint> seen = new java.util.HashSet<>();
        for (Constraint c : cs) {
            if (c == null) throw new IllegalArgumentException("constraint must not be null, was null");
            checkAddable(c);
            if (!seen.add(c)) throw new IllegalArgumentException("constraint must be added once, was listed twice (" + c.family() + ")");
        }
        for (Constraint c : cs) addOne(c);
        bodyChanged();
        return this;
    }

    private void checkAddable(Constraint c) {
        for (int i : c.particles()) Check.index("constraint particle", i, particles.count());
        if (c.block.owner != null)
            throw new IllegalArgumentException("constraint must not be in a simulation already, was a " + c.family() + " constraint of " + (c.block.owner == this ? "this one" : "another"));
    }

    private void addOne(Constraint c) {
        ConstraintBlock last = body.isEmpty() ? null : body.get(body.size() - 1);
        if (last == null || last != openBlock || last.getClass() != c.block.getClass() || last.family() != c.family()) {
            openBlock = c.block.emptyLike(16);
            openBlock.owner = this;
            body.add(openBlock);
        }
        int j = openBlock.appendCopy(c.block, c.index);
        c.block = openBlock;
        c.index = j;
    }

    /** Adds a whole block of constraints after those already added, taking it over (or a copy, if another simulation has it). */
    public Simulation add(ConstraintBlock block) {
        if (block == null) throw new IllegalArgumentException("block must not be null, was null");
        return addBlocks(List.of(block));
    }

    /** Adds whole blocks (a cloth's), taking them over, or copies of them if another simulation has them. */
    Simulation addBlocks(List<ConstraintBlock> blocks) {
        for (ConstraintBlock b : blocks)
            for (int i = 0; i < b.count(); i++)
                for (int k = 0; k < b.arity(); k++) Check.index("constraint particle", b.particle(i, k), particles.count());
        for (ConstraintBlock b : blocks) {
            ConstraintBlock mine = b;
            if (b.owner != null) {
                mine = b.emptyLike(b.count());
                for (int i = 0; i < b.count(); i++) mine.appendCopy(b, i);
            }
            mine.owner = this;
            body.add(mine);
        }
        openBlock = null;
        bodyChanged();
        return this;
    }

    /** Adds a sphere; its contacts are found each substep (brute force, O(particles × spheres)). */
    public Simulation add(Sphere s) {
        if (s == null) throw new IllegalArgumentException("sphere must not be null, was null");
        spheres.add(s);
        contacts.reserve(particles.count(), colliderCount());
        return this;
    }

    /** Adds a fixed plane (a floor, a wall, a slope); its contacts are found each substep like the spheres'. */
    public Simulation add(Plane plane) {
        if (plane == null) throw new IllegalArgumentException("plane must not be null, was null");
        planes.add(plane);
        contacts.reserve(particles.count(), colliderCount());
        return this;
    }

    /** Makes the cloth keep a thickness from itself (replacing any earlier self-collision); null turns it off. */
    public Simulation selfCollision(SelfCollision s) {
        if (s != null && s.restParticles() != particles.count())
            throw new IllegalArgumentException("self-collision was made for " + s.restParticles() + " particles, the simulation has " + particles.count());
        self = s;
        return this;
    }

    /** Adds a box or a capsule; its contacts are found each substep like the spheres', continuous when fast. */
    public Simulation add(RigidCollider solid) {
        if (solid == null) throw new IllegalArgumentException("collider must not be null, was null");
        solids.add(solid);
        contacts.reserve(particles.count(), colliderCount());
        return this;
    }

    public Simulation add(Kinematics k) {
        if (k == null) throw new IllegalArgumentException("kinematics must not be null, was null");
        kinematics.add(k);
        return this;
    }

    public Simulation add(ExternalForce f) {
        if (f == null) throw new IllegalArgumentException("force must not be null, was null");
        f.check(particles);
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
        AttachmentConstraint a = attachments.view(attachments.add(i, x, y, z));
        grabs.add(a);
        attachmentsChanged();
        return a;
    }

    /** Lets go of an attachment made by {@link #attach}; the object keeps its particle and target. */
    public void release(AttachmentConstraint a) {
        int k = grabs.indexOf(a);
        if (k < 0) return;
        AttachmentBlock own = new AttachmentBlock(1);
        own.appendCopy(attachments, a.index);
        attachments.remove(a.index);
        grabs.remove(k);
        for (int j = k; j < grabs.size(); j++) grabs.get(j).index--;
        a.block = own;
        a.index = 0;
        attachmentsChanged();
    }

    /** Sets PBD stiffness k for every constraint of a family. */
    public void setStiffness(ConstraintFamily family, double k) {
        Check.inRange("stiffness", k, 0, 1);
        for (ConstraintBlock b : body) if (b.family() == family) b.setStiffness(k);
    }

    /** Sets XPBD compliance α (m/N) for every constraint of a family. */
    public void setCompliance(ConstraintFamily family, double alpha) {
        Check.nonNegative("compliance", alpha);
        Check.inRange("compliance", alpha, 0, EngineRange.MAX_COMPLIANCE);
        for (ConstraintBlock b : body) if (b.family() == family) b.setCompliance(alpha);
    }

    private void bodyChanged() {
        bodyColouring = null;
        global = null;
        attachmentsChanged();
    }

    /** Grabbing and releasing land here: the order and stage are remade, the global solver is kept. */
    private void attachmentsChanged() {
        List<ConstraintBlock> all = new ArrayList<>(body);
        all.add(attachments);
        order = SweepOrder.asBuilt(all);
        coloured = null;
        solve = null;
        views = null;
    }

    private SweepOrder colouring() {
        if (coloured == null) {
            if (bodyColouring == null) bodyColouring = Colouring.of(body, particles.count());
            coloured = SweepOrder.coloured(List.of(bodyColouring, Colouring.of(List.of(attachments), particles.count())));
        }
        return coloured;
    }

    /** Number of colours of the coloured order (built if needed): the barriers per sweep when parallel. */
    public int colourCount() { return colouring().phases(); }

    /** The global solver in use (for tests: that grabbing keeps it), or null. */
    GlobalSolver globalSolverInUse() { return global; }

    /** One step of the settings' timestep. */
    public void step() { step(settings.timestep()); }

    /**
     * One step of dt seconds, split into the settings' substeps. If it leaves any position or velocity
     * non-finite, the state from before the step is restored and a {@link SimulationDivergedException}
     * names the stage and constraint family that produced the first non-finite number; if anything inside
     * the step throws, the state is restored too and the exception carries the cause.
     */
    public void step(double dt) {
        Check.positive("dt", dt);
        snapshot.save(particles, spheres, time, stepCount);
        try {
            run(dt, StepObserver.NONE, solveStage());
        } catch (RuntimeException failed) {
            // Whatever a stage throws, half a step is not a state: put the one before it back.
            restoreSnapshot();
            throw new SimulationDivergedException(stepCount + 1, failed);
        }
        if (!Metrics.allFinite(particles)) throw diverged(dt);
    }

    /**
     * The stages of one step (see {@link Stage}), each a call. The observer hears the end of every stage
     * (a no-op but when replaying a step that diverged, whose solve stage then checks every projection).
     */
    private void run(double dt, StepObserver observer, SolveStage solveStage) {
        final int substeps = settings.substeps(), iterations = settings.iterations();
        final double h = dt / substeps;
        for (int f = 0, nf = forces.size(); f < nf; f++) forces.get(f).apply(particles, time, dt);
        observer.after(Stage.FORCES);
        collideNanos = 0;
        solveNanos = 0;
        contacts.takeProjectNanos();
        ctx.load(settings, h);
        for (int s = 0; s < substeps; s++) {
            final double t = time + h;
            predict(h);
            particles.clearDepenetration();
            System.arraycopy(particles.x, 0, prediction, 0, prediction.length);
            observer.after(Stage.PREDICT);
            moveKinematics(t, h);
            attachments.glide((s + 1) / (double) substeps);
            observer.after(Stage.KINEMATICS);
            long c0 = System.nanoTime();
            contacts.collide(particles, spheres, planes, solids, self, h, settings.threads() > 1 && sweepListener == NO_LISTENER ? parallelFor(settings.threads()) : null);
            collideNanos += System.nanoTime() - c0;
            observer.after(Stage.COLLIDE);
            for (int b = 0, nb = body.size(); b < nb; b++) body.get(b).beginSubstep(ctx);
            attachments.beginSubstep(ctx);
            sweepListener.afterSweep(this, s, -1);
            long s0 = System.nanoTime();
            solveStage.solve(s, iterations);
            solveNanos += System.nanoTime() - s0;
            observer.after(Stage.SOLVE);
            updateVelocities(h);
            observer.after(Stage.UPDATE_VELOCITIES);
            velocityPass(h);
            observer.after(Stage.VELOCITY_PASS);
            time = t;
        }
        attachments.arrive();
        projectContactNanos = contacts.takeProjectNanos();
        java.util.Arrays.fill(particles.force, 0);
        stepCount++;
    }

    private void moveKinematics(double t, double h) {
        for (int k = 0, nk = kinematics.size(); k < nk; k++) kinematics.get(k).apply(particles, t);
        for (int k = 0, nk = spheres.size(); k < nk; k++) spheres.get(k).advance(t, h);
        for (int k = 0, nk = solids.size(); k < nk; k++) solids.get(k).advance(t, h);
    }

    /**
     * The solve stage for the current settings: chosen here, once per change of the constraint set or
     * of the solver type, order, thread count, PCG settings or listener, never inside the substep loop.
     */
    private SolveStage solveStage() {
        SolverType type = settings.solver();
        boolean coloured = settings.order() == ConstraintOrder.COLOURED;
        int threads = settings.threads();
        boolean pcg = type.isGlobal();
        GlobalSolver g = pcg ? globalSolver() : null; // remade if the PCG settings changed
        if (solve != null && solvedFor.matches(type, coloured, threads, sweepListener, g)) return solve;
        if (type == SolverType.VERTEX_BLOCK_DESCENT) {
            solve = new VertexBlockDescent(body, attachments, particles, ctx, settings, contacts, this, sweepListener,
                    sweepListener == NO_LISTENER ? parallelFor(threads) : null);
        } else if (pcg) {
            List<ConstraintBlock> local = new ArrayList<>();
            for (ConstraintBlock blk : body) if (!GlobalSolver.takes(blk)) local.add(blk);
            SequentialSweeps rest = new SequentialSweeps(SweepOrder.asBuilt(List.of(attachments)), particles, ctx, contacts, this, sweepListener);
            solve = new GlobalIterations(g, SweepOrder.asBuilt(local), rest, new SequentialSweeps(order, particles, ctx, contacts, this, sweepListener), contacts, particles, ctx, this, sweepListener);
        } else if (!coloured) {
            solve = new SequentialSweeps(order, particles, ctx, contacts, this, sweepListener);
        } else {
            SweepOrder col = colouring();
            SequentialSweeps sequential = new SequentialSweeps(col, particles, ctx, contacts, this, sweepListener);
            // The team runs a substep's sweeps in one go, so a listener to single sweeps gets the sequential one.
            Team team = sweepListener == NO_LISTENER ? parallelFor(threads) : null;
            solve = team == null ? sequential : new ParallelColouredSweeps(col, team, particles, ctx, contacts, sequential);
        }
        solvedFor.set(type, coloured, threads, sweepListener, g);
        return solve;
    }

    /** What the solve stage was chosen for (compared each step without allocating). */
    private static final class SolveChoice {
        SolverType type;
        boolean coloured;
        int threads;
        SweepListener listener;
        GlobalSolver global;

        boolean matches(SolverType t, boolean c, int n, SweepListener l, GlobalSolver g) {
            return t == type && c == coloured && n == threads && l == listener && g == global;
        }

        void set(SolverType t, boolean c, int n, SweepListener l, GlobalSolver g) {
            type = t; coloured = c; threads = n; listener = l; global = g;
        }
    }

    /** Restores the state before the step, replays it with a probe to find the culprit, restores again. */
    private SimulationDivergedException diverged(double dt) {
        restoreSnapshot();
        StepProbe probe = new StepProbe(particles);
        try {
            run(dt, probe, solveStage().probed(probe));
        } catch (StepProbe.Found found) {
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
        for (RigidCollider s : solids) s.moveTo(time); // a pose is a function of time
    }

    private GlobalSolver globalSolver() {
        boolean mg = settings.solver() == SolverType.MULTIGRID_PCG;
        if (global == null || global.multigrid() != mg || global.tolerance() != settings.pcgTolerance() || global.maxIterations() != settings.pcgMaxIterations())
            global = new GlobalSolver(globalViews(), particles.count(), mg, settings.pcgTolerance(), settings.pcgMaxIterations());
        return global;
    }

    private Constraint[] bodyViews() {
        List<Constraint> v = new ArrayList<>();
        for (ConstraintBlock b : body) for (int i = 0; i < b.count(); i++) v.add(b.view(i));
        return v.toArray(new Constraint[0]);
    }

    /** The cloth constraints the global system takes; the other blocks are swept before each global step. */
    private Constraint[] globalViews() {
        List<Constraint> v = new ArrayList<>();
        for (ConstraintBlock b : body) if (GlobalSolver.takes(b)) for (int i = 0; i < b.count(); i++) v.add(b.view(i));
        return v.toArray(new Constraint[0]);
    }

    /** Conjugate-gradient iterations of the last global iteration (0 with Gauss–Seidel). */
    public int lastPcgIterations() { return global == null || settings.solver() == SolverType.GAUSS_SEIDEL ? 0 : global.lastIterations(); }

    /** Global iterations whose step was not taken since the global solver was built (see {@link GlobalSolver#iterate}). */
    public int rejectedGlobalSteps() { return global == null ? 0 : global.rejectedSteps(); }

    /** Conjugate-gradient iterations since the global solver was built. */
    public int totalPcgIterations() { return global == null ? 0 : global.totalIterations(); }

    /** Nanoseconds the global solver spent on its setup (once per constraint topology), 0 with Gauss–Seidel. */
    public long globalSetupNanos() { return global == null ? 0 : global.setupNanos(); }

    /** Multigrid levels and setup time (ns) of the global solver, {0, 0} if none. */
    public long[] multigridSetup() { return global == null ? new long[2] : new long[] {global.multigridLevels(), global.multigridSetupNanos()}; }

    /** The helper threads for {@code threads} (made once per thread count), or null for one thread. */
    private Team parallelFor(int threads) {
        if (threads <= 1) return null;
        if (parallel == null || parallel.threads() != threads) {
            if (parallel != null) parallel.close();
            parallel = new Team(threads);
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

    /** Damping, v ← v·e^(−c·h) for free particles (pinned ones have v = 0 or a scripted velocity). */
    private void velocityPass(double h) {
        final double c = settings.damping();
        if (c == 0) return;
        final double decay = Math.exp(-c * h);
        final double[] v = particles.v, w = particles.w;
        for (int i = 0, n = particles.count(); i < n; i++) {
            if (w[i] == 0) continue;
            final int k = 3 * i;
            v[k] *= decay; v[k + 1] *= decay; v[k + 2] *= decay;
        }
    }

    /** Observes the solver after every sweep (convergence experiments); null for none. */
    public void setSweepListener(SweepListener listener) { sweepListener = listener == null ? NO_LISTENER : listener; }

    /**
     * How far the last step is from solving its own equation: the worst free particle's leftover force as a
     * fraction of its weight ({@link StepBalance}); below {@link StepBalance#CONVERGED} the shape is the material's.
     */
    public double balance() {
        if (balance == null) balance = new StepBalance(particles.count());
        return balance.worst(this);
    }

    private StepBalance balance;

    /** The last substep's prediction y (live; null before the first step). */
    double[] lastPrediction() { return stepCount == 0 ? null : prediction; }

    /** Marks the particles something without an energy holds now: touching a contact or another layer, or attached. */
    void markHeld(boolean[] held) {
        contacts.markTouching(particles, held);
        if (self != null) self.markTouching(particles, held, 1.01);
        for (int i = 0; i < attachments.count(); i++) held[attachments.particle(i, 0)] = true;
    }

    /** Contacts found in the last substep (candidates within reach of a sphere, touching or not). */
    public int contactCount() { return contacts.count(); }

    /** Of those, the ones touching their collider now. */
    public int touchingContacts() { return contacts.touching(particles); }

    /** Wall time of the last step's collide stages (finding the contacts, all substeps), ms. */
    public double collideMs() { return collideNanos / 1e6; }

    /** Particles inside a collider at the end of the last step, caught where two colliders close on them (see ContactSet.inside). */
    public int pinchedParticles() { return contacts.inside(particles); }

    /**
     * Wall time the last step spent on contacts, ms: finding them (hash, self-collision pairs, colliders)
     * and projecting them in every sweep. Projection is timed per sweep, not per contact, so the clock
     * costs two reads a sweep.
     */
    public double contactMs() { return (collideNanos + projectContactNanos) / 1e6; }

    /** Wall time of the last step's solve stages minus the contacts projected in them: the cloth's own constraints, ms. */
    public double constraintSolveMs() { return (solveNanos - projectContactNanos) / 1e6; }

    private long collideNanos, solveNanos, projectContactNanos;

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
        for (ConstraintBlock b : body) {
            ConstraintFamily f = b.family();
            if (f == ConstraintFamily.COLLISION || f == ConstraintFamily.ATTACHMENT) continue;
            for (int i = 0; i < b.count(); i++) {
                double r = b.evaluate(i, particles) + (xpbd ? b.compliance(i) * inverseH2 * b.lambda[i] : 0);
                sum += r * r;
            }
        }
        return Math.sqrt(sum);
    }

    /** Places every sphere, box and capsule at its path's start and sets the clock to 0 (scene reset). */
    public void resetClock() {
        time = 0;
        stepCount = 0;
        for (Sphere s : spheres) s.moveTo(0);
        for (RigidCollider s : solids) s.moveTo(0);
    }
}
