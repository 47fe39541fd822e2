package xpbdcloth.engine;

import java.util.Arrays;

/**
 * The constraints of one kind (distance, shear, bend, attachment) and one {@link ConstraintFamily}, stored
 * as flat arrays: the particle indices ({@link #arity} per constraint), the rest values (in the subclass),
 * λ, and the material. A solver walks these arrays; a {@link Constraint} is only a view of one entry.
 *
 * <p>Why flat: a constraint as an object with its own fields cost 77 bytes and a pointer chase, and at
 * large N those objects no longer fit in the cache, so each projection cost more the bigger the cloth.
 * Here a distance constraint is 24 bytes (two indices, a rest length, λ); the benchmark's coloured cases
 * at N = 128 and 256 show the cost per projection no longer grows (docs/performance.md).
 *
 * <p>Material: one stiffness k and compliance α for the whole block (what a cloth's family has), with a
 * per-constraint array made only when one constraint is given a value of its own.
 *
 * <p>Each kind's maths (C, ∇C, the projection) is written once, in its subclass, as {@link #evaluate},
 * {@link #gradient} and {@link #project}; Gauss–Seidel, the parallel sweeps, the global solver's
 * assembly and the single-constraint views all call those. Δλ itself, the one place where PBD and XPBD
 * differ, is {@link Constraint#deltaLambda}.
 */
public abstract class ConstraintBlock {
    /** The most particles one constraint takes: a {@link BendingPatch} row's twelve. */
    public static final int MAX_ARITY = BendingPatch.MAX_SLOTS;
    private final ConstraintFamily family;
    private final int arity;
    /** Rows solved together in one projection (a unit): 1, or a triangle's three membrane rows, a bend's three components. */
    private final int rowsPerUnit;
    int count;
    /** Particle indices, {@link #arity} per constraint. */
    int[] particles;
    /** λ per constraint, accumulated over the current substep. */
    double[] lambda;

    private double stiffness = 1.0, compliance = 0.0, stiffnessPerSweep = 1.0;
    /** Per-constraint values, null while every constraint has the block's. */
    private double[] stiffnessOf, complianceOf, stiffnessPerSweepOf;
    /** The iteration count and correction switch the k' above were computed for; {@link #STALE} to recompute. */
    private int preparedIterations = STALE;
    private boolean preparedMuller;
    private static final int STALE = -1;
    /** The simulation this block is solved in, or null. */
    ConstraintSet owner;

    ConstraintBlock(ConstraintFamily family, int arity, int capacity) { this(family, arity, 1, capacity); }

    /** A block whose projections each solve {@code rowsPerUnit} consecutive rows on the same particles together. */
    ConstraintBlock(ConstraintFamily family, int arity, int rowsPerUnit, int capacity) {
        if (family == null) throw new IllegalArgumentException("family must not be null, was null");
        this.family = family;
        this.arity = arity;
        this.rowsPerUnit = rowsPerUnit;
        particles = new int[arity * Math.max(capacity, 1)];
        lambda = new double[Math.max(capacity, 1)];
    }

    public final ConstraintFamily family() { return family; }
    /** Scalar constraints (rows) in the block. */
    public final int count() { return count; }
    /** Particles per constraint. */
    public final int arity() { return arity; }
    /** Rows projected together ({@link #project} takes a unit): 1 for a scalar constraint. */
    public final int rowsPerUnit() { return rowsPerUnit; }
    /** Whether every C of the block is linear in the positions (∇C constant): its Hessian is ∇C∇Cᵀ exactly. */
    public boolean isLinear() { return false; }
    /** Units in the block: what a sweep projects, one at a time; a unit's rows are consecutive and share particles. */
    public final int units() { return count / rowsPerUnit; }
    /** The k-th particle (0 ≤ k &lt; arity) of constraint i. */
    public final int particle(int i, int k) { return particles[arity * i + k]; }
    public final double lambda(int i) { return lambda[i]; }

    public final double stiffness(int i) { return stiffnessOf == null ? stiffness : stiffnessOf[i]; }
    public final double compliance(int i) { return complianceOf == null ? compliance : complianceOf[i]; }
    /** k' for the current iteration count (or k without Müller's correction). */
    public final double stiffnessPerSweep(int i) { return stiffnessPerSweepOf == null ? stiffnessPerSweep : stiffnessPerSweepOf[i]; }

    /** PBD stiffness k ∈ [0, 1] for every constraint of the block. */
    public final void setStiffness(double k) { applyStiffness(Check.inRange("stiffness", k, 0, 1)); }

    /** k and α for every constraint of the block, as one value (checked when it was made). */
    public final void setMaterial(Material m) {
        applyStiffness(m.stiffness);
        applyCompliance(m.compliance);
    }

    private void applyStiffness(double k) {
        stiffness = k;
        stiffnessOf = null;
        stiffnessPerSweepOf = null;
        preparedIterations = STALE;
    }

    /** XPBD compliance α ≥ 0 (m/N) for every constraint of the block. */
    public final void setCompliance(double alpha) { applyCompliance(Check.inRange("compliance", alpha, 0, EngineRange.MAX_COMPLIANCE)); }

    private void applyCompliance(double alpha) {
        compliance = alpha;
        complianceOf = null;
        materialChanged();
    }

    /** Changes of the block's material (compliances, or a subclass's own coefficients) so far. */
    private long materialVersion;

    /** How many times the material changed: a solver that derives stiffnesses from it re-derives them when this moves. */
    final long materialVersion() { return materialVersion; }

    /** Marks the material changed (a subclass calls it when it rewrites coefficients of its own). */
    final void materialChanged() { materialVersion++; }

    /**
     * Whether a unit's rows are the components of one vector constraint and so share one material (a
     * bend's three rows: a compliance per axis would make its energy depend on the frame's orientation).
     * Then a value given to one row is given to its unit's rows.
     */
    boolean rowsShareMaterial() { return false; }

    /** PBD stiffness k ∈ [0, 1] for constraint i alone (for its unit's rows, where they share their material). */
    public final void setStiffness(int i, double k) {
        Check.inRange("stiffness", k, 0, 1);
        if (stiffnessOf == null) {
            if (k == stiffness) return;
            stiffnessOf = filled(stiffness);
            stiffnessPerSweepOf = filled(stiffnessPerSweep);
        }
        for (int r = firstRowWith(i), end = lastRowWith(i); r <= end; r++) stiffnessOf[r] = k;
        preparedIterations = STALE;
    }

    /** XPBD compliance α ≥ 0 (m/N) for constraint i alone (for its unit's rows, where they share their material). */
    public final void setCompliance(int i, double alpha) {
        Check.inRange("compliance", alpha, 0, EngineRange.MAX_COMPLIANCE);
        if (complianceOf == null) {
            if (alpha == compliance) return;
            complianceOf = filled(compliance);
        }
        for (int r = firstRowWith(i), end = lastRowWith(i); r <= end; r++) complianceOf[r] = alpha;
        materialChanged();
    }

    /** The rows that take row i's material: its unit's (those added so far), or i alone. */
    private int firstRowWith(int i) { return rowsShareMaterial() ? i - i % rowsPerUnit : i; }
    private int lastRowWith(int i) { return rowsShareMaterial() ? Math.min(i - i % rowsPerUnit + rowsPerUnit, count) - 1 : i; }

    private double[] filled(double value) {
        double[] a = new double[lambda.length];
        Arrays.fill(a, value);
        return a;
    }

    /** C(x) of constraint i at the current positions. */
    public abstract double evaluate(int i, Particles p);

    /** ∇C of constraint i, three components per particle in {@link #particle} order; zeros where C has none. */
    public abstract void gradient(int i, Particles p, double[] out);

    /**
     * One projection of unit u (rows u·{@link #rowsPerUnit} … on, solved together) in the context's mode:
     * the kind's maths, written once.
     */
    abstract void project(int u, Particles p, SolverContext ctx);

    /** Projects units from..to−1 in index order (a loop of its own per kind, so {@link #project} inlines). */
    abstract void projectRange(int from, int to, Particles p, SolverContext ctx);

    /** Projects units order[from..to−1] (the coloured order). */
    abstract void projectListed(int[] order, int from, int to, Particles p, SolverContext ctx);

    /**
     * The coloured sweep's order of this block's units (all of them, colour by colour), told once when a
     * coloured order is made and before any sweep in it, so a block may keep its rows' data in that order
     * ({@link #layOutIn}); {@link #projectListed} then gets this very array and asks {@link #laidOutIn}.
     * Told the order it has already (a grab recolours only the attachments), it copies nothing.
     */
    final void sweepOrder(int[] order) {
        if (laidOutIn(order)) return;
        if (layOutIn(order)) { laidOutOrder = order; laidOutUnits = units(); }
    }

    /** The order the block's copy is in (null before any), and its unit count then (a unit added since makes it stale). */
    private int[] laidOutOrder;
    private int laidOutUnits = -1;

    /** Whether the block holds a copy of its data in this order, made for the units it has now. */
    final boolean laidOutIn(int[] order) { return order == laidOutOrder && laidOutUnits == units(); }

    /** Copies what a sweep reads per unit into {@code order}'s order; false for a kind that keeps no copy (the default). */
    boolean layOutIn(int[] order) { return false; }

    /** a[stride·order[k] + j] for every k and every j &lt; width, in that order: per-unit data laid out in a sweep's order. */
    static int[] inOrder(int[] a, int stride, int width, int[] order) {
        int[] out = new int[width * order.length];
        for (int k = 0; k < order.length; k++) System.arraycopy(a, stride * order[k], out, width * k, width);
        return out;
    }

    /** The same for a double array. */
    static double[] inOrder(double[] a, int stride, int width, int[] order) {
        double[] out = new double[width * order.length];
        for (int k = 0; k < order.length; k++) System.arraycopy(a, stride * order[k], out, width * k, width);
        return out;
    }

    /** A view of constraint i. */
    abstract Constraint view(int i);

    /** An empty block of the same kind and family, for constraints copied in one by one. */
    abstract ConstraintBlock emptyLike(int capacity);

    /** Copies the kind's rest values of constraint j of {@code from} (the same kind) to slot i of this. */
    abstract void copyRest(int i, ConstraintBlock from, int j);

    /** Makes room for one more constraint and returns its index; the subclass fills its particles and rest value. */
    final int newSlot() {
        if (count == lambda.length) grow(2 * count);
        return count++;
    }

    /** Appends a copy of constraint j of {@code from} (same kind), material included. */
    final int appendCopy(ConstraintBlock from, int j) {
        if (count == 0) {
            stiffness = from.stiffness(j);
            compliance = from.compliance(j);
            stiffnessPerSweep = from.stiffnessPerSweep(j);
            preparedIterations = STALE;
        }
        if (count == lambda.length) grow(2 * count);
        int i = count++;
        System.arraycopy(from.particles, from.arity * j, particles, arity * i, arity);
        copyRest(i, from, j);
        lambda[i] = from.lambda[j];
        setStiffness(i, from.stiffness(j));
        setCompliance(i, from.compliance(j));
        return i;
    }

    /** Grows every array to {@code capacity} constraints (the subclass grows its own). */
    void grow(int capacity) {
        particles = Arrays.copyOf(particles, arity * capacity);
        lambda = Arrays.copyOf(lambda, capacity);
        if (stiffnessOf != null) stiffnessOf = Arrays.copyOf(stiffnessOf, capacity);
        if (stiffnessPerSweepOf != null) stiffnessPerSweepOf = Arrays.copyOf(stiffnessPerSweepOf, capacity);
        if (complianceOf != null) complianceOf = Arrays.copyOf(complianceOf, capacity);
    }

    /** Removes constraint i, moving the later ones down by one (attachments, which are few). */
    void remove(int i) {
        int tail = count - i - 1;
        System.arraycopy(particles, arity * (i + 1), particles, arity * i, arity * tail);
        System.arraycopy(lambda, i + 1, lambda, i, tail);
        if (stiffnessOf != null) System.arraycopy(stiffnessOf, i + 1, stiffnessOf, i, tail);
        if (stiffnessPerSweepOf != null) System.arraycopy(stiffnessPerSweepOf, i + 1, stiffnessPerSweepOf, i, tail);
        if (complianceOf != null) System.arraycopy(complianceOf, i + 1, complianceOf, i, tail);
        count--;
    }

    /**
     * Whether the block's compliance comes from a measured modulus (a fabric's membrane and bending): then
     * it is solved with it in either mode. PBD's k is a fraction of the error one projection removes, with no
     * unit to take a modulus, and a fabric given k = 1 instead is a rigid plate whose hard membrane and
     * bending fight each other: a 6 × 6 denim in PBD mode reached 1e4 m/s in 2 s (docs/robustness.md).
     */
    boolean compliantInAnyMode() { return false; }

    /** The mode this block is solved in: the context's, or XPBD for a {@link #compliantInAnyMode} block. */
    final ConstraintMode mode(SolverContext ctx) { return compliantInAnyMode() ? ConstraintMode.XPBD : ctx.mode; }

    /** Whether a sweep may take this block in XPBD with one compliance for all (no per-constraint values). */
    final boolean uniformXpbd(SolverContext ctx) { return mode(ctx) == ConstraintMode.XPBD && complianceOf == null; }

    /** Once per substep before the sweeps: λ = 0, and k' refreshed if n, k or the correction changed. */
    final void beginSubstep(SolverContext ctx) {
        Arrays.fill(lambda, 0, count, 0);
        if (preparedIterations == ctx.iterations && preparedMuller == ctx.mullerCorrection) return;
        stiffnessPerSweep = perSweep(stiffness, ctx);
        if (stiffnessOf != null) for (int i = 0; i < count; i++) stiffnessPerSweepOf[i] = perSweep(stiffnessOf[i], ctx);
        preparedIterations = ctx.iterations;
        preparedMuller = ctx.mullerCorrection;
    }

    /** Müller's k' = 1 − (1 − k)^(1/n), so n sweeps of one constraint remove the fraction k of its error. */
    private static double perSweep(double k, SolverContext ctx) {
        return ctx.mullerCorrection && ctx.iterations > 1 ? 1.0 - Math.pow(1.0 - k, 1.0 / ctx.iterations) : k;
    }

    /** Δλ for constraint i with value C and Σ wᵢ|∇ᵢC|² = wGradSq, accumulated into λ. */
    final double deltaLambda(int i, double C, double wGradSq, SolverContext ctx) {
        double dLambda = Constraint.deltaLambda(C, wGradSq, lambda[i],
                complianceOf == null ? compliance : complianceOf[i],
                stiffnessPerSweepOf == null ? stiffnessPerSweep : stiffnessPerSweepOf[i], mode(ctx), ctx);
        lambda[i] += dLambda;
        return dLambda;
    }
}
