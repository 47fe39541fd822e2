package xpbdcloth.experiments;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.MembraneBlock;
import xpbdcloth.engine.Particles;
import xpbdcloth.fabric.Fabric;
import xpbdcloth.fabric.FabricConstraints;
import xpbdcloth.fabric.MeasuredStiffening;
import xpbdcloth.scene.FabricCatalogue;

/**
 * Experiment 14: what the measured stretching curve changes. Denim's membrane is pulled along the warp, the bias
 * and the weft by 0 to 20 % (a wide strip: held at its width), and its force per unit width is read from the
 * engine's own energy, with the curve ({@link MeasuredStiffening}) and as the linear fabric (the curve's slope at
 * zero strain, what the catalogue was before).
 */
final class MeasuredStretching implements Experiment {
    static final double[] ANGLES = {0, 45, 90};
    static final String[] NAMES = {"warp", "bias", "weft"};

    @Override public String name() { return "measured-stretching"; }

    @Override public String claim() { return "the catalogue's fabrics stiffen with strain as measured; the linear model is softer beyond a few per cent"; }

    /**
     * The force per unit width (N/m) of a 5 × 5 sheet of the fabric stretched uniformly by e along φ degrees to the
     * warp and held at its width: d(U/A)/de from the membrane's energy, the stiffness (with the curve) taken at that
     * stretch and held, as a step holds it.
     */
    static double force(Fabric fabric, double e, double phi, boolean curve) {
        Cloth sheet = new ClothBuilder().resolution(5, 5).size(0.1, 0.1).plane(ClothBuilder.Plane.HORIZONTAL).arealDensity(0.3).build();
        Particles p = sheet.particles();
        List<ConstraintBlock> blocks = FabricConstraints.build(p, sheet.triangles(), new double[] {1, 0, 0}, fabric.membrane, fabric.bendingStiffness, false);
        MembraneBlock m = (MembraneBlock) blocks.get(0);
        double[] rest = p.positions().clone();
        double dx = Math.cos(Math.toRadians(phi)), dz = Math.sin(Math.toRadians(phi));
        stretch(p, rest, e, dx, dz);
        if (curve) new MeasuredStiffening(blocks, fabric.stretchingCurve).afterStep(p, 0.01);
        double h = 1e-7 * Math.max(e, 1e-3), area = 0;
        for (int t = 0; t < m.triangleCount(); t++) area += m.area(t);
        stretch(p, rest, e + h, dx, dz);
        double up = energy(m, p);
        stretch(p, rest, e - h, dx, dz);
        return (up - energy(m, p)) / (2 * h) / area;
    }

    private static void stretch(Particles p, double[] rest, double e, double dx, double dz) {
        for (int i = 0; i < p.count(); i++) {
            double x = rest[3 * i], y = rest[3 * i + 1], z = rest[3 * i + 2], along = e * (x * dx + z * dz);
            p.setPosition(i, x + along * dx, y, z + along * dz);
        }
    }

    private static double energy(MembraneBlock m, Particles p) {
        double u = 0;
        for (int i = 0; i < m.count(); i++) { double c = m.evaluate(i, p); u += 0.5 * c * c / m.compliance(i); }
        return u;
    }

    @Override public List<String> run(Context ctx) throws IOException {
        Fabric denim = FabricCatalogue.named("denim");
        Table t = new Table(name(), "direction", "strain_percent", "force_measured_N_per_m", "force_linear_N_per_m");
        Plot plot = new Plot("Denim pulled held at its width: measured curve (solid) against the linear model (grey)",
                "strain, %", "force per unit width, N/m", false, false);
        List<String> out = new ArrayList<>();
        java.awt.Color[] colours = {new java.awt.Color(0x1f77b4), new java.awt.Color(0xd62728), new java.awt.Color(0x2ca02c)};
        for (int d = 0; d < 3; d++) {
            List<Double> xs = new ArrayList<>(), measured = new ArrayList<>(), linear = new ArrayList<>();
            for (int percent = 0; percent <= 20; percent++) {
                double e = percent / 100.0, fm = force(denim, e, ANGLES[d], true), fl = force(denim, e, ANGLES[d], false);
                t.add(NAMES[d], percent, fm, fl);
                xs.add((double) percent);
                measured.add(fm);
                linear.add(fl);
            }
            plot.line(NAMES[d] + ", measured", xs, measured, colours[d]).line(NAMES[d] + ", linear", xs, linear, java.awt.Color.GRAY);
            out.add(String.format("%s: at 5 %% measured %.1f N/m, linear %.1f (%+.1f %%); at 10 %% %.1f, %.1f (%+.1f %%); at 20 %% %.1f, %.1f (%+.1f %%)",
                    NAMES[d], measured.get(5), linear.get(5), 100 * (linear.get(5) / measured.get(5) - 1), measured.get(10), linear.get(10),
                    100 * (linear.get(10) / measured.get(10) - 1), measured.get(20), linear.get(20), 100 * (linear.get(20) / measured.get(20) - 1)));
        }
        ctx.save(t);
        ctx.save(plot, name());
        return out;
    }
}
