package xpbdcloth.tools;

import java.io.File;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import xpbdcloth.engine.Metrics;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.StepBalance;
import xpbdcloth.mesh.ObjWriter;
import xpbdcloth.scene.Preset;
import xpbdcloth.scene.PresetLoader;
import xpbdcloth.scene.Scene;

/**
 * {@code xpbd-cloth drape PATTERN --body MESH --out garment.obj}: sews a pattern onto a body, headless, as the
 * garment scenes do (the skirt's solver and contacts), lets it settle, and writes the draped garment with its
 * pattern's texture coordinates; says how long it took, how far from rest it ended and whether it crossed
 * itself.
 */
@Command(name = "drape", mixinStandardHelpOptions = true, showDefaultValues = true,
        description = "Sews a garment pattern onto a body mesh headless, lets it settle, writes the draped garment as OBJ and reports the time, its strain and whether it is at rest.")
final class DrapeCommand implements Callable<Integer> {
    @CommandLine.Parameters(paramLabel = "PATTERN", description = "a built-in pattern (skirt) or a pattern file")
    String pattern;

    @Option(names = "--body", required = true, description = "the body to sew onto: an OBJ (closed, y up, in metres), e.g. data/mannequin-a-pose.obj")
    File body;

    @Option(names = "--out", required = true, description = "OBJ file for the draped garment")
    File out;

    @Option(names = "--settle", description = "seconds of settling after the seams close")
    double settle = 3;

    @Option(names = "--sewing", description = "sewing time in seconds")
    double sewing = 1.5;

    @Option(names = "--threads", description = "solver threads (same result for any count)")
    int threads = 1;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override public Integer call() throws java.io.IOException {
        if (!(settle >= 0 && settle <= 600)) throw new CommandLine.ParameterException(spec.commandLine(), "--settle must be in [0, 600] s, was " + settle);
        if (threads < 1 || threads > 64) throw new CommandLine.ParameterException(spec.commandLine(), "--threads must be in [1, 64], was " + threads);
        String json = "{\"name\": \"drape\", \"cloth\": {\"pattern\": " + quote(pattern) + ", \"sewing\": {\"time\": " + sewing + "}},"
                + " \"selfCollision\": {\"thickness\": 0.006, \"staticFriction\": 0.3, \"kineticFriction\": 0.2, \"continuous\": true},"
                + " \"solver\": {\"mode\": \"XPBD\", \"iterations\": 3, \"substeps\": 20, \"dt\": 0.02, \"mullerCorrection\": true, \"gravity\": [0, -9.81, 0], \"damping\": 0.5},"
                + " \"colliders\": [{\"type\": \"mesh\", \"file\": " + quote(body.getAbsolutePath()) + ", \"margin\": 0.006, \"staticFriction\": 0.6, \"kineticFriction\": 0.45},"
                + " {\"type\": \"plane\", \"point\": [0, 0, 0], \"normal\": [0, 1, 0], \"margin\": 0.006, \"staticFriction\": 0.6, \"kineticFriction\": 0.45}]}";
        Preset preset = PresetLoader.parseBeside("drape", json, Path.of(""));
        Scene scene = Scene.of(preset);
        Simulation sim = scene.simulation();
        sim.settings(sim.settings().withThreads(threads));
        java.io.PrintWriter w = spec.commandLine().getOut();
        double dt = sim.settings().timestep();
        int sewSteps = (int) Math.ceil(preset.cloth.garment.sewingTime / dt - 1e-9), settleSteps = (int) Math.round(settle / dt);
        long start = System.nanoTime();
        for (int s = 0; s < sewSteps; s++) sim.step();
        double sewn = (System.nanoTime() - start) / 1e9;
        for (int s = 0; s < settleSteps; s++) sim.step();
        double total = (System.nanoTime() - start) / 1e9;
        w.printf("%s on %s: %d particles, %d triangles, %d seams%n", preset.cloth.meshFile, body.getName(), sim.particles().count(),
                scene.cloth().triangles().length / 3, preset.cloth.garment.pattern.pattern.seams().size());
        w.printf("sewn in %.2f s of simulated time (%d steps, %.1f s wall), settled %.2f s more (%.1f s wall in all, %d thread%s; %s)%n",
                sewSteps * dt, sewSteps, sewn, settleSteps * dt, total, threads, threads == 1 ? "" : "s", java.time.LocalDate.now());
        w.printf("widest seam gap %.2g m, largest strain %.3f, %d crossing triangle pairs; last step: %s%n",
                scene.sewing().largestGap(sim.particles()), Metrics.maxClothStrain(sim), scene.crossingPairs(), StepBalance.verdict(sim.balance()));
        ObjWriter.write(out.toPath(), scene.cloth().mesh(), sim.particles().positions(), "xpbd-cloth drape " + pattern + " on " + body.getName() + ": vt are fabric coordinates (u along the grain)");
        w.println("wrote " + out);
        w.flush();
        return 0;
    }

    private static String quote(String s) { return "\"" + s.replace("\\", "\\\\").replace("\"", "\\\"") + "\""; }
}
