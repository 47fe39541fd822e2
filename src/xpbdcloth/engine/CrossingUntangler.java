package xpbdcloth.engine;

import java.util.Arrays;
import xpbdcloth.mesh.TriangleIntersections;

/**
 * The safety net under self-collision: a cloth that has passed through itself anyway (between particles kept
 * apart only as particles, or a crossing the guard let through) is pushed back, each crossed vertex to the
 * side of the face it held when it was last free of a crossing. At the end of a step every edge that pierces
 * a face is found (where the face shares no vertex with at least one of the edge's triangles: exactly the
 * triangle pairs the measure, {@code TriangleIntersections}, counts, with its segment–triangle test); the end of the edge that changed sides
 * of the face since then is the one that went through, and one contact per piercing puts it back:
 * <pre>
 *   C(x) = σ (x_p − Σᵢ βᵢ x_fᵢ) · n − g ≥ 0
 *   ∇_p C = σ n,   ∇_fᵢ C = −σ βᵢ n
 *   Δλ = −C / (w_p + Σᵢ βᵢ² w_fᵢ),   Δx_p = w_p Δλ σ n,   Δx_fᵢ = −βᵢ w_fᵢ Δλ σ n
 * </pre>
 * with p the end that went through, fᵢ the face's corners and βᵢ the piercing point's barycentric
 * coordinates, n the face's unit normal, σ the side of the face's plane p held in the history, and g the gap
 * it is put back at (a tenth of the thickness: the particle pairs then hold the layers apart; put back
 * farther, a vertex in a stack of layers is pushed into the next). Where both ends or neither changed sides,
 * the end nearer the plane is put back. One contact moves at most a mean edge, so a side read from an old
 * history cannot fling the cloth. Passes (find, put back) run in the order found, up to {@link #MOST_PASSES}
 * a step, and the step keeps the pass that left the fewest piercings, so untangling never leaves a step more
 * crossed than it found it.
 *
 * <p>The history is per particle: after each step, every particle no remaining piercing holds (an end of
 * the edge or a corner of the face) takes its position as its clean one, and the others keep the one they
 * had when last free. A single clean snapshot of the whole cloth would go stale while any crossing lasted (a
 * fold that stays crossed for a second turns its faces over, and the sides they had then say nothing now).
 * This is the history-based route; Baraff, Witkin and Kass 2003 ("Untangling cloth") decide the sides with
 * no history, by flood-filling the regions the intersection contours bound, which is not done here.
 *
 * <p>Only positions move: the velocities the step made are kept, so untangling adds no speed; linear momentum
 * is kept by each contact (the moves are inverse-mass weighted) and pinned particles (inverse mass 0) never
 * move. Stitched particles ({@code same}) are taken as one in telling neighbours from crossings, as in
 * {@link CrossingGuard}; each is moved on its own, and the sewing's weld joins them again. Candidates come from
 * a {@link TriangleGrid} of the faces' boxes rebuilt each pass; nothing is allocated once the arrays have
 * grown to the most piercings seen. Where it fails: a piercing whose face and edge are all pinned (a grip
 * driven through the cloth) can only be answered by the free side, and layers that the solve pushes through
 * each other again every step are put back every step, at the cost of the passes. Measured: docs/contacts.md.
 */
public final class CrossingUntangler {
    /** Passes (find the piercings, put them back) a step at most. */
    static final int MOST_PASSES = 8;
    /**
     * The most candidate faces a search reads per edge, on average: a cloth whose edges' boxes span most of it
     * (flung apart, or crossing nearly all of itself) would cost edges × faces tests a pass; past this the
     * step is left as it is ({@link #overloads()}).
     */
    static final int MOST_CANDIDATES = 512;

    private final int particles;
    private final int[] triangles, edges, same;
    /** Each edge's opposite corners in its first two triangles (−1 where it has one): a face touching its triangles is a neighbour. */
    private final int[] opposite;
    private final double gap, meanEdge;
    private final TriangleGrid grid;
    private final TriangleGrid.Query query = new TriangleGrid.Query();
    private final double[] faceBoxes, clean;
    /** The positions of the pass that left the fewest piercings this step (the step's own if none did better). */
    private final double[] fewest;
    /** Particles a piercing left at the step's end hold this step's stamp: their clean positions are kept. */
    private final int[] held;
    private int stamp;
    private boolean hasClean;
    /** The piercings of the current pass: the edge, the face, and where on the face (β₁, β₂). */
    private int[] pierceEdge = new int[16], pierceFace = new int[16];
    private double[] pierceAt = new double[32];
    /** Where the last test found a piercing on its face (β₁, β₂). */
    private final double[] hit = new double[2];
    private int pierces;
    private long pushed, left, tangledSteps, overloads;

    /**
     * @param triangles the cloth's triangles, 3 particle indices each
     * @param rest      the rest positions, xyz interleaved (for the mean edge the grid's cells are sized by)
     * @param same      particles {@code same[i] == same[j]} taken as one (a garment's stitched pairs), or null
     * @param thickness the self-collision thickness, m: a crossed vertex is put back a tenth of it from the face
     */
    public CrossingUntangler(int[] triangles, double[] rest, int[] same, double thickness) {
        if (triangles == null || triangles.length % 3 != 0)
            throw new IllegalArgumentException("triangles must hold 3 particle indices each, had " + (triangles == null ? "null" : triangles.length + " indices"));
        if (rest == null || rest.length % 3 != 0)
            throw new IllegalArgumentException("rest must hold x, y, z per particle, had " + (rest == null ? "null" : rest.length + " numbers"));
        particles = rest.length / 3;
        for (int k = 0; k < triangles.length; k++) Check.index("triangles", triangles[k], particles);
        if (same != null && same.length != particles)
            throw new IllegalArgumentException("same must name a particle per particle (" + particles + "), had " + same.length);
        this.triangles = triangles.clone();
        this.same = new int[particles];
        for (int i = 0; i < particles; i++) this.same[i] = same == null ? i : Check.index("same", same[i], particles);
        this.gap = 0.1 * Check.inRange("thickness", thickness, Double.MIN_NORMAL, EngineRange.MAX_RADIUS);
        final TriangleEdges numbered = TriangleEdges.of(this.triangles, particles);
        edges = numbered.ends();
        opposite = new int[edges.length];
        for (int e = 0; e < numbered.count(); e++) {
            opposite[2 * e] = oppositeCorner(numbered.firstSide(e));
            opposite[2 * e + 1] = oppositeCorner(numbered.secondSide(e));
        }
        final double mean = CrossingGuard.meanEdge(edges, rest);
        grid = new TriangleGrid(mean);
        meanEdge = mean;
        faceBoxes = new double[2 * this.triangles.length];
        clean = new double[3 * particles];
        fewest = new double[3 * particles];
        held = new int[particles];
    }

    /** Contacts projected since it was made (one per piercing per pass). */
    public long pushed() { return pushed; }

    /** Piercings still there at the end of a step after the last pass, summed over steps. */
    public long left() { return left; }

    /** Steps that ended with the cloth pierced before the passes (each untangled, or tried). */
    public long tangledSteps() { return tangledSteps; }

    /** Steps left as they were because a search would have read more than {@link #MOST_CANDIDATES} faces per edge. */
    public long overloads() { return overloads; }

    /** Forgets the history (a scene reset, or positions set by hand): the next step's positions are the history. */
    public void forget() { hasClean = false; }

    /**
     * At the end of a step: finds the cloth's piercings and puts them back, up to {@link #MOST_PASSES} passes,
     * then updates the history. Returns the piercings left.
     */
    int untangle(Particles p) {
        final double[] x = p.x, w = p.w;
        int found = find(x);
        if (found < 0) { overloads++; return 0; }
        if (found > 0) {
            tangledSteps++;
            System.arraycopy(x, 0, fewest, 0, fewest.length);
            int least = found;
            for (int pass = 0; pass < MOST_PASSES && found > 0; pass++) {
                putBack(x, w);
                found = find(x);
                if (found < 0) { found = Integer.MAX_VALUE; break; } // overloaded by this pass's moves: the fewest is kept below
                if (found < least) {
                    least = found;
                    System.arraycopy(x, 0, fewest, 0, fewest.length);
                }
            }
            if (found > least) {
                // Puts back where the passes left the fewest: untangling never leaves a step more crossed than it found it.
                System.arraycopy(fewest, 0, x, 0, fewest.length);
                found = find(x); // the piercings of the state kept, for the history: as many as the least seen
            }
        }
        left += found;
        if (finite(x)) remember(x);
        return found;
    }

    /**
     * Keeps, as each particle's clean position, where it is now unless a piercing still holds it (an end of the
     * edge or a corner of the face): a particle caught in a crossing keeps the position it had when it was
     * last free of one, and the rest of the cloth a history as recent as the step. One clean snapshot of the
     * whole cloth would grow stale while any crossing lasted (a fold that stays crossed for seconds turns its
     * faces over, and the sides they had then say nothing now).
     */
    private void remember(double[] x) {
        if (++stamp == Integer.MAX_VALUE) { Arrays.fill(held, 0); stamp = 1; }
        for (int k = 0; k < pierces; k++) {
            held[edges[2 * pierceEdge[k]]] = stamp;
            held[edges[2 * pierceEdge[k] + 1]] = stamp;
            for (int c = 0; c < 3; c++) held[triangles[3 * pierceFace[k] + c]] = stamp;
        }
        if (pierces == 0 || !hasClean) System.arraycopy(x, 0, clean, 0, clean.length);
        else for (int i = 0; i < particles; i++)
            if (held[i] != stamp) { clean[3 * i] = x[3 * i]; clean[3 * i + 1] = x[3 * i + 1]; clean[3 * i + 2] = x[3 * i + 2]; }
        hasClean = true;
    }

    /**
     * Finds every edge that pierces a face, but for neighbours ({@link #shares}); returns how many, or −1 past
     * {@link #MOST_CANDIDATES} faces read per edge.
     */
    private int find(double[] x) {
        final int faces = triangles.length / 3;
        for (int f = 0; f < faces; f++) {
            final int b = 6 * f, a = 3 * triangles[3 * f], c = 3 * triangles[3 * f + 1], d = 3 * triangles[3 * f + 2];
            for (int k = 0; k < 3; k++) {
                faceBoxes[b + k] = Math.min(x[a + k], Math.min(x[c + k], x[d + k]));
                faceBoxes[b + 3 + k] = Math.max(x[a + k], Math.max(x[c + k], x[d + k]));
            }
        }
        grid.build(faceBoxes, faces);
        pierces = 0;
        long budget = (long) MOST_CANDIDATES * (edges.length / 2);
        for (int e = 0; e < edges.length; e += 2) {
            final int a = edges[e], b = edges[e + 1];
            final int n = grid.query(query, Math.min(x[3 * a], x[3 * b]), Math.min(x[3 * a + 1], x[3 * b + 1]), Math.min(x[3 * a + 2], x[3 * b + 2]),
                    Math.max(x[3 * a], x[3 * b]), Math.max(x[3 * a + 1], x[3 * b + 1]), Math.max(x[3 * a + 2], x[3 * b + 2]));
            if ((budget -= n) < 0) { pierces = 0; return -1; }
            final int[] hits = query.found();
            for (int k = 0; k < n; k++) {
                final int f = hits[k];
                if (shares(e / 2, f)) continue; // the grid returns only faces whose box overlaps the edge's
                pierce(x, e / 2, a, b, f);
            }
        }
        return pierces;
    }

    /** Records edge a→b piercing face f, with where on the face, if it does (the measure's own test). */
    private void pierce(double[] x, int edge, int a, int b, int f) {
        if (!TriangleIntersections.segmentHit(x, a, b, triangles[3 * f], triangles[3 * f + 1], triangles[3 * f + 2], hit)) return;
        if (pierces == pierceEdge.length) {
            pierceEdge = Arrays.copyOf(pierceEdge, 2 * pierces);
            pierceFace = Arrays.copyOf(pierceFace, 2 * pierces);
            pierceAt = Arrays.copyOf(pierceAt, 4 * pierces);
        }
        pierceEdge[pierces] = edge;
        pierceFace[pierces] = f;
        pierceAt[2 * pierces] = hit[0];
        pierceAt[2 * pierces + 1] = hit[1];
        pierces++;
    }

    /** One contact per piercing, in the order found (Gauss–Seidel: each sees the moves before it). */
    private void putBack(double[] x, double[] w) {
        for (int k = 0; k < pierces; k++) {
            final int a = edges[2 * pierceEdge[k]], b = edges[2 * pierceEdge[k] + 1], f = pierceFace[k];
            final int f0 = triangles[3 * f], f1 = triangles[3 * f + 1], f2 = triangles[3 * f + 2];
            final double b1 = pierceAt[2 * k], b2 = pierceAt[2 * k + 1], b0 = Math.max(0, 1 - b1 - b2);
            double nx, ny, nz;
            {
                final double e1x = x[3 * f1] - x[3 * f0], e1y = x[3 * f1 + 1] - x[3 * f0 + 1], e1z = x[3 * f1 + 2] - x[3 * f0 + 2];
                final double e2x = x[3 * f2] - x[3 * f0], e2y = x[3 * f2 + 1] - x[3 * f0 + 1], e2z = x[3 * f2 + 2] - x[3 * f0 + 2];
                nx = e1y * e2z - e1z * e2y; ny = e1z * e2x - e1x * e2z; nz = e1x * e2y - e1y * e2x;
                final double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
                if (!(len > 0)) continue;
                nx /= len; ny /= len; nz /= len;
            }
            final double sa = side(x, a, f0, nx, ny, nz), sb = side(x, b, f0, nx, ny, nz);
            if (sa * sb > 0) continue; // an earlier contact this pass already took the edge off the face
            int through;
            double sigma;
            final double ca = hasClean ? cleanSide(a, f) : 0, cb = hasClean ? cleanSide(b, f) : 0;
            final boolean aCrossed = ca != 0 && Math.signum(ca) != Math.signum(sa), bCrossed = cb != 0 && Math.signum(cb) != Math.signum(sb);
            if (aCrossed && !bCrossed) { through = a; sigma = Math.signum(ca); }
            else if (bCrossed && !aCrossed) { through = b; sigma = Math.signum(cb); }
            else if (Math.abs(sa) <= Math.abs(sb)) { through = a; sigma = sb >= 0 ? 1 : -1; }
            else { through = b; sigma = sa >= 0 ? 1 : -1; }
            final double s = through == a ? sa : sb;
            final double constraint = sigma * s - gap;
            if (constraint >= 0) continue;
            final double denominator = w[through] + b0 * b0 * w[f0] + b1 * b1 * w[f1] + b2 * b2 * w[f2];
            if (!(denominator > 0)) continue; // all pinned: nothing can move
            // At most a mean edge a contact: a side read from an old history must not fling the cloth.
            final double step = Math.min(-constraint, meanEdge) / denominator * sigma;
            move(x, through, w[through] * step, nx, ny, nz);
            move(x, f0, -b0 * w[f0] * step, nx, ny, nz);
            move(x, f1, -b1 * w[f1] * step, nx, ny, nz);
            move(x, f2, -b2 * w[f2] * step, nx, ny, nz);
            pushed++;
        }
    }

    /** The signed distance of particle i from face f's plane when the cloth was last clean. */
    private double cleanSide(int i, int f) {
        final int f0 = triangles[3 * f], f1 = triangles[3 * f + 1], f2 = triangles[3 * f + 2];
        final double e1x = clean[3 * f1] - clean[3 * f0], e1y = clean[3 * f1 + 1] - clean[3 * f0 + 1], e1z = clean[3 * f1 + 2] - clean[3 * f0 + 2];
        final double e2x = clean[3 * f2] - clean[3 * f0], e2y = clean[3 * f2 + 1] - clean[3 * f0 + 1], e2z = clean[3 * f2 + 2] - clean[3 * f0 + 2];
        final double nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
        return (clean[3 * i] - clean[3 * f0]) * nx + (clean[3 * i + 1] - clean[3 * f0 + 1]) * ny + (clean[3 * i + 2] - clean[3 * f0 + 2]) * nz;
    }

    private static double side(double[] x, int i, int f0, double nx, double ny, double nz) {
        return (x[3 * i] - x[3 * f0]) * nx + (x[3 * i + 1] - x[3 * f0 + 1]) * ny + (x[3 * i + 2] - x[3 * f0 + 2]) * nz;
    }

    private static void move(double[] x, int i, double by, double nx, double ny, double nz) {
        x[3 * i] += by * nx;
        x[3 * i + 1] += by * ny;
        x[3 * i + 2] += by * nz;
    }

    /**
     * Whether edge e piercing face f is no crossing: f has one of the edge's ends, or shares a vertex with each
     * of the edge's triangles. A piercing counts where the face shares no vertex with at least one of them,
     * exactly the triangle pairs the measure ({@code TriangleIntersections}) counts.
     */
    private boolean shares(int e, int f) {
        final int a = same[edges[2 * e]], b = same[edges[2 * e + 1]];
        final int c = opposite[2 * e] < 0 ? -1 : same[opposite[2 * e]], d = opposite[2 * e + 1] < 0 ? -1 : same[opposite[2 * e + 1]];
        boolean hasC = false, hasD = false;
        for (int k = 0; k < 3; k++) {
            final int s = same[triangles[3 * f + k]];
            if (s == a || s == b) return true;
            hasC |= s == c;
            hasD |= s == d;
        }
        return hasC && (d < 0 || hasD);
    }

    private int oppositeCorner(int side) {
        return side < 0 ? -1 : triangles[side - side % 3 + (side % 3 + 2) % 3];
    }

    private static boolean finite(double[] x) {
        for (double v : x) if (!Double.isFinite(v)) return false;
        return true;
    }
}
