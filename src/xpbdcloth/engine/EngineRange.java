package xpbdcloth.engine;

/**
 * The ranges in which the engine is tested to stay finite (the fuzzer and the extreme-parameter tests
 * draw from them). A value outside is refused where it enters, naming the parameter and the range,
 * because inside the engine it would end in an overflow several steps later: α/h² with dt = 1e-300, an
 * inverse mass of 1/1e-310, a position of 1e308 squared. They are far wider than any cloth needs; the
 * presets' own, narrower ranges are in the scene package's Limits.
 */
public final class EngineRange {
    private EngineRange() {}

    /** Step dt, s. */
    public static final double MIN_DT = 1e-6, MAX_DT = 1;
    public static final int MAX_ITERATIONS = 10_000, MAX_SUBSTEPS = 1_000, MAX_PCG_ITERATIONS = 100_000;
    /** Each component of gravity, m/s². */
    public static final double MAX_GRAVITY = 1e4;
    /**
     * Particle mass, kg: down to 1e-18, because the lightest legal preset (1e-3 kg/m² on a 1 mm square
     * of 512² particles) gives its corners 1e-15 kg; 1/m stays far from overflow.
     */
    public static final double MIN_MASS = 1e-18, MAX_MASS = 1e12;
    /** Each coordinate of a position or target, m; each component of a velocity, m/s; of a force, N. */
    public static final double MAX_POSITION = 1e6, MAX_SPEED = 1e6, MAX_FORCE = 1e9;
    /** Velocity damping, 1/s (1e4 halves a velocity in 69 µs: anything above is a frozen cloth). */
    public static final double MAX_DAMPING = 1e4;
    /**
     * XPBD compliance α, m/N (or its unit for other constraints). Springs stay far below it; a fabric's rows
     * reach it where the material is soft and the mesh fine: a hinge's α is (A₀ + A₁)/(B|e|²), 1/B on a
     * regular grid, so the catalogue's softest bending (B = 1e-6 N·m) is α = 1e6 there, and a membrane
     * row's α is 1/(qA). α/h² stays finite at the smallest step (1e12/1e-12).
     */
    public static final double MAX_COMPLIANCE = 1e12;
    /** A sphere's radius and margin, m. */
    public static final double MAX_RADIUS = 1e6;
    /** Particles in one simulation (2048² = 4 194 304). */
    public static final long MAX_PARTICLES = 2048L * 2048L;

    static void vector(String name, double x, double y, double z, double max) {
        Check.finite3(name, x, y, z);
        if (Math.abs(x) > max || Math.abs(y) > max || Math.abs(z) > max)
            throw new IllegalArgumentException(name + " must be within ±" + max + " per component, was (" + x + ", " + y + ", " + z + ")");
    }
}
