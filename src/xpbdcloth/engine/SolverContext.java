package xpbdcloth.engine;

/**
 * What every projection reads during one substep, filled once per substep so the constraints do no
 * settings look-ups or divisions that do not change within it.
 */
public final class SolverContext {
    ConstraintMode mode = ConstraintMode.XPBD;
    int iterations = 1;
    boolean mullerCorrection = true;
    /** The substep h, seconds. */
    double h = 1;
    /** 1/h², so α̃ = α/h² is one multiplication. */
    double inverseH2 = 1;
    /** Gravity, m/s² (what the prediction adds; vertex block descent's inertia reads it too). */
    double gravityX, gravityY, gravityZ;

    void load(SolverSettings s, double h) {
        mode = s.mode();
        iterations = s.iterations();
        mullerCorrection = s.mullerCorrection();
        this.h = h;
        inverseH2 = 1.0 / (h * h);
        gravityX = s.gravityX(); gravityY = s.gravityY(); gravityZ = s.gravityZ();
    }

    public ConstraintMode mode() { return mode; }
    public double substep() { return h; }
    public int iterations() { return iterations; }
}
