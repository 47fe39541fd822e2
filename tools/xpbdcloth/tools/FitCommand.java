package xpbdcloth.tools;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.fit.DynamicFit;
import xpbdcloth.fit.FitException;
import xpbdcloth.fit.FitFiles;
import xpbdcloth.fit.FitIteration;
import xpbdcloth.fit.MaterialFit;
import xpbdcloth.fit.Observation;
import xpbdcloth.fit.RestShape;
import xpbdcloth.fit.StaticFit;
import xpbdcloth.fit.Trajectory;
import xpbdcloth.scene.Preset;
import xpbdcloth.scene.PresetLoader;
import xpbdcloth.scene.Scene;

/** `xpbd-cloth fit`: recovers compliances (and damping) from an observed rest shape or motion, or makes such an observation. */
@Command(name = "fit", mixinStandardHelpOptions = true, showDefaultValues = true,
        description = {"Fits a scene's compliances (and damping) to an observed rest shape or motion.",
                "Given a rest shape (an OBJ in the scene's vertex order), the equilibrium is differentiated through the implicit"
                + " function theorem and Gauss-Newton steps in ln(alpha) follow.",
                "Given a folder of OBJ frames instead (a trajectory, one per step of the scene's dt, the first after one step) it fits"
                + " the compliances and the damping to the motion: every substep is differentiated in reverse and BFGS steps follow.",
                "Writes <out>/<scene>-fitted.json (a preset), iterations.csv and fit.png. Exit 0 converged, 1 not converged (files still written), 2 bad input.",
                "With --make-observation FILE it instead settles the scene, polishes it to its exact equilibrium and writes that shape (plus --noise-mm of noise);"
                + " with --make-observation DIR --frames N it writes the scene's first N steps."})
final class FitCommand implements Callable<Integer> {
    /**
     * The families a fitted preset can say: a spring family's compliance, a fabric's membrane moduli and its
     * bending stiffness (each fitted as one factor on all its constraints' compliances).
     */
    static final List<ConstraintFamily> FITTABLE = List.of(ConstraintFamily.STRUCTURAL, ConstraintFamily.SHEAR, ConstraintFamily.BEND,
            ConstraintFamily.MEMBRANE, ConstraintFamily.DIHEDRAL);
    static final String FITTABLE_NAMES = "structural, shear, bend, membrane, dihedral";

    @Option(names = "--scene", description = "built-in scene or preset file", defaultValue = "drape")
    String scene;

    @Option(names = "--observed", description = "the observed shape, an OBJ with the scene's vertices in the scene's order; or a folder of such OBJs, one per step (a trajectory), or a trajectory as one USD file (.usda, recorded with --fps 1/dt)")
    File observed;

    @Option(names = "--params", split = ",", description = "what to fit, of structural, shear, bend, membrane, dihedral (a fabric's moduli) and (for a trajectory) damping (default: the families the scene has, and its damping if it has one and a trajectory is fitted)")
    List<String> params;

    @Option(names = "--noise-mm", description = "with --make-observation: Gaussian noise (mm, per coordinate) added to every vertex; with --observed: the noise the observation has, to judge the residual", defaultValue = "0")
    double noiseMm;

    @Option(names = "--seed", description = "seed of the noise", defaultValue = "1")
    long seed;

    @Option(names = "--make-observation", description = "write the scene's rest shape to this OBJ instead of fitting (with --frames: its first steps into this folder, or into this .usda file)")
    File makeObservation;

    @Option(names = "--frames", description = "with --make-observation: write this many steps of the scene's motion (a trajectory) instead of its rest", defaultValue = "0")
    int frames;

    @Option(names = "--start-factor", description = "start the fit from the scene's compliances times this", defaultValue = "1")
    double startFactor;

    @Option(names = "--max-iterations", description = "iterations at most (Gauss-Newton for a shape, BFGS for a trajectory)", defaultValue = "60")
    int maxIterations;

    @Option(names = "--out", description = "folder for the fitted preset, CSV and PNG (default build/fit/<scene>)")
    File outFolder;

    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;
    private java.io.PrintWriter out;

    @Override public Integer call() throws Exception {
        out = spec.commandLine().getOut();
        try {
            return run();
        } catch (FitException | IllegalArgumentException e) { // PresetException and MeshFileException are IllegalArgumentExceptions
            spec.commandLine().getErr().println("xpbd-cloth fit: " + e.getMessage());
            return 2;
        }
    }

    private int run() throws Exception {
        Preset preset = PresetLoader.byNameOrPath(scene);
        if (!(noiseMm >= 0) || !Double.isFinite(noiseMm)) throw new IllegalArgumentException("noise-mm must be >= 0, was " + noiseMm);
        if (maxIterations < 1) throw new IllegalArgumentException("max-iterations must be >= 1, was " + maxIterations);
        if (frames < 0 || frames > Trajectory.MAX_FRAMES) throw new IllegalArgumentException("frames must be in [0, " + Trajectory.MAX_FRAMES + "], was " + frames);
        if ((makeObservation == null) == (observed == null))
            throw new IllegalArgumentException("give exactly one of --observed FILE (fit) and --make-observation FILE, was " + (observed == null ? "neither" : "both"));
        if (frames > 0 && makeObservation == null)
            throw new IllegalArgumentException("frames is for --make-observation (a fit takes as many frames as the folder holds), was " + frames);
        Scene sc = Scene.of(preset);
        if (makeObservation != null) return frames > 0 ? makeTrajectory(sc) : makeObservation(sc);
        boolean dynamic = Files.isDirectory(observed.toPath()) || Trajectory.isUsd(observed.toPath());
        boolean fitsDamping = fitsDamping(preset, dynamic);
        List<ConstraintFamily> families = families(preset, present(sc), dynamic);
        if (families.isEmpty() && !fitsDamping) throw new IllegalArgumentException("params must name at least one of " + FITTABLE_NAMES + (dynamic ? ", damping" : "") + ", was empty");
        long t0 = System.nanoTime();
        MaterialFit fit;
        String what = names(families) + (fitsDamping ? (families.isEmpty() ? "" : ", ") + "damping" : "");
        if (dynamic) {
            double[][] trajectory = Trajectory.read(observed.toPath(), sc);
            out.printf(Locale.ROOT, "fitting %s of %s (%d particles) to %d frames (%.2f s) in %s%n", what, preset.name,
                    sc.simulation().particles().count(), trajectory.length, trajectory.length * sc.simulation().settings().timestep(), observed);
            fit = new DynamicFit(sc.simulation(), families, fitsDamping, trajectory, startFactor);
        } else {
            double[] shape = Observation.read(observed.toPath(), sc);
            if (sc.simulation().colliderCount() > 0)
                out.println("note: " + preset.name + " has " + sc.simulation().colliderCount() + " colliders; the fit assumes none touches the cloth at rest");
            out.printf(Locale.ROOT, "fitting %s of %s (%d particles) to %s%n", what, preset.name, sc.simulation().particles().count(), observed);
            fit = new StaticFit(sc.simulation(), families, shape, startFactor);
        }
        print(fit, fit.last());
        boolean converged = fit.run(maxIterations, it -> print(fit, it));
        double seconds = (System.nanoTime() - t0) / 1e9;
        Path folder = outFolder != null ? outFolder.toPath() : Path.of("build", "fit", preset.name);
        Files.createDirectories(folder);
        Path json = folder.resolve(preset.name + "-fitted.json");
        FitFiles.writePreset(json, preset, PresetLoader.text(scene), preset.name + "-fitted", fit, observed.getName());
        FitFiles.writeCsv(folder.resolve("iterations.csv"), fit);
        FitChart.writePng(folder.resolve("fit.png"), fit);
        FitIteration last = fit.last();
        out.printf(Locale.ROOT, "%s after %d iterations in %.1f s: RMS %.4f mm%n", converged ? "converged" : "NOT converged", last.index, seconds, last.rms * 1e3);
        if (noiseMm > 0)
            out.printf(Locale.ROOT, "noise of %.3f mm per coordinate alone leaves an RMS of about %.3f mm%n", noiseMm, noiseMm * Math.sqrt(3));
        if (!converged) out.printf(Locale.ROOT, "the fit did not converge in %d iterations; last loss %.4e m²; what it reached is written%n", maxIterations, last.loss);
        if (!dynamic && converged) {
            // Whether the simulator, at the fitted material and the scene's settings, rests where the fit assumed.
            double tolerance = Math.max(0.25 * last.rms, 1e-5);
            try {
                out.println(xpbdcloth.fit.SolverRestGap.of(PresetLoader.byNameOrPath(json.toString()), tolerance).say(last.rms));
            } catch (xpbdcloth.fit.FitException e) {
                out.println("note: the fitted material's own rest could not be checked against the simulator's (" + e.getMessage()
                        + "): a fitted material without a stable rest is a sign the observation is not one the scene's energy can rest in");
            }
        }
        out.println("wrote " + json + ", " + folder.resolve("iterations.csv") + ", " + folder.resolve("fit.png"));
        return converged ? 0 : 1;
    }

    private int makeObservation(Scene sc) throws Exception {
        RestShape rest = RestShape.of(sc);
        double[] shape = Observation.withNoise(rest.positions, noiseMm * 1e-3, seed);
        Path file = makeObservation.toPath();
        if (file.toAbsolutePath().getParent() != null) Files.createDirectories(file.toAbsolutePath().getParent());
        Observation.write(file, sc, shape, String.format(Locale.ROOT, "xpbd-cloth fit --make-observation: %s at rest, noise %.3f mm, seed %d", sc.preset().name, noiseMm, seed));
        out.printf(Locale.ROOT, "wrote %s: %s at rest (simulated %.1f s, then Newton; the simulator's own rest was %.2f mm from the equilibrium), noise %.3f mm%n",
                file, sc.preset().name, rest.simulatedSeconds, rest.simulatorGap * 1e3, noiseMm);
        return 0;
    }

    private int makeTrajectory(Scene sc) throws Exception {
        Path folder = makeObservation.toPath();
        if (Trajectory.isUsd(folder)) {
            double dt = sc.simulation().settings().timestep();
            try (xpbdcloth.usd.UsdRecording r = xpbdcloth.usd.UsdRecording.start(folder, sc, 1 / dt)) {
                for (int f = 0; f < frames; f++) {
                    sc.simulation().step();
                    r.frame(Observation.withNoise(sc.simulation().particles().positions(), noiseMm * 1e-3, seed + f));
                }
            }
            out.printf(Locale.ROOT, "wrote %s: %d frames (%.2f s of %s from its start, a time code per step of %.4f s), noise %.3f mm%n",
                    folder, frames, frames * dt, sc.preset().name, dt, noiseMm);
            return 0;
        }
        List<Path> files = Trajectory.simulateInto(folder, sc, frames, noiseMm * 1e-3, seed, String.format(Locale.ROOT,
                "xpbd-cloth fit --make-observation: %s, noise %.3f mm, seed %d", sc.preset().name, noiseMm, seed));
        out.printf(Locale.ROOT, "wrote %d frames (%.2f s of %s from its start, one per step of %.4f s) to %s, noise %.3f mm%n",
                files.size(), frames * sc.simulation().settings().timestep(), sc.preset().name, sc.simulation().settings().timestep(), folder, noiseMm);
        return 0;
    }

    /** Whether "damping" is among the params (or, by default, for a trajectory of a damped scene). */
    private boolean fitsDamping(Preset preset, boolean dynamic) {
        if (params == null) return dynamic && preset.solver.damping() > 0;
        boolean named = params.stream().anyMatch(p -> p.trim().equalsIgnoreCase("damping"));
        if (named && !dynamic)
            throw new IllegalArgumentException("params names damping, which a rest shape does not depend on: observe a trajectory (a folder of frames) to fit it");
        return named;
    }

    /** The fittable families the scene's cloth has, in the order it builds them. */
    private static List<ConstraintFamily> present(Scene sc) {
        List<ConstraintFamily> out = new ArrayList<>();
        for (ConstraintBlock b : sc.simulation().blocks())
            if (b.count() > 0 && FITTABLE.contains(b.family()) && !out.contains(b.family())) out.add(b.family());
        return out;
    }

    private List<ConstraintFamily> families(Preset preset, List<ConstraintFamily> present, boolean dynamic) {
        if (params == null) {
            if (present.isEmpty()) throw new IllegalArgumentException("params: scene " + preset.name + " has none of " + FITTABLE_NAMES + " to fit");
            return present;
        }
        List<ConstraintFamily> out = new ArrayList<>();
        for (String p : params) {
            if (dynamic && p.trim().equalsIgnoreCase("damping")) continue;
            ConstraintFamily f = FITTABLE.stream().filter(x -> x.name().equalsIgnoreCase(p.trim())).findFirst()
                    .orElseThrow(() -> new IllegalArgumentException("params must name " + FITTABLE_NAMES + (dynamic ? " or damping" : " or (for a trajectory) damping") + ", was " + p));
            if (!present.contains(f))
                throw new IllegalArgumentException("params names " + p + ", which scene " + preset.name + " does not have; it has " + names(present));
            if (!out.contains(f)) out.add(f);
        }
        return out;
    }

    private static String names(List<ConstraintFamily> families) {
        List<String> s = new ArrayList<>();
        for (ConstraintFamily f : families) s.add(f.name().toLowerCase(Locale.ROOT));
        return String.join(", ", s);
    }

    private void print(MaterialFit fit, FitIteration it) {
        // Against the iteration cap while it runs; whole once converged, which is usually far under the cap.
        int filled = fit.converged() ? 20 : (int) Math.round(20.0 * Math.min(it.index, maxIterations) / maxIterations);
        StringBuilder s = new StringBuilder(String.format(Locale.ROOT, "[%s%s] it %2d  loss %.3e m²  rms %8.4f mm  |grad| %.2e ",
                "#".repeat(filled), ".".repeat(20 - filled), it.index, it.loss, it.rms * 1e3, it.gradientNorm));
        for (int f = 0; f < it.compliance.length; f++)
            s.append(String.format(Locale.ROOT, " %s %.4e", fit.families().get(f).name().toLowerCase(Locale.ROOT), it.compliance[f]));
        if (fit.fitsDamping()) s.append(String.format(Locale.ROOT, " damping %.4f/s", it.damping));
        out.println(s);
    }
}
