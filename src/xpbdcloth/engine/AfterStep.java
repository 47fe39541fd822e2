package xpbdcloth.engine;

import java.util.List;

/**
 * What changes a cloth's material between steps, from the state a step left: rest angles that yield
 * ({@link HingePlasticity}), stiffnesses that follow the strain. It runs after every step the simulation
 * keeps (an undone step leaves the material as it was), serially, in the order added.
 */
public interface AfterStep {
    void afterStep(Particles particles, double dt);

    /** Throws if this was made for blocks the simulation does not hold (called when added). */
    default void check(List<ConstraintBlock> blocks) { }
}
