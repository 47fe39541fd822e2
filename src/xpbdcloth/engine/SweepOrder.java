package xpbdcloth.engine;

import java.util.ArrayList;
import java.util.List;

/**
 * The order of one Gauss–Seidel sweep: segments, each a range of one block's units (as built) or a
 * stretch of a list of its unit indices (coloured), grouped into phases whose constraints share no particle
 * (the colours), so that a phase can be split across threads. In the as-built order each segment is a
 * phase of its own and is never split.
 */
final class SweepOrder {
    final ConstraintBlock[] block;
    /** Per segment: the index list, or null for the plain range from..to−1. */
    final int[][] list;
    final int[] from, to;
    /** Phase k holds segments phaseStart[k] .. phaseStart[k + 1] − 1. */
    final int[] phaseStart;

    private SweepOrder(List<ConstraintBlock> b, List<int[]> l, List<int[]> range, List<Integer> phases) {
        int n = b.size();
        block = b.toArray(new ConstraintBlock[0]);
        list = l.toArray(new int[0][]);
        from = new int[n];
        to = new int[n];
        for (int s = 0; s < n; s++) { from[s] = range.get(s)[0]; to[s] = range.get(s)[1]; }
        phaseStart = new int[phases.size()];
        for (int k = 0; k < phaseStart.length; k++) phaseStart[k] = phases.get(k);
    }

    int phases() { return phaseStart.length - 1; }

    /** Each block whole, in the given order (a block with no constraints is left out). */
    static SweepOrder asBuilt(List<ConstraintBlock> blocks) {
        List<ConstraintBlock> b = new ArrayList<>();
        List<int[]> l = new ArrayList<>(), range = new ArrayList<>();
        List<Integer> phases = new ArrayList<>(List.of(0));
        for (ConstraintBlock block : blocks) {
            if (block.units() == 0) continue;
            b.add(block);
            l.add(null);
            range.add(new int[] {0, block.units()});
            phases.add(b.size());
        }
        return new SweepOrder(b, l, range, phases);
    }

    /** The colours of each colouring in turn (body, then attachments), each colour block by block. */
    static SweepOrder coloured(List<Colouring> parts) {
        List<ConstraintBlock> b = new ArrayList<>();
        List<int[]> l = new ArrayList<>(), range = new ArrayList<>();
        List<Integer> phases = new ArrayList<>(List.of(0));
        for (Colouring part : parts) {
            for (int k = 0; k < part.blocks.size(); k++) part.blocks.get(k).sweepOrder(part.order[k]);
            for (int c = 0; c < part.colours; c++) {
                for (int k = 0; k < part.blocks.size(); k++) {
                    int lo = part.start[k][c], hi = part.start[k][c + 1];
                    if (hi == lo) continue;
                    b.add(part.blocks.get(k));
                    l.add(part.order[k]);
                    range.add(new int[] {lo, hi});
                }
                phases.add(b.size());
            }
        }
        return new SweepOrder(b, l, range, phases);
    }

    /** Projects segment s, or its share [id/threads, (id+1)/threads) when split across threads. */
    void project(int s, int id, int threads, Particles p, SolverContext ctx) {
        int size = to[s] - from[s];
        int lo = from[s] + (int) ((long) size * id / threads), hi = from[s] + (int) ((long) size * (id + 1) / threads);
        if (list[s] == null) block[s].projectRange(lo, hi, p, ctx);
        else block[s].projectListed(list[s], lo, hi, p, ctx);
    }

    /** One sweep on this thread. */
    void sweep(Particles p, SolverContext ctx) {
        for (int s = 0; s < block.length; s++) {
            if (list[s] == null) block[s].projectRange(from[s], to[s], p, ctx);
            else block[s].projectListed(list[s], from[s], to[s], p, ctx);
        }
    }

    /** One sweep, the state checked after every projection (the replay of a step that diverged). */
    void sweep(Particles p, SolverContext ctx, StepProbe probe) {
        for (int s = 0; s < block.length; s++)
            for (int k = from[s]; k < to[s]; k++) {
                int u = list[s] == null ? k : list[s][k];
                block[s].project(u, p, ctx);
                probe.check(block[s], u * block[s].rowsPerUnit());
            }
    }
}
