package xpbdcloth.engine;

import java.util.Arrays;

/**
 * The cloth keeps its thickness between a vertex and a face of another part of itself: a vertex may not come
 * closer than the thickness t to a triangle it was not near at rest, on the side of the triangle's plane it
 * was on when the substep began, and slides on it with Coulomb friction. Particle pairs alone let a layer
 * pass between three particles of another wherever the spacing exceeds t; this holds the face itself.
 *
 * <pre>
 *   q = Σᵢ βᵢ x_fᵢ      the point of face f closest to the vertex p (βᵢ its barycentric weights)
 *   on the face:         C(x) = σ (x_p − q) · n − t ≥ 0      n the face's unit normal, σ = ±1 the side p held
 *   on an edge or corner: C(x) = |x_p − q| − t ≥ 0            n = (x_p − q)/|x_p − q|, σ = 1
 *   ∇_p C = σ n,   ∇_fᵢ C = −σ βᵢ n,   Σ w|∇C|² = w_p + Σᵢ βᵢ² w_fᵢ
 * </pre>
 * Hard (α = 0), projected only while violated: Δλ = −C / (w_p + Σ βᵢ² w_fᵢ), Δx_p = w_p Δλ σ n,
 * Δx_fᵢ = −βᵢ w_fᵢ Δλ σ n (inverse-mass weighted: momentum kept, pins unmoved); then the relative
 * tangential displacement over the substep, r = Δx_p − Σ βᵢ Δx_fᵢ less its normal part, is removed entirely
 * while under μₛ times the normal correction, else by μₖ times it, shared by the same weights (as the particle
 * pairs' friction, {@link SelfCollision}). The side σ is read once per substep, from where the vertex and the
 * face were when it began (the previous positions): a vertex the prediction carried through the face is put
 * back on the side it came from, not pushed on through (an unsigned distance would finish the crossing).
 * A vertex more than {@link #DEEP} thicknesses past the face on the other side is left alone: it has crossed,
 * possibly before the substep began, so the side it began on is the wrong one, and pulling it back through
 * would fight the cloth. Preventing the crossing is the {@link CrossingGuard}'s, putting it back the
 * {@link CrossingUntangler}'s.
 * Sources: the point–triangle proximity of Bridson, Fedkiw and Anderson 2002, "Robust treatment of
 * collisions, contact and friction for cloth animation", §6, as a position-based constraint (Müller et al.
 * 2007, §4.4, "Collisions", the one-sided triangle constraint); closest point as Ericson 2005, §5.1.5.
 *
 * <p>Candidates are kept in a list as the particle pairs' ({@link SelfCollision}) are, with the same reach
 * and skin: every vertex within t(1 + slack) + s, plus its own and the face's motion in the prediction, of a
 * face, from a {@link TriangleGrid} of the faces' reaches, listed again once some particle has drifted s/2
 * (with its motion) from where the list saw it, so no pair outside the list can come within t(1 + slack). A vertex of the face, a stitched partner of one ({@code same}), or a vertex closer than
 * {@link SelfCollision#NEIGHBOURHOOD} thicknesses to the face at rest is its neighbour: the cloth's own
 * constraints keep them apart. The lists grow only when a cloth needs more than before (0 bytes a step once
 * grown), and never past {@link #MOST_FACES} faces a vertex.
 */
final class PointTriangleContacts extends Collider {
    /**
     * A vertex more than this many thicknesses past the face, on the side it did not begin on, has crossed and
     * is not pulled back. Pulled back from any depth, the twisted cloth (docs/contacts.md) was thrown about at
     * 40 m/s within 0.3 s of its first wraps, its layers held on the sides they had crossed to.
     */
    static final double DEEP = 1;

    /** The most faces one vertex lists (a vertex in a crushed stack of layers may be near many). */
    static final int MOST_FACES = 64;
    private final int[] triangles;
    private final double[] rest;
    private final int[] same;
    private final double thickness;
    private final TriangleGrid grid;
    private final double neighbours2;
    private final TriangleGrid.Query query = new TriangleGrid.Query();
    private double[] boxes = new double[0];
    // The listed (vertex, face) pairs, and the side each vertex held at this substep's start.
    private int[] vertexOf = new int[16], faceOf = new int[16];
    private byte[] side = new byte[16];
    private int pairs;
    /** Builds where some vertex found more than {@link #MOST_FACES} faces and listed the first of them. */
    private long overloads;
    /** Scratch: the projections' closest points, and a measurement's (read from another thread, the sketch's). */
    private final double[] closest = new double[6], measured = new double[6];

    PointTriangleContacts(int[] triangles, double[] rest, int[] same, double thickness, double staticFriction, double kineticFriction) {
        super(0, staticFriction, kineticFriction);
        if (triangles == null || triangles.length == 0 || triangles.length % 3 != 0)
            throw new IllegalArgumentException("triangles must hold 3 particle indices per triangle, had " + (triangles == null ? "null" : triangles.length + " numbers"));
        final int n = rest.length / 3;
        for (int k = 0; k < triangles.length; k++)
            if (triangles[k] < 0 || triangles[k] >= n)
                throw new IllegalArgumentException("triangles[" + k + "] must be a particle index in [0, " + n + "), was " + triangles[k]);
        if (same != null && same.length != n)
            throw new IllegalArgumentException("same must hold one entry per particle (" + n + "), had " + same.length);
        this.triangles = triangles.clone();
        this.rest = rest;
        this.same = same;
        this.thickness = thickness;
        // Cells as wide as a face's reach at rest (its edge and the listing reach, 1.75 t, either side): a box
        // then spans two cells an axis; cells a mean edge wide put every reach over TriangleGrid's most cells,
        // in the list every query reads.
        final double reach = (1 + ContactSet.SLACK + SelfCollision.SKIN) * thickness;
        final double meanEdge = CrossingGuard.meanEdge(TriangleEdges.of(this.triangles, n).ends(), rest);
        this.grid = new TriangleGrid(meanEdge + 2 * reach);
        // The particle pairs' neighbourhood. Two thicknesses and a mean edge held drop-fold at 128² (t = 0.9 of the
        // spacing) to 0–1 crossing pairs where this leaves 615, but let denim-fold's tight creases cross (12, not 1).
        this.neighbours2 = SelfCollision.NEIGHBOURHOOD * SelfCollision.NEIGHBOURHOOD * thickness * thickness;
    }

    /** (vertex, face) pairs listed at the last build. */
    int pairCount() { return pairs; }

    /** Builds that listed only the first {@link #MOST_FACES} faces of some vertex. */
    long overloads() { return overloads; }

    /**
     * Lists every (vertex, face) pair that can come within t(1 + slack) before some particle drifts half the
     * skin from here, each particle's reach being its motion in the prediction ({@code reach}, one per particle).
     * The owner ({@link SelfCollision}) calls this when its particle pairs are listed again: the same reach, skin
     * and drift decide both lists, measured once.
     */
    void list(Particles p, double[] reach) {
        final double base = (1 + ContactSet.SLACK + SelfCollision.SKIN) * thickness;
        final double[] x = p.x, w = p.w;
        final int faces = triangles.length / 3, n = p.count();
        if (boxes.length < 6 * faces) boxes = new double[6 * faces];
        for (int f = 0; f < faces; f++) {
            final int a = triangles[3 * f], b = triangles[3 * f + 1], c = triangles[3 * f + 2];
            final double grow = base + Math.max(reach[a], Math.max(reach[b], reach[c]));
            for (int d = 0; d < 3; d++) {
                final double va = x[3 * a + d], vb = x[3 * b + d], vc = x[3 * c + d];
                boxes[6 * f + d] = Math.min(va, Math.min(vb, vc)) - grow;
                boxes[6 * f + 3 + d] = Math.max(va, Math.max(vb, vc)) + grow;
            }
        }
        grid.build(boxes, faces);
        pairs = 0;
        for (int i = 0; i < n; i++) {
            final int k = 3 * i;
            final double xi = x[k], yi = x[k + 1], zi = x[k + 2], ri = reach[i];
            final int found = grid.query(query, xi - ri, yi - ri, zi - ri, xi + ri, yi + ri, zi + ri);
            final int[] list = query.found();
            int listed = 0;
            for (int s = 0; s < found; s++) {
                final int f = list[s];
                final int a = triangles[3 * f], b = triangles[3 * f + 1], c = triangles[3 * f + 2];
                if (w[i] + w[a] + w[b] + w[c] == 0 || touches(i, a, b, c)) continue;
                // A corner nearer at rest than the neighbourhood makes the face nearer still: the cheap test first.
                if (restSquared(k, a) < neighbours2 || restSquared(k, b) < neighbours2 || restSquared(k, c) < neighbours2) continue;
                TriangleGeometry.closestPoint(xi, yi, zi, x, a, b, c, closest);
                final double reachPair = base + ri + Math.max(reach[a], Math.max(reach[b], reach[c]));
                if (distanceSquared(xi, yi, zi, closest) >= reachPair * reachPair) continue;
                TriangleGeometry.closestPoint(rest[k], rest[k + 1], rest[k + 2], rest, a, b, c, closest);
                if (distanceSquared(rest[k], rest[k + 1], rest[k + 2], closest) < neighbours2) continue;
                if (listed == MOST_FACES) { overloads++; break; }
                add(i, f);
                listed++;
            }
        }
    }

    /** Whether vertex i is a corner of the face (a, b, c), or stitched to one. */
    private boolean touches(int i, int a, int b, int c) {
        if (i == a || i == b || i == c) return true;
        if (same == null) return false;
        final int s = same[i];
        return s == same[a] || s == same[b] || s == same[c];
    }

    /** The squared rest distance between particle k/3 and particle j. */
    private double restSquared(int k, int j) {
        final double dx = rest[k] - rest[3 * j], dy = rest[k + 1] - rest[3 * j + 1], dz = rest[k + 2] - rest[3 * j + 2];
        return dx * dx + dy * dy + dz * dz;
    }

    private static double distanceSquared(double x, double y, double z, double[] q) {
        final double dx = x - q[0], dy = y - q[1], dz = z - q[2];
        return dx * dx + dy * dy + dz * dz;
    }

    private void add(int i, int f) {
        if (pairs == vertexOf.length) {
            vertexOf = Arrays.copyOf(vertexOf, 2 * pairs);
            faceOf = Arrays.copyOf(faceOf, 2 * pairs);
            side = Arrays.copyOf(side, 2 * pairs);
        }
        vertexOf[pairs] = i;
        faceOf[pairs] = f;
        pairs++;
    }

    /**
     * The listed pairs as this substep's contacts ({@link #list} keeps the list), each with the side of the
     * face's plane its vertex began the substep on.
     */
    @Override void findContacts(Particles p, double h, ContactSet contacts) {
        final double[] prev = p.prev;
        for (int m = 0; m < pairs; m++) {
            final int i = vertexOf[m], f = faceOf[m], k = 3 * i;
            final int a = 3 * triangles[3 * f], b = 3 * triangles[3 * f + 1], c = 3 * triangles[3 * f + 2];
            final double e1x = prev[b] - prev[a], e1y = prev[b + 1] - prev[a + 1], e1z = prev[b + 2] - prev[a + 2];
            final double e2x = prev[c] - prev[a], e2y = prev[c + 1] - prev[a + 1], e2z = prev[c + 2] - prev[a + 2];
            final double nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
            final double s = (prev[k] - prev[a]) * nx + (prev[k + 1] - prev[a + 1]) * ny + (prev[k + 2] - prev[a + 2]) * nz;
            side[m] = (byte) (s < 0 ? -1 : 1);
            contacts.add(i, m, this);
        }
    }

    @Override void project(Particles p, int m, double h) {
        final double[] x = p.x, prev = p.prev, w = p.w;
        final int i = vertexOf[m], f = faceOf[m];
        final int ia = triangles[3 * f], ib = triangles[3 * f + 1], ic = triangles[3 * f + 2];
        final int k = 3 * i, a = 3 * ia, b = 3 * ib, c = 3 * ic;
        final int feature = TriangleGeometry.closestPoint(x[k], x[k + 1], x[k + 2], x, ia, ib, ic, closest);
        final double ba = closest[3], bb = closest[4], bc = closest[5];
        double nx, ny, nz, C;
        if (feature == TriangleGeometry.FACE) {
            final double e1x = x[b] - x[a], e1y = x[b + 1] - x[a + 1], e1z = x[b + 2] - x[a + 2];
            final double e2x = x[c] - x[a], e2y = x[c + 1] - x[a + 1], e2z = x[c + 2] - x[a + 2];
            nx = e1y * e2z - e1z * e2y; ny = e1z * e2x - e1x * e2z; nz = e1x * e2y - e1y * e2x;
            final double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
            if (!(len > 0)) return; // a face folded flat has no normal: its neighbours' contacts hold the vertex
            final double s = side[m] / len;
            nx *= s; ny *= s; nz *= s;
            final double d = (x[k] - closest[0]) * nx + (x[k + 1] - closest[1]) * ny + (x[k + 2] - closest[2]) * nz;
            if (d < -DEEP * thickness) return;
            C = d - thickness;
        } else {
            nx = x[k] - closest[0]; ny = x[k + 1] - closest[1]; nz = x[k + 2] - closest[2];
            final double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
            if (len < DistanceBlock.MIN_LENGTH) return;
            C = len - thickness;
            nx /= len; ny /= len; nz /= len;
        }
        if (C >= 0) return;
        final double wp = w[i], wa = w[ia], wb = w[ib], wc = w[ic];
        final double W = wp + ba * ba * wa + bb * bb * wb + bc * bc * wc;
        if (W == 0) return;
        final double l = -C / W;
        move(x, k, wp * l, nx, ny, nz);
        move(x, a, -ba * wa * l, nx, ny, nz);
        move(x, b, -bb * wb * l, nx, ny, nz);
        move(x, c, -bc * wc * l, nx, ny, nz);
        // Friction on the vertex's displacement over the substep relative to the face point's, tangent to n.
        double rx = (x[k] - prev[k]) - (ba * (x[a] - prev[a]) + bb * (x[b] - prev[b]) + bc * (x[c] - prev[c]));
        double ry = (x[k + 1] - prev[k + 1]) - (ba * (x[a + 1] - prev[a + 1]) + bb * (x[b + 1] - prev[b + 1]) + bc * (x[c + 1] - prev[c + 1]));
        double rz = (x[k + 2] - prev[k + 2]) - (ba * (x[a + 2] - prev[a + 2]) + bb * (x[b + 2] - prev[b + 2]) + bc * (x[c + 2] - prev[c + 2]));
        final double along = rx * nx + ry * ny + rz * nz;
        rx -= along * nx; ry -= along * ny; rz -= along * nz;
        final double slip = Math.sqrt(rx * rx + ry * ry + rz * rz);
        if (slip == 0) return;
        final double removed = slip < staticFriction * -C ? 1.0 : Math.min(kineticFriction * -C / slip, 1.0);
        final double s = removed / W;
        move(x, k, -wp * s, rx, ry, rz);
        move(x, a, ba * wa * s, rx, ry, rz);
        move(x, b, bb * wb * s, rx, ry, rz);
        move(x, c, bc * wc * s, rx, ry, rz);
    }

    private static void move(double[] x, int k, double by, double dx, double dy, double dz) {
        x[k] += by * dx; x[k + 1] += by * dy; x[k + 2] += by * dz;
    }

    @Override double clearance(Particles p, int m) {
        final double[] x = p.x;
        final int i = vertexOf[m], f = faceOf[m], k = 3 * i;
        TriangleGeometry.closestPoint(x[k], x[k + 1], x[k + 2], x, triangles[3 * f], triangles[3 * f + 1], triangles[3 * f + 2], measured);
        return Math.sqrt(distanceSquared(x[k], x[k + 1], x[k + 2], measured)) - thickness;
    }

    /** The face's corners of contact m, with its vertex (marked by the contact set), held by it. */
    @Override void markOthers(int m, boolean[] held) {
        final int f = faceOf[m];
        held[triangles[3 * f]] = held[triangles[3 * f + 1]] = held[triangles[3 * f + 2]] = true;
    }

    @Override boolean internal() { return true; }

    /** The cloth's thickness is no solid a point can be inside. */
    @Override public double clearanceAt(double x, double y, double z) { return Double.POSITIVE_INFINITY; }
}
