package xpbdcloth.engine;

import java.util.AbstractList;
import java.util.List;
import xpbdcloth.mesh.ClothMesh;

/**
 * A cloth as built by {@link MeshClothBuilder} (or by {@link ClothBuilder}, which makes a grid mesh): its
 * particles (one per mesh vertex, same order), its constraints in Gauss–Seidel order (one block per
 * family, {@link ConstraintBlock}), and the mesh it was
 * built from, whose triangles a renderer, an aerodynamic force or an exporter needs. A grid cloth also
 * answers to (row, col): particle index row·columns + col, row 0 the top (or far) edge.
 */
public final class Cloth {
    private final Particles particles;
    private final ClothMesh mesh;
    private final int columns, rows;
    private final List<ConstraintBlock> blocks;
    private final int[] triangles;

    Cloth(Particles particles, ClothMesh mesh, int columns, int rows, List<ConstraintBlock> blocks) {
        this.particles = particles;
        this.mesh = mesh;
        this.columns = columns;
        this.rows = rows;
        this.blocks = List.copyOf(blocks);
        this.triangles = mesh.triangles();
    }

    public Particles particles() { return particles; }
    /** The constraint blocks in Gauss–Seidel order (structural, shear, bend; those the builder made). */
    public List<ConstraintBlock> blocks() { return blocks; }

    /**
     * Views of the constraints in Gauss–Seidel order, made as they are read. They see the blocks of the
     * first simulation made from this cloth (which takes the blocks over; later ones get copies).
     */
    public List<Constraint> constraints() {
        return new AbstractList<Constraint>() {
            @Override public Constraint get(int i) {
                Check.index("constraint", i, size());
                for (ConstraintBlock b : blocks) {
                    if (i < b.count()) return b.view(i);
                    i -= b.count();
                }
                throw new AssertionError();
            }

            @Override public int size() {
                int n = 0;
                for (ConstraintBlock b : blocks) n += b.count();
                return n;
            }
        };
    }

    /** The rest mesh: faces, groups and the vertex order the particles follow. */
    public ClothMesh mesh() { return mesh; }

    /** True for a cloth made by {@link ClothBuilder}, which {@link #index} can address by row and column. */
    public boolean isGrid() { return columns > 0; }

    /** Grid columns, 0 for a cloth that is not a grid. */
    public int columns() { return columns; }

    /** Grid rows, 0 for a cloth that is not a grid. */
    public int rows() { return rows; }

    /** Particle indices, three per triangle, counter-clockwise seen from the front (+z for a vertical grid, +y for a horizontal one). */
    public int[] triangles() { return triangles; }

    public int index(int row, int col) {
        if (!isGrid())
            throw new IllegalArgumentException("row and col address a grid cloth; this cloth is a mesh of " + particles.count() + " vertices, was (" + row + ", " + col + ")");
        Check.index("row", row, rows);
        Check.index("col", col, columns);
        return row * columns + col;
    }

    /** A simulation of this cloth alone, with its constraints in the builder's order. */
    public Simulation simulation(SolverSettings settings) {
        return new Simulation(particles, settings).addBlocks(blocks);
    }
}
