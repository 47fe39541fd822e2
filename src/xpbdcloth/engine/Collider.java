package xpbdcloth.engine;

/**
 * A solid the cloth cannot enter (a sphere, a plane): in the collide stage it lists the particles it may
 * touch this substep, and in the solve it projects the contact with one of them. Kinematic: the cloth
 * never pushes it. Each kind's contact maths lives in its own class ({@link SphereCollisionConstraint},
 * {@link PlaneCollisionConstraint}); this is only how {@link ContactSet} reaches it.
 */
public abstract class Collider {
    Collider() {}

    /** The collide stage: adds to {@code contacts} every free particle this collider may touch this substep. */
    abstract void findContacts(Particles p, double h, ContactSet contacts);

    /** One projection of the contact with particle i (nothing while it is outside). */
    abstract void project(Particles p, int i, double h);
}
