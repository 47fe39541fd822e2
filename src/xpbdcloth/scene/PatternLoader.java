package xpbdcloth.scene;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import xpbdcloth.pattern.Curve;
import xpbdcloth.pattern.Outline;
import xpbdcloth.pattern.Panel;
import xpbdcloth.pattern.Pattern;
import xpbdcloth.pattern.PatternMesh;
import xpbdcloth.pattern.Placement;
import xpbdcloth.pattern.Seam;
import xpbdcloth.pattern.Stretch;

/**
 * Reads garment patterns (JSON, documented in the README under "Patterns") as strictly as presets: every
 * problem a {@link PresetException} naming the file, the field and, for what the pattern's geometry refuses
 * (an outline crossing itself, a stretch past its outline's end or sewn twice), the panel or seam.
 */
public final class PatternLoader {
    private PatternLoader() {}

    /** A pattern and the edge length its panels are meshed at. */
    public static final class Loaded {
        public final Pattern pattern;
        public final double edge;
        public final String description;

        Loaded(Pattern pattern, double edge, String description) {
            this.pattern = pattern;
            this.edge = edge;
            this.description = description;
        }

        /** The panels meshed at the pattern's edge length (or a finer or coarser one). */
        public PatternMesh mesh(double edge) { return PatternMesh.of(pattern, edge); }
    }

    /** The folder of the built-in patterns, in data/ and in the jar beside the presets. */
    public static final String FOLDER = "patterns";

    /** A built-in pattern by name ("skirt": data/patterns/skirt.json, in the jar), or a pattern file by path. */
    public static Loaded byNameOrPath(String nameOrPath) {
        if (isBuiltIn(nameOrPath)) return builtIn(nameOrPath);
        Path path = Path.of(nameOrPath);
        return parse(path.getFileName().toString(), PresetLoader.readGuarded(path));
    }

    /** Whether a plain name is a pattern that ships in the jar. */
    static boolean isBuiltIn(String name) {
        return !name.contains("/") && !name.contains("\\") && PatternLoader.class.getResource(resource(name)) != null;
    }

    static Loaded builtIn(String name) {
        try (java.io.InputStream in = PatternLoader.class.getResourceAsStream(resource(name))) {
            if (in == null) throw new PresetException(name, "(file)", "is not a built-in pattern");
            return parse(name + ".json", new String(in.readAllBytes(), java.nio.charset.StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new PresetException(name, "(file)", "cannot be read from the jar: " + e.getMessage());
        }
    }

    private static String resource(String name) { return "/presets/" + FOLDER + "/" + name + ".json"; }

    /** Why a pattern cannot be meshed at that edge length (too many vertices, or a panel too small for it), or null. */
    static String edgeProblem(Pattern pattern, double edge) {
        double area = 0;
        for (Panel p : pattern.panels()) area += p.outline.area();
        // A triangular lattice of spacing h has one vertex per (√3/2) h² of area.
        double vertices = area / (Math.sqrt(3) / 2 * edge * edge);
        if (vertices > Limits.PATTERN_VERTICES.hi)
            return String.format("an edge of %.3g m would mesh the panels' %.3g m² into about %.0f vertices; at most %.0f are allowed: give a longer edge", edge, area, vertices, Limits.PATTERN_VERTICES.hi);
        for (Panel p : pattern.panels())
            if (p.outline.length() < 3 * edge)
                return "an edge of " + String.format("%.3g", edge) + " m is too long for panel \"" + p.name + "\" (its outline is " + String.format("%.3g", p.outline.length()) + " m round): give an edge at most a third of that";
        return null;
    }

    /** Parses a pattern's text; {@code file} names it in errors. */
    public static Loaded parse(String file, String text) {
        Reader reader = new Reader(file);
        JsonFields.Node root = new JsonFields.Node(JsonFields.readJson(file, text), "");
        return reader.whole(() -> reader.pattern(root));
    }

    private static final class Reader extends JsonFields {
        Reader(String file) { super(file); }

        Loaded pattern(Node root) {
            object(root, Set.of("name", "description", "edge", "panels", "seams"));
            String name = string(required(root, "name"));
            Node d = optional(root, "description");
            String description = d == null ? "" : string(d);
            double edge = number(required(root, "edge"), Limits.PATTERN_EDGE);
            List<Panel> panels = new ArrayList<>();
            for (Node p : array(required(root, "panels"), 1000)) {
                Panel panel = part(() -> panel(p));
                if (panel != null) panels.add(panel);
            }
            List<Seam> seams = new ArrayList<>();
            Node s = optional(root, "seams");
            if (s != null)
                for (Node n : array(s, 10_000)) {
                    Seam seam = part(() -> seam(n, seams.size()));
                    if (seam != null) seams.add(seam);
                }
            if (!found.isEmpty()) return null;
            Pattern pattern;
            try {
                pattern = new Pattern(name, panels, seams);
            } catch (IllegalArgumentException e) {
                throw fail(e.getMessage().startsWith("seam") ? "seams" : "panels", e.getMessage());
            }
            String problem = edgeProblem(pattern, edge);
            if (problem != null) throw fail("edge", problem);
            return new Loaded(pattern, edge, description);
        }

        Panel panel(Node n) {
            object(n, Set.of("name", "fabric", "grain", "outline", "position", "rotation", "wrap", "around"));
            String name = string(required(n, "name"));
            Node f = required(n, "fabric");
            String fabric = string(f);
            if (FabricCatalogue.named(fabric) == null)
                throw fail(f.path, "panel \"" + name + "\": no fabric \"" + fabric + "\" in " + FabricCatalogue.FILE + "; one of " + String.join(", ", FabricCatalogue.names()));
            Node g = required(n, "grain");
            double[] grain = pair(g);
            if (Math.hypot(grain[0], grain[1]) < 1e-9) throw fail(g.path, "panel \"" + name + "\": must be a direction, was [0, 0]");
            Node o = required(n, "outline");
            Outline outline = outline(o, name);
            Node p = optional(n, "position"), r = optional(n, "rotation"), w = optional(n, "wrap"), around = optional(n, "around");
            Placement at;
            if (around != null) {
                for (Node other : new Node[] {p, r, w})
                    if (other != null) throw fail(other.path, "panel \"" + name + "\": a panel is placed by position, rotation and wrap, or around a body part, not both");
                object(around, Set.of("centre", "radii", "angle", "axis"));
                Node radii = required(around, "radii"), angle = optional(around, "angle"), axis = optional(around, "axis");
                if (!radii.json.isArray() || radii.json.size() != 2) throw fail(radii.path, "must be [x, z], the half widths of the body part, was " + describe(radii.json));
                at = Placement.around(vector(required(around, "centre"), Limits.POSITION),
                        new double[] {number(new Node(radii.json.get(0), radii.path + "[0]"), Limits.SIZE), number(new Node(radii.json.get(1), radii.path + "[1]"), Limits.SIZE)},
                        angle == null ? 0 : number(angle, Limits.ROTATION), axis == null ? new double[] {0, 1, 0} : direction(axis));
            } else {
                at = new Placement(p == null ? new double[3] : vector(p, Limits.POSITION),
                        r == null ? new double[3] : vector(r, Limits.ROTATION), w == null ? 0 : number(w, Limits.WRAP_RADIUS));
            }
            return new Panel(name, outline, grain, fabric, at);
        }

        /** Corners with the edge from each to the next: straight, an arc ("bulge") or a Bézier curve ("controls"). */
        Outline outline(Node n, String panel) {
            List<Node> entries = array(n, 1000);
            if (entries.size() < 2) throw fail(n.path, "panel \"" + panel + "\": an outline needs at least 2 corners, had " + entries.size());
            double[][] corners = new double[entries.size()][];
            for (int k = 0; k < corners.length; k++) {
                object(entries.get(k), Set.of("at", "bulge", "controls"));
                corners[k] = pair(required(entries.get(k), "at"));
            }
            Curve[] edges = new Curve[corners.length];
            for (int k = 0; k < corners.length; k++) {
                Node e = entries.get(k), bulge = optional(e, "bulge"), controls = optional(e, "controls");
                double[] a = corners[k], b = corners[(k + 1) % corners.length];
                if (bulge != null && controls != null) throw fail(e.path, "panel \"" + panel + "\": an edge is an arc (\"bulge\") or a Bézier curve (\"controls\"), not both");
                if (bulge != null) {
                    double s = number(bulge, Limits.PATTERN_COORDINATE);
                    edges[k] = s == 0 ? Curve.line(a, b) : Curve.arc(a, b, s);
                } else if (controls != null) {
                    List<Node> c = array(controls, 2);
                    if (c.size() != 2) throw fail(controls.path, "panel \"" + panel + "\": must be two control points [[x, y], [x, y]], was " + describe(controls.json));
                    edges[k] = Curve.bezier(a, pair(c.get(0)), pair(c.get(1)), b);
                } else {
                    edges[k] = Curve.line(a, b);
                }
            }
            try {
                return new Outline(corners, edges);
            } catch (IllegalArgumentException e) {
                throw fail(n.path, "panel \"" + panel + "\": " + e.getMessage());
            }
        }

        Seam seam(Node n, int index) {
            object(n, Set.of("name", "a", "b"));
            Node nm = optional(n, "name");
            String name = nm == null ? "seam " + (index + 1) : string(nm);
            return new Seam(name, stretch(required(n, "a")), stretch(required(n, "b")));
        }

        Stretch stretch(Node n) {
            object(n, Set.of("panel", "from", "to", "backward"));
            Node b = optional(n, "backward");
            return new Stretch(string(required(n, "panel")), number(required(n, "from"), Limits.PATTERN_POSITION),
                    number(required(n, "to"), Limits.PATTERN_POSITION), b != null && bool(b));
        }

        double[] pair(Node n) {
            if (!n.json.isArray() || n.json.size() != 2) throw fail(n.path, "must be [x, y], was " + describe(n.json));
            return new double[] {number(new Node(n.json.get(0), n.path + "[0]"), Limits.PATTERN_COORDINATE),
                    number(new Node(n.json.get(1), n.path + "[1]"), Limits.PATTERN_COORDINATE)};
        }
    }
}
