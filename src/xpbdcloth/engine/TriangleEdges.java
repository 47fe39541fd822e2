package xpbdcloth.engine;

import java.util.Arrays;
import java.util.HashMap;

/**
 * The edges of a triangle mesh, numbered in the order the triangles first walk them. A side is a slot
 * 3t + e of the triangle array, the edge from corner e to corner e + 1 (ab, bc, ca). For each edge: its two
 * vertices (lower first), how many triangles have it, and the first two sides that walk it (on a manifold
 * mesh an inner edge's two triangles, the hinge a bending model puts there). Built once with a cloth or a
 * mesh body.
 */
public final class TriangleEdges {
    private final int[] ends, edgeOfSide, uses, sides;

    private TriangleEdges(int[] ends, int[] edgeOfSide, int[] uses, int[] sides) {
        this.ends = ends;
        this.edgeOfSide = edgeOfSide;
        this.uses = uses;
        this.sides = sides;
    }

    /** The edges of triangles (3 vertex indices each, every index in [0, vertexCount)). */
    public static TriangleEdges of(int[] triangles, int vertexCount) {
        HashMap<Long, Integer> index = new HashMap<>();
        int[] ends = new int[2 * triangles.length], uses = new int[triangles.length], sides = new int[2 * triangles.length];
        int[] edgeOfSide = new int[triangles.length];
        for (int s = 0; s < triangles.length; s++) {
            int a = triangles[s], b = triangles[s % 3 == 2 ? s - 2 : s + 1];
            int lo = Math.min(a, b), hi = Math.max(a, b);
            Integer e = index.get((long) lo * vertexCount + hi);
            if (e == null) {
                e = index.size();
                index.put((long) lo * vertexCount + hi, e);
                ends[2 * e] = lo;
                ends[2 * e + 1] = hi;
                sides[2 * e] = s;
                sides[2 * e + 1] = -1;
            } else if (sides[2 * e + 1] < 0) {
                sides[2 * e + 1] = s;
            }
            uses[e]++;
            edgeOfSide[s] = e;
        }
        int count = index.size();
        return new TriangleEdges(Arrays.copyOf(ends, 2 * count), edgeOfSide, Arrays.copyOf(uses, count), Arrays.copyOf(sides, 2 * count));
    }

    public int count() { return uses.length; }

    /** The edge that side s (slot 3t + e of the triangle array) walks. */
    public int edgeOf(int side) { return edgeOfSide[side]; }

    /** How many triangles have edge e (1 on a border, 2 inside a manifold mesh). */
    public int uses(int e) { return uses[e]; }

    /** The first side that walks edge e. */
    public int firstSide(int e) { return sides[2 * e]; }

    /** The second side that walks edge e, or −1 on a border. */
    public int secondSide(int e) { return sides[2 * e + 1]; }

    /** All edges' vertices, two each, lower first (a copy). */
    public int[] ends() { return ends.clone(); }

    /** Each side's edge (a copy). */
    public int[] edgeOfSides() { return edgeOfSide.clone(); }
}
