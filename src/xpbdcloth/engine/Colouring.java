package xpbdcloth.engine;

import java.util.List;

/**
 * Greedy graph colouring of constraints: constraint i gets the smallest colour that no earlier
 * constraint sharing one of its particles has. Within a colour the original order is kept, so the
 * result is deterministic. Built when the set of constraints changes, never during a step.
 */
final class Colouring {
    /** The constraints grouped by colour. */
    final Constraint[] ordered;
    /** Colour c holds ordered[start[c] .. start[c + 1]). */
    final int[] start;

    private Colouring(Constraint[] ordered, int[] start) {
        this.ordered = ordered;
        this.start = start;
    }

    int colours() { return start.length - 1; }

    static Colouring of(Constraint[] cs, int particleCount) {
        // usedBy[p] lists the colours already used by constraints on particle p, as a growable bit set.
        long[][] usedBy = new long[particleCount][];
        int[] colourOf = new int[cs.length];
        int colours = 0;
        for (int i = 0; i < cs.length; i++) {
            int[] ps = cs[i].particles();
            int c = 0;
            search:
            while (true) {
                for (int p : ps) if (isSet(usedBy[p], c)) { c++; continue search; }
                break;
            }
            for (int p : ps) usedBy[p] = set(usedBy[p], c);
            colourOf[i] = c;
            colours = Math.max(colours, c + 1);
        }
        int[] start = new int[colours + 1];
        for (int c : colourOf) start[c + 1]++;
        for (int c = 0; c < colours; c++) start[c + 1] += start[c];
        int[] fill = start.clone();
        Constraint[] ordered = new Constraint[cs.length];
        for (int i = 0; i < cs.length; i++) ordered[fill[colourOf[i]]++] = cs[i];
        return new Colouring(ordered, start);
    }

    /** Concatenates colourings of consecutive groups (body, attachments, contacts): groups stay in turn. */
    static Colouring concat(List<Colouring> parts) {
        int n = 0, colours = 0;
        for (Colouring p : parts) { n += p.ordered.length; colours += p.colours(); }
        Constraint[] ordered = new Constraint[n];
        int[] start = new int[colours + 1];
        int k = 0, c = 0;
        for (Colouring p : parts) {
            for (int j = 0; j < p.colours(); j++) start[c + j + 1] = k + p.start[j + 1];
            System.arraycopy(p.ordered, 0, ordered, k, p.ordered.length);
            k += p.ordered.length;
            c += p.colours();
        }
        return new Colouring(ordered, start);
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
