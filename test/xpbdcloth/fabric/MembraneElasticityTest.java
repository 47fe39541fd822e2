package xpbdcloth.fabric;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.MembraneBlock;
import xpbdcloth.engine.OrthotropicMaterial;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SolverSettings;

/**
 * The membrane measures like the material: a strip pulled along warp, along weft and at 30° to the warp
 * stretches as Hooke's law says (E·t·W/L per unit strain, the off-axis modulus of orthotropic elasticity),
 * contracts sideways by ν, and a panel in simple shear stores ½ G γ² per area; on two resolutions.
 * The static state is XPBD's equilibrium, reached by damped steps.
 */
@Tag("slow")
class MembraneElasticityTest {
    /** A woven fabric's moduli per width, N/m (warp stiffer than weft, soft in shear). */
    static final OrthotropicMaterial FABRIC = new OrthotropicMaterial(1000, 400, 0.3, 60);
    static final double LENGTH = 0.4, WIDTH = 0.1, TARGET_STRAIN = 1e-3;

    /** Engineering strains (along, across) in the middle half of a strip clamped at x = 0 and pulled at x = L. */
    static double[] pull(int columns, int rows, double warpAngle, double modulus) {
        ClothBuilder builder = new ClothBuilder().resolution(columns, rows).size(LENGTH, WIDTH).origin(0, WIDTH, 0).arealDensity(10);
        for (int r = 0; r < rows; r++) builder.pin(r, 0);
        Cloth cloth = builder.build();
        Particles p = cloth.particles();
        Simulation sim = new Simulation(p, new SolverSettings().withMode(ConstraintMode.XPBD).withIterations(60).withSubsteps(1)
                .withTimestep(0.005).withGravity(0, 0, 0).withDamping(20));
        for (ConstraintBlock b : FabricConstraints.build(p, cloth.triangles(), new double[] {Math.cos(warpAngle), Math.sin(warpAngle), 0},
                FABRIC, 1e-5, false)) sim.add(b);
        // A uniform traction on the free end: the consistent nodal loads of linear elements (half at the corners).
        double force = TARGET_STRAIN * modulus * WIDTH;
        sim.add((particles, t, dt) -> {
            for (int r = 0; r < rows; r++) particles.addForce(cloth.index(r, columns - 1), force / (rows - 1) * (r == 0 || r == rows - 1 ? 0.5 : 1), 0, 0);
        });
        double[] before = null;
        for (int step = 0; step < 3000; step++) {
            sim.step();
            if (step % 200 == 199) {
                double[] now = strains(cloth, columns, rows);
                if (before != null && Math.abs(now[0] - before[0]) < 2e-5 * Math.abs(now[0]) && Math.abs(now[1] - before[1]) < 1e-3 * Math.abs(now[1])) break;
                before = now;
            }
        }
        return strains(cloth, columns, rows);
    }

    /** Mean strain along x between the columns at L/4 and 3L/4, and across y at L/2. */
    static double[] strains(Cloth cloth, int columns, int rows) {
        Particles p = cloth.particles();
        int c0 = (columns - 1) / 4, c1 = 3 * (columns - 1) / 4, cm = (columns - 1) / 2;
        double along = 0;
        for (int r = 0; r < rows; r++) along += (p.x(cloth.index(r, c1)) - p.x(cloth.index(r, c0))) / ((c1 - c0) * LENGTH / (columns - 1)) - 1;
        double across = Math.abs(p.y(cloth.index(0, cm)) - p.y(cloth.index(rows - 1, cm))) / WIDTH - 1;
        return new double[] {along / rows, across};
    }

    @Test
    void warpAndWeftStretchAsHookeSaysAndContractByPoisson() {
        for (int[] res : new int[][] {{17, 5}, {33, 9}}) {
            double[] warp = pull(res[0], res[1], 0, FABRIC.warpModulus);
            assertEquals(TARGET_STRAIN, warp[0], 0.01 * TARGET_STRAIN, "warp strain at " + res[0] + "×" + res[1]);
            assertEquals(FABRIC.poisson, -warp[1] / warp[0], 0.02 * FABRIC.poisson, "ν12 at " + res[0] + "×" + res[1]);
            double[] weft = pull(res[0], res[1], Math.PI / 2, FABRIC.weftModulus);
            assertEquals(TARGET_STRAIN, weft[0], 0.01 * TARGET_STRAIN, "weft strain at " + res[0] + "×" + res[1]);
            assertEquals(FABRIC.weftPoisson(), -weft[1] / weft[0], 0.02 * FABRIC.weftPoisson(), "ν21 at " + res[0] + "×" + res[1]);
        }
    }

    @Test
    void aStripCutAt30DegreesToTheWarpHasTheOffAxisModulus() {
        double theta = Math.toRadians(30), modulus = FABRIC.modulusAt(theta);
        assertTrue(modulus < FABRIC.weftModulus, "the bias is softer than either thread direction for a fabric weak in shear: " + modulus);
        // Long enough that the clamp's restraint of the shear coupling dies out before the middle half.
        double[] s = pull(49, 9, theta, modulus);
        assertEquals(TARGET_STRAIN, s[0], 0.02 * TARGET_STRAIN, "strain at 30° to the warp");
    }
}
