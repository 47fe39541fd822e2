package xpbdcloth.engine;

/** A force field (wind, a user's push) that adds forces to particles once per step. Allocates nothing. */
@FunctionalInterface
public interface ExternalForce {
    /**
     * Adds this step's forces (N) with {@link Particles#addForce}; t is the simulated time (s) at the
     * step's start and dt the step (s) the forces will act over.
     */
    void apply(Particles particles, double t, double dt);

    /** Refuses, when added to a simulation, what would fail inside a step (an index past its particles). */
    default void check(Particles particles) { }
}
