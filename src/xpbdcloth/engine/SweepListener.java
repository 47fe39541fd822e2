package xpbdcloth.engine;

/** Called after every Gauss–Seidel sweep, to watch the solver converge. Must not change the state. */
@FunctionalInterface
public interface SweepListener {
    /** Nobody listening: the solve may then run a substep's sweeps in one go, on several threads. */
    SweepListener NONE = (substep, sweep) -> { };

    /**
     * {@code substep} and {@code sweep} count from 0 within the current step; sweep −1 is the state
     * before the first sweep (predicted positions, λ = 0).
     */
    void afterSweep(int substep, int sweep);
}
