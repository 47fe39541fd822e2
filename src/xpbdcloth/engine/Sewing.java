package xpbdcloth.engine;

import java.util.List;

/**
 * A garment's seams sewn shut over a set time, as garment CAD sews panels placed around a body. Each stitch
 * ({@link StitchBlock}) starts at its gap; its rest length shrinks linearly to zero over the first
 * {@link #PULLING} of the sewing time, pulling with the sewing compliance, then it holds hard (α = 0, rest
 * 0). At the sewing time the seams close: each group of stitched particles is welded into one point after
 * every step ({@link #weld}), so a closed seam is one line of points, and the hinges across the seams
 * ({@link DihedralBlock}, family {@link ConstraintFamily#SEAM}, flat at rest) bend at the fabric's
 * stiffness times a factor (1: the seam bends as the fabric does; more: a stiffer seam allowance). Those
 * hinges come in over the last {@link #HINGES_FROM} of the sewing; before that they are as compliant as
 * the engine allows: their two triangles do not meet yet, and a bend between them would be a torque on
 * nothing.
 *
 * <p>Runs after each step the simulation keeps; it allocates nothing.
 */
public final class Sewing implements AfterStep {
    private final StitchBlock stitches;
    /** The stitched particles in groups that become one point (a corner where three panels meet is one group of three). */
    private final int[] groupStart, groupMember;
    /** While sewing weightless: the simulation whose gravity is held off (null once closed, or if not weightless). */
    private Simulation floating;
    /** Velocity damping while sewing weightless, 1/s: the panels follow their stitches without momentum. */
    static final double SEWING_DAMPING = 20;
    /** The stitches' rest lengths reach zero at this fraction of the sewing time; they hold hard after it. */
    static final double PULLING = 0.6;
    /** The hinges across the seams come in over the last part of the sewing, this fraction of it (quadratically). */
    static final double HINGES_FROM = 0.4;
    private final DihedralBlock hinges;
    private final double[] startGap;
    private final double time, seamFactor;
    /** Each seam hinge's fabric bending stiffness B, N·m (the mean of its two sides' where they differ). */
    private final double[] bendingStiffness;
    private double elapsed;
    /** Whether the stitches hold hard (their pulling done), and whether the seams have closed. */
    private boolean holding, closed;

    /**
     * @param stitchPairs            particle pairs (a, b, a, b, …) to sew together
     * @param hinges                 the hinges across the seams, (o0, o1, e0, e1) per hinge
     * @param restAreaOverEdgeSquared each hinge's (A₀ + A₁)/|e|² at rest
     * @param time                   sewing time, s (0: closed from the start)
     * @param compliance             the stitches' compliance while sewing, m/N
     * @param bendingStiffness       the fabric's bending stiffness B, N·m
     * @param seamFactor             the seam's bending stiffness over the fabric's (≥ 1 for a seam allowance)
     */
    public Sewing(Particles p, int[] stitchPairs, int[] hinges, double[] restAreaOverEdgeSquared, double time, double compliance,
                  double bendingStiffness, double seamFactor) {
        this(p, stitchPairs, hinges, restAreaOverEdgeSquared, time, compliance,
                filled(restAreaOverEdgeSquared.length, Check.inRange("bendingStiffness", bendingStiffness, Double.MIN_NORMAL, 1e6)), seamFactor);
    }

    /** As above, each seam hinge with its own fabric bending stiffness (a seam between panels of two fabrics). */
    public Sewing(Particles p, int[] stitchPairs, int[] hinges, double[] restAreaOverEdgeSquared, double time, double compliance,
                  double[] bendingStiffness, double seamFactor) {
        if (stitchPairs.length % 2 != 0) throw new IllegalArgumentException("stitchPairs must be pairs, was " + stitchPairs.length + " numbers");
        if (hinges.length != 4 * restAreaOverEdgeSquared.length)
            throw new IllegalArgumentException("hinges must be 4 particles per rest value (" + 4 * restAreaOverEdgeSquared.length + "), was " + hinges.length);
        this.time = Check.inRange("time", time, 0, 1e6);
        Check.inRange("compliance", compliance, 0, EngineRange.MAX_COMPLIANCE);
        if (bendingStiffness.length != restAreaOverEdgeSquared.length)
            throw new IllegalArgumentException("bendingStiffness must have one value per hinge (" + restAreaOverEdgeSquared.length + "), was " + bendingStiffness.length);
        for (int h = 0; h < bendingStiffness.length; h++) Check.inRange("bendingStiffness[" + h + "]", bendingStiffness[h], Double.MIN_NORMAL, 1e6);
        this.bendingStiffness = bendingStiffness.clone();
        this.seamFactor = Check.inRange("seamFactor", seamFactor, 1e-3, 1e3);
        stitches = new StitchBlock(Math.max(1, stitchPairs.length / 2));
        startGap = new double[stitchPairs.length / 2];
        for (int k = 0; k < startGap.length; k++) {
            Check.index("stitchPairs", stitchPairs[2 * k], p.count());
            Check.index("stitchPairs", stitchPairs[2 * k + 1], p.count());
            startGap[k] = DistanceBlock.distance(p, stitchPairs[2 * k], stitchPairs[2 * k + 1]);
            stitches.add(stitchPairs[2 * k], stitchPairs[2 * k + 1], startGap[k]);
            stitches.setCompliance(k, compliance);
        }
        int[][] groups = groups(stitchPairs, p.count());
        groupStart = groups[0];
        groupMember = groups[1];
        this.hinges = new DihedralBlock(ConstraintFamily.SEAM, Math.max(1, restAreaOverEdgeSquared.length));
        for (int h = 0; h < restAreaOverEdgeSquared.length; h++) {
            for (int k = 0; k < 4; k++) Check.index("hinges", hinges[4 * h + k], p.count());
            this.hinges.addFlat(hinges[4 * h], hinges[4 * h + 1], hinges[4 * h + 2], hinges[4 * h + 3], restAreaOverEdgeSquared[h], EngineRange.MAX_COMPLIANCE);
        }
        if (this.time == 0) close();
    }

    /**
     * The blocks to add to the simulation, after the fabric's: the hinges across the seams, then the
     * stitches, so a sweep ends with each stitched pair put together (the crossing guard, after the solve,
     * then sees the seams shut, and the weld after the step moves next to nothing).
     */
    public List<ConstraintBlock> blocks() { return List.of(hinges, stitches); }

    public StitchBlock stitches() { return stitches; }

    public DihedralBlock hinges() { return hinges; }

    @Override public void afterStep(Particles particles, double dt) {
        if (!closed) {
            elapsed += dt;
            if (elapsed >= time) close();
        }
        if (closed) { weld(particles); return; }
        // The rest lengths reach zero at PULLING of the time; the stitches hold hard for the rest of it, so
        // the seams have met when they close and the weld moves nothing far (a weld that snaps millimetres
        // moves particles after the crossing guard has passed them).
        double pulled = Math.min(1, elapsed / (PULLING * time));
        if (pulled < 1) for (int k = 0; k < startGap.length; k++) stitches.setRestLength(k, startGap[k] * (1 - pulled));
        else if (!holding) holdHard();
        double left = 1 - elapsed / time;
        if (left < HINGES_FROM) {
            double ramp = (HINGES_FROM - left) / HINGES_FROM;
            bendHinges(ramp);
        }
    }

    /** The stitched particles' groups (union of the pairs), as (start offsets, members): each group two or more. */
    private static int[][] groups(int[] pairs, int n) {
        int[] root = new int[n];
        for (int i = 0; i < n; i++) root[i] = i;
        for (int k = 0; k < pairs.length; k += 2) {
            int a = find(root, pairs[k]), b = find(root, pairs[k + 1]);
            if (a != b) root[Math.max(a, b)] = Math.min(a, b);
        }
        java.util.Map<Integer, java.util.List<Integer>> byRoot = new java.util.TreeMap<>();
        for (int v : pairs) {
            java.util.List<Integer> g = byRoot.computeIfAbsent(find(root, v), r -> new java.util.ArrayList<>());
            if (!g.contains(v)) g.add(v);
        }
        int[] start = new int[byRoot.size() + 1], member = new int[byRoot.values().stream().mapToInt(java.util.List::size).sum()];
        int g = 0, m = 0;
        for (java.util.List<Integer> group : byRoot.values()) {
            start[g++] = m;
            for (int v : group) member[m++] = v;
        }
        start[g] = m;
        return new int[][] {start, member};
    }

    private static int find(int[] root, int v) {
        while (root[v] != v) v = root[v] = root[root[v]];
        return v;
    }

    /**
     * A closed seam's stitched particles made one point at the end of every step: each group moved to its
     * centre of mass with its momentum's velocity (a perfectly inelastic merge: momentum kept, the relative
     * motion, which hard stitches leave at a millimetre against a stiff fabric pressed onto a body, taken
     * out). A group with a pinned particle gathers where the pin is and moves as it does.
     */
    private void weld(Particles p) {
        final double[] x = p.x, v = p.v, w = p.w;
        for (int g = 0; g + 1 < groupStart.length; g++) {
            double mass = 0, mx = 0, my = 0, mz = 0, px = 0, py = 0, pz = 0;
            boolean pinned = false;
            for (int k = groupStart[g]; k < groupStart[g + 1]; k++) {
                int i = groupMember[k];
                if (w[i] == 0) {
                    if (!pinned) { mass = 0; mx = my = mz = px = py = pz = 0; }
                    pinned = true;
                    mass += 1;
                    mx += x[3 * i]; my += x[3 * i + 1]; mz += x[3 * i + 2];
                    px += v[3 * i]; py += v[3 * i + 1]; pz += v[3 * i + 2];
                } else if (!pinned) {
                    double m = 1 / w[i];
                    mass += m;
                    mx += m * x[3 * i]; my += m * x[3 * i + 1]; mz += m * x[3 * i + 2];
                    px += m * v[3 * i]; py += m * v[3 * i + 1]; pz += m * v[3 * i + 2];
                }
            }
            mx /= mass; my /= mass; mz /= mass; px /= mass; py /= mass; pz /= mass;
            for (int k = groupStart[g]; k < groupStart[g + 1]; k++) {
                int i = 3 * groupMember[k];
                if (w[groupMember[k]] == 0) continue;
                x[i] = mx; x[i + 1] = my; x[i + 2] = mz;
                v[i] = px; v[i + 1] = py; v[i + 2] = pz;
            }
        }
    }

    /**
     * Sews without weight and without momentum: until the seams close, a force on every free particle holds
     * up its weight (−m g, the simulation's gravity whatever its settings then) and damps its motion at
     * {@link #SEWING_DAMPING} per second (−m c v at the step's start). The panels float where they were
     * placed and follow their stitches, as garment CAD sews them: under gravity they fall before they meet,
     * and with their momentum two edges coming together overshoot, one past the other, and the seam closes
     * folded back on itself (a 180° hinge: measured on the skirt's side seams, docs/garments.md). A force
     * and not changed settings, so whatever sets the simulation's settings meanwhile (a key) keeps them.
     */
    public Sewing weightless(Simulation sim) {
        if (closed) return this;
        floating = sim;
        sim.add(this::holdUp);
        return this;
    }

    private void holdUp(Particles p, double t, double dt) {
        if (floating == null) return;
        SolverSettings s = floating.settings();
        final double gx = s.gravityX(), gy = s.gravityY(), gz = s.gravityZ(), c = SEWING_DAMPING;
        for (int i = 0, n = p.count(); i < n; i++) {
            if (p.w[i] == 0) continue;
            double m = 1 / p.w[i];
            p.addForce(i, -m * (gx + c * p.v[3 * i]), -m * (gy + c * p.v[3 * i + 1]), -m * (gz + c * p.v[3 * i + 2]));
        }
    }

    private void holdHard() {
        holding = true;
        for (int k = 0; k < startGap.length; k++) {
            stitches.setRestLength(k, 0);
            stitches.setCompliance(k, 0);
        }
        stitches.gatherGroups(groupStart, groupMember);
    }

    private void close() {
        closed = true;
        holdHard();
        bendHinges(1);
        floating = null;
    }

    /**
     * The hinges across the seams at bending stiffness seamFactor · B · ramp² (N·m), the ramp rising to 1 as
     * the seams close; as compliant as the engine allows where that is softer.
     */
    private void bendHinges(double ramp) {
        for (int h = 0; h < hinges.count(); h++) {
            double b = seamFactor * bendingStiffness[h] * ramp * ramp;
            hinges.setCompliance(h, Math.min(EngineRange.MAX_COMPLIANCE, hinges.areaOverEdgeSquared[h] / b));
        }
    }

    private static double[] filled(int n, double value) {
        double[] out = new double[n];
        java.util.Arrays.fill(out, value);
        return out;
    }

    @Override public void check(List<ConstraintBlock> blocks) {
        if (!blocks.contains(stitches) || !blocks.contains(hinges))
            throw new IllegalArgumentException("sewing: add its blocks (blocks()) to the simulation before the sewing itself");
    }

    /** A new fabric's bending stiffness: the seams bend with it (times the seam factor) once closed. */
    public void useBendingStiffness(double b) {
        java.util.Arrays.fill(bendingStiffness, Check.inRange("bendingStiffness", b, Double.MIN_NORMAL, 1e6));
        if (closed) bendHinges(1);
    }

    public boolean closed() { return closed; }

    /** Time sewn so far, s. */
    public double elapsed() { return elapsed; }

    public double time() { return time; }

    /** The widest gap of any stitch now, m. */
    public double largestGap(Particles p) {
        double g = 0;
        for (int k = 0; k < startGap.length; k++) g = Math.max(g, stitches.gap(k, p));
        return g;
    }
}
