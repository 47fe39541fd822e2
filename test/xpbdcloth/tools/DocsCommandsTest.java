package xpbdcloth.tools;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import xpbdcloth.scene.PresetLoader;

/**
 * Every command the docs show runs as written. The commands are read from README.md and docs/*.md (fenced
 * blocks and code spans that start with {@code gradle}, {@code xpbd-cloth}, {@code build/install/…},
 * {@code xvfb-run} or {@code scripts/}) and checked without the long work: a Gradle command's tasks
 * against the build's own tasks and its {@code -P} properties against the ones build.gradle reads (Gradle's
 * own options against the few the docs may use); a launcher command parsed by the launcher's own picocli
 * model (an unknown option, a missing value or a value of the wrong kind fails), its scene and input files
 * checked to exist; and the cheap ones run ({@code check}, {@code --help}). A token in angle brackets,
 * {@code <preset.json>}, is a placeholder the reader fills in: the test puts a real one in its place.
 * Each failure names the file, the line and the command.
 */
class DocsCommandsTest {
    /** A command as the docs show it. */
    static final class DocCommand {
        final String file;
        final int line;
        final String text;

        DocCommand(String file, int line, String text) { this.file = file; this.line = line; this.text = text; }

        @Override public String toString() { return file + ":" + line + ": `" + text + "`"; }
    }

    static final Pattern FENCE = Pattern.compile("^\\s*```");
    static final Pattern SPAN = Pattern.compile("`([^`]+)`");
    static final Set<String> STARTS = Set.of("gradle", "xpbd-cloth", "xvfb-run", "scripts/deps");

    /** The documents read: the README and every page under docs/. */
    static List<Path> documents() throws IOException {
        List<Path> out = new ArrayList<>(List.of(Path.of("README.md")));
        try (Stream<Path> docs = Files.list(Path.of("docs"))) {
            docs.filter(p -> p.toString().endsWith(".md")).sorted().forEach(out::add);
        }
        return out;
    }

    /** The commands of one document, each part of a chain (&&, ;) on its own. */
    static List<DocCommand> commands(Path doc) throws IOException {
        List<DocCommand> out = new ArrayList<>();
        List<String> lines = Files.readAllLines(doc);
        boolean fenced = false;
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i);
            if (FENCE.matcher(line).find()) { fenced = !fenced; continue; }
            if (fenced) {
                String text = line.replaceAll("\\s+#.*$", "").trim();
                while (text.endsWith("\\") && i + 1 < lines.size()) text = text.substring(0, text.length() - 1) + " " + lines.get(++i).trim();
                addParts(out, doc.toString(), i + 1, text);
            } else {
                Matcher m = SPAN.matcher(line);
                while (m.find()) addParts(out, doc.toString(), i + 1, m.group(1));
            }
        }
        return out;
    }

    static void addParts(List<DocCommand> out, String file, int line, String text) {
        for (String part : text.split("&&|;|\\|\\|")) {
            String p = part.trim();
            String first = p.split("\\s+")[0];
            // A tool's name alone in prose (`gradle`, `xvfb-run`) names it; it is not a command.
            boolean nameAlone = p.equals(first) && !first.contains("/");
            if ((STARTS.contains(first) || first.startsWith("build/install/")) && !nameAlone) out.add(new DocCommand(file, line, p));
        }
    }

    /** The tokens of a command, quotes kept together (single or double) and removed. */
    static List<String> tokens(String command) {
        // As a shell splits words: quotes group (and are removed) wherever they start, so
        // -Pargs="--scene corners" is one word, -Pargs=--scene corners.
        List<String> out = new ArrayList<>();
        StringBuilder word = new StringBuilder();
        boolean inWord = false;
        char quote = 0;
        for (char ch : command.toCharArray()) {
            if (quote != 0) {
                if (ch == quote) quote = 0;
                else word.append(ch);
            } else if (ch == '"' || ch == '\'') {
                quote = ch;
                inWord = true;
            } else if (Character.isWhitespace(ch)) {
                if (inWord) out.add(word.toString());
                word.setLength(0);
                inWord = false;
            } else {
                word.append(ch);
                inWord = true;
            }
        }
        if (inWord) out.add(word.toString());
        return out;
    }

    /** A placeholder's stand-in: a value of the kind its name says. */
    static String standIn(String token) {
        Matcher m = Pattern.compile("<([^>]*)>").matcher(token);
        StringBuilder b = new StringBuilder();
        while (m.find()) {
            String name = m.group(1).toLowerCase(java.util.Locale.ROOT);
            String value = name.matches("n|frames|count|number") ? "2"
                    : name.endsWith(".json") || name.contains("preset") ? "data/hanging.json"
                    : name.endsWith(".obj") ? "data/flag-with-hole.obj"
                    : name.equals("scene") ? "hanging"
                    : "build/docs-test/" + name.replaceAll("[^a-z0-9.]", "-");
            m.appendReplacement(b, Matcher.quoteReplacement(value));
        }
        m.appendTail(b);
        return b.toString();
    }

    /** The tasks the build has: its own and the Java and application plugins'. */
    static Set<String> gradleTasks(String build) {
        Set<String> tasks = new LinkedHashSet<>(List.of("run", "test", "installDist", "jar", "build", "clean", "compileJava", "compileTestJava",
                "classes", "testClasses", "javadoc", "distZip", "distTar", "assemble", "check", "startScripts", "tasks", "help"));
        Matcher m = Pattern.compile("(?m)^task\\s+(\\w+)").matcher(build);
        while (m.find()) tasks.add(m.group(1));
        return tasks;
    }

    /** The -P properties build.gradle reads. */
    static Set<String> gradleProperties(String build) {
        Set<String> out = new LinkedHashSet<>();
        Matcher m = Pattern.compile("project\\.(?:hasProperty|property)\\('(\\w+)'\\)").matcher(build);
        while (m.find()) out.add(m.group(1));
        return out;
    }

    /** Gradle's own options the docs may use. */
    static final Set<String> GRADLE_OPTIONS = Set.of("--no-daemon", "-q", "--quiet", "--offline", "--info", "--stacktrace", "-i", "--console=plain");

    /** What is wrong with one command, or null. */
    static String problem(DocCommand c, Set<String> tasks, Set<String> properties) {
        List<String> t = new ArrayList<>();
        for (String token : tokens(c.text)) t.add(standIn(token));
        // xvfb-run [-a] [-s 'options'] COMMAND ...
        if (t.get(0).equals("xvfb-run")) {
            int k = 1;
            while (k < t.size() && t.get(k).startsWith("-")) k += t.get(k).equals("-s") ? 2 : 1;
            t = t.subList(k, t.size());
            if (t.isEmpty()) return "xvfb-run runs nothing";
        }
        String first = t.get(0);
        if (first.equals("gradle")) return gradleProblem(t.subList(1, t.size()), tasks, properties);
        if (first.equals("xpbd-cloth") || first.startsWith("build/install/")) {
            if (first.startsWith("build/install/") && !first.equals("build/install/xpbd-cloth/bin/xpbd-cloth"))
                return "the launcher is build/install/xpbd-cloth/bin/xpbd-cloth, not " + first;
            return launcherProblem(t.subList(1, t.size()));
        }
        if (first.equals("scripts/deps")) {
            if (!Files.isExecutable(Path.of(first))) return first + " is not an executable file";
            for (String a : t.subList(1, t.size())) if (!a.equals("--headless") && !a.equals("--blender")) return "scripts/deps takes only --headless or --blender, was " + a;
            return null;
        }
        return "does not start with a command the docs may show";
    }

    static String gradleProblem(List<String> args, Set<String> tasks, Set<String> properties) {
        boolean anyTask = false;
        for (String a : args) {
            if (a.startsWith("-P")) {
                String name = a.substring(2).split("=", 2)[0];
                if (!properties.contains(name)) return "the build reads no property -P" + name + " (it reads " + properties + ")";
                if (name.equals("scene") && a.contains("=")) {
                    String scene = a.substring(a.indexOf('=') + 1);
                    if (!PresetLoader.BUILT_IN.contains(scene) && !Files.exists(Path.of(scene))) return "-Pscene=" + scene + " is neither a built-in scene nor a file";
                }
                if (name.equals("makeObservation") && a.contains("=")) OUTPUTS.add(normal(a.substring(a.indexOf('=') + 1)));
                if (name.equals("observed") && a.contains("=") && !OUTPUTS.contains(normal(a.substring(a.indexOf('=') + 1)))
                        && !Files.exists(Path.of(a.substring(a.indexOf('=') + 1))))
                    return a + ": no such file, nor does an earlier command of the page write it";
                if (name.equals("args") && a.contains("=")) {
                    String problem = launcherProblem(tokens(a.substring(a.indexOf('=') + 1)));
                    if (problem != null) return "-Pargs: " + problem;
                }
            } else if (a.startsWith("-")) {
                if (!GRADLE_OPTIONS.contains(a)) return "Gradle has no option " + a + " the docs may use (a task's own settings are -P properties)";
            } else {
                if (!tasks.contains(a)) return "the build has no task " + a;
                anyTask = true;
            }
        }
        return anyTask ? null : "names no task";
    }

    /** What the commands read so far on the page write (a later command may read it): reset per page. */
    static final Set<String> OUTPUTS = new java.util.HashSet<>();

    static String normal(String path) {
        return path.endsWith("/") ? path.substring(0, path.length() - 1) : path;
    }

    static String launcherProblem(List<String> args) {
        CommandLine cli = new CommandLine(new Main());
        StringWriter out = new StringWriter(), err = new StringWriter();
        cli.setOut(new PrintWriter(out));
        cli.setErr(new PrintWriter(err));
        CommandLine.ParseResult parsed;
        try {
            parsed = cli.parseArgs(args.toArray(new String[0]));
        } catch (CommandLine.ParameterException e) {
            return e.getMessage();
        }
        CommandLine.ParseResult leaf = parsed;
        while (leaf.hasSubcommand()) leaf = leaf.subcommand();
        String command = leaf.commandSpec().name();
        if (leaf.hasMatchedOption("--scene")) {
            String scene = leaf.matchedOptionValue("--scene", "");
            if (!PresetLoader.BUILT_IN.contains(scene) && !Files.exists(Path.of(scene))) return "--scene " + scene + " is neither a built-in scene nor a file";
        }
        for (String option : new String[] {"--make-observation", "--out", "--obj", "--usd", "--gif", "--mp4"})
            if (leaf.hasMatchedOption(option)) OUTPUTS.add(normal(leaf.matchedOptionValue(option, new java.io.File("")).toString()));
        if (leaf.hasMatchedOption("--observed")) {
            String observed = normal(leaf.matchedOptionValue("--observed", new java.io.File("")).toString());
            if (!observed.startsWith("build/docs-test/") && !Files.exists(Path.of(observed)) && !OUTPUTS.contains(observed))
                return "--observed " + observed + " does not exist (nor does an earlier command of the page write it)";
        }
        boolean help = leaf.isUsageHelpRequested() || parsed.isUsageHelpRequested();
        if (command.equals("check") || help) {
            // Cheap: run it, the files expanded as the shell would.
            List<String> expanded = new ArrayList<>();
            for (String a : args) expanded.addAll(glob(a));
            int code = new CommandLine(new Main()).setOut(new PrintWriter(out)).setErr(new PrintWriter(err)).execute(expanded.toArray(new String[0]));
            if (code != 0) return "exits " + code + ": " + err.toString().trim();
        }
        return null;
    }

    /** A shell glob of one path part (data/*.json), expanded in the repository; other tokens as they are. */
    static List<String> glob(String token) {
        if (!token.contains("*")) return List.of(token);
        Path dir = Path.of(token).getParent() == null ? Path.of(".") : Path.of(token).getParent();
        String pattern = Path.of(token).getFileName().toString();
        List<String> out = new ArrayList<>();
        try (java.nio.file.DirectoryStream<Path> files = Files.newDirectoryStream(dir, pattern)) {
            for (Path f : files) out.add(f.toString());
        } catch (IOException e) {
            return List.of(token);
        }
        out.sort(String::compareTo);
        return out.isEmpty() ? List.of(token) : out;
    }

    @Test
    void everyCommandTheDocsShowRunsAsWritten() throws IOException {
        String build = Files.readString(Path.of("build.gradle"));
        Set<String> tasks = gradleTasks(build), properties = gradleProperties(build);
        List<String> failures = new ArrayList<>();
        int checked = 0;
        for (Path doc : documents()) {
            OUTPUTS.clear();
            for (DocCommand c : commands(doc)) {
                checked++;
                String problem = problem(c, tasks, properties);
                if (problem != null) failures.add(c + ": " + problem);
            }
        }
        System.out.println("commands in the docs checked: " + checked);
        assertTrue(checked > 20, "the docs show commands: " + checked + " found");
        assertEquals(List.of(), failures);
    }

    /** The checker itself catches what it should, so the test above cannot pass vacuously. */
    @Test
    void theCheckerCatchesWhatTheOldReadmeGotWrong() {
        String build;
        try {
            build = Files.readString(Path.of("build.gradle"));
        } catch (IOException e) {
            throw new AssertionError(e);
        }
        Set<String> tasks = gradleTasks(build), properties = gradleProperties(build);
        assertNotNull(problem(new DocCommand("x", 1, "gradle experiments --no-daemon --only mesh-independence"), tasks, properties));
        assertNull(problem(new DocCommand("x", 1, "gradle experiments --no-daemon -Ponly=mesh-independence"), tasks, properties));
        assertNotNull(problem(new DocCommand("x", 1, "gradle record --no-daemon -Pscene=hangin"), tasks, properties));
        assertNotNull(problem(new DocCommand("x", 1, "gradle recrd --no-daemon"), tasks, properties));
        assertNotNull(problem(new DocCommand("x", 1, "build/install/xpbd-cloth/bin/xpbd-cloth record --scene rope --frame 12"), tasks, properties));
        assertNotNull(problem(new DocCommand("x", 1, "xpbd-cloth record --scene rope --fps"), tasks, properties));
        assertNull(problem(new DocCommand("x", 1, "gradle run --no-daemon -Pargs=\"--scene corners --side-by-side\""), tasks, properties));
        assertNotNull(problem(new DocCommand("x", 1, "gradle run --no-daemon -Pargs=\"--scene corners --side-by-sid\""), tasks, properties));
        OUTPUTS.clear();
        assertNotNull(problem(new DocCommand("x", 1, "xpbd-cloth fit --scene drape --observed shape.obj"), tasks, properties));
        assertNull(problem(new DocCommand("x", 1, "xpbd-cloth fit --scene drape --make-observation shape.obj"), tasks, properties));
        assertNull(problem(new DocCommand("x", 1, "xpbd-cloth fit --scene drape --observed shape.obj"), tasks, properties), "written by the command before");
        OUTPUTS.clear();
        assertNull(problem(new DocCommand("x", 1, "xpbd-cloth check data/*.json"), tasks, properties));
        assertNull(problem(new DocCommand("x", 1, "xpbd-cloth check <preset.json>"), tasks, properties));
        assertNotNull(problem(new DocCommand("x", 1, "xpbd-cloth check no-such-file.json"), tasks, properties));
    }
}
