package xpbdcloth.experiments;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code gradle experiments}: runs every experiment headless and writes one CSV and one PNG per
 * experiment into the output folder, then prints a summary table. Deterministic: no randomness, no
 * threads, no wall-clock inputs.
 */
@Command(name = "experiments", mixinStandardHelpOptions = true, showDefaultValues = true,
        description = "Reproduces the source texts' claims as CSV and PNG plots.")
public final class Experiments implements Callable<Integer> {
    static List<Experiment> all() {
        List<Experiment> e = new ArrayList<>();
        e.add(new StiffnessVsIterations());
        e.add(new StiffnessVsTimestep());
        e.add(new MullerSaturation());
        e.add(new ClosedForm());
        e.add(new GaussSeidelConvergence());
        e.add(new SubstepsVsIterations());
        e.add(new GlobalSolverComparison());
        e.add(new MeshIndependence());
        e.add(new FitOnceSimulateAnywhere());
        e.add(new DynamicFitRecovery());
        e.add(new TautCurtain());
        e.add(new MultigridOnTriangles());
        e.add(new SolverChoice());
        e.add(new MeasuredStretching());
        e.add(new MeasuredBendingCurve());
        return e;
    }

    @Option(names = "--only", split = ",", description = "run only these experiments (by name)")
    List<String> only;

    @Option(names = "--quick", description = "fewer points and shorter runs")
    boolean quick;

    @Option(names = "--out", description = "output folder", defaultValue = "build/experiments")
    Path out;

    @Option(names = "--docs", description = "also copy the PNGs into this folder (the project's docs/)")
    Path docs;

    public static void main(String[] args) {
        System.setProperty("java.awt.headless", "true");
        System.exit(new CommandLine(new Experiments()).execute(args));
    }

    @Override public Integer call() throws Exception {
        System.setProperty("java.awt.headless", "true");
        Context ctx = new Context(out, docs, quick);
        List<String> names = new ArrayList<>();
        for (Experiment e : all()) names.add(e.name());
        if (only != null)
            for (String o : only)
                if (!names.contains(o)) throw new IllegalArgumentException("only must name experiments among " + names + ", was " + o);
        System.out.println("experiment | claim | result");
        for (Experiment e : all()) {
            if (only != null && !only.contains(e.name())) continue;
            long t0 = System.nanoTime();
            List<String> lines = e.run(ctx);
            ctx.progress(e.name(), String.format("done in %.1f s", (System.nanoTime() - t0) / 1e9));
            for (int i = 0; i < lines.size(); i++)
                System.out.println((i == 0 ? e.name() + " | " + e.claim() : " | ") + " | " + lines.get(i));
        }
        System.out.println("CSV and PNG files in " + out.toAbsolutePath());
        return 0;
    }
}
