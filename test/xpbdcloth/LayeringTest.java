package xpbdcloth;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The layering is one-way: tools, library → sketch → fit/experiments → usd → scene → fabric → engine, pattern → mesh, linalg. The engine (and its tests)
 * imports nothing of the layers above it nor of Processing; the fabric package nothing above it; the scene package nothing of the sketch,
 * the tools or the experiments. Read from the source text, so a wrong import fails here by name. The tools and experiments are a
 * source set of their own (tools/), which the simulator's (src/) cannot see at all: the compiler holds that line.
 */
class LayeringTest {
    static final Pattern IMPORT = Pattern.compile("^import\\s+(static\\s+)?([\\w.]+)", Pattern.MULTILINE);

    static List<String> violations(Path dir, String... forbidden) throws IOException {
        List<String> out = new ArrayList<>();
        try (Stream<Path> files = Files.walk(dir)) {
            for (Path f : (Iterable<Path>) files.filter(p -> p.toString().endsWith(".java"))::iterator) {
                Matcher m = IMPORT.matcher(Files.readString(f));
                while (m.find())
                    for (String prefix : forbidden)
                        if (m.group(2).startsWith(prefix)) out.add(f + " imports " + m.group(2));
            }
        }
        return out;
    }

    @Test
    void engineImportsNothingAboveIt() throws IOException {
        String[] above = {"xpbdcloth.fabric", "xpbdcloth.scene", "xpbdcloth.fit", "xpbdcloth.sketch", "xpbdcloth.experiments", "xpbdcloth.tools", "processing."};
        assertEquals(List.of(), violations(Path.of("src/xpbdcloth/engine"), above));
        assertEquals(List.of(), violations(Path.of("test/xpbdcloth/engine"), above));
    }

    /** A cloth as a material is built from the engine's blocks; it knows nothing of scenes or the sketch. */
    @Test
    void fabricImportsOnlyTheEngineAndMeshes() throws IOException {
        String[] above = {"xpbdcloth.scene", "xpbdcloth.fit", "xpbdcloth.sketch", "xpbdcloth.experiments", "xpbdcloth.tools", "xpbdcloth.library", "processing."};
        assertEquals(List.of(), violations(Path.of("src/xpbdcloth/fabric"), above));
    }

    /** Meshes are below the engine: geometry and files, no physics, nothing of the project at all. */
    @Test
    void meshImportsNothingOfTheProject() throws IOException {
        String[] project = {"xpbdcloth.engine", "xpbdcloth.scene", "xpbdcloth.sketch", "xpbdcloth.experiments", "xpbdcloth.tools", "processing."};
        assertEquals(List.of(), violations(Path.of("src/xpbdcloth/mesh"), project));
    }

    /** Garment patterns are geometry: outlines, their meshing (JTS) and stitches, on meshes and nothing above. */
    @Test
    void patternImportsOnlyMeshes() throws IOException {
        String[] above = {"xpbdcloth.engine", "xpbdcloth.fabric", "xpbdcloth.scene", "xpbdcloth.usd", "xpbdcloth.fit", "xpbdcloth.sketch",
                "xpbdcloth.experiments", "xpbdcloth.tools", "xpbdcloth.library", "processing."};
        assertEquals(List.of(), violations(Path.of("src/xpbdcloth/pattern"), above));
    }

    /** Linear algebra is below the engine too: matrices and their solvers, nothing of cloth. */
    @Test
    void linearAlgebraImportsNothingOfTheProject() throws IOException {
        String[] project = {"xpbdcloth.engine", "xpbdcloth.mesh", "xpbdcloth.fabric", "xpbdcloth.scene", "xpbdcloth.usd", "xpbdcloth.fit",
                "xpbdcloth.sketch", "xpbdcloth.experiments", "xpbdcloth.tools", "xpbdcloth.library", "processing."};
        assertEquals(List.of(), violations(Path.of("src/xpbdcloth/linalg"), project));
    }

    @Test
    void sceneImportsNoSketchToolsOrExperiments() throws IOException {
        String[] above = {"xpbdcloth.fit", "xpbdcloth.sketch", "xpbdcloth.experiments", "xpbdcloth.tools", "processing."};
        assertEquals(List.of(), violations(Path.of("src/xpbdcloth/scene"), above));
    }

    /** USD files are written from scenes and read for fitting and the sketch: the exchange format knows neither. */
    @Test
    void usdSitsOnScenesAndNothingBelowKnowsIt() throws IOException {
        String[] above = {"xpbdcloth.fit", "xpbdcloth.sketch", "xpbdcloth.experiments", "xpbdcloth.tools", "xpbdcloth.library", "processing."};
        assertEquals(List.of(), violations(Path.of("src/xpbdcloth/usd"), above));
        for (String below : new String[] {"scene", "fabric", "engine", "mesh"})
            assertEquals(List.of(), violations(Path.of("src/xpbdcloth/" + below), "xpbdcloth.usd"));
    }

    /** Fitting sits on scenes and the engine; the sketch and the command line use it, never the reverse. */
    @Test
    void fitImportsNoSketchToolsExperimentsOrLibrary() throws IOException {
        String[] above = {"xpbdcloth.sketch", "xpbdcloth.experiments", "xpbdcloth.tools", "xpbdcloth.library", "processing."};
        assertEquals(List.of(), violations(Path.of("src/xpbdcloth/fit"), above));
    }

    /** The Processing library is a face on the sketch's parts: nothing below it knows it exists. */
    @Test
    void nothingImportsTheLibrary() throws IOException {
        for (String below : new String[] {"sketch", "fit", "scene", "engine", "mesh", "linalg"})
            assertEquals(List.of(), violations(Path.of("src/xpbdcloth/" + below), "xpbdcloth.library"));
        assertEquals(List.of(), violations(Path.of("tools/xpbdcloth/experiments"), "xpbdcloth.library", "xpbdcloth.tools"));
    }

    /** The repository cites papers and public sources, never a folder outside itself. */
    @Test
    void nothingPointsOutsideTheRepository() throws IOException {
        List<String> out = new ArrayList<>();
        for (String root : new String[] {"README.md", "src", "test", "data", "build.gradle", "scripts", "xpbd_cloth", "processing-library"})
            try (Stream<Path> files = Files.walk(Path.of(root))) {
                for (Path f : (Iterable<Path>) files.filter(Files::isRegularFile)::iterator)
                    if (!f.toString().endsWith("LayeringTest.java") && Files.readString(f, java.nio.charset.StandardCharsets.ISO_8859_1).contains("../" + "shared")) out.add(f.toString());
            }
        assertEquals(List.of(), out);
    }

    /** The scanner itself finds an import it should (so the two tests above cannot pass vacuously). */
    @Test
    void theScannerSeesImports() throws IOException {
        assertFalse(violations(Path.of("src/xpbdcloth/sketch"), "processing.").isEmpty());
    }
}
