package xpbdcloth.scene;

import static org.junit.jupiter.api.Assertions.*;

import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import xpbdcloth.engine.DihedralBlock;
import xpbdcloth.engine.MembraneBlock;
import xpbdcloth.engine.OrthotropicMaterial;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.fabric.Fabric;

/**
 * The measured fabrics: each is, at small strain, the energy its source's simulator (ARCSim, with Wang et
 * al. 2011's data) gives the same deformation; a preset can name one; the fabric key swaps one into a
 * running cloth exactly as if the scene had been built with it; the README's table is the catalogue's.
 */
class FabricCatalogueTest {

    /** Denim's tabulated zero-strain and zero-curvature samples (11oz-black-denim), as in data/fabrics.json. */
    static final double[] DENIM_STRETCHING = {205.352005, 10.234077, 1013.88629, 53.387184};
    static final double[] DENIM_BENDING = {64.196457e-6, 73.384567e-6, 96.951576e-6};

    @Test
    void theCatalogueHoldsAtLeastSixMeasuredFabricsWithSources() {
        List<Fabric> all = FabricCatalogue.all();
        assertTrue(all.size() >= 6, "six fabrics or more, had " + all.size());
        for (Fabric f : all) {
            assertTrue(f.source.contains("Wang") && f.source.contains("sample"), f.name + " names its source and sample");
            assertTrue(f.arealDensity > 0.05 && f.arealDensity < 0.5, f.name + " weighs like cloth");
            assertFalse(f.description.isEmpty(), f.name + " says what it is");
        }
        Fabric denim = FabricCatalogue.named("denim");
        // E₁ = Q₁₁ − Q₁₂²/Q₂₂ with Q = 2 × the tabulated sample: 410.704 − 20.468²/2027.77.
        assertEquals(410.4974, denim.membrane.warpModulus, 1e-3);
        assertEquals(2026.7525, denim.membrane.weftModulus, 1e-3);
        assertEquals(0.0100939, denim.membrane.poisson, 1e-6);
        assertEquals(53.387184, denim.membrane.shearModulus, 1e-9);
        assertEquals((64.196457e-6 + 96.951576e-6) / 8, denim.bendingStiffness, 1e-15);
        assertEquals(0.324, denim.arealDensity);
    }

    /** Q from E₁, E₂, ν₁₂, G and back: the conversion is the exact inverse of the stiffness. */
    @Test
    void stiffnessRoundTrips() {
        for (Fabric f : FabricCatalogue.all()) {
            double[] q = f.membrane.stiffness();
            OrthotropicMaterial back = OrthotropicMaterial.fromStiffness(q[0], q[1], q[4], q[8]);
            assertEquals(f.membrane.warpModulus, back.warpModulus, 1e-12 * q[0], f.name);
            assertEquals(f.membrane.weftModulus, back.weftModulus, 1e-12 * q[4], f.name);
            assertEquals(f.membrane.poisson, back.poisson, 1e-12, f.name);
        }
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> OrthotropicMaterial.fromStiffness(12.5, -19.9, 3.3, 17.6));
        assertTrue(e.getMessage().startsWith("q12 must satisfy"), e.getMessage());
    }

    /**
     * A triangle of denim stretched and sheared homogeneously stores what ARCSim's stretching energy gives
     * the same Green strain with the same data: A (½k₀E₀₀² + k₁E₀₀E₁₁ + ½k₂E₁₁² + k₃E₀₁²), k = 2 × sample
     * (its physics.cpp and dde.cpp). Written here from that formula, not from our conversion.
     */
    @Test
    void aDenimTriangleStoresArcsimsEnergy() {
        Fabric denim = FabricCatalogue.named("denim");
        Particles p = new Particles(3);
        double[][] rest = {{0, 0}, {0.1, 0}, {0.02, 0.08}};
        for (int i = 0; i < 3; i++) p.setPosition(i, rest[i][0], rest[i][1], 0);
        MembraneBlock m = new MembraneBlock(ConstraintFamily.MEMBRANE, 1);
        m.addTriangle(p, 0, 1, 2, 1, 0, 0, denim.membrane);
        double[][] F = {{1.004, 0.003}, {-0.002, 0.995}};
        for (int i = 0; i < 3; i++)
            p.setPosition(i, F[0][0] * rest[i][0] + F[0][1] * rest[i][1], F[1][0] * rest[i][0] + F[1][1] * rest[i][1], 0);
        double e00 = 0.5 * (F[0][0] * F[0][0] + F[1][0] * F[1][0] - 1), e11 = 0.5 * (F[0][1] * F[0][1] + F[1][1] * F[1][1] - 1);
        double e01 = 0.5 * (F[0][0] * F[0][1] + F[1][0] * F[1][1]);
        double[] k = new double[4];
        for (int j = 0; j < 4; j++) k[j] = 2 * DENIM_STRETCHING[j];
        double area = 0.5 * 0.1 * 0.08;
        double arcsim = area * (0.5 * k[0] * e00 * e00 + k[1] * e00 * e11 + 0.5 * k[2] * e11 * e11 + k[3] * e01 * e01);
        double ours = 0;
        for (int r = 0; r < 3; r++) ours += m.evaluate(r, p) * m.evaluate(r, p) / (2 * m.compliance(r));
        assertEquals(arcsim, ours, 1e-9 * arcsim);
    }

    /** A hinge of denim folded by θ stores ARCSim's bending energy k_e |e|² θ²/(8(A₀ + A₁)), k_e the 0°/90° mean. */
    @Test
    void aDenimHingeStoresArcsimsBendingEnergy() {
        Fabric denim = FabricCatalogue.named("denim");
        double theta = 0.2, h = 0.05, l = 0.08;
        Particles p = new Particles(4);
        // Edge along y from (0,0,0) to (0,l,0); one wing in the xy-plane, the other turned by θ about the edge.
        p.setPosition(0, -h, 0.3 * l, 0);
        p.setPosition(1, h, 0.6 * l, 0);
        p.setPosition(2, 0, 0, 0);
        p.setPosition(3, 0, l, 0);
        DihedralBlock d = new DihedralBlock(ConstraintFamily.DIHEDRAL, 1);
        d.addAtCurrentShape(p, 0, 1, 2, 3, denim.bendingStiffness);
        p.setPosition(1, h * Math.cos(theta), 0.6 * l, h * Math.sin(theta));
        double ke = (DENIM_BENDING[0] + DENIM_BENDING[2]) / 2;
        double arcsim = ke * l * l * theta * theta / (8 * (h * l));
        double c = d.evaluate(0, p);
        assertEquals(theta, Math.abs(c), 1e-12);
        assertEquals(arcsim, c * c / (2 * d.compliance(0)), 1e-12 * arcsim);
    }

    static String catalogueScene(String fabric, String extra) {
        return "{ \"name\": \"c\", \"cloth\": { \"columns\": 8, \"rows\": 8, \"width\": 0.5, \"height\": 0.5, " + extra + "\"pins\": [\"top-left\", \"top-right\"] },"
                + " \"fabric\": { \"catalogue\": \"" + fabric + "\", \"warp\": [1, 0, 0], \"tethers\": true },"
                + " \"solver\": { \"mode\": \"XPBD\", \"iterations\": 4, \"substeps\": 4, \"dt\": 0.02 } }";
    }

    /**
     * The fabric key's swap is the same as building the scene with that fabric: a cloth built as interlock
     * and turned into denim before its first step moves as one built as denim (to rounding: the swap scales
     * the masses, the builder computes them), and its mass is denim's areal density times its area.
     */
    @Test
    void swappingAFabricIsBuildingWithIt() {
        Scene denim = Scene.of(PresetLoader.parse("d.json", catalogueScene("denim", "")));
        Scene swapped = Scene.of(PresetLoader.parse("i.json", catalogueScene("interlock", "")));
        assertEquals("interlock", swapped.fabric().name);
        swapped.useFabric(FabricCatalogue.named("denim"));
        double mass = 0;
        Particles p = swapped.cloth().particles();
        for (int i = 0; i < p.count(); i++) mass += p.mass(i);
        assertEquals(0.324 * 0.25, mass, 1e-12);
        for (int s = 0; s < 40; s++) { denim.simulation().step(); swapped.simulation().step(); }
        double[] a = denim.cloth().particles().positions(), b = p.positions();
        for (int k = 0; k < a.length; k++) assertEquals(a[k], b[k], 1e-12, "coordinate " + k);
        assertTrue(p.isPinned(0), "pins stay pinned");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Scene.builtIn("hanging").useFabric(FabricCatalogue.named("denim")));
        assertTrue(e.getMessage().startsWith("fabric: this cloth is springs"), e.getMessage());
    }

    @Test
    void badCatalogueUseIsNamed() {
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.parse("c.json", catalogueScene("denimm", "")));
        assertEquals("fabric.catalogue", e.field());
        assertTrue(e.problem().contains("one of denim, interlock"), e.getMessage());
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("c.json", catalogueScene("denim", "\"arealDensity\": 0.3, ")));
        assertEquals("cloth.arealDensity", e.field(), "a catalogue fabric brings its own density");
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("c.json",
                catalogueScene("denim", "").replace("\"catalogue\": \"denim\",", "\"catalogue\": \"denim\", \"shearModulus\": 5,")));
        assertEquals("fabric.shearModulus", e.field());
        e = assertThrows(PresetException.class, () -> PresetLoader.load(java.nio.file.Path.of("data", FabricCatalogue.FILE)));
        assertTrue(e.problem().startsWith("is the fabric catalogue, not a scene"), e.getMessage());
        // A catalogue with a fabric whose sample has no positive-definite stiffness names the field.
        String broken = "{ \"source\": \"s\", \"fabrics\": [ { \"name\": \"x\", \"sample\": \"navy-sparkle-sweat\", \"arealDensity\": 0.224,"
                + " \"stretching\": [12.486332, -19.875324, 3.272434, 17.616289], \"bending\": [59e-6, 40e-6, 45e-6] } ] }";
        e = assertThrows(PresetException.class, () -> PresetLoader.parseCatalogue("fabrics.json", broken));
        assertEquals("fabrics[0].stretching", e.field());
        assertTrue(e.problem().contains("positive-definite"), e.getMessage());
        e = assertThrows(PresetException.class, () -> PresetLoader.parseCatalogue("fabrics.json", broken.replace("[59e-6, 40e-6, 45e-6]", "[59e-6, 40e-6]")));
        assertEquals("fabrics[0].bending", e.field());
        // A bending curve of the wrong shape, or with a negative sample, is named to the sample.
        String denim = "{ \"source\": \"s\", \"fabrics\": [ { \"name\": \"x\", \"sample\": \"11oz-black-denim\", \"arealDensity\": 0.324,"
                + " \"stretching\": [205.352005, 10.234077, 1013.88629, 53.387184], \"bending\": [64e-6, 73e-6, 97e-6],"
                + " \"bendingCurve\": [[60e-6, 61e-6, 62e-6, 20e-6], [60e-6, 61e-6, 68e-6, 36e-6], [108e-6, 113e-6, 121e-6, 80e-6]] } ] }";
        assertEquals(80e-6 / 4, PresetLoader.parseCatalogue("fabrics.json", denim).get(0).bendingCurve.stiffness(40, Math.PI / 2), 1e-20, "the last sample along v");
        e = assertThrows(PresetException.class, () -> PresetLoader.parseCatalogue("fabrics.json", denim.replace("[60e-6, 61e-6, 68e-6, 36e-6]", "[60e-6, 61e-6, -68e-6, 36e-6]")));
        assertEquals("fabrics[0].bendingCurve[1][2]", e.field());
        e = assertThrows(PresetException.class, () -> PresetLoader.parseCatalogue("fabrics.json", denim.replace(", [108e-6, 113e-6, 121e-6, 80e-6]", "")));
        assertEquals("fabrics[0].bendingCurve", e.field());
        assertTrue(e.problem().contains("must be 3 rows"), e.getMessage());
    }

    /** README's table of fabrics is the catalogue's, row for row. */
    @Test
    void readmeTableIsTheCatalogue() throws java.io.IOException {
        String readme = java.nio.file.Files.readString(java.nio.file.Path.of("docs/fabric.md"));
        for (Fabric f : FabricCatalogue.all()) assertTrue(readme.contains(row(f)), "docs/fabric.md lists " + row(f));
    }

    static String row(Fabric f) {
        return String.format(Locale.ROOT, "| `%s` | %s | %.0f | %.0f | %.0f | %.3f | %.1f | %.1e |", f.name, f.description,
                1000 * f.arealDensity, f.membrane.warpModulus, f.membrane.weftModulus, f.membrane.poisson, f.membrane.shearModulus, f.bendingStiffness);
    }
}
