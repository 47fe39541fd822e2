package xpbdcloth.sketch;

import static org.junit.jupiter.api.Assertions.*;

import java.awt.image.BufferedImage;
import java.io.File;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import processing.mode.java.preproc.PdePreprocessIssue;
import processing.mode.java.preproc.PdePreprocessor;
import processing.mode.java.preproc.PreprocessorResult;

/**
 * Every sketch a Processing user gets (the library's examples and {@code xpbd_cloth/}) built the way the
 * Processing IDE builds it: its tabs through Processing's own preprocessor, the Java compiled against
 * Processing's core and the jars the user would have (the library folder's {@code library/}, or the
 * sketch's {@code code/} folder) and nothing else, then run under a display for 60 frames. The frames
 * must show a cloth, and it must move. A sketch that does not preprocess or compile fails with the
 * preprocessor's or the compiler's own message.
 */
@Tag("slow")
class ProcessingSketchesTest {
    static final Path LIBRARY = Path.of("build/processing-library/xpbdcloth");
    static final int FIRST = 20, LAST = 60;

    static Stream<String> sketches() throws Exception {
        List<String> all = new ArrayList<>();
        try (Stream<Path> examples = Files.list(LIBRARY.resolve("examples"))) {
            examples.sorted().forEach(p -> all.add(p.toString()));
        }
        assertTrue(all.size() >= 5, "examples in " + LIBRARY + ": " + all);
        all.add("xpbd_cloth");
        return all.stream();
    }

    /** The library's jar holds the simulator and the library, not the launcher, experiments and tools (whose libraries it does not ship). */
    @org.junit.jupiter.api.Test
    void theLibraryJarHoldsTheSimulatorOnly() throws Exception {
        List<String> names = new ArrayList<>();
        try (java.util.jar.JarFile jar = new java.util.jar.JarFile(LIBRARY.resolve("library/xpbdcloth.jar").toFile())) {
            jar.stream().forEach(e -> names.add(e.getName()));
        }
        assertTrue(names.contains("xpbdcloth/library/ClothView.class") && names.contains("xpbdcloth/engine/Simulation.class"), "the library and the engine");
        assertTrue(names.contains("presets/hanging.json"), "the built-in presets");
        for (String n : names)
            assertFalse(n.startsWith("xpbdcloth/tools/") || n.startsWith("xpbdcloth/experiments/"), "not in a library: " + n);
        String properties = Files.readString(LIBRARY.resolve("library.properties"));
        assertTrue(properties.contains("vertex block descent") && properties.contains("box and capsule"), "library.properties describes what the library is now");
    }

    @ParameterizedTest
    @MethodSource("sketches")
    void sketchPreprocessesCompilesRunsAndShowsAMovingCloth(String folder, @TempDir Path out) throws Exception {
        RecordingSmokeTest.requireDisplay();
        Path sketch = Path.of(folder);
        String name = sketch.getFileName().toString();
        // What the user has: Processing's core (with JOGL), plus the library's jars or the sketch's code/ folder.
        List<String> jars = new ArrayList<>(processingCore());
        Path own = name.equals("xpbd_cloth") ? sketch.resolve("code") : LIBRARY.resolve("library");
        try (Stream<Path> s = Files.list(own)) {
            s.filter(p -> p.toString().endsWith(".jar")).forEach(p -> jars.add(p.toAbsolutePath().toString()));
        }

        String java = preprocess(sketch, name);
        Files.writeString(out.resolve(name + ".java"), java);
        Files.writeString(out.resolve("XpbdProbe.java"), probe(name));
        compile(out, jars, out.resolve(name + ".java"), out.resolve("XpbdProbe.java"));

        List<String> cmd = new ArrayList<>(List.of(javaBinary(), "-cp", out + File.pathSeparator + String.join(File.pathSeparator, jars),
                "-Dprobe.out=" + out, "processing.core.PApplet", "--sketch-path=" + sketch.toAbsolutePath(), "XpbdProbe"));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(out.resolve("log.txt").toFile()).start();
        boolean finished = p.waitFor(120, TimeUnit.SECONDS);
        if (!finished) p.destroyForcibly();
        String log = Files.readString(out.resolve("log.txt"));
        assertTrue(finished, name + " ran its " + LAST + " frames within 2 minutes; log:\n" + log);
        assertEquals(0, p.exitValue(), name + " exit code; log:\n" + log);
        assertFalse(log.contains("Exception"), name + " printed an exception:\n" + log);

        BufferedImage a = ImageIO.read(out.resolve("probe-" + FIRST + ".png").toFile());
        BufferedImage b = ImageIO.read(out.resolve("probe-" + LAST + ".png").toFile());
        double cloth = RecordingSmokeTest.clothShare(b), changed = RecordingSmokeTest.changed(a, b);
        System.out.printf("%s: preprocessed, compiled against %d jars, ran %d frames; cloth covers %.1f %% of the frame, %.2f %% of pixels changed%n",
                name, jars.size(), LAST, 100 * cloth, 100 * changed);
        assertTrue(cloth > 0.005 && cloth < 0.8, name + ": the frame shows a cloth (its colours cover " + cloth + " of it)");
        assertTrue(changed > 0.002, name + ": the cloth moves between frames " + FIRST + " and " + LAST);
    }

    /** The sketch's tabs (main tab first, then the others by name), through Processing's preprocessor. */
    static String preprocess(Path sketch, String name) throws Exception {
        List<Path> tabs;
        try (Stream<Path> s = Files.list(sketch)) {
            tabs = s.filter(p -> p.toString().endsWith(".pde")).sorted().collect(Collectors.toList());
        }
        Path main = sketch.resolve(name + ".pde");
        assertTrue(tabs.remove(main), "main tab " + main);
        tabs.add(0, main);
        StringBuilder program = new StringBuilder();
        for (Path tab : tabs) program.append(Files.readString(tab, StandardCharsets.UTF_8)).append('\n');
        StringWriter java = new StringWriter();
        PreprocessorResult r = PdePreprocessor.builderFor(name).setTabSize(2).build().write(java, program.toString(), List.of());
        StringBuilder issues = new StringBuilder();
        for (PdePreprocessIssue i : r.getPreprocessIssues())
            issues.append(String.format("%s.pde:%d:%d: %s%n", name, i.getLine(), i.getCharPositionInLine(), i.getMsg()));
        assertEquals("", issues.toString(), name + " does not preprocess");
        assertEquals(name, r.getClassName());
        return java.toString();
    }

    /**
     * A subclass of the sketch that saves two frames and quits; its saver is registered after the sketch's
     * own setup, so it runs after everything the sketch and the library draw.
     */
    static String probe(String sketch) {
        return "import processing.core.PApplet;\n"
                + "public class XpbdProbe extends " + sketch + " {\n"
                + "  public static final class Saver {\n"
                + "    final PApplet app; final String out;\n"
                + "    Saver(PApplet app) { this.app = app; this.out = System.getProperty(\"probe.out\"); }\n"
                + "    public void draw() {\n"
                + "      if (app.frameCount == " + FIRST + " || app.frameCount == " + LAST + ") app.saveFrame(out + \"/probe-\" + app.frameCount + \".png\");\n"
                + "      if (app.frameCount == " + LAST + ") app.exit();\n"
                + "    }\n"
                + "  }\n"
                + "  @Override public void setup() { super.setup(); registerMethod(\"draw\", new Saver(this)); }\n"
                + "}\n";
    }

    static void compile(Path out, List<String> classpath, Path... sources) throws Exception {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        try (StandardJavaFileManager files = javac.getStandardFileManager(diagnostics, null, StandardCharsets.UTF_8)) {
            List<String> options = List.of("-d", out.toString(), "-cp", String.join(File.pathSeparator, classpath), "-nowarn", "-encoding", "UTF-8");
            boolean ok = javac.getTask(null, files, diagnostics, options, null, files.getJavaFileObjects(sources)).call();
            assertTrue(ok, "does not compile:\n" + diagnostics.getDiagnostics().stream()
                    .map(d -> d.getSource().getName() + ":" + d.getLineNumber() + ": " + d.getMessage(null)).collect(Collectors.joining("\n")));
        }
    }

    /** Processing's core as the IDE ships it: core, JOGL and gluegen (with their natives), Kotlin's library. */
    static List<String> processingCore() {
        List<String> out = new ArrayList<>();
        for (String entry : System.getProperty("java.class.path").split(File.pathSeparator)) {
            String file = new File(entry).getName();
            if (file.startsWith("core-4") || file.startsWith("jogl-all") || file.startsWith("gluegen-rt") || file.startsWith("kotlin-stdlib"))
                out.add(entry);
        }
        assertTrue(out.stream().anyMatch(e -> new File(e).getName().startsWith("core-4")), "Processing core on the test classpath");
        return out;
    }

    static String javaBinary() { return Path.of(System.getProperty("java.home"), "bin", "java").toString(); }
}
