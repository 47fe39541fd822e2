package xpbdcloth.engine;

/**
 * A view of one entry of a block whose kind needs no API of its own beyond {@link Constraint}'s (C, ∇C,
 * material, λ): the membrane's rows, the dihedral bends and the tethers. Their maths is in their blocks.
 */
final class BlockConstraint extends Constraint {
    BlockConstraint(ConstraintBlock block, int index) { super(block, index); }
}
