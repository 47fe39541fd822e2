package xpbdcloth.engine;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * A set of particles, their constraints, colliders, forces and scripts, stepped by position-based dynamics.
 *
 * <p>{@code step(dt)} gathers external forces once and runs, for each of s substeps of h = dt/s (Macklin et
 * al. 2019, "Small Steps"), the stages of {@link Stage} in order, each one call in {@link #run}: predict,
 * kinematics (scripts and colliders move to the substep's end, attachment targets glide their share),
 * collide, solve (λ = 0 and each enclosed gas linearised once per substep, then n sweeps or global
 * iterations, each ending with the gases and then the contacts, so hard contacts have the last word; then the self-collision's {@link CrossingGuard}, if any,
 * cuts back motion that would pass the cloth through itself), update velocities, velocity pass (damping).
 *
 * <p>After a step is kept, what changes the material runs ({@link AfterStep}: bending that yields, stiffness
 * that follows the strain).
 *
 * <p>Last line of defence: the state is copied before every step (into arrays made once) and checked
 * after it; a step that leaves a non-finite number, or throws, is undone and reported, never kept.
 *
 * <p>Where the rest lives: the constraints in a {@link ConstraintSet}, the choice of solve stage in
 * {@link SolveStages}, the prediction and velocity update in {@link Integrator}, what a step cost in its
 * {@link StepProfile}.
 */
public final class Simulation {
    private final Particles particles;
    private SolverSettings settings;
    private final ConstraintSet constraints;
    private final List<Sphere> spheres = new ArrayList<>();
    private final List<RigidCollider> solids = new ArrayList<>();
    private final List<Plane> planes = new ArrayList<>();
    /** The cloth's contacts with itself, or null. */
    private SelfCollision self;
    /** What changes the material after each kept step (plasticity, stiffening), in order. */
    private final List<AfterStep> afterSteps = new ArrayList<>();
    private final ContactSet contacts = new ContactSet();
    private final EnclosedGases gases = new EnclosedGases();
    private final List<Kinematics> kinematics = new ArrayList<>();
    private final List<ExternalForce> forces = new ArrayList<>();
    private final SolverContext ctx = new SolverContext();
    private final SolveStages stages;
    private final StepProfile profile;
    private final StepSnapshot snapshot;
    /** Where the last substep's prediction put each particle (y), for {@link StepBalance}. */
    private final double[] prediction;
    private StepBalance balance;
    private SweepListener sweepListener = SweepListener.NONE;
    private double time;
    private long stepCount;

    public Simulation(Particles particles, SolverSettings settings) {
        if (particles == null) throw new IllegalArgumentException("particles must not be null, was null");
        if (settings == null) throw new IllegalArgumentException("settings must not be null, was null");
        this.particles = particles;
        this.settings = settings;
        this.constraints = new ConstraintSet(particles.count());
        this.stages = new SolveStages(constraints, particles, ctx, gases, contacts);
        this.profile = new StepProfile(contacts, particles, stages);
        this.snapshot = new StepSnapshot(particles.count());
        this.prediction = new double[3 * particles.count()];
    }

    public Particles particles() { return particles; }
    public SolverSettings settings() { return settings; }

    /**
     * Takes new settings whole, from the next step on (a value, already validated; a step in progress keeps
     * the ones it started with). Particles, λ and the constraints are kept: a changed mode, solver or
     * iteration count acts on the same cloth.
     */
    public void settings(SolverSettings s) {
        if (s == null) throw new IllegalArgumentException("settings must not be null, was null");
        settings = s;
    }
    public double time() { return time; }
    public long stepCount() { return stepCount; }
    public List<Sphere> spheres() { return Collections.unmodifiableList(spheres); }
    public List<Plane> planes() { return Collections.unmodifiableList(planes); }
    /** The boxes and capsules. */
    public List<RigidCollider> solids() { return Collections.unmodifiableList(solids); }

    /** The cloth's self-collision, or null when it passes through itself. */
    public SelfCollision selfCollision() { return self; }

    /** Spheres, planes, boxes and capsules together. */
    public int colliderCount() { return spheres.size() + planes.size() + solids.size(); }
    public List<ExternalForce> forces() { return Collections.unmodifiableList(forces); }

    /** Whether anything moves particles by script (pin scripts, kinematic paths). */
    public boolean hasKinematics() { return !kinematics.isEmpty(); }

    /**
     * Pinned or held particles (pins, pin motions, attachments) inside a solid collider now: the solid and the
     * hold fight through the cloth between them, doing work no energy bound holds ({@link HeldInsideColliders}).
     */
    public int heldInsideColliders() { return HeldInsideColliders.count(particles, constraints.attachments(), spheres, planes, solids); }

    /** What the last step cost and found (filled in place by every step). */
    public StepProfile profile() { return profile; }

    /**
     * Views of the constraints in solve order (cloth constraints, then attachments), made when first
     * asked for after the set changed; do not modify. The solvers work on {@link #blocks()}.
     */
    public Constraint[] constraints() { return constraints.views(); }

    /** The number of constraints, attachments included. */
    public int constraintCount() { return constraints.count(); }

    /** The cloth constraints' blocks in solve order (attachments not included); a live view. */
    public List<ConstraintBlock> blocks() { return constraints.cloth(); }

    /**
     * Adds a constraint on particles that exist. Its data moves into this simulation's blocks and the
     * object stays its view; a constraint already in a simulation is refused.
     */
    public Simulation add(Constraint c) { return addAll(Collections.singletonList(c)); }

    /** Adds constraints in order; all are checked before any is added. */
    public Simulation addAll(List<? extends Constraint> cs) {
        constraints.addAll(cs);
        return this;
    }

    /** Adds a whole block of constraints after those already added, taking it over (or a copy, if another simulation has it). */
    public Simulation add(ConstraintBlock block) { return addBlocks(Collections.singletonList(block)); }

    /** Adds whole blocks (a cloth's), taking them over, or copies of them if another simulation has them. */
    Simulation addBlocks(List<ConstraintBlock> blocks) {
        constraints.addBlocks(blocks);
        return this;
    }

    /** Adds a sphere; its contacts are found each substep (brute force, O(particles × spheres)). */
    public Simulation add(Sphere s) { return addCollider(spheres, s, "sphere"); }

    /** Adds a fixed plane (a floor, a wall, a slope); its contacts are found each substep like the spheres'. */
    public Simulation add(Plane plane) { return addCollider(planes, plane, "plane"); }

    /** Adds a box or a capsule; its contacts are found each substep like the spheres', continuous when fast. */
    public Simulation add(RigidCollider solid) { return addCollider(solids, solid, "collider"); }

    private <C> Simulation addCollider(List<C> list, C collider, String what) {
        if (collider == null) throw new IllegalArgumentException(what + " must not be null, was null");
        list.add(collider);
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

    /** Adds a gas (or a held volume) inside a closed surface of this simulation's particles. */
    public Simulation add(EnclosedGas gas) {
        if (gas == null) throw new IllegalArgumentException("gas must not be null, was null");
        for (int i : gas.particles())
            if (i >= particles.count()) throw new IllegalArgumentException("gas surface particle must be within [0, " + particles.count() + "), was " + i);
        gases.add(gas);
        return this;
    }

    /** Lets a gas out (the surface is free again); false if it was not here. */
    public boolean remove(EnclosedGas gas) { return gases.remove(gas); }

    /**
     * The solver the last step ran: the settings', except vertex block descent on a cloth with a gas, which
     * Gauss–Seidel solves ({@link EnclosedGas}); null before the first step.
     */
    public SolverType solverInUse() { return stages.inUse(); }

    /** The enclosed gases and held volumes, in the order added. */
    public List<EnclosedGas> gases() { return gases.view(); }

    /** Adds what changes the material after each kept step (plasticity, stiffening), run after those added before. */
    public Simulation add(AfterStep a) {
        if (a == null) throw new IllegalArgumentException("after-step must not be null, was null");
        a.check(constraints.cloth());
        afterSteps.add(a);
        return this;
    }

    /** What changes the material after each step, in order. */
    public List<AfterStep> afterSteps() { return Collections.unmodifiableList(afterSteps); }

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
    public AttachmentConstraint attach(int i, double x, double y, double z) { return constraints.attach(i, x, y, z); }

    /** Lets go of an attachment made by {@link #attach}; the object keeps its particle and target. */
    public void release(AttachmentConstraint a) { constraints.release(a); }

    /**
     * The work the attachments (grabs, handles) have done on the cloth since the simulation began, J
     * ({@link AttachmentBlock#work}: each substep, the force on the particle times its move): what an energy
     * balance counts as put in by hand. Counted where an attachment is projected, which is every hard one under
     * every solver and a compliant one except under vertex block descent (which takes a compliant attachment
     * into its particle's energy instead).
     */
    public double workByAttachments() { return constraints.attachments().work(); }

    /**
     * The work the colliders (spheres, planes, boxes, capsules, meshes; their pushes and their friction) have
     * done on the cloth since the simulation began, J: each substep, the force of their projections on a
     * particle times its move ({@code ContactSet.countWork}), as {@link #workByAttachments} counts a hand's.
     */
    public double workByColliders() { return contacts.work(); }

    /** Sets PBD stiffness k for every constraint of a family. */
    public void setStiffness(ConstraintFamily family, double k) { constraints.setStiffness(family, k); }

    /** Sets k and α for every constraint of a family. */
    public void setMaterial(ConstraintFamily family, Material m) { constraints.setMaterial(family, m); }

    /** Sets XPBD compliance α (m/N) for every constraint of a family. */
    public void setCompliance(ConstraintFamily family, double alpha) { constraints.setCompliance(family, alpha); }

    /** Number of colours of the coloured order (built if needed): the barriers per sweep when parallel. */
    public int colourCount() { return stages.colouring().phases(); }

    /** Observes the solver after every sweep (convergence experiments); null for none. */
    public void setSweepListener(SweepListener listener) { sweepListener = listener == null ? SweepListener.NONE : listener; }

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
            run(dt, null);
        } catch (RuntimeException failed) {
            // Whatever a stage throws, half a step is not a state: put the one before it back.
            restoreSnapshot();
            throw new SimulationDivergedException(stepCount + 1, failed);
        }
        if (!Metrics.allFinite(particles)) throw diverged(dt);
        // Only after the step is kept: an undone step must leave the material (rest angles, stiffnesses) as it was.
        for (int a = 0, n = afterSteps.size(); a < n; a++) afterSteps.get(a).afterStep(particles, dt);
    }

    /**
     * The stages of one step (see {@link Stage}), each a call. A probe, when replaying a step that diverged,
     * hears the end of every stage and the solve checks every projection; null otherwise.
     */
    private void run(double dt, StepProbe probe) {
        final StepObserver observer = probe == null ? StepObserver.NONE : probe;
        final SolverSettings settings = this.settings; // the step's, whatever a listener sets meanwhile
        final SolveStage solveStage = stages.stage(settings, sweepListener);
        final int substeps = settings.substeps(), iterations = settings.iterations();
        final double h = dt / substeps;
        final AttachmentBlock attachments = constraints.attachments();
        final List<ConstraintBlock> cloth = constraints.cloth();
        final Team team = sweepListener == SweepListener.NONE ? stages.team(settings.threads()) : null;
        for (int f = 0, nf = forces.size(); f < nf; f++) forces.get(f).apply(particles, time, dt);
        observer.after(Stage.FORCES);
        long collideNanos = 0, solveNanos = 0;
        contacts.takeProjectNanos();
        ctx.load(settings, h);
        for (int s = 0; s < substeps; s++) {
            final double t = time + h;
            Integrator.predict(particles, ctx);
            if (self != null && self.guard() != null) self.guard().begin(particles);
            particles.clearDepenetration();
            System.arraycopy(particles.x, 0, prediction, 0, prediction.length);
            observer.after(Stage.PREDICT);
            for (int k = 0, nk = kinematics.size(); k < nk; k++) kinematics.get(k).apply(particles, t);
            for (int k = 0, nk = spheres.size(); k < nk; k++) spheres.get(k).advance(t, h);
            for (int k = 0, nk = solids.size(); k < nk; k++) solids.get(k).advance(t, h);
            attachments.glide((s + 1) / (double) substeps);
            observer.after(Stage.KINEMATICS);
            long c0 = System.nanoTime();
            contacts.collide(particles, spheres, planes, solids, self, h, team);
            collideNanos += System.nanoTime() - c0;
            observer.after(Stage.COLLIDE);
            for (int b = 0, nb = cloth.size(); b < nb; b++) cloth.get(b).beginSubstep(ctx);
            attachments.beginSubstep(ctx);
            gases.beginSubstep(particles, h);
            sweepListener.afterSweep(s, -1);
            long s0 = System.nanoTime();
            solveStage.solve(s, iterations, probe);
            long g0 = System.nanoTime();
            solveNanos += g0 - s0;
            if (self != null && self.guard() != null) {
                self.guard().hold(particles, team);
                collideNanos += System.nanoTime() - g0;
            }
            attachments.countWork(particles);
            contacts.countWork(particles, h);
            observer.after(Stage.SOLVE);
            Integrator.updateVelocities(particles, h);
            observer.after(Stage.UPDATE_VELOCITIES);
            Integrator.damp(particles, settings.damping(), h);
            observer.after(Stage.VELOCITY_PASS);
            time = t;
        }
        attachments.arrive();
        if (self != null && self.untangler() != null) {
            long u0 = System.nanoTime();
            self.untangler().untangle(particles);
            collideNanos += System.nanoTime() - u0;
        }
        java.util.Arrays.fill(particles.force, 0);
        stepCount++;
        profile.collideNanos = collideNanos;
        profile.solveNanos = solveNanos;
        profile.projectContactNanos = contacts.takeProjectNanos();
    }

    /** Restores the state before the step, replays it with a probe to find the culprit, restores again. */
    private SimulationDivergedException diverged(double dt) {
        restoreSnapshot();
        StepProbe probe = new StepProbe(particles);
        try {
            run(dt, probe);
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

    /** Stops helper threads, if any (they are daemons, so this is only needed to free them early). */
    public void close() { stages.close(); }

    /**
     * How far the last step is from solving its own equation: the worst free particle's leftover force as a
     * fraction of its weight ({@link StepBalance}); below {@link StepBalance#CONVERGED} the shape is the material's.
     */
    public double balance() {
        if (balance == null) balance = new StepBalance(particles.count());
        return balance.worst(this);
    }

    /** The last substep's prediction y (live; null before the first step). */
    double[] lastPrediction() { return stepCount == 0 ? null : prediction; }

    /** Marks the particles something without an energy holds now: touching a contact or another layer, or attached. */
    void markHeld(boolean[] held) {
        contacts.markTouching(particles, held);
        if (self != null) self.markTouching(particles, held, 1.01);
        constraints.markAttached(held);
    }

    /**
     * Marks (sets true, never clears) the particles that touch something now: a collider's surface, or another
     * layer of the cloth within its thickness. For drawing what holds the cloth; the rest of {@code out} is kept.
     */
    public void markTouching(boolean[] out) {
        if (out == null || out.length < particles.count())
            throw new IllegalArgumentException("out must hold a flag per particle (" + particles.count() + "), was " + (out == null ? "null" : out.length));
        contacts.markTouching(particles, out);
        if (self != null) self.markTouching(particles, out, 1.01);
    }

    /** The substep h of the step in progress (or of the last step), seconds. */
    public double substep() { return ctx.h; }

    /**
     * Continues another simulation of the same scene whose particles this one maps (a cloth cut where it tore:
     * particle i here is particle {@code source[i]} there, a split vertex's copies both its original): the
     * particles' positions, previous positions, velocities and pending forces, each sphere's state, the clock
     * and the step count, which is all a step carries over ({@link StepSnapshot}). The spheres must be the
     * same in number; masses, pins and constraints are this simulation's own.
     */
    public void continueFrom(Simulation before, int[] source) {
        if (before == null || source == null) throw new IllegalArgumentException("before and source must not be null");
        if (source.length != particles.count())
            throw new IllegalArgumentException("source must map each of the " + particles.count() + " particles, was " + source.length);
        if (before.spheres.size() != spheres.size())
            throw new IllegalArgumentException("spheres must be the same (" + spheres.size() + "), before had " + before.spheres.size());
        Particles from = before.particles;
        for (int i = 0; i < source.length; i++) {
            int j = 3 * Check.index("source", source[i], from.count()), o = 3 * i;
            for (int k = 0; k < 3; k++) {
                particles.x[o + k] = from.x[j + k];
                particles.prev[o + k] = from.prev[j + k];
                particles.v[o + k] = from.v[j + k];
                particles.force[o + k] = from.force[j + k];
            }
        }
        for (int k = 0; k < spheres.size(); k++) {
            Sphere s = spheres.get(k), b = before.spheres.get(k);
            s.cx = b.cx; s.cy = b.cy; s.cz = b.cz;
            s.vx = b.vx; s.vy = b.vy; s.vz = b.vz;
            s.spinAngle = b.spinAngle;
        }
        time = before.time;
        stepCount = before.stepCount;
        for (RigidCollider s : solids) s.moveTo(time);
    }

    /** Places every sphere, box and capsule at its path's start and sets the clock to 0 (scene reset). */
    public void resetClock() {
        time = 0;
        stepCount = 0;
        for (Sphere s : spheres) s.moveTo(0);
        for (RigidCollider s : solids) s.moveTo(0);
    }
}
