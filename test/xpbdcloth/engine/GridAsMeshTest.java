package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import xpbdcloth.mesh.ClothMesh;

/**
 * The grid is one generator of a mesh, and the families derived from the mesh's topology are exactly the
 * original simulator's grid families: the same constraints, over the same particles, in the same order.
 */
class GridAsMeshTest {

    /** The seed's grid families, listed the way its builder looped (the reference the mesh path must equal). */
    static List<String> seedGridFamilies(int columns, int rows) {
        List<String> out = new ArrayList<>();
        for (int r = 0; r < rows; r++)
            for (int c = 0; c < columns; c++) {
                int i = r * columns + c;
                if (c + 1 < columns) out.add("STRUCTURAL " + i + " " + (i + 1));
                if (r + 1 < rows) out.add("STRUCTURAL " + i + " " + (i + columns));
            }
        for (int r = 0; r + 1 < rows; r++)
            for (int c = 0; c + 1 < columns; c++) {
                int i = r * columns + c;
                out.add("SHEAR " + i + " " + (i + 1) + " " + (i + columns));
            }
        for (int r = 0; r < rows; r++)
            for (int c = 0; c < columns; c++) {
                int i = r * columns + c;
                if (c + 2 < columns) out.add("BEND " + i + " " + (i + 1) + " " + (i + 2));
                if (r + 2 < rows) out.add("BEND " + i + " " + (i + columns) + " " + (i + 2 * columns));
            }
        return out;
    }

    static List<String> describe(Cloth cloth) {
        List<String> out = new ArrayList<>();
        for (Constraint c : cloth.constraints()) {
            StringBuilder s = new StringBuilder(c.family().name());
            for (int i : c.particles()) s.append(' ').append(i);
            out.add(s.toString());
        }
        return out;
    }

    static ClothBuilder allFamilies(int columns, int rows) {
        return new ClothBuilder().family(ConstraintFamily.STRUCTURAL, 1, 0).resolution(columns, rows).size(0.7, 0.5).arealDensity(0.2)
                .family(ConstraintFamily.SHEAR, 0.5, 1e-3).family(ConstraintFamily.BEND, 0.1, 1e-2);
    }

    @Test
    void gridFamiliesAreTheSeeds() {
        int[][] shapes = {{8, 6}, {2, 2}, {3, 7}, {1, 12}, {12, 1}, {32, 32}};
        for (int[] s : shapes) {
            Cloth cloth = allFamilies(s[0], s[1]).build();
            assertEquals(seedGridFamilies(s[0], s[1]), describe(cloth), s[0] + "x" + s[1]);
        }
    }

    /**
     * The grid's mesh given to the general builder with an areal density (mass lumped by face area)
     * gives the same constraints with the same rest values, and the same masses to rounding.
     */
    @Test
    void theGridsMeshThroughTheGeneralBuilderIsTheSameCloth() {
        ClothBuilder grid = allFamilies(9, 7);
        Cloth direct = grid.build();
        ClothMesh mesh = grid.mesh();
        Cloth viaMesh = new MeshClothBuilder(mesh).family(ConstraintFamily.STRUCTURAL, 1, 0).arealDensity(0.2)
                .family(ConstraintFamily.SHEAR, 0.5, 1e-3).family(ConstraintFamily.BEND, 0.1, 1e-2).build();
        assertEquals(describe(direct), describe(viaMesh));
        for (int k = 0; k < direct.constraints().size(); k++) {
            Constraint a = direct.constraints().get(k), b = viaMesh.constraints().get(k);
            assertEquals(a.evaluate(direct.particles()), b.evaluate(viaMesh.particles()), 0.0, "constraint " + k + " at rest");
            assertEquals(a.compliance(), b.compliance(), 0.0);
            assertEquals(a.stiffness(), b.stiffness(), 0.0);
        }
        for (int i = 0; i < mesh.vertexCount(); i++)
            assertEquals(direct.particles().mass(i), viaMesh.particles().mass(i), 1e-15, "mass of particle " + i);
        assertArrayEquals(direct.triangles(), viaMesh.triangles(), "the alternating diagonals survive");
        double total = 0;
        for (int i = 0; i < mesh.vertexCount(); i++) total += viaMesh.particles().mass(i);
        assertEquals(0.2 * 0.7 * 0.5, total, 1e-15, "areal density × area");
    }

    /** A rope is a polyline: links and bends, no faces, mass shared by length. */
    @Test
    void ropeIsAPolyline() {
        double[] x = new double[3 * 5];
        for (int i = 0; i < 5; i++) x[3 * i + 1] = -0.1 * i;
        Cloth rope = new MeshClothBuilder(ClothMesh.polyline(x)).family(ConstraintFamily.STRUCTURAL, 1, 0).totalMass(0.4).family(ConstraintFamily.BEND, 1, 0).pin(0).build();
        assertEquals(List.of("STRUCTURAL 0 1", "STRUCTURAL 1 2", "STRUCTURAL 2 3", "STRUCTURAL 3 4", "BEND 0 1 2", "BEND 1 2 3", "BEND 2 3 4"), describe(rope));
        assertEquals(0.05, rope.particles().mass(0), 1e-15, "an end stands for half a link");
        assertEquals(0.1, rope.particles().mass(2), 1e-15);
        assertEquals(0, rope.triangles().length);
        assertFalse(rope.isGrid());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> rope.index(0, 0));
        assertTrue(e.getMessage().startsWith("row and col address a grid cloth"), e.getMessage());
        IllegalArgumentException d = assertThrows(IllegalArgumentException.class, () -> new MeshClothBuilder(ClothMesh.polyline(x)).family(ConstraintFamily.STRUCTURAL, 1, 0).arealDensity(0.2).build());
        assertTrue(d.getMessage().startsWith("arealDensity needs a mesh of non-zero area"), d.getMessage());
    }
}
