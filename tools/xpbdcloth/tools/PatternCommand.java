package xpbdcloth.tools;

import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import xpbdcloth.mesh.ObjWriter;
import xpbdcloth.pattern.MeshQuality;
import xpbdcloth.pattern.Panel;
import xpbdcloth.pattern.PatternMesh;
import xpbdcloth.pattern.Seam;
import xpbdcloth.scene.PatternLoader;

/**
 * {@code xpbd-cloth pattern PATTERN [--edge M] [--out FILE.obj]}: meshes a garment pattern's panels and says
 * how well (per panel: vertices, triangles, the smallest angle, the triangles' sizes against the target; per
 * seam: its stitches and how much one side is eased into the other); writes the placed panels as OBJ with
 * their fabric coordinates as texture coordinates and a group per panel and seam. Exits 2, saying why, when
 * the mesh is too coarse for a seam to close (a preset sewing it would be refused).
 */
@Command(name = "pattern", mixinStandardHelpOptions = true, showDefaultValues = true,
        description = "Meshes a garment pattern (built-in name or file) and reports each panel's mesh quality and each seam's stitches; --out writes the placed panels as OBJ.")
final class PatternCommand implements Callable<Integer> {
    @CommandLine.Parameters(paramLabel = "PATTERN", description = "a built-in pattern (skirt) or a pattern file")
    String pattern;

    @Option(names = "--edge", description = "target edge length in metres (default: the pattern's own)")
    Double edge;

    @Option(names = "--out", description = "OBJ file to write the placed panels to")
    java.io.File out;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override public Integer call() throws java.io.IOException {
        PatternLoader.Loaded loaded = PatternLoader.byNameOrPath(pattern);
        double h = edge == null ? loaded.edge : edge;
        if (!(h >= 1e-3 && h <= 1)) throw new CommandLine.ParameterException(spec.commandLine(), "--edge must be in [0.001, 1] m, was " + edge);
        long start = System.nanoTime();
        PatternMesh mesh = loaded.mesh(h);
        double seconds = (System.nanoTime() - start) / 1e9;
        java.io.PrintWriter w = spec.commandLine().getOut();
        w.printf("%s: %d panels, %d seams, %d vertices, %d triangles at edge %.3g m (meshed in %.2f s)%n", loaded.pattern.name,
                loaded.pattern.panels().size(), loaded.pattern.seams().size(), mesh.vertexCount(), mesh.triangleCount(), h, seconds);
        List<Panel> panels = loaded.pattern.panels();
        for (int i = 0; i < panels.size(); i++) {
            int[] v = mesh.panelVertexRange(i), t = mesh.panelTriangleRange(i);
            MeshQuality q = MeshQuality.ofPanel(mesh, i);
            w.printf("  panel %-14s %5d vertices %5d triangles  angles ≥ %.1f°  sizes %.2f–%.2f of the edge  %s%n",
                    "\"" + panels.get(i).name + "\"", v[1] - v[0], t[1] - t[0], q.smallestAngle, q.smallestSize, q.largestSize, panels.get(i).fabric);
        }
        for (Seam s : loaded.pattern.seams()) {
            double a = s.a.length(loaded.pattern.panel(s.a.panel).outline), b = s.b.length(loaded.pattern.panel(s.b.panel).outline);
            w.printf("  seam %-26s %3d stitches  %.3f m to %.3f m (eased %.1f %%)%n", "\"" + s.name + "\"", mesh.stitches(s.name).length / 2,
                    a, b, 100 * Math.abs(a - b) / Math.max(a, b));
        }
        if (out != null) {
            ObjWriter.write(out.toPath(), mesh.toClothMesh(), null, "xpbd-cloth pattern " + loaded.pattern.name + ": panels placed, unsewn; vt are fabric coordinates (u along the grain)");
            w.println("wrote " + out);
        }
        w.flush();
        // The panels mesh, but a preset sewing them would be refused: say so, as the loader would.
        String tooCoarse = mesh.seamProblem();
        if (tooCoarse != null) {
            spec.commandLine().getErr().printf("xpbd-cloth pattern: at an edge of %.3g m, %s%n", h, tooCoarse);
            return 2;
        }
        return 0;
    }
}
