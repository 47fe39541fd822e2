package xpbdcloth.engine;

import java.util.List;

/**
 * This substep's contacts, found by the collide stage and projected after every sweep of the solve: a
 * transient list, not one permanent object per particle and collider. Flat arrays sized once for the
 * worst case (every particle against every collider), so finding and solving allocate nothing. Each
 * {@link Collider} lists its own candidates and projects its own contacts; this set only holds them.
 *
 * <p>What counts as a contact: a particle closer to a sphere's surface (radius + margin) than
 * {@link #SLACK} of the radius plus the distance the particle itself moved in the prediction. Its
 * projection does nothing while the particle is outside, so a generous candidate list costs only the
 * test; it must include every particle the sweeps could push into the sphere within the substep, which a
 * particle moving farther than that in one substep's sweeps would escape (it is then caught in the next
 * substep). Order: sphere by sphere, particles ascending, the order the permanent contacts had, so
 * trajectories are unchanged bit for bit; then box, capsule and mesh, for particles within reach of the
 * ball (or the triangles) that hold the solid along its path over the substep; then the cloth's pairs
 * with itself; last plane by plane, for particles within {@link #PLANE_SLACK} of the surface (plus margin
 * and their own motion): a fixed plane has the last word in every sweep.
 */
final class ContactSet {
    /** Candidate distance beyond the surface, as a fraction of the sphere's radius. */
    static final double SLACK = 0.25;
    /** Candidate distance beyond a plane's surface, m (a plane has no size to take a fraction of). */
    static final double PLANE_SLACK = 0.05;

    private int[] particle = new int[0];
    /** What the collider knows the contact by: the particle, or (self-collision) its pair. */
    private int[] entry = new int[0];
    private Collider[] with = new Collider[0];
    private int count;
    /** Per particle: the last {@link #inside} call that counted it (no clearing between calls). */
    private int[] countedIn = new int[0];
    private int insideCalls;

    /**
     * Per particle (xyz interleaved): how far the colliders' projections moved it in this substep's solve, m,
     * for their work ({@link #countWork}); back to 0 for every particle once counted.
     */
    private double[] moved = new double[0];
    /** The work the colliders have done on the cloth so far, J. */
    private double work;

    /** The self-collision of the last collide stage, or null: its pairs are among the contacts. */
    private SelfCollision self;
    /** The self-collision's vertex–face contacts are entries [facesFrom, facesTo). */
    private int facesFrom, facesTo;

    int count() { return count; }
    SelfCollision self() { return self; }
    int particle(int k) { return particle[k]; }
    Collider with(int k) { return with[k]; }
    int entry(int k) { return entry[k]; }

    /** Makes room for every particle against every collider (when colliders are added, never during a step). */
    void reserve(int particles, int colliders) {
        int n = particles * colliders;
        if (particle.length < n) { particle = new int[n]; entry = new int[n]; with = new Collider[n]; }
        if (moved.length < 3 * particles) moved = new double[3 * particles];
    }

    /**
     * The collide stage: this substep's candidates (the spheres' first), from the predicted positions and
     * placed colliders; the self-collision's list is made by the team's threads when there is one.
     */
    void collide(Particles p, List<Sphere> spheres, List<Plane> planes, List<RigidCollider> solids, SelfCollision self, double h, Team team) {
        forgetMoves(); // a step that threw leaves its last substep's moves uncounted: they are not this substep's
        count = 0;
        this.self = self;
        for (int s = 0, ns = spheres.size(); s < ns; s++) spheres.get(s).findContacts(p, h, this);
        for (int s = 0, ns = solids.size(); s < ns; s++) solids.get(s).findContacts(p, h, this);
        facesFrom = facesTo = 0;
        if (self != null) {
            self.findContacts(p, h, this, team);
            facesFrom = count;
            self.findFaceContacts(p, h, this);
            facesTo = count;
        }
        // The fixed planes last, so they have the last word in every sweep (see project).
        for (int s = 0, ns = planes.size(); s < ns; s++) planes.get(s).findContacts(p, h, this);
    }

    /** A candidate: particle i against collider c. */
    void add(int i, Collider c) { add(i, i, c); }

    /**
     * A candidate of particle i that collider c knows by {@code e} (a self-collision pair). Pairs are not
     * bounded by the particle count, so the arrays grow when a cloth needs more than ever before.
     */
    void add(int i, int e, Collider c) {
        if (count == particle.length) {
            int n = Math.max(16, 2 * count);
            particle = java.util.Arrays.copyOf(particle, n);
            entry = java.util.Arrays.copyOf(entry, n);
            with = java.util.Arrays.copyOf(with, n);
        }
        particle[count] = i;
        entry[count] = e;
        with[count] = c;
        count++;
    }

    /** Candidates touching their collider now (within 1 µm of the surface plus margin, or inside). */
    int touching(Particles p) {
        int n = 0;
        for (int k = 0; k < count; k++) if (with[k].clearance(p, entry[k]) < TOUCHING) n++;
        return n;
    }

    /** Marks the particles of every candidate touching its collider now (both particles of a touching pair). */
    void markTouching(Particles p, boolean[] held) {
        for (int k = 0; k < count; k++) {
            if (with[k].clearance(p, entry[k]) >= TOUCHING) continue;
            held[particle[k]] = true;
            with[k].markOthers(entry[k], held);
        }
    }

    /** How near (m) a particle may be to its collider's surface plus margin and count as touching it. */
    static final double TOUCHING = 1e-6;

    /**
     * One Gauss–Seidel pass over the contacts, the fixed planes' last: where a moving solid (or the cloth's
     * own pairs) has pushed a particle into a plane (a box lowered onto cloth on the floor), the plane has
     * the last word, so the cloth is never pushed through it; it is left inside the solid instead, and
     * counted ({@link #inside}).
     */
    void project(Particles p, SolverContext ctx) {
        long t0 = System.nanoTime();
        for (int k = 0; k < count; k++) project(p, ctx, k);
        projectNanos += System.nanoTime() - t0;
    }

    /**
     * After a substep's solve: the colliders' work on the cloth, each particle's mass times what they moved it
     * by over h² (the force of their impulses, as an attachment's is counted) dotted with its move in the
     * substep, F·Δx. A moving solid's push and its friction's drag put energy in; a fixed one's stops take it out.
     * The cloth's pairs with itself are internal forces and do none.
     */
    void countWork(Particles p, double h) {
        work += workInSubstep(p, h);
        forgetMoves();
    }

    /** Forgets what the projections moved the particles by in this substep (a solve that is redone). */
    void forgetMoves() {
        for (int k = 0; k < count; k++) if (!with[k].internal()) { int k3 = 3 * particle[k]; moved[k3] = 0; moved[k3 + 1] = 0; moved[k3 + 2] = 0; }
    }

    /**
     * What {@link #countWork} adds, J, without counting it: the colliders' work in this substep's solve so far.
     * Per particle, not per contact, so a particle that two colliders moved is counted once. Only colliders'
     * projections write {@link #moved}; the cloth's own pairs do not.
     */
    double workInSubstep(Particles p, double h) {
        if (count == 0) return 0; // nothing touched: every move was forgotten when the contacts were found
        double w = 0, inverseH2 = 1 / (h * h);
        for (int i = 0, n = Math.min(p.count(), moved.length / 3); i < n; i++) {
            int k3 = 3 * i;
            double mx = moved[k3], my = moved[k3 + 1], mz = moved[k3 + 2];
            if (mx == 0 && my == 0 && mz == 0) continue;
            w += (mx * (p.x[k3] - p.prev[k3]) + my * (p.x[k3 + 1] - p.prev[k3 + 1]) + mz * (p.x[k3 + 2] - p.prev[k3 + 2])) * inverseH2 / p.w[i];
        }
        return w;
    }

    /** What the colliders (not the cloth's own pairs) have done on the cloth since this set was made, J ({@link #countWork}). */
    double work() { return work; }

    /**
     * Particles now inside a collider's surface by more than a tenth of its margin (clearance below −1.1
     * margins): caught between two colliders that close on them, where one had to give.
     */
    int inside(Particles p) {
        if (countedIn.length < p.count()) countedIn = new int[p.count()];
        insideCalls++;
        int n = 0;
        for (int k = 0; k < count; k++) {
            int i = particle[k];
            if (countedIn[i] != insideCalls && !with[k].internal() && with[k].clearance(p, entry[k]) < -1.1 * with[k].margin) {
                countedIn[i] = insideCalls;
                n++;
            }
        }
        return n;
    }

    /** Wall time spent in {@link #project(Particles, SolverContext)} since the counter was last read. */
    long takeProjectNanos() {
        long t = projectNanos;
        projectNanos = 0;
        return t;
    }

    private long projectNanos;

    /**
     * The contacts of each particle (both particles of a pair), as lists: particle i's are
     * list[start[i] .. start[i + 1]); {@code start} has n + 1 entries, {@code list} grows when it must.
     */
    int[] byParticle(int n, int[] start, int[] list) {
        java.util.Arrays.fill(start, 0, n + 1, 0);
        int entries = 0;
        for (int k = 0; k < count; k++) {
            start[particle[k] + 1]++;
            int other = with[k].partner(entry[k]);
            if (other >= 0) start[other + 1]++;
        }
        for (int i = 0; i < n; i++) start[i + 1] += start[i];
        entries = start[n];
        if (list.length < entries) list = new int[Math.max(entries, 2 * list.length)];
        for (int k = 0; k < count; k++) {
            list[start[particle[k]]++] = k;
            int other = with[k].partner(entry[k]);
            if (other >= 0) list[start[other]++] = k;
        }
        // The fill advanced each start to its list's end: shift back.
        for (int i = n; i > 0; i--) start[i] = start[i - 1];
        start[0] = 0;
        return list;
    }

    /**
     * The cloth's vertices against its faces alone, in order: a solver that steps one particle at a time
     * (vertex block descent) projects these four-particle contacts after its sweep, as it does hard rows.
     */
    void projectFaces(Particles p, double h) {
        if (facesFrom == facesTo) return;
        long t0 = System.nanoTime();
        for (int k = facesFrom; k < facesTo; k++) with[k].project(p, entry[k], h);
        projectNanos += System.nanoTime() - t0;
    }

    /** Contact k's projection moving only {@code particle} (one of its particles). */
    void projectOne(Particles p, int k, int particle, double h) {
        if (with[k].internal()) { with[k].projectOne(p, entry[k], particle, h); return; }
        int k3 = 3 * particle;
        double x = p.x[k3], y = p.x[k3 + 1], z = p.x[k3 + 2];
        with[k].projectOne(p, entry[k], particle, h);
        moved[k3] += p.x[k3] - x; moved[k3 + 1] += p.x[k3 + 1] - y; moved[k3 + 2] += p.x[k3 + 2] - z;
    }

    /** Contact k alone (the probe's replay checks after each); a collider's move of its particle is kept for its work. */
    void project(Particles p, SolverContext ctx, int k) {
        if (with[k].internal()) { with[k].project(p, entry[k], ctx.h); return; }
        int k3 = 3 * particle[k];
        double x = p.x[k3], y = p.x[k3 + 1], z = p.x[k3 + 2];
        with[k].project(p, entry[k], ctx.h);
        moved[k3] += p.x[k3] - x; moved[k3 + 1] += p.x[k3 + 1] - y; moved[k3 + 2] += p.x[k3 + 2] - z;
    }
}
