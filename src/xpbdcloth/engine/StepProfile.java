package xpbdcloth.engine;

/**
 * What the last step cost and what it found, one value in the manner of box2d's {@code b2Profile} and
 * {@code b2Counters}: the simulation writes the step's times at its end (in place, nothing allocated), and
 * the counts are read when asked from the last substep's contacts and from the global solver, live (a
 * sweep listener sees the conjugate-gradient count grow within a step). The HUD, the benchmarks and the
 * experiments read it through {@link Simulation#profile()}.
 */
public final class StepProfile {
    private final ContactSet contacts;
    private final Particles particles;
    private final SolveStages stages;
    long collideNanos, solveNanos, projectContactNanos;

    StepProfile(ContactSet contacts, Particles particles, SolveStages stages) {
        this.contacts = contacts;
        this.particles = particles;
        this.stages = stages;
    }

    /** Wall time of the step's collide stages (finding the contacts, all substeps), ms. */
    public double collideMs() { return collideNanos / 1e6; }

    /**
     * Wall time the step spent on contacts, ms: finding them (hash, self-collision pairs, colliders) and
     * projecting them in every sweep. Projection is timed per sweep, not per contact, so the clock costs two
     * reads a sweep.
     */
    public double contactMs() { return (collideNanos + projectContactNanos) / 1e6; }

    /** Wall time of the step's solve stages minus the contacts projected in them: the cloth's own constraints, ms. */
    public double constraintSolveMs() { return (solveNanos - projectContactNanos) / 1e6; }

    /** Conjugate-gradient iterations of the step's last global iteration (0 unless a global solver is chosen). */
    public int lastPcgIterations() { return stages.globalInUse() == null ? 0 : stages.globalInUse().lastIterations(); }

    /** Conjugate-gradient iterations since the last global solver was built (kept while another solver is chosen). */
    public int totalPcgIterations() { return stages.global() == null ? 0 : stages.global().totalIterations(); }

    /** Global iterations whose step was not taken since the global solver was built (see {@link GlobalSolver#iterate}). */
    public int rejectedGlobalSteps() { return stages.global() == null ? 0 : stages.global().rejectedSteps(); }

    /** How many times a global system has been set up: once per cloth topology or PCG setting, never for a grab. */
    public int globalSetups() { return stages.globalSetups(); }

    /** Nanoseconds the last global solver built spent on its setup, 0 without one. */
    public long globalSetupNanos() { return stages.global() == null ? 0 : stages.global().setupNanos(); }

    /** Levels of the global solver's multigrid, 0 without one. */
    public int multigridLevels() { return stages.global() == null ? 0 : stages.global().multigridLevels(); }

    /** Nanoseconds the multigrid's setup took, 0 without one. */
    public long multigridSetupNanos() { return stages.global() == null ? 0 : stages.global().multigridSetupNanos(); }

    /** Contacts found in the last substep (candidates within reach of a collider, touching or not). */
    public int contactCount() { return contacts.count(); }

    /** Of those, the ones touching their collider now. */
    public int touchingContacts() { return contacts.touching(particles); }

    /** Particles inside a collider now, caught where two colliders close on them (see ContactSet.inside). */
    public int pinchedParticles() { return contacts.inside(particles); }
}
