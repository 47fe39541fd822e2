package xpbdcloth.engine;

import java.util.Arrays;

/**
 * Stitches: each pulls a particle on one side of a seam towards its partner on the other, down to a rest
 * distance the sewing shrinks to zero ({@link Sewing}), then holds them together.
 *
 * <pre>
 *   C(x)   = |x_a − x_b| − r        (r from the stitch's starting gap down to 0 as the seam is sewn)
 *   ∇_a C  =  n,   ∇_b C = −n,   n = (x_a − x_b) / |x_a − x_b|,   Σ wᵢ|∇ᵢC|² = w_a + w_b
 * </pre>
 * A distance constraint (Müller et al. 2007, §3.3; compliant, Macklin et al. 2016, eq. 18) whose rest length
 * changes between steps, which is why it is a block of its own: the solvers that take distance rows into
 * their own systems (vertex block descent, the global solvers) read those rest lengths once, and project
 * stitches as they project anything else they do not take. Degenerate case: a closed stitch (the two
 * particles at one point) has no direction and is satisfied; it is skipped.
 */
public final class StitchBlock extends ConstraintBlock {
    /** r per stitch, m. */
    private double[] rest;

    public StitchBlock(int capacity) {
        super(ConstraintFamily.SEAM, 2, capacity);
        rest = new double[lambda.length];
    }

    /** Adds a stitch between a and b at rest distance r (m); returns its index. */
    public int add(int a, int b, double r) {
        DistanceBlock.checkEnds(a, b, r);
        int i = newSlot();
        particles[2 * i] = a;
        particles[2 * i + 1] = b;
        rest[i] = r;
        return i;
    }

    public int a(int i) { return particles[2 * i]; }
    public int b(int i) { return particles[2 * i + 1]; }
    public double restLength(int i) { return rest[i]; }
    public void setRestLength(int i, double r) { rest[i] = Check.nonNegative("r", r); }

    /** How far apart the stitch's two particles are now, m. */
    public double gap(int i, Particles p) { return DistanceBlock.distance(p, a(i), b(i)); }


    @Override public double evaluate(int i, Particles p) { return gap(i, p) - rest[i]; }

    @Override public void gradient(int i, Particles p, double[] out) { DistanceBlock.unitGradient(p, a(i), b(i), out); }

    @Override void project(int i, Particles p, SolverContext ctx) { DistanceBlock.projectPair(this, i, a(i), b(i), rest[i], p, ctx); }

    @Override void projectRange(int from, int to, Particles p, SolverContext ctx) {
        for (int i = from; i < to; i++) project(i, p, ctx);
        if (to == count() && groupStart != null) gather(p);
    }

    /** Groups of stitched particles (start offsets, members) that are put at one point after a whole sweep of the block, or null. */
    private int[] groupStart, groupMember;

    /**
     * Once the seams hold hard: after each sweep over all its stitches the block puts every group of
     * stitched particles at its centre of mass. One pass of pairwise projections leaves a group of three or
     * four (where seams meet at a corner) a millimetre apart; gathered here, inside the solve, a seam is
     * shut before the crossing guard looks at the substep, so nothing moves it after the guard has passed.
     * Null: no gathering (while the seams are still pulled).
     */
    void gatherGroups(int[] start, int[] member) { groupStart = start; groupMember = member; }

    private void gather(Particles p) {
        final double[] x = p.x, w = p.w;
        for (int g = 0; g + 1 < groupStart.length; g++) {
            double mass = 0, cx = 0, cy = 0, cz = 0;
            boolean pinned = false;
            for (int k = groupStart[g]; k < groupStart[g + 1]; k++) {
                int i = groupMember[k];
                double m = w[i] == 0 ? 1 : 1 / w[i];
                if (w[i] == 0 && !pinned) { pinned = true; mass = cx = cy = cz = 0; }
                if (pinned && w[i] != 0) continue;
                mass += m; cx += m * x[3 * i]; cy += m * x[3 * i + 1]; cz += m * x[3 * i + 2];
            }
            cx /= mass; cy /= mass; cz /= mass;
            for (int k = groupStart[g]; k < groupStart[g + 1]; k++) {
                int i = groupMember[k];
                if (w[i] == 0) continue;
                x[3 * i] = cx; x[3 * i + 1] = cy; x[3 * i + 2] = cz;
            }
        }
    }

    @Override void projectListed(int[] order, int from, int to, Particles p, SolverContext ctx) {
        for (int k = from; k < to; k++) project(order[k], p, ctx);
    }

    @Override Constraint view(int i) { return new Constraint(this, i) { }; }

    @Override StitchBlock emptyLike(int capacity) { return new StitchBlock(capacity); }

    @Override void copyRest(int i, ConstraintBlock from, int j) { rest[i] = ((StitchBlock) from).rest[j]; }

    @Override void grow(int capacity) {
        super.grow(capacity);
        rest = Arrays.copyOf(rest, capacity);
    }
}
