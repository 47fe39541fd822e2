package xpbdcloth.engine;

import java.util.Arrays;

/**
 * The cloth keeps its thickness from itself: two particles that were not neighbours at rest may not come
 * closer than the thickness t, and slide on each other with Coulomb friction.
 *
 * <pre>
 *   C(xᵢ, xⱼ) = |xᵢ − xⱼ| − t ≥ 0     (an inequality: projected only while violated)
 *   ∇ᵢC = n = (xᵢ − xⱼ)/|xᵢ − xⱼ|,  ∇ⱼC = −n,   Σ w|∇C|² = wᵢ + wⱼ
 * </pre>
 * Hard (k = 1, α = 0): Δxᵢ = −wᵢ C n / (wᵢ + wⱼ), Δxⱼ = +wⱼ C n / (wᵢ + wⱼ); then the pair's relative
 * tangential displacement over the substep is removed entirely while under μₛ times the normal correction,
 * else by μₖ times it, shared by inverse mass (as {@link CoulombFriction}, for two moving bodies).
 * Pairs closer than 2t in the rest mesh are neighbours and never collide: the cloth's own constraints keep
 * them apart (with t near the cloth's spacing, 1t would leave every edge a candidate: thousands of idle
 * pairs on the drop-fold scene's 48² cloth, against a handful at 2t; docs/contacts.md).
 * Source: the particle self-collision of Müller's Ten Minute Physics, tutorial 15 ("Self collisions"),
 * which also gives the spatial hash; friction as Macklin et al. 2014 eq. (24)–(25).
 * Degenerate case: two particles at the same point have no normal; they are left to the cloth.
 *
 * <p>Candidates come from a spatial hash over flat arrays (a power-of-two table of at least 2n buckets,
 * counting-sorted, positions copied in bucket order so a bucket's candidates are read one after another)
 * and are kept while they stay valid, as a molecular-dynamics Verlet list is: a build lists the pairs
 * closer than R = t + {@link ContactSet#SLACK}·t + a skin s = t/2 (plus both particles' motion in the
 * prediction, for fast ones), and while no particle has drifted, with its motion this substep, more than
 * s/2 from where the build saw it, no pair outside the list can come within t: the list is used again
 * and the hash is not rebuilt. A cloth at rest or sliding slowly rebuilds rarely; one falling fast, every
 * substep. Cells are 2R wide: a particle searches the cells its own reach spans (each pair is found by
 * the faster of its two), so one fast particle no longer widens every cell. The arrays grow only when
 * the cloth needs more (more pairs than ever before), so steady stepping allocates nothing, and never
 * past {@link #MOST_PAIRS} a particle (a cloth moving far across itself in one substep, {@link #overloads()}).
 * Where it fails: a particle passing through the middle of a triangle between three others far apart
 * (the cloth's spacing larger than t) is not caught: this is particle–particle, not point–triangle; with
 * {@link #withPointTriangle} each vertex is also kept from the faces ({@link PointTriangleContacts}); the
 * {@link CrossingGuard}, made with the triangles, catches what passes (at a cost, docs/contacts.md), and a
 * {@link CrossingUntangler} ({@link #untangling}) puts back what has passed at a step's end.
 */
public final class SelfCollision extends Collider implements Team.Job {
    /** Pairs closer than this many thicknesses at rest are neighbours: the cloth's own constraints keep them apart. */
    static final double NEIGHBOURHOOD = 2;
    /**
     * The most pairs one particle lists (each pair is listed by one of its two, so a build lists at most this
     * many per particle). Particles kept t apart fill a ball of radius R = 1.75 t with about 90 at the
     * densest packing; a cloth lists a handful each (the shipped scenes with self-collision, 600 steps each,
     * have at most 15 pairs at any particle, counting both ends, on denim-fold). Only motion far beyond the
     * thickness reaches the bound; see {@link #overloads()}.
     */
    static final int MOST_PAIRS = 128;
    final double thickness;
    private final double[] rest;
    private final CrossingGuard guard;
    private final int[] same;
    private CrossingUntangler untangler;
    /** Vertices kept from faces ({@link #withPointTriangle}), or null. */
    private PointTriangleContacts faces;
    // The hash: particles sorted by cell; cellStart[h] .. cellStart[h + 1] - 1 index into sorted.
    private int[] cellStart = new int[0], sorted = new int[0], cellOf = new int[0];
    // The positions in the hash's order (candidates in a bucket are read one after another) and each
    // particle's reach (its motion in the prediction).
    private double[] sortedX = new double[0], sortedReach = new double[0], reachOf = new double[0];
    // The pairs of the last build, and where the build saw each particle.
    private int[] pairI = new int[16], pairJ = new int[16];
    private int pairs;
    private double[] built = new double[0];
    private boolean listed;
    /** Hash rebuilds since this self-collision was made (the list kept otherwise). */
    private long builds;
    /** Builds whose reach through the substep's motion found too many pairs, see {@link #overloads()}. */
    private long overloads;
    /** Each thread's own finds (particles split in ascending ranges, so their concatenation is the one-thread list). */
    private Finds[] finds = {new Finds()};
    private double buildBase, buildCell;
    /** The particles of the build in progress, for the team's threads. */
    private Particles buildParticles;

    /** One thread's part of a build: its pairs and which buckets its current particle has visited. */
    private static final class Finds {
        int[] i = new int[16], j = new int[16];
        int count;
        int[] visitedBy = new int[0];
        /** Some particle of this share found {@link #MOST_PAIRS} pairs and searched no further. */
        boolean full;

        void add(int a, int b) {
            if (count == i.length) { i = Arrays.copyOf(i, 2 * count); j = Arrays.copyOf(j, 2 * count); }
            i[count] = a;
            j[count] = b;
            count++;
        }
    }

    /**
     * @param restPositions the rest mesh, xyz interleaved (pairs closer than 2t here never collide)
     * @param thickness     t, m, &gt; 0
     */
    public SelfCollision(double[] restPositions, double thickness, double staticFriction, double kineticFriction) {
        this(restPositions, null, thickness, staticFriction, kineticFriction);
    }

    /**
     * Particle pairs as above and, when {@code triangles} is given, a {@link CrossingGuard} on them: the
     * substep's motion is cut back wherever a vertex would pass through a face or an edge through an edge.
     *
     * @param triangles the cloth's triangles (3 particle indices each), or null for particle pairs alone
     */
    public SelfCollision(double[] restPositions, int[] triangles, double thickness, double staticFriction, double kineticFriction) {
        this(restPositions, triangles, null, thickness, staticFriction, kineticFriction);
    }

    /**
     * As above, the guard taking particles {@code same[i] == same[j]} as one ({@link CrossingGuard}): a garment
     * whose stitched pairs are welded. The particle pairs need no such map: give such pairs one rest position.
     */
    public SelfCollision(double[] restPositions, int[] triangles, int[] same, double thickness, double staticFriction, double kineticFriction) {
        super(0, staticFriction, kineticFriction);
        if (restPositions == null || restPositions.length % 3 != 0)
            throw new IllegalArgumentException("restPositions must hold x, y, z per particle, had " + (restPositions == null ? "null" : restPositions.length + " numbers"));
        this.rest = restPositions.clone();
        this.thickness = Check.inRange("thickness", thickness, Double.MIN_NORMAL, EngineRange.MAX_RADIUS);
        this.guard = triangles == null ? null : new CrossingGuard(triangles, restPositions, same);
        this.same = same == null ? null : same.clone();
    }

    /**
     * Adds a {@link CrossingUntangler} on the triangles: at each step's end, a cloth found passed through itself
     * is put back to the sides its vertices held when last free of a crossing. Returns this.
     */
    public SelfCollision untangling(int[] triangles) {
        this.untangler = new CrossingUntangler(triangles, rest, same, thickness);
        return this;
    }

    /**
     * Adds {@link PointTriangleContacts} on the triangles: each vertex kept the thickness from the faces of other
     * parts of the cloth, on the side of the face it began each substep on. Returns this.
     */
    public SelfCollision withPointTriangle(int[] triangles) {
        this.faces = new PointTriangleContacts(triangles, rest, same, thickness, staticFriction, kineticFriction);
        return this;
    }

    /** Whether vertices are kept from faces as well as from particles ({@link #withPointTriangle}). */
    public boolean pointTriangle() { return faces != null; }

    /** (Vertex, face) pairs listed at the last build, 0 without {@link #withPointTriangle}. */
    public int pointTrianglePairs() { return faces == null ? 0 : faces.pairCount(); }

    /** The untangler, or null when a crossed cloth is left crossed. */
    public CrossingUntangler untangler() { return untangler; }

    /** The continuous triangle guard, or null when only particle pairs keep the cloth from itself. */
    public CrossingGuard guard() { return guard; }

    public double thickness() { return thickness; }

    /** The particle count of the rest mesh it was made for. */
    public int restParticles() { return rest.length / 3; }

    /** Pairs listed at the last build (each is a candidate until the next). */
    public int pairCount() { return pairs; }

    /** The two particles of listed pair k (0 ≤ k &lt; {@link #pairCount}), end 0 or 1. */
    public int pairParticle(int k, int end) {
        if (k < 0 || k >= pairs) throw new IllegalArgumentException("pair must be within [0, " + pairs + "), was " + k);
        return end == 0 ? pairI[k] : pairJ[k];
    }

    /**
     * Marks both particles of every listed pair closer than {@code slack} thicknesses now: held by a contact
     * whose force no energy of the step accounts for (a penalty pair presses slightly inside t).
     */
    void markTouching(Particles p, boolean[] held, double slack) {
        final double[] x = p.x;
        final double reach = slack * thickness;
        for (int k = 0; k < pairs; k++) {
            int a = 3 * pairI[k], b = 3 * pairJ[k];
            double dx = x[a] - x[b], dy = x[a + 1] - x[b + 1], dz = x[a + 2] - x[b + 2];
            if (dx * dx + dy * dy + dz * dz < reach * reach) held[pairI[k]] = held[pairJ[k]] = true;
        }
    }

    /** Hash rebuilds since this self-collision was made: the list is kept while it stays valid. */
    public long builds() { return builds; }

    /**
     * Builds where some particle, reaching through its motion in the substep, found more than
     * {@link #MOST_PAIRS} pairs: a cloth that moves many times its thickness in one substep, so nearly every
     * particle may meet nearly every other (the preset fuzzer found one, seed 9100088: a 105 × 158 cloth of
     * 0.28 mm thickness falling 11 cm a substep would have listed all 1.4e8 pairs and ran out of memory).
     * Such a build lists again the pairs within reach where the particles are now, without their motion:
     * pairs already closer than t are still pushed apart, but two particles that meet only during the substep
     * are missed there (as a particle passing between three others is). Where even that exceeds the bound
     * (a cloth crushed into a ball a few thicknesses wide), each particle keeps the first pairs it found, and
     * the list is made again the next substep.
     */
    public long overloads() { return overloads; }

    /**
     * The skin s as a fraction of the thickness: pairs up to t + slack + s apart are listed, and the list holds
     * while no particle drifts s/2. Half the thickness keeps that reach, 1.75 t, inside the rest neighbourhood
     * (2 t), so a flat layer lists none of its own particles: with s = t, a cloth whose thickness is 0.9 of its
     * spacing listed every particle two spacings away in its own layer (49,068 idle pairs on denim-fold at 128²,
     * which also constrained the solver's colouring), where s = t/2 lists 1,550 and rebuilds a third more often.
     * The point–triangle list shares it: a skin of one and of two thicknesses there made drop-fold's and
     * denim-fold's steps 1.2–3.4 times longer (more pairs projected every sweep; a folding cloth lists again
     * nearly every substep whatever its skin).
     */
    static final double SKIN = 0.5;

    double skin() { return SKIN * thickness; }

    @Override void findContacts(Particles p, double h, ContactSet contacts) { findContacts(p, h, contacts, null); }

    /** The collide stage: the listed pairs, listed anew when the list ran out, by the team's threads if given. */
    void findContacts(Particles p, double h, ContactSet contacts, Team team) {
        final int n = p.count();
        final double[] x = p.x, prev = p.prev;
        if (reachOf.length < n) { reachOf = new double[n]; built = new double[3 * n]; listed = false; }
        double drift = 0;
        for (int i = 0; i < n; i++) {
            final int k = 3 * i;
            reachOf[i] = motion(x, prev, k);
            if (listed) {
                double dx = x[k] - built[k], dy = x[k + 1] - built[k + 1], dz = x[k + 2] - built[k + 2];
                drift = Math.max(drift, Math.sqrt(dx * dx + dy * dy + dz * dz) + reachOf[i]);
            }
        }
        if (!listed || drift > 0.5 * skin()) {
            if (faces != null) faces.list(p, reachOf); // before build, which may clear the reach (overloads())
            build(p, team);
        }
        for (int k = 0; k < pairs; k++) contacts.add(pairI[k], k, this);
    }

    /**
     * The collide stage's vertex–face contacts ({@link #withPointTriangle}), listed with the pairs: the contact
     * set adds them in one run after the pairs, so a solver can project them apart.
     */
    void findFaceContacts(Particles p, double h, ContactSet contacts) {
        if (faces != null) faces.findContacts(p, h, contacts);
    }

    /** Lists every pair that can come within t before some particle drifts s/2 from here. */
    private void build(Particles p, Team team) {
        final int n = p.count();
        System.arraycopy(p.x, 0, built, 0, 3 * n);
        listed = true;
        builds++;
        buildBase = thickness * (1 + ContactSet.SLACK) + skin();
        // Cells 2R wide: a slow particle's search, R either way, spans two cells on each axis, eight in all
        // (cells R wide would make it three, 27 buckets of fewer particles: more time in the buckets' own
        // overhead than the fewer candidates save; ContactBench's self-collision cases).
        buildCell = 2 * buildBase;
        buildHash(p.x, n, buildCell);
        int threads = team == null ? 1 : team.threads();
        if (finds.length != threads) {
            finds = new Finds[threads];
            for (int t = 0; t < threads; t++) finds[t] = new Finds();
        }
        search(p, team);
        if (full()) {
            overloads++;
            // Again without the substep's motion: the pairs near each other now (see overloads()).
            Arrays.fill(reachOf, 0, n, 0.0);
            buildHash(p.x, n, buildCell);
            search(p, team);
            if (full()) listed = false;
        }
        pairs = 0;
        for (Finds f : finds)
            for (int k = 0; k < f.count; k++) addPair(f.i[k], f.j[k]);
    }

    /** Every share's finds, from empty. */
    private void search(Particles p, Team team) {
        for (Finds f : finds) {
            f.count = 0;
            f.full = false;
            if (f.visitedBy.length != cellStart.length - 1) f.visitedBy = new int[cellStart.length - 1];
            else Arrays.fill(f.visitedBy, 0);
        }
        buildParticles = p;
        if (team == null) find(p, 0, 1);
        else team.run(this);
    }

    private boolean full() {
        for (Finds f : finds) if (f.full) return true;
        return false;
    }

    /** A build's search on the team: each thread its share of the particles. */
    @Override public void work(int id, Team team) {
        find(buildParticles, id, team.threads());
        team.await();
    }

    /** The pairs found by particles of share id (an ascending range), into that share's finds. */
    private void find(Particles p, int id, int shares) {
        final int n = p.count();
        final double[] x = p.x, w = p.w;
        final Finds out = finds[id];
        final int[] visitedBy = out.visitedBy;
        final int table = cellStart.length - 1;
        final double base = buildBase, cell = buildCell;
        final double neighbours = NEIGHBOURHOOD * NEIGHBOURHOOD * thickness * thickness;
        for (int i = (int) ((long) n * id / shares), last = (int) ((long) n * (id + 1) / shares); i < last; i++) {
            final int k = 3 * i, first = out.count;
            final double xi = x[k], yi = x[k + 1], zi = x[k + 2], mi = reachOf[i];
            // A pair is found by the faster of the two (by index when equally fast): i searches as far as a
            // partner as fast as itself could need, base + 2 mᵢ, over the cells that span on each axis (two or
            // three at rest, where a span rounded up about i's own cell would make it five, 125 cells in all).
            final double reach = base + 2 * mi;
            final int x0 = HashedCells.index(xi - reach, cell), x1 = HashedCells.index(xi + reach, cell);
            final int y0 = HashedCells.index(yi - reach, cell), y1 = HashedCells.index(yi + reach, cell);
            final int z0 = HashedCells.index(zi - reach, cell), z1 = HashedCells.index(zi + reach, cell);
            if (((double) x1 - x0 + 1) * ((double) y1 - y0 + 1) * ((double) z1 - z0 + 1) > n) {
                // A particle moving many cells in a substep (a fast one on a fine cloth) would search more
                // cells than there are particles: look at every particle instead (the fuzzer found a 4 × 2
                // cloth taking minutes a step, searching 1e11 cells).
                scan(out, i, first, 0, n, mi, w, neighbours);
                continue;
            }
            // Long counters: a cell index saturated at Integer.MAX_VALUE (a tiny thickness far out) still ends the loop.
            search:
            for (long cx = x0; cx <= x1; cx++)
                for (long cy = y0; cy <= y1; cy++)
                    for (long cz = z0; cz <= z1; cz++) {
                        final int bucket = HashedCells.bucket((int) cx, (int) cy, (int) cz, table);
                        // Two of the cells searched can share a bucket: visit it once, or its pairs would be found twice.
                        if (visitedBy[bucket] == i + 1) continue;
                        visitedBy[bucket] = i + 1;
                        if (!scan(out, i, first, cellStart[bucket], cellStart[bucket + 1], mi, w, neighbours)) break search;
                    }
        }
    }

    /**
     * Particle i against the hash's particles sorted[from .. to): each pair it is the one to find (the
     * faster, or the higher index when as fast), within reach now and not neighbours at rest, into out;
     * false (and out full) once i has found {@link #MOST_PAIRS} since {@code first}.
     */
    private boolean scan(Finds out, int i, int first, int from, int to, double mi, double[] w, double neighbours) {
        final double[] sx = sortedX, x = buildParticles.x;
        final int k = 3 * i;
        final double xi = x[k], yi = x[k + 1], zi = x[k + 2], base = buildBase;
        for (int s = from; s < to; s++) {
            final double mj = sortedReach[s];
            if (mj > mi) continue;
            final int j = sorted[s];
            if (j == i || (mj == mi && j < i)) continue;
            final double ex = xi - sx[3 * s], ey = yi - sx[3 * s + 1], ez = zi - sx[3 * s + 2], d2 = ex * ex + ey * ey + ez * ez;
            final double reach = base + mi + mj;
            if (d2 >= reach * reach || w[i] + w[j] == 0) continue;
            final int m = 3 * j;
            final double rx = rest[k] - rest[m], ry = rest[k + 1] - rest[m + 1], rz = rest[k + 2] - rest[m + 2];
            if (rx * rx + ry * ry + rz * rz < neighbours) continue; // neighbours at rest
            if (out.count - first == MOST_PAIRS) { out.full = true; return false; }
            out.add(Math.min(i, j), Math.max(i, j));
        }
        return true;
    }

    private static double motion(double[] x, double[] prev, int k) {
        double mx = x[k] - prev[k], my = x[k + 1] - prev[k + 1], mz = x[k + 2] - prev[k + 2];
        return Math.sqrt(mx * mx + my * my + mz * mz);
    }

    private void addPair(int i, int j) {
        if (pairs == pairI.length) { pairI = Arrays.copyOf(pairI, 2 * pairs); pairJ = Arrays.copyOf(pairJ, 2 * pairs); }
        pairI[pairs] = i;
        pairJ[pairs] = j;
        pairs++;
    }

    /** Counting sort of the particles by hashed cell. */
    private void buildHash(double[] x, int n, double cell) {
        int table = Integer.highestOneBit(Math.max(1, 2 * n - 1)) << 1; // the power of two at or above 2n
        if (cellStart.length != table + 1) { cellStart = new int[table + 1]; sorted = new int[n]; cellOf = new int[n]; sortedX = new double[3 * n]; sortedReach = new double[n]; }
        Arrays.fill(cellStart, 0);
        for (int i = 0; i < n; i++) {
            int k = 3 * i;
            cellOf[i] = HashedCells.bucket(HashedCells.index(x[k], cell), HashedCells.index(x[k + 1], cell), HashedCells.index(x[k + 2], cell), table);
            cellStart[cellOf[i]]++;
        }
        // Running ends, then each particle placed from its cell's end down: cellStart[c] becomes its start.
        for (int c = 0, sum = 0; c <= table; c++) { sum += cellStart[c]; cellStart[c] = sum; }
        for (int i = 0; i < n; i++) sorted[--cellStart[cellOf[i]]] = i;
        for (int s = 0; s < n; s++) {
            int k = 3 * sorted[s];
            sortedX[3 * s] = x[k]; sortedX[3 * s + 1] = x[k + 1]; sortedX[3 * s + 2] = x[k + 2];
            sortedReach[s] = reachOf[sorted[s]];
        }
    }

    @Override void project(Particles p, int pair, double h) {
        final int i = pairI[pair], j = pairJ[pair], a = 3 * i, b = 3 * j;
        final double[] x = p.x, prev = p.prev;
        double dx = x[a] - x[b], dy = x[a + 1] - x[b + 1], dz = x[a + 2] - x[b + 2];
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double C = len - thickness;
        double wi = p.w[i], wj = p.w[j], w = wi + wj;
        if (C >= 0 || len < DistanceBlock.MIN_LENGTH || w == 0) return;
        double nx = dx / len, ny = dy / len, nz = dz / len, s = -C / w;
        x[a] += wi * s * nx; x[a + 1] += wi * s * ny; x[a + 2] += wi * s * nz;
        x[b] -= wj * s * nx; x[b + 1] -= wj * s * ny; x[b + 2] -= wj * s * nz;
        // Friction on the pair's relative displacement over the substep, tangent to n.
        double rx = (x[a] - prev[a]) - (x[b] - prev[b]), ry = (x[a + 1] - prev[a + 1]) - (x[b + 1] - prev[b + 1]), rz = (x[a + 2] - prev[a + 2]) - (x[b + 2] - prev[b + 2]);
        double along = rx * nx + ry * ny + rz * nz;
        double tx = rx - along * nx, ty = ry - along * ny, tz = rz - along * nz;
        double slip = Math.sqrt(tx * tx + ty * ty + tz * tz);
        if (slip == 0) return;
        double normalCorrection = -C;
        double removed = slip < staticFriction * normalCorrection ? 1.0 : Math.min(kineticFriction * normalCorrection / slip, 1.0);
        double fi = removed * wi / w, fj = removed * wj / w;
        x[a] -= fi * tx; x[a + 1] -= fi * ty; x[a + 2] -= fi * tz;
        x[b] += fj * tx; x[b + 1] += fj * ty; x[b + 2] += fj * tz;
    }

    @Override int partner(int pair) { return pairJ[pair]; }

    /** The particle of the pair other than {@code self}. */
    int other(int pair, int self) { return pairI[pair] == self ? pairJ[pair] : pairI[pair]; }

    /** The pair's projection moving only {@code particle}, by its mass share of the overlap, with friction on it alone. */
    @Override void projectOne(Particles p, int pair, int particle, double h) {
        final int i = pairI[pair], j = pairJ[pair];
        final int self = particle == i ? i : j, other = particle == i ? j : i, a = 3 * self, b = 3 * other;
        final double[] x = p.x, prev = p.prev;
        double dx = x[a] - x[b], dy = x[a + 1] - x[b + 1], dz = x[a + 2] - x[b + 2];
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double C = len - thickness;
        double ws = p.w[self], w = ws + p.w[other];
        if (C >= 0 || len < DistanceBlock.MIN_LENGTH || ws == 0) return;
        double nx = dx / len, ny = dy / len, nz = dz / len, move = -C * ws / w;
        x[a] += move * nx; x[a + 1] += move * ny; x[a + 2] += move * nz;
        double rx = (x[a] - prev[a]) - (x[b] - prev[b]), ry = (x[a + 1] - prev[a + 1]) - (x[b + 1] - prev[b + 1]), rz = (x[a + 2] - prev[a + 2]) - (x[b + 2] - prev[b + 2]);
        double along = rx * nx + ry * ny + rz * nz;
        double tx = rx - along * nx, ty = ry - along * ny, tz = rz - along * nz;
        double slip = Math.sqrt(tx * tx + ty * ty + tz * tz);
        if (slip == 0) return;
        double removed = slip < staticFriction * -C ? 1.0 : Math.min(kineticFriction * -C / slip, 1.0);
        double share = removed * ws / w;
        x[a] -= share * tx; x[a + 1] -= share * ty; x[a + 2] -= share * tz;
    }

    @Override double clearance(Particles p, int pair) {
        int a = 3 * pairI[pair], b = 3 * pairJ[pair];
        double dx = p.x[a] - p.x[b], dy = p.x[a + 1] - p.x[b + 1], dz = p.x[a + 2] - p.x[b + 2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz) - thickness;
    }

    @Override boolean internal() { return true; }

    /** The cloth's thickness is no solid a point can be inside. */
    @Override public double clearanceAt(double x, double y, double z) { return Double.POSITIVE_INFINITY; }
}
