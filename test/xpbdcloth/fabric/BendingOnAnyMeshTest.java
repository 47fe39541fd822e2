package xpbdcloth.fabric;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import xpbdcloth.engine.BendingPatch;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.QuadraticBendBlock;

/**
 * The bending patches' energy is the plate's, ½ B |II|² per area, whatever the triangulation: a sheet curved
 * uniformly in any direction stores ½ B κ² per area on every mesh a cloth comes on, a twist stores B τ², and
 * no flat placement or rigid motion stores anything.
 */
class BendingOnAnyMeshTest {
    static final double B = 2e-5;

    static List<StripMeshes.Mesh> meshes() {
        return List.of(
                StripMeshes.grid(0.2, 0.1, 20, 10, true),
                StripMeshes.grid(0.2, 0.1, 20, 10, false),
                StripMeshes.grid(0.2, 0.1, 10, 15, true),  // cells 20 × 6.7 mm: aspect ratio 3
                StripMeshes.grid(0.2, 0.1, 30, 5, false),  // cells 6.7 × 20 mm, the other way
                StripMeshes.delaunay(0.2, 0.1, 0.01, 1));
    }

    /** The rows of the triangles no free edge reaches ({@link BendingPatch#surrounded}), and their rest area. */
    static List<QuadraticBendBlock> surroundedPatches(StripMeshes.Mesh mesh, Particles p, double[] areaOut) {
        BendingPatch patch = new BendingPatch(p.positions(), p.count(), mesh.triangles);
        QuadraticBendBlock[] bySlots = new QuadraticBendBlock[BendingPatch.MAX_SLOTS + 1];
        int[] stencil = new int[BendingPatch.MAX_SLOTS];
        double[] rows = new double[3 * BendingPatch.MAX_SLOTS];
        for (int t = 0; t < mesh.triangles.length / 3; t++) {
            if (!patch.surrounded(t)) continue;
            int n = patch.rows(t, stencil, rows);
            if (bySlots[n] == null) bySlots[n] = QuadraticBendBlock.patches(ConstraintFamily.DIHEDRAL, n, 16);
            bySlots[n].addPatch(stencil, n, rows, B);
            areaOut[0] += mesh.area(3 * t);
        }
        List<QuadraticBendBlock> out = new java.util.ArrayList<>();
        for (QuadraticBendBlock b : bySlots) if (b != null) out.add(b);
        assertTrue(areaOut[0] > 0.5 * 0.2 * 0.1, mesh + ": most of the sheet is surrounded");
        return out;
    }

    static double energy(List<QuadraticBendBlock> blocks, Particles p) {
        double e = 0;
        for (QuadraticBendBlock b : blocks) e += FabricConstraintMathsTest.energy(b, p);
        return e;
    }

    @Test
    void aUniformlyCurvedSheetStoresHalfBKappaSquaredPerAreaOnEveryMeshInEveryDirection() {
        double kappa = 4; // r = 25 cm over a 20 × 10 cm sheet
        for (StripMeshes.Mesh mesh : meshes())
            for (double degrees : new double[] {0, 30, 45, 60, 90, 135}) {
                Particles p = mesh.particles(0.3);
                double[] area = {0};
                List<QuadraticBendBlock> patches = surroundedPatches(mesh, p, area);
                double dx = Math.cos(Math.toRadians(degrees)), dz = Math.sin(Math.toRadians(degrees));
                // Roll the sheet (y = 0) into a cylinder whose generators run along (−dz, 0, dx): an isometry.
                FabricConstraintMathsTest.moveAll(p, q -> {
                    double s = q[0] * dx + q[2] * dz, t = -q[0] * dz + q[2] * dx, angle = s * kappa;
                    double along = Math.sin(angle) / kappa, up = (1 - Math.cos(angle)) / kappa;
                    return new double[] {along * dx - t * dz, up, along * dz + t * dx};
                });
                double expected = 0.5 * B * kappa * kappa * area[0];
                assertEquals(expected, energy(patches, p), 0.005 * expected, mesh + ", curved at " + degrees + "°: energy against ½Bκ²A");
            }
    }

    @Test
    void aTwistStoresBTauSquaredPerArea() {
        double tau = 1.5; // y = τ x z: twist rate τ, H = [[0, τ], [τ, 0]], |II|² = 2τ²
        for (StripMeshes.Mesh mesh : meshes()) {
            Particles p = mesh.particles(0.3);
            double[] area = {0};
            List<QuadraticBendBlock> patches = surroundedPatches(mesh, p, area);
            FabricConstraintMathsTest.moveAll(p, q -> new double[] {q[0], tau * (q[0] - 0.1) * (q[2] - 0.05), q[2]});
            double expected = B * tau * tau * area[0];
            assertEquals(expected, energy(patches, p), 0.01 * expected, mesh + ": twist energy against Bτ²A");
        }
    }

    @Test
    void noFlatPlacementOrRigidMotionStoresEnergy() {
        Random random = new Random(3);
        for (StripMeshes.Mesh mesh : meshes()) {
            Particles p = mesh.particles(0.3);
            List<ConstraintBlock> bends = FabricConstraints.bends(p, mesh.triangles, B);
            int rows = 0;
            for (ConstraintBlock b : bends) {
                assertTrue(((QuadraticBendBlock) b).isPatchBlock(), mesh + ": a flat cloth bends by patches alone");
                rows += b.count();
            }
            assertEquals(9 * mesh.triangles.length / 3, rows, mesh + ": three vector rows for every triangle");
            // Any affine map of the plane into space (a rotation, a shear, a stretch, a shift) leaves it flat.
            double[] m = new double[9];
            for (int k = 0; k < 9; k++) m[k] = 2 * random.nextDouble() - 1;
            FabricConstraintMathsTest.moveAll(p, q -> new double[] {
                    m[0] * q[0] + m[1] * q[2] + m[2], m[3] * q[0] + m[4] * q[2] + m[5], m[6] * q[0] + m[7] * q[2] + m[8]});
            for (ConstraintBlock b : bends)
                for (int i = 0; i < b.count(); i++)
                    assertEquals(0, b.evaluate(i, p), 1e-9, mesh + ": row " + i + " of a flat placement");
        }
    }

    @Test
    void sixNeighboursOnOneConicStillBendAsAPlate() {
        // A regular hexagon's corners lie on a circle: the middle triangle (0, 2, 4) and the three across its
        // edges fix no quadratic; the patch leaves one out and the fan still bends, and stays flat when flat.
        Particles p = new Particles(6);
        for (int k = 0; k < 6; k++) p.setPosition(k, Math.cos(k * Math.PI / 3), 0, Math.sin(k * Math.PI / 3));
        int[] triangles = {0, 2, 4, 0, 1, 2, 2, 3, 4, 4, 5, 0};
        List<QuadraticBendBlock> built = FabricConstraints.patches(p, triangles, B);
        assertEquals(4 * 9, built.stream().mapToInt(ConstraintBlock::count).sum(), "three vector rows for each of the four triangles");
        FabricConstraintMathsTest.moveAll(p, q -> new double[] {q[0], 0.5 * q[0] * q[0], q[2]});
        double stored = 0;
        for (QuadraticBendBlock b : built) stored += FabricConstraintMathsTest.energy(b, p);
        assertTrue(stored > 0, "a curved hexagon stores energy, was " + stored);
    }
}
