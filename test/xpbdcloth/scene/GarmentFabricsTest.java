package xpbdcloth.scene;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.MembraneBlock;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;
import xpbdcloth.fabric.Fabric;
import xpbdcloth.pattern.PatternMesh;

/**
 * A garment of several fabrics: each panel weighs its own fabric's areal density times its cut area, and
 * stretches and bends as its own fabric; a strip of two fabrics sewn end to end hangs as statics says.
 */
class GarmentFabricsTest {
    static final double G = 9.81;

    /**
     * The bordered tablecloth (a polyester top, a denim border): every particle carries a third of each of its
     * triangles' flat areas at that triangle's panel's density, and the cloth weighs the square's area at
     * polyester's density plus the four trapezoids' at denim's; F makes it all one fabric, weighing the
     * whole cut area at that fabric's density.
     */
    @Test
    void eachPanelWeighsItsOwnFabric() {
        Scene scene = Scene.builtIn("bordered-tablecloth");
        PatternMesh pattern = scene.preset().cloth.garment.pattern;
        double top = FabricCatalogue.named("tablecloth").arealDensity, border = FabricCatalogue.named("denim").arealDensity;
        assertEquals("tablecloth (top), denim (front border, right border, back border, left border)", scene.cutFrom());
        assertEquals(java.util.List.of(FabricCatalogue.named("tablecloth"), FabricCatalogue.named("denim")), scene.fabrics(), "each fabric once");
        double[] expected = lumped(pattern, new double[] {top, border, border, border, border});
        Particles p = scene.cloth().particles();
        double total = 0;
        for (int i = 0; i < p.count(); i++) {
            assertEquals(expected[i], p.mass(i), 1e-15 * expected[i], "particle " + i);
            total += p.mass(i);
        }
        // A 90 cm square and four trapezoids 102 cm and 90 cm along their parallel sides, 6 cm apart.
        assertEquals(0.81 * top + 4 * (1.02 + 0.90) / 2 * 0.06 * border, total, 1e-12);

        Fabric interlock = FabricCatalogue.named("interlock");
        scene.useFabric(interlock);
        assertNull(scene.cutFrom(), "one fabric now");
        assertEquals(java.util.List.of(interlock), scene.fabrics());
        double ρ = interlock.arealDensity;
        expected = lumped(pattern, new double[] {ρ, ρ, ρ, ρ, ρ});
        total = 0;
        for (int i = 0; i < p.count(); i++) {
            assertEquals(expected[i], p.mass(i), 1e-15 * expected[i], "particle " + i + " after F");
            total += p.mass(i);
        }
        assertEquals((0.81 + 4 * (1.02 + 0.90) / 2 * 0.06) * ρ, total, 1e-12);
    }

    /** m_i = Σ over the triangles at i of ρ(panel) · (flat area) / 3, the areas from the pattern's own plane. */
    static double[] lumped(PatternMesh pattern, double[] density) {
        double[] flat = pattern.flatPositions(), mass = new double[flat.length / 2];
        int[] t = pattern.triangles(), panel = pattern.panelOfTriangle();
        for (int k = 0; k < t.length; k += 3) {
            int a = t[k], b = t[k + 1], c = t[k + 2];
            double area = 0.5 * Math.abs((flat[2 * b] - flat[2 * a]) * (flat[2 * c + 1] - flat[2 * a + 1]) - (flat[2 * c] - flat[2 * a]) * (flat[2 * b + 1] - flat[2 * a + 1]));
            for (int v : new int[] {a, b, c}) mass[v] += density[panel[k / 3]] * area / 3;
        }
        return mass;
    }

    /**
     * A strip 10 cm wide: 30 cm of interlock on top, held along its top edge, and 15 cm of denim sewn to its
     * bottom edge. At rest the interlock's middle carries the denim's weight and the lower half of its own,
     * T = g (ρ_denim · 0.1 · 0.15 + ρ_interlock · 0.1 · 0.15) / 0.1 per metre of width, and stretches along its
     * warp (the strip's length) as its own modulus E₁ says. The membrane is Saint Venant–Kirchhoff: the second
     * Piola–Kirchhoff stress is E₁ E_uu (E_uu the Green strain), and the load per rest width is
     * T = (1 + ε) E₁ E_uu with 1 + ε = √(1 + 2E_uu). Cut from one fabric, the load would be 27 % less. Steps
     * of twenty 0.1 ms substeps: at so short a substep inertia dominates each solve and five sweeps converge
     * it, so the rest reached is the static equilibrium, not the solver's (at 10 ms and 100 sweeps the strip
     * sags 16 % more).
     */
    @Test
    void aStripOfTwoFabricsHangsAsStaticsSays(@org.junit.jupiter.api.io.TempDir Path folder) throws Exception {
        Files.writeString(folder.resolve("strip.json"), "{ \"name\": \"strip\", \"description\": \"interlock over denim\", \"edge\": 0.0125,"
                + " \"panels\": ["
                + " { \"name\": \"upper\", \"fabric\": \"interlock\", \"grain\": [0, 1], \"outline\": [{\"at\": [0, 0]}, {\"at\": [0.1, 0]}, {\"at\": [0.1, 0.3]}, {\"at\": [0, 0.3]}],"
                + "   \"position\": [0, 1.15, 0], \"rotation\": [0, 0, 0] },"
                + " { \"name\": \"lower\", \"fabric\": \"denim\", \"grain\": [0, 1], \"outline\": [{\"at\": [0, 0]}, {\"at\": [0.1, 0]}, {\"at\": [0.1, 0.15]}, {\"at\": [0, 0.15]}],"
                + "   \"position\": [0, 0.925, 0], \"rotation\": [0, 0, 0] } ],"
                + " \"seams\": [ { \"name\": \"join\", \"a\": {\"panel\": \"upper\", \"from\": 0, \"to\": 1}, \"b\": {\"panel\": \"lower\", \"from\": 3, \"to\": 2, \"backward\": true} } ] }");
        Preset preset = PresetLoader.parseBeside("strip-preset.json", "{ \"name\": \"strip\", \"description\": \"a strip of two fabrics\","
                + " \"cloth\": { \"pattern\": \"strip.json\", \"sewing\": { \"time\": 0 } },"
                + " \"solver\": { \"mode\": \"XPBD\", \"iterations\": 5, \"substeps\": 20, \"dt\": 0.002, \"mullerCorrection\": true, \"gravity\": [0, -9.81, 0], \"damping\": 20 } }", folder);
        Scene scene = Scene.of(preset);
        Simulation sim = scene.simulation();
        Particles p = sim.particles();
        PatternMesh pattern = preset.cloth.garment.pattern;
        int[] upper = pattern.panelVertexRange(0);
        for (int i = upper[0]; i < upper[1]; i++) if (p.y(i) > 1.3 - 1e-9) p.pin(i);
        MembraneBlock membrane = null;
        for (ConstraintBlock b : sim.blocks()) if (b instanceof MembraneBlock) membrane = (MembraneBlock) b;
        int[] panelOf = pattern.panelOfTriangle();
        double[] flat = pattern.flatPositions();
        int[] t = pattern.triangles();
        double before = Double.NaN, strain = 0;
        for (int step = 1; step <= 3000; step++) {
            sim.step();
            if (step % 100 != 0) continue;
            // The mean warp Green strain of the interlock's triangles in its middle third (pattern y 0.1 to 0.2).
            double sum = 0;
            int count = 0;
            for (int k = 0; k < t.length / 3; k++) {
                double y = (flat[2 * t[3 * k] + 1] + flat[2 * t[3 * k + 1] + 1] + flat[2 * t[3 * k + 2] + 1]) / 3;
                if (panelOf[k] != 0 || y < 0.1 || y > 0.2) continue;
                sum += membrane.strain(k, p)[0];
                count++;
            }
            strain = sum / count;
            if (Math.abs(strain - before) < 1e-5 * Math.abs(strain)) break;
            before = strain;
        }
        Fabric interlock = FabricCatalogue.named("interlock"), denim = FabricCatalogue.named("denim");
        double expected = G * (denim.arealDensity * 0.1 * 0.15 + interlock.arealDensity * 0.1 * 0.15) / 0.1;
        double measured = Math.sqrt(1 + 2 * strain) * interlock.membrane.warpModulus * strain;
        System.out.printf("two-fabric strip: warp Green strain %.5f, load %.4f N/m, statics %.4f N/m%n", strain, measured, expected);
        assertEquals(expected, measured, 0.01 * expected);
    }
}
