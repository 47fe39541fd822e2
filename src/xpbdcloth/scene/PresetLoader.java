package xpbdcloth.scene;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.Material;
import xpbdcloth.engine.SolverSettings;
import xpbdcloth.engine.OrthotropicMaterial;
import xpbdcloth.fabric.DataDrivenSample;
import xpbdcloth.fabric.Fabric;
import xpbdcloth.mesh.BodyMesh;
import xpbdcloth.mesh.ClothMesh;
import xpbdcloth.mesh.MeshFileException;
import xpbdcloth.mesh.ObjReader;
import xpbdcloth.mesh.UsdMeshAnimation;
import xpbdcloth.mesh.UsdaReader;

/**
 * Reads scene presets (JSON) strictly: bad syntax, a missing or unknown field, a wrong type or a value out
 * of range is a {@link PresetException} naming the file, the field and the problem. The format is
 * documented in the README ("Presets"); the files in {@code data/} are its examples.
 */
public final class PresetLoader {
    /** The presets that ship with the project, in the order the sketch offers them. */
    public static final List<String> BUILT_IN = List.of("hanging", "corners", "sphere-pass", "rope", "spinning-sphere", "curtain", "flag", "tablecloth", "table", "arm", "drop-fold", "fabric", "flag-fabric", "drape", "denim-fold", "mannequin-poncho", "mannequin-turn", "torus-spin", "crease", "pillow", "balloon", "skirt", "tshirt", "tshirt-turn", "bordered-tablecloth", "drape-tester", "tear", "rip");

    private PresetLoader() {}

    /** A built-in preset by name (from the jar), e.g. "hanging". */
    public static Preset builtIn(String name) {
        return parse(name + ".json", builtInText(name), BUILT_IN_FILES);
    }

    /**
     * A built-in preset whose mesh files are looked for in {@code folder} first (the jar's where the folder
     * has none): the same scene on another mesh of the same name, e.g. a specimen meshed finer.
     */
    public static Preset builtIn(String name, Path folder) {
        return parseBeside(name + ".json", builtInText(name), folder);
    }

    private static String builtInText(String name) {
        String file = name + ".json";
        try (InputStream in = PresetLoader.class.getResourceAsStream("/presets/" + file)) {
            if (in == null) throw new PresetException(name, "(file)", "no built-in preset of that name; built-in: " + String.join(", ", BUILT_IN));
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new PresetException(file, "(file)", "cannot be read: " + e.getMessage());
        }
    }

    /** A mesh file beside the built-in presets (in the jar). */
    private static ClothMesh builtInMesh(String name, double weld) {
        try (InputStream in = PresetLoader.class.getResourceAsStream("/presets/" + name)) {
            if (in == null) throw new MeshFileException(name, 0, "no such file beside the built-in presets");
            return ObjReader.parse(name, new String(in.readAllBytes(), StandardCharsets.UTF_8), weld);
        } catch (IOException e) {
            throw new MeshFileException(name, 0, "cannot be read: " + e.getMessage());
        }
    }

    /** A body file beside the built-in presets (in the jar): an OBJ or a USD text file. */
    private static BodyMesh builtInBody(String name) {
        try (InputStream in = PresetLoader.class.getResourceAsStream("/presets/" + name)) {
            if (in == null) throw new MeshFileException(name, 0, "no such file beside the built-in presets");
            String text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
            if (name.toLowerCase(java.util.Locale.ROOT).endsWith(".usda"))
                return BodyMesh.of(UsdMeshAnimation.of(UsdaReader.parse(name, new java.io.StringReader(text)), null));
            return BodyMesh.of(name, ObjReader.parse(name, text, BODY_WELD));
        } catch (IOException e) {
            throw new MeshFileException(name, 0, "cannot be read: " + e.getMessage());
        }
    }

    /** Vertices of a body's OBJ closer than this (m) are one: exporters split them along seams. */
    static final double BODY_WELD = 1e-6;

    /** Where a preset's mesh files are found: by their names relative to the preset. */
    interface MeshFiles {
        /** A cloth's mesh. */
        ClothMesh load(String relativeName, double weld);

        /** A body to collide with: an OBJ, a .usda with an animated Mesh, or a folder of OBJ frames (played at fps). */
        BodyMesh body(String relativeName, double fps);

        /** A garment pattern: a built-in one by name (data/patterns/NAME.json), or a file. */
        PatternLoader.Loaded pattern(String relativeName);
    }

    private static final MeshFiles BUILT_IN_FILES = new MeshFiles() {
        @Override public ClothMesh load(String name, double weld) { return builtInMesh(name, weld); }
        @Override public BodyMesh body(String name, double fps) { return builtInBody(name); }
        @Override public PatternLoader.Loaded pattern(String name) { return PatternLoader.builtIn(name); }
    };

    /**
     * Mesh files relative to a folder; a plain name found nowhere there but shipped beside the built-in
     * presets is taken from the jar, so a copied built-in preset (cp data/flag.json .) still runs.
     */
    private static MeshFiles besides(Path folder) {
        return new MeshFiles() {
            @Override public ClothMesh load(String name, double weld) {
                Path file = folder.resolve(name);
                if (!Files.exists(file) && builtIn(name)) return builtInMesh(name, weld);
                return ObjReader.read(file, weld);
            }

            @Override public BodyMesh body(String name, double fps) {
                Path file = folder.resolve(name);
                if (!Files.exists(file) && builtIn(name)) return builtInBody(name);
                if (Files.isDirectory(file)) {
                    if (Double.isNaN(fps)) throw new MeshFileException(name, 0, "is a folder of frames: give their rate, fps");
                    return BodyMesh.ofFrames(file, fps, BODY_WELD);
                }
                if (name.toLowerCase(java.util.Locale.ROOT).endsWith(".usda")) return BodyMesh.of(UsdMeshAnimation.read(file, null));
                return BodyMesh.of(name, ObjReader.read(file, BODY_WELD));
            }

            @Override public PatternLoader.Loaded pattern(String name) {
                Path file = folder.resolve(name);
                if (!Files.exists(file) && PatternLoader.isBuiltIn(name)) return PatternLoader.builtIn(name);
                return PatternLoader.parse(file.getFileName().toString(), readGuarded(file));
            }

            private boolean builtIn(String name) {
                boolean plainName = !name.contains("/") && !name.contains("\\");
                return plainName && PresetLoader.class.getResource("/presets/" + name) != null;
            }
        };
    }

    /** A preset's text as if it were a file in {@code folder} (the meshes and patterns it names are looked for there); {@code file} names it in errors. */
    public static Preset parseBeside(String file, String text, Path folder) {
        return parse(file, text, besides(folder.toAbsolutePath()));
    }

    /** The largest preset file read, bytes: the biggest sensible preset is a few kB. */
    public static final long MAX_FILE_BYTES = 1 << 20;

    /**
     * A preset file on disk: a regular file (not a directory, device or pipe, which could be endless or
     * block), at most {@link #MAX_FILE_BYTES}, in UTF-8.
     */
    public static Preset load(Path path) {
        String file = path.toString();
        return parse(file, readGuarded(path), besides(path.toAbsolutePath().getParent()));
    }

    /** A preset-sized text file's text: a regular file, at most {@link #MAX_FILE_BYTES}, UTF-8; else the problem, named. */
    static String readGuarded(Path path) {
        String file = path.toString();
        if (Files.isDirectory(path)) throw new PresetException(file, "(file)", "is a directory, not a preset file");
        if (!Files.exists(path)) throw new PresetException(file, "(file)", "does not exist");
        if (!Files.isRegularFile(path)) throw new PresetException(file, "(file)", "is not a regular file (a device or a pipe?), not a preset file");
        try {
            long size = Files.size(path);
            if (size > MAX_FILE_BYTES)
                throw new PresetException(file, "(file)", "is " + size + " bytes; a preset is at most " + MAX_FILE_BYTES + " bytes (this is not a preset, or it lists far too much)");
            return utf8(file, Files.readAllBytes(path));
        } catch (IOException e) {
            throw new PresetException(file, "(file)", "cannot be read: " + e.getMessage());
        }
    }

    /**
     * The fabrics of a catalogue file (one whose top level lists {@code "fabrics"}, as data/fabrics.json),
     * validated, or null when the file is something else (a preset): so {@code check data/*.json} checks
     * the catalogue as a catalogue. A built-in scene name is never a catalogue.
     */
    public static List<Fabric> catalogueOrNull(String nameOrPath) {
        if (BUILT_IN.contains(nameOrPath)) return null;
        Path path = Path.of(nameOrPath);
        if (!Files.isRegularFile(path)) return null;
        String text = readGuarded(path);
        return JsonFields.readJson(nameOrPath, text).has("fabrics") ? parseCatalogue(nameOrPath, text) : null;
    }

    /** The bytes as UTF-8 text, or an error saying where they stop being UTF-8. */
    static String utf8(String file, byte[] bytes) {
        java.nio.charset.CharsetDecoder d = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(java.nio.charset.CodingErrorAction.REPORT).onUnmappableCharacter(java.nio.charset.CodingErrorAction.REPORT);
        java.nio.ByteBuffer in = java.nio.ByteBuffer.wrap(bytes);
        try {
            return d.decode(in).toString();
        } catch (java.nio.charset.CharacterCodingException e) {
            boolean utf16 = bytes.length >= 2 && ((bytes[0] & 0xff) == 0xfe && (bytes[1] & 0xff) == 0xff || (bytes[0] & 0xff) == 0xff && (bytes[1] & 0xff) == 0xfe);
            throw new PresetException(file, "(file)", "is not UTF-8 text" + (utf16 ? " (it looks like UTF-16: save it as UTF-8)" : " (invalid byte near offset " + in.position() + ")"));
        }
    }

    /** A built-in name or a path to a file; a near miss of a built-in name is told which one it missed. */
    public static Preset byNameOrPath(String nameOrPath) {
        if (BUILT_IN.contains(nameOrPath)) return builtIn(nameOrPath);
        Path path = Path.of(nameOrPath);
        if (!Files.exists(path) && !nameOrPath.contains("/") && !nameOrPath.endsWith(".json"))
            throw new PresetException(nameOrPath, "(file)", "is neither a built-in scene nor a file; did you mean \"" + nearest(nameOrPath)
                    + "\"? Built-in: " + String.join(", ", BUILT_IN));
        return load(path);
    }

    /** The JSON text of a built-in preset or a preset file (already loadable: call {@link #byNameOrPath} first). */
    public static String text(String nameOrPath) {
        if (BUILT_IN.contains(nameOrPath)) {
            try (InputStream in = PresetLoader.class.getResourceAsStream("/presets/" + nameOrPath + ".json")) {
                return new String(in.readAllBytes(), StandardCharsets.UTF_8);
            } catch (IOException | NullPointerException e) {
                throw new PresetException(nameOrPath, "(file)", "cannot be read: " + e.getMessage());
            }
        }
        try {
            return utf8(nameOrPath, Files.readAllBytes(Path.of(nameOrPath)));
        } catch (IOException e) {
            throw new PresetException(nameOrPath, "(file)", "cannot be read: " + e.getMessage());
        }
    }

    /** The built-in name with the fewest single-character edits from {@code s}. */
    static String nearest(String s) {
        String best = BUILT_IN.get(0);
        int bestDistance = Integer.MAX_VALUE;
        for (String name : BUILT_IN) {
            int[] prev = new int[name.length() + 1], cur = new int[name.length() + 1];
            for (int j = 0; j <= name.length(); j++) prev[j] = j;
            for (int i = 1; i <= s.length(); i++) {
                cur[0] = i;
                for (int j = 1; j <= name.length(); j++)
                    cur[j] = Math.min(Math.min(cur[j - 1], prev[j]) + 1, prev[j - 1] + (s.charAt(i - 1) == name.charAt(j - 1) ? 0 : 1));
                int[] t = prev; prev = cur; cur = t;
            }
            if (prev[name.length()] < bestDistance) { bestDistance = prev[name.length()]; best = name; }
        }
        return best;
    }

    /** Parses a fabric catalogue ({@code fabrics.json}); {@code file} names it in errors. */
    static List<Fabric> parseCatalogue(String file, String text) {
        Reader reader = new Reader(file, null);
        JsonNode json = JsonFields.readJson(file, text);
        return reader.whole(() -> reader.catalogue(new JsonFields.Node(json, "")));
    }

    /** Parses preset text; {@code file} names it in errors; a mesh file is looked up beside it. */
    public static Preset parse(String file, String text) {
        Path parent = Path.of(file).toAbsolutePath().getParent();
        return parse(file, text, besides(parent == null ? Path.of("").toAbsolutePath() : parent));
    }

    static Preset parse(String file, String text, MeshFiles meshes) {
        Reader reader = new Reader(file, meshes);
        JsonNode json = JsonFields.readJson(file, text);
        return reader.whole(() -> reader.preset(new JsonFields.Node(json, "")));
    }

    private static final class Reader extends JsonFields {
        final MeshFiles meshes;

        Reader(String file, MeshFiles meshes) {
            super(file);
            this.meshes = meshes;
        }


        /** The preset, or null when a part it needs could not be read (its problems are in {@link #found}). */
        Preset preset(Node root) {
            if (root.json.isObject() && root.json.has("fabrics") && !root.json.has("cloth"))
                throw fail("", "is the fabric catalogue, not a scene: name one of its fabrics in a preset's \"fabric\": {\"catalogue\": NAME}, or press F on a fabric scene");
            object(root, Set.of("name", "description", "cloth", "families", "solver", "spheres", "colliders", "selfCollision", "pinMotions", "wind", "fabric", "aerodynamics", "pressure"));
            String name = string(required(root, "name"));
            Node d = optional(root, "description");
            String description = d == null ? "" : string(d);
            // The fabric, the cloth (which needs the fabric to know its mass), the families (optional with a
            // fabric, a whole material, added on top if given) and the solver are read apart, so a problem in one
            // does not hide another's; the rest needs all of them.
            Node fn = optional(root, "fabric");
            Preset.FabricSpec given = fn == null ? null : part(() -> fabric(fn));
            Preset.Cloth cloth = fn != null && given == null ? null : part(() -> cloth(required(root, "cloth"), given));
            // A garment is cut from its panels' fabric unless the preset names another.
            Preset.FabricSpec fabric = given == null && cloth != null && cloth.garment != null ? cloth.garment.fabric : given;
            boolean garment = root.json.path("cloth").has("pattern");
            Node fs = fn == null && !garment ? part(() -> required(root, "families")) : optional(root, "families");
            Map<ConstraintFamily, Material> families = fs == null ? (fn == null && !garment ? null : new EnumMap<>(ConstraintFamily.class)) : part(() -> families(fs));
            SolverSettings solver = part(() -> solver(required(root, "solver")));
            if (cloth == null || families == null || solver == null) return null;
            return part(() -> rest(root, name, description, fabric, cloth, families, solver));
        }

        /** The parts that need the cloth and the solver: the colliders, self-collision, pin motions, wind and aerodynamics. */
        private Preset rest(Node root, String name, String description, Preset.FabricSpec fabric, Preset.Cloth cloth,
                            Map<ConstraintFamily, Material> families, SolverSettings solver) {
            if (fabric != null && fabric.warp == null) {
                if (!cloth.isMesh())
                    throw fail("fabric.warp", "is missing, and a grid cloth has no texture coordinates to take it from: give the warp direction, e.g. [1, 0, 0]");
                if (cloth.mesh.triangleUVs() == null)
                    throw fail("fabric.warp", "is missing, and " + cloth.meshFile + " cannot give it: " + cloth.mesh.whyNoTextureCoordinates() + "; give the warp direction");
            }
            boolean triangles = cloth.isMesh() ? cloth.mesh.faceCount() > 0 : cloth.columns > 1 && cloth.rows > 1;
            String none = "and this cloth has none (" + (cloth.isMesh() ? cloth.meshFile + " has only lines" : "a single row or column of particles") + ")";
            if (fabric != null && !triangles) throw fail("fabric", "is a membrane of triangles, " + none + ": give the cloth two rows and columns, or spring families");
            if (root.json.has("aerodynamics") && !triangles) throw fail("aerodynamics", "acts on triangles, " + none + ": use wind, which acts on particles");
            Preset.PressureSpec pressure = pressure(optional(root, "pressure"), cloth);
            if (fabric != null && !Double.isNaN(fabric.breakingStrain)) {
                if (pressure != null) throw fail("fabric.breakingStrain", "and pressure cannot be given together: a torn cloth no longer holds its gas");
                if (cloth.garment != null) throw fail("fabric.breakingStrain", "cannot tear a garment (its seams are welded as it is sewn): give it to a cloth or a mesh");
                if (cloth.isMesh() && cloth.mesh.segmentCount() > 0) throw fail("fabric.breakingStrain", "tears triangles, and " + cloth.meshFile + " has lines too");
            }
            List<Preset.SphereSpec> spheres = new ArrayList<>();
            Node ss = optional(root, "spheres");
            if (ss != null) for (Node s : array(ss, Limits.MAX_SPHERES)) spheres.add(sphere(s));
            List<Preset.PlaneSpec> planes = new ArrayList<>();
            List<Preset.SolidSpec> solids = new ArrayList<>();
            List<Preset.BodySpec> bodies = new ArrayList<>();
            Node cs = optional(root, "colliders");
            if (cs != null) for (Node c : array(cs, Limits.MAX_SPHERES)) {
                String type = c.json.isObject() && c.json.has("type") ? string(required(c, "type")) : "";
                switch (type) {
                    case "plane": planes.add(plane(c)); break;
                    case "sphere": spheres.add(sphere(c)); break;
                    case "box": case "capsule": solids.add(solid(c, type)); break;
                    case "mesh": bodies.add(body(c)); break;
                    default: throw fail(c.child("type"), (type.isEmpty() ? "is missing" : "was \"" + type + "\"") + "; one of plane, sphere, box, capsule, mesh");
                }
            }
            int colliders = spheres.size() + planes.size() + solids.size() + bodies.size();
            if (colliders > Limits.MAX_SPHERES)
                throw fail("colliders", "at most " + Limits.MAX_SPHERES + " colliders with the spheres, had " + colliders);
            checkThickness(cloth, spheres, planes, solids);
            for (int i = 0; i < bodies.size(); i++) checkThickness(bodies.get(i).margin, cloth.shortestEdge(), "colliders (mesh " + i + ").margin");
            Node sc = optional(root, "selfCollision");
            Preset.SelfCollisionSpec self = sc == null ? null : selfCollision(sc, cloth);
            List<Preset.PinMotion> motions = new ArrayList<>();
            Node ms = optional(root, "pinMotions");
            if (ms != null) for (Node m : array(ms, Limits.MAX_PIN_MOTIONS)) motions.addAll(pinMotions(m, cloth));
            Node w = optional(root, "wind");
            long particles = cloth.mesh != null ? cloth.mesh.vertexCount() : (long) cloth.columns * cloth.rows;
            String tooMuch = Limits.workProblem(particles, solver.iterations(), solver.substeps(), colliders, solver.solver().isGlobal());
            // Judged on the values read, not on a field's stand-in for one out of range.
            if (tooMuch != null && found.isEmpty()) throw fail("solver", tooMuch);
            return new Preset(file, name, description, cloth, families, solver, spheres, planes, solids, bodies, self, motions, w == null ? null : wind(w), fabric, aerodynamics(optional(root, "aerodynamics")), pressure);
        }

        Preset.Cloth cloth(Node n, Preset.FabricSpec fabric) {
            if (n.json.isObject() && n.json.has("mesh")) return meshCloth(n, fabric);
            if (n.json.isObject() && n.json.has("pattern")) return garmentCloth(n, fabric);
            object(n, Set.of("columns", "rows", "width", "height", "plane", "origin", "arealDensity", "totalMass", "pins"));
            int columns = integer(required(n, "columns"), Limits.RESOLUTION);
            int rows = integer(required(n, "rows"), Limits.RESOLUTION);
            if (columns * rows < 2) throw fail(n.child("rows"), "the cloth needs at least 2 particles, columns*rows was " + columns * rows);
            double width = size(required(n, "width"), columns > 1);
            double height = size(required(n, "height"), rows > 1);
            Node pl = optional(n, "plane");
            ClothBuilder.Plane plane = pl == null ? ClothBuilder.Plane.VERTICAL : choice(pl, ClothBuilder.Plane.class);
            Node o = optional(n, "origin");
            double[] origin = o == null ? new double[3] : vector(o, Limits.POSITION);
            double[] mass = mass(n, fabric);
            List<int[]> pins = new ArrayList<>();
            Node ps = optional(n, "pins");
            if (ps != null) {
                // Each particle once, however many entries name it: an edge listed 200 000 times is one edge.
                java.util.LinkedHashSet<Integer> seen = new java.util.LinkedHashSet<>();
                for (Node p : array(ps, Limits.MAX_PIN_ENTRIES))
                    for (int[] rc : pinned(p, columns, rows)) if (seen.add(rc[0] * columns + rc[1])) pins.add(rc);
            }
            return new Preset.Cloth(columns, rows, width, height, plane, origin, mass[0], mass[1], pins);
        }

        /** A cloth from a mesh file: placed by scale, rotation and translation; pinned by index, group or box. */
        Preset.Cloth meshCloth(Node n, Preset.FabricSpec fabric) {
            object(n, Set.of("mesh", "arealDensity", "totalMass", "pins"));
            Node m = required(n, "mesh");
            object(m, Set.of("file", "weld", "scale", "rotation", "translation"));
            Node f = required(m, "file");
            String name = string(f);
            Node w = optional(m, "weld");
            double weld = w == null ? 1e-6 : number(w, Limits.WELD);
            Placement at = placement(m);
            ClothMesh mesh = fromFile(f, name, () -> meshes.load(name, weld));
            if (!Limits.MESH_VERTICES.contains(mesh.vertexCount()))
                throw fail(f.path, name + ": must have " + Limits.MESH_VERTICES.text() + " vertices after welding, had " + mesh.vertexCount());
            mesh = mesh.transformed(at.scale, at.rotation, at.translation);
            for (int i = 0; i < mesh.vertexCount(); i++)
                if (!Limits.POSITION.contains(mesh.x(i)) || !Limits.POSITION.contains(mesh.y(i)) || !Limits.POSITION.contains(mesh.z(i)))
                    throw fail(m.path, "vertex " + i + " lands at (" + mesh.x(i) + ", " + mesh.y(i) + ", " + mesh.z(i) + "), outside " + Limits.POSITION.text() + " m");
            double[] mass = mass(n, fabric);
            if (!Double.isNaN(mass[0]) && mesh.area() == 0)
                throw fail(n.child("arealDensity"), "needs a mesh with faces of non-zero area (" + name + " has none); use totalMass");
            TreeSet<Integer> pinned = new TreeSet<>();
            Node ps = optional(n, "pins");
            if (ps != null) for (Node p : array(ps, Limits.MAX_PIN_ENTRIES)) for (int v : meshPins(p, mesh)) pinned.add(v);
            return new Preset.Cloth(mesh, name, mass[0], mass[1], pinned.stream().mapToInt(Integer::intValue).toArray());
        }

        /**
         * A garment from a pattern (a built-in name or a file beside the preset), meshed at the pattern's edge
         * length or the cloth's own, and how it is sewn. Each panel is its own fabric unless the preset gives one
         * for all.
         */
        Preset.Cloth garmentCloth(Node n, Preset.FabricSpec fabric) {
            object(n, Set.of("pattern", "edge", "sewing", "arealDensity", "totalMass"));
            Node pn = required(n, "pattern");
            String name = string(pn);
            PatternLoader.Loaded loaded;
            try {
                loaded = meshes.pattern(name);
            } catch (PresetException e) {
                throw fail(pn.path, e.getMessage());
            }
            Node e = optional(n, "edge");
            double edge = e == null ? loaded.edge : number(e, Limits.PATTERN_EDGE);
            String tooFine = PatternLoader.edgeProblem(loaded.pattern, edge);
            if (tooFine != null) throw fail(e == null ? pn.path : e.path, name + ": " + tooFine);
            List<xpbdcloth.pattern.Panel> panels = loaded.pattern.panels();
            Fabric[] panelFabrics = new Fabric[panels.size()];
            for (int i = 0; i < panelFabrics.length; i++) panelFabrics[i] = fabric != null ? fabric.fabric : FabricCatalogue.named(panels.get(i).fabric);
            Preset.FabricSpec cut = fabric != null ? fabric : new Preset.FabricSpec(panelFabrics[0], null, false, null, false);
            Node s = optional(n, "sewing");
            double time = 1.5, compliance = 1e-6, seam = 1;
            if (s != null) {
                object(s, Set.of("time", "compliance", "seamBending"));
                Node t = optional(s, "time"), c = optional(s, "compliance"), b = optional(s, "seamBending");
                if (t != null) time = number(t, Limits.SEWING_TIME);
                if (c != null) compliance = number(c, Limits.COMPLIANCE);
                if (b != null) seam = number(b, Limits.SEAM_BENDING);
            }
            double[] mass = mass(n, cut);
            xpbdcloth.pattern.PatternMesh mesh = loaded.mesh(edge);
            String tooCoarse = mesh.seamProblem();
            if (tooCoarse != null)
                throw fail(e == null ? pn.path : e.path, name + ": at an edge of " + String.format(java.util.Locale.ROOT, "%.3g", edge) + " m, " + tooCoarse);
            return new Preset.Cloth(mesh.toClothMesh(), name, mass[0], mass[1], new int[0], new Preset.GarmentSpec(mesh, cut, panelFabrics, time, compliance, seam));
        }

        /**
         * The cloth's (arealDensity, totalMass), one of them NaN: exactly one given, or neither when a
         * catalogue fabric brings its own areal density (then giving one is an error, not a silent choice).
         */
        double[] mass(Node n, Preset.FabricSpec fabric) {
            Node ad = optional(n, "arealDensity"), tm = optional(n, "totalMass");
            double fabricDensity = fabric == null ? Double.NaN : fabric.fabric.arealDensity;
            if (!Double.isNaN(fabricDensity)) {
                Node given = ad != null ? ad : tm;
                if (given != null)
                    throw fail(given.path, "the fabric \"" + fabric.fabric.name + "\" brings its own areal density (" + fabricDensity
                            + " kg/m²): give the cloth's mass or a catalogue fabric, not both");
                return new double[] {fabricDensity, Double.NaN};
            }
            if ((ad == null) == (tm == null)) throw fail(n.path.isEmpty() ? "cloth" : n.path, "needs exactly one of arealDensity (kg/m²) and totalMass (kg)");
            return new double[] {ad == null ? Double.NaN : number(ad, Limits.AREAL_DENSITY), tm == null ? Double.NaN : number(tm, Limits.TOTAL_MASS)};
        }

        /** A vertex index, {"group": name} (an OBJ g/o name) or {"box": {"min": [x,y,z], "max": [x,y,z]}} in scene coordinates. */
        int[] meshPins(Node p, ClothMesh mesh) {
            if (p.json.isNumber()) return new int[] {vertexIndex(p, mesh)};
            if (!p.json.isObject()) throw fail(p.path, "must be a vertex index, {\"group\": name} or {\"box\": {\"min\": [x, y, z], \"max\": [x, y, z]}}, was " + describe(p.json));
            object(p, Set.of("group", "box"));
            if (p.json.size() != 1) throw fail(p.path, "must have exactly one of group, box");
            Node g = optional(p, "group");
            if (g != null) {
                String name = string(g);
                try {
                    return mesh.group(name);
                } catch (IllegalArgumentException e) {
                    throw fail(g.path, e.getMessage().replaceFirst("^group ", ""));
                }
            }
            Node b = required(p, "box");
            object(b, Set.of("min", "max"));
            double[] min = vector(required(b, "min"), Limits.POSITION), max = vector(required(b, "max"), Limits.POSITION);
            for (int d = 0; d < 3; d++)
                if (min[d] > max[d]) throw fail(b.child("max") + "[" + d + "]", "must be >= min[" + d + "] (" + min[d] + "), was " + max[d]);
            int[] in = mesh.inBox(min, max);
            if (in.length == 0) throw fail(b.path, "contains no vertex of the mesh (a pin box that pins nothing is a mistake)");
            return in;
        }

        int vertexIndex(Node p, ClothMesh mesh) {
            int v = integer(p);
            if (v < 0 || v >= mesh.vertexCount()) throw fail(p.path, "must be a vertex index in [0, " + (mesh.vertexCount() - 1) + "], was " + v);
            return v;
        }

        static final String PIN_NAMES = "top-left, top-right, bottom-left, bottom-right, top-edge, bottom-edge, left-edge, right-edge";

        /** The particles a pin stands for: [row, col] or a corner is one particle, an edge all along it. */
        List<int[]> pinned(Node p, int columns, int rows) {
            List<int[]> out = new ArrayList<>();
            if (p.json.isTextual()) {
                switch (p.json.asText()) {
                    case "top-left": out.add(new int[] {0, 0}); break;
                    case "top-right": out.add(new int[] {0, columns - 1}); break;
                    case "bottom-left": out.add(new int[] {rows - 1, 0}); break;
                    case "bottom-right": out.add(new int[] {rows - 1, columns - 1}); break;
                    case "top-edge": for (int c = 0; c < columns; c++) out.add(new int[] {0, c}); break;
                    case "bottom-edge": for (int c = 0; c < columns; c++) out.add(new int[] {rows - 1, c}); break;
                    case "left-edge": for (int r = 0; r < rows; r++) out.add(new int[] {r, 0}); break;
                    case "right-edge": for (int r = 0; r < rows; r++) out.add(new int[] {r, columns - 1}); break;
                    default: throw fail(p.path, "must be [row, col] or one of " + PIN_NAMES + ", was \"" + p.json.asText() + "\"");
                }
                return out;
            }
            if (!p.json.isArray() || p.json.size() != 2) throw fail(p.path, "must be [row, col] or a corner or edge name, was " + describe(p.json));
            Node r = new Node(p.json.get(0), p.path + "[0]"), c = new Node(p.json.get(1), p.path + "[1]");
            int row = integer(r), col = integer(c);
            if (row < 0 || row >= rows || col < 0 || col >= columns)
                throw fail(p.path, "pin [" + row + ", " + col + "] is outside the " + rows + "x" + columns + " grid (rows x columns)");
            out.add(new int[] {row, col});
            return out;
        }

        /**
         * A fabric by catalogue name ({@code fabrics.json}) or by its own moduli per unit width (N/m), ν₁₂
         * with its positive-definite bound, B (N·m); and the warp direction and tethers either way.
         */
        Preset.FabricSpec fabric(Node n) {
            List<String> moduli = List.of("name", "warpModulus", "weftModulus", "poisson", "shearModulus", "bendingStiffness");
            Set<String> allowed = new java.util.HashSet<>(moduli);
            allowed.addAll(Set.of("catalogue", "warp", "tethers", "plasticity", "stiffening", "breakingStrain"));
            object(n, allowed);
            Node cat = optional(n, "catalogue");
            Fabric material;
            if (cat != null) {
                String wanted = string(cat);
                for (String f : moduli)
                    if (optional(n, f) != null)
                        throw fail(n.child(f), "comes with the catalogue fabric \"" + wanted + "\": give a catalogue fabric or your own moduli, not both");
                material = FabricCatalogue.named(wanted);
                if (material == null)
                    throw fail(cat.path, "no fabric \"" + wanted + "\" in " + FabricCatalogue.FILE + "; one of " + String.join(", ", FabricCatalogue.names()));
            } else {
                Node nm = optional(n, "name");
                double e1 = number(required(n, "warpModulus"), Limits.MODULUS), e2 = number(required(n, "weftModulus"), Limits.MODULUS);
                Node nu = required(n, "poisson");
                double poisson = number(nu, Limits.POISSON);
                double g = number(required(n, "shearModulus"), Limits.MODULUS);
                OrthotropicMaterial membrane;
                try {
                    membrane = new OrthotropicMaterial(e1, e2, poisson, g);
                } catch (IllegalArgumentException e) {
                    throw fail(nu.path, e.getMessage());
                }
                material = new Fabric(nm == null ? "" : string(nm), "", "", Double.NaN, membrane, number(required(n, "bendingStiffness"), Limits.BENDING_STIFFNESS));
            }
            // Without a warp direction, the mesh's texture coordinates give it (checked with the cloth).
            Node wd = optional(n, "warp");
            double[] warp = wd == null ? null : vector(wd, Limits.NORMAL);
            if (warp != null && Math.sqrt(warp[0] * warp[0] + warp[1] * warp[1] + warp[2] * warp[2]) < 1e-3)
                throw fail(wd.path, "must be a direction (length at least 1e-3), was " + java.util.Arrays.toString(warp));
            Node t = optional(n, "tethers"), pl = optional(n, "plasticity");
            Preset.PlasticitySpec plasticity = null;
            if (pl != null) {
                object(pl, Set.of("yieldCurvature", "rate"));
                plasticity = new Preset.PlasticitySpec(number(required(pl, "yieldCurvature"), Limits.YIELD_CURVATURE), number(required(pl, "rate"), Limits.PLASTIC_RATE));
            }
            Node st = optional(n, "stiffening");
            boolean stiffening = st != null && bool(st);
            if (stiffening && material.stretchingCurve == null)
                throw fail(st.path, "needs a measured stretching curve: a catalogue fabric, not moduli of your own (they are a linear membrane)");
            Node bs = optional(n, "breakingStrain");
            double breaking = bs == null ? Double.NaN : number(bs, Limits.BREAKING_STRAIN);
            // A tear rebuilds the cloth from its rest shape, and a yielded crease is a rest shape of its own.
            if (bs != null && plasticity != null)
                throw fail(bs.path, "and plasticity cannot be given together: a tear rebuilds the cloth from its rest shape, which would lose the creases");
            return new Preset.FabricSpec(material, warp, t != null && bool(t), plasticity, stiffening, breaking);
        }

        /** The fabric catalogue: a source for all, and per fabric its data-driven sample (see {@link DataDrivenSample}). */
        List<Fabric> catalogue(Node root) {
            object(root, Set.of("description", "source", "fabrics"));
            String source = string(required(root, "source"));
            List<Fabric> out = new ArrayList<>();
            Set<String> names = new java.util.HashSet<>();
            for (Node f : array(required(root, "fabrics"), 1000)) {
                object(f, Set.of("name", "description", "sample", "arealDensity", "stretching", "bending", "stretchingCurve", "bendingCurve"));
                Node nm = required(f, "name");
                String name = string(nm);
                if (!names.add(name)) throw fail(nm.path, "\"" + name + "\" is listed twice");
                double density = number(required(f, "arealDensity"), Limits.AREAL_DENSITY);
                Node st = required(f, "stretching"), bd = required(f, "bending");
                double[] stretching = numbers(st, 4, Limits.MODULUS.hi), bending = numbers(bd, 3, Limits.BENDING_STIFFNESS.hi);
                Node d = optional(f, "description"), sc = optional(f, "stretchingCurve"), bc = optional(f, "bendingCurve");
                String sample = string(required(f, "sample"));
                double[][] curve = null;
                if (sc != null) {
                    if (!sc.json.isArray() || sc.json.size() != 5) throw fail(sc.path, "must be 5 samples (0°, 22.5°, 45°, 67.5°, 90°) of 4 numbers, was " + describe(sc.json));
                    curve = new double[5][];
                    for (int j = 0; j < 5; j++) curve[j] = numbers(new Node(sc.json.get(j), sc.path + "[" + j + "]"), 4, Limits.MODULUS.hi);
                }
                double[][] bendingCurve = null;
                if (bc != null) {
                    if (!bc.json.isArray() || bc.json.size() != 3) throw fail(bc.path, "must be 3 rows (0°, 45°, 90°) of 4 numbers (α = 5, 10, 15, 20 /m), was " + describe(bc.json));
                    bendingCurve = new double[3][];
                    for (int j = 0; j < 3; j++) {
                        bendingCurve[j] = numbers(new Node(bc.json.get(j), bc.path + "[" + j + "]"), 4, Limits.BENDING_STIFFNESS.hi);
                        for (int i = 0; i < 4; i++)
                            if (bendingCurve[j][i] < 0) throw fail(bc.path + "[" + j + "][" + i + "]", "must not be negative, was " + bendingCurve[j][i]);
                    }
                }
                try {
                    out.add(DataDrivenSample.fabric(name, d == null ? "" : string(d), source + ", sample \"" + sample + "\"", density, stretching, bending, curve, bendingCurve));
                } catch (IllegalArgumentException e) {
                    throw fail(st.path, e.getMessage());
                }
            }
            return out;
        }

        /** A JSON array of exactly {@code count} finite numbers, each of magnitude below {@code limit}. */
        double[] numbers(Node n, int count, double limit) {
            if (!n.json.isArray() || n.json.size() != count) throw fail(n.path, "must be an array of " + count + " numbers, was " + describe(n.json));
            double[] out = new double[count];
            for (int k = 0; k < count; k++) {
                JsonNode j = n.json.get(k);
                if (!j.isNumber() || !(Math.abs(j.asDouble()) < limit)) throw fail(n.path + "[" + k + "]", "must be a number of magnitude below " + limit + ", was " + describe(j));
                out[k] = j.asDouble();
            }
            return out;
        }

        /** Quadratic drag and lift: density (kg/m³), coefficients, the air's velocity (m/s); null when absent. */
        Preset.AerodynamicsSpec aerodynamics(Node n) {
            if (n == null) return null;
            object(n, Set.of("density", "drag", "lift", "air"));
            Node d = optional(n, "density");
            return new Preset.AerodynamicsSpec(d == null ? xpbdcloth.engine.Aerodynamics.AIR_DENSITY : number(d, Limits.AIR_DENSITY),
                    number(required(n, "drag"), Limits.AERO_COEFFICIENT), number(required(n, "lift"), Limits.AERO_COEFFICIENT),
                    vector(required(n, "air"), Limits.SPEED));
        }

        /**
         * What fills a closed cloth: {@code gauge} (Pa over the air at the rest shape), {@code moles} (with an optional
         * {@code temperature}, K, default 293.15) or {@code volumeRatio}, exactly one; {@code ambient} (Pa, default
         * 101325) outside a gas. Null when absent. The cloth must be a closed mesh.
         */
        Preset.PressureSpec pressure(Node n, Preset.Cloth cloth) {
            if (n == null) return null;
            object(n, Set.of("gauge", "moles", "temperature", "volumeRatio", "ambient"));
            if (!cloth.isMesh())
                throw fail(n.path, "needs a closed surface, and a grid cloth has a boundary: give cloth.mesh a closed OBJ (data/pillow.obj, data/balloon.obj)");
            String open = xpbdcloth.engine.EnclosedGas.openEdge(cloth.mesh.triangles());
            if (open != null) throw fail(n.path, "needs a closed surface, and " + cloth.meshFile + " is not one: " + open);
            Node g = optional(n, "gauge"), m = optional(n, "moles"), v = optional(n, "volumeRatio"), t = optional(n, "temperature"), a = optional(n, "ambient");
            int given = (g == null ? 0 : 1) + (m == null ? 0 : 1) + (v == null ? 0 : 1);
            if (given != 1)
                throw fail(n.path, "needs exactly one of gauge (Pa over the air outside), moles (the gas's amount) and volumeRatio (a held volume), had " + given);
            if (t != null && m == null) throw fail(t.path, "goes with moles (a gas given by its amount)");
            if (a != null && v != null) throw fail(a.path, "goes with a gas (gauge or moles), not a held volume");
            double ambient = a == null ? 101325 : number(a, Limits.AMBIENT_PRESSURE);
            double gauge = g == null ? Double.NaN : number(g, Limits.GAUGE_PRESSURE);
            if (g != null && !(ambient + gauge > 0))
                throw fail(g.path, "must leave the gas a pressure above 0 (gauge > −ambient, " + -ambient + " Pa), was " + gauge);
            return new Preset.PressureSpec(gauge, m == null ? Double.NaN : number(m, Limits.MOLES), t == null ? 293.15 : number(t, Limits.TEMPERATURE),
                    v == null ? Double.NaN : number(v, Limits.VOLUME_RATIO), v == null ? ambient : 0);
        }

        Map<ConstraintFamily, Material> families(Node n) {
            object(n, Set.of("structural", "shear", "bend"));
            Map<ConstraintFamily, Material> out = new EnumMap<>(ConstraintFamily.class);
            out.put(ConstraintFamily.STRUCTURAL, material(required(n, "structural")));
            Node s = optional(n, "shear");
            if (s != null) out.put(ConstraintFamily.SHEAR, material(s));
            Node b = optional(n, "bend");
            if (b != null) out.put(ConstraintFamily.BEND, material(b));
            return out;
        }

        Material material(Node n) {
            object(n, Set.of("stiffness", "compliance"));
            return new Material(number(required(n, "stiffness"), Limits.STIFFNESS), number(required(n, "compliance"), Limits.COMPLIANCE));
        }

        SolverSettings solver(Node n) {
            object(n, Set.of("mode", "iterations", "substeps", "dt", "mullerCorrection", "gravity", "damping", "type"));
            ConstraintMode mode = choice(required(n, "mode"), ConstraintMode.class);
            int iterations = integer(required(n, "iterations"), Limits.ITERATIONS);
            Node s = optional(n, "substeps");
            int substeps = s == null ? 1 : integer(s, Limits.SUBSTEPS);
            double dt = number(required(n, "dt"), Limits.DT);
            Node m = optional(n, "mullerCorrection");
            boolean muller = m == null || bool(m);
            Node g = optional(n, "gravity");
            double[] gravity = g == null ? new double[] {0, -9.81, 0} : vector(g, Limits.GRAVITY);
            Node d = optional(n, "damping");
            double damping = d == null ? 0 : number(d, Limits.DAMPING);
            Node t = optional(n, "type");
            xpbdcloth.engine.SolverType type = t == null ? xpbdcloth.engine.SolverType.GAUSS_SEIDEL : solverType(t);
            if (mode == ConstraintMode.PBD && type != xpbdcloth.engine.SolverType.GAUSS_SEIDEL)
                throw fail(t.path, "must be gauss-seidel in PBD mode (a global solve needs XPBD's compliance), was \"" + type.label() + "\"");
            return new SolverSettings().withModeAndSolver(mode, type).withIterations(iterations).withSubsteps(substeps).withTimestep(dt)
                    .withMullerCorrection(muller).withGravity(gravity[0], gravity[1], gravity[2]).withDamping(damping);
        }

        /** "gauss-seidel", "jacobi-pcg" or "multigrid-pcg". */
        xpbdcloth.engine.SolverType solverType(Node n) {
            String s = string(n);
            for (xpbdcloth.engine.SolverType t : xpbdcloth.engine.SolverType.values())
                if (t.name().replace('_', '-').equalsIgnoreCase(s)) return t;
            throw fail(n.path, "must be one of gauss-seidel, jacobi-pcg, multigrid-pcg, was \"" + s + "\"");
        }

        /** A collider of the "colliders" list: so far a plane (spheres are listed under "spheres"). */
        Preset.PlaneSpec plane(Node n) {
            object(n, Set.of("type", "point", "normal", "margin", "staticFriction", "kineticFriction", "depenetrationSpeed"));
            double[] point = vector(required(n, "point"), Limits.POSITION);
            double[] normal = direction(required(n, "normal"));
            return new Preset.PlaneSpec(point, normal, margin(n), number(required(n, "staticFriction"), Limits.FRICTION),
                    number(required(n, "kineticFriction"), Limits.FRICTION), depenetrationSpeed(n));
        }

        /** The cloth's thickness against itself: no more than its shortest edge at rest. */
        Preset.SelfCollisionSpec selfCollision(Node n, Preset.Cloth cloth) {
            object(n, Set.of("thickness", "staticFriction", "kineticFriction", "continuous", "untangle", "pointTriangle"));
            Node t = required(n, "thickness");
            double thickness = number(t, Limits.THICKNESS);
            double edge = cloth.shortestEdge();
            if (thickness > edge)
                throw fail(t.path, String.format(java.util.Locale.ROOT, "must be at most the cloth's shortest edge %.4g m, was %.4g m: thicker, neighbouring"
                        + " particles that are not neighbours at rest would hold the cloth apart from itself in steps", edge, thickness));
            Node continuous = optional(n, "continuous"), untangle = optional(n, "untangle"), pointTriangle = optional(n, "pointTriangle");
            return new Preset.SelfCollisionSpec(thickness, number(required(n, "staticFriction"), Limits.FRICTION), number(required(n, "kineticFriction"), Limits.FRICTION),
                    continuous != null && bool(continuous), untangle != null && bool(untangle), pointTriangle != null && bool(pointTriangle));
        }

        double margin(Node n) {
            Node m = optional(n, "margin");
            return m == null ? 0 : number(m, Limits.MARGIN);
        }

        /** The fastest a collider pushes out a particle found deep inside it (m/s); PhysX's maximum depenetration velocity. */
        double depenetrationSpeed(Node n) {
            Node d = optional(n, "depenetrationSpeed");
            return d == null ? xpbdcloth.engine.Collider.MAX_DEPENETRATION_SPEED : number(d, Limits.DEPENETRATION_SPEED);
        }

        /** A box (half extents, rotation) or a capsule (axis, half length, radius), with path, spin and friction. */
        Preset.SolidSpec solid(Node n, String type) {
            boolean box = type.equals("box");
            Set<String> allowed = new java.util.HashSet<>(Set.of("type", "margin", "staticFriction", "kineticFriction", "angularVelocity", "path", "depenetrationSpeed"));
            allowed.addAll(box ? Set.of("halfExtents", "rotation") : Set.of("axis", "halfLength", "radius"));
            object(n, allowed);
            double mus = number(required(n, "staticFriction"), Limits.FRICTION);
            double muk = number(required(n, "kineticFriction"), Limits.FRICTION);
            Node w = optional(n, "angularVelocity");
            double[] omega = w == null ? new double[3] : vector(w, Limits.ANGULAR_VELOCITY);
            Preset.PathSpec path = path(required(n, "path"));
            if (box) {
                double[] half = vector(required(n, "halfExtents"), Limits.SPHERE_RADIUS);
                Node r = optional(n, "rotation");
                return new Preset.SolidSpec(type, half, r == null ? new double[3] : vector(r, Limits.ROTATION), null, 0, 0, margin(n), mus, muk, omega, path, depenetrationSpeed(n));
            }
            return new Preset.SolidSpec(type, null, null, direction(required(n, "axis")), number(required(n, "halfLength"), Limits.PATH_RADIUS),
                    number(required(n, "radius"), Limits.SPHERE_RADIUS), margin(n), mus, muk, omega, path, depenetrationSpeed(n));
        }

        /** Where a mesh file is put in the scene: a uniform scale, then rotations about x, y, z (degrees), then a move. */
        final class Placement {
            final double scale;
            final double[] rotation, translation;

            Placement(double scale, double[] rotation, double[] translation) { this.scale = scale; this.rotation = rotation; this.translation = translation; }
        }

        /** The placement fields of n ("scale", "rotation", "translation"), each optional. */
        Placement placement(Node n) {
            Node sc = optional(n, "scale"), r = optional(n, "rotation"), t = optional(n, "translation");
            return new Placement(sc == null ? 1 : number(sc, Limits.MESH_SCALE), r == null ? new double[3] : vector(r, Limits.ROTATION),
                    t == null ? new double[3] : vector(t, Limits.POSITION));
        }

        /** What {@code read} makes of the file a field names, its problems reported at that field. */
        <T> T fromFile(Node field, String name, java.util.function.Supplier<T> read) {
            try {
                return read.get();
            } catch (MeshFileException e) {
                throw fail(field.path, e.getMessage());
            } catch (IllegalArgumentException e) {
                throw fail(field.path, name + ": " + e.getMessage());
            }
        }

        /**
         * A triangle mesh to collide with, from a file (OBJ, USD text, or a folder of OBJ frames), placed by
         * scale, rotation and translation; still, animated by its frames (fps, start, loop), and moved rigidly by a
         * path and spin about the path's start (default: fixed at the origin, the mesh where its file puts it).
         */
        Preset.BodySpec body(Node n) {
            object(n, Set.of("type", "file", "fps", "start", "loop", "scale", "rotation", "translation", "margin", "staticFriction", "kineticFriction", "angularVelocity", "path",
                    "depenetrationSpeed"));
            Node f = required(n, "file");
            String name = string(f);
            Node fp = optional(n, "fps"), sp = optional(n, "start"), lp = optional(n, "loop");
            double fps = fp == null ? Double.NaN : number(fp, Limits.FRAME_RATE);
            double start = sp == null ? 0 : number(sp, Limits.START_TIME);
            boolean loop = lp != null && bool(lp);
            Placement at = placement(n);
            double mus = number(required(n, "staticFriction"), Limits.FRICTION);
            double muk = number(required(n, "kineticFriction"), Limits.FRICTION);
            Node w = optional(n, "angularVelocity");
            double[] omega = w == null ? new double[3] : vector(w, Limits.ANGULAR_VELOCITY);
            Node pn = optional(n, "path");
            Preset.PathSpec path = pn == null ? new Preset.PathSpec("fixed", new double[3], new double[3], 0, 0) : path(pn);
            BodyMesh body = fromFile(f, name, () -> meshes.body(name, fps));
            if (body.animated() && fp != null) body = body.at(fps);
            if (!body.animated() && fp != null) throw fail(fp.path, "is the rate of an animated body's frames; " + name + " is still (one shape)");
            if (!body.animated() && lp != null) throw fail(lp.path, "loops an animated body's frames; " + name + " is still (one shape)");
            if (!body.animated() && sp != null) throw fail(sp.path, "starts an animated body's frames; " + name + " is still (one shape)");
            body = body.transformed(at.scale, at.rotation, at.translation);
            double[][] shapes = body.animated() ? body.frames : new double[][] {body.vertices};
            for (int k = 0; k < shapes.length; k++)
                for (int i = 0; i < shapes[k].length; i++)
                    if (!Limits.POSITION.contains(shapes[k][i]))
                        throw fail(n.path, "vertex " + i / 3 + (body.animated() ? " of frame " + k : "") + " lands at " + shapes[k][i] + " on axis " + "xyz".charAt(i % 3) + ", outside " + Limits.POSITION.text() + " m");
            return new Preset.BodySpec(name, body, start, loop, margin(n), mus, muk, omega, path, depenetrationSpeed(n));
        }

        /**
         * The cloth's thickness is twice a collider's margin; thicker than the cloth's shortest edge, contacts
         * would hold particles farther apart than the cloth's own spacing, and a draped cloth would stand off
         * its collider in steps.
         */
        void checkThickness(Preset.Cloth cloth, List<Preset.SphereSpec> spheres, List<Preset.PlaneSpec> planes, List<Preset.SolidSpec> solids) {
            double edge = cloth.shortestEdge();
            for (int i = 0; i < spheres.size(); i++) checkThickness(spheres.get(i).margin, edge, "spheres[" + i + "].margin");
            for (int i = 0; i < planes.size(); i++) checkThickness(planes.get(i).margin, edge, "colliders (plane " + i + ").margin");
            for (int i = 0; i < solids.size(); i++) checkThickness(solids.get(i).margin, edge, "colliders (" + solids.get(i).type + " " + i + ").margin");
        }

        void checkThickness(double margin, double edge, String field) {
            if (2 * margin > edge)
                throw fail(field, String.format(java.util.Locale.ROOT, "makes the cloth %.4g m thick (twice the margin), more than its shortest edge %.4g m:"
                        + " contacts would hold the particles farther apart than the cloth's own spacing", 2 * margin, edge));
        }

        Preset.SphereSpec sphere(Node n) {
            object(n, Set.of("type", "radius", "margin", "staticFriction", "kineticFriction", "angularVelocity", "path", "depenetrationSpeed"));
            double radius = number(required(n, "radius"), Limits.SPHERE_RADIUS);
            double mus = number(required(n, "staticFriction"), Limits.FRICTION);
            double muk = number(required(n, "kineticFriction"), Limits.FRICTION);
            Node w = optional(n, "angularVelocity");
            double[] omega = w == null ? new double[3] : vector(w, Limits.ANGULAR_VELOCITY);
            Preset.PathSpec p = path(required(n, "path"));
            return new Preset.SphereSpec(radius, margin(n), mus, muk, omega, p.type, p.centre, p.vector, p.radius, p.rate, depenetrationSpeed(n));
        }

        /** A collider's path: fixed, linear, circle or oscillation. */
        Preset.PathSpec path(Node p) {
            object(p, Set.of("type", "centre", "start", "velocity", "radius", "angularSpeed", "amplitude", "frequency"));
            Node typeNode = p.json.has("type") ? required(p, "type") : null;
            if (typeNode == null) throw fail(p.child("type"), "is missing; one of fixed, linear, circle, oscillation");
            String type = string(typeNode);
            switch (type) {
                case "fixed":
                    only(p, Set.of("type", "centre"));
                    return new Preset.PathSpec(type, vector(required(p, "centre"), Limits.POSITION), new double[3], 0, 0);
                case "linear":
                    only(p, Set.of("type", "start", "velocity"));
                    return new Preset.PathSpec(type, vector(required(p, "start"), Limits.POSITION), vector(required(p, "velocity"), Limits.SPEED), 0, 0);
                case "circle":
                    only(p, Set.of("type", "centre", "radius", "angularSpeed"));
                    return new Preset.PathSpec(type, vector(required(p, "centre"), Limits.POSITION), new double[3],
                            number(required(p, "radius"), Limits.PATH_RADIUS), number(required(p, "angularSpeed"), Limits.ANGULAR_SPEED));
                case "oscillation":
                    only(p, Set.of("type", "centre", "amplitude", "frequency"));
                    return new Preset.PathSpec(type, vector(required(p, "centre"), Limits.POSITION), vector(required(p, "amplitude"), Limits.DISPLACEMENT),
                            0, number(required(p, "frequency"), Limits.FREQUENCY));
                default:
                    throw fail(p.child("type"), "must be one of fixed, linear, circle, oscillation, was \"" + type + "\"");
            }
        }

        /**
         * A pin motion: a displacement, a turn ({@code "rotation": {"axis", "centre", "turns"}}), or both, of one
         * pinned particle, or of every particle of a grid's named edge (each must be pinned).
         */
        List<Preset.PinMotion> pinMotions(Node n, Preset.Cloth cloth) {
            object(n, Set.of("pin", "displacement", "rotation", "start", "duration"));
            Node pn = required(n, "pin");
            List<Integer> vertices = new ArrayList<>();
            if (cloth.isMesh()) {
                int vertex = vertexIndex(pn, cloth.mesh);
                if (Arrays.binarySearch(cloth.pinnedVertices, vertex) < 0) throw fail(pn.path, "vertex " + vertex + " must also be pinned by cloth.pins");
                vertices.add(vertex);
            } else {
                for (int[] pin : pinned(pn, cloth.columns, cloth.rows)) {
                    boolean pinned = false;
                    for (int[] p : cloth.pins) pinned |= p[0] == pin[0] && p[1] == pin[1];
                    if (!pinned) throw fail(n.child("pin"), "particle [" + pin[0] + ", " + pin[1] + "] must also be listed in cloth.pins");
                    vertices.add(cloth.vertex(pin[0], pin[1]));
                }
            }
            Node s = optional(n, "start"), dn = optional(n, "displacement"), rn = optional(n, "rotation");
            if (dn == null && rn == null) throw fail(n.path, "must give a displacement, a rotation or both");
            double[] displacement = dn == null ? new double[3] : vector(dn, Limits.DISPLACEMENT), axis = null, centre = null;
            double angle = 0;
            if (rn != null) {
                object(rn, Set.of("axis", "centre", "turns"));
                Node an = required(rn, "axis");
                axis = vector(an, Limits.NORMAL);
                double length = Math.sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
                if (length < 1e-3) throw fail(an.path, "must be a direction (length at least 1e-3), was " + Arrays.toString(axis));
                for (int k = 0; k < 3; k++) axis[k] /= length;
                centre = vector(required(rn, "centre"), Limits.POSITION);
                angle = 2 * Math.PI * number(required(rn, "turns"), Limits.TURNS);
            }
            double start = s == null ? 0 : number(s, Limits.START_TIME), duration = number(required(n, "duration"), Limits.DURATION);
            List<Preset.PinMotion> out = new ArrayList<>();
            for (int v : vertices) out.add(new Preset.PinMotion(v, displacement, start, duration, axis, centre, angle));
            return out;
        }

        Preset.WindSpec wind(Node n) {
            object(n, Set.of("velocity", "drag", "gust"));
            Node g = optional(n, "gust");
            return new Preset.WindSpec(vector(required(n, "velocity"), Limits.WIND_SPEED), number(required(n, "drag"), Limits.DRAG), g == null ? 0 : number(g, Limits.GUST));
        }

        /** Width or height: 0 along a single particle, else in {@link Limits#SIZE}. */
        double size(Node n, boolean spans) {
            if (spans) return number(n, Limits.SIZE);
            if (!n.json.isNumber() || n.json.asDouble() != 0 && !Limits.SIZE.contains(n.json.asDouble()))
                throw fail(n.path, "must be 0 or in " + Limits.SIZE.text() + " m, was " + n.json.asText());
            return n.json.asDouble();
        }
    }
}
