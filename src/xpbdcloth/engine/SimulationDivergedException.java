package xpbdcloth.engine;

/**
 * A step failed: it produced a non-finite position or velocity, or something inside it threw (a force
 * past the engine's range, say). The simulation has already restored the state it had before that step
 * (bit for bit), so the caller loses nothing and may change a parameter and go on. For a non-finite
 * state the exception says which stage, and within the solve which constraint family, first produced a
 * non-finite number, found by replaying the step with a check after every stage and projection; for a
 * throw, the cause is the exception the step threw.
 */
public final class SimulationDivergedException extends IllegalStateException {
    private final long step;
    private final Stage stage;
    private final ConstraintFamily family;

    SimulationDivergedException(long step, Stage stage, ConstraintFamily family) {
        super("step " + step + " produced a non-finite position in stage '" + stage.label() + "'"
                + (family == null ? "" : ", constraint family " + family.name().toLowerCase(java.util.Locale.ROOT))
                + "; the state before that step is restored");
        this.step = step;
        this.stage = stage;
        this.family = family;
    }

    SimulationDivergedException(long step, RuntimeException cause) {
        super("step " + step + " failed: " + cause.getMessage() + "; the state before that step is restored", cause);
        this.step = step;
        this.stage = null;
        this.family = null;
    }

    /** The number of the step that diverged (1 for the first step). */
    public long step() { return step; }

    /** The stage that first went non-finite, or null when the step threw instead (see {@link #getCause()}). */
    public Stage stage() { return stage; }

    /** The family whose projection first went non-finite, or null outside the solve stage. */
    public ConstraintFamily family() { return family; }
}
