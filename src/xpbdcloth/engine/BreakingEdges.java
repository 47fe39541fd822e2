package xpbdcloth.engine;

import java.util.HashSet;
import java.util.Set;

/**
 * Watches a cloth's edges for the strain that breaks them: after every step the simulation keeps, the most
 * strained edge of the triangles, ε = |x_a − x_b| / L − 1 (L its rest length), breaks if ε > ε_break (the
 * first in the edges' fixed order among equals). One a step: a tear starts at the worst edge and grows from
 * its tip, where the strain gathers, rather than opening everywhere a uniformly stretched cloth passes
 * ε_break at once. Cutting the mesh there is the scene's (it changes the particles); this only says where.
 * Serial and allocation-free.
 */
public final class BreakingEdges implements AfterStep {
    /** Each edge's ends (a < b) and its rest length, in ascending (a, b). */
    private final int[] ends;
    private final double[] restLength;
    private int worst = -1;
    private double breakingStrain, largestStrain;

    /**
     * @param rest           the particles at rest (their edges' rest lengths are read here)
     * @param triangles      three particles each
     * @param breakingStrain the engineering strain past which an edge breaks
     */
    public BreakingEdges(Particles rest, int[] triangles, double breakingStrain) {
        if (rest == null || triangles == null) throw new IllegalArgumentException("rest and triangles must not be null");
        if (triangles.length % 3 != 0) throw new IllegalArgumentException("triangles must be 3 indices each, was " + triangles.length);
        setBreakingStrain(breakingStrain);
        Set<Long> seen = new HashSet<>();
        for (int t = 0; t < triangles.length; t += 3)
            for (int k = 0; k < 3; k++) {
                int a = Check.index("triangles", triangles[t + k], rest.count()), b = Check.index("triangles", triangles[t + (k + 1) % 3], rest.count());
                seen.add((long) Math.min(a, b) << 32 | Math.max(a, b));
            }
        long[] sorted = seen.stream().mapToLong(Long::longValue).sorted().toArray();
        ends = new int[2 * sorted.length];
        restLength = new double[sorted.length];
        for (int e = 0; e < sorted.length; e++) {
            ends[2 * e] = (int) (sorted[e] >>> 32);
            ends[2 * e + 1] = (int) sorted[e];
            restLength[e] = DistanceBlock.distance(rest, ends[2 * e], ends[2 * e + 1]);
            if (!(restLength[e] > 0)) throw new IllegalArgumentException("edge (" + ends[2 * e] + ", " + ends[2 * e + 1] + ") has zero length at rest");
        }
    }

    /** Sets ε_break (a key changes it live); edges are checked against it from the next step. */
    public void setBreakingStrain(double strain) {
        breakingStrain = Check.inRange("breakingStrain", strain, 1e-6, 100);
    }

    public double breakingStrain() { return breakingStrain; }

    @Override public void afterStep(Particles p, double dt) {
        int most = -1;
        double largest = 0;
        for (int e = 0, n = restLength.length; e < n; e++) {
            double strain = DistanceBlock.distance(p, ends[2 * e], ends[2 * e + 1]) / restLength[e] - 1;
            if (strain > largest) { largest = strain; most = e; }
        }
        largestStrain = largest;
        worst = largest > breakingStrain ? most : -1;
    }

    /** Whether the last step broke an edge. */
    public boolean broke() { return worst >= 0; }

    /** The broken edge's ends, a < b (when {@link #broke}). */
    public int brokenA() { return ends[2 * brokenEdge()]; }
    public int brokenB() { return ends[2 * brokenEdge() + 1]; }

    private int brokenEdge() {
        if (worst < 0) throw new IllegalStateException("no edge broke in the last step");
        return worst;
    }

    /** The largest edge strain the last step left. */
    public double largestStrain() { return largestStrain; }
}
