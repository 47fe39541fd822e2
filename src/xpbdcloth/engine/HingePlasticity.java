package xpbdcloth.engine;

import java.util.ArrayList;
import java.util.List;

/**
 * Bending that yields, so a cloth folded hard keeps a crease: where a {@link DihedralBlock} hinge is bent past
 * its yield angle, its rest angle flows toward the angle it is held at.
 *
 * <pre>
 *   C = θ − θ₀   (the hinge's bend from rest, wrapped into (−π, π] as the block wraps it)
 *   θ_y = κ_y w,   w = (A₀ + A₁)/|e| at rest   (the hinge's width: a cloth bent to curvature κ turns a hinge by κ w)
 *   dθ₀/dt = r · sign(C) · max(|C| − θ_y, 0)   (rate-dependent plastic flow: Perzyna's overstress model)
 *   over a step, θ held:  θ₀ ← θ₀ + sign(C) · max(|C| − θ_y, 0) · (1 − e^(−r·dt))
 * </pre>
 * A hinge held at θ therefore settles at θ₀ = θ ∓ θ_y with time constant 1/r, and, let go, springs back by θ_y:
 * the crease is the fold less the elastic part the yield allows. A bend below the yield is elastic and returns flat.
 * The flow integrates exactly for a held angle, so any rate and step are stable (r·dt ≫ 1 is instant yield).
 * The yield is a curvature, not a hinge angle, so the same fabric creases the same on any mesh (a hinge angle
 * threshold, as Houdini Vellum's plastic threshold, yields at a curvature that grows as the mesh is refined).
 * Plastic bending with a yield in cloth and sheets: Narain, Pfaff, O'Brien 2013, "Folding and Crumpling
 * Adaptive Sheets" (§4, plastic bending); the overstress flow: Perzyna 1966, "Fundamental Problems in
 * Viscoplasticity".
 *
 * <p>It runs once after every step that the simulation kept (a step undone leaves the rest angles too), on the
 * hinges of the blocks it was made for, serially: the same rest angles on any number of threads.
 */
public final class HingePlasticity implements AfterStep {
    private final DihedralBlock[] blocks;
    /** θ_y per hinge of each block, rad. */
    private final double[][] yieldAngle;
    private final double yieldCurvature, rate;

    /**
     * @param blocks         a simulation's blocks; its {@link DihedralBlock}s yield (the others are not touched)
     * @param rest           the particles at the blocks' rest shape (it gives each hinge's width)
     * @param yieldCurvature κ_y, 1/m: a bend sharper than this flows
     * @param rate           r, 1/s: how fast a rest angle follows the overstress
     */
    public HingePlasticity(List<ConstraintBlock> blocks, Particles rest, double yieldCurvature, double rate) {
        if (blocks == null) throw new IllegalArgumentException("blocks must not be null, was null");
        if (rest == null) throw new IllegalArgumentException("rest must not be null, was null");
        Check.inRange("yieldCurvature", yieldCurvature, Double.MIN_NORMAL, 1e6);
        Check.inRange("rate", rate, Double.MIN_NORMAL, 1e6);
        this.yieldCurvature = yieldCurvature;
        this.rate = rate;
        List<DihedralBlock> hinges = new ArrayList<>();
        for (ConstraintBlock b : blocks) if (b instanceof DihedralBlock) hinges.add((DihedralBlock) b);
        if (hinges.isEmpty()) throw new IllegalArgumentException("blocks have no dihedral hinge to yield (a cloth of springs, or bending as quadratic patches)");
        this.blocks = hinges.toArray(new DihedralBlock[0]);
        yieldAngle = new double[this.blocks.length][];
        final double[] x = rest.x;
        for (int k = 0; k < this.blocks.length; k++) {
            DihedralBlock d = this.blocks[k];
            yieldAngle[k] = new double[d.count()];
            for (int i = 0; i < d.count(); i++) {
                int e0 = 3 * d.particles[4 * i + 2], e1 = 3 * d.particles[4 * i + 3];
                double ex = x[e1] - x[e0], ey = x[e1 + 1] - x[e0 + 1], ez = x[e1 + 2] - x[e0 + 2];
                double width = d.areaOverEdgeSquared[i] * Math.sqrt(ex * ex + ey * ey + ez * ez);
                yieldAngle[k][i] = Math.min(yieldCurvature * width, Math.PI);
            }
        }
    }

    @Override public void check(List<ConstraintBlock> held) {
        for (DihedralBlock d : blocks)
            if (!held.contains(d)) throw new IllegalArgumentException("plasticity was made for blocks this simulation does not hold");
    }

    /** θ_y of hinge i of the k-th yielding block, rad. */
    public double yieldAngle(int k, int i) { return yieldAngle[k][i]; }

    public double rate() { return rate; }

    /** κ_y, 1/m. */
    public double yieldCurvature() { return yieldCurvature; }

    /** Moves every overstressed hinge's rest angle for a step of dt held at the particles' angles. */
    @Override public void afterStep(Particles p, double dt) {
        final double follow = -Math.expm1(-rate * dt);
        for (int k = 0; k < blocks.length; k++) {
            final DihedralBlock d = blocks[k];
            final double[] rest = d.restAngle, yield = yieldAngle[k];
            for (int i = 0, n = d.count(); i < n; i++) {
                double theta = d.angleAndGradient(i, p.x, null);
                if (Double.isNaN(theta)) continue;
                double c = d.wrapped(i, theta), over = Math.abs(c) - yield[i];
                if (over <= 0) continue;
                double r = rest[i] + Math.copySign(over * follow, c);
                rest[i] = r > Math.PI ? r - 2 * Math.PI : r <= -Math.PI ? r + 2 * Math.PI : r;
            }
        }
    }
}
