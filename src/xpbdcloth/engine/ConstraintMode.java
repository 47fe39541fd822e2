package xpbdcloth.engine;

/** Which projection every constraint of a simulation uses. Switchable while the simulation runs. */
public enum ConstraintMode {
    /**
     * Position-based dynamics (Müller et al. 2007): a dimensionless stiffness k ∈ [0,1] scales each
     * correction. The material's apparent stiffness then depends on iterations and timestep.
     */
    PBD,
    /**
     * Extended PBD (Macklin, Müller, Chentanez 2016): a compliance α (m/N, inverse stiffness) and a
     * Lagrange multiplier λ accumulated over the substep make stiffness a property of the material.
     */
    XPBD
}
