package xpbdcloth.scene;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import xpbdcloth.engine.Particles;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Broken presets: each kind of mistake gets a message naming the file, the field and the problem. */
class PresetLoaderTest {

    static String valid() {
        return "{ \"name\": \"t\", \"cloth\": { \"columns\": 4, \"rows\": 4, \"width\": 1, \"height\": 1, \"arealDensity\": 0.2, \"pins\": [\"top-left\"] },"
                + " \"families\": { \"structural\": { \"stiffness\": 1, \"compliance\": 0 } },"
                + " \"solver\": { \"mode\": \"XPBD\", \"iterations\": 2, \"dt\": 0.02 } }";
    }

    @Test
    void validTextLoads() {
        Preset p = PresetLoader.parse("t.json", valid());
        assertEquals(4, p.cloth.columns);
        assertEquals(1, p.solver.substeps(), "default substeps");
        assertEquals(-9.81, p.solver.gravityY(), "default gravity");
    }

    /**
     * A file's every problem at once, in the order it reads: a pin outside the grid (the cloth), a negative
     * compliance (the families) and too many iterations (the solver) stop three parts that do not need each
     * other; a number out of range does not stop even its own part (a density in the same cloth is found too).
     */
    @Test
    void everyProblemOfAFileIsReportedAtOnce() {
        String text = valid().replace("\"pins\": [\"top-left\"]", "\"pins\": [[9, 0]]").replace("\"arealDensity\": 0.2", "\"arealDensity\": -1")
                .replace("\"compliance\": 0", "\"compliance\": -1").replace("\"iterations\": 2", "\"iterations\": 0");
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.parse("t.json", text));
        java.util.List<String> fields = e.all().stream().map(PresetException::field).collect(java.util.stream.Collectors.toList());
        assertEquals(java.util.List.of("cloth.arealDensity", "cloth.pins[0]", "families.structural.compliance", "solver.iterations"), fields, e.getMessage());
        assertEquals("cloth.arealDensity", e.field(), "the first problem is the exception's own");
        assertEquals(4, e.getMessage().lines().count(), "a line each: " + e.getMessage());
        assertTrue(e.getMessage().lines().allMatch(l -> l.startsWith("t.json: ")), e.getMessage());
        // One problem stays one exception, as before.
        PresetException one = assertThrows(PresetException.class, () -> PresetLoader.parse("t.json", valid().replace("\"iterations\": 2", "\"iterations\": 0")));
        assertEquals(java.util.List.of(one), one.all());
    }

    /**
     * Every field within its range, and still a step of hours: 512² particles at 1000 iterations × 100
     * substeps. The product is limited, and the error names it with its factors; the same cloth at the
     * limit loads. Global solvers have their own, smaller limit (64² at 2 × 10).
     */
    @Test
    void aStepOfHoursIsRefusedWithItsFactors() {
        String big = valid().replace("\"columns\": 4, \"rows\": 4", "\"columns\": 512, \"rows\": 512");
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.parse("big.json",
                big.replace("\"iterations\": 2", "\"iterations\": 1000, \"substeps\": 100")));
        assertEquals("solver", e.field());
        assertTrue(e.problem().startsWith("particles × substeps × (iterations + colliders) must be at most 33554432"), e.getMessage());
        assertTrue(e.problem().contains("262144 × 100 × (1000 + 0) = 26214400000"), e.getMessage());
        assertEquals(128, PresetLoader.parse("big.json", big.replace("\"iterations\": 2", "\"iterations\": 128")).solver.iterations());

        String global = valid().replace("\"iterations\": 2", "\"iterations\": 2, \"substeps\": 10, \"type\": \"jacobi-pcg\"");
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("g.json", global.replace("\"columns\": 4, \"rows\": 4", "\"columns\": 128, \"rows\": 128")));
        assertTrue(e.problem().startsWith("particles × substeps × iterations must be at most 81920 with a global solver"), e.getMessage());
        assertTrue(e.problem().endsWith("use gauss-seidel, or fewer particles, substeps or iterations"), e.getMessage());
        assertEquals(64, PresetLoader.parse("g.json", global.replace("\"columns\": 4, \"rows\": 4", "\"columns\": 64, \"rows\": 64")).cloth.columns);
    }

    static String fabric(String fields) {
        return valid().replace(" \"families\": { \"structural\": { \"stiffness\": 1, \"compliance\": 0 } },",
                " \"fabric\": { " + fields + " },");
    }

    static final String COTTONISH = "\"warpModulus\": 2000, \"weftModulus\": 800, \"poisson\": 0.25, \"shearModulus\": 30, \"bendingStiffness\": 1e-5, \"warp\": [1, 0, 0]";

    /**
     * No material is refused for the mesh it is on: the softest bending the range allows loads on a fine grid
     * and on cells three times longer than wide (its patch rows' compliance is 1/B whatever the cells), and a
     * value below the range is named by its preset field.
     */
    @Test
    void theSoftestBendingLoadsOnFineAndElongatedCells() {
        String softest = COTTONISH.replace("\"bendingStiffness\": 1e-5", "\"bendingStiffness\": " + Limits.BENDING_STIFFNESS.lo);
        for (String cloth : new String[] {"\"columns\": 48, \"rows\": 48, \"width\": 0.24, \"height\": 0.24",
                                          "\"columns\": 48, \"rows\": 16, \"width\": 0.24, \"height\": 0.24"}) {
            String text = fabric(softest).replace("\"columns\": 4, \"rows\": 4, \"width\": 1, \"height\": 1", cloth);
            Scene scene = Scene.of(PresetLoader.parse("soft.json", text));
            assertTrue(scene.simulation().constraintCount() > 0, cloth);
        }
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.parse("f.json",
                fabric(COTTONISH.replace("\"bendingStiffness\": 1e-5", "\"bendingStiffness\": 1e-7"))));
        assertEquals("fabric.bendingStiffness", e.field());
    }

    /**
     * Bending that yields: the scene's hinges are all dihedral (one per interior edge) and yield; a curvature or rate
     * of zero, an unknown field and a missing one are named by field.
     */
    @Test
    void plasticityLoadsAndBadOnesAreNamed() {
        String plastic = COTTONISH + ", \"plasticity\": { \"yieldCurvature\": 15, \"rate\": 2 }";
        Scene scene = Scene.of(PresetLoader.parse("p.json", fabric(plastic)));
        // 4 × 4: 18 triangles (3 membrane rows each) and 21 interior edges (33 edges less the 12 on the border).
        assertEquals(18 * 3 + 21, scene.simulation().constraintCount());
        assertEquals(15, ((xpbdcloth.engine.HingePlasticity) scene.simulation().afterSteps().get(0)).yieldCurvature());
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.parse("p.json", fabric(plastic.replace("\"yieldCurvature\": 15", "\"yieldCurvature\": 0"))));
        assertEquals("fabric.plasticity.yieldCurvature", e.field());
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("p.json", fabric(plastic.replace("\"rate\": 2", "\"rate\": -1"))));
        assertEquals("fabric.plasticity.rate", e.field());
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("p.json", fabric(plastic.replace("\"rate\": 2", "\"rate\": 2, \"yieldAngle\": 1"))));
        assertTrue(e.getMessage().contains("yieldAngle"), e.getMessage());
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("p.json", fabric(plastic.replace(", \"rate\": 2", ""))));
        assertEquals("fabric.plasticity.rate", e.field());
    }

    /** A closed mesh of a measured fabric with a pressure block (the balloon's sphere), read as data/x.json reads its mesh. */
    static String closed(String cloth, String pressure) {
        return "{ \"name\": \"b\", \"cloth\": " + cloth + ", \"fabric\": { \"catalogue\": \"swimsuit\" },"
                + " \"solver\": { \"mode\": \"XPBD\", \"iterations\": 2, \"substeps\": 2, \"dt\": 0.02 }, \"pressure\": " + pressure + " }";
    }

    static final String BALLOON = "{ \"mesh\": { \"file\": \"balloon.obj\" } }";

    /**
     * A pressure block fills a closed mesh with a gas by its gauge at the rest shape or by its amount, or holds a
     * volume; one that asks for two, none, a vacuum inside, a field of another kind, or a cloth that is not closed
     * is refused by field.
     */
    @Test
    void pressureFillsAClosedMeshAndBadOnesAreNamed() {
        String file = "data/b.json";
        xpbdcloth.engine.EnclosedGas gas = Scene.of(PresetLoader.parse(file, closed(BALLOON, "{ \"gauge\": 150 }"))).gas();
        assertEquals((101325 + 150) * gas.restVolume(), gas.amount(), 1e-9 * gas.amount());
        gas = Scene.of(PresetLoader.parse(file, closed(BALLOON, "{ \"moles\": 0.5, \"temperature\": 300, \"ambient\": 0 }"))).gas();
        assertEquals(0.5 * xpbdcloth.engine.EnclosedGas.GAS_CONSTANT * 300, gas.amount(), 1e-12);
        assertEquals(0, gas.ambient());
        gas = Scene.of(PresetLoader.parse(file, closed(BALLOON, "{ \"volumeRatio\": 1.2 }"))).gas();
        assertEquals(1.2 * gas.restVolume(), gas.targetVolume(), 1e-15);
        String[][] bad = {
                {"{ \"gauge\": 150, \"moles\": 1 }", "pressure", "exactly one"},
                {"{ \"ambient\": 1000 }", "pressure", "exactly one"},
                {"{ \"gauge\": -2e5 }", "pressure.gauge", "above 0"},
                {"{ \"gauge\": 10, \"temperature\": 300 }", "pressure.temperature", "goes with moles"},
                {"{ \"volumeRatio\": 1, \"ambient\": 0 }", "pressure.ambient", "goes with a gas"},
                {"{ \"volumeRatio\": 0 }", "pressure.volumeRatio", ""},
                {"{ \"gauge\": 10, \"volume\": 1 }", "pressure.volume", "volume"}};
        for (String[] b : bad) {
            PresetException e = assertThrows(PresetException.class, () -> PresetLoader.parse(file, closed(BALLOON, b[0])), b[0]);
            assertEquals(b[1], e.field(), b[0]);
            assertTrue(e.getMessage().contains(b[2]), e.getMessage());
        }
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.parse(file, closed("{ \"mesh\": { \"file\": \"flag-with-hole.obj\" } }", "{ \"gauge\": 10 }")
                .replace("\"swimsuit\"", "\"swimsuit\", \"warp\": [1, 0, 0]")));
        assertEquals("pressure", e.field());
        assertTrue(e.getMessage().contains("borders one triangle only"), e.getMessage());
        e = assertThrows(PresetException.class, () -> PresetLoader.parse(file, fabric(COTTONISH).replace("\"cloth\"", "\"pressure\": { \"gauge\": 10 }, \"cloth\"")));
        assertEquals("pressure", e.field());
        assertTrue(e.getMessage().contains("grid cloth has a boundary"), e.getMessage());
    }

    /** The measured curve is a catalogue fabric's: moduli of one's own have none, and asking for it is named. */
    @Test
    void stiffeningNeedsAMeasuredCurve() {
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.parse("s.json", fabric(COTTONISH + ", \"stiffening\": true")));
        assertEquals("fabric.stiffening", e.field());
        String denim = fabric("\"catalogue\": \"denim\", \"warp\": [1, 0, 0], \"stiffening\": true").replace(" \"arealDensity\": 0.2,", "");
        Scene scene = Scene.of(PresetLoader.parse("d.json", denim));
        assertTrue(scene.simulation().afterSteps().get(0) instanceof xpbdcloth.fabric.MeasuredStiffening);
    }

    /**
     * A fabric replaces the spring families (which become optional): the scene gets three membrane rows and
     * three bending patch rows per triangle; moduli out of range, a Poisson ratio without a
     * positive-definite stiffness and a zero warp direction are named by field.
     */
    @Test
    void fabricLoadsAndBadOnesAreNamed() {
        Scene scene = Scene.of(PresetLoader.parse("f.json", fabric(COTTONISH + ", \"tethers\": true")));
        // 4 × 4: 18 triangles (3 membrane rows each, and 3 curvature rows of 3 components each), 15 free particles tethered to the pin.
        assertEquals(18 * 3 + 18 * 9 + 15, scene.simulation().constraintCount());
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.parse("f.json", fabric(COTTONISH.replace("\"poisson\": 0.25", "\"poisson\": 1.8"))));
        assertEquals("fabric.poisson", e.field());
        assertTrue(e.problem().contains("positive-definite"), e.getMessage());
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("f.json", fabric(COTTONISH.replace("\"warpModulus\": 2000", "\"warpModulus\": -5"))));
        assertEquals("fabric.warpModulus", e.field());
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("f.json", fabric(COTTONISH.replace("[1, 0, 0]", "[0, 0, 0]"))));
        assertEquals("fabric.warp", e.field());
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("f.json", fabric(COTTONISH.replace("\"bendingStiffness\": 1e-5", "\"bendingStiffness\": 0"))));
        assertEquals("fabric.bendingStiffness", e.field());
        // The warp must lie in the cloth: along z it is normal to this vertical cloth, named by the scene.
        e = assertThrows(PresetException.class, () -> Scene.of(PresetLoader.parse("f.json", fabric(COTTONISH.replace("[1, 0, 0]", "[0, 0, 1]")))));
        assertTrue(e.problem().contains("warp direction"), e.getMessage());
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("n.json", valid().replace(" \"families\": { \"structural\": { \"stiffness\": 1, \"compliance\": 0 } },", "")));
        assertEquals("families", e.field(), "without a fabric the families are still required");
        String air = fabric(COTTONISH).replace(" \"solver\":", " \"aerodynamics\": { \"drag\": 1.2, \"lift\": 1.0, \"air\": [6, 0, 0] }, \"solver\":");
        assertEquals(1.2, PresetLoader.parse("a.json", air).aerodynamics.density, "the air's density by default");
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("a.json", air.replace("\"drag\": 1.2", "\"drag\": -1")));
        assertEquals("aerodynamics.drag", e.field());
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("a.json", air.replace("\"air\": [6, 0, 0]", "\"air\": [6, 0]")));
        assertEquals("aerodynamics.air", e.field());
    }

    /** Plane colliders: a floor loads into the scene's simulation; an unknown type and a zero normal are named. */
    @Test
    void planeCollidersLoadAndBadOnesAreNamed() {
        String floor = withColliders("{ \"type\": \"plane\", \"point\": [0, -1, 0], \"normal\": [0, 1, 0],"
                + " \"margin\": 0.005, \"staticFriction\": 0.5, \"kineticFriction\": 0.4 }");
        Scene scene = Scene.of(PresetLoader.parse("floor.json", floor));
        assertEquals(1, scene.simulation().planes().size());
        assertEquals(1.005, scene.simulation().planes().get(0).distance(0, 0.005, 0), 1e-12, "a floor at y = -1");
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.parse("cone.json", floor.replace("\"type\": \"plane\"", "\"type\": \"cone\"")));
        assertEquals("colliders[0].type", e.field(), e.getMessage());
        assertEquals("was \"cone\"; one of plane, sphere, box, capsule, mesh", e.problem());
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("flat.json", floor.replace("\"normal\": [0, 1, 0]", "\"normal\": [0, 0, 0]")));
        assertEquals("colliders[0].normal", e.field(), e.getMessage());
    }

    static String withColliders(String colliders) {
        return valid().replace(" \"solver\":", " \"colliders\": [" + colliders + "], \"solver\":");
    }

    static final String BOX = "{ \"type\": \"box\", \"halfExtents\": [0.3, 0.2, 0.1], \"rotation\": [0, 90, 0], \"margin\": 0.005,"
            + " \"staticFriction\": 0.6, \"kineticFriction\": 0.45, \"path\": { \"type\": \"fixed\", \"centre\": [0, 0.2, 0] } }";
    static final String CAPSULE = "{ \"type\": \"capsule\", \"axis\": [0, 0, 0.5], \"halfLength\": 0.25, \"radius\": 0.05,"
            + " \"staticFriction\": 0.6, \"kineticFriction\": 0.45, \"angularVelocity\": [0, 0, 3],"
            + " \"path\": { \"type\": \"oscillation\", \"centre\": [0, 1, 0], \"amplitude\": [0.2, 0, 0], \"frequency\": 0.5 } }";

    /**
     * Boxes and capsules load with their shape, pose, path and spin: the scene's box turned 90° about y has
     * its x half extent along z; the capsule's axis (given as (0, 0, 2)) is z, its end caps 0.25 m from the
     * centre, and it follows its oscillation.
     */
    @Test
    void boxesAndCapsulesLoadWithTheirShapeAndPose() {
        Scene scene = Scene.of(PresetLoader.parse("solids.json", withColliders(BOX + ", " + CAPSULE)));
        java.util.List<xpbdcloth.engine.RigidCollider> solids = scene.simulation().solids();
        assertEquals(2, solids.size());
        xpbdcloth.engine.Box box = (xpbdcloth.engine.Box) solids.get(0);
        double[] r = new double[9];
        box.rotation(r);
        // Local x (the 0.3 m half extent) turned 90° about y points along −z: column 0 of R.
        assertEquals(0, r[0], 1e-12);
        assertEquals(-1, r[6], 1e-12);
        assertEquals(0.2, box.centreY(), 0);
        xpbdcloth.engine.Capsule capsule = (xpbdcloth.engine.Capsule) solids.get(1);
        capsule.rotation(r);
        assertEquals(1, r[7], 1e-12, "the segment's local y lies along world z");
        assertEquals(0.25, capsule.halfLength());
        scene.simulation().step();
        assertEquals(0.2 * Math.sin(2 * Math.PI * 0.5 * 0.02), capsule.centreX(), 1e-12, "on its oscillation after one step");
    }

    /** Bad colliders are named by field: no size, friction below 0, a thickness the cloth's spacing cannot hold. */
    @Test
    void badBoxesAndCapsulesAreNamed() {
        assertProblem(BOX.replace("[0.3, 0.2, 0.1]", "[0.3, 0, 0.1]"), "colliders[0].halfExtents[1]", "must be in [0.001, 100] m");
        assertProblem(CAPSULE.replace("\"radius\": 0.05", "\"radius\": -0.05"), "colliders[0].radius", "must be in [0.001, 100] m");
        assertProblem(CAPSULE.replace("\"staticFriction\": 0.6", "\"staticFriction\": -0.1"), "colliders[0].staticFriction", "must be in [0, 10]");
        assertProblem(CAPSULE.replace("[0, 0, 0.5]", "[0, 0, 0]"), "colliders[0].axis", "must not be (almost) zero");
        assertProblem(BOX.replace("\"rotation\": [0, 90, 0], ", "\"radius\": 1, "), "colliders[0].radius", "unknown field");
        // The 4 × 4 test cloth of 1 m has 0.333 m edges: a 0.2 m margin makes it 0.4 m thick.
        assertProblem(BOX.replace("\"margin\": 0.005", "\"margin\": 0.2"), "colliders (box 0).margin", "makes the cloth 0.4000 m thick (twice the margin), more than its shortest edge 0.3333 m");
    }

    /** Self-collision loads into the scene; a thickness above the cloth's spacing is named with both numbers. */
    @Test
    void selfCollisionLoadsAndATooThickClothIsNamed() {
        String text = valid().replace(" \"solver\":", " \"selfCollision\": { \"thickness\": 0.2, \"staticFriction\": 0.3, \"kineticFriction\": 0.2 }, \"solver\":");
        Scene scene = Scene.of(PresetLoader.parse("self.json", text));
        assertEquals(0.2, scene.simulation().selfCollision().thickness());
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.parse("thick.json", text.replace("\"thickness\": 0.2", "\"thickness\": 0.5")));
        assertEquals("selfCollision.thickness", e.field(), e.getMessage());
        assertTrue(e.problem().startsWith("must be at most the cloth's shortest edge 0.3333 m, was 0.5000 m"), e.getMessage());
        // The hash is rebuilt when the list it made runs out, so there is no period to set.
        String every5 = text.replace("\"kineticFriction\": 0.2 }", "\"kineticFriction\": 0.2, \"rebuildEvery\": 5 }");
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("self.json", every5));
        assertEquals("selfCollision.rebuildEvery", e.field(), e.getMessage());
        // Untangling is off unless asked for; asked for, the self-collision has an untangler; not a boolean, named.
        assertNull(scene.simulation().selfCollision().untangler());
        String untangled = text.replace("\"kineticFriction\": 0.2 }", "\"kineticFriction\": 0.2, \"untangle\": true }");
        assertNotNull(Scene.of(PresetLoader.parse("self.json", untangled)).simulation().selfCollision().untangler());
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("self.json", untangled.replace("\"untangle\": true", "\"untangle\": 1")));
        assertEquals("selfCollision.untangle", e.field(), e.getMessage());
        // Point–triangle contacts likewise.
        assertFalse(scene.simulation().selfCollision().pointTriangle());
        String faces = text.replace("\"kineticFriction\": 0.2 }", "\"kineticFriction\": 0.2, \"pointTriangle\": true }");
        assertTrue(Scene.of(PresetLoader.parse("self.json", faces)).simulation().selfCollision().pointTriangle());
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("self.json", faces.replace("\"pointTriangle\": true", "\"pointTriangle\": \"yes\"")));
        assertEquals("selfCollision.pointTriangle", e.field(), e.getMessage());
    }

    static final String TURNING_BODY = "{ \"type\": \"mesh\", \"file\": \"mannequin-turn.usda\", \"start\": 2.5, \"loop\": true, \"margin\": 0.005,"
            + " \"staticFriction\": 0.6, \"kineticFriction\": 0.45 }";

    /** An animated body's frames start to play at its "start"; a still body has none to start, and a start is a time, not below 0. */
    @Test
    void anAnimatedBodyStartsWhenItSays() {
        Preset p = PresetLoader.parse("data/turning.json", withColliders(TURNING_BODY));
        assertEquals(2.5, p.bodies.get(0).start);
        assertEquals(0, PresetLoader.parse("data/turning.json", withColliders(TURNING_BODY.replace("\"start\": 2.5, ", ""))).bodies.get(0).start, "default: at once");
        assertProblem(TURNING_BODY.replace("2.5", "-1"), "colliders[0].start", "must be in [0, 1000000] s");
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.parse("data/still.json",
                withColliders(TURNING_BODY.replace("mannequin-turn.usda", "torus.obj").replace("\"loop\": true, ", ""))));
        assertEquals("colliders[0].start", e.field(), e.getMessage());
        assertEquals("starts an animated body's frames; torus.obj is still (one shape)", e.problem());
    }

    static void assertProblem(String collider, String field, String problemStart) {
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.parse("bad.json", withColliders(collider)));
        assertEquals(field, e.field(), e.getMessage());
        assertTrue(e.problem().startsWith(problemStart) || e.problem().contains(problemStart), e.getMessage());
    }

    /** A near miss of a built-in name says which one, and lists them. */
    @Test
    void aMistypedSceneNameSuggestsTheNearest() {
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.byNameOrPath("hangin"));
        assertTrue(e.problem().startsWith("is neither a built-in scene nor a file; did you mean \"hanging\"? Built-in: hanging, corners"), e.getMessage());
        assertEquals("spinning-sphere", PresetLoader.nearest("spining-sphere"));
    }

    /** NaN is refused in the project's words, not with the JSON parser's advice to enable a feature. */
    @Test
    void notANumberIsSaidPlainly() {
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.parse("nan.json", valid().replace("\"dt\": 0.02", "\"dt\": NaN")));
        assertTrue(e.problem().contains("NaN and Infinity are not numbers in JSON"), e.getMessage());
        assertFalse(e.getMessage().contains("ALLOW_NON_NUMERIC_NUMBERS"), e.getMessage());
    }

    /** What is not a preset file is refused before it is read: devices, pipes, huge files, other encodings. */
    @Test
    void notAPresetFile(@TempDir Path dir) throws IOException {
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.load(Path.of("/dev/zero")));
        assertTrue(e.problem().startsWith("is not a regular file"), e.getMessage());
        Path big = dir.resolve("big.json");
        Files.write(big, new byte[(int) PresetLoader.MAX_FILE_BYTES + 1]);
        e = assertThrows(PresetException.class, () -> PresetLoader.load(big));
        assertTrue(e.problem().contains("a preset is at most 1048576 bytes"), e.getMessage());
        Path utf16 = Files.write(dir.resolve("utf16.json"), valid().getBytes(java.nio.charset.StandardCharsets.UTF_16));
        e = assertThrows(PresetException.class, () -> PresetLoader.load(utf16));
        assertEquals("is not UTF-8 text (it looks like UTF-16: save it as UTF-8)", e.problem());
    }

    /** Trailing content, huge integers, control characters, endless lists: each named, none silently accepted. */
    @Test
    void hostileTextIsNamed() {
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.parse("t.json", valid() + " xyz"));
        assertEquals("(syntax)", e.field(), e.getMessage());
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("t.json", valid().replace("\"columns\": 4", "\"columns\": 12345678901234567890123")));
        assertTrue(e.problem().startsWith("is too large: must be a whole number within"), e.getMessage());
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("t.json", valid().replace("\"name\": \"t\"", "\"name\": \"t\", \"\\u001b[2Jx\": 1")));
        assertFalse(e.getMessage().contains("\u001b"), "no raw escape character: " + e.getMessage());
        assertTrue(e.getMessage().contains("\\u001b[2Jx"), e.getMessage());
        StringBuilder many = new StringBuilder();
        for (int i = 0; i < 5000; i++) many.append(i == 0 ? "" : ", ").append("\"top-edge\"");
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("t.json", valid().replace("[\"top-left\"]", "[" + many + "]")));
        assertEquals("cloth.pins", e.field());
        assertTrue(e.problem().startsWith("has 5000 entries; at most 4096"), e.getMessage());
    }

    /** An edge name pins every particle along that edge. */
    @Test
    void edgeNamesPinWholeEdges() {
        Preset p = PresetLoader.parse("t.json", valid().replace("[\"top-left\"]", "[\"top-edge\", \"left-edge\"]"));
        assertEquals(7, p.cloth.pins.size(), "4 along the top, 3 more down the left (the shared corner once)");
        for (int c = 0; c < 4; c++) assertArrayEquals(new int[] {0, c}, p.cloth.pins.get(c));
        for (int r = 1; r < 4; r++) assertArrayEquals(new int[] {r, 0}, p.cloth.pins.get(3 + r));
    }

    /** A pin motion on an edge moves every particle of it, and each must be pinned: one that is not is named. */
    @Test
    void pinMotionOnAnEdgeNeedsTheWholeEdgePinned() {
        String text = valid().replace("\"dt\": 0.02 } }",
                "\"dt\": 0.02 }, \"pinMotions\": [{ \"pin\": \"top-edge\", \"displacement\": [0, 0, 0], \"start\": 0, \"duration\": 1 }] }");
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.parse("bad.json", text));
        assertEquals("pinMotions[0].pin", e.field(), e.getMessage());
        assertTrue(e.problem().contains("[0, 1] must also be listed in cloth.pins"), e.getMessage());
    }

    /**
     * A held edge turned a quarter turn about the vertical through the origin and raised 10 cm ends where the
     * rotation matrix puts it, every particle of it; a motion with neither a displacement nor a rotation, a zero
     * axis and turns out of range are named.
     */
    @Test
    void pinMotionsTurnAndMoveWholeEdges() {
        String motion = "{ \"pin\": \"left-edge\", \"rotation\": { \"axis\": [0, 0.5, 0], \"centre\": [0, 0, 0], \"turns\": 0.25 },"
                + " \"displacement\": [0, 0.1, 0], \"start\": 0, \"duration\": 1 }";
        String text = valid().replace("\"pins\": [\"top-left\"]", "\"pins\": [\"left-edge\"]").replace("\"dt\": 0.02 } }", "\"dt\": 0.02 }, \"pinMotions\": [" + motion + "] }");
        Scene scene = Scene.of(PresetLoader.parse("turn.json", text));
        Particles p = scene.simulation().particles();
        double[][] before = new double[4][];
        for (int r = 0; r < 4; r++) { int i = scene.cloth().index(r, 0); before[r] = new double[] {p.x(i), p.y(i), p.z(i)}; }
        for (int s = 0; s < 60; s++) scene.simulation().step();
        for (int r = 0; r < 4; r++) {
            int i = scene.cloth().index(r, 0);
            // R_y(90°): (x, y, z) → (z, y, −x), then up by 0.1.
            assertEquals(before[r][2], p.x(i), 1e-12, "row " + r);
            assertEquals(before[r][1] + 0.1, p.y(i), 1e-12, "row " + r);
            assertEquals(-before[r][0], p.z(i), 1e-12, "row " + r);
        }
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.parse("t.json", text.replace(" \"displacement\": [0, 0.1, 0],", "")
                .replace("\"rotation\": { \"axis\": [0, 0.5, 0], \"centre\": [0, 0, 0], \"turns\": 0.25 },", "")));
        assertEquals("pinMotions[0]", e.field(), e.getMessage());
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("t.json", text.replace("[0, 0.5, 0]", "[0, 0, 0]")));
        assertEquals("pinMotions[0].rotation.axis", e.field(), e.getMessage());
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("t.json", text.replace("\"turns\": 0.25", "\"turns\": 1000")));
        assertEquals("pinMotions[0].rotation.turns", e.field(), e.getMessage());
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
        "truncated            | \"dt\": 0.02 } }                    | \"dt\": 0.02                     | (syntax)             | not valid JSON",
        "wrong type           | \"columns\": 4                      | \"columns\": \"four\"              | cloth.columns        | must be a whole number, was string \"four\"",
        "unknown key          | \"iterations\": 2                   | \"iterations\": 2, \"iters\": 3     | solver.iters         | unknown field",
        "negative size        | \"width\": 1                        | \"width\": -1                    | cloth.width          | must be in [0.001, 100] m, was -1",
        "NaN as string        | \"dt\": 0.02                        | \"dt\": \"NaN\"                    | solver.dt            | must be a number, was string \"NaN\"",
        "pin outside grid     | \"pins\": [\"top-left\"]              | \"pins\": [[9, 0]]                | cloth.pins[0]        | outside the 4x4 grid",
        "stiffness over 1     | \"stiffness\": 1                    | \"stiffness\": 1.5               | families.structural.stiffness | must be in [0, 1], was 1.5",
        "negative compliance  | \"compliance\": 0                   | \"compliance\": -1e-6            | families.structural.compliance | must be in [0, 1000] m/N, was -1.0E-6",
        "missing field        | \"name\": \"t\",                      | ''                               | name                 | is missing",
        "zero iterations      | \"iterations\": 2                   | \"iterations\": 0                | solver.iterations    | must be in [1, 1000], was 0",
        "bad mode             | \"mode\": \"XPBD\"                    | \"mode\": \"FEM\"                  | solver.mode          | must be one of pbd, xpbd, was \"FEM\"",
        "both masses          | \"arealDensity\": 0.2               | \"arealDensity\": 0.2, \"totalMass\": 1 | cloth             | needs exactly one of arealDensity",
        "dt zero              | \"dt\": 0.02                        | \"dt\": 0                        | solver.dt            | must be in [1.0e-4, 0.1] s, was 0",
        "dt underflows alpha/h2 | \"dt\": 0.02                      | \"dt\": 1e-300                   | solver.dt            | must be in [1.0e-4, 0.1] s, was 1.0E-300",
        "PBD with a global solve | \"XPBD\", \"iterations\": 2, \"dt\": 0.02 } | \"PBD\", \"iterations\": 2, \"dt\": 0.02, \"type\": \"jacobi-pcg\" } | solver.type | must be gauss-seidel in PBD mode",
        "hurricane squared    | \"dt\": 0.02 } }                  | \"dt\": 0.02 }, \"wind\": { \"velocity\": [1e6, 0, 0], \"drag\": 0.5 } } | wind.velocity[0] | must be in [-100, 100] m/s, was 1000000.0",
        "sphere path untyped  | \"dt\": 0.02 } }                  | \"dt\": 0.02 }, \"spheres\": [{ \"radius\": 0.1, \"staticFriction\": 0, \"kineticFriction\": 0, \"path\": { \"centre\": [0, 0, 0] } }] } | spheres[0].path.type | is missing; one of fixed, linear, circle, oscillation",
        "unknown pin name     | \"pins\": [\"top-left\"]              | \"pins\": [\"top\"]                | cloth.pins[0]        | one of top-left, top-right, bottom-left, bottom-right, top-edge, bottom-edge, left-edge, right-edge, was \"top\"",
        "duplicate key        | \"rows\": 4                         | \"rows\": 4, \"rows\": 5           | (syntax)             | Duplicate field",
    })
    void brokenPresetNamesFieldAndProblem(String kind, String from, String to, String field, String problem) {
        String text = valid().replace(from.trim(), to.trim());
        assertNotEquals(valid(), text, "the case edits the text: " + kind);
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.parse("bad.json", text));
        assertEquals("bad.json", e.file());
        assertEquals(field.trim(), e.field(), kind + ": " + e.getMessage());
        assertTrue(e.problem().contains(problem.trim()), kind + ": " + e.getMessage());
    }

    @Test
    void emptyFileAndDirectoryAndMissingFile(@TempDir Path dir) throws IOException {
        Path empty = Files.writeString(dir.resolve("empty.json"), "  \n");
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.load(empty));
        assertEquals("is empty", e.problem());
        assertTrue(e.getMessage().startsWith(empty.toString() + ": (file): "));
        e = assertThrows(PresetException.class, () -> PresetLoader.load(dir));
        assertEquals("is a directory, not a preset file", e.problem());
        e = assertThrows(PresetException.class, () -> PresetLoader.load(dir.resolve("nope.json")));
        assertEquals("does not exist", e.problem());
        e = assertThrows(PresetException.class, () -> PresetLoader.byNameOrPath("no-such-scene"));
        assertTrue(e.problem().startsWith("is neither a built-in scene nor a file"), e.getMessage());
        e = assertThrows(PresetException.class, () -> PresetLoader.byNameOrPath(dir.resolve("nope.json").toString()));
        assertEquals("does not exist", e.problem(), "a path is a path");
    }

    @Test
    void everyFileInDataLoads() throws IOException {
        try (var files = Files.list(Path.of("data"))) {
            long n = files.filter(f -> f.toString().endsWith(".json") && !f.endsWith(FabricCatalogue.FILE)).peek(f -> {
                Preset p = PresetLoader.load(f);
                assertEquals(f.getFileName().toString().replace(".json", ""), p.name, "file name matches preset name");
            }).count();
            assertEquals(PresetLoader.BUILT_IN.size(), n, "every preset in data/ is built in");
        }
        // The stress tests beside them (opened by path) load too.
        try (var files = Files.list(Path.of("data", "stress"))) {
            assertTrue(files.filter(f -> f.toString().endsWith(".json")).peek(f -> Scene.of(PresetLoader.load(f))).count() > 0);
        }
    }
}
