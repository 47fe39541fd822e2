package xpbdcloth.engine;

/**
 * One shear (angle) constraint acos(ê₁·ê₂) − θ₀ = 0 at a vertex: a view of one entry of a
 * {@link ShearBlock}, whose header gives C(x), its gradient, the source and the degenerate cases.
 */
public final class ShearConstraint extends Constraint {
    ShearConstraint(ShearBlock block, int index) { super(block, index); }

    /** A constraint of its own (until added to a simulation) keeping the angle at vertex at restAngle. */
    public ShearConstraint(ConstraintFamily family, int vertex, int end1, int end2, double restAngle) {
        this(new ShearBlock(family, 1), 0);
        ((ShearBlock) block).add(vertex, end1, end2, restAngle);
    }

    /** A shear constraint at the particles' current angle. */
    public static ShearConstraint atCurrentAngle(ConstraintFamily family, Particles p, int vertex, int end1, int end2) {
        ShearBlock block = new ShearBlock(family, 1);
        return block.view(block.addAtCurrentAngle(p, vertex, end1, end2));
    }

    public double restAngle() { return ((ShearBlock) block).restAngle(index); }

    /** The current angle θ in radians (π/2 if an edge has zero length). */
    public double angle(Particles p) { return ((ShearBlock) block).angle(index, p); }
}
