package xpbdcloth.engine;

/**
 * Moves pinned particles along a script, once per substep after the prediction, so the motion over the
 * substep becomes their velocity (see {@link Particles#moveKinematic}). Implementations allocate nothing.
 */
@FunctionalInterface
public interface Kinematics {
    /** Places the scripted particles where they are at time t (s). */
    void apply(Particles particles, double t);
}
