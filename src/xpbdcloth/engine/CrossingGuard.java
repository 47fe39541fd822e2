package xpbdcloth.engine;

import java.util.Arrays;

/**
 * Continuous self-collision of the cloth's triangles: a substep may not make the cloth pass through itself.
 * After the solve, each particle is taken to move in a straight line from where the substep began (x_prev)
 * to where the solve put it (x). Two triangles that did not intersect at the start can intersect at the end
 * only if, in between, a vertex passed through a face or an edge through an edge, so those events are all
 * that is looked for (Provot 1997, "Collision and self-collision handling in cloth model dedicated to
 * design garments"; Bridson, Fedkiw and Anderson 2002, "Robust treatment of collisions, contact and friction
 * for cloth animation", §4):
 * <pre>
 *   vertex p, face (a, b, c):  det(x_b − x_a, x_c − x_a, x_p − x_a)(τ) = 0 and p inside the face at τ
 *   edges (p, q) and (r, s):   det(x_q − x_p, x_r − x_p, x_s − x_p)(τ) = 0 and the segments meet at τ
 * </pre>
 * each a cubic in τ ∈ (0, 1] ({@link TriangleGeometry#coplanarCubic}).
 *
 * <p>Response: the motion of an event's four particles is cut back to {@link #BACKOFF} of the time of
 * contact τ, less what would bring them within a small gap of each other (each particle's own fraction fᵢ
 * of its move, xᵢ = x_startᵢ + fᵢ (x_endᵢ − x_startᵢ), multiplied by the smallest over its events, a
 * stitched group's particles by the smallest over the group's; see {@link #keep}), and the pass is
 * repeated on the cut motion until it finds none. After {@link #CUT_PASSES} passes an event's particles
 * are put back where the substep began (f = 0): that state was clean, so the passes end (Bridson et
 * al.'s rigid impact zones play this part there; putting the particles back is the cruder,
 * always-terminating version: they lose the substep's velocity, an inelastic stop). Pinned
 * particles (inverse mass 0) move as their scripts say and are never cut. The cloth's thickness is kept by
 * the particle pairs of {@link SelfCollision} inside the solve; this guard only makes sure that what slips
 * past them does not pass through.
 *
 * <p>Round-off: a cubic within round-off of zero at the substep's end, with the point in the face or the
 * edges meeting, counts as contact then (a layer landing on one that lies on the floor ends exactly in its
 * plane); four points within round-off of one plane all substep (layers pressed flat on the floor) are
 * judged in that plane, edges that meet at the end and did not at the start being put back.
 *
 * <p>Candidates: each vertex with the faces, and each edge with the edges, whose boxes could overlap over
 * the substep, listed from a {@link TriangleGrid} of the triangles' reaches (each particle's motion grown
 * by a skin of {@link #SKIN_EDGES} mean edges) and kept across substeps while every particle stays within
 * its reach moved by one shift common to all (a Verlet list, as the particle pairs keep theirs, that a cloth
 * falling or sliding as a whole does not outrun): searching a grid rebuilt every pass was most of the guard's
 * time, and a cloth that folds slowly keeps its lists for several substeps. The skin
 * sets only how often the lists are made and how long they are, never what is found. Each pass clears the
 * listed pairs by their swept boxes, bounding spheres, the distance at the start against the most the
 * features can move, and the cubic's Bernstein coefficients, before any root is sought. Edge pairs are
 * listed once (the lower-numbered edge holds them). On the solver's team each thread lists and sweeps its
 * share of vertices and edges into cuts of its own, and the smallest is taken: the same bits on any thread
 * count. Nothing is allocated in a substep except when a list is longer than ever before; a list is never
 * longer than {@link #MOST_CANDIDATES} per feature (past it the whole substep is put back where it began).
 * Where it fails: a root at τ = 0 (a vertex exactly in a face's plane and inside it at the substep's start)
 * is taken as a touch, not a crossing; pinned particles pushed through the cloth by their script cannot be
 * stopped (counted in {@link #unresolved()}); a cloth that is already crossed stays so (it keeps a clean
 * cloth clean, it does not untangle: {@link CrossingUntangler} does). Cost: docs/contacts.md.
 */
public final class CrossingGuard implements Team.Job {
    /** The share of the time to contact an event's particles keep of their move. */
    static final double BACKOFF = 0.9;
    /** Passes that cut motion back before an event's particles are put back where the substep began. */
    static final int CUT_PASSES = 4;
    /**
     * The most candidates the lists hold per vertex (faces) and per edge (edges), on average: the sewn skirt
     * and tablecloth list at most 5; a cloth crossing most of itself in one substep would list them all, and
     * is put back instead.
     */
    static final int MOST_CANDIDATES = 512;
    /** At most this many passes; only pinned particles moved by script through the cloth can use them all. */
    static final int MAX_PASSES = 12;
    /** Barycentric and segment-parameter slack: an event on a shared edge or vertex is not missed by round-off. */
    private static final double SLACK = 1e-6;
    /** Boxes are grown by this much (m) so round-off in a refit loses no candidate. */
    private static final double PAD = 1e-9;
    /** Round-off of a coplanarity determinant, relative to its points' size cubed (a few hundred ulps). */
    static final double ROUND_OFF = 1e-13;
    /** The gap an event's features keep, in mean rest edges: far above round-off, far below any thickness. */
    static final double GAP_EDGES = 1e-3;
    /** The grid's cells, in mean rest edges. */
    static final double CELL_EDGES = 1;
    /** How far, in mean rest edges, a particle may move beyond its motion when the candidates were listed before they are listed again. */
    static final double SKIN_EDGES = 0.25;

    private final int particles;
    private final int[] triangles;
    /** Each edge's two vertices, and each triangle's three edges (sides ab, bc, ca). */
    private final int[] edges, triangleEdges;
    private final TriangleGrid grid;
    /** The closest an event's features are let come, m; the skin the candidate lists are made with, m. */
    private final double gap, meanEdge;
    private double skin;
    /**
     * Each particle's reach when the candidates were listed (its motion then, grown by the skin: min xyz, max
     * xyz) and each triangle's, the box of its corners' reaches. While every particle's start and end stay
     * inside its reach, any two features whose swept boxes overlap had overlapping reaches, so they are in the
     * lists: the lists are made again only when a particle leaves its reach (or the thread count changes).
     */
    private final double[] particleReach, triangleReach;
    private boolean listed;
    /** Whether this pass lists the candidates again. */
    private boolean passLists;
    private final double[] start, end, fraction;
    /** Each thread's pass: its cuts, scratch, queries and events. */
    private Share[] shares;
    /** The pass the team's threads run: the positions, inverse masses and whether events put their particles back. */
    private double[] passX, passW;
    private boolean passPutsBack;
    /** Each particle's move this pass, and each triangle's swept box (min xyz, max xyz). */
    private final double[] moved, triangleBox;
    /**
     * Each edge's and then each triangle's bounding sphere at the substep's start (centre, radius: 4 numbers),
     * and the most any of its vertices moves this pass: two features whose spheres are farther apart than
     * both can move cannot meet, which clears most candidates before any exact distance.
     */
    private final double[] sphere, edgeMove, triangleMove;

    private long events, unresolved, passes, overloads, listings;
    /** Each particle's representative: features with one in common are neighbours, never an event. */
    private final int[] same;
    /**
     * Per representative, the smallest cut of a pass over its particles (null when every particle is its
     * own): a welded group moves as one point, so its particles are cut back together. Cut one by one, the
     * weld after the step would pull them together again where the guard never looks.
     */
    private final double[] groupCut;

    /**
     * @param triangles the cloth's triangles, 3 particle indices each
     * @param rest      the rest positions, xyz interleaved (the hierarchy's shape; refitted as the cloth moves)
     */
    public CrossingGuard(int[] triangles, double[] rest) { this(triangles, rest, null); }

    /**
     * As above, with particles {@code same[i] == same[j]} taken as one (a garment's stitched pairs, which its
     * sewing welds): a vertex is not tested against a face, nor an edge against an edge, that has it. Null:
     * each particle its own.
     */
    public CrossingGuard(int[] triangles, double[] rest, int[] same) {
        if (triangles == null || triangles.length % 3 != 0)
            throw new IllegalArgumentException("triangles must hold 3 particle indices each, had " + (triangles == null ? "null" : triangles.length + " indices"));
        if (rest == null || rest.length % 3 != 0)
            throw new IllegalArgumentException("rest must hold x, y, z per particle, had " + (rest == null ? "null" : rest.length + " numbers"));
        particles = rest.length / 3;
        for (int k = 0; k < triangles.length; k++)
            if (triangles[k] < 0 || triangles[k] >= particles)
                throw new IllegalArgumentException("triangles[" + k + "] must be a particle in [0, " + particles + "), was " + triangles[k]);
        this.triangles = triangles.clone();
        if (same != null && same.length != particles)
            throw new IllegalArgumentException("same must name a particle per particle (" + particles + "), had " + same.length);
        this.same = new int[particles];
        for (int i = 0; i < particles; i++) {
            this.same[i] = same == null ? i : same[i];
            if (this.same[i] < 0 || this.same[i] >= particles) throw new IllegalArgumentException("same[" + i + "] must be a particle in [0, " + particles + "), was " + this.same[i]);
        }
        boolean grouped = false;
        for (int i = 0; i < particles; i++) grouped |= this.same[i] != i;
        groupCut = grouped ? new double[particles] : null;
        final TriangleEdges numbered = TriangleEdges.of(this.triangles, particles);
        edges = numbered.ends();
        triangleEdges = numbered.edgeOfSides();
        final double mean = meanEdge(edges, rest);
        grid = new TriangleGrid(CELL_EDGES * mean);
        gap = GAP_EDGES * mean;
        meanEdge = mean;
        skin = SKIN_EDGES * mean;
        particleReach = new double[6 * particles];
        triangleReach = new double[2 * this.triangles.length];
        start = new double[3 * particles];
        end = new double[3 * particles];
        fraction = new double[particles];
        shares = new Share[] {new Share()};
        moved = new double[particles];
        triangleBox = new double[2 * this.triangles.length];
        sphere = new double[4 * (edges.length / 2 + this.triangles.length / 3)];
        edgeMove = new double[edges.length / 2];
        triangleMove = new double[this.triangles.length / 3];
    }

    /** Sets the skin, in mean rest edges (≥ 0), from the next listing on: what is found does not depend on it, only the cost. */
    void skinEdges(double edges) {
        skin = Check.inRange("skinEdges", edges, 0, 100) * meanEdge;
        listed = false;
    }

    /** Events found and cut back since it was made (one per vertex–face or edge–edge contact per pass). */
    public long events() { return events; }

    /** Events still found after the last pass, since it was made: only pinned particles driven through the cloth leave any. */
    public long unresolved() { return unresolved; }

    /** Passes since it was made (one a substep when nothing touches). */
    public long passes() { return passes; }

    /** Substeps put back whole because their candidates would have passed {@link #MOST_CANDIDATES} per feature. */
    public long overloads() { return overloads; }

    /** Times the candidates were listed (the grid of reaches built again). */
    public long listings() { return listings; }

    private boolean overflowed() {
        for (Share sh : shares) if (sh.overflowed) return true;
        return false;
    }

    /**
     * Keeps where the substep begins (the prediction's x_prev, before any contact moves x_prev to undo a
     * depth the particle started at): the clean state the motion is measured from.
     */
    void begin(Particles p) { System.arraycopy(p.prev, 0, start, 0, 3 * particles); }

    /**
     * Cuts back the substep's motion (from {@link #begin}'s positions to x) until no vertex passes through a
     * face and no edge through an edge; the passes on the team's threads if given (the same cuts on any
     * count: each share lowers its own, and the smallest is taken).
     */
    void hold(Particles p, Team team) {
        final int n = particles, threads = team == null ? 1 : team.threads();
        final double[] x = p.x, w = p.w;
        if (shares.length != threads) {
            shares = new Share[threads];
            for (int t = 0; t < threads; t++) shares[t] = new Share();
            listed = false;
        }
        if (!listed || !withinReach(start, x)) relist(start, x);
        System.arraycopy(x, 0, end, 0, 3 * n);
        Arrays.fill(fraction, 1);
        passX = x;
        passW = w;
        startSpheres(start);
        int found = 0;
        for (int pass = 0; pass < MAX_PASSES; pass++) {
            passes++;
            sweptBoxes(start, x);
            passPutsBack = pass >= CUT_PASSES;
            final boolean listing = passLists;
            if (threads == 1) sweep(shares[0], 0, 1);
            else team.run(this);
            passLists = false;
            if (listing && overflowed()) {
                // The cloth moves so far across itself in this substep that nearly every feature may meet nearly
                // every other: listing them all would take memory without bound (a fuzzed cloth under 100 m/s² and a
                // 100 m/s wind needed 6 GB). The start was clean, so the whole substep's motion is put back.
                for (int i = 0; i < n; i++) if (w[i] != 0) System.arraycopy(start, 3 * i, x, 3 * i, 3);
                overloads++;
                listed = false;
                return;
            }
            found = 0;
            for (Share sh : shares) found += sh.found;
            if (found == 0) return;
            events += found;
            if (groupCut != null) {
                Arrays.fill(groupCut, 1);
                for (int i = 0; i < n; i++) groupCut[same[i]] = Math.min(groupCut[same[i]], cut(i, threads));
            }
            for (int i = 0; i < n; i++) {
                final double c = groupCut != null ? groupCut[same[i]] : cut(i, threads);
                if (c == 1 || w[i] == 0) continue;
                fraction[i] *= c;
                final int k = 3 * i;
                final double f = fraction[i];
                x[k] = start[k] + f * (end[k] - start[k]);
                x[k + 1] = start[k + 1] + f * (end[k + 1] - start[k + 1]);
                x[k + 2] = start[k + 2] + f * (end[k + 2] - start[k + 2]);
            }
        }
        unresolved += found;
    }

    /** Particle i's cut in this pass: the smallest any thread's events gave it. */
    private double cut(int i, int threads) {
        double c = shares[0].cut[i];
        for (int t = 1; t < threads; t++) c = Math.min(c, shares[t].cut[i]);
        return c;
    }

    /** A pass on the team: each thread its share of the vertices and of the edges. */
    @Override public void work(int id, Team team) {
        sweep(shares[id], id, team.threads());
        team.await();
    }

    /**
     * One pass over share id's vertices against the faces and its edges against the edges (ascending ranges);
     * each event lowers its particles' cut in the share's own cuts, the events counted in its found.
     */
    private void sweep(Share sh, int id, int count) {
        final double[] x = passX, w = passW, start = this.start, scratch = sh.scratch, closest = sh.closest;
        final boolean putBack = passPutsBack;
        Arrays.fill(sh.cut, 1);
        final int edgeCount = edges.length / 2;
        final double[] sphere = this.sphere;
        int found = 0;
        if (passLists) list(sh, id, count);
        final int[] faces = sh.faces, edgePairs = sh.edgePairs;
        for (int c = 0, lastI = -1, k = 0; c < sh.faceCount; c++) {
            final int i = faces[2 * c], t = faces[2 * c + 1];
            if (i != lastI) { sh.sweptBox(start, x, i, i); lastI = i; k = 3 * i; }
            final int a = triangles[3 * t], b = triangles[3 * t + 1], d = triangles[3 * t + 2];
            if (w[i] + w[a] + w[b] + w[d] == 0 || !sh.overlaps(triangleBox, t)) continue;
            final int o = 4 * (edgeCount + t);
            final double cx = start[k] - sphere[o], cy = start[k + 1] - sphere[o + 1], cz = start[k + 2] - sphere[o + 2];
            final double bound = sphere[o + 3] + moved[i] + triangleMove[t] + PAD;
            if (cx * cx + cy * cy + cz * cz > bound * bound) continue;
            // Apart by more than they move (any point of the face moves at most as far as its fastest corner): no contact.
            TriangleGeometry.closestPoint(start[k], start[k + 1], start[k + 2], start, a, b, d, closest);
            final double gx = closest[0] - start[k], gy = closest[1] - start[k + 1], gz = closest[2] - start[k + 2];
            final double reach = moved[i] + triangleMove[t] + PAD, apart2 = gx * gx + gy * gy + gz * gz;
            if (apart2 > reach * reach) continue;
            TriangleGeometry.coplanarCubic(start, x, a, b, d, start[k], start[k + 1], start[k + 2], x[k], x[k + 1], x[k + 2], scratch);
            final double noise = roundOff(start, a, b, d, i);
            if (oneSigned(scratch, noise)) continue;
            double tau = TriangleGeometry.firstRootInside(start[k], start[k + 1], start[k + 2], x[k], x[k + 1], x[k + 2], start, x, a, b, d, SLACK, 0, noise, scratch);
            if (tau < 0) continue;
            found++;
            sh.stop(i, a, b, d, putBack ? 0 : keep(tau, apart2));
        }
        for (int c = 0, lastE = -1, p = 0, q = 0; c < sh.edgePairCount; c++) {
            final int e = edgePairs[2 * c], f = edgePairs[2 * c + 1];
            if (e != lastE) { p = edges[2 * e]; q = edges[2 * e + 1]; sh.sweptBox(start, x, p, q); lastE = e; }
            final int r = edges[2 * f], s = edges[2 * f + 1];
            if (w[p] + w[q] + w[r] + w[s] == 0 || !sh.nearSwept(start, x, r, s, gap)) continue;
            final double reach = edgeMove[e] + edgeMove[f] + PAD;
            // Bounding spheres at the start farther apart than the features can move: no contact.
            final double cx = sphere[4 * e] - sphere[4 * f], cy = sphere[4 * e + 1] - sphere[4 * f + 1], cz = sphere[4 * e + 2] - sphere[4 * f + 2];
            final double bound = sphere[4 * e + 3] + sphere[4 * f + 3] + reach;
            if (cx * cx + cy * cy + cz * cz > bound * bound) continue;
            final double apart2 = segmentDistanceSquared(0, p, q, r, s, start, start);
            if (apart2 > reach * reach) continue;
            TriangleGeometry.coplanarCubic(start, x, p, q, r, start[3 * s], start[3 * s + 1], start[3 * s + 2], x[3 * s], x[3 * s + 1], x[3 * s + 2], scratch);
            final double noise = roundOff(start, p, q, r, s);
            if (flat(scratch, noise)) {
                // Four points in one plane all the substep (a layer pressed flat on the floor): the cubic is
                // round-off and its roots say nothing; edges that cross in the plane at the end and did not at
                // the start crossed during it. Their particles go back where the substep began.
                if (segmentsMeet(1, p, q, r, s, start, x) && !segmentsMeet(0, p, q, r, s, start, x)) {
                    found++;
                    sh.stop(p, q, r, s, 0);
                }
                continue;
            }
            if (oneSigned(scratch, noise)) continue;
            double tau = firstEdgeContact(p, q, r, s, start, x, noise, scratch);
            if (tau < 0) continue;
            found++;
            sh.stop(p, q, r, s, putBack ? 0 : keep(tau, apart2));
        }
        sh.found = found;
    }

    /**
     * Lists share id's candidates from the grid of the triangles' reaches: its vertices against the faces
     * whose reach overlaps theirs (not their own), its edges against the edges of such faces (each pair once,
     * by the lower-numbered edge; not sharing a vertex), in ascending order of vertex and of edge.
     */
    private void list(Share sh, int id, int count) {
        sh.faceCount = 0;
        sh.overflowed = false;
        final int firstParticle = (int) ((long) particles * id / count), lastParticle = (int) ((long) particles * (id + 1) / count);
        sh.faceCap = (int) Math.min(Integer.MAX_VALUE / 2, (long) MOST_CANDIDATES * (lastParticle - firstParticle));
        for (int i = firstParticle, last = lastParticle; i < last && !sh.overflowed; i++) {
            final int m = sh.reachQuery(i, i);
            final int[] candidates = sh.query.found();
            for (int c = 0; c < m; c++) {
                final int t = candidates[c];
                final int si = same[i];
                if (si == same[triangles[3 * t]] || si == same[triangles[3 * t + 1]] || si == same[triangles[3 * t + 2]]) continue; // the grid returns only faces whose reach overlaps
                sh.addFace(i, t);
            }
        }
        sh.edgePairCount = 0;
        final int edgeCount = edges.length / 2;
        final int[] edgeSeen = sh.edgeSeen;
        final int firstEdge = (int) ((long) edgeCount * id / count), lastEdge = (int) ((long) edgeCount * (id + 1) / count);
        sh.edgePairCap = (int) Math.min(Integer.MAX_VALUE / 2, (long) MOST_CANDIDATES * (lastEdge - firstEdge));
        for (int e = firstEdge, last = lastEdge; e < last && !sh.overflowed; e++) {
            final int p = edges[2 * e], q = edges[2 * e + 1], sp = same[p], sq = same[q];
            if (++sh.edgeStamp == Integer.MAX_VALUE) { Arrays.fill(edgeSeen, 0); sh.edgeStamp = 1; }
            final int stamp = sh.edgeStamp;
            final int m = sh.reachQuery(p, q);
            final int[] candidates = sh.query.found();
            for (int c = 0; c < m; c++) {
                final int t = candidates[c];
                for (int side = 0; side < 3; side++) {
                    final int f = triangleEdges[3 * t + side];
                    if (f <= e || edgeSeen[f] == stamp) continue;
                    edgeSeen[f] = stamp;
                    final int r = edges[2 * f], s = edges[2 * f + 1];
                    final int sr = same[r], ss = same[s];
                    if (sr == sp || sr == sq || ss == sp || ss == sq || !sh.nearReach(r, s, gap)) continue;
                    sh.addEdgePair(e, f);
                }
            }
        }
    }

    /**
     * Whether the lists still hold: some one shift s, the same for every particle, puts each particle's start
     * and end inside its reach (false for a non-finite one). Two features whose reaches did not overlap at
     * listing cannot meet while both lie in their reaches moved by the same s, so a cloth that falls or slides
     * as a whole keeps its lists (s = 0 is the plain Verlet test); only motion of its parts against each other
     * past the skin lists again. Per axis, s is bounded by max(start, x) − hi ≤ s ≤ min(start, x) − lo for every
     * particle, so one pass finds whether such an s exists.
     */
    private boolean withinReach(double[] start, double[] x) {
        for (int d = 0; d < 3; d++) {
            double least = -Double.MAX_VALUE, most = Double.MAX_VALUE;
            for (int i = 0; i < particles; i++) {
                final int k = 3 * i + d;
                final double a = start[k], b = x[k];
                least = Math.max(least, Math.max(a, b) - particleReach[6 * i + 3 + d]);
                most = Math.min(most, Math.min(a, b) - particleReach[6 * i + d]);
            }
            if (!(least <= most)) return false;
        }
        return true;
    }

    /** New reaches about this substep's motion (start → x) grown by the skin, and their grid; the first pass lists the candidates from it. */
    private void relist(double[] start, double[] x) {
        for (int i = 0; i < particles; i++)
            for (int d = 0; d < 3; d++) {
                final int k = 3 * i + d;
                particleReach[6 * i + d] = Math.min(start[k], x[k]) - skin - PAD;
                particleReach[6 * i + 3 + d] = Math.max(start[k], x[k]) + skin + PAD;
            }
        for (int t = 0, count = triangles.length / 3; t < count; t++)
            for (int d = 0; d < 3; d++) {
                double lo = Double.MAX_VALUE, hi = -Double.MAX_VALUE;
                for (int corner = 0; corner < 3; corner++) {
                    final int v = triangles[3 * t + corner];
                    lo = Math.min(lo, particleReach[6 * v + d]);
                    hi = Math.max(hi, particleReach[6 * v + 3 + d]);
                }
                triangleReach[6 * t + d] = lo;
                triangleReach[6 * t + 3 + d] = hi;
            }
        grid.build(triangleReach, triangles.length / 3);
        listings++;
        listed = true;
        passLists = true;
    }

    /** The first root τ ∈ (0, 1] of the cubic in scratch at which edges (p, q) and (r, s) meet, or 1 if it ends within round-off of 0 with them meeting; −1 if none. */
    private static double firstEdgeContact(int p, int q, int r, int s, double[] start, double[] x, double noise, double[] scratch) {
        final double end = scratch[0] + scratch[1] + scratch[2] + scratch[3];
        final int roots = TriangleGeometry.coplanarRoots(scratch);
        for (int k = 0; k < roots; k++) {
            final double t = scratch[4 + k];
            if (t > 0 && segmentsMeet(t, p, q, r, s, start, x)) return t;
        }
        return Math.abs(end) <= noise && segmentsMeet(1, p, q, r, s, start, x) ? 1 : -1;
    }

    /**
     * What round-off can make of the coplanarity determinant of a, b, c and p at the substep's start (the
     * cubic's terms are products of three of their differences): {@link #ROUND_OFF} times the cube of
     * their size. A cubic within it of 0 says nothing about which side p is on.
     */
    private static double roundOff(double[] v, int a, int b, int c, int p) {
        final int A = 3 * a, B = 3 * b, C = 3 * c, P = 3 * p;
        final double size2 = squared(v[B] - v[A], v[B + 1] - v[A + 1], v[B + 2] - v[A + 2]) + squared(v[C] - v[A], v[C + 1] - v[A + 1], v[C + 2] - v[A + 2])
                + squared(v[P] - v[A], v[P + 1] - v[A + 1], v[P + 2] - v[A + 2]);
        return ROUND_OFF * size2 * Math.sqrt(size2);
    }

    /** Whether segments pq and rs, at τ of their motion (coplanar there, so they meet if this close), come within a millionth of their lengths. */
    static boolean segmentsMeet(double t, int p, int q, int r, int s, double[] start, double[] x) {
        final int P = 3 * p, Q = 3 * q, R = 3 * r, S = 3 * s;
        final double u = 1 - t;
        final double a = Math.sqrt(squared(u * (start[Q] - start[P]) + t * (x[Q] - x[P]), u * (start[Q + 1] - start[P + 1]) + t * (x[Q + 1] - x[P + 1]), u * (start[Q + 2] - start[P + 2]) + t * (x[Q + 2] - x[P + 2])));
        final double e = Math.sqrt(squared(u * (start[S] - start[R]) + t * (x[S] - x[R]), u * (start[S + 1] - start[R + 1]) + t * (x[S + 1] - x[R + 1]), u * (start[S + 2] - start[R + 2]) + t * (x[S + 2] - x[R + 2])));
        final double tolerance = SLACK * (a + e);
        return segmentDistanceSquared(t, p, q, r, s, start, x) <= tolerance * tolerance;
    }

    /**
     * The squared distance between segments pq and rs at τ of their motion (from v0 to v1): closest points of
     * two segments, Ericson 2005, "Real-Time Collision Detection", §5.1.9. A collapsed segment is taken as
     * far (∞): its vertices' own face events cover it.
     */
    static double segmentDistanceSquared(double t, int p, int q, int r, int s, double[] v0, double[] v1) {
        final double u = 1 - t;
        final int P = 3 * p, Q = 3 * q, R = 3 * r, S = 3 * s;
        final double px = u * v0[P] + t * v1[P], py = u * v0[P + 1] + t * v1[P + 1], pz = u * v0[P + 2] + t * v1[P + 2];
        final double rx = u * v0[R] + t * v1[R], ry = u * v0[R + 1] + t * v1[R + 1], rz = u * v0[R + 2] + t * v1[R + 2];
        final double d1x = u * v0[Q] + t * v1[Q] - px, d1y = u * v0[Q + 1] + t * v1[Q + 1] - py, d1z = u * v0[Q + 2] + t * v1[Q + 2] - pz;
        final double d2x = u * v0[S] + t * v1[S] - rx, d2y = u * v0[S + 1] + t * v1[S + 1] - ry, d2z = u * v0[S + 2] + t * v1[S + 2] - rz;
        final double ox = px - rx, oy = py - ry, oz = pz - rz;
        final double a = d1x * d1x + d1y * d1y + d1z * d1z, e = d2x * d2x + d2y * d2y + d2z * d2z;
        if (!(a > 0) || !(e > 0)) return Double.POSITIVE_INFINITY;
        final double b = d1x * d2x + d1y * d2y + d1z * d2z, c = d1x * ox + d1y * oy + d1z * oz, f = d2x * ox + d2y * oy + d2z * oz;
        final double denom = a * e - b * b;
        double sc = denom > 0 ? clamp((b * f - c * e) / denom) : 0;
        double tc = (b * sc + f) / e;
        if (tc < 0) { tc = 0; sc = clamp(-c / a); }
        else if (tc > 1) { tc = 1; sc = clamp((b - c) / a); }
        return squared(ox + sc * d1x - tc * d2x, oy + sc * d1y - tc * d2y, oz + sc * d1z - tc * d2z);
    }

    private static double squared(double x, double y, double z) { return x * x + y * y + z * z; }


    /**
     * Whether the cubic k[0..3] is round-off all substep: its Bernstein coefficients (the control points of
     * the curve over [0, 1], which lies in their convex hull) all within ten times the round-off bound, four
     * points in one plane over the whole substep.
     */
    private static boolean flat(double[] k, double noise) {
        final double bound = 10 * noise;
        final double b0 = k[0], b1 = k[0] + k[1] / 3, b2 = k[0] + (2 * k[1] + k[2]) / 3, b3 = k[0] + k[1] + k[2] + k[3];
        return Math.abs(b0) <= bound && Math.abs(b1) <= bound && Math.abs(b2) <= bound && Math.abs(b3) <= bound;
    }

    /**
     * Whether the cubic k[0..3] keeps one sign on [0, 1], clear of round-off: its Bernstein coefficients all
     * beyond ±noise on one side (Tang, Manocha and Tong 2010, "Fast continuous collision detection using
     * deforming non-penetration filters", use the same bound).
     */
    static boolean oneSigned(double[] k, double noise) {
        final double b0 = k[0], b1 = k[0] + k[1] / 3, b2 = k[0] + (2 * k[1] + k[2]) / 3, b3 = k[0] + k[1] + k[2] + k[3];
        return (b0 > noise && b1 > noise && b2 > noise && b3 > noise) || (b0 < -noise && b1 < -noise && b2 < -noise && b3 < -noise);
    }

    /** Each edge's and each triangle's bounding sphere at the substep's start (fixed for all its passes). */
    private void startSpheres(double[] start) {
        final int edgeCount = edges.length / 2;
        for (int e = 0; e < edgeCount; e++) {
            final int p = 3 * edges[2 * e], q = 3 * edges[2 * e + 1], o = 4 * e;
            sphere[o] = 0.5 * (start[p] + start[q]);
            sphere[o + 1] = 0.5 * (start[p + 1] + start[q + 1]);
            sphere[o + 2] = 0.5 * (start[p + 2] + start[q + 2]);
            sphere[o + 3] = 0.5 * Math.sqrt(squared(start[q] - start[p], start[q + 1] - start[p + 1], start[q + 2] - start[p + 2]));
        }
        for (int t = 0, count = triangles.length / 3; t < count; t++) {
            // Centred on the centroid, out to the farthest corner.
            final int a = 3 * triangles[3 * t], b = 3 * triangles[3 * t + 1], c = 3 * triangles[3 * t + 2], o = 4 * (edgeCount + t);
            final double mx = (start[a] + start[b] + start[c]) / 3, my = (start[a + 1] + start[b + 1] + start[c + 1]) / 3, mz = (start[a + 2] + start[b + 2] + start[c + 2]) / 3;
            sphere[o] = mx; sphere[o + 1] = my; sphere[o + 2] = mz;
            sphere[o + 3] = Math.sqrt(Math.max(squared(start[a] - mx, start[a + 1] - my, start[a + 2] - mz),
                    Math.max(squared(start[b] - mx, start[b + 1] - my, start[b + 2] - mz), squared(start[c] - mx, start[c + 1] - my, start[c + 2] - mz))));
        }
    }

    /** Each particle's move and each triangle's box over the substep's motion (start → x), padded. */
    private void sweptBoxes(double[] start, double[] x) {
        for (int i = 0; i < particles; i++) {
            final int k = 3 * i;
            moved[i] = Math.sqrt(squared(x[k] - start[k], x[k + 1] - start[k + 1], x[k + 2] - start[k + 2]));
        }
        final int edgeCount = edges.length / 2;
        for (int e = 0; e < edgeCount; e++) edgeMove[e] = Math.max(moved[edges[2 * e]], moved[edges[2 * e + 1]]);
        for (int t = 0, count = triangles.length / 3; t < count; t++) {
            triangleMove[t] = Math.max(moved[triangles[3 * t]], Math.max(moved[triangles[3 * t + 1]], moved[triangles[3 * t + 2]]));
            final int b = 6 * t;
            for (int d = 0; d < 3; d++) {
                double lo = Double.MAX_VALUE, hi = -Double.MAX_VALUE;
                for (int corner = 0; corner < 3; corner++) {
                    final int v = 3 * triangles[3 * t + corner] + d;
                    lo = Math.min(lo, Math.min(start[v], x[v]));
                    hi = Math.max(hi, Math.max(start[v], x[v]));
                }
                triangleBox[b + d] = lo - PAD;
                triangleBox[b + 3 + d] = hi + PAD;
            }
        }
    }


    private static double clamp(double v) { return v < 0 ? 0 : v > 1 ? 1 : v; }

    /**
     * The share of the move an event's particles keep: {@link #BACKOFF} of the time of contact τ, less the
     * share that would bring them within the gap g of each other (their distance d₀ at the start closing
     * about linearly until τ: kept τ (1 − g/d₀)); nothing if they start within it. Without the gap a pair
     * pushed together substep after substep would close to a tenth of its distance each time, down to
     * round-off, where the cubic no longer sees which side is which.
     */
    private double keep(double tau, double apart2) {
        final double apart = Math.sqrt(apart2);
        return apart <= gap ? 0 : BACKOFF * tau * (1 - gap / apart);
    }


    /** One thread's part of a pass. */
    private final class Share {
        final double[] cut = new double[particles], scratch = new double[9], closest = new double[6];
        final int[] edgeSeen = new int[edges.length / 2];
        int edgeStamp, found;
        final TriangleGrid.Query query = new TriangleGrid.Query();
        /** The candidates: (vertex, triangle) and (edge, edge) pairs, two numbers each. */
        int[] faces = new int[64], edgePairs = new int[64];
        int faceCount, edgePairCount;
        /** The most candidates this share's lists may hold ({@link #MOST_CANDIDATES} per feature), and whether its last listing met that. */
        int faceCap, edgePairCap;
        boolean overflowed;
        /** The box the overlap tests compare with. */
        double lx, ly, lz, hx, hy, hz;

        void addFace(int i, int t) {
            if (faceCount == faceCap) { overflowed = true; return; }
            if (2 * faceCount == faces.length) faces = Arrays.copyOf(faces, 2 * faces.length);
            faces[2 * faceCount] = i;
            faces[2 * faceCount++ + 1] = t;
        }

        void addEdgePair(int e, int f) {
            if (edgePairCount == edgePairCap) { overflowed = true; return; }
            if (2 * edgePairCount == edgePairs.length) edgePairs = Arrays.copyOf(edgePairs, 2 * edgePairs.length);
            edgePairs[2 * edgePairCount] = e;
            edgePairs[2 * edgePairCount++ + 1] = f;
        }

        /** The box of particles i's and j's reaches; the triangles whose reaches overlap it, into the query. */
        int reachQuery(int i, int j) {
            lx = Math.min(particleReach[6 * i], particleReach[6 * j]); ly = Math.min(particleReach[6 * i + 1], particleReach[6 * j + 1]); lz = Math.min(particleReach[6 * i + 2], particleReach[6 * j + 2]);
            hx = Math.max(particleReach[6 * i + 3], particleReach[6 * j + 3]); hy = Math.max(particleReach[6 * i + 4], particleReach[6 * j + 4]); hz = Math.max(particleReach[6 * i + 5], particleReach[6 * j + 5]);
            return grid.query(query, lx, ly, lz, hx, hy, hz);
        }

        /** Whether the box of particles i's and j's reaches comes within g of the last query's box. */
        boolean nearReach(int i, int j, double g) {
            return !(Math.min(particleReach[6 * i], particleReach[6 * j]) > hx + g || Math.max(particleReach[6 * i + 3], particleReach[6 * j + 3]) < lx - g
                    || Math.min(particleReach[6 * i + 1], particleReach[6 * j + 1]) > hy + g || Math.max(particleReach[6 * i + 4], particleReach[6 * j + 4]) < ly - g
                    || Math.min(particleReach[6 * i + 2], particleReach[6 * j + 2]) > hz + g || Math.max(particleReach[6 * i + 5], particleReach[6 * j + 5]) < lz - g);
        }

        /** Whether the box swept by particles i and j over the pass's motion comes within g of the last swept box. */
        boolean nearSwept(double[] start, double[] x, int i, int j, double g) {
            final int a = 3 * i, b = 3 * j;
            return !(Math.min(Math.min(start[a], x[a]), Math.min(start[b], x[b])) > hx + g || Math.max(Math.max(start[a], x[a]), Math.max(start[b], x[b])) < lx - g
                    || Math.min(Math.min(start[a + 1], x[a + 1]), Math.min(start[b + 1], x[b + 1])) > hy + g || Math.max(Math.max(start[a + 1], x[a + 1]), Math.max(start[b + 1], x[b + 1])) < ly - g
                    || Math.min(Math.min(start[a + 2], x[a + 2]), Math.min(start[b + 2], x[b + 2])) > hz + g || Math.max(Math.max(start[a + 2], x[a + 2]), Math.max(start[b + 2], x[b + 2])) < lz - g);
        }

        /** The box swept by particles i and j (one particle when i == j) over the pass's motion, padded. */
        void sweptBox(double[] start, double[] x, int i, int j) {
            final int a = 3 * i, b = 3 * j;
            lx = Math.min(Math.min(start[a], x[a]), Math.min(start[b], x[b])) - PAD;
            ly = Math.min(Math.min(start[a + 1], x[a + 1]), Math.min(start[b + 1], x[b + 1])) - PAD;
            lz = Math.min(Math.min(start[a + 2], x[a + 2]), Math.min(start[b + 2], x[b + 2])) - PAD;
            hx = Math.max(Math.max(start[a], x[a]), Math.max(start[b], x[b])) + PAD;
            hy = Math.max(Math.max(start[a + 1], x[a + 1]), Math.max(start[b + 1], x[b + 1])) + PAD;
            hz = Math.max(Math.max(start[a + 2], x[a + 2]), Math.max(start[b + 2], x[b + 2])) + PAD;
        }

        /** Whether triangle t's swept box overlaps the last query's box. */
        boolean overlaps(double[] box, int t) {
            final int b = 6 * t;
            return !(box[b] > hx || box[b + 3] < lx || box[b + 1] > hy || box[b + 4] < ly || box[b + 2] > hz || box[b + 5] < lz);
        }

        /** Lowers the cut of an event's four particles to f (0: back to the substep's start). */
        void stop(int i, int j, int k, int l, double f) {
            cut[i] = Math.min(cut[i], f);
            cut[j] = Math.min(cut[j], f);
            cut[k] = Math.min(cut[k], f);
            cut[l] = Math.min(cut[l], f);
        }
    }

    /** The mean length of edges (vertex pairs) over positions rest; 1 for none or all of length 0. */
    static double meanEdge(int[] edges, double[] rest) {
        double sum = 0;
        for (int e = 0; e < edges.length; e += 2)
            sum += Math.sqrt(squared(rest[3 * edges[e]] - rest[3 * edges[e + 1]], rest[3 * edges[e] + 1] - rest[3 * edges[e + 1] + 1], rest[3 * edges[e] + 2] - rest[3 * edges[e + 1] + 2]));
        return edges.length == 0 || !(sum > 0) ? 1 : sum / (edges.length / 2);
    }
}
