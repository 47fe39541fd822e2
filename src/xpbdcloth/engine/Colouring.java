package xpbdcloth.engine;

import java.util.List;

/**
 * Greedy graph colouring of the units (what one projection solves: a constraint, or a triangle's rows)
 * of some blocks, taken in order (block by block, index by index): each unit gets the smallest colour that no earlier constraint sharing one of its
 * particles has. Within a colour the original order is kept, so the result is deterministic, and a
 * colour's constraints, sharing no particle, can be projected in any order or on any number of threads
 * with the same result. Built when the set of constraints changes, never during a step.
 */
final class Colouring {
    final List<ConstraintBlock> blocks;
    final int colours;
    /** For block b: its unit indices grouped by colour; colour c is order[b][start[b][c] .. start[b][c + 1]). */
    final int[][] order, start;

    private Colouring(List<ConstraintBlock> blocks, int colours, int[][] order, int[][] start) {
        this.blocks = blocks;
        this.colours = colours;
        this.order = order;
        this.start = start;
    }

    static Colouring of(List<ConstraintBlock> blocks, int particleCount) {
        // usedBy[p] lists the colours already used by constraints on particle p, as a growable bit set.
        long[][] usedBy = new long[particleCount][];
        int[][] colourOf = new int[blocks.size()][];
        int colours = 0;
        for (int b = 0; b < blocks.size(); b++) {
            ConstraintBlock block = blocks.get(b);
            colourOf[b] = new int[block.units()];
            for (int u = 0; u < block.units(); u++) {
                int i = u * block.rowsPerUnit(), c = 0;
                search:
                while (true) {
                    for (int k = 0; k < block.arity(); k++) if (isSet(usedBy[block.particle(i, k)], c)) { c++; continue search; }
                    break;
                }
                for (int k = 0; k < block.arity(); k++) {
                    int p = block.particle(i, k);
                    usedBy[p] = set(usedBy[p], c);
                }
                colourOf[b][u] = c;
                colours = Math.max(colours, c + 1);
            }
        }
        int[][] order = new int[blocks.size()][], start = new int[blocks.size()][];
        for (int b = 0; b < blocks.size(); b++) {
            int[] s = new int[colours + 1];
            for (int c : colourOf[b]) s[c + 1]++;
            for (int c = 0; c < colours; c++) s[c + 1] += s[c];
            int[] fill = s.clone(), o = new int[colourOf[b].length];
            for (int i = 0; i < o.length; i++) o[fill[colourOf[b][i]]++] = i;
            order[b] = o;
            start[b] = s;
        }
        return new Colouring(List.copyOf(blocks), colours, order, start);
    }

    private static boolean isSet(long[] bits, int c) {
        return bits != null && (c >> 6) < bits.length && (bits[c >> 6] & (1L << (c & 63))) != 0;
    }

    private static long[] set(long[] bits, int c) {
        int word = c >> 6;
        if (bits == null) bits = new long[word + 1];
        else if (word >= bits.length) bits = java.util.Arrays.copyOf(bits, word + 1);
        bits[word] |= 1L << (c & 63);
        return bits;
    }
}
