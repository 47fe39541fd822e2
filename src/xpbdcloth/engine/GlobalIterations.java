package xpbdcloth.engine;

/**
 * The global solve: each iteration is a Gauss–Seidel sweep over the families the global system does not
 * take (shear, bend, membrane, dihedral, tethers), one Newton–PCG step on the distance constraints at
 * once ({@link GlobalSolver}), then a Gauss–Seidel sweep over the attachments and the substep's contacts
 * (inequalities and moving targets, which a linear solve handles badly).
 *
 * <p>Why the split: stretch is what Gauss–Seidel carries one edge per sweep and a global solve carries
 * across the cloth at once; the other families are local and compliant, and Gauss–Seidel converges
 * them in a few sweeps. Taken into the system they made it slow and nearly singular: on `hanging` (32²,
 * all three families, 4865 rows against 3066 degrees of freedom) every solve stopped at its cap of 100
 * CG iterations; split, a solve takes tens of Jacobi-PCG or a few multigrid-PCG iterations. The price is
 * slower convergence of the whole system where shear is nearly hard (docs/experiments.md, experiment 7).
 * They are swept before the global step so that each iteration ends with the stretch solved.
 *
 * <p>While the substep has contacts, that sweep covers the cloth constraints too. The linear system does
 * not see the contacts, so a Newton step alone pulls the cloth back into a collider, the contact sweep
 * pushes it out, and the two fight: a sphere starting inside a 32² cloth gave strain 88–230 and 9 kJ of
 * kinetic energy under Jacobi-PCG where Gauss–Seidel peaks at 11.5. A local sweep after the global step
 * lets each constraint meet the contacts as Gauss–Seidel does (strain back to 2–13). Without contacts
 * nothing changes: the global step is followed by the attachments alone.
 */
final class GlobalIterations implements SolveStage {
    private final GlobalSolver global;
    /** The cloth constraints the global system does not take, swept before each global step. */
    private final SweepOrder local;
    /** The attachments and contacts, swept after each global step. */
    private final SequentialSweeps rest;
    /** The cloth constraints, attachments and contacts, swept after each global step while there are contacts. */
    private final SequentialSweeps all;
    private final ContactSet contacts;
    private final Particles particles;
    private final SolverContext ctx;
    private final SweepListener listener;

    GlobalIterations(GlobalSolver global, SweepOrder local, SequentialSweeps rest, SequentialSweeps all, ContactSet contacts, Particles particles, SolverContext ctx, SweepListener listener) {
        this.global = global;
        this.local = local;
        this.rest = rest;
        this.all = all;
        this.contacts = contacts;
        this.particles = particles;
        this.ctx = ctx;
        this.listener = listener;
    }

    GlobalSolver global() { return global; }

    @Override public void solve(int substep, int iterations, StepProbe probe) {
        for (int it = 0; it < iterations; it++) {
            SequentialSweeps after = contacts.count() > 0 ? all : rest;
            if (probe == null) {
                local.sweep(particles, ctx);
                global.iterate(particles, ctx);
                after.sweep();
            } else {
                local.sweep(particles, ctx, probe);
                global.iterate(particles, ctx);
                global.check(probe);
                after.sweep(probe);
            }
            listener.afterSweep(substep, it);
        }
    }
}
