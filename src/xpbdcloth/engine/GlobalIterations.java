package xpbdcloth.engine;

/**
 * The global solve: each iteration is one Newton–PCG step on all cloth constraints at once
 * ({@link GlobalSolver}), then a Gauss–Seidel sweep over the attachments and the substep's contacts
 * (inequalities and moving targets, which a linear solve handles badly).
 */
final class GlobalIterations implements SolveStage {
    private final GlobalSolver global;
    /** The attachments and contacts, swept after each global step. */
    private final SequentialSweeps rest;
    private final Particles particles;
    private final SolverContext ctx;
    private final Simulation sim;
    private final SweepListener listener;

    GlobalIterations(GlobalSolver global, SequentialSweeps rest, Particles particles, SolverContext ctx, Simulation sim, SweepListener listener) {
        this.global = global;
        this.rest = rest;
        this.particles = particles;
        this.ctx = ctx;
        this.sim = sim;
        this.listener = listener;
    }

    GlobalSolver global() { return global; }

    @Override public void solve(int substep, int iterations) {
        for (int it = 0; it < iterations; it++) {
            global.iterate(particles, ctx);
            rest.sweep();
            listener.afterSweep(sim, substep, it);
        }
    }

    @Override public SolveStage probed(StepProbe probe) {
        return new SolveStage() {
            @Override public void solve(int substep, int iterations) {
                for (int it = 0; it < iterations; it++) {
                    global.iterate(particles, ctx);
                    probe.check(global);
                    rest.sweep(probe);
                }
            }

            @Override public SolveStage probed(StepProbe p) { return this; }
        };
    }
}
