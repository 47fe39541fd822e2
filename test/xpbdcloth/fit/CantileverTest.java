package xpbdcloth.fit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import xpbdcloth.TwoAtATime;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SolverSettings;
import xpbdcloth.fabric.Fabric;
import xpbdcloth.fabric.FabricConstraints;
import xpbdcloth.fabric.StripMeshes;
import xpbdcloth.scene.FabricCatalogue;

/**
 * The textile industry's bending test, ASTM D1388's cantilever: a strip of a catalogue fabric clamped flat and
 * overhanging by l comes to rest where its weight and its bending balance. The exact heavy elastica
 * ({@link HeavyElastica}) gives the chord angle from the clamp edge to the tip for l/c (c = (B/w)^⅓, the
 * bending length the industry measures fabrics by); the bending length the simulated strip shows is the c
 * whose elastica has its chord angle. It must be the fabric's own within 2 %, on every triangulation of the
 * strip, from l = c to 3c, at two resolutions (6 and 12 cells per bending length). The rest is the energy's minimum (Newton, {@link Equilibrium}):
 * what is measured is the discrete energy, not how far a solver got.
 *
 * <p>The clamp is the strip's midline, pinned, with a cantilever on either side: by symmetry each leaves it
 * flat, as a clamp holds it. (Pinning a band of particles instead holds the last pinned segment flat, which
 * puts the discrete clamp edge half a cell behind the first free particles: an overhang longer by h/2, 3–8 %
 * on these meshes, that has nothing to do with bending.)
 */
class CantileverTest {
    static final double GRAVITY = 9.81;

    @Test
    void theElasticaMeetsPeircesFortyOneAndAHalfDegreesAtTwiceTheBendingLength() {
        // ASTM D1388 reads c = l/2 where the chord to the tip is 41.5° below horizontal (Peirce 1930).
        assertEquals(41.5, Math.toDegrees(HeavyElastica.of(2).chordAngle()), 0.5);
        assertEquals(2, HeavyElastica.overhangForChordAngle(HeavyElastica.of(2).chordAngle()), 1e-6);
        // Small overhangs bend as a linear beam: tip drop w l⁴/(8B), i.e. chord angle ≈ λ³/8.
        assertEquals(0.2 * 0.2 * 0.2 / 8, HeavyElastica.of(0.2).chordAngle(), 1e-5);
    }

    @Test
    void denimOverhangingTwiceItsBendingLengthShowsItsOwnBendingLengthOnEveryMesh() {
        Fabric denim = FabricCatalogue.named("denim");
        for (StripMeshes.Mesh mesh : meshes(denim, 2, 6)) assertBendingLength(denim, 2, mesh);
    }

    @Test
    @Tag("slow")
    void catalogueFabricsShowTheirBendingLengthFromOneToThreeTimesItOnEveryMeshAtTwoResolutions() throws Exception {
        // Sixty strips, each its own simulation: two at a time, checked in order.
        List<Callable<Void>> strips = new ArrayList<>();
        for (String name : new String[] {"denim", "interlock"}) {
            Fabric fabric = FabricCatalogue.named(name);
            for (double overhang : new double[] {1, 2, 3})
                for (int resolution : new int[] {6, 12})
                    for (StripMeshes.Mesh mesh : meshes(fabric, overhang, resolution))
                        strips.add(() -> { assertBendingLength(fabric, overhang, mesh); return null; });
        }
        TwoAtATime.results(strips);
    }

    static double bendingLength(Fabric fabric) { return Math.cbrt(fabric.bendingStiffness / (fabric.arealDensity * GRAVITY)); }

    /**
     * Meshes of the strip, 2l long (x from −l to l once placed) and 1.25c wide (25 mm for a bending length of
     * 2 cm), {@code perBendingLength} cells along each bending length c: square cells split along alternating
     * and along one diagonal, cells three times longer than wide and three times wider than long, and Delaunay.
     */
    static List<StripMeshes.Mesh> meshes(Fabric fabric, double overhang, int perBendingLength) {
        double c = bendingLength(fabric), l = overhang * c, width = 1.25 * c;
        int cells = (int) Math.round(overhang * perBendingLength);
        double h = l / cells;
        int across = (int) Math.round(width / h);
        List<StripMeshes.Mesh> out = new ArrayList<>();
        out.add(StripMeshes.grid(2 * l, width, 2 * cells, across, true));
        out.add(StripMeshes.grid(2 * l, width, 2 * cells, across, false));
        out.add(StripMeshes.grid(2 * l, width, 2 * cells, 3 * across, true));
        out.add(StripMeshes.grid(2 * l, width, 2 * cells, Math.max(2, (int) Math.round(width / (3 * h))), false));
        out.add(StripMeshes.delaunay(2 * l, width, h, 7, l));
        return out;
    }

    /** Pins the midline, solves the rest, and compares each half's chord angle with the elastica's. */
    static void assertBendingLength(Fabric fabric, double overhang, StripMeshes.Mesh mesh) {
        double c = bendingLength(fabric), l = overhang * c;
        Particles p = mesh.particles(fabric.arealDensity);
        for (int i = 0; i < p.count(); i++) {
            p.setPosition(i, p.x(i) - l, p.y(i), p.z(i));
            if (Math.abs(p.x(i)) <= 1e-9 * c) p.pin(i);
        }
        Simulation sim = new Simulation(p, new SolverSettings().withMode(ConstraintMode.XPBD).withGravity(0, -GRAVITY, 0));
        for (ConstraintBlock b : FabricConstraints.build(p, mesh.triangles, new double[] {1, 0, 0}, fabric.membrane, fabric.bendingStiffness, false))
            sim.add(b);
        ClothEnergy energy = new ClothEnergy(sim, List.of());
        double weight = 0;
        for (int i = 0; i < p.count(); i++) weight = Math.max(weight, p.mass(i) * GRAVITY);
        // Newton starts from the elastica laid on the mesh (a few iterations, not thirty from flat); where it
        // ends is the discrete energy's own minimum.
        HeavyElastica exact = HeavyElastica.of(overhang);
        double[] start = p.positions().clone();
        for (int i = 0; i < p.count(); i++) {
            double[] q = exact.at(Math.abs(start[3 * i]) / c);
            start[3 * i] = Math.signum(start[3 * i]) * q[0] * c;
            start[3 * i + 1] = -q[1] * c;
        }
        Equilibrium rest = Equilibrium.solve(energy, start, weight);
        assertTrue(rest.converged, mesh + ": Newton did not reach the rest (force residual " + rest.forceResidual + " N)");
        for (int side = -1; side <= 1; side += 2) {
            // The tip: the free end's particles, averaged; x from the clamp, drop below it.
            double tipX = 0, tipDrop = 0;
            int n = 0;
            for (int i = 0; i < p.count(); i++)
                if (Math.abs(mesh.positions[3 * i] - l - side * l) < 1e-9 * c) { tipX += side * rest.positions[3 * i]; tipDrop -= rest.positions[3 * i + 1]; n++; }
            double chord = Math.atan2(tipDrop / n, tipX / n);
            double shown = overhang / HeavyElastica.overhangForChordAngle(chord);
            assertEquals(1, shown, 0.02, String.format("%s at l/c = %.1f on %s, %s half: chord %.2f° against the elastica's %.2f°, bending length %.4f c",
                    fabric.name, overhang, mesh, side < 0 ? "left" : "right", Math.toDegrees(chord), Math.toDegrees(HeavyElastica.of(overhang).chordAngle()), shown));
        }
    }
}
