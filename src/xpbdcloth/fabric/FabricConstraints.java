package xpbdcloth.fabric;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.PriorityQueue;
import xpbdcloth.engine.BendingPatch;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.DihedralBlock;
import xpbdcloth.engine.MembraneBlock;
import xpbdcloth.engine.OrthotropicMaterial;
import xpbdcloth.engine.QuadraticBendBlock;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.TetherBlock;
import xpbdcloth.engine.TriangleEdges;

/**
 * A cloth as a material rather than as springs: from a triangle mesh at rest, the membrane of every
 * triangle ({@link MembraneBlock}, warp along a given in-plane direction), bending ({@link BendingPatch}
 * rows on every triangle where the rest is flat, {@link DihedralBlock} hinges where it is not) and, if
 * asked, a tether from every free particle to its nearest pinned one along the mesh ({@link TetherBlock}). The blocks' constants come from the material's
 * moduli and the mesh's rest shape, so the same fabric on a finer mesh is the same cloth.
 */
public final class FabricConstraints {
    private FabricConstraints() {}

    /**
     * @param p         the cloth's particles at rest (pinned ones have inverse mass 0)
     * @param triangles three particle indices per triangle
     * @param warp      the warp direction (x, y, z), projected into each triangle's plane; or one per
     *                  triangle (3 numbers each, e.g. {@link #warpFromTextureCoordinates})
     * @param membrane  in-plane elasticity
     * @param bendingStiffness B, N·m (per unit width)
     * @param tethers   whether to tether free particles to their nearest pin
     * @return the membrane block, the bending blocks ({@link #bends}) and (if asked and anything is pinned) the tether block, in that order
     */
    public static List<ConstraintBlock> build(Particles p, int[] triangles, double[] warp, OrthotropicMaterial membrane,
                                              double bendingStiffness, boolean tethers) {
        return build(p, triangles, warp, membrane, bendingStiffness, tethers, false);
    }

    /**
     * As {@link #build(Particles, int[], double[], OrthotropicMaterial, double, boolean)}, with bending that may
     * yield: then every hinge is a {@link DihedralBlock}, the one model whose rest angle can move
     * ({@link xpbdcloth.engine.HingePlasticity}); the quadratic models hold a flat rest.
     */
    public static List<ConstraintBlock> build(Particles p, int[] triangles, double[] warp, OrthotropicMaterial membrane,
                                              double bendingStiffness, boolean tethers, boolean yielding) {
        if (triangles == null || triangles.length == 0 || triangles.length % 3 != 0)
            throw new IllegalArgumentException("triangles must hold three indices per triangle, had " + (triangles == null ? "null" : triangles.length));
        if (warp == null || warp.length != 3 && warp.length != triangles.length)
            throw new IllegalArgumentException("warp must be a direction (x, y, z) or one per triangle (" + triangles.length + " numbers), was "
                    + (warp == null ? "null" : warp.length + " numbers"));
        MembraneBlock m = new MembraneBlock(ConstraintFamily.MEMBRANE, triangles.length / 3);
        for (int t = 0; t < triangles.length; t += 3) {
            int w = warp.length == 3 ? 0 : t;
            m.addTriangle(p, triangles[t], triangles[t + 1], triangles[t + 2], warp[w], warp[w + 1], warp[w + 2], membrane);
        }
        List<ConstraintBlock> blocks = new ArrayList<>(List.of(m));
        blocks.addAll(yielding ? hinges(p, triangles, bendingStiffness, true) : bends(p, triangles, bendingStiffness));
        if (tethers) {
            TetherBlock t = tethers(p, triangles);
            if (t.count() > 0) blocks.add(t);
        }
        return blocks;
    }

    /**
     * The warp of each triangle from the mesh's texture coordinates: the direction in which u grows,
     * ∂x/∂u = (Δv₂ e₁ − Δv₁ e₂)/(Δu₁Δv₂ − Δu₂Δv₁) with e_k = x_k − x₀ and Δ the corners' (u, v) less
     * corner 0's (the usual tangent of texture space, as for normal mapping). Pattern pieces laid out in
     * UV space then keep their grain however the mesh was cut.
     *
     * @param uvs (u, v) of each triangle's corners, 6 per triangle
     * @return 3 numbers per triangle (not normalised; {@link MembraneBlock} projects and normalises)
     */
    public static double[] warpFromTextureCoordinates(Particles p, int[] triangles, double[] uvs) {
        if (uvs == null || uvs.length != 2 * triangles.length)
            throw new IllegalArgumentException("uvs must hold 6 numbers per triangle (" + 2 * triangles.length + "), was " + (uvs == null ? "null" : uvs.length));
        double[] out = new double[triangles.length];
        for (int t = 0; t < triangles.length / 3; t++) {
            int a = triangles[3 * t], b = triangles[3 * t + 1], c = triangles[3 * t + 2];
            double du1 = uvs[6 * t + 2] - uvs[6 * t], dv1 = uvs[6 * t + 3] - uvs[6 * t + 1];
            double du2 = uvs[6 * t + 4] - uvs[6 * t], dv2 = uvs[6 * t + 5] - uvs[6 * t + 1];
            double det = du1 * dv2 - du2 * dv1;
            double size = Math.max(Math.abs(du1) + Math.abs(dv1), Math.abs(du2) + Math.abs(dv2));
            if (!(Math.abs(det) > 1e-12 * size * size))
                throw new IllegalArgumentException("triangle " + t + " (" + a + ", " + b + ", " + c + ") has texture coordinates of zero area: no warp direction there");
            out[3 * t] = (dv2 * (p.x(b) - p.x(a)) - dv1 * (p.x(c) - p.x(a))) / det;
            out[3 * t + 1] = (dv2 * (p.y(b) - p.y(a)) - dv1 * (p.y(c) - p.y(a))) / det;
            out[3 * t + 2] = (dv2 * (p.z(b) - p.z(a)) - dv1 * (p.z(c) - p.z(a))) / det;
        }
        return out;
    }

    /** A flat hinge's rest angle may differ from 0 by this much (rad) and still bend quadratically. */
    static final double FLAT = 1e-6;

    /**
     * The bending of the cloth: where the rest mesh is flat across every edge, {@link BendingPatch} rows on
     * every triangle (in {@link QuadraticBendBlock}s of patches, by the particles a triangle's rows take),
     * whose energy is the plate's whatever the triangulation; otherwise {@link #hinges}. The blocks that have any.
     */
    static List<ConstraintBlock> bends(Particles p, int[] triangles, double bendingStiffness) {
        BendingPatch patch = new BendingPatch(p.positions(), p.count(), triangles);
        for (int t = 0; t < triangles.length; t += 3)
            for (int e = 0; e < 3; e++) {
                int across = patch.across(t / 3, e);
                if (across >= 0 && !QuadraticBendBlock.isFlat(p, triangles[t + (e + 2) % 3], across, triangles[t + (e + 1) % 3], triangles[t + e], FLAT))
                    return hinges(p, triangles, bendingStiffness, false);
            }
        return new ArrayList<>(patches(p, triangles, patch, bendingStiffness));
    }

    /**
     * A bend on every edge two triangles share (an edge of more than two bends between the first two): a
     * {@link QuadraticBendBlock} of hinges where the rest is flat across it and a {@link DihedralBlock} where it
     * is bent (a rest shape the quadratic model cannot hold), with the discrete-shell weight B|e|²/(A₀ + A₁).
     * A hinge model's stiffness depends on the triangulation (see {@link BendingPatch}): what a cloth bent at
     * rest gets, and the model the patches are measured against. The blocks that have any, in that order.
     * With {@code allDihedral}, flat hinges are dihedral too (a rest angle that may change).
     */
    static List<ConstraintBlock> hinges(Particles p, int[] triangles, double bendingStiffness, boolean allDihedral) {
        QuadraticBendBlock flat = new QuadraticBendBlock(ConstraintFamily.DIHEDRAL, triangles.length / 2);
        DihedralBlock bent = new DihedralBlock(ConstraintFamily.DIHEDRAL, 16);
        TriangleEdges edges = TriangleEdges.of(triangles, p.count());
        // A hinge where the second triangle walks its edge, in the order the triangles come.
        for (int s = 0; s < triangles.length; s++) {
            int edge = edges.edgeOf(s);
            if (edges.secondSide(edge) != s) continue;
            int first = edges.firstSide(edge), t = s - s % 3, a = triangles[s], b = triangles[t + (s % 3 + 1) % 3], opposite = triangles[t + (s % 3 + 2) % 3];
            int other = triangles[first - first % 3 + (first % 3 + 2) % 3];
            // The edge as the first triangle walked it (b→a, the second walking it a→b): the order fixes the angle's sign convention.
            if (!allDihedral && QuadraticBendBlock.isFlat(p, other, opposite, b, a, FLAT)) flat.addAtCurrentShape(p, other, opposite, b, a, bendingStiffness);
            else bent.addAtCurrentShape(p, other, opposite, b, a, bendingStiffness);
        }
        List<ConstraintBlock> out = new ArrayList<>();
        if (flat.count() > 0) out.add(flat);
        if (bent.count() > 0) out.add(bent);
        return out;
    }

    /**
     * {@link BendingPatch} rows on every triangle of a flat cloth that has a neighbour, in one block per
     * number of particles a triangle's rows take (twelve inside the mesh, fewer near its edges), largest first.
     */
    static List<QuadraticBendBlock> patches(Particles p, int[] triangles, double bendingStiffness) {
        return patches(p, triangles, new BendingPatch(p.positions(), p.count(), triangles), bendingStiffness);
    }

    private static List<QuadraticBendBlock> patches(Particles p, int[] triangles, BendingPatch patch, double bendingStiffness) {
        QuadraticBendBlock[] bySlots = new QuadraticBendBlock[BendingPatch.MAX_SLOTS + 1];
        int[] stencil = new int[BendingPatch.MAX_SLOTS];
        double[] rows = new double[3 * BendingPatch.MAX_SLOTS];
        for (int t = 0; t < triangles.length / 3; t++) {
            if (!patch.bends(t)) continue;
            int slots = patch.rows(t, stencil, rows);
            if (bySlots[slots] == null)
                bySlots[slots] = QuadraticBendBlock.patches(ConstraintFamily.DIHEDRAL, slots, slots == BendingPatch.MAX_SLOTS ? triangles.length / 3 : 16);
            bySlots[slots].addPatch(stencil, slots, rows, bendingStiffness);
        }
        List<QuadraticBendBlock> out = new ArrayList<>();
        for (int slots = BendingPatch.MAX_SLOTS; slots >= 4; slots--) if (bySlots[slots] != null) out.add(bySlots[slots]);
        return out;
    }

    /** Each free particle tethered to its nearest pin along the rest mesh's edges (Dijkstra from all pins). */
    static TetherBlock tethers(Particles p, int[] triangles) {
        int n = p.count();
        List<List<int[]>> neighbours = new ArrayList<>();
        for (int i = 0; i < n; i++) neighbours.add(new ArrayList<>());
        for (int t = 0; t < triangles.length; t += 3)
            for (int e = 0; e < 3; e++) {
                int a = triangles[t + e], b = triangles[t + (e + 1) % 3];
                neighbours.get(a).add(new int[] {b});
                neighbours.get(b).add(new int[] {a});
            }
        double[] distance = new double[n];
        int[] anchor = new int[n];
        Arrays.fill(distance, Double.POSITIVE_INFINITY);
        Arrays.fill(anchor, -1);
        PriorityQueue<double[]> queue = new PriorityQueue<>((u, v) -> Double.compare(u[0], v[0]));
        for (int i = 0; i < n; i++)
            if (p.inverseMass(i) == 0) { distance[i] = 0; anchor[i] = i; queue.add(new double[] {0, i}); }
        while (!queue.isEmpty()) {
            double[] top = queue.poll();
            int i = (int) top[1];
            if (top[0] > distance[i]) continue;
            for (int[] j : neighbours.get(i)) {
                double d = distance[i] + dist(p, i, j[0]);
                if (d < distance[j[0]]) { distance[j[0]] = d; anchor[j[0]] = anchor[i]; queue.add(new double[] {d, j[0]}); }
            }
        }
        TetherBlock block = new TetherBlock(ConstraintFamily.TETHER, n);
        for (int i = 0; i < n; i++) if (p.inverseMass(i) > 0 && anchor[i] >= 0) block.add(anchor[i], i, distance[i]);
        return block;
    }

    private static double dist(Particles p, int a, int b) {
        double dx = p.x(a) - p.x(b), dy = p.y(a) - p.y(b), dz = p.z(a) - p.z(b);
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }
}
