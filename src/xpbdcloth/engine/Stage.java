package xpbdcloth.engine;

/**
 * The stages of one step, in the order {@link Simulation#step(double)} runs them. FORCES runs once per
 * step; the others once per substep of h = dt / substeps.
 */
public enum Stage {
    /** External forces (wind, pushes) are gathered for the whole step. */
    FORCES,
    /** Semi-implicit Euler: v += h·(g + w·f), x_prev = x, x += h·v. */
    PREDICT,
    /** Scripted pins and kinematic colliders move to their place at the end of the substep. */
    KINEMATICS,
    /** This substep's contacts are found: particles within reach of a collider. */
    COLLIDE,
    /** The constraints are projected (λ reset first): n sweeps or n global iterations, then contacts. */
    SOLVE,
    /** v = (x − x_prev) / h. */
    UPDATE_VELOCITIES,
    /**
     * What acts on velocities rather than positions: damping, v ← v·e^(−c·h) ({@link SolverSettings#damping}).
     * The place for velocity-level friction and restitution once contacts need them.
     */
    VELOCITY_PASS;

    /** The name the HUD and messages use: "update velocities". */
    public String label() { return name().toLowerCase(java.util.Locale.ROOT).replace('_', ' '); }
}
