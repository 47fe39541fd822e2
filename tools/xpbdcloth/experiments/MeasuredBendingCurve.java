package xpbdcloth.experiments;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.DihedralBlock;
import xpbdcloth.engine.Particles;
import xpbdcloth.fabric.Fabric;
import xpbdcloth.fabric.FabricConstraints;
import xpbdcloth.fabric.MeasuredBending;
import xpbdcloth.scene.FabricCatalogue;

/**
 * Experiment 15: what the measured bending curve changes. A denim hinge (a 2 cm square split on its diagonal)
 * with its edge along the warp, the bias and the weft is bent to 0–50 /m, and its moment per unit length is
 * read from the engine's own hinge, θ/(α|e|), with the curve ({@link MeasuredBending}) and as the linear fabric
 * (the one isotropic B the catalogue gives, the mean of the 0° and 90° samples at zero curvature).
 */
final class MeasuredBendingCurve implements Experiment {
    static final String[] NAMES = {"warp", "bias", "weft"};

    @Override public String name() { return "measured-bending"; }

    @Override public String claim() { return "the catalogue's fabrics bend as measured: anisotropic, and softer or stiffer with curvature than one linear B"; }

    /** The moment per unit length (N·m/m) of the hinge bent to κ, its edge at {@code edgeAngle} (rad) to the warp. */
    static double moment(Fabric fabric, double curvature, double edgeAngle, boolean curve) {
        Cloth square = new ClothBuilder().resolution(2, 2).size(0.02, 0.02).plane(ClothBuilder.Plane.HORIZONTAL).arealDensity(0.3).build();
        Particles p = square.particles();
        List<ConstraintBlock> blocks = FabricConstraints.build(p, square.triangles(), new double[] {1, 0, 0}, fabric.membrane, fabric.bendingStiffness, false, true);
        DihedralBlock hinge = null;
        for (ConstraintBlock b : blocks) if (b instanceof DihedralBlock) hinge = (DihedralBlock) b;
        int o1 = hinge.particle(0, 1), e0 = hinge.particle(0, 2), e1 = hinge.particle(0, 3);
        double ex = p.x(e1) - p.x(e0), ez = p.z(e1) - p.z(e0), edge = Math.hypot(ex, ez);
        // The warp turned in the plane so the diagonal edge makes the angle asked with it.
        double turn = Math.atan2(ez, ex) - edgeAngle;
        double[] warp = {Math.cos(turn), 0, Math.sin(turn)};
        blocks = FabricConstraints.build(p, square.triangles(), warp, fabric.membrane, fabric.bendingStiffness, false, true);
        for (ConstraintBlock b : blocks) if (b instanceof DihedralBlock) hinge = (DihedralBlock) b;
        double theta = curvature * hinge.restAreaOverEdgeSquared(0) * edge;
        // Turn o1 about the edge (the edge lies in y = 0): its offset from e0 rotated about the edge's direction.
        double ax = ex / edge, az = ez / edge, rx = p.x(o1) - p.x(e0), rz = p.z(o1) - p.z(e0), d = ax * rx + az * rz;
        double px = rx - d * ax, pz = rz - d * az;  // the part square to the edge, in the plane
        double c = Math.cos(theta), s = Math.sin(theta);
        // a × (px, 0, pz) = (0, az·px − ax·pz, 0)
        p.setPosition(o1, p.x(e0) + d * ax + c * px, p.y(e0) + s * (az * px - ax * pz), p.z(e0) + d * az + c * pz);
        if (curve) new MeasuredBending(blocks, restOf(square), square.triangles(), warp, fabric.bendingCurve).afterStep(p, 0.01);
        return Math.abs(hinge.evaluate(0, p)) / (hinge.compliance(0) * edge);
    }

    private static Particles restOf(Cloth square) {
        return new ClothBuilder().resolution(2, 2).size(0.02, 0.02).plane(ClothBuilder.Plane.HORIZONTAL).arealDensity(0.3).build().particles();
    }

    @Override public List<String> run(Context ctx) throws IOException {
        Fabric denim = FabricCatalogue.named("denim");
        double[] angles = {0, Math.PI / 4, Math.PI / 2};
        Table t = new Table(name(), "edge", "curvature_per_m", "moment_measured_uNm_per_m", "moment_linear_uNm_per_m");
        Plot plot = new Plot("Denim hinges bent: measured curve (solid) against the linear model (grey)",
                "curvature, 1/m", "moment per unit length, µN·m/m", false, false);
        List<String> out = new ArrayList<>();
        java.awt.Color[] colours = {new java.awt.Color(0x1f77b4), new java.awt.Color(0xd62728), new java.awt.Color(0x2ca02c)};
        for (int k = 0; k < 3; k++) {
            List<Double> xs = new ArrayList<>(), measured = new ArrayList<>(), linear = new ArrayList<>();
            for (int curvature = 0; curvature <= 50; curvature++) {
                double mm = 1e6 * moment(denim, curvature, angles[k], true), ml = 1e6 * moment(denim, curvature, angles[k], false);
                t.add(NAMES[k], curvature, mm, ml);
                xs.add((double) curvature);
                measured.add(mm);
                linear.add(ml);
            }
            plot.line(NAMES[k] + ", measured", xs, measured, colours[k]).line(NAMES[k] + ", linear", xs, linear, java.awt.Color.GRAY);
            out.add(String.format("%s: at 10 /m measured %.0f µN·m/m, linear %.0f (%+.0f %%); at 30 /m %.0f, %.0f (%+.0f %%); at 45 /m %.0f, %.0f (%+.0f %%)",
                    NAMES[k], measured.get(10), linear.get(10), 100 * (linear.get(10) / measured.get(10) - 1), measured.get(30), linear.get(30),
                    100 * (linear.get(30) / measured.get(30) - 1), measured.get(45), linear.get(45), 100 * (linear.get(45) / measured.get(45) - 1)));
        }
        ctx.save(t);
        ctx.save(plot, name());
        return out;
    }
}
