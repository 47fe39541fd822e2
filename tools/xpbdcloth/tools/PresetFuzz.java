package xpbdcloth.tools;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import xpbdcloth.engine.Metrics;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SimulationDivergedException;
import xpbdcloth.scene.Limits;
import xpbdcloth.scene.PresetException;
import xpbdcloth.scene.PresetLoader;
import xpbdcloth.scene.Scene;

/**
 * Random preset files: every numeric field drawn across its {@link Limits} range, an edge of the range
 * one time in four, the whole scene loaded and stepped; it must stay finite. One case in five also puts
 * one field just outside its range, and the loader must refuse it naming that field and the range.
 *
 * <p>Every field the loader accepts is drawn (a test holds the fuzzer to the loader's own list of fields):
 * grids and the shipped meshes (placed, welded, pinned by index, group or box; the closed pillow and balloon
 * filled by a pressure block: a gas by its gauge or its amount, in air or a vacuum, or a held volume; the skirt's,
 * the T-shirt's or the two-fabric tablecloth's pattern sewn as a garment at a coarse edge, its sewing drawn), spring
 * families or a fabric (its moduli or a catalogue name, warp, tethers, plasticity, a catalogue fabric's
 * stiffening, a breaking strain), every solver, spheres and colliders of every kind, pin motions (moves and turns), wind,
 * aerodynamics and self-collision.
 *
 * <p>What is not drawn jointly: a case's work (particles × iterations × substeps × steps) is held under
 * a budget so a case costs a fraction of a second, so the largest cloths run with few sweeps and the
 * most sweeps run on small cloths; global solvers are drawn on cloths up to 32 × 32. A mesh's weld
 * tolerance is drawn up to 1 mm (a larger one merges the shipped meshes' vertices into faces of nothing,
 * which the loader refuses, rightly); a fabric on a mesh turns it about the warp's axis only (a warp
 * normal to a triangle is refused).
 */
final class PresetFuzz {
    private PresetFuzz() {}

    /** Particle-sweeps a case may cost over all its steps (a global iteration counts 100 sweeps). */
    static final double WORK_BUDGET = 3e6;

    /** The shipped meshes a case may use: file, particles, shortest rest edge (m), a vertex group (or null). */
    static final Object[][] MESHES = {{"flag-with-hole.obj", "hoist"}, {"round-tablecloth.obj", "hem"}};
    /** The shipped closed meshes, which a "pressure" block fills: file, a vertex group (or null). */
    static final Object[][] CLOSED = {{"pillow.obj", "seam"}, {"balloon.obj", null}};
    private static double[] meshFacts; // per mesh (MESHES, then CLOSED): particles, shortest edge

    /** Particles and shortest edge of each shipped mesh, read once from the jar. */
    static synchronized double[] meshFacts() {
        if (meshFacts != null) return meshFacts;
        double[] out = new double[2 * (MESHES.length + CLOSED.length)];
        for (int m = 0; m < MESHES.length + CLOSED.length; m++) {
            Object file = m < MESHES.length ? MESHES[m][0] : CLOSED[m - MESHES.length][0];
            String text = "{\"name\": \"m\", \"cloth\": {\"mesh\": {\"file\": \"" + file + "\"}, \"arealDensity\": 0.2, \"pins\": [0]},"
                    + " \"families\": {\"structural\": {\"stiffness\": 1, \"compliance\": 0}}, \"solver\": {\"mode\": \"XPBD\", \"iterations\": 1, \"substeps\": 1, \"dt\": 0.02, \"mullerCorrection\": true, \"gravity\": [0, -9.81, 0]}}";
            xpbdcloth.mesh.ClothMesh mesh = Scene.of(PresetLoader.parse("fuzz.json", text)).cloth().mesh();
            double shortest = Double.MAX_VALUE;
            for (int k = 0; k < mesh.faceCount(); k++) {
                int[] f = mesh.face(k);
                for (int j = 0; j < f.length; j++) shortest = Math.min(shortest, mesh.distance(f[j], f[(j + 1) % f.length]));
            }
            out[2 * m] = mesh.vertexCount();
            out[2 * m + 1] = shortest;
        }
        return meshFacts = out;
    }

    /** The stream of a seed's latest fields (the untangling, the point–triangle contacts), apart from its others. */
    static Random latest(long seed) { return new Random(Long.rotateLeft(seed, 17) ^ 0x2545F4914F6CDD1DL); }

    /** The preset a seed draws (its text only, nothing run). */
    static String text(long seed) {
        return new Case(new Random(seed), new Random(~seed), latest(seed)).json();
    }

    /** One case: null if it passed, else why not. */
    static String runCase(long seed) {
        Random r = new Random(seed);
        Case c = new Case(r, new Random(~seed), latest(seed));
        String text = c.json();
        if (c.brokenField != null) {
            try {
                PresetLoader.parse("fuzz.json", text);
                return "preset seed " + seed + ": " + c.brokenField + " outside its range was accepted";
            } catch (PresetException e) {
                if (!e.field().equals(c.brokenField) || !e.problem().contains(c.brokenRange))
                    return "preset seed " + seed + ": expected " + c.brokenField + " " + c.brokenRange + ", got " + e.getMessage();
                return null;
            }
        }
        try {
            // Stepped as a scene: a cloth that tears goes on torn.
            Scene scene = Scene.of(PresetLoader.parse("fuzz.json", text));
            for (int s = 0; s < c.steps; s++) scene = scene.step();
            return Metrics.allFinite(scene.simulation().particles()) ? null : "preset seed " + seed + ": non-finite";
        } catch (SimulationDivergedException e) {
            return "preset seed " + seed + ": diverged: " + e.getMessage() + "\n" + text;
        } catch (RuntimeException | Error e) {
            return "preset seed " + seed + ": " + e + "\n" + text;
        }
    }

    /** A drawn preset. Fields are written in the order the README documents them. */
    private static final class Case {
        final Random r;
        final List<String[]> numbers = new ArrayList<>(); // {path, value}
        String brokenField, brokenRange;
        int steps;
        final StringBuilder json = new StringBuilder();

        /** Draws of fields added later, apart, so that a seed's other draws stay what they were. */
        final Random later;

        /** Draws of fields added after {@code later}'s, from a stream of their own for the same reason. */
        final Random latest;

        Case(Random r, Random later, Random latest) { this.r = r; this.later = later; this.latest = latest; }

        /** A collider's depenetration speed, in one collider of two (else the engine's default). */
        String depenetration() {
            if (later.nextBoolean()) return "";
            Limits.Range d = Limits.DEPENETRATION_SPEED;
            double v = later.nextInt(4) == 0 ? (later.nextBoolean() ? d.lo : d.hi) : Math.exp(Math.log(d.lo) + later.nextDouble() * Math.log(d.hi / d.lo));
            return ", \"depenetrationSpeed\": " + num(v);
        }

        /**
         * Self-collision's continuous triangle guard, said in one case of two (on in one of those two); and its
         * untangling and its point–triangle contacts, said likewise from a stream of their own.
         */
        String continuous() {
            String untangle = latest.nextBoolean() ? "" : ", \"untangle\": " + latest.nextBoolean();
            untangle += latest.nextBoolean() ? "" : ", \"pointTriangle\": " + latest.nextBoolean();
            if (later.nextBoolean()) return untangle;
            return ", \"continuous\": " + later.nextBoolean() + untangle;
        }

        /** Uniform in the range, or one of its edges one time in four; log-uniform for positive ranges. */
        double draw(Limits.Range range, boolean log) {
            if (r.nextInt(4) == 0) return r.nextBoolean() ? range.lo : range.hi;
            if (log && range.lo > 0) return Math.exp(Math.log(range.lo) + r.nextDouble() * (Math.log(range.hi) - Math.log(range.lo)));
            return range.lo + r.nextDouble() * (range.hi - range.lo);
        }

        /** As {@link #draw} on a log scale, from another stream. */
        static double logUniform(Random own, Limits.Range range) {
            if (own.nextInt(4) == 0) return own.nextBoolean() ? range.lo : range.hi;
            return Fuzz.logUniform(own, range.lo, range.hi);
        }

        String num(double v) { return Double.toString(v); }

        /** A collider's path: fixed, linear, circle or oscillation. */
        String path() {
            switch (r.nextInt(4)) {
                case 0: return "{ \"type\": \"fixed\", \"centre\": " + vec(Limits.POSITION) + " }";
                case 1: return "{ \"type\": \"linear\", \"start\": " + vec(Limits.POSITION) + ", \"velocity\": " + vec(Limits.SPEED) + " }";
                case 2: return "{ \"type\": \"circle\", \"centre\": " + vec(Limits.POSITION) + ", \"radius\": " + num(draw(Limits.PATH_RADIUS, false))
                        + ", \"angularSpeed\": " + num(draw(Limits.ANGULAR_SPEED, false)) + " }";
                default: return "{ \"type\": \"oscillation\", \"centre\": " + vec(Limits.POSITION) + ", \"amplitude\": " + vec(Limits.DISPLACEMENT)
                        + ", \"frequency\": " + num(draw(Limits.FREQUENCY, false)) + " }";
            }
        }

        String vec(Limits.Range range) { return "[" + num(draw(range, false)) + ", " + num(draw(range, false)) + ", " + num(draw(range, false)) + "]"; }

        String json() {
            boolean global = r.nextInt(3) == 0;
            boolean mesh = !global && r.nextInt(4) == 0;
            int meshIndex = r.nextInt(MESHES.length);
            boolean fabric = r.nextInt(3) == 0;
            boolean catalogue = fabric && r.nextBoolean();
            int maxSide = global ? 32 : (int) Limits.RESOLUTION.hi;
            int columns = (int) Math.round(Math.min(maxSide, draw(Limits.RESOLUTION, true)));
            int rows = (int) Math.round(Math.min(maxSide, draw(Limits.RESOLUTION, true)));
            if (columns * rows < 2) rows = 2;
            double width = columns > 1 ? draw(Limits.SIZE, true) : 0, height = rows > 1 ? draw(Limits.SIZE, true) : 0;
            boolean byDensity = r.nextBoolean();
            double density = draw(Limits.AREAL_DENSITY, true), mass = draw(Limits.TOTAL_MASS, true);
            boolean pbd = !global && !fabric && r.nextBoolean();
            boolean descent = !global && !pbd && r.nextInt(3) == 0;
            int iterations = (int) Math.round(draw(Limits.ITERATIONS, true)), substeps = (int) Math.round(draw(Limits.SUBSTEPS, true));
            double dt = draw(Limits.DT, true);
            // The shipped meshes are a metre or two across in metres: past a scale of 500 they cannot fit the ±1000 m scene.
            double meshScale = mesh ? Math.min(500, draw(Limits.MESH_SCALE, true)) : 1;
            boolean triangles = mesh || (columns > 1 && rows > 1);
            if (!triangles) fabric = catalogue = false;
            // A closed mesh filled by a "pressure" block in one mesh case of three, drawn from a stream of its own (seeded
            // by values drawn above) so the case's other draws stay: the pillow under a fabric (a warp of [1, 0, 0] lies
            // in none of the balloon's side triangles), either under springs.
            Random closedDraw = new Random(Double.doubleToLongBits(density) ^ Double.doubleToLongBits(dt) ^ iterations);
            int closed = mesh && closedDraw.nextInt(3) == 0 ? (fabric ? 0 : closedDraw.nextInt(CLOSED.length)) : -1;
            int facts = closed >= 0 ? MESHES.length + closed : meshIndex;
            Object meshFile = closed >= 0 ? CLOSED[closed][0] : MESHES[meshIndex][0], meshGroup = closed >= 0 ? CLOSED[closed][1] : MESHES[meshIndex][1];
            // A garment (the skirt's pattern or, one time in two, the T-shirt's, its sleeves about slanted axes, one
            // fabric; or the bordered tablecloth's, two; coarse: 5 to 20 cm edges) in one open-mesh case of four, from a
            // stream of its own (the T-shirt drawn last, so earlier seeds draw what they did but for it).
            Random garmentDraw = new Random(Double.doubleToLongBits(width) ^ rows ^ 0x5eed);
            boolean garment = mesh && closed < 0 && garmentDraw.nextInt(4) == 0;
            double edge = 0.05 + 0.15 * garmentDraw.nextDouble();
            String pattern = garmentDraw.nextBoolean() ? "skirt" : "tablecloth";
            if (pattern.equals("skirt") && garmentDraw.nextBoolean()) pattern = "tshirt";
            xpbdcloth.mesh.ClothMesh garmentMesh = null;
            if (garment) {
                // Some coarse edges leave a seam no room to close (the loader refuses those, naming cloth.edge,
                // PatternLoaderTest): the edge drawn is shortened by a tenth until its seams close.
                xpbdcloth.scene.PatternLoader.Loaded loaded = xpbdcloth.scene.PatternLoader.byNameOrPath(pattern);
                xpbdcloth.pattern.PatternMesh meshed = loaded.mesh(edge);
                while (meshed.seamProblem() != null) meshed = loaded.mesh(edge *= 0.9);
                garmentMesh = meshed.toClothMesh();
            }
            long particles = garment ? garmentMesh.vertexCount()
                    : mesh ? (long) meshFacts()[2 * facts] : (long) columns * rows;
            double budget = global ? WORK_BUDGET / 100 : WORK_BUDGET;
            while (particles * (double) iterations * substeps > budget && iterations * substeps > 1) {
                if (iterations >= substeps) iterations = Math.max(1, iterations / 2); else substeps = Math.max(1, substeps / 2);
            }
            steps = (int) Math.max(1, Math.min(20, budget / (particles * (double) iterations * substeps)));

            json.append("{ \"name\": \"fuzz\", \"description\": \"seeded random preset\", \"cloth\": { ");
            String massField = catalogue ? "" : byDensity ? ", \"arealDensity\": " + num(density) : ", \"totalMass\": " + num(mass);
            List<String> corners = new ArrayList<>();
            if (garment) {
                json.append("\"pattern\": \"").append(pattern).append("\", \"edge\": ").append(num(edge)).append(", \"sewing\": { \"time\": ").append(num(draw(Limits.SEWING_TIME, false)))
                    .append(", \"compliance\": ").append(num(draw(Limits.COMPLIANCE, true))).append(", \"seamBending\": ").append(num(draw(Limits.SEAM_BENDING, true)))
                    .append(" }").append(fabric && !catalogue ? massField : "").append(" }");
            } else if (mesh) {
                // Turned about x only when a fabric's warp [1, 0, 0] must stay in every triangle's plane.
                String rotation = fabric ? "[" + num(draw(Limits.ROTATION, false)) + ", 0, 0]" : vec(Limits.ROTATION);
                json.append("\"mesh\": { \"file\": \"").append(meshFile).append("\", \"weld\": ").append(num(r.nextInt(4) == 0 ? 0 : 1e-3 * r.nextDouble()))
                    .append(", \"scale\": ").append(num(meshScale)).append(", \"rotation\": ").append(rotation)
                    .append(", \"translation\": ").append(vec(new Limits.Range(-(990 - 2 * meshScale), 990 - 2 * meshScale, "m"))).append(" }").append(massField).append(", \"pins\": [");
                int pins = r.nextInt(4);
                for (int k = 0; k < pins; k++) {
                    json.append(k == 0 ? "" : ", ");
                    switch (r.nextInt(3)) {
                        case 0: json.append(r.nextInt((int) particles)); break;
                        case 1:
                            if (meshGroup != null) { json.append("{ \"group\": \"").append(meshGroup).append("\" }"); break; }
                            json.append(r.nextInt((int) particles)); break;
                        default: json.append("{ \"box\": { \"min\": [-1000, -1000, -1000], \"max\": [1000, 1000, 1000] } }"); // every vertex
                    }
                }
                if (pins > 0) { json.append(", 0"); corners.add("0"); } // vertex 0 pinned: a pin motion may name it
                json.append("] }");
            } else {
                json.append("\"columns\": ").append(columns).append(", \"rows\": ").append(rows)
                    .append(", \"width\": ").append(num(width)).append(", \"height\": ").append(num(height))
                    .append(", \"plane\": \"").append(r.nextBoolean() ? "vertical" : "horizontal").append("\", \"origin\": ").append(vec(Limits.POSITION))
                    .append(massField).append(", \"pins\": [");
                String[] pinNames = {"top-left", "top-right", "bottom-left", "bottom-right", "top-edge", "left-edge"};
                int pins = r.nextInt(4);
                for (int k = 0; k < pins; k++) {
                    String p = pinNames[r.nextInt(pinNames.length)];
                    json.append(k == 0 ? "" : ", ").append('"').append(p).append('"');
                    if (!p.endsWith("edge")) corners.add('"' + p + '"');
                }
                json.append("] }");
            }
            if (fabric) {
                json.append(", \"fabric\": { ");
                if (catalogue) {
                    List<xpbdcloth.fabric.Fabric> all = xpbdcloth.scene.FabricCatalogue.all();
                    json.append("\"catalogue\": \"").append(all.get(r.nextInt(all.size())).name).append('"');
                } else {
                    double e1 = draw(Limits.MODULUS, true), e2 = draw(Limits.MODULUS, true);
                    // |ν12| < √(E1/E2) for a positive-definite stiffness: drawn inside that, and inside its range.
                    double bound = Math.min(Math.sqrt(e1 / e2) * 0.999, Limits.POISSON.hi);
                    double nu = Math.max(Limits.POISSON.lo, -bound) + r.nextDouble() * (bound - Math.max(Limits.POISSON.lo, -bound));
                    json.append("\"name\": \"drawn\", \"warpModulus\": ").append(num(e1)).append(", \"weftModulus\": ").append(num(e2))
                        .append(", \"poisson\": ").append(num(nu)).append(", \"shearModulus\": ").append(num(draw(Limits.MODULUS, true)))
                        .append(", \"bendingStiffness\": ").append(num(draw(Limits.BENDING_STIFFNESS, true)));
                }
                json.append(", \"warp\": [1, 0, 0], \"tethers\": ").append(r.nextBoolean());
                // Bending that yields in one fabric of two, and a catalogue fabric's measured stretching, drawn from a
                // stream of its own (the preset so far) so that the case's other draws stay what they were.
                Random own = new Random(json.toString().hashCode());
                // A catalogue fabric follows its measured stretching curve in one case of two.
                if (catalogue && own.nextBoolean()) json.append(", \"stiffening\": true");
                boolean yielding = own.nextBoolean();
                if (yielding)
                    json.append(", \"plasticity\": { \"yieldCurvature\": ").append(num(logUniform(own, Limits.YIELD_CURVATURE)))
                        .append(", \"rate\": ").append(num(logUniform(own, Limits.PLASTIC_RATE))).append(" }");
                // A breaking strain in one of two fabrics that may tear (not a yielding one, a garment or a gas's), from a
                // stream of its own again.
                Random tears = new Random(json.toString().hashCode() * 31L + 7);
                if (!yielding && !garment && closed < 0 && tears.nextBoolean())
                    json.append(", \"breakingStrain\": ").append(num(logUniform(tears, Limits.BREAKING_STRAIN)));
                json.append(" }");
            }
            boolean springs = !fabric || r.nextBoolean(); // a fabric needs no families; given, they are whole
            if (springs) json.append(", \"families\": { ");
            String[] families = {"structural", "shear", "bend"};
            boolean first = true;
            for (String f : families) {
                if (!springs) break;
                if (!f.equals("structural") && r.nextBoolean()) continue;
                double alpha = r.nextInt(5) == 0 ? 0 : draw(new LogCompliance().range, true);
                json.append(first ? "" : ", ").append('"').append(f).append("\": { \"stiffness\": ").append(num(draw(Limits.STIFFNESS, false)))
                    .append(", \"compliance\": ").append(num(alpha)).append(" }");
                first = false;
            }
            json.append(springs ? " }" : "").append(", \"solver\": { \"mode\": \"").append(pbd ? "PBD" : "XPBD").append("\", \"iterations\": ").append(iterations)
                .append(", \"substeps\": ").append(substeps).append(", \"dt\": ").append(num(dt))
                .append(", \"mullerCorrection\": ").append(r.nextBoolean()).append(", \"gravity\": ").append(vec(Limits.GRAVITY))
                .append(", \"damping\": ").append(num(draw(Limits.DAMPING, false)))
                .append(", \"type\": \"").append(global ? (r.nextBoolean() ? "jacobi-pcg" : "multigrid-pcg") : descent ? "vertex-block-descent" : "gauss-seidel").append("\" }");
            // A collider's margin is half the cloth's thickness, which may not exceed the cloth's spacing.
            double halfEdge = garment ? 0.5 * garmentMesh.shortestEdge() : mesh ? 0.5 * meshScale * meshFacts()[2 * facts + 1]
                    : 0.5 * Math.min(columns > 1 ? width / (columns - 1) : Double.POSITIVE_INFINITY, rows > 1 ? height / (rows - 1) : Double.POSITIVE_INFINITY);
            int spheres = r.nextInt(3);
            if (spheres > 0) {
                json.append(", \"spheres\": [");
                for (int k = 0; k < spheres; k++) {
                    json.append(k == 0 ? "" : ", ").append("{ \"radius\": ").append(num(draw(Limits.SPHERE_RADIUS, true)))
                        .append(", \"margin\": ").append(num(Math.min(0.999 * halfEdge, draw(Limits.MARGIN, false))))
                        .append(", \"staticFriction\": ").append(num(draw(Limits.FRICTION, false)))
                        .append(", \"kineticFriction\": ").append(num(draw(Limits.FRICTION, false)))
                        .append(", \"angularVelocity\": ").append(vec(Limits.ANGULAR_VELOCITY)).append(", \"path\": ").append(path()).append(depenetration()).append(" }");
                }
                json.append("]");
            }
            int solids = r.nextInt(3);
            if (solids > 0) {
                json.append(", \"colliders\": [");
                for (int k = 0; k < solids; k++) {
                    json.append(k == 0 ? "" : ", ");
                    int kind = r.nextInt(5);
                    if (kind == 4) { // a triangle mesh: still, animated (its own rate or another, from a start, looped or held), placed anywhere
                        String[] bodies = {"torus.obj", "mannequin.obj", "mannequin-turn.usda", "mannequin-a-pose-turn.usda"};
                        String body = bodies[r.nextInt(bodies.length)];
                        json.append("{ \"type\": \"mesh\", \"file\": \"").append(body).append('"');
                        if (body.endsWith(".usda") && r.nextBoolean()) json.append(", \"fps\": ").append(num(draw(Limits.FRAME_RATE, true)));
                        if (body.endsWith(".usda") && r.nextBoolean()) json.append(", \"loop\": ").append(r.nextBoolean());
                        if (body.endsWith(".usda") && r.nextBoolean()) json.append(", \"start\": ").append(num(r.nextInt(4) == 0 ? 0 : draw(Limits.START_TIME, false) * 1e-5));
                        json.append(", \"scale\": ").append(num(Math.exp(r.nextDouble() * 2 - 1)))
                            .append(", \"rotation\": ").append(vec(Limits.ROTATION)) // a body of a few metres at most, kept inside the world's bounds
                            .append(", \"translation\": [").append(num(0.99 * draw(Limits.POSITION, false))).append(", ").append(num(0.99 * draw(Limits.POSITION, false)))
                            .append(", ").append(num(0.99 * draw(Limits.POSITION, false))).append("]")
                            .append(", \"margin\": ").append(num(Math.min(0.999 * halfEdge, draw(Limits.MARGIN, false))))
                            .append(", \"staticFriction\": ").append(num(draw(Limits.FRICTION, false)))
                            .append(", \"kineticFriction\": ").append(num(draw(Limits.FRICTION, false)));
                        if (r.nextBoolean()) json.append(", \"angularVelocity\": ").append(vec(Limits.ANGULAR_VELOCITY)).append(", \"path\": ").append(path());
                        json.append(depenetration()).append(" }");
                        continue;
                    }
                    if (kind == 2) { // a plane: any point, a normal not near zero
                        json.append("{ \"type\": \"plane\", \"point\": ").append(vec(Limits.POSITION)).append(", \"normal\": [")
                            .append(num(r.nextDouble() * 2 - 1)).append(", ").append(num(0.5 + 0.5 * r.nextDouble())).append(", ").append(num(r.nextDouble() * 2 - 1))
                            .append("], \"margin\": ").append(num(Math.min(0.999 * halfEdge, draw(Limits.MARGIN, false))))
                            .append(", \"staticFriction\": ").append(num(draw(Limits.FRICTION, false)))
                            .append(", \"kineticFriction\": ").append(num(draw(Limits.FRICTION, false))).append(depenetration()).append(" }");
                        continue;
                    }
                    if (kind == 3) json.append("{ \"type\": \"sphere\", \"radius\": ").append(num(draw(Limits.SPHERE_RADIUS, true)));
                    else if (kind == 0) json.append("{ \"type\": \"box\", \"halfExtents\": ").append(vec(Limits.SPHERE_RADIUS)).append(", \"rotation\": ").append(vec(Limits.ROTATION));
                    else json.append("{ \"type\": \"capsule\", \"axis\": [0, ").append(num(0.5 + 0.5 * r.nextDouble())).append(", ").append(num(r.nextDouble() - 0.5))
                            .append("], \"halfLength\": ").append(num(draw(Limits.PATH_RADIUS, false))).append(", \"radius\": ").append(num(draw(Limits.SPHERE_RADIUS, true)));
                    json.append(", \"margin\": ").append(num(Math.min(0.999 * halfEdge, draw(Limits.MARGIN, false))))
                        .append(", \"staticFriction\": ").append(num(draw(Limits.FRICTION, false)))
                        .append(", \"kineticFriction\": ").append(num(draw(Limits.FRICTION, false)))
                        .append(", \"angularVelocity\": ").append(vec(Limits.ANGULAR_VELOCITY)).append(", \"path\": ").append(path()).append(depenetration()).append(" }");
                }
                json.append("]");
            }
            if (!corners.isEmpty() && r.nextBoolean()) {
                json.append(", \"pinMotions\": [{ \"pin\": ").append(corners.get(0)).append(", \"displacement\": ").append(vec(Limits.DISPLACEMENT));
                // A turn in one motion of two, from a stream of its own (the preset so far) so the other draws stay.
                Random own = new Random(json.toString().hashCode());
                if (own.nextBoolean()) {
                    double turns = Limits.TURNS.lo + own.nextDouble() * (Limits.TURNS.hi - Limits.TURNS.lo);
                    json.append(", \"rotation\": { \"axis\": [").append(num(own.nextDouble() - 0.5)).append(", ").append(num(0.5 + 0.5 * own.nextDouble()))
                        .append(", ").append(num(own.nextDouble() - 0.5)).append("], \"centre\": [").append(num(own.nextGaussian())).append(", ")
                        .append(num(own.nextGaussian())).append(", ").append(num(own.nextGaussian())).append("], \"turns\": ").append(num(turns)).append(" }");
                }
                json.append(", \"start\": ").append(num(r.nextInt(4) == 0 ? 0 : draw(Limits.START_TIME, true) * 1e-6))
                    .append(", \"duration\": ").append(num(draw(Limits.DURATION, true))).append(" }]");
            }
            if (r.nextBoolean()) {
                double drag = draw(Limits.DRAG, false);
                json.append(", \"wind\": { \"velocity\": ").append(vec(Limits.WIND_SPEED)).append(", \"drag\": ").append(num(drag))
                    .append(", \"gust\": ").append(num(draw(Limits.GUST, false))).append(" }");
            }
            if (triangles && r.nextInt(3) == 0)
                json.append(", \"aerodynamics\": { \"density\": ").append(num(draw(Limits.AIR_DENSITY, true))).append(", \"drag\": ").append(num(draw(Limits.AERO_COEFFICIENT, false)))
                    .append(", \"lift\": ").append(num(draw(Limits.AERO_COEFFICIENT, false))).append(", \"air\": ").append(vec(Limits.WIND_SPEED)).append(" }");
            if (r.nextInt(4) == 0 && Double.isFinite(halfEdge)) {
                // Thickness up to the cloth's shortest edge (2 × halfEdge), and inside its range.
                double t = Math.max(Limits.THICKNESS.lo, Math.min(1.998 * halfEdge, draw(Limits.THICKNESS, true)));
                if (t <= 1.998 * halfEdge)
                    json.append(", \"selfCollision\": { \"thickness\": ").append(num(t)).append(", \"staticFriction\": ").append(num(draw(Limits.FRICTION, false)))
                        .append(", \"kineticFriction\": ").append(num(draw(Limits.FRICTION, false))).append(continuous()).append(" }");
            }
            if (closed >= 0) json.append(pressure(new Random(json.toString().hashCode())));
            json.append(" }");
            if (r.nextInt(5) == 0 && !mesh) breakOneField();
            return json.toString();
        }

        /** A "pressure" block: a gas by its gauge or its amount (in air or a vacuum), or a held volume, each a third of the time. */
        static String pressure(Random own) {
            double ambient = own.nextInt(4) == 0 ? 0 : Limits.AMBIENT_PRESSURE.hi * own.nextDouble();
            switch (own.nextInt(3)) {
                case 0: {
                    // Above −ambient (a gas needs a pressure above 0), up to the range's top.
                    double gauge = ambient == 0 ? logUniform(own, new Limits.Range(1e-3, Limits.GAUGE_PRESSURE.hi, "Pa"))
                            : -0.999 * ambient + own.nextDouble() * (Limits.GAUGE_PRESSURE.hi + 0.999 * ambient);
                    return ", \"pressure\": { \"gauge\": " + gauge + ", \"ambient\": " + ambient + " }";
                }
                case 1:
                    return ", \"pressure\": { \"moles\": " + logUniform(own, Limits.MOLES) + ", \"temperature\": " + logUniform(own, Limits.TEMPERATURE)
                            + ", \"ambient\": " + ambient + " }";
                default:
                    return ", \"pressure\": { \"volumeRatio\": " + logUniform(own, Limits.VOLUME_RATIO) + " }";
            }
        }

        /** Puts one field just outside its range. */
        void breakOneField() {
            String[][] fields = {
                    {"solver.dt", "\"dt\": ", Limits.DT.text(), "1e-300"},
                    {"solver.dt", "\"dt\": ", Limits.DT.text(), "0.2"},
                    {"solver.iterations", "\"iterations\": ", Limits.ITERATIONS.text(), "1001"},
                    {"solver.substeps", "\"substeps\": ", Limits.SUBSTEPS.text(), "0"},
                    {"solver.damping", "\"damping\": ", Limits.DAMPING.text(), "-1"},
                    {"solver.gravity[0]", "\"gravity\": [", Limits.GRAVITY.text(), "-1e6"},
                    {"cloth.origin[0]", "\"origin\": [", Limits.POSITION.text(), "1e5"},
                    {"families.structural.compliance", "\"structural\": { \"stiffness\": ", Limits.COMPLIANCE.text(), null},
                    {"cloth.columns", "\"columns\": ", Limits.RESOLUTION.text(), "513"},
            };
            String[] f = fields[r.nextInt(fields.length)];
            int at = json.indexOf(f[1]);
            if (at < 0) return; // that field is not in this preset (a fabric without spring families)
            if (f[3] == null) {
                int c = json.indexOf("\"compliance\": ", at) + "\"compliance\": ".length();
                int end = json.indexOf(" ", c);
                json.replace(c, end, "1e6");
            } else {
                int from = at + f[1].length();
                int end = from;
                while (end < json.length() && "0123456789.eE+-".indexOf(json.charAt(end)) >= 0) end++;
                json.replace(from, end, f[3]);
            }
            brokenField = f[0];
            brokenRange = f[2];
        }
    }

    /** Compliance drawn log-uniformly from the smallest non-zero value the sketch offers to the maximum. */
    private static final class LogCompliance {
        final Limits.Range range = new Limits.Range(Limits.SMALLEST_NONZERO_COMPLIANCE, Limits.COMPLIANCE.hi, "m/N");
    }

    static String summary(int cases, long seed, int failed, double seconds) {
        return String.format(Locale.ROOT, "fuzz presets: %d cases from seed %d, %d failed, %.1f s", cases, seed, failed, seconds);
    }
}
