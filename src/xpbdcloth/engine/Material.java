package xpbdcloth.engine;

/**
 * One constraint family's material, the pair both formulations read: PBD's stiffness k ∈ [0, 1] (the
 * fraction of its error one projection removes) and XPBD's compliance α ≥ 0 (m/N, the inverse of a
 * stiffness; 0 is hard). Checked once, when it is made; builders and simulations take it as it is.
 */
public final class Material {
    /** k = 1, α = 0: a hard constraint in either mode. */
    public static final Material HARD = new Material(1, 0);

    public final double stiffness, compliance;

    /** @throws IllegalArgumentException naming the field when k is outside [0, 1] or α outside [0, 1e12] m/N */
    public Material(double stiffness, double compliance) {
        this.stiffness = Check.inRange("stiffness", stiffness, 0, 1);
        this.compliance = Check.inRange("compliance", compliance, 0, EngineRange.MAX_COMPLIANCE);
    }

    @Override public boolean equals(Object o) {
        return o instanceof Material && ((Material) o).stiffness == stiffness && ((Material) o).compliance == compliance;
    }

    @Override public int hashCode() { return Double.hashCode(stiffness) * 31 + Double.hashCode(compliance); }

    @Override public String toString() { return "k " + stiffness + ", α " + compliance + " m/N"; }
}
