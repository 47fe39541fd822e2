package xpbdcloth.engine;

/**
 * A uniform grid's cells hashed into a power-of-two table, the one both self-collision searches use
 * (particles in {@link SelfCollision}, triangles' boxes in {@link TriangleGrid}): the primes of Teschner et
 * al. 2003, "Optimized spatial hashing for collision detection of deformable objects".
 */
final class HashedCells {
    private HashedCells() {}

    /** The cell of a coordinate, for cells of side cell. */
    static int index(double v, double cell) { return (int) Math.floor(v / cell); }

    /** Cell (x, y, z)'s bucket in a table of the given size, a power of two (a mask, not a division). */
    static int bucket(int x, int y, int z, int table) {
        return ((x * 92837111) ^ (y * 689287499) ^ (z * 283923481)) & (table - 1);
    }
}
