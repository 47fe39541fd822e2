package xpbdcloth.engine;

/**
 * One particle as an object: a view of index {@code index} in a {@link Particles} store. Made for code
 * outside the solver's loops (scenes, tests, the sketch); the loops read the arrays directly.
 */
public final class Particle {
    private final Particles store;
    private final int index;

    Particle(Particles store, int index) {
        this.store = store;
        this.index = index;
    }

    public int index() { return index; }
    public double x() { return store.x(index); }
    public double y() { return store.y(index); }
    public double z() { return store.z(index); }
    public double previousX() { return store.prev[3 * index]; }
    public double previousY() { return store.prev[3 * index + 1]; }
    public double previousZ() { return store.prev[3 * index + 2]; }
    public double vx() { return store.vx(index); }
    public double vy() { return store.vy(index); }
    public double vz() { return store.vz(index); }
    public double inverseMass() { return store.inverseMass(index); }
    public double mass() { return store.mass(index); }
    public boolean isPinned() { return store.isPinned(index); }
    public double forceX() { return store.force[3 * index]; }
    public double forceY() { return store.force[3 * index + 1]; }
    public double forceZ() { return store.force[3 * index + 2]; }

    public void setPosition(double x, double y, double z) { store.setPosition(index, x, y, z); }
    public void setVelocity(double vx, double vy, double vz) { store.setVelocity(index, vx, vy, vz); }
    public void pin() { store.pin(index); }
    public void unpin() { store.unpin(index); }
    public void addForce(double fx, double fy, double fz) { store.addForce(index, fx, fy, fz); }

    @Override public String toString() {
        return "Particle " + index + " (" + x() + ", " + y() + ", " + z() + ")" + (isPinned() ? " pinned" : "");
    }
}
