package xpbdcloth.engine;

/**
 * One distance constraint |x_a − x_b| − L = 0 (structural edges, rope links): a view of one entry of a
 * {@link DistanceBlock}, whose header gives C(x), its gradient and the source.
 */
public final class DistanceConstraint extends Constraint {
    /** Below this length (m) the direction n is numerically meaningless. */
    static final double MIN_LENGTH = DistanceBlock.MIN_LENGTH;

    DistanceConstraint(DistanceBlock block, int index) { super(block, index); }

    /** A constraint of its own (until added to a simulation) keeping a and b at restLength (m). */
    public DistanceConstraint(ConstraintFamily family, int a, int b, double restLength) {
        this(new DistanceBlock(family, 1), 0);
        ((DistanceBlock) block).add(a, b, restLength);
    }

    /** A structural constraint at the particles' current distance. */
    public static DistanceConstraint between(Particles p, int a, int b) {
        DistanceBlock block = new DistanceBlock(ConstraintFamily.STRUCTURAL, 1);
        return block.view(block.addAtCurrentLength(p, a, b));
    }

    private DistanceBlock data() { return (DistanceBlock) block; }

    public int a() { return data().a(index); }
    public int b() { return data().b(index); }
    public double restLength() { return data().restLength(index); }

    /** |x_a − x_b| / L − 1 (0 at rest, &gt; 0 stretched); 0 for a zero rest length. */
    public double strain(Particles p) { return data().strain(index, p); }
}
