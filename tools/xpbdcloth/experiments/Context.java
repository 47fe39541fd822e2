package xpbdcloth.experiments;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

/** Where experiments write, how thoroughly they run, and where they report progress. */
final class Context {
    final Path out;
    /** Also copy each PNG here (the project's docs/), or null. */
    final Path docs;
    /** Fewer points and shorter runs: for tests and a first look. */
    final boolean quick;
    private final long start = System.nanoTime();

    Context(Path out, Path docs, boolean quick) throws IOException {
        this.out = Files.createDirectories(out);
        this.docs = docs == null ? null : Files.createDirectories(docs);
        this.quick = quick;
    }

    /** Progress on stderr, so stdout stays the summary table. */
    void progress(String experiment, String what) {
        System.err.printf("[%6.1f s] %s: %s%n", (System.nanoTime() - start) / 1e9, experiment, what);
    }

    void save(Table table) throws IOException { table.write(out); }

    void save(Plot plot, String name) throws IOException {
        Path png = plot.write(out, name);
        if (docs != null) Files.copy(png, docs.resolve(png.getFileName()), StandardCopyOption.REPLACE_EXISTING);
    }
}
