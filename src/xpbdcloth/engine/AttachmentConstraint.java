package xpbdcloth.engine;

/**
 * One attachment |x − t| = 0 holding a particle at a movable target (the mouse grab): a view of one entry
 * of an {@link AttachmentBlock}, whose header gives C(x), its gradient and the source.
 */
public final class AttachmentConstraint extends Constraint {
    AttachmentConstraint(AttachmentBlock block, int index) { super(block, index); }

    /** An attachment of its own (until added to a simulation) of particle to (x, y, z). */
    public AttachmentConstraint(int particle, double x, double y, double z) {
        this(new AttachmentBlock(1), 0);
        ((AttachmentBlock) block).add(particle, x, y, z);
    }

    private AttachmentBlock data() { return (AttachmentBlock) block; }

    public int particle() { return block.particle(index, 0); }
    public double targetX() { return data().targetX(index); }
    public double targetY() { return data().targetY(index); }
    public double targetZ() { return data().targetZ(index); }

    public void moveTarget(double x, double y, double z) { data().moveTarget(index, x, y, z); }
}
