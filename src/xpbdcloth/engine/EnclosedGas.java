package xpbdcloth.engine;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;

/**
 * The gas a closed cloth encloses (a pillow, a balloon): one constraint on the volume inside the surface.
 * <pre>
 *   V(x)  = (1/6) Σ_t (x_a − o)·((x_b − o) × (x_c − o))     the divergence theorem over the outward triangles (a, b, c)
 *   ∇_a V = (1/6) Σ_{t ∋ a} (x_b − o) × (x_c − o)           a, b, c cyclic in each triangle; o any point (V does not move with it)
 * </pre>
 * The gas is ideal and isothermal: p V = nRT, with the ambient pressure p₀ outside. Its energy is
 * U(V) = p₀V − nRT ln V, which pushes every particle with (p − p₀) ∇V. U is not quadratic, so once per
 * substep it is replaced by the quadratic with the same slope and curvature at the predicted volume V_c
 * (a Newton step on the gas law), and that is solved as one compliant XPBD row (Macklin, Müller, Chentanez 2016):
 * <pre>
 *   C = V − V*,   α = V_c² / nRT,   V* = V_c + α (nRT/V_c − p₀)
 * </pre>
 * so the pressure the solver applies, p = p₀ + λ/h², is the gas law's linearised about V_c, exact where the
 * substep ends at V_c, second-order close elsewhere. Stiff air (nRT/V of 10⁵ Pa in a pillow) makes α small:
 * an explicit pressure force would need a substep of microseconds, the row takes any. A target volume instead
 * (Müller et al. 2007, "Position Based Dynamics", §4.4, the constraint on a closed mesh's volume): C = V − V_t,
 * hard, its λ/h² the pressure that holds it.
 *
 * <p>Projected once after every sweep, serially, on whichever thread runs the contacts (one row over every
 * particle of the surface: no colouring can share it out, and it costs one pass over the triangles). Where a
 * surface is crushed or turned inside out the volume is floored at a thousandth of the rest volume, which caps
 * the pressure at a thousand times its rest value instead of an infinite push.
 */
public final class EnclosedGas {
    /** R, J/(mol·K) (the 2019 SI value). */
    public static final double GAS_CONSTANT = 8.314462618;
    /** The most nRT (J) and volume (m³) taken: ten atmospheres in a cube 2 km on a side (the presets' world) and more. */
    public static final double MAX_AMOUNT = 1e18, MAX_VOLUME = 1e12;
    /** The volume below which the linearisation stops following, as a fraction of the rest volume. */
    static final double VOLUME_FLOOR = 1e-3;

    /** The particles of the surface. */
    private final int[] vertex;
    /** Each triangle's corners as indices into {@link #vertex}, outward (the surface's own orientation, flipped if it faced in). */
    private final int[] corner;
    private final double restVolume, ambient;
    /** nRT, J; NaN for a target volume. */
    private double amount;
    /** The held volume, m³; NaN for a gas. */
    private double target;
    /** ∇V per vertex, six times over (the 1/6 applied once per projection). */
    private final double[] gradient;
    // The substep's row: goal V*, compliance α/h², λ, and h for the pressure.
    private double goal, alphaTilde, lambda, h = Double.NaN;

    /**
     * A gas of nRT joules (its pressure at volume V is nRT/V) in a closed surface, with the ambient pressure outside.
     *
     * @param triangles three particle indices per triangle: a closed, consistently oriented surface (either way round)
     * @param nRT       the gas's amount times its temperature, J (n moles at T kelvin: n · {@link #GAS_CONSTANT} · T)
     * @param ambient   the pressure outside, Pa (101325 at sea level; 0 in a vacuum)
     */
    public static EnclosedGas ofGas(Particles rest, int[] triangles, double nRT, double ambient) {
        Check.inRange("nRT", nRT, Double.MIN_NORMAL, MAX_AMOUNT);
        Check.inRange("ambient", ambient, 0, 1e7);
        return new EnclosedGas(rest, triangles, nRT, Double.NaN, ambient);
    }

    /**
     * A gas whose pressure at the surface's rest shape is {@code gauge} over the ambient: nRT = (p₀ + gauge)·V_rest
     * (a pillow filled to a given firmness).
     */
    public static EnclosedGas ofGauge(Particles rest, int[] triangles, double gauge, double ambient) {
        Check.inRange("ambient", ambient, 0, 1e7);
        Check.inRange("gauge", gauge, -ambient, 1e7);
        if (!(ambient + gauge > 0)) throw new IllegalArgumentException("gauge must leave the gas a pressure above 0 (more than " + -ambient + " Pa), was " + gauge);
        EnclosedGas g = new EnclosedGas(rest, triangles, 1, Double.NaN, ambient);
        g.setAmount((ambient + gauge) * g.restVolume);
        return g;
    }

    /** A closed surface that holds {@code ratio} times its rest volume whatever presses on it (an incompressible filling). */
    public static EnclosedGas ofHeldVolume(Particles rest, int[] triangles, double ratio) {
        Check.inRange("ratio", ratio, Double.MIN_NORMAL, 1e6);
        EnclosedGas g = new EnclosedGas(rest, triangles, Double.NaN, 1, 0);
        g.setTargetVolume(ratio * g.restVolume);
        return g;
    }

    private EnclosedGas(Particles rest, int[] triangles, double amount, double target, double ambient) {
        if (rest == null) throw new IllegalArgumentException("particles must not be null, was null");
        if (triangles == null || triangles.length == 0 || triangles.length % 3 != 0)
            throw new IllegalArgumentException("triangles must be three indices per triangle, was " + (triangles == null ? "null" : triangles.length + " indices"));
        for (int k : triangles)
            if (k < 0 || k >= rest.count()) throw new IllegalArgumentException("triangle index must be within [0, " + rest.count() + "), was " + k);
        String open = openEdge(triangles);
        if (open != null) throw new IllegalArgumentException("triangles must enclose a volume: " + open);
        Map<Integer, Integer> local = new HashMap<>();
        corner = new int[triangles.length];
        for (int k = 0; k < triangles.length; k++) corner[k] = local.computeIfAbsent(triangles[k], key -> local.size());
        vertex = new int[local.size()];
        for (Map.Entry<Integer, Integer> e : local.entrySet()) vertex[e.getValue()] = e.getKey();
        gradient = new double[3 * vertex.length];
        double v = volumeAndGradient(rest.x, null);
        double extent = extent(rest.x);
        if (!(Math.abs(v) > 1e-9 * extent * extent * extent))
            throw new IllegalArgumentException("triangles must enclose a volume, enclose " + v + " m³ (a flat or folded-shut surface)");
        if (v < 0) { // the surface faced inwards: turn every triangle round
            for (int t = 0; t < corner.length; t += 3) { int b = corner[t + 1]; corner[t + 1] = corner[t + 2]; corner[t + 2] = b; }
            v = -v;
        }
        restVolume = v;
        this.amount = amount;
        this.target = target;
        this.ambient = ambient;
    }

    /**
     * Null if the triangles form closed, consistently oriented surfaces (each edge bordered by two triangles
     * that run along it in opposite directions), else the first edge that is not, in words.
     */
    public static String openEdge(int[] triangles) {
        Map<Long, Boolean> directed = new HashMap<>();
        for (int t = 0; t + 2 < triangles.length; t += 3)
            for (int k = 0; k < 3; k++) {
                int a = triangles[t + k], b = triangles[t + (k + 1) % 3];
                if (directed.put(key(a, b), Boolean.TRUE) != null)
                    return "edge (" + a + ", " + b + ") runs the same way in two triangles (the triangles are not oriented alike, or more than two meet there)";
            }
        for (long k : directed.keySet()) {
            int a = (int) (k >>> 32), b = (int) k;
            if (!directed.containsKey(key(b, a))) return "edge (" + a + ", " + b + ") borders one triangle only (the surface has a hole or a boundary)";
        }
        return null;
    }

    private static long key(int a, int b) { return ((long) a << 32) | (b & 0xffffffffL); }

    /** The surface's largest extent along an axis, m. */
    private double extent(double[] x) {
        double largest = 0;
        for (int k = 0; k < 3; k++) {
            double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
            for (int v : vertex) { lo = Math.min(lo, x[3 * v + k]); hi = Math.max(hi, x[3 * v + k]); }
            largest = Math.max(largest, hi - lo);
        }
        return largest;
    }

    /**
     * V at x, and 6∇V into g unless it is null; positions taken relative to the first vertex (less round-off far
     * from the origin).
     */
    private double volumeAndGradient(double[] x, double[] g) {
        if (g != null) Arrays.fill(g, 0);
        final int o = 3 * vertex[0];
        final double ox = x[o], oy = x[o + 1], oz = x[o + 2];
        double six = 0;
        for (int t = 0; t < corner.length; t += 3) {
            final int a = corner[t], b = corner[t + 1], c = corner[t + 2];
            final int ia = 3 * vertex[a], ib = 3 * vertex[b], ic = 3 * vertex[c];
            double ax = x[ia] - ox, ay = x[ia + 1] - oy, az = x[ia + 2] - oz;
            double bx = x[ib] - ox, by = x[ib + 1] - oy, bz = x[ib + 2] - oz;
            double cx = x[ic] - ox, cy = x[ic + 1] - oy, cz = x[ic + 2] - oz;
            double bcx = by * cz - bz * cy, bcy = bz * cx - bx * cz, bcz = bx * cy - by * cx;
            six += ax * bcx + ay * bcy + az * bcz;
            if (g == null) continue;
            g[3 * a] += bcx; g[3 * a + 1] += bcy; g[3 * a + 2] += bcz;
            g[3 * b] += cy * az - cz * ay; g[3 * b + 1] += cz * ax - cx * az; g[3 * b + 2] += cx * ay - cy * ax;
            g[3 * c] += ay * bz - az * by; g[3 * c + 1] += az * bx - ax * bz; g[3 * c + 2] += ax * by - ay * bx;
        }
        return six / 6;
    }

    /** The volume the surface encloses now, m³. */
    public double volume(Particles p) { return volumeAndGradient(p.x, null); }

    /** The volume it enclosed when made, m³. */
    public double restVolume() { return restVolume; }

    /** Whether this is a gas (pressure from pV = nRT), not a held volume. */
    public boolean isGas() { return !Double.isNaN(amount); }

    /** nRT, J (NaN for a held volume). */
    public double amount() { return amount; }

    /** The held volume, m³ (NaN for a gas). */
    public double targetVolume() { return target; }

    public double ambient() { return ambient; }

    /** Pumps gas in or lets it out (nRT, J), from the next substep. */
    public void setAmount(double nRT) {
        if (!isGas()) throw new IllegalArgumentException("nRT: this surface holds a volume, not a gas");
        amount = Check.inRange("nRT", nRT, Double.MIN_NORMAL, MAX_AMOUNT);
    }

    /** Makes it hold another volume (m³), from the next substep. */
    public void setTargetVolume(double volume) {
        if (isGas()) throw new IllegalArgumentException("volume: this surface holds a gas, not a volume");
        target = Check.inRange("volume", volume, Double.MIN_NORMAL, MAX_VOLUME);
    }

    /** The pressure inside that the last substep applied, Pa: p₀ + λ/h² (NaN before the first substep). */
    public double pressure() { return ambient + lambda / (h * h); }

    /** The particles of the surface (a copy). */
    public int[] particles() { return vertex.clone(); }

    /** A volume no smaller than {@link #VOLUME_FLOOR} of the rest volume (a crushed or inverted surface's stand-in). */
    private double floored(double volume) { return Math.max(volume, VOLUME_FLOOR * restVolume); }

    /** Once per substep, after the prediction: λ = 0, and the gas law linearised at the predicted volume. */
    void beginSubstep(Particles p, double h) {
        this.h = h;
        lambda = 0;
        if (!isGas()) {
            goal = target;
            alphaTilde = 0;
            return;
        }
        double vc = floored(volumeAndGradient(p.x, null));
        double alpha = vc * vc / amount;
        // Newton's step on U is 2V_c − p₀V_c²/nRT, which falls below 0 for a gas blown past twice its volume in the air
        // (nRT/V_c < p₀/2): damped to halving or doubling the volume in a substep (a fuzzed 50 µm pillow at 3·10¹⁴ Pa
        // grew 10⁹-fold in six substeps, then its undamped goal was −9·10⁻⁵ m³ and it turned inside out to infinity).
        goal = Math.max(0.5 * vc, Math.min(2 * vc, vc + alpha * (amount / vc - ambient)));
        alphaTilde = alpha / (h * h);
    }

    /** One XPBD projection of the row: Δλ = (−C − α̃λ)/(Σ w|∇V|² + α̃), Δx = w ∇V Δλ. */
    void project(Particles p) {
        final double[] x = p.x, w = p.w, g = gradient;
        final double c = volumeAndGradient(x, g) - goal;
        double weighted = 0;
        for (int l = 0; l < vertex.length; l++) {
            double gx = g[3 * l], gy = g[3 * l + 1], gz = g[3 * l + 2];
            weighted += w[vertex[l]] * (gx * gx + gy * gy + gz * gz);
        }
        weighted /= 36;
        double denominator = weighted + alphaTilde;
        if (!(denominator > 0)) return; // every particle pinned
        double dLambda = (-c - alphaTilde * lambda) / denominator;
        // V is cubic in the positions: a projection whose linear change reaches the volume itself can overshoot through
        // zero (a spiky surface), so one projection changes it by half the current volume at most, to first order.
        double most = 0.5 * floored(Math.abs(c + goal)) / weighted;
        dLambda = Math.max(-most, Math.min(most, dLambda));
        lambda += dLambda;
        for (int l = 0; l < vertex.length; l++) {
            int i = vertex[l];
            double s = w[i] * dLambda / 6;
            x[3 * i] += s * g[3 * l];
            x[3 * i + 1] += s * g[3 * l + 1];
            x[3 * i + 2] += s * g[3 * l + 2];
        }
    }

    /**
     * Adds the gradient of the gas's energy, (p₀ − nRT/V) ∇V, to a residual of 3 numbers per particle, or, for a
     * held volume (hard: no energy), marks its particles held.
     */
    void addForceTerm(Particles p, double[] residual, boolean[] held) {
        double v = volumeAndGradient(p.x, gradient);
        for (int l = 0; l < vertex.length; l++) {
            int i = vertex[l];
            if (!isGas()) { held[i] = true; continue; }
            double s = (ambient - amount / floored(v)) / 6;
            for (int a = 0; a < 3; a++) residual[3 * i + a] += s * gradient[3 * l + a];
        }
    }

    /** The particle the probe checks after a projection: every one of the surface's. */
    int particle(int l) { return vertex[l]; }

    int particleCount() { return vertex.length; }
}
