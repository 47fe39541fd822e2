package xpbdcloth.engine;

/**
 * A block whose constraints are lengths of a linear combination of their particles:
 * <pre>
 *   C(x) = |d| − r,   d = Σₖ cₖ x_k,   ∇ₖC = cₖ n,   n = d/|d|
 * </pre>
 * with the same coefficients cₖ for every constraint of the block (a distance: c = (1, −1); a triangle
 * bend: (−⅓, ⅔, −⅓)). Knowing that form is what lets the global solver add such a constraint's
 * geometric stiffness ({@link GeometricStiffness}) without a second copy of its maths.
 */
interface LinearLength {
    /** cₖ for the k-th particle of every constraint of the block. */
    double coefficient(int k);
}
