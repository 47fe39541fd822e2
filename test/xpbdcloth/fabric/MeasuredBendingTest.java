package xpbdcloth.fabric;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.DihedralBlock;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SolverSettings;
import xpbdcloth.engine.StepBalance;
import xpbdcloth.scene.FabricCatalogue;

/**
 * The catalogue's denim bends as its measured bending curve says: a hinge's moment per unit length at
 * curvature κ along an edge at angle φ to the warp is B(κ, φ)·κ, with B from the data's fifteen samples
 * interpolated as ARCSim's dde.cpp does (written out here from the data, not from the project's conversion);
 * and a hinge bent by a weight comes to rest where the weight's torque is the measured hinge's.
 */
class MeasuredBendingTest {
    /** 11oz-black-denim's bending samples as ARCSim distributes them: rows 0°, 45°, 90°; columns α = 0, 5, 10, 15, 20 /m. */
    static final double[][] DENIM = {
            {64.196457e-6, 60.286175e-6, 60.943428e-6, 62.433697e-6, 19.824701e-6},
            {73.384567e-6, 59.671982e-6, 61.080757e-6, 68.242569e-6, 36.033474e-6},
            {96.951576e-6, 107.848228e-6, 113.060738e-6, 120.569740e-6, 79.781021e-6}};

    /** ARCSim's k_e for curvature κ (its θ·l/(A₀ + A₁)) and an edge whose material direction is (du, dv). */
    static double arcsimKe(double curvature, double du, double dv) {
        double value = curvature / 2 * 0.2;
        if (value > 4) value = 4;
        int vi = Math.min((int) value, 3);
        value -= vi;
        double bias = Math.atan2(dv, du) * 4 / Math.PI;
        if (bias < 0) bias = -bias;
        if (bias > 4) bias = 8 - bias;
        if (bias > 2) bias = 4 - bias;
        int bi = Math.min((int) bias, 1);
        bias -= bi;
        return DENIM[bi][vi] * (1 - bias) * (1 - value) + DENIM[bi + 1][vi] * bias * (1 - value)
                + DENIM[bi][vi + 1] * (1 - bias) * value + DENIM[bi + 1][vi + 1] * bias * value;
    }

    /**
     * A 2 cm square of denim lying flat, split along a diagonal into the one hinge, its warp at {@code warpTurn}
     * (rad) from x in the plane: the hinge's edge is at ±45° − warpTurn to the warp (the grid's diagonal).
     */
    static final class Hinge {
        final Particles p;
        final Simulation sim;
        final DihedralBlock block;
        final MeasuredBending bending;
        final double edge, areas;
        final double du, dv;

        Hinge(double warpTurn, double arealDensity) {
            Cloth square = new ClothBuilder().resolution(2, 2).size(0.02, 0.02).plane(ClothBuilder.Plane.HORIZONTAL).arealDensity(arealDensity).build();
            p = square.particles();
            Fabric denim = FabricCatalogue.named("denim");
            double[] warp = {Math.cos(warpTurn), 0, Math.sin(warpTurn)};
            sim = new Simulation(p, new SolverSettings().withMode(ConstraintMode.XPBD).withIterations(8).withSubsteps(10).withTimestep(0.01).withDamping(20));
            List<ConstraintBlock> blocks = FabricConstraints.build(p, square.triangles(), warp, denim.membrane, denim.bendingStiffness, false, true);
            for (ConstraintBlock b : blocks) sim.add(b);
            DihedralBlock found = null;
            for (ConstraintBlock b : sim.blocks()) if (b instanceof DihedralBlock) found = (DihedralBlock) b;
            block = found;
            assertEquals(1, block.count(), "one hinge: the diagonal");
            bending = new MeasuredBending(sim.blocks(), p, square.triangles(), warp, denim.bendingCurve);
            sim.add(bending);
            int e0 = block.particle(0, 2), e1 = block.particle(0, 3);
            double[] e = {p.x(e1) - p.x(e0), p.y(e1) - p.y(e0), p.z(e1) - p.z(e0)};
            edge = Math.sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
            areas = block.restAreaOverEdgeSquared(0) * edge * edge;
            // The edge in the fabric's own coordinates: along the warp, and along the weft (warp turned 90° in the plane).
            du = e[0] * warp[0] + e[2] * warp[2];
            dv = -e[0] * warp[2] + e[2] * warp[0];
        }

        /** Turns particle o1 about the hinge's edge by θ (rad). */
        void bend(double theta) {
            int o1 = block.particle(0, 1), e0 = block.particle(0, 2), e1 = block.particle(0, 3);
            double[] a = {p.x(e1) - p.x(e0), p.y(e1) - p.y(e0), p.z(e1) - p.z(e0)};
            double n = Math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
            for (int k = 0; k < 3; k++) a[k] /= n;
            double[] r = {p.x(o1) - p.x(e0), p.y(o1) - p.y(e0), p.z(o1) - p.z(e0)};
            double c = Math.cos(theta), s = Math.sin(theta), d = a[0] * r[0] + a[1] * r[1] + a[2] * r[2];
            double[] cross = {a[1] * r[2] - a[2] * r[1], a[2] * r[0] - a[0] * r[2], a[0] * r[1] - a[1] * r[0]};
            double[] turned = new double[3];
            for (int k = 0; k < 3; k++) turned[k] = r[k] * c + cross[k] * s + a[k] * d * (1 - c);
            p.setPosition(o1, p.x(e0) + turned[0], p.y(e0) + turned[1], p.z(e0) + turned[2]);
        }

        /** The hinge's moment per unit edge length, θ/(α|e|) (its energy θ²/2α), N·m/m. */
        double momentPerLength() {
            return Math.abs(block.evaluate(0, p)) / (block.compliance(0) * edge);
        }
    }

    @Test
    void aHingesMomentIsTheDatasAtItsCurvatureAlongWarpBiasWeftAndBetween() {
        double worst = 0;
        for (double warpTurn : new double[] {Math.PI / 4, 0, -Math.PI / 4, Math.PI / 8, 0.3}) {
            for (double curvature : new double[] {2, 10, 17.5, 26, 33, 47}) {
                Hinge h = new Hinge(warpTurn, 0.324);
                h.bend(curvature * h.areas / h.edge);
                h.bending.afterStep(h.p, 0.01);
                double measured = Math.abs(h.block.evaluate(0, h.p)) * h.edge / h.areas;
                assertEquals(curvature, measured, 1e-9 * curvature, "the hinge is bent to the curvature asked");
                double expected = arcsimKe(curvature, h.du, h.dv) / 4 * curvature, got = h.momentPerLength();
                worst = Math.max(worst, Math.abs(got - expected) / expected);
                assertEquals(expected, got, 1e-9 * expected, "warp turned " + warpTurn + " rad, κ = " + curvature + " /m");
            }
        }
        System.out.printf("moment per length against ARCSim's formula: worst relative difference %.2e%n", worst);
        // The curve is felt: at 40 /m along the warp denim bends at under a third of its stiffness at zero.
        Hinge along = new Hinge(Math.PI / 4, 0.324);
        if (Math.abs(along.dv) > 1e-12) along = new Hinge(-Math.PI / 4, 0.324);
        assertEquals(0, along.dv, 1e-12, "the edge along the warp");
        along.bend(40 * along.areas / along.edge);
        along.bending.afterStep(along.p, 0.01);
        assertEquals(19.824701e-6 / 4 * 40, along.momentPerLength(), 1e-9, "the table's last sample along the warp");
    }

    @Test
    void aHingeBentByAWeightComesToRestWhereTheWeightsTorqueIsTheMeasuredMoment() {
        for (double warpTurn : new double[] {-Math.PI / 4, 0, Math.PI / 4}) {
            Hinge h = new Hinge(warpTurn, 0.5);
            int o0 = h.block.particle(0, 0), o1 = h.block.particle(0, 1), e0 = h.block.particle(0, 2), e1 = h.block.particle(0, 3);
            for (int q : new int[] {o0, e0, e1}) h.p.pin(q);
            for (int s = 0; s < 1500; s++) h.sim.step();
            assertTrue(h.sim.balance() < StepBalance.CONVERGED, "at rest: balance " + h.sim.balance());
            // Gravity's torque on o1 about the edge axis.
            double[] a = {h.p.x(e1) - h.p.x(e0), h.p.y(e1) - h.p.y(e0), h.p.z(e1) - h.p.z(e0)};
            double n = Math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
            double rx = h.p.x(o1) - h.p.x(e0), rz = h.p.z(o1) - h.p.z(e0), w = h.p.mass(o1) * 9.81;
            // r × (0, −w, 0) = (w rz, 0, −w rx), along the edge's unit vector.
            double torque = Math.abs((w * rz * a[0] - w * rx * a[2]) / n);
            double theta = Math.abs(h.block.evaluate(0, h.p)), curvature = theta * h.edge / h.areas;
            double measured = arcsimKe(curvature, h.du, h.dv) / 4 * theta * h.edge * h.edge / h.areas;
            double linear = DataDrivenSample.bendingStiffness(new double[] {DENIM[0][0], DENIM[1][0], DENIM[2][0]}) * theta * h.edge * h.edge / h.areas;
            System.out.printf("warp turned %.2f rad: κ %.1f /m, weight's torque %.4e N·m, measured hinge %.4e, linear hinge %.4e%n",
                    warpTurn, curvature, torque, measured, linear);
            assertTrue(curvature > 5, "bent into the curve, not at its zero-curvature slope: κ " + curvature);
            assertEquals(torque, measured, 0.01 * torque, "the weight balances the measured hinge");
            assertTrue(Math.abs(linear - torque) > 0.05 * torque, "and not the linear one: " + linear + " against " + torque);
        }
    }
}
