package xpbdcloth.engine;

/**
 * Gauss–Seidel over the coloured order on several threads ({@link Team}): each colour's part of every
 * block split into equal contiguous chunks, one per thread, a barrier before the next colour, then the
 * enclosed gases and the contacts on the calling thread, n times. Constraints of one colour share no particle, so the result is
 * the sequential coloured sweep's, bit for bit, for any thread count. Chosen only when nobody listens to
 * single sweeps (the team runs all of a substep's sweeps in one go).
 */
final class ParallelColouredSweeps implements SolveStage, Team.Job {
    private final SweepOrder colouring;
    private final Team team;
    private final Particles particles;
    private final SolverContext ctx;
    private final EnclosedGases gases;
    private final ContactSet contacts;
    private final SequentialSweeps sameResult;
    private int iterations;

    ParallelColouredSweeps(SweepOrder colouring, Team team, Particles particles, SolverContext ctx, EnclosedGases gases, ContactSet contacts, SequentialSweeps sameResult) {
        this.colouring = colouring;
        this.team = team;
        this.particles = particles;
        this.ctx = ctx;
        this.gases = gases;
        this.contacts = contacts;
        this.sameResult = sameResult;
    }

    @Override public void solve(int substep, int iterations, StepProbe probe) {
        if (probe != null) { // replayed on one thread: the same result, and a probe is not thread-safe
            sameResult.solve(substep, iterations, probe);
            return;
        }
        this.iterations = iterations;
        team.run(this);
    }

    @Override public void work(int id, Team t) {
        final SweepOrder c = colouring;
        final int colours = c.phases(), threads = t.threads();
        final boolean serialPart = contacts.count() > 0 || gases.count() > 0;
        // Read once, at the top (the team closes every job on a barrier before the caller sets the next).
        final int iterations = this.iterations;
        for (int it = 0; it < iterations; it++) {
            for (int k = 0; k < colours; k++) {
                // Each thread takes its share of every block's part of the colour.
                for (int s = c.phaseStart[k]; s < c.phaseStart[k + 1]; s++) c.project(s, id, threads, particles, ctx);
                t.await();
            }
            // Contacts are few and found per substep, a gas is one row over its whole surface: the calling
            // thread takes them, the others wait.
            if (serialPart) {
                if (id == 0) {
                    gases.project(particles);
                    contacts.project(particles, ctx);
                }
                t.await();
            }
        }
    }
}
