package xpbdcloth.tools;

import java.io.File;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import xpbdcloth.scene.PresetLoader;
import xpbdcloth.sketch.ClothApp;
import xpbdcloth.sketch.Launcher;

/** The command line: opens the sketch, records frames, runs the benchmark. */
@Command(name = "xpbd-cloth", mixinStandardHelpOptions = true, showDefaultValues = true, version = "xpbd-cloth 0.1.0",
        description = "Real-time PBD/XPBD cloth. With no command, opens the sketch.",
        subcommands = {Main.Record.class, Main.CheckCommand.class, Main.BenchCommand.class, FitCommand.class, PatternCommand.class, DrapeCommand.class, DrapeCoefficientCommand.class, xpbdcloth.experiments.Experiments.class})
public final class Main implements Callable<Integer> {
    /** What both the window and the recorder take: the scene, the layout, the size, the solver threads. */
    static final class SketchOptions {
        @Option(names = "--scene", description = "built-in scene (${COMPLETION-CANDIDATES}) or a preset file", defaultValue = "hanging",
                completionCandidates = Scenes.class)
        String scene;

        @Option(names = "--side-by-side", description = "PBD left and XPBD right")
        boolean sideBySide;

        @Option(names = "--size", description = "window or frame size WxH in pixels", defaultValue = "1280x800")
        String size;

        @Option(names = "--threads", description = "solver threads (coloured parallel solve; same result for any count; default: 2, or 1 on a one-core machine)")
        Integer threads;

        /** Validates the options (a bad scene, size or thread count fails here, with its message) and opens the sketch. */
        void open(ClothApp.Recording recording) {
            PresetLoader.byNameOrPath(scene);
            int[] wh = parseSize(size);
            if (threads != null) xpbdcloth.sketch.SketchState.setThreads(threads);
            Launcher.open(scene, sideBySide, recording, wh[0], wh[1]);
        }
    }

    @CommandLine.Mixin
    SketchOptions sketch = new SketchOptions();

    static final class Scenes extends java.util.ArrayList<String> {
        Scenes() { super(PresetLoader.BUILT_IN); }
    }

    public static void main(String[] args) {
        CommandLine cli = new CommandLine(new Main());
        // Bad input (a broken preset, a bad size) is a message, not a stack trace.
        cli.setExecutionExceptionHandler((e, line, parsed) -> {
            if (!(e instanceof IllegalArgumentException)) throw e;
            line.getErr().println("xpbd-cloth: " + e.getMessage());
            return 2;
        });
        int code = optionsBeforeCommand(cli, args) ? 2 : cli.execute(args);
        // An open sketch keeps running on Processing's threads and exits when its window closes.
        if (!Launcher.opened()) System.exit(code);
    }

    /**
     * Options written before a command (`xpbd-cloth --scene rope record`) belong to the window, not to
     * the command, which would silently run with its own defaults: refuse them and say where they go.
     */
    static boolean optionsBeforeCommand(CommandLine cli, String[] args) {
        CommandLine.ParseResult parsed;
        try {
            parsed = cli.parseArgs(args);
        } catch (CommandLine.ParameterException e) {
            return false; // execute reports it, with usage
        }
        if (!parsed.hasSubcommand() || parsed.matchedOptions().isEmpty()) return false;
        String command = parsed.subcommand().commandSpec().name();
        cli.getErr().println("xpbd-cloth: " + parsed.matchedOptions().get(0).longestName() + " is written before '" + command
                + "', where it would be ignored; put the options after the command: xpbd-cloth " + command + " "
                + String.join(" ", parsed.originalArgs().subList(0, parsed.originalArgs().indexOf(command))) + " ...");
        return true;
    }

    @Override public Integer call() {
        // The user's own mistakes first (a misspelt scene, a bad size), then the machine's (no display).
        PresetLoader.byNameOrPath(sketch.scene);
        parseSize(sketch.size);
        if (!displayAvailable("xpbd-cloth --scene " + sketch.scene)) return 2;
        sketch.open(null);
        return 0;
    }

    static int[] parseSize(String s) {
        String[] p = s.toLowerCase().split("x");
        try {
            int w = Integer.parseInt(p[0].trim()), h = Integer.parseInt(p[1].trim());
            if (w < 200 || h < 150) throw new NumberFormatException();
            return new int[] {w, h};
        } catch (RuntimeException e) {
            throw new IllegalArgumentException("size must be WxH with W >= 200 and H >= 150, was " + s);
        }
    }

    /**
     * The launcher as the user can type it from where they stand: the installed script's absolute path
     * (found from the jar this class came from, lib/ beside bin/), else its name.
     */
    static String launcher() {
        try {
            java.nio.file.Path jar = java.nio.file.Path.of(Main.class.getProtectionDomain().getCodeSource().getLocation().toURI());
            java.nio.file.Path script = jar.getParent().getParent().resolve("bin").resolve("xpbd-cloth");
            if (java.nio.file.Files.isExecutable(script)) return script.toString();
        } catch (RuntimeException | java.net.URISyntaxException e) {
            // not from an installed jar (gradle run, an IDE): the name will do
        }
        return "xpbd-cloth";
    }

    /** True if a window can open; otherwise says how to run under Xvfb instead of a stack trace. */
    static boolean displayAvailable(String commandLine) {
        String os = System.getProperty("os.name", "").toLowerCase();
        boolean linux = os.contains("linux") || os.contains("bsd");
        String display = System.getenv("DISPLAY");
        if (linux && (display == null || display.isEmpty()) && System.getenv("WAYLAND_DISPLAY") == null) {
            System.err.println("xpbd-cloth: no display (DISPLAY is not set), so no window can open.");
            System.err.println("Run it under a virtual display instead:");
            System.err.println("  sudo apt-get install -y xvfb libgl1-mesa-dri   # once");
            System.err.println("  xvfb-run -a -s '-screen 0 1600x1000x24' " + launcher() + commandLine.substring("xpbd-cloth".length()));
            return false;
        }
        return true;
    }

    @Command(name = "record", mixinStandardHelpOptions = true, showDefaultValues = true,
            description = "Renders a scene through the real P3D sketch at a fixed timestep and writes PNG frames (and optionally a GIF and an MP4).")
    static final class Record implements Callable<Integer> {
        @CommandLine.Mixin
        SketchOptions sketch = new SketchOptions();

        @Option(names = "--frames", description = "number of frames (one 60 Hz frame each)", defaultValue = "120")
        int frames;

        @Option(names = "--out", description = "folder for frame-0001.png, ... (default build/frames/<scene>)")
        File out;

        @Option(names = "--gif", description = "also write the frames as one looping GIF (every second frame, half size) to this file")
        File gif;

        @Option(names = "--mp4", description = "also write the frames as an H.264 MP4 video at the window's size to this file")
        File mp4;

        @Option(names = "--fps", description = "frames per second: of the MP4, 60 (every frame, the default) or 30 (every second frame), both real time; "
                + "of an --obj sequence, in simulated time, any rate whose frame is a whole number of the scene's steps (default: one frame per 1/60 s, or per step when dt is longer)")
        Integer fps;

        @Option(names = "--obj", description = "instead of PNG frames, write the cloth as one OBJ per frame (frame-0001.obj, ...) into this folder; headless, no display needed")
        File obj;

        @Option(names = "--usd", description = "instead of PNG frames, write the scene as one USD stage (text, .usda): the cloth's mesh with its points per frame, "
                + "the colliders with their poses; the same frame rates as --obj; headless, no display needed")
        File usd;

        @Override public Integer call() throws java.io.IOException {
            if (frames < 1) throw new IllegalArgumentException("frames must be >= 1, was " + frames);
            if (obj != null && usd != null) throw new IllegalArgumentException("--obj and --usd each write the whole recording; give one");
            if (obj != null) return recordObj();
            if (usd != null) return recordUsd();
            PresetLoader.byNameOrPath(sketch.scene); // a broken preset or size fails before anything is said or written
            parseSize(sketch.size);
            String name = new File(sketch.scene).getName().replace(".json", "");
            // Absolute against where the user stands: Processing resolves a relative path against the sketch's folder.
            File folder = (out != null ? out : new File("build/frames/" + name + (sketch.sideBySide ? "-side-by-side" : ""))).getAbsoluteFile();
            if (gif != null) gif = gif.getAbsoluteFile();
            if (mp4 != null) mp4 = mp4.getAbsoluteFile();
            ClothApp.Recording recording = new ClothApp.Recording(folder, frames, gif, mp4, fps == null ? 60 : fps); // checks fps before the display
            if (!displayAvailable("xpbd-cloth record --scene " + sketch.scene + " --frames " + frames + (out != null ? " --out " + out : ""))) return 2;
            System.out.println("recording " + frames + " frames of " + sketch.scene + " into " + folder);
            sketch.open(recording);
            return 0;
        }

        private int recordUsd() throws java.io.IOException {
            refuseImagesAndTwoCloths("--usd");
            xpbdcloth.scene.Preset preset = PresetLoader.byNameOrPath(sketch.scene);
            int steps = announce(preset, "frames", usd);
            long t0 = System.nanoTime();
            xpbdcloth.scene.Scene scene = xpbdcloth.scene.Scene.of(preset);
            int n = xpbdcloth.usd.UsdRecording.record(scene, frames, usd.toPath(), steps);
            System.out.printf(java.util.Locale.ROOT, "wrote %s: %d time codes (0 is the start), %.1f MB, in %.1f s%s%n",
                    usd, n, java.nio.file.Files.size(usd.toPath()) / 1e6, (System.nanoTime() - t0) / 1e9,
                    n < frames + 1 ? " (ended where the cloth tore: a USD stage holds one topology; --obj writes each frame's)" : "");
            System.out.println("last step: " + xpbdcloth.engine.StepBalance.verdict(scene.simulation().balance()));
            return 0;
        }

        /** Steps per recorded frame at --fps (or the scene's own rate), having said what is recorded where and at what rate. */
        private int announce(xpbdcloth.scene.Preset preset, String what, File into) {
            double dt = preset.solver.timestep();
            int steps = fps == null ? xpbdcloth.scene.ObjExport.stepsPerFrame(dt) : xpbdcloth.scene.ObjExport.stepsPerFrame(dt, fps);
            System.out.printf(java.util.Locale.ROOT, "recording %d %s of %s into %s: %.6g frames per second of simulated time (a frame every %d step%s of %.4g ms)%n",
                    frames, what, sketch.scene, into, 1 / (steps * dt), steps, steps == 1 ? "" : "s", 1000 * dt);
            return steps;
        }

        private void refuseImagesAndTwoCloths(String option) {
            if (sketch.sideBySide) throw new IllegalArgumentException(option + " records one cloth; drop --side-by-side (it shows two)");
            if (gif != null) throw new IllegalArgumentException(option + " writes meshes, not images; drop --gif");
            if (mp4 != null) throw new IllegalArgumentException(option + " writes meshes, not images; drop --mp4");
        }

        private int recordObj() throws java.io.IOException {
            refuseImagesAndTwoCloths("--obj");
            xpbdcloth.scene.Preset preset = PresetLoader.byNameOrPath(sketch.scene);
            int steps = announce(preset, "OBJ frames", obj);
            long t0 = System.nanoTime();
            xpbdcloth.scene.Scene scene = xpbdcloth.scene.Scene.of(preset);
            scene = xpbdcloth.scene.ObjExport.recordSequence(scene, frames, obj.toPath(), steps);
            int first = preset.cloth.isMesh() ? preset.cloth.mesh.vertexCount() : preset.cloth.columns * preset.cloth.rows, last = scene.cloth().particles().count();
            System.out.printf(java.util.Locale.ROOT, "wrote %d OBJ frames (%s; import at %.6g fps to play in real time) in %.1f s%n", frames,
                    first == last ? first + " vertices each" : first + " vertices, " + last + " by the end: the cloth tore", 1 / (steps * preset.solver.timestep()), (System.nanoTime() - t0) / 1e9);
            System.out.println("last step: " + xpbdcloth.engine.StepBalance.verdict(scene.simulation().balance()));
            return 0;
        }
    }

    @Command(name = "check", mixinStandardHelpOptions = true, showDefaultValues = true,
            description = "Loads presets (and fabric catalogues) without a window, builds their scenes, steps them, and reports each one's problems "
                    + "on standard error (exit code 2 if any) and whether its solve converges (a note, not a problem).")
    static final class CheckCommand implements Callable<Integer> {
        @CommandLine.Parameters(arity = "1..*", paramLabel = "PRESET", description = "built-in scene names, preset files or fabric catalogue files")
        java.util.List<String> presets;

        @Option(names = "--steps", description = "steps to run before saying whether the solve has converged (0: build only)")
        int steps = 10;

        @CommandLine.Spec
        CommandLine.Model.CommandSpec spec;

        @Override public Integer call() {
            if (steps < 0) throw new CommandLine.ParameterException(spec.commandLine(), "--steps must be >= 0, was " + steps);
            int bad = 0;
            java.io.PrintWriter out = spec.commandLine().getOut(), err = spec.commandLine().getErr();
            for (String p : presets) {
                try {
                    java.util.List<xpbdcloth.fabric.Fabric> fabrics = PresetLoader.catalogueOrNull(p);
                    if (fabrics != null) {
                        out.printf("%s: ok (a fabric catalogue: %d fabrics)%n", p, fabrics.size());
                        continue;
                    }
                    xpbdcloth.scene.Scene scene = xpbdcloth.scene.Scene.of(PresetLoader.byNameOrPath(p));
                    out.printf("%s: ok (%d particles, %d constraints)%n", p, scene.cloth().particles().count(), scene.simulation().constraintCount());
                    if (steps > 0) {
                        for (int s = 0; s < steps; s++) scene.simulation().step();
                        out.printf("  after %d steps: %s%n", steps, xpbdcloth.engine.StepBalance.verdict(scene.simulation().balance()));
                    }
                } catch (IllegalArgumentException e) {
                    err.println(e.getMessage());
                    bad++;
                }
            }
            out.flush();
            err.flush();
            return bad == 0 ? 0 : 2;
        }
    }

    @Command(name = "bench", mixinStandardHelpOptions = true, showDefaultValues = true, description = "The engine benchmark (CSV on stdout).")
    static final class BenchCommand implements Callable<Integer> {
        @Option(names = "--full", description = "also the peer workloads, all families, N = 256 and the parallel solve")
        boolean full;

        @Override public Integer call() {
            Bench.main(full ? new String[] {"--full"} : new String[0]);
            return 0;
        }
    }
}
