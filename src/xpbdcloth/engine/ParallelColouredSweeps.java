package xpbdcloth.engine;

/**
 * Gauss–Seidel over the coloured order on several threads ({@link ParallelSweeps}): the colours of one
 * sweep in parallel, then the contacts on the calling thread, n times. Constraints of one colour share no
 * particle, so the result is the sequential coloured sweep's, bit for bit, for any thread count. Chosen
 * only when nobody listens to single sweeps (the team runs all of a substep's sweeps in one go).
 */
final class ParallelColouredSweeps implements SolveStage {
    private final SweepOrder colouring;
    private final ParallelSweeps team;
    private final Particles particles;
    private final SolverContext ctx;
    private final ContactSet contacts;
    private final SequentialSweeps sameResult;

    ParallelColouredSweeps(SweepOrder colouring, ParallelSweeps team, Particles particles, SolverContext ctx, ContactSet contacts, SequentialSweeps sameResult) {
        this.colouring = colouring;
        this.team = team;
        this.particles = particles;
        this.ctx = ctx;
        this.contacts = contacts;
        this.sameResult = sameResult;
    }

    @Override public void solve(int substep, int iterations) {
        team.sweep(colouring, particles, ctx, iterations, contacts);
    }

    /** Replayed on one thread: the same result, and a probe is not thread-safe. */
    @Override public SolveStage probed(StepProbe probe) { return sameResult.probed(probe); }
}
