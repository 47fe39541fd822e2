package xpbdcloth.sketch;

/**
 * How many simulation steps of dt a frame runs. While the simulation keeps up it follows the wall
 * clock (an accumulator), which is what makes the frame-rate trap reproducible: dt = 1/120 s means two
 * steps per 60 Hz frame. When it cannot keep up (a step costs more than the frame's budget, as the
 * global solvers do on the three-family scenes) it runs fewer steps and forgets the debt, so the scene
 * plays in slow motion instead of each frame trying to catch up and taking seconds.
 */
public final class FramePacer {
    static final int MAX_STEPS_PER_FRAME = 8;
    /** Simulation time a frame may spend before the scene slows down (keeps the window at ≥ 20 fps). */
    static final double BUDGET_MS = 40;

    private double accumulator;
    private boolean slowMotion;

    /**
     * Steps for a frame that follows {@code frameSeconds} of wall time, for steps of {@code dt} s that
     * last cost {@code stepMs} ms each (0 if not known yet).
     */
    public int steps(double frameSeconds, double dt, double stepMs) {
        accumulator += frameSeconds;
        int steps = (int) Math.floor(accumulator / dt);
        accumulator -= steps * dt;
        int affordable = stepMs > 0 ? Math.max(1, (int) Math.floor(BUDGET_MS / stepMs)) : MAX_STEPS_PER_FRAME;
        int cap = Math.min(MAX_STEPS_PER_FRAME, affordable);
        slowMotion = steps > cap;
        if (slowMotion) { steps = cap; accumulator = 0; }
        return steps;
    }

    /** Whether the last frame ran fewer steps than the wall clock asked for. */
    public boolean slowMotion() { return slowMotion; }

    /** Forgets time owed (while paused). */
    public void reset() { accumulator = 0; }
}
