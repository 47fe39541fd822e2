package xpbdcloth.fit;

import java.util.ArrayList;
import java.util.List;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;
import xpbdcloth.linalg.BandedMatrix;

/**
 * The energy whose minimum is XPBD's rest shape, with the compliances as parameters.
 *
 * <p>At rest (v = 0) a step of XPBD with timestep h leaves x unchanged exactly when the solve's equations
 * hold at x̃ = x + h²g, i.e. M(x − x̃) = Σⱼ ∇Cⱼᵀλⱼ and Cⱼ(x) + (αⱼ/h²)λⱼ = 0 (Macklin et al. 2016, eq. 8–9).
 * Eliminating λⱼ = −h²Cⱼ/αⱼ leaves Σⱼ Cⱼ∇Cⱼ/αⱼ = Mg, which is ∇E = 0 for
 * <pre>
 *   E(x) = Σⱼ Cⱼ(x)² / (2αⱼ) − Σᵢ mᵢ g·xᵢ        (free particles i; pinned ones are fixed)
 * </pre>
 * — the same for every h and every sweep count, which is why a fitted α is a property of the cloth and
 * a fitted PBD k is not. Parameters: θ_f = ln s_f per fitted family f, αⱼ = s_f αⱼ⁰ (αⱼ⁰ as the scene
 * built it), so a family with one α is fitted as that α and a family with per-constraint compliances
 * (a fabric's membrane rows and dihedral edges) keeps their ratios and fits their common scale.
 *
 * <p>Derivatives: ∇E uses each block's own analytic C and ∇C (the functions the solvers project with);
 * the Hessian is ∇Cⱼ∇Cⱼᵀ for a linear Cⱼ (bending), else the central difference of each constraint's
 * Cⱼ∇Cⱼ, i.e. of those same functions, at steps of 1e-4 and ½·1e-4 of the shortest rest edge combined by Richardson extrapolation (error O(h⁴): the plain
 * difference's O(h²) error at 1e-5, 1e-10 of an entry, became 1e-4 in the gradient of a draped cloth whose Hessian
 * spans ten decades) — so there is no second
 * copy of any constraint's maths to drift from the first. Differencing Cⱼ∇Cⱼ rather than ∇Cⱼ keeps the
 * triangle bend smooth where its C = |d| is not (Cⱼ∇Cⱼ = d there).
 *
 * <p>Left out: tethers (an inequality, inactive at a rest shape they do not stretch; {@link #activeTethers}
 * counts any that are not), contacts (the fit assumes none touch), and hard constraints (α = 0 stores no
 * energy to differentiate: refused).
 */
final class ClothEnergy {
    private final Particles scratch;
    private final double[] mass;
    /** The scene's positions when the energy was made: the gravity term's zero. */
    private final double[] rest;
    private final double gx, gy, gz;
    /** Free degree of freedom of coordinate c (3·particle + axis), or −1 for a pinned particle's. */
    final int[] dofOf;
    final int freeDofs;
    private final List<ConstraintBlock> blocks = new ArrayList<>();
    private final List<ConstraintBlock> tethers = new ArrayList<>();
    /** Parameter index of each block in {@link #blocks}, −1 when its family is not fitted. */
    private final int[] parameterOf;
    final List<ConstraintFamily> fitted;
    private final double[] scale;
    private final double step;
    private final int band;
    private final double[] grad = new double[3 * ConstraintBlock.MAX_ARITY], unit = new double[3 * ConstraintBlock.MAX_ARITY], column = new double[3 * ConstraintBlock.MAX_ARITY];
    private final DirectionalDifference difference = new DirectionalDifference();
    /** Cⱼ∇Cⱼ of a constraint at the particles' positions: ∇ of ½Cⱼ², smooth where Cⱼ = |d| is not. */
    private static final DirectionalDifference.BlockFunction FORCE = (b, i, p, out) -> {
        double c = b.evaluate(i, p);
        b.gradient(i, p, out);
        for (int q = 0, m = 3 * b.arity(); q < m; q++) out[q] *= c;
    };

    ClothEnergy(Simulation sim, List<ConstraintFamily> fitted) {
        if (sim.settings().mode() != ConstraintMode.XPBD)
            throw new IllegalArgumentException("mode must be XPBD for a fit (a PBD rest shape depends on the sweep count, so it has no energy to fit), was " + sim.settings().mode());
        Particles p = sim.particles();
        int n = p.count();
        scratch = new Particles(n);
        mass = new double[n];
        rest = p.positions().clone();
        dofOf = new int[3 * n];
        int free = 0;
        for (int i = 0; i < n; i++) {
            mass[i] = p.mass(i);
            for (int a = 0; a < 3; a++) dofOf[3 * i + a] = p.isPinned(i) ? -1 : free++;
        }
        freeDofs = free;
        if (freeDofs == 0) throw new IllegalArgumentException("scene has no free particle to fit, was " + n + " pinned");
        gx = sim.settings().gravityX(); gy = sim.settings().gravityY(); gz = sim.settings().gravityZ();
        this.fitted = List.copyOf(fitted);
        scale = new double[fitted.size()];
        java.util.Arrays.fill(scale, 1.0);
        List<Integer> params = new ArrayList<>();
        for (ConstraintBlock b : sim.blocks()) {
            if (b.count() == 0) continue;
            if (b.family() == ConstraintFamily.TETHER) { tethers.add(b); continue; }
            for (int i = 0; i < b.count(); i++)
                if (!(b.compliance(i) > 0))
                    throw new IllegalArgumentException("families." + name(b.family()) + ".compliance must be > 0 for a fit (a hard constraint stores no energy), was " + b.compliance(i));
            blocks.add(b);
            params.add(fitted.indexOf(b.family()));
        }
        for (ConstraintFamily f : fitted)
            if (blocks.stream().noneMatch(b -> b.family() == f))
                throw new IllegalArgumentException("params names " + name(f) + ", which this scene does not have; it has " + present());
        parameterOf = params.stream().mapToInt(Integer::intValue).toArray();
        step = 1e-4 * shortestRestEdge(p);
        band = bandwidth();
    }

    static String name(ConstraintFamily f) { return f.name().toLowerCase(java.util.Locale.ROOT); }

    /** The families this scene has that a fit can take. */
    String present() {
        StringBuilder s = new StringBuilder();
        for (ConstraintBlock b : blocks) s.append(s.length() == 0 ? "" : ", ").append(name(b.family()));
        return s.toString();
    }

    private double shortestRestEdge(Particles p) {
        double shortest = Double.POSITIVE_INFINITY;
        for (ConstraintBlock b : blocks)
            for (int i = 0; i < b.count(); i++)
                for (int k = 1; k < b.arity(); k++) {
                    int u = b.particle(i, 0), v = b.particle(i, k);
                    double dx = p.x(u) - p.x(v), dy = p.y(u) - p.y(v), dz = p.z(u) - p.z(v);
                    double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
                    if (d > 0) shortest = Math.min(shortest, d);
                }
        return Double.isFinite(shortest) ? shortest : 1e-2;
    }

    private int bandwidth() {
        int band = 2;
        for (ConstraintBlock b : blocks)
            for (int i = 0; i < b.count(); i++) {
                int lo = Integer.MAX_VALUE, hi = -1;
                for (int k = 0; k < b.arity(); k++)
                    for (int a = 0; a < 3; a++) {
                        int d = dofOf[3 * b.particle(i, k) + a];
                        if (d >= 0) { lo = Math.min(lo, d); hi = Math.max(hi, d); }
                    }
                if (hi >= 0) band = Math.max(band, hi - lo);
            }
        return band;
    }

    int parameters() { return scale.length; }

    /** θ = ln s per fitted family. */
    void setLogScales(double[] theta) {
        for (int f = 0; f < scale.length; f++) scale[f] = Math.exp(theta[f]);
    }

    /** αⱼ of constraint i of the k-th block at the current scales. */
    private double compliance(int k, int i) {
        int f = parameterOf[k];
        return blocks.get(k).compliance(i) * (f < 0 ? 1 : scale[f]);
    }

    /** The scene's own α of fitted family f, unscaled (its first constraint's, for a per-constraint family). */
    double sceneCompliance(int f) {
        for (int k = 0; k < blocks.size(); k++) if (parameterOf[k] == f) return blocks.get(k).compliance(0);
        throw new IllegalArgumentException("parameter must name a fitted family, was " + f);
    }

    private void load(double[] positions) {
        System.arraycopy(positions, 0, scratch.positions(), 0, positions.length);
    }

    /**
     * E(x) for the full position vector (pinned particles as given), the gravity term measured from the
     * rest mesh so E stays small and its round-off with it.
     */
    double energy(double[] positions) {
        load(positions);
        double e = 0;
        for (int k = 0; k < blocks.size(); k++) {
            ConstraintBlock b = blocks.get(k);
            for (int i = 0; i < b.count(); i++) {
                double c = b.evaluate(i, scratch);
                e += c * c / (2 * compliance(k, i));
            }
        }
        for (int i = 0; i < mass.length; i++)
            if (dofOf[3 * i] >= 0) e -= mass[i] * (gx * (positions[3 * i] - rest[3 * i]) + gy * (positions[3 * i + 1] - rest[3 * i + 1]) + gz * (positions[3 * i + 2] - rest[3 * i + 2]));
        return e;
    }

    /** ∇E on the free degrees of freedom. */
    void gradient(double[] positions, double[] out) {
        java.util.Arrays.fill(out, 0, freeDofs, 0);
        load(positions);
        for (int k = 0; k < blocks.size(); k++) addForces(k, out);
        for (int i = 0; i < mass.length; i++) {
            int d = dofOf[3 * i];
            if (d < 0) continue;
            out[d] -= mass[i] * gx;
            out[d + 1] -= mass[i] * gy;
            out[d + 2] -= mass[i] * gz;
        }
    }

    /**
     * F_f = Σ_{j ∈ f} Cⱼ∇Cⱼ/αⱼ on the free degrees of freedom: the elastic force of family f with its sign
     * flipped, which is also −∂(∇E)/∂θ_f, the right-hand side of the equilibrium's sensitivity to θ_f.
     */
    void familyForce(double[] positions, int f, double[] out) {
        java.util.Arrays.fill(out, 0, freeDofs, 0);
        load(positions);
        for (int k = 0; k < blocks.size(); k++) if (parameterOf[k] == f) addForces(k, out);
    }

    /** Adds Σ Cⱼ∇Cⱼ/αⱼ of the k-th block at the loaded positions. */
    private void addForces(int k, double[] out) {
        ConstraintBlock b = blocks.get(k);
        int arity = b.arity();
        for (int i = 0; i < b.count(); i++) {
            double c = b.evaluate(i, scratch);
            if (c == 0) continue;
            b.gradient(i, scratch, grad);
            double s = c / compliance(k, i);
            for (int q = 0; q < arity; q++)
                for (int a = 0; a < 3; a++) {
                    int d = dofOf[3 * b.particle(i, q) + a];
                    if (d >= 0) out[d] += s * grad[3 * q + a];
                }
        }
    }

    /** ∇²E on the free degrees of freedom (central differences of each constraint's Cⱼ∇Cⱼ). */
    BandedMatrix hessian(double[] positions) {
        BandedMatrix h = new BandedMatrix(freeDofs, band);
        load(positions);
        for (int k = 0; k < blocks.size(); k++) {
            ConstraintBlock b = blocks.get(k);
            int arity = b.arity(), local = 3 * arity;
            for (int i = 0; i < b.count(); i++) {
                double inv = 1 / compliance(k, i);
                if (b.isLinear()) b.gradient(i, scratch, grad);
                for (int col = 0; col < local; col++) {
                    int dc = dofOf[3 * b.particle(i, col / 3) + col % 3];
                    if (dc < 0) continue;
                    if (b.isLinear()) {
                        // A linear C: the column of ∇C∇Cᵀ, exact (differences would only add round-off).
                        for (int row = 0; row < local; row++) column[row] = grad[row] * grad[col];
                    } else {
                        // Column col: the derivative along that coordinate, at steps h and h/2 (Richardson), never shrunk.
                        unit[col] = 1;
                        difference.along(b, i, scratch, FORCE, unit, step, 0, column);
                        unit[col] = 0;
                    }
                    // Each off-diagonal pair is met twice (as (r, c) and (c, r)): half of each makes H symmetric.
                    for (int row = 0; row < local; row++) {
                        int dr = dofOf[3 * b.particle(i, row / 3) + row % 3];
                        if (dr < 0) continue;
                        double v = column[row] * inv;
                        h.add(dr, dc, row == col ? v : v / 2);
                    }
                }
            }
        }
        return h;
    }

    /** Tethers that are stretched at these positions (the energy leaves them out). */
    int activeTethers(double[] positions) {
        load(positions);
        int n = 0;
        for (ConstraintBlock b : tethers) for (int i = 0; i < b.count(); i++) if (b.evaluate(i, scratch) > 1e-9) n++;
        return n;
    }

    /** The free coordinates of a full position vector. */
    double[] free(double[] positions) {
        double[] out = new double[freeDofs];
        for (int c = 0; c < dofOf.length; c++) if (dofOf[c] >= 0) out[dofOf[c]] = positions[c];
        return out;
    }

    /** positions += t·delta on the free coordinates. */
    void addFree(double[] positions, double t, double[] delta) {
        for (int c = 0; c < dofOf.length; c++) if (dofOf[c] >= 0) positions[c] += t * delta[dofOf[c]];
    }
}
