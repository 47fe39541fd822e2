package xpbdcloth.engine;

/** How each iteration of a substep solves the constraints. */
public enum SolverType {
    /** Sequential Gauss–Seidel: one projection per constraint per sweep (the original's solver). */
    GAUSS_SEIDEL,
    /** Global: linearise all constraints and solve (J W Jᵀ + α̃) Δλ = −C − α̃λ by conjugate gradients, Jacobi-preconditioned. */
    JACOBI_PCG,
    /** The same system, preconditioned by an unsmoothed-aggregation multigrid V-cycle (as MGPBD). */
    MULTIGRID_PCG,
    /**
     * XPBD's step solved in positions, particle by particle ({@link VertexBlockDescent}): a cloth at rest is
     * a fixed point at any sweep count, so it settles to the converged cloth; contacts, tethers and hard
     * constraints are projected as in Gauss–Seidel after each iteration.
     */
    VERTEX_BLOCK_DESCENT;

    /** Whether an iteration is a linear solve over the whole cloth (and costs like one). */
    public boolean isGlobal() { return this == JACOBI_PCG || this == MULTIGRID_PCG; }

    /** The name users type and read: gauss-seidel, jacobi-pcg, multigrid-pcg, vertex-block-descent. */
    public String label() { return name().toLowerCase(java.util.Locale.ROOT).replace('_', '-'); }
}
