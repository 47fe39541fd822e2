package xpbdcloth.engine;

import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.LockSupport;

/**
 * Runs the sweeps of one substep over a coloured constraint order on several threads: each colour's
 * part of every block is split into equal contiguous chunks, one per thread, and all threads meet at a
 * barrier before the next colour. Constraints of one colour share no particles, so the result does not depend on timing or on
 * the thread count. Helper threads are made once and reused; between substeps they spin briefly and
 * then park, and the barrier is a counter, so a step allocates nothing.
 */
final class ParallelSweeps {
    private final int threads;
    private final Thread[] helpers;
    private final AtomicInteger arrived = new AtomicInteger();
    private volatile int barrierGeneration;
    private volatile int jobGeneration;
    private volatile boolean shutdown;

    // The job, published before jobGeneration is bumped.
    private SweepOrder colouring;
    private Particles particles;
    private SolverContext ctx;
    private int iterations;
    private ContactSet contacts;

    ParallelSweeps(int threads) {
        this.threads = threads;
        helpers = new Thread[threads - 1];
        for (int t = 1; t < threads; t++) {
            final int id = t;
            Thread th = new Thread(() -> helperLoop(id), "xpbd-sweeps-" + t);
            th.setDaemon(true);
            helpers[t - 1] = th;
            th.start();
        }
    }

    int threads() { return threads; }

    /** n sweeps over the coloured order, each followed by the contacts, this thread taking chunk 0. */
    void sweep(SweepOrder c, Particles p, SolverContext context, int n, ContactSet contactSet) {
        colouring = c;
        particles = p;
        ctx = context;
        iterations = n;
        contacts = contactSet;
        jobGeneration++; // volatile write publishes the job
        for (Thread h : helpers) LockSupport.unpark(h);
        work(0);
    }

    private void helperLoop(int id) {
        int seen = 0;
        while (!shutdown) {
            int spins = 0;
            while (jobGeneration == seen && !shutdown) {
                if (++spins < 20_000) Thread.onSpinWait();
                else LockSupport.parkNanos(this, 1_000_000);
            }
            if (shutdown) return;
            seen = jobGeneration;
            work(id);
        }
    }

    private void work(int id) {
        final SweepOrder c = colouring;
        final Particles p = particles;
        final SolverContext context = ctx;
        final int colours = c.phases();
        final ContactSet touching = contacts;
        final boolean anyContact = touching.count() > 0;
        for (int it = 0; it < iterations; it++) {
            for (int k = 0; k < colours; k++) {
                // Each thread takes its share of every block's part of the colour.
                for (int s = c.phaseStart[k]; s < c.phaseStart[k + 1]; s++) c.project(s, id, threads, p, context);
                await();
            }
            // Contacts are few and found per substep: the calling thread takes them, the others wait.
            if (anyContact) {
                if (id == 0) touching.project(p, context);
                await();
            }
        }
    }

    /** A sense-reversing counter barrier: the last thread to arrive opens the next generation. */
    private void await() {
        int generation = barrierGeneration;
        if (arrived.incrementAndGet() == threads) {
            arrived.set(0);
            barrierGeneration = generation + 1;
        } else {
            int spins = 0;
            while (barrierGeneration == generation) {
                // More threads than cores would starve a pure spin: yield now and then.
                if (++spins % 4096 == 0) Thread.yield();
                else Thread.onSpinWait();
            }
        }
    }

    void close() {
        shutdown = true;
        for (Thread h : helpers) LockSupport.unpark(h);
    }
}
