package xpbdcloth.engine;

import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.LockSupport;

/**
 * A fixed team of threads that runs one job at a time on all of them, the caller taking share 0, with a
 * barrier the job calls between its phases. Helper threads are made once and reused; between jobs they
 * spin briefly and then park, and the barrier is a counter, so a step allocates nothing. A job whose
 * phases touch disjoint data per share (the colours of a sweep) gives the same bits on any thread count.
 * {@link #run} returns only once every thread has left the job (each meets one more barrier after its
 * share), so the caller may set the next job's fields at once: no helper still reads them for this one.
 */
final class Team {
    /** What every thread of the team runs: {@code id} is its share, 0 the caller's. */
    interface Job {
        void work(int id, Team team);
    }

    private final int threads;
    private final Thread[] helpers;
    private final AtomicInteger arrived = new AtomicInteger();
    private volatile int barrierGeneration;
    private volatile int jobGeneration;
    private volatile boolean shutdown;
    /** The job, published before jobGeneration is bumped. */
    private Job job;

    Team(int threads) {
        this.threads = threads;
        helpers = new Thread[threads - 1];
        for (int t = 1; t < threads; t++) {
            final int id = t;
            Thread th = new Thread(() -> helperLoop(id), "xpbd-team-" + t);
            th.setDaemon(true);
            helpers[t - 1] = th;
            th.start();
        }
    }

    int threads() { return threads; }

    /** Runs {@code j} on every thread, this one taking share 0; returns when every share has left the job. */
    void run(Job j) {
        job = j;
        jobGeneration++; // volatile write publishes the job
        for (Thread h : helpers) LockSupport.unpark(h);
        j.work(0, this);
        await(); // the job is over for every thread before the caller may change what it reads
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
            job.work(id, this);
            await();
        }
    }

    /** A sense-reversing counter barrier: the last thread to arrive opens the next generation. */
    void await() {
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
