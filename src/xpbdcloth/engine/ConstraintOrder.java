package xpbdcloth.engine;

/**
 * The order in which a Gauss–Seidel sweep visits the constraints.
 */
public enum ConstraintOrder {
    /** As built: for a grid cloth, structural row-major, then shear, then bend (the original's order). */
    AS_BUILT,
    /**
     * Graph-coloured: constraints grouped so that no two in a group share a particle, groups in turn.
     * Still Gauss–Seidel (every projection sees the newest positions), but consecutive projections are
     * independent, so the processor overlaps their square roots and divisions, and a group can be split
     * across threads with the same result for any thread count. The converged answer is the same; the
     * path to it differs slightly from the as-built order (see docs/performance.md).
     */
    COLOURED
}
