package xpbdcloth.engine;

/**
 * One triangle bending constraint |x_v − centroid(b₀, v, b₁)| − h₀ = 0 (Kelager et al. 2010): a view of
 * one entry of a {@link BendBlock}, whose header gives C(x), its gradient and the source.
 */
public final class BendConstraint extends Constraint {
    BendConstraint(BendBlock block, int index) { super(block, index); }

    /** A constraint of its own (until added to a simulation) keeping v at restDistance from the centroid. */
    public BendConstraint(ConstraintFamily family, int b0, int v, int b1, double restDistance) {
        this(new BendBlock(family, 1), 0);
        ((BendBlock) block).add(b0, v, b1, restDistance);
    }

    /** A bend constraint at the particles' current shape. */
    public static BendConstraint atCurrentShape(ConstraintFamily family, Particles p, int b0, int v, int b1) {
        BendBlock block = new BendBlock(family, 1);
        return block.view(block.addAtCurrentShape(p, b0, v, b1));
    }

    public double restDistance() { return ((BendBlock) block).restDistance(index); }

    /** |x_v − centroid|. */
    public double centroidDistance(Particles p) { return ((BendBlock) block).centroidDistance(index, p); }
}
