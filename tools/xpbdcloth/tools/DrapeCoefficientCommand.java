package xpbdcloth.tools;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.StepBalance;
import xpbdcloth.mesh.ObjWriter;
import xpbdcloth.mesh.ShadowArea;
import xpbdcloth.pattern.DrapeSpecimen;
import xpbdcloth.scene.FabricCatalogue;
import xpbdcloth.scene.Preset;
import xpbdcloth.scene.PresetLoader;
import xpbdcloth.scene.Scene;

/**
 * {@code xpbd-cloth drape-coefficient [FABRIC...]}: Cusick's drape test on catalogue fabrics, headless. The
 * scene is the {@code drape-tester} preset (its solver, clamp and pedestal) with the fabric and, if asked,
 * the specimen's mesh changed; after the settling time it reports the drape coefficient
 * DC = (S − πr²) / (πR² − πr²), S the shadow's area (G. E. Cusick, "The measurement of fabric drape",
 * J. Textile Institute 59, 1968), the number of folds (nodes) and how far the hem hangs in.
 */
@Command(name = "drape-coefficient", mixinStandardHelpOptions = true, showDefaultValues = true,
        description = "Cusick's drape test (a 30 cm circle clamped on an 18 cm disc) on catalogue fabrics: prints each one's drape coefficient, folds and hem, after it settles.")
final class DrapeCoefficientCommand implements Callable<Integer> {
    /** The specimen's and the support's radii (m): BS 5058's 30 cm circle on an 18 cm disc, as drape-specimen.obj is cut. */
    static final double RADIUS = 0.15, SUPPORT = 0.09;
    /** The shadow's grid cell (m): its error is about the hem's length times half a cell, under 0.1 % of the ring. */
    static final double CELL = 2.5e-4;
    /** A fold counts when the hem swings out and back in by more than this (m), so a ripple is not a node. */
    static final double NODE_DEPTH = 0.005;
    /**
     * The finest specimen (m): its shortest edge (3 mm) still holds the pedestal's contact (1.5 mm margin, so
     * 3 mm thick), which the loader keeps under the cloth's shortest edge; finer, over 5,000 particles, is
     * minutes a fabric.
     */
    static final double MIN_EDGE = 0.004;

    @CommandLine.Parameters(paramLabel = "FABRIC", arity = "0..*", description = "catalogue fabrics (data/fabrics.json); default: all of them")
    List<String> fabrics = new ArrayList<>();

    @Option(names = "--edge", description = "the specimen's edge length in metres (default: data/drape-specimen.obj's, 7.5 mm)")
    Double edge;

    @Option(names = "--settle", description = "seconds the specimen drapes before it is measured")
    double settle = 10;

    @Option(names = "--out", description = "folder to write each draped specimen to, as FABRIC.obj")
    java.io.File out;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    /** One fabric's test. */
    static final class Result {
        final String fabric;
        final double coefficient, innermostHem, outermostHem, seconds;
        final int nodes, particles;
        final String rest;
        final double[] positions;
        final int[] triangles;

        Result(String fabric, double coefficient, int nodes, double innermostHem, double outermostHem, String rest, int particles, double seconds, double[] positions, int[] triangles) {
            this.fabric = fabric; this.coefficient = coefficient; this.nodes = nodes; this.innermostHem = innermostHem; this.outermostHem = outermostHem;
            this.rest = rest; this.particles = particles; this.seconds = seconds; this.positions = positions; this.triangles = triangles;
        }
    }

    @Override public Integer call() throws IOException {
        if (!(settle > 0 && settle <= 600)) throw new CommandLine.ParameterException(spec.commandLine(), "--settle must be in (0, 600] s, was " + settle);
        if (edge != null && !(edge >= MIN_EDGE && edge <= (RADIUS - SUPPORT) / 2))
            throw new CommandLine.ParameterException(spec.commandLine(), "--edge must be in [" + MIN_EDGE + ", " + (RADIUS - SUPPORT) / 2 + "] m, was " + edge);
        List<String> names = fabrics.isEmpty() ? FabricCatalogue.names() : fabrics;
        for (String name : names)
            if (!FabricCatalogue.names().contains(name))
                throw new CommandLine.ParameterException(spec.commandLine(), "FABRIC \"" + name + "\" is not in the catalogue: " + String.join(", ", FabricCatalogue.names()));
        java.io.PrintWriter w = spec.commandLine().getOut();
        w.printf("Cusick drape test: %.0f cm circle on a %.0f cm disc, %s s settling (%s)%n", 200 * RADIUS, 200 * SUPPORT, settle, java.time.LocalDate.now());
        w.printf("%-18s %6s %6s %16s %10s  %s%n", "fabric", "DC", "nodes", "hem radius (cm)", "wall (s)", "last step");
        for (String name : names) {
            Result r = measure(name, edge, settle);
            w.printf("%-18s %6.3f %6d %7.1f – %-6.1f %10.1f  %s%n", name, r.coefficient, r.nodes, 100 * r.innermostHem, 100 * r.outermostHem, r.seconds, r.rest);
            w.flush();
            if (out != null) {
                Files.createDirectories(out.toPath());
                Path file = out.toPath().resolve(name + ".obj");
                ObjWriter.write(file, xpbdcloth.mesh.ClothMesh.of(r.positions, null, r.triangles, null, null), null,
                        "xpbd-cloth drape-coefficient " + name + ": DC " + String.format("%.3f", r.coefficient) + ", " + r.nodes + " nodes");
            }
        }
        w.flush();
        return 0;
    }

    /**
     * Drapes the tester's specimen in {@code fabric} for {@code seconds} and measures it: the built-in
     * {@code drape-tester} scene, its fabric swapped as the sketch's F key does; {@code edge} null keeps the
     * shipped specimen, otherwise one meshed at that edge takes its place (the preset's pedestal margin,
     * 1.5 mm, is thin enough for any edge the option takes).
     */
    static Result measure(String fabric, Double edge, double seconds) throws IOException {
        Path folder = null;
        try {
            Preset p;
            if (edge == null) p = PresetLoader.builtIn("drape-tester");
            else {
                folder = Files.createTempDirectory("drape-tester");
                ObjWriter.write(folder.resolve("drape-specimen.obj"), DrapeSpecimen.generate(RADIUS, SUPPORT, edge), null, "drape specimen at edge " + edge);
                p = PresetLoader.builtIn("drape-tester", folder);
            }
            Scene scene = Scene.of(p);
            scene.useFabric(FabricCatalogue.named(fabric));
            Simulation sim = scene.simulation();
            long start = System.nanoTime();
            int steps = (int) Math.round(seconds / sim.settings().timestep());
            for (int s = 0; s < steps; s++) sim.step();
            double wall = (System.nanoTime() - start) / 1e9;
            double[] x = sim.particles().positions();
            int[] triangles = scene.cloth().triangles();
            double shadow = ShadowArea.of(x, triangles, CELL);
            double disc = Math.PI * SUPPORT * SUPPORT, ring = Math.PI * RADIUS * RADIUS - disc;
            int[] hem = p.cloth.mesh.group("hem");
            double[] radii = new double[hem.length];
            double in = Double.MAX_VALUE, outermost = 0;
            for (int i = 0; i < hem.length; i++) {
                radii[i] = Math.hypot(x[3 * hem[i]], x[3 * hem[i] + 2]);
                in = Math.min(in, radii[i]);
                outermost = Math.max(outermost, radii[i]);
            }
            return new Result(fabric, (shadow - disc) / ring, nodes(radii, NODE_DEPTH), in, outermost, StepBalance.verdict(sim.balance()),
                    sim.particles().count(), wall, x, triangles);
        } finally {
            if (folder != null) {
                Files.deleteIfExists(folder.resolve("drape-specimen.obj"));
                Files.deleteIfExists(folder);
            }
        }
    }

    /**
     * The folds round a closed hem, from its distances to the axis in order: the swings out and back in by
     * more than {@code depth} (hysteresis: a peak counts once the hem has come {@code depth} back in from it,
     * starting from the innermost point, so noise smaller than {@code depth} never makes a node).
     */
    static int nodes(double[] radii, double depth) {
        int n = radii.length, start = 0;
        for (int i = 1; i < n; i++) if (radii[i] < radii[start]) start = i;
        int count = 0;
        boolean rising = true;
        double low = radii[start], high = radii[start];
        for (int k = 1; k <= n; k++) {
            double r = radii[(start + k) % n];
            if (rising) {
                high = Math.max(high, r);
                if (high - r > depth && high - low > depth) { count++; rising = false; low = r; }
            } else {
                low = Math.min(low, r);
                if (r - low > depth) { rising = true; high = r; }
            }
        }
        return count;
    }
}
