package xpbdcloth.engine;

/**
 * Gauss–Seidel on one thread: each sweep projects the constraints in a fixed order (insertion order, or
 * the coloured order, which gives the parallel solve's result), then the enclosed gases, then the substep's contacts.
 */
final class SequentialSweeps implements SolveStage {
    private final SweepOrder order;
    private final Particles particles;
    private final SolverContext ctx;
    private final EnclosedGases gases;
    private final ContactSet contacts;
    private final SweepListener listener;

    SequentialSweeps(SweepOrder order, Particles particles, SolverContext ctx, EnclosedGases gases, ContactSet contacts, SweepListener listener) {
        this.order = order;
        this.particles = particles;
        this.ctx = ctx;
        this.gases = gases;
        this.contacts = contacts;
        this.listener = listener;
    }

    @Override public void solve(int substep, int iterations, StepProbe probe) {
        for (int it = 0; it < iterations; it++) {
            if (probe == null) sweep();
            else sweep(probe);
            listener.afterSweep(substep, it);
        }
    }

    /** One sweep: the constraints in order, the enclosed gases, then the contacts. */
    void sweep() {
        order.sweep(particles, ctx);
        gases.project(particles);
        contacts.project(particles, ctx);
    }

    /** The same sweep, the state checked after every projection. */
    void sweep(StepProbe probe) {
        order.sweep(particles, ctx, probe);
        gases.project(particles, probe);
        for (int k = 0; k < contacts.count(); k++) {
            contacts.project(particles, ctx, k);
            probe.check(contacts.particle(k), ConstraintFamily.COLLISION);
        }
    }
}
