package xpbdcloth.engine;

import java.util.List;

/**
 * Constraints named by (block, index) in two flat arrays: how a solver that takes its rows from several
 * blocks (the global solver) walks them through the blocks' own arrays, without a view object per row.
 */
final class ConstraintRows {
    final ConstraintBlock[] block;
    final int[] index;

    private ConstraintRows(int n) {
        block = new ConstraintBlock[n];
        index = new int[n];
    }

    /** Every row of these blocks, block by block. */
    static ConstraintRows of(List<ConstraintBlock> blocks) {
        int n = 0;
        for (ConstraintBlock b : blocks) n += b.count();
        ConstraintRows r = new ConstraintRows(n);
        int k = 0;
        for (ConstraintBlock b : blocks)
            for (int i = 0; i < b.count(); i++, k++) { r.block[k] = b; r.index[k] = i; }
        return r;
    }

    /** The rows these views stand for, in their order. */
    static ConstraintRows of(Constraint[] views) {
        ConstraintRows r = new ConstraintRows(views.length);
        for (int k = 0; k < views.length; k++) { r.block[k] = views[k].block; r.index[k] = views[k].index; }
        return r;
    }

    int count() { return index.length; }

    /** The particles of row k, in its gradient's order. */
    int[] particles(int k) {
        int[] p = new int[block[k].arity()];
        for (int j = 0; j < p.length; j++) p[j] = block[k].particle(index[k], j);
        return p;
    }
}
