package xpbdcloth.engine;

/**
 * The global solve: each iteration is one Newton–PCG step on all cloth constraints at once
 * ({@link GlobalSolver}), then a Gauss–Seidel pass over the attachments and the substep's contacts
 * (inequalities and moving targets, which a linear solve handles badly).
 */
final class GlobalIterations implements SolveStage {
    private final GlobalSolver global;
    private final Constraint[] attachments;
    private final Particles particles;
    private final SolverContext ctx;
    private final ContactSet contacts;
    private final Simulation sim;
    private final SweepListener listener;

    GlobalIterations(GlobalSolver global, Constraint[] attachments, Particles particles, SolverContext ctx, ContactSet contacts,
                     Simulation sim, SweepListener listener) {
        this.global = global;
        this.attachments = attachments;
        this.particles = particles;
        this.ctx = ctx;
        this.contacts = contacts;
        this.sim = sim;
        this.listener = listener;
    }

    GlobalSolver global() { return global; }

    @Override public void solve(int substep, int iterations) {
        for (int it = 0; it < iterations; it++) {
            global.iterate(particles, ctx);
            for (Constraint c : attachments) c.project(particles, ctx);
            contacts.project(particles, ctx);
            listener.afterSweep(sim, substep, it);
        }
    }

    @Override public SolveStage probed(StepProbe probe) {
        return new SolveStage() {
            @Override public void solve(int substep, int iterations) {
                for (int it = 0; it < iterations; it++) {
                    global.iterate(particles, ctx);
                    probe.check(global);
                    for (Constraint c : attachments) {
                        c.project(particles, ctx);
                        probe.check(c);
                    }
                    SequentialSweeps.projectContacts(particles, ctx, contacts, probe);
                }
            }

            @Override public SolveStage probed(StepProbe p) { return this; }
        };
    }
}
