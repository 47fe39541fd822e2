package xpbdcloth.fit;

import java.util.List;
import java.util.function.Consumer;
import xpbdcloth.engine.ConstraintFamily;

/** A fit of a scene's compliances (and perhaps its damping) to an observation, iterated to convergence. */
public interface MaterialFit {
    List<ConstraintFamily> families();
    /** Whether the damping rate is fitted too. */
    boolean fitsDamping();
    /** "static" (a rest shape) or "dynamic" (a trajectory). */
    String kind();
    /** What {@link FitIteration#solves} counts, for a CSV column. */
    String solvesName();
    List<FitIteration> history();
    boolean converged();
    /** One iteration; false once converged (then it does nothing). */
    boolean iterate();

    default FitIteration last() { return history().get(history().size() - 1); }
    /** α per fitted family now. */
    default double[] compliance() { return last().compliance.clone(); }
    /**
     * The factor s_f each fitted family's compliances were multiplied by (α = s_f·α⁰, the scene's α⁰):
     * for a family built from moduli (a fabric's membrane, its dihedral bending) the moduli are divided by it.
     */
    double[] scale();

    /** Runs until converged or {@code maxIterations} iterations; true if it converged. */
    default boolean run(int maxIterations, Consumer<FitIteration> progress) {
        while (history().size() <= maxIterations && iterate()) if (progress != null) progress.accept(last());
        if (progress != null && converged()) progress.accept(last());
        return converged();
    }
}
