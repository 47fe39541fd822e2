package xpbdcloth.engine;

/**
 * Finds where a replayed step first leaves a non-finite number: the stage, and in the solve the
 * constraint family. It watches the state after every stage ({@link StepObserver}) and, passed to the solve
 * stage ({@link SolveStage#solve}), after every projection; when it finds one it records where and unwinds
 * the replay.
 */
final class StepProbe implements StepObserver {
    /** Thrown to stop the replay at the first non-finite number (no stack trace: it is control flow). */
    static final class Found extends RuntimeException {
        Found() { super(null, null, false, false); }
    }

    private final Particles particles;
    Stage stage;
    ConstraintFamily family;

    StepProbe(Particles particles) { this.particles = particles; }

    @Override public void after(Stage st) {
        boolean finite = Metrics.allFinite(particles);
        if (st == Stage.FORCES) for (double f : particles.force) finite &= Double.isFinite(f);
        if (!finite) found(st, null);
    }

    /** After the projection of constraint i of a block. */
    void check(ConstraintBlock block, int i) {
        for (int k = 0; k < block.arity(); k++) check(block.particle(i, k), block.family());
    }

    /** After a projection that moved particle i, of the given family. */
    void check(int i, ConstraintFamily f) {
        for (int k = 3 * i; k < 3 * i + 3; k++)
            if (!Double.isFinite(particles.x[k])) found(Stage.SOLVE, f);
    }

    private void found(Stage st, ConstraintFamily f) {
        stage = st;
        family = f;
        throw new Found();
    }
}
