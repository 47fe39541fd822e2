package xpbdcloth.engine;

/**
 * A solid the cloth cannot enter (a sphere, a plane, a box, a capsule): in the collide stage it lists the
 * particles it may touch this substep, and in the solve it projects the contact with one of them.
 * Kinematic: the cloth never pushes it. Each kind's contact maths lives in its own class
 * ({@link SphereContact}, {@link PlaneContact}, {@link ShapeContact});
 * this is only how {@link ContactSet} reaches it, with what every contact shares: the cloth's half
 * thickness kept from the surface, and Coulomb's two coefficients.
 */
public abstract class Collider {
    /** Half the cloth's thickness, kept between particle centres and the surface, m. */
    final double margin;
    /** Coulomb's μₛ and μₖ between the cloth and this surface. */
    final double staticFriction, kineticFriction;

    Collider(double margin, double staticFriction, double kineticFriction) {
        this.margin = Check.inRange("margin", margin, 0, EngineRange.MAX_RADIUS);
        this.staticFriction = Check.nonNegative("staticFriction", staticFriction);
        this.kineticFriction = Check.nonNegative("kineticFriction", kineticFriction);
    }

    /**
     * The fastest a contact moves a particle out of a solid it started the substep inside of, m/s (what
     * PhysX calls the maximum depenetration velocity). A cloth found deep inside a collider (one placed
     * around it, or driven into it faster than contacts could hold) comes out over several substeps instead
     * of being flung away at depth/h: a box of half-extent 10 m around a cloth threw it at about 5e4 m/s.
     * Particles that start a substep outside, or inside by less than this speed times the substep, are put
     * on the surface as before, so resting and sliding contacts are unchanged.
     */
    public static final double MAX_DEPENETRATION_SPEED = 10;

    /** This collider's own depenetration speed (m/s): {@link #MAX_DEPENETRATION_SPEED} unless a preset or the code sets it. */
    private double depenetrationSpeed = MAX_DEPENETRATION_SPEED;

    /** The fastest (m/s) this collider pushes out a particle found deep inside it; in [0.01, 1000] m/s. */
    public Collider depenetrationSpeed(double metresPerSecond) {
        depenetrationSpeed = Check.inRange("depenetrationSpeed", metresPerSecond, 0.01, 1000);
        return this;
    }

    public final double depenetrationSpeed() { return depenetrationSpeed; }

    /**
     * The depth (m) a contact leaves particle i at, {@code startDepth} being its depth (≤ 0: outside) at its
     * previous position now. Contacts move the previous position out with the particle as they undo its start
     * depth, so a later projection in the same substep measures less: what was undone is added back, and the
     * particle comes out no more than the depenetration speed times h in a substep however many sweeps project
     * it (with the depth measured afresh each sweep it came out that much in each: twice the speed at two sweeps).
     * Only this collider's own undoing is added back: another's was along another normal (a box pressing cloth
     * into the floor), and the floor, which has the last word, measures from where the particle is.
     */
    final double leftInside(Particles p, int i, double startDepth, double h) {
        double start = startDepth + undoneHere(p, i);
        return Math.max(0, start - depenetrationSpeed * h);
    }

    /** How far this collider has moved particle i's previous position out with it this substep. */
    private double undoneHere(Particles p, int i) { return p.depenetratedBy[i] == this ? p.depenetrated[i] : 0; }

    /**
     * After a contact moved particle k (index 3i) out by {@code correction} along n: the part of it that only
     * undoes where the particle already was inside at the substep's start ({@code startDepth} beyond the
     * margin, less what is left inside) is moved in its previous position too, so getting out of a solid
     * adds no velocity. Without this, cloth a solid had passed into (a box lowered through cloth lying on
     * the floor) left it at the depenetration speed and flew metres high; the part of the correction that
     * stops the particle's own motion into the surface still removes that motion's velocity, as a contact must.
     * Returns the depth undone (0 for a particle that started outside).
     */
    final double depenetrateWithoutVelocity(Particles p, int k, double nx, double ny, double nz, double correction, double startDepth, double h) {
        final int i = k / 3;
        // Of the depth it started the substep inside (startDepth plus what it undid already), what this substep
        // may undo, less what it already has: startDepth less the depth it is to be left at.
        double undone = Math.min(correction, startDepth - leftInside(p, i, startDepth, h));
        if (!(undone > TOUCHING_DEPTH)) return 0;
        p.prev[k] += undone * nx; p.prev[k + 1] += undone * ny; p.prev[k + 2] += undone * nz;
        p.depenetrated[i] = undoneHere(p, i) + undone;
        p.depenetratedBy[i] = this;
        return undone;
    }

    /** Depths below this (m) are a resting contact's rounding, not a particle inside. */
    static final double TOUCHING_DEPTH = 1e-9;

    public final double margin() { return margin; }
    public final double staticFriction() { return staticFriction; }
    public final double kineticFriction() { return kineticFriction; }

    /** The collide stage: adds to {@code contacts} every free particle this collider may touch this substep. */
    abstract void findContacts(Particles p, double h, ContactSet contacts);

    /** One projection of contact i (nothing while it is outside): particle i, or the entry i its findContacts gave. */
    abstract void project(Particles p, int i, double h);

    /** C(x) of contact i (as in {@link #project}): its distance outside the surface plus margin, m (negative inside). */
    abstract double clearance(Particles p, int i);

    /**
     * The same C for any world point (x, y, z) against the collider where it is now: its distance outside the
     * surface less the margin, m, negative where a contact would push a particle out. A measurement, for what
     * contacts cannot move (a pinned or held particle); +∞ for what is not a solid (the cloth's own thickness).
     */
    public abstract double clearanceAt(double x, double y, double z);

    /**
     * Contact i's projection moving {@code particle} alone (a solver that updates particles one at a time):
     * a collider's contact moves only its particle anyway; a contact between two particles moves this one
     * by its share.
     */
    void projectOne(Particles p, int i, int particle, double h) { project(p, i, h); }

    /** The second particle of contact i, or −1 when the other side is a solid. */
    int partner(int i) { return -1; }

    /** Marks the particles of contact i other than the one the contact set lists it by (its partner, if any). */
    void markOthers(int i, boolean[] held) {
        int other = partner(i);
        if (other >= 0) held[other] = true;
    }

    /**
     * Whether this is the cloth against itself (its particle pairs, its vertices against its faces): internal
     * forces, which do no work on the cloth as a whole and leave no particle inside a solid.
     */
    boolean internal() { return false; }

    /**
     * Whether this collider moved or turned over the last substep: its contacts can then do work on the
     * cloth, which a still one cannot (it only takes energy out, by friction and inelastic pushes).
     */
    boolean moving() { return false; }
}
