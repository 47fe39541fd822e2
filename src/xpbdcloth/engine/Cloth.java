package xpbdcloth.engine;

import java.util.Collections;
import java.util.List;

/**
 * A rectangular grid cloth as built by {@link ClothBuilder}: its particles, constraints by family and the
 * triangles a renderer or an aerodynamic force needs. Particle (row, col) has index row·columns + col;
 * row 0 is the top (or far) edge.
 */
public final class Cloth {
    private final Particles particles;
    private final int columns, rows;
    private final List<Constraint> constraints;
    private final int[] triangles;

    Cloth(Particles particles, int columns, int rows, List<Constraint> constraints, int[] triangles) {
        this.particles = particles;
        this.columns = columns;
        this.rows = rows;
        this.constraints = Collections.unmodifiableList(constraints);
        this.triangles = triangles;
    }

    public Particles particles() { return particles; }
    public int columns() { return columns; }
    public int rows() { return rows; }
    public List<Constraint> constraints() { return constraints; }

    /** Particle indices, three per triangle, counter-clockwise seen from +z (vertical) or +y (horizontal). */
    public int[] triangles() { return triangles; }

    public int index(int row, int col) {
        Check.index("row", row, rows);
        Check.index("col", col, columns);
        return row * columns + col;
    }

    /** A simulation of this cloth alone, with its constraints in the builder's order. */
    public Simulation simulation(SolverSettings settings) {
        return new Simulation(particles, settings).addAll(constraints);
    }
}
