package xpbdcloth.scene;

/**
 * The ranges a preset's numbers must lie in, one table for the loader, the sketch's keys and the preset
 * fuzzer ({@code gradle fuzz -Ppresets}), which draws every field across its range, edges included,
 * and requires the scene to stay finite. Units are SI. A range is as wide as the engine is tested to
 * hold, not as wide as a double: the old loader took dt = 1e-300 (α/h² overflows) and a 1e6 m/s wind,
 * and both went NaN within 20 steps.
 */
public final class Limits {
    private Limits() {}

    /** A closed interval [lo, hi] with its unit, for messages and the README. */
    public static final class Range {
        public final double lo, hi;
        public final String unit;

        public Range(double lo, double hi, String unit) {
            this.lo = lo;
            this.hi = hi;
            this.unit = unit;
        }

        public boolean contains(double v) { return v >= lo && v <= hi; }

        public double clamp(double v) { return Math.max(lo, Math.min(hi, v)); }

        /** "[1e-4, 0.1]" */
        public String text() { return "[" + format(lo) + ", " + format(hi) + "]"; }

        static String format(double v) {
            return v == Math.rint(v) && Math.abs(v) < 1e7 ? String.valueOf((long) v) : String.valueOf(v).replace('E', 'e');
        }
    }

    /** Particles along each side of the grid. */
    public static final Range RESOLUTION = new Range(1, 512, "particles");
    /** Width or height of a cloth with more than one particle along it, m. */
    public static final Range SIZE = new Range(1e-3, 100, "m");
    /** Any position a preset gives (origin, sphere centres), m. */
    public static final Range POSITION = new Range(-1000, 1000, "m");
    public static final Range AREAL_DENSITY = new Range(1e-3, 100, "kg/m²");
    public static final Range TOTAL_MASS = new Range(1e-6, 1e4, "kg");
    /** PBD's k. */
    public static final Range STIFFNESS = new Range(0, 1, "");
    /** XPBD's α; the sketch's key steps it by √10 between 1e-10 and this maximum (below 1e-10 it is 0). */
    public static final Range COMPLIANCE = new Range(0, 1e3, "m/N");
    public static final double SMALLEST_NONZERO_COMPLIANCE = 1e-10;
    public static final Range ITERATIONS = new Range(1, 1000, "");
    public static final Range SUBSTEPS = new Range(1, 100, "");
    /** The step, s: 10 kHz to 10 Hz. */
    public static final Range DT = new Range(1e-4, 0.1, "s");
    /** Each component of gravity, m/s² (about ±10 g). */
    public static final Range GRAVITY = new Range(-100, 100, "m/s²");
    /** Velocity damping, 1/s: 100 stops a cloth's motion in about 50 ms. */
    public static final Range DAMPING = new Range(0, 100, "1/s");
    public static final Range SPHERE_RADIUS = new Range(1e-3, 100, "m");
    public static final Range MARGIN = new Range(0, 1, "m");
    /** The fastest a collider pushes out a particle found deep inside it (the engine's check, {@code Collider.depenetrationSpeed}). */
    public static final Range DEPENETRATION_SPEED = new Range(0.01, 1000, "m/s");
    /** The cloth's thickness against itself. */
    public static final Range THICKNESS = new Range(1e-4, 1, "m");
    /** Each component of a plane's normal (any length from 1e-3 up: it is normalised). */
    public static final Range NORMAL = new Range(-1, 1, "");
    /** A fabric's in-plane moduli per unit width (E·t, G·t), N/m: from a rubber film to a stiff canvas. */
    public static final Range MODULUS = new Range(1e-1, 1e7, "N/m");
    /** A fabric's bending stiffness per unit width, N·m (Kawabata's B of 0.01 gf·cm²/cm is 1e-6). */
    public static final Range BENDING_STIFFNESS = new Range(1e-6, 1, "N·m");
    /** A crease's yield: from a 10 m bend (barely one) to a 0.1 mm radius. */
    public static final Range YIELD_CURVATURE = new Range(0.1, 1e4, "1/m");
    /** The edge strain past which a fabric tears: from a tenth of a per cent to elevenfold. */
    public static final Range BREAKING_STRAIN = new Range(1e-3, 10, "");
    /** How fast a yielded hinge's rest follows: an hour's creep to instant. */
    public static final Range PLASTIC_RATE = new Range(1e-4, 1e4, "1/s");
    /** Poisson's ratio ν₁₂ before the positive-definite check. */
    public static final Range POISSON = new Range(-0.99, 10, "");
    /** The air outside a closed cloth: a vacuum to ten atmospheres. */
    public static final Range AMBIENT_PRESSURE = new Range(0, 1e6, "Pa");
    /** A gas's pressure over the air outside at the rest shape (less than the air's would make a vacuum inside: refused). */
    public static final Range GAUGE_PRESSURE = new Range(-1e6, 1e6, "Pa");
    /** The gas inside a closed cloth, by amount: a nanomole to a tonne of air's worth. */
    public static final Range MOLES = new Range(1e-9, 1e6, "mol");
    public static final Range TEMPERATURE = new Range(1, 1e4, "K");
    /** A held volume as a multiple of the rest volume. */
    public static final Range VOLUME_RATIO = new Range(0.01, 100, "");
    /** Air's density, kg/m³ (water would be 1000). */
    public static final Range AIR_DENSITY = new Range(1e-3, 1e3, "kg/m³");
    /** A flat plate's drag or lift coefficient. */
    public static final Range AERO_COEFFICIENT = new Range(0, 10, "");
    /** μₛ and μₖ. */
    public static final Range FRICTION = new Range(0, 10, "");
    /** Each component of a sphere's spin, rad/s. */
    public static final Range ANGULAR_VELOCITY = new Range(-100, 100, "rad/s");
    /** Each component of a linear path's velocity, m/s. */
    public static final Range SPEED = new Range(-100, 100, "m/s");
    public static final Range PATH_RADIUS = new Range(0, 100, "m");
    public static final Range ANGULAR_SPEED = new Range(-100, 100, "rad/s");
    /** Each component of an oscillation's amplitude or a pin motion's displacement, m. */
    public static final Range DISPLACEMENT = new Range(-100, 100, "m");
    public static final Range FREQUENCY = new Range(0, 100, "Hz");
    public static final Range START_TIME = new Range(0, 1e6, "s");
    /** A pin motion's turns about its axis (either way). */
    public static final Range TURNS = new Range(-100, 100, "turns");
    public static final Range DURATION = new Range(1e-2, 1e6, "s");
    /** Each component of the wind, m/s (a hurricane is 33 m/s and up). */
    public static final Range WIND_SPEED = new Range(-100, 100, "m/s");
    public static final Range DRAG = new Range(0, 10, "kg/(m²·s)");
    public static final Range GUST = new Range(0, 1, "");
    /** Spheres in a preset: each is tested against every particle every substep. */
    public static final int MAX_SPHERES = 16;
    /** Entries in cloth.pins (an edge name counts once, whatever its length). */
    public static final int MAX_PIN_ENTRIES = 4096;
    public static final int MAX_PIN_MOTIONS = 256;
    /**
     * The work a step may ask of Gauss–Seidel, in particle visits: particles × substeps × (iterations +
     * colliders). 2²⁵ is, for example, 512² particles at 128 sweeps a step, or 128² at 2048: about 4 s per
     * step on a 2-core laptop (about 5 constraints per particle at 50 M projections/s). Each field can be
     * at its maximum; all of them at once would be hours per step.
     */
    public static final long MAX_WORK = 1L << 25;
    /**
     * The same for the global solvers, whose iteration is a whole linear solve (up to 100 conjugate-gradient
     * iterations) and costs more than it saves beyond this: 64² particles at 2 iterations × 10 substeps,
     * measured at 1.7 s per step with Jacobi-PCG (128² took 13.8 s, 256² more than a minute).
     */
    public static final long MAX_GLOBAL_WORK = 64 * 64 * 20;

    /** The problem with a step this large, in words, or null if it is within {@link #MAX_WORK} (or {@link #MAX_GLOBAL_WORK}). */
    public static String workProblem(long particles, int iterations, int substeps, int colliders, boolean global) {
        long work = global ? particles * substeps * (long) iterations : particles * substeps * (long) (iterations + colliders);
        long max = global ? MAX_GLOBAL_WORK : MAX_WORK;
        if (work <= max) return null;
        return global
                ? "particles × substeps × iterations must be at most " + max + " with a global solver (64² at 2 × 10 takes 1.7 s a step), was "
                        + particles + " × " + substeps + " × " + iterations + " = " + work + "; use gauss-seidel, or fewer particles, substeps or iterations"
                : "particles × substeps × (iterations + colliders) must be at most " + max + " (about 4 s a step), was "
                        + particles + " × " + substeps + " × (" + iterations + " + " + colliders + ") = " + work + "; use fewer particles, substeps or iterations";
    }

    /** Vertices of a mesh cloth after welding: as many as the largest grid. */
    public static final Range MESH_VERTICES = new Range(2, 512 * 512, "vertices");
    /** Frames per second of an animated body's frames. */
    public static final Range FRAME_RATE = new Range(0.01, 1000, "frames per second");
    /** A mesh file's uniform scale (its units to metres). */
    public static final Range MESH_SCALE = new Range(1e-4, 1e4, "");
    /** Each rotation angle of a mesh file, degrees. */
    public static final Range ROTATION = new Range(-360, 360, "degrees");
    /** Distance within which a mesh file's vertices are welded, in the file's units. */
    public static final Range WELD = new Range(0, 1, "");

    /** A garment pattern's target edge length (its panels' triangles). */
    public static final Range PATTERN_EDGE = new Range(1e-3, 1, "m");
    /** A pattern's coordinates, an arc's bulge, a Bézier curve's control points (metres in the pattern plane). */
    public static final Range PATTERN_COORDINATE = new Range(-100, 100, "m");
    /** A position on a panel's outline: corner k is k, 1.5 is halfway along edge 1 (the corner count is checked by the pattern). */
    public static final Range PATTERN_POSITION = new Range(0, 1000, "");
    /** The radius of the cylinder a panel is wrapped onto (0: flat). */
    public static final Range WRAP_RADIUS = new Range(0, 100, "m");
    /** Vertices of a meshed pattern, all panels (the relaxation takes about a second per ten thousand). */
    public static final Range PATTERN_VERTICES = new Range(3, 50_000, "vertices");
    /** A garment's sewing time: its seams pulled shut over this, then closed. */
    public static final Range SEWING_TIME = new Range(0, 60, "s");
    /** A closed seam's bending stiffness over its fabric's (a seam allowance is stiffer). */
    public static final Range SEAM_BENDING = new Range(1e-3, 1e3, "");
}
