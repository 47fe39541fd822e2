package xpbdcloth.fabric;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import xpbdcloth.engine.AfterStep;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.DihedralBlock;
import xpbdcloth.engine.Particles;

/**
 * Bending whose stiffness follows the curvature as the measured fabric's does ({@link BendingCurve}): after
 * every step, each of the fabric's dihedral hinges takes the curve's secant stiffness at the curvature the
 * step left and at its edge's angle to the warp, which the next step solves with. At equilibrium the lag
 * is gone: the moment is the data's at the cloth's own curvature. Serial and allocation-free.
 */
public final class MeasuredBending implements AfterStep {
    private final DihedralBlock[] blocks;
    /** Per block, per hinge: |e| at rest, and the edge's angle to the warp (rad, in [0, π/2]). */
    private final double[][] restLength, edgeAngle;
    private BendingCurve curve;

    /**
     * @param blocks    a simulation's blocks; its {@link ConstraintFamily#DIHEDRAL} blocks (the fabric's
     *                  hinges, not a garment's seams) follow the curve
     * @param rest      the particles at their rest shape (a garment's flat pattern), read here only
     * @param triangles the cloth's triangles, three particles each
     * @param warp      the warp (x, y, z), or one per triangle (3 numbers each), as {@link FabricConstraints#build}
     */
    public MeasuredBending(List<ConstraintBlock> blocks, Particles rest, int[] triangles, double[] warp, BendingCurve curve) {
        if (blocks == null || rest == null || triangles == null || warp == null)
            throw new IllegalArgumentException("blocks, rest, triangles and warp must not be null");
        if (curve == null) throw new IllegalArgumentException("curve must not be null, was null");
        if (warp.length != 3 && warp.length != triangles.length)
            throw new IllegalArgumentException("warp must be a direction (x, y, z) or one per triangle (" + triangles.length + " numbers), was " + warp.length + " numbers");
        List<DihedralBlock> hinges = new ArrayList<>();
        for (ConstraintBlock b : blocks) if (b instanceof DihedralBlock && b.family() == ConstraintFamily.DIHEDRAL) hinges.add((DihedralBlock) b);
        if (hinges.isEmpty()) throw new IllegalArgumentException("blocks have no dihedral hinges to follow a bending curve (the fabric bends by plate patches)");
        this.blocks = hinges.toArray(new DihedralBlock[0]);
        Map<Long, Integer> triangleOfEdge = new HashMap<>();
        for (int t = 0; t < triangles.length; t += 3)
            for (int k = 0; k < 3; k++) triangleOfEdge.putIfAbsent(undirected(triangles[t + k], triangles[t + (k + 1) % 3]), t);
        restLength = new double[this.blocks.length][];
        edgeAngle = new double[this.blocks.length][];
        double[] x = rest.positions();
        for (int b = 0; b < this.blocks.length; b++) {
            DihedralBlock d = this.blocks[b];
            restLength[b] = new double[d.count()];
            edgeAngle[b] = new double[d.count()];
            for (int i = 0; i < d.count(); i++) {
                int e0 = d.particle(i, 2), e1 = d.particle(i, 3);
                Integer t = triangleOfEdge.get(undirected(e0, e1));
                if (t == null) throw new IllegalArgumentException("hinge " + i + "'s edge (" + e0 + ", " + e1 + ") is in no triangle");
                double[] e = {x[3 * e1] - x[3 * e0], x[3 * e1 + 1] - x[3 * e0 + 1], x[3 * e1 + 2] - x[3 * e0 + 2]};
                restLength[b][i] = Math.sqrt(dot(e, e));
                int w = warp.length == 3 ? 0 : t;
                double[] inPlane = inPlane(x, triangles[t], triangles[t + 1], triangles[t + 2], warp[w], warp[w + 1], warp[w + 2]);
                double cos = Math.abs(dot(e, inPlane)) / (restLength[b][i] * Math.sqrt(dot(inPlane, inPlane)));
                edgeAngle[b][i] = Math.acos(Math.min(1, cos));
            }
        }
        this.curve = curve;
    }

    @Override public void check(List<ConstraintBlock> held) {
        for (DihedralBlock d : blocks)
            if (!held.contains(d)) throw new IllegalArgumentException("bending curve was made for blocks this simulation does not hold");
    }

    /**
     * Follows another fabric's curve from the next step (a fabric swapped live), or none: null leaves the
     * hinges as they are given ({@link FabricSwap} gives them the new fabric's linear B).
     */
    public void use(BendingCurve next) { curve = next; }

    /** The angle (rad, in [0, π/2]) of hinge i of the b-th followed block's edge to the warp. */
    public double edgeAngle(int b, int i) { return edgeAngle[b][i]; }

    @Override public void afterStep(Particles p, double dt) {
        if (curve == null) return;
        for (int b = 0; b < blocks.length; b++) {
            DihedralBlock d = blocks[b];
            double[] length = restLength[b], angle = edgeAngle[b];
            for (int i = 0, n = d.count(); i < n; i++) {
                double curvature = Math.abs(d.evaluate(i, p)) / (d.restAreaOverEdgeSquared(i) * length[i]);
                d.setBendingStiffness(i, curve.stiffness(curvature, angle[i]));
            }
        }
    }

    private static long undirected(int a, int b) { return (long) Math.min(a, b) << 32 | Math.max(a, b); }

    private static double dot(double[] a, double[] b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

    /** The warp projected into triangle (a, b, c)'s plane. */
    private static double[] inPlane(double[] x, int a, int b, int c, double wx, double wy, double wz) {
        double ux = x[3 * b] - x[3 * a], uy = x[3 * b + 1] - x[3 * a + 1], uz = x[3 * b + 2] - x[3 * a + 2];
        double vx = x[3 * c] - x[3 * a], vy = x[3 * c + 1] - x[3 * a + 1], vz = x[3 * c + 2] - x[3 * a + 2];
        double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx, nn = nx * nx + ny * ny + nz * nz;
        double s = (wx * nx + wy * ny + wz * nz) / nn;
        return new double[] {wx - s * nx, wy - s * ny, wz - s * nz};
    }
}
