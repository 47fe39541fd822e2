package xpbdcloth;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;

/**
 * Independent jobs of a long test (each its own simulation) run two at a time, the machines having two
 * cores, and their results come back in the order the jobs were given, so a test reports and checks them
 * as it would have one by one. A job that throws (an assertion too) is rethrown as it was.
 */
public final class TwoAtATime {
    private TwoAtATime() {}

    public static <T> List<T> results(List<Callable<T>> jobs) throws Exception {
        ExecutorService pool = Executors.newFixedThreadPool(2);
        try {
            List<Future<T>> running = new ArrayList<>();
            for (Callable<T> job : jobs) running.add(pool.submit(job));
            List<T> out = new ArrayList<>();
            for (Future<T> f : running) {
                try {
                    out.add(f.get());
                } catch (ExecutionException e) {
                    if (e.getCause() instanceof Error) throw (Error) e.getCause();
                    if (e.getCause() instanceof Exception) throw (Exception) e.getCause();
                    throw e;
                }
            }
            return out;
        } finally {
            pool.shutdownNow();
        }
    }
}
