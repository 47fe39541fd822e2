package xpbdcloth.engine;

/**
 * The particles of one simulation, stored as flat arrays (xyz interleaved) so the solver's hot loops walk
 * contiguous memory and allocate nothing. {@link Particle} is the object view for code outside the loops.
 *
 * <p>Units: metres, seconds, kilograms, newtons. A particle is pinned when its inverse mass is 0; it then
 * moves only when a scene or the user sets its position (kinematically), and the solver never moves it.
 */
public final class Particles {
    private final int count;
    /** Positions x, the solver's working state. */
    final double[] x;
    /** Positions at the start of the current substep; v = (x − prev) / h after the projection. */
    final double[] prev;
    /** Velocities, m/s. */
    final double[] v;
    /** Inverse masses w = 1/m, 0 for pinned particles. */
    final double[] w;
    /** Masses, kept so a pinned or grabbed particle can be released to its own mass. */
    final double[] mass;
    /** External forces accumulated for the next step (N), cleared after it. */
    final double[] force;
    /**
     * How far (m) contacts have moved each particle's previous position out with it this substep, undoing the
     * depth it started inside a collider at ({@link Collider#depenetrateWithoutVelocity}); cleared each substep.
     */
    final double[] depenetrated;
    /** The collider each particle's {@link #depenetrated} is owed to (another's normal is another direction). */
    final Collider[] depenetratedBy;

    /** At each substep's start: no contact has undone any particle's depth yet. */
    void clearDepenetration() {
        java.util.Arrays.fill(depenetrated, 0);
        java.util.Arrays.fill(depenetratedBy, null);
    }

    /** {@code count} particles at the origin, each of mass 1 kg. */
    public Particles(int count) {
        this.count = Check.inRange("particleCount", count, 1, EngineRange.MAX_PARTICLES);
        x = new double[3 * count];
        prev = new double[3 * count];
        v = new double[3 * count];
        force = new double[3 * count];
        depenetrated = new double[count];
        depenetratedBy = new Collider[count];
        w = new double[count];
        mass = new double[count];
        java.util.Arrays.fill(w, 1.0);
        java.util.Arrays.fill(mass, 1.0);
    }

    public int count() { return count; }

    public Particle get(int i) { return new Particle(this, Check.index("particle", i, count)); }

    public double x(int i) { return x[3 * i]; }
    public double y(int i) { return x[3 * i + 1]; }
    public double z(int i) { return x[3 * i + 2]; }
    public double vx(int i) { return v[3 * i]; }
    public double vy(int i) { return v[3 * i + 1]; }
    public double vz(int i) { return v[3 * i + 2]; }
    public double inverseMass(int i) { return w[i]; }
    public double mass(int i) { return mass[i]; }
    public boolean isPinned(int i) { return w[i] == 0; }

    /**
     * The live position array (xyz interleaved, length 3·count) for renderers and measurements that must
     * not copy. Read it; write positions through {@link #setPosition} so pinned particles stay consistent.
     */
    public double[] positions() { return x; }

    /** Moves particle i (pinned ones included) and its previous position, so no velocity is implied. */
    public void setPosition(int i, double px, double py, double pz) {
        Check.index("particle", i, count);
        EngineRange.vector("position", px, py, pz, EngineRange.MAX_POSITION);
        int k = 3 * i;
        x[k] = px; x[k + 1] = py; x[k + 2] = pz;
        prev[k] = px; prev[k + 1] = py; prev[k + 2] = pz;
    }

    /**
     * Moves particle i kinematically during a substep: the previous position is kept, so the solver sees
     * the motion as the particle's velocity (a pinned corner being pulled drags the cloth with that speed).
     */
    public void moveKinematic(int i, double px, double py, double pz) {
        Check.index("particle", i, count);
        EngineRange.vector("position", px, py, pz, EngineRange.MAX_POSITION);
        int k = 3 * i;
        x[k] = px; x[k + 1] = py; x[k + 2] = pz;
    }

    public void setVelocity(int i, double vx, double vy, double vz) {
        Check.index("particle", i, count);
        EngineRange.vector("velocity", vx, vy, vz, EngineRange.MAX_SPEED);
        int k = 3 * i;
        v[k] = vx; v[k + 1] = vy; v[k + 2] = vz;
    }

    /** Sets the mass (kg, &gt; 0) of a free particle; a pinned particle keeps w = 0 until released. */
    public void setMass(int i, double m) {
        Check.index("particle", i, count);
        Check.inRange("mass", m, EngineRange.MIN_MASS, EngineRange.MAX_MASS);
        mass[i] = m;
        if (w[i] != 0) w[i] = 1.0 / m;
    }

    /** Pins particle i: w = 0, velocity zeroed. */
    public void pin(int i) {
        Check.index("particle", i, count);
        w[i] = 0;
        v[3 * i] = v[3 * i + 1] = v[3 * i + 2] = 0;
    }

    /** Releases particle i back to its own mass. */
    public void unpin(int i) {
        Check.index("particle", i, count);
        w[i] = 1.0 / mass[i];
    }

    /** Adds an external force (N) acting during the next step only. */
    public void addForce(int i, double fx, double fy, double fz) {
        Check.index("particle", i, count);
        EngineRange.vector("force", fx, fy, fz, EngineRange.MAX_FORCE);
        int k = 3 * i;
        force[k] += fx; force[k + 1] += fy; force[k + 2] += fz;
    }

    /** Copies all state from {@code other} (same count), for side-by-side runs and determinism checks. */
    public void copyFrom(Particles other) {
        if (other.count != count)
            throw new IllegalArgumentException("particleCount must match, was " + other.count + " vs " + count);
        System.arraycopy(other.x, 0, x, 0, x.length);
        System.arraycopy(other.prev, 0, prev, 0, prev.length);
        System.arraycopy(other.v, 0, v, 0, v.length);
        System.arraycopy(other.w, 0, w, 0, w.length);
        System.arraycopy(other.mass, 0, mass, 0, mass.length);
        System.arraycopy(other.force, 0, force, 0, force.length);
    }
}
