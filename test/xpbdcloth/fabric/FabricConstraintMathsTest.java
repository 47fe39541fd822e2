package xpbdcloth.fabric;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.DihedralBlock;
import xpbdcloth.engine.MembraneBlock;
import xpbdcloth.engine.OrthotropicMaterial;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.QuadraticBendBlock;

/**
 * The membrane's and the dihedral bend's maths: ∇C against central differences, zero energy under any
 * rigid motion, ½ G γ² per area in simple shear, ½ B κ² per area on a cylinder, and bad input refused.
 */
class FabricConstraintMathsTest {
    static final OrthotropicMaterial FABRIC = MembraneElasticityTest.FABRIC;

    static Cloth sheet(int n, double size) {
        return new ClothBuilder().resolution(n, n).size(size, size).arealDensity(0.2).build();
    }

    /** ½ Σ C²/α over a block: the energy XPBD's equilibrium minimises (J). */
    static double energy(ConstraintBlock b, Particles p) {
        double u = 0;
        for (int i = 0; i < b.count(); i++) { double c = b.evaluate(i, p); u += 0.5 * c * c / b.compliance(i); }
        return u;
    }

    static void moveAll(Particles p, java.util.function.UnaryOperator<double[]> map) {
        for (int i = 0; i < p.count(); i++) {
            double[] q = map.apply(new double[] {p.x(i), p.y(i), p.z(i)});
            p.setPosition(i, q[0], q[1], q[2]);
        }
    }

    @Test
    void gradientsMatchCentralDifferences() {
        Cloth cloth = sheet(5, 0.2);
        Particles p = cloth.particles();
        List<ConstraintBlock> blocks = FabricConstraints.build(p, cloth.triangles(), new double[] {1, 0.4, 0}, FABRIC, 1e-5, false);
        Random r = new Random(7);
        moveAll(p, q -> new double[] {q[0] + 0.01 * r.nextGaussian(), q[1] + 0.01 * r.nextGaussian(), q[2] + 0.01 * r.nextGaussian()});
        double worst = 0;
        for (ConstraintBlock b : blocks) {
            double[] g = new double[3 * b.arity()];
            for (int i = 0; i < b.count(); i++) {
                b.gradient(i, p, g);
                double scale = 0;
                for (double v : g) scale = Math.max(scale, Math.abs(v));
                for (int k = 0; k < b.arity(); k++)
                    for (int c = 0; c < 3; c++) {
                        double[] x = p.positions();
                        int at = 3 * b.particle(i, k) + c;
                        double o = x[at], h = 1e-6;
                        x[at] = o + h; double plus = b.evaluate(i, p);
                        x[at] = o - h; double minus = b.evaluate(i, p);
                        x[at] = o;
                        worst = Math.max(worst, Math.abs((plus - minus) / (2 * h) - g[3 * k + c]) / scale);
                    }
            }
        }
        assertTrue(worst < 1e-6, "largest relative difference between ∇C and central differences: " + worst);
    }

    @Test
    void rigidMotionStoresNoEnergy() {
        Cloth cloth = sheet(6, 0.3);
        Particles p = cloth.particles();
        List<ConstraintBlock> blocks = FabricConstraints.build(p, cloth.triangles(), new double[] {1, 0, 0}, FABRIC, 1e-5, false);
        // A rotation by 50° about (1, 2, 3) and a translation.
        double[] axis = {1 / Math.sqrt(14), 2 / Math.sqrt(14), 3 / Math.sqrt(14)};
        double c = Math.cos(0.87), s = Math.sin(0.87);
        moveAll(p, q -> {
            double d = axis[0] * q[0] + axis[1] * q[1] + axis[2] * q[2];
            double[] cross = {axis[1] * q[2] - axis[2] * q[1], axis[2] * q[0] - axis[0] * q[2], axis[0] * q[1] - axis[1] * q[0]};
            double[] out = new double[3];
            for (int k = 0; k < 3; k++) out[k] = q[k] * c + cross[k] * s + axis[k] * d * (1 - c) + 0.5 * (k + 1);
            return out;
        });
        for (ConstraintBlock b : blocks)
            for (int i = 0; i < b.count(); i++) assertEquals(0, b.evaluate(i, p), 1e-12, b.family() + " constraint " + i + " after a rigid motion");
    }

    @Test
    void simpleShearStoresHalfGGammaSquaredPerArea() {
        for (int n : new int[] {5, 9}) {
            double size = 0.2, gamma = 1e-3;
            Cloth cloth = sheet(n, size);
            Particles p = cloth.particles();
            MembraneBlock m = (MembraneBlock) FabricConstraints.build(p, cloth.triangles(), new double[] {1, 0, 0}, FABRIC, 1e-5, false).get(0);
            moveAll(p, q -> new double[] {q[0] + gamma * q[1], q[1], q[2]});
            double measuredG = 2 * energy(m, p) / (gamma * gamma * size * size);
            assertEquals(FABRIC.shearModulus, measuredG, 0.02 * FABRIC.shearModulus, "G from the energy of simple shear at " + n + "²");
        }
    }

    /**
     * Rolled into a cylinder of curvature κ = 1/r along a row of edges, both hinge models store ½Bκ² per bent
     * area (the patches a flat sheet gets store it in any direction: {@code BendingOnAnyMeshTest}): the
     * quadratic hinges (|C|² = 4 sin²(θ/2), θ²/12 ≈ 2e-4 below θ² here) and the dihedral
     * angles a bent rest would get, on the same hinges.
     */
    @Test
    void aSheetBentIntoACylinderStoresHalfBKappaSquaredPerArea() {
        double bending = 2e-5, radius = 0.5, size = 0.4;
        for (int n : new int[] {17, 33})
            for (int axis = 0; axis < 2; axis++) {
                Cloth cloth = sheet(n, size);
                Particles p = cloth.particles();
                QuadraticBendBlock quadratic = (QuadraticBendBlock) FabricConstraints.hinges(p, cloth.triangles(), bending, false).get(0);
                DihedralBlock dihedral = new DihedralBlock(ConstraintFamily.DIHEDRAL, quadratic.hingeCount());
                for (int u = 0; u < quadratic.hingeCount(); u++)
                    dihedral.addAtCurrentShape(p, quadratic.particle(3 * u, 0), quadratic.particle(3 * u, 1), quadratic.particle(3 * u, 2), quadratic.particle(3 * u, 3), bending);
                final int a = axis;
                // Roll the sheet (in its plane x–y) around an axis along y (a = 0) or x (a = 1).
                moveAll(p, q -> {
                    double along = q[a], angle = along / radius;
                    double[] out = q.clone();
                    out[a] = radius * Math.sin(angle);
                    out[2] = q[2] + radius * (1 - Math.cos(angle));
                    return out;
                });
                // The area the bent (interior) edges span: half a column of squares at each rolled end has none.
                double expected = 0.5 * bending * size * size * (n - 2) / (n - 1) / (radius * radius);
                assertEquals(expected, energy(quadratic, p), 0.02 * expected, "quadratic bending energy of a cylinder at " + n + "², axis " + a);
                assertEquals(expected, energy(dihedral, p), 0.02 * expected, "dihedral bending energy of a cylinder at " + n + "², axis " + a);
            }
    }

    @Test
    void aBendsThreeRowsShareOneComplianceSoItsEnergyDoesNotDependOnTheFrame() {
        Cloth cloth = sheet(9, 0.3);
        Particles p = cloth.particles();
        QuadraticBendBlock quadratic = (QuadraticBendBlock) FabricConstraints.hinges(p, cloth.triangles(), 2e-5, false).get(0);
        // Half the units stiffer, set through their y row alone (as a Constraint view would).
        for (int u = 0; u < quadratic.hingeCount(); u += 2) quadratic.setCompliance(3 * u + 1, 0.25 * quadratic.compliance(3 * u + 1));
        for (int u = 0; u < quadratic.hingeCount(); u++)
            for (int r = 0; r < 3; r++) assertEquals(quadratic.compliance(3 * u + 1), quadratic.compliance(3 * u + r), 0, "row " + r + " of unit " + u);
        moveAll(p, q -> new double[] {0.5 * Math.sin(q[0] / 0.5), q[1], q[2] + 0.5 * (1 - Math.cos(q[0] / 0.5))});
        double bent = energy(quadratic, p);
        // A rotation by 70° about (2, -1, 1): a compliance per axis would weigh the rotated components differently.
        double[] axis = {2 / Math.sqrt(6), -1 / Math.sqrt(6), 1 / Math.sqrt(6)};
        double c = Math.cos(1.22), s = Math.sin(1.22);
        moveAll(p, q -> {
            double d = axis[0] * q[0] + axis[1] * q[1] + axis[2] * q[2];
            double[] cross = {axis[1] * q[2] - axis[2] * q[1], axis[2] * q[0] - axis[0] * q[2], axis[0] * q[1] - axis[1] * q[0]};
            double[] out = new double[3];
            for (int k = 0; k < 3; k++) out[k] = q[k] * c + cross[k] * s + axis[k] * d * (1 - c);
            return out;
        });
        assertTrue(bent > 0, "the cylinder stores bending energy");
        assertEquals(bent, energy(quadratic, p), 1e-10 * bent, "bending energy after rotating the bent sheet");
    }

    @Test
    void badMaterialsAndShapesAreRefusedByName() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new OrthotropicMaterial(100, 400, 0.6, 10));
        assertTrue(e.getMessage().contains("poisson") && e.getMessage().contains("0.6"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> new OrthotropicMaterial(-1, 400, 0.3, 10));
        assertTrue(e.getMessage().contains("warpModulus"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> new OrthotropicMaterial(100, 400, 0.3, 0));
        assertTrue(e.getMessage().contains("shearModulus"), e.getMessage());
        Particles p = new Particles(3);
        p.setPosition(1, 1, 0, 0);
        p.setPosition(2, 2, 0, 0);
        e = assertThrows(IllegalArgumentException.class, () -> new MembraneBlock(ConstraintFamily.MEMBRANE, 1).addTriangle(p, 0, 1, 2, 1, 0, 0, FABRIC));
        assertTrue(e.getMessage().contains("triangle (0, 1, 2)") && e.getMessage().contains("zero area"), e.getMessage());
        p.setPosition(2, 0, 1, 0);
        e = assertThrows(IllegalArgumentException.class, () -> new MembraneBlock(ConstraintFamily.MEMBRANE, 1).addTriangle(p, 0, 1, 2, 0, 0, 1, FABRIC));
        assertTrue(e.getMessage().contains("warp direction"), e.getMessage());
    }
}
