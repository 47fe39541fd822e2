package xpbdcloth.engine;

import java.util.Arrays;

/**
 * Triangles' boxes in a uniform grid of hashed cells over flat arrays, rebuilt whenever the boxes move: a
 * box is listed in every cell it overlaps (counting-sorted by bucket, a copy of the box beside each entry so a
 * bucket is read in one sweep), and a query box reads the buckets of the cells it overlaps and returns the
 * triangles whose boxes overlap it, each once: a one-cell query (a point's) reads the copied boxes in one sweep,
 * and one over several cells, which share most of their triangles, tests each triangle's box once. With cells
 * about a triangle's size a box spans one to eight cells, and a query reads a few triangles where a tree's
 * walk visits dozens of nodes. A box spanning more than {@link #MOST_CELLS} cells (a triangle moving many
 * cells in a substep) is kept in a list every query reads instead. The arrays grow only when a build needs
 * more than any before, so steady use allocates nothing.
 */
final class TriangleGrid {
    /** A box spanning more cells than this is read by every query rather than listed in each of its cells. */
    static final int MOST_CELLS = 64;

    private final double cell;
    private int[] bucketStart = new int[1], listed = new int[0], large = new int[0];
    /** Per entry, in bucket order: its triangle's box (6 numbers). */
    private double[] entryBox = new double[0];
    private double[] boxes = new double[0];
    /** Whether each triangle is listed in its cells (else in the large list). */
    private boolean[] inCells = new boolean[0];
    private int largeCount, count;

    /** One thread's queries: which triangles the current one has found (each once) and the list of them. */
    static final class Query {
        private int[] seen = new int[0];
        private int stamp;
        private int[] found = new int[64];

        /** The triangles the last query found; valid until the next. */
        int[] found() { return found; }

        /** Whether t is met for the first time in this query (marking it met). */
        private boolean first(int t) {
            if (seen[t] == stamp) return false;
            seen[t] = stamp;
            return true;
        }

        private int add(int t, int count) { return first(t) ? append(t, count) : count; }

        private int append(int t, int count) {
            if (count == found.length) found = Arrays.copyOf(found, 2 * count);
            found[count] = t;
            return count + 1;
        }
    }

    /** @param cell the cells' side, m (about a triangle's size) */
    TriangleGrid(double cell) {
        this.cell = Check.positive("cell", cell);
    }

    /** Lists triangles 0 .. count − 1 by their boxes (6 numbers each: min xyz, max xyz), read now and kept. */
    void build(double[] boxes, int count) {
        this.boxes = boxes;
        this.count = count;
        if (large.length < count) { large = new int[count]; inCells = new boolean[count]; }
        long entries = 0;
        largeCount = 0;
        for (int t = 0; t < count; t++) {
            long cells = cellsOf(boxes, t);
            inCells[t] = cells <= MOST_CELLS;
            if (inCells[t]) entries += cells;
            else large[largeCount++] = t;
        }
        // A table of at least twice the entries, a power of two; kept when larger (so a count that crosses a
        // power of two back and forth allocates nothing).
        final int needed = Integer.highestOneBit((int) Math.max(1, Math.min(1 << 28, 2 * entries - 1))) << 1;
        if (bucketStart.length < needed + 1) bucketStart = new int[needed + 1];
        else Arrays.fill(bucketStart, 0);
        final int table = bucketStart.length - 1;
        // Grown to at least twice what it held: a cloth whose reaches widen a little at a time (a garment carried
        // round by a turning body) would otherwise make a new list, of the whole size, at every new largest.
        if (listed.length < entries) {
            final int size = (int) Math.min((Integer.MAX_VALUE - 8) / 6, Math.max(entries, 2L * listed.length));
            listed = new int[size];
            entryBox = new double[6 * size];
        }
        for (int pass = 0; pass < 2; pass++) {
            for (int t = 0; t < count; t++) {
                final int b = 6 * t;
                if (!inCells[t]) continue;
                final int x0 = index(boxes[b]), x1 = index(boxes[b + 3]), y0 = index(boxes[b + 1]), y1 = index(boxes[b + 4]);
                final int z0 = index(boxes[b + 2]), z1 = index(boxes[b + 5]);
                for (long cx = x0; cx <= x1; cx++) // long: an index saturated at Integer.MAX_VALUE still ends the loop
                    for (long cy = y0; cy <= y1; cy++)
                        for (long cz = z0; cz <= z1; cz++) {
                            final int h = HashedCells.bucket((int) cx, (int) cy, (int) cz, table);
                            if (pass == 0) { bucketStart[h]++; continue; }
                            final int s = --bucketStart[h];
                            listed[s] = t;
                            final int e = 6 * s;
                            entryBox[e] = boxes[b]; entryBox[e + 1] = boxes[b + 1]; entryBox[e + 2] = boxes[b + 2];
                            entryBox[e + 3] = boxes[b + 3]; entryBox[e + 4] = boxes[b + 4]; entryBox[e + 5] = boxes[b + 5];
                        }
            }
            // After counting: running ends, so placing each entry from its bucket's end down leaves its start.
            if (pass == 0) for (int c = 0, sum = 0; c <= table; c++) { sum += bucketStart[c]; bucketStart[c] = sum; }
        }
    }

    /**
     * The triangles whose boxes overlap the box [lo, hi] (closed), each once, into q's {@link Query#found()};
     * returns how many. Queries with their own q may run on several threads.
     */
    int query(Query q, double lx, double ly, double lz, double hx, double hy, double hz) {
        if (q.seen.length < this.count) { q.seen = new int[this.count]; q.stamp = 0; }
        if (++q.stamp == Integer.MAX_VALUE) { Arrays.fill(q.seen, 0); q.stamp = 1; }
        int count = 0;
        for (int k = 0; k < largeCount; k++) {
            final int b = 6 * large[k];
            if (overlaps(boxes, b, lx, ly, lz, hx, hy, hz)) count = q.add(large[k], count);
        }
        final int table = bucketStart.length - 1;
        final int x0 = index(lx), x1 = index(hx), y0 = index(ly), y1 = index(hy), z0 = index(lz), z1 = index(hz);
        if (((double) x1 - x0 + 1) * ((double) y1 - y0 + 1) * ((double) z1 - z0 + 1) > table) {
            // A query box larger than the table: every entry once.
            for (int s = 0; s < bucketStart[table]; s++)
                if (overlaps(entryBox, 6 * s, lx, ly, lz, hx, hy, hz)) count = q.add(listed[s], count);
            return count;
        }
        if (x0 == x1 && y0 == y1 && z0 == z1) {
            // One cell (a point's query): its bucket's boxes, read in one sweep beside the entries.
            final int h = HashedCells.bucket(x0, y0, z0, table);
            for (int s = bucketStart[h], e = bucketStart[h + 1]; s < e; s++)
                if (overlaps(entryBox, 6 * s, lx, ly, lz, hx, hy, hz)) count = q.add(listed[s], count);
            return count;
        }
        // Several cells share most of their triangles: each triangle's box is tested once, when first met.
        for (long cx = x0; cx <= x1; cx++)
            for (long cy = y0; cy <= y1; cy++)
                for (long cz = z0; cz <= z1; cz++) {
                    final int h = HashedCells.bucket((int) cx, (int) cy, (int) cz, table);
                    for (int s = bucketStart[h], e = bucketStart[h + 1]; s < e; s++) {
                        final int t = listed[s];
                        if (q.first(t) && overlaps(boxes, 6 * t, lx, ly, lz, hx, hy, hz)) count = q.append(t, count);
                    }
                }
        return count;
    }

    private static boolean overlaps(double[] box, int b, double lx, double ly, double lz, double hx, double hy, double hz) {
        return !(hx < box[b] || lx > box[b + 3] || hy < box[b + 1] || ly > box[b + 4] || hz < box[b + 2] || lz > box[b + 5]);
    }

    private long cellsOf(double[] boxes, int t) {
        final int b = 6 * t;
        return ((long) index(boxes[b + 3]) - index(boxes[b]) + 1) * ((long) index(boxes[b + 4]) - index(boxes[b + 1]) + 1)
                * ((long) index(boxes[b + 5]) - index(boxes[b + 2]) + 1);
    }

    private int index(double v) { return HashedCells.index(v, cell); }
}
