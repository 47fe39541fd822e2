package xpbdcloth.engine;

/**
 * Gauss–Seidel on one thread: each sweep projects the constraints in a fixed order (insertion order, or
 * the coloured order, which gives the parallel solve's result), then the substep's contacts.
 */
final class SequentialSweeps implements SolveStage {
    private final Constraint[] order;
    private final Particles particles;
    private final SolverContext ctx;
    private final ContactSet contacts;
    private final Simulation sim;
    private final SweepListener listener;

    SequentialSweeps(Constraint[] order, Particles particles, SolverContext ctx, ContactSet contacts, Simulation sim, SweepListener listener) {
        this.order = order;
        this.particles = particles;
        this.ctx = ctx;
        this.contacts = contacts;
        this.sim = sim;
        this.listener = listener;
    }

    @Override public void solve(int substep, int iterations) {
        for (int it = 0; it < iterations; it++) {
            for (Constraint c : order) c.project(particles, ctx);
            contacts.project(particles, ctx);
            listener.afterSweep(sim, substep, it);
        }
    }

    @Override public SolveStage probed(StepProbe probe) {
        return new SolveStage() {
            @Override public void solve(int substep, int iterations) {
                for (int it = 0; it < iterations; it++) {
                    for (Constraint c : order) {
                        c.project(particles, ctx);
                        probe.check(c);
                    }
                    projectContacts(particles, ctx, contacts, probe);
                }
            }

            @Override public SolveStage probed(StepProbe p) { return this; }
        };
    }

    /** The contacts one by one, each checked (shared by the probed stages). */
    static void projectContacts(Particles particles, SolverContext ctx, ContactSet contacts, StepProbe probe) {
        for (int k = 0; k < contacts.count(); k++) {
            contacts.project(particles, ctx, k);
            probe.check(contacts.particle(k), ConstraintFamily.COLLISION);
        }
    }
}
