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
 * them apart (with t near the cloth's spacing, 1t would leave every edge a candidate: 4500 idle pairs and
 * 52 ms a step on the drop-fold scene's 48² cloth at 2 × 10 sweeps, against 8 pairs and 38 ms at 2t).
 * Source: the particle self-collision of Müller's Ten Minute Physics, tutorial 15 ("Self collisions"),
 * which also gives the spatial hash; friction as Macklin et al. 2014 eq. (24)–(25).
 * Degenerate case: two particles at the same point have no normal; they are left to the cloth.
 *
 * <p>Candidates come from a spatial hash over flat arrays, rebuilt every substep from the predicted
 * positions (cell size: the reach below). A pair is a candidate when closer than
 * t + {@link ContactSet#SLACK}·t + both particles' motion in the prediction. The arrays grow only when the
 * cloth needs more (more pairs than ever before), so steady stepping allocates nothing. Where it fails: a
 * particle passing through the middle of a triangle between three others far apart (the cloth's spacing
 * larger than t) is not caught: this is particle–particle, not point–triangle.
 */
public final class SelfCollision extends Collider {
    /** Pairs closer than this many thicknesses at rest are neighbours: the cloth's own constraints keep them apart. */
    static final double NEIGHBOURHOOD = 2;
    final double thickness;
    private final double[] rest;
    // The hash: particles sorted by cell; cellStart[h] .. cellStart[h + 1] - 1 index into sorted.
    private int[] cellStart = new int[0], sorted = new int[0], cellOf = new int[0];
    // Candidate pairs found this substep.
    private int[] pairI = new int[16], pairJ = new int[16];
    private int pairs;

    /**
     * @param restPositions the rest mesh, xyz interleaved (pairs closer than 2t here never collide)
     * @param thickness     t, m, &gt; 0
     */
    public SelfCollision(double[] restPositions, double thickness, double staticFriction, double kineticFriction) {
        super(0, staticFriction, kineticFriction);
        if (restPositions == null || restPositions.length % 3 != 0)
            throw new IllegalArgumentException("restPositions must hold x, y, z per particle, had " + (restPositions == null ? "null" : restPositions.length + " numbers"));
        this.rest = restPositions.clone();
        this.thickness = Check.inRange("thickness", thickness, Double.MIN_NORMAL, EngineRange.MAX_RADIUS);
    }

    public double thickness() { return thickness; }

    /** The particle count of the rest mesh it was made for. */
    public int restParticles() { return rest.length / 3; }

    /** Pairs found in the last substep. */
    public int pairCount() { return pairs; }

    @Override void findContacts(Particles p, double h, ContactSet contacts) {
        final int n = p.count();
        final double[] x = p.x, prev = p.prev;
        double maxMotion = 0;
        for (int k = 0; k < 3 * n; k += 3) {
            double mx = x[k] - prev[k], my = x[k + 1] - prev[k + 1], mz = x[k + 2] - prev[k + 2];
            maxMotion = Math.max(maxMotion, mx * mx + my * my + mz * mz);
        }
        final double base = thickness * (1 + ContactSet.SLACK);
        final double cell = base + 2 * Math.sqrt(maxMotion);
        buildHash(x, n, cell);
        pairs = 0;
        final int table = cellStart.length - 1;
        for (int i = 0; i < n; i++) {
            int k = 3 * i;
            int cx = cellIndex(x[k], cell), cy = cellIndex(x[k + 1], cell), cz = cellIndex(x[k + 2], cell);
            double mi = motion(x, prev, k);
            for (int dx = -1; dx <= 1; dx++)
                for (int dy = -1; dy <= 1; dy++)
                    for (int dz = -1; dz <= 1; dz++) {
                        int hsh = hash(cx + dx, cy + dy, cz + dz, table);
                        for (int s = cellStart[hsh]; s < cellStart[hsh + 1]; s++) {
                            int j = sorted[s];
                            if (j <= i || p.w[i] + p.w[j] == 0) continue;
                            int m = 3 * j;
                            double ex = x[k] - x[m], ey = x[k + 1] - x[m + 1], ez = x[k + 2] - x[m + 2];
                            double reach = base + mi + motion(x, prev, m);
                            if (ex * ex + ey * ey + ez * ez >= reach * reach) continue;
                            double rx = rest[k] - rest[m], ry = rest[k + 1] - rest[m + 1], rz = rest[k + 2] - rest[m + 2];
                            if (rx * rx + ry * ry + rz * rz < NEIGHBOURHOOD * NEIGHBOURHOOD * thickness * thickness) continue; // neighbours at rest
                            addPair(i, j, contacts);
                        }
                    }
        }
    }

    private static double motion(double[] x, double[] prev, int k) {
        double mx = x[k] - prev[k], my = x[k + 1] - prev[k + 1], mz = x[k + 2] - prev[k + 2];
        return Math.sqrt(mx * mx + my * my + mz * mz);
    }

    private void addPair(int i, int j, ContactSet contacts) {
        if (pairs == pairI.length) { pairI = Arrays.copyOf(pairI, 2 * pairs); pairJ = Arrays.copyOf(pairJ, 2 * pairs); }
        pairI[pairs] = i;
        pairJ[pairs] = j;
        contacts.add(i, pairs, this);
        pairs++;
    }

    private static int cellIndex(double v, double cell) { return (int) Math.floor(v / cell); }

    private static int hash(int x, int y, int z, int table) {
        int h = (x * 92837111) ^ (y * 689287499) ^ (z * 283923481);
        return Math.floorMod(h, table);
    }

    /** Counting sort of the particles by hashed cell. */
    private void buildHash(double[] x, int n, double cell) {
        int table = 2 * n;
        if (cellStart.length != table + 1) { cellStart = new int[table + 1]; sorted = new int[n]; cellOf = new int[n]; }
        Arrays.fill(cellStart, 0);
        for (int i = 0; i < n; i++) {
            int k = 3 * i;
            cellOf[i] = hash(cellIndex(x[k], cell), cellIndex(x[k + 1], cell), cellIndex(x[k + 2], cell), table);
            cellStart[cellOf[i]]++;
        }
        // Running ends, then each particle placed from its cell's end down: cellStart[c] becomes its start.
        for (int c = 0, sum = 0; c <= table; c++) { sum += cellStart[c]; cellStart[c] = sum; }
        for (int i = 0; i < n; i++) sorted[--cellStart[cellOf[i]]] = i;
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

    @Override double clearance(Particles p, int pair) {
        int a = 3 * pairI[pair], b = 3 * pairJ[pair];
        double dx = p.x[a] - p.x[b], dy = p.x[a + 1] - p.x[b + 1], dz = p.x[a + 2] - p.x[b + 2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz) - thickness;
    }
}
