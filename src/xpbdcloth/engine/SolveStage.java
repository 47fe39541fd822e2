package xpbdcloth.engine;

/**
 * The solve stage of one substep: n sweeps (or n global iterations) over the cloth's constraints and
 * the attachments, each followed by a pass over the substep's contacts, so hard contacts have the last
 * word. Three implementations: {@link SequentialSweeps} (Gauss–Seidel in a fixed order, insertion or
 * coloured), {@link ParallelColouredSweeps} (the coloured order on several threads, the same result) and
 * {@link GlobalIterations} (a global Newton–PCG step per iteration, then attachments and contacts by
 * Gauss–Seidel). {@link SolveStages} chooses one when the constraint set or the solver settings change,
 * never by branches inside the substep loop.
 */
interface SolveStage {
    /**
     * The substep's solve; the listener hears every sweep. With a probe (only when replaying a step that
     * produced a non-finite number) the same computation, on one thread, checks the state after every
     * projection to find the first constraint family that did; null otherwise. One loop serves both, so
     * the replay cannot drift from the step it replays.
     */
    void solve(int substep, int iterations, StepProbe probe);
}
