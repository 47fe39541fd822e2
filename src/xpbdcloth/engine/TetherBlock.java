package xpbdcloth.engine;

import java.util.Arrays;

/**
 * Long-range attachments (tethers): a free particle may not be farther from a pinned particle than its
 * rest distance to it along the cloth. An inequality, projected only while stretched:
 *
 * <pre>
 *   C(x) = |x_f − x_a| − d̄ ≤ 0,   ∇_f C = n = (x_f − x_a)/|x_f − x_a|   (the anchor is pinned: w_a = 0)
 *   Δx_f = −C n  when C &gt; 0  (hard; the anchor does not move)
 * </pre>
 * Particle order: anchor, free particle. d̄ is the rest geodesic distance (shortest path along the rest
 * mesh's edges, an upper bound of the true geodesic by at most the mesh's zig-zag), so a tether never
 * pulls a cloth that is not stretched. Source: Kim, Chentanez, Müller 2012, "Long Range Attachments – A
 * Method to Simulate Inextensible Clothing in Computer Games" (one tether to the nearest anchor).
 * Why: Gauss–Seidel carries a pin's hold down a long hanging cloth one edge per sweep, so a cloth many
 * edges long stretches under its weight however stiff its material; the tether bounds that stretch in one
 * projection. Degenerate case: the particle on its anchor has no direction, and C ≤ 0 anyway.
 */
public final class TetherBlock extends ConstraintBlock {
    /** d̄ per tether, m. */
    double[] restDistance;

    public TetherBlock(ConstraintFamily family, int capacity) {
        super(family, 2, capacity);
        restDistance = new double[lambda.length];
    }

    /** Tethers {@code free} to {@code anchor} at distance at most {@code distance} (m). */
    public int add(int anchor, int free, double distance) {
        if (anchor == free) throw new IllegalArgumentException("anchor and free particle must differ, was " + anchor);
        Check.nonNegative("distance", distance);
        int i = newSlot();
        particles[2 * i] = anchor;
        particles[2 * i + 1] = free;
        restDistance[i] = distance;
        return i;
    }

    public double restDistance(int i) { return restDistance[i]; }

    private double length(int i, double[] x) {
        int a = 3 * particles[2 * i], f = 3 * particles[2 * i + 1];
        double dx = x[f] - x[a], dy = x[f + 1] - x[a + 1], dz = x[f + 2] - x[a + 2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /** max(0, |x_f − x_a| − d̄): the inequality's violation (0 when slack). */
    @Override public double evaluate(int i, Particles p) { return Math.max(0, length(i, p.x) - restDistance[i]); }

    @Override public void gradient(int i, Particles p, double[] out) {
        Arrays.fill(out, 0, 6, 0);
        double[] x = p.x;
        int a = 3 * particles[2 * i], f = 3 * particles[2 * i + 1];
        double len = length(i, x);
        if (len < DistanceBlock.MIN_LENGTH || len <= restDistance[i]) return;
        for (int k = 0; k < 3; k++) {
            double n = (x[f + k] - x[a + k]) / len;
            out[3 + k] = n;
            out[k] = -n;
        }
    }

    @Override void project(int i, Particles p, SolverContext ctx) {
        final double[] x = p.x;
        final int anchor = particles[2 * i], free = particles[2 * i + 1], a = 3 * anchor, f = 3 * free;
        double dx = x[f] - x[a], dy = x[f + 1] - x[a + 1], dz = x[f + 2] - x[a + 2];
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double C = len - restDistance[i];
        double w = p.w[free];
        if (C <= 0 || len < DistanceBlock.MIN_LENGTH || w == 0) return;
        double s = -C / len; // hard, and the anchor is pinned: the free particle takes all of it
        x[f] += s * dx; x[f + 1] += s * dy; x[f + 2] += s * dz;
    }

    @Override void projectRange(int from, int to, Particles p, SolverContext ctx) {
        for (int i = from; i < to; i++) project(i, p, ctx);
    }

    @Override void projectListed(int[] order, int from, int to, Particles p, SolverContext ctx) {
        for (int k = from; k < to; k++) project(order[k], p, ctx);
    }

    @Override Constraint view(int i) { return new BlockConstraint(this, i); }

    @Override TetherBlock emptyLike(int capacity) { return new TetherBlock(family(), capacity); }

    @Override void copyRest(int i, ConstraintBlock from, int j) { restDistance[i] = ((TetherBlock) from).restDistance[j]; }

    @Override void grow(int capacity) {
        super.grow(capacity);
        restDistance = Arrays.copyOf(restDistance, capacity);
    }
}
