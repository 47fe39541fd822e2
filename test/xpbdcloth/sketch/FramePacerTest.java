package xpbdcloth.sketch;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/** The sketch's clock: real time while the simulation keeps up, slow motion (never a freeze) when not. */
class FramePacerTest {
    static final double FRAME = 1 / 60.0;

    /** The frame-rate trap: dt = 1/120 s runs two steps per 60 Hz frame, dt = 20 ms five in six frames. */
    @Test
    void followsTheWallClockWhenStepsAreCheap() {
        FramePacer p = new FramePacer();
        int total = 0;
        for (int f = 0; f < 60; f++) {
            int n = p.steps(FRAME, 1 / 120.0, 0.5);
            assertTrue(n == 2 || (f < 2 && n >= 1 && n <= 3), "frame " + f + ": " + n);
            total += n;
        }
        assertEquals(120, total, 1, "one second of 1/120 s steps");
        p = new FramePacer();
        total = 0;
        for (int f = 0; f < 600; f++) total += p.steps(FRAME, 0.02, 2.5);
        assertEquals(500, total, 1, "10 s of 20 ms steps");
        assertFalse(p.slowMotion());
    }

    /** A 660 ms step (multigrid-PCG on a three-family scene) runs once per frame, and owes nothing after. */
    @Test
    void costlyStepsSlowTheSceneInsteadOfFreezingIt() {
        FramePacer p = new FramePacer();
        for (int f = 0; f < 10; f++) {
            assertEquals(1, p.steps(0.25, 0.02, 660), "one step per (slow) frame");
            assertTrue(p.slowMotion());
        }
        // Back on a cheap solver the debt is gone: the next 60 Hz frame runs 0 or 1 step, not a burst of 8.
        assertTrue(p.steps(FRAME, 0.02, 2.5) <= 1);
        assertFalse(p.slowMotion());
        // A 10 ms step may run four times in a 40 ms budget, not eight.
        assertEquals(4, new FramePacer().steps(0.25, 0.02, 10));
    }
}
