package xpbdcloth.experiments;

import java.io.IOException;
import java.util.List;

/** One experiment: writes {@code <name>.csv} and {@code <name>.png} and returns summary lines. */
interface Experiment {
    String name();

    /** What the experiment checks, in one line. */
    String claim();

    List<String> run(Context ctx) throws IOException;
}
