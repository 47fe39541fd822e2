package xpbdcloth.fabric;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.EnclosedGas;
import xpbdcloth.engine.MeshClothBuilder;
import xpbdcloth.engine.OrthotropicMaterial;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SolverSettings;
import xpbdcloth.mesh.Balloon;
import xpbdcloth.mesh.ClothMesh;

/**
 * A balloon of a stretchy isotropic fabric blown up by a gas comes to rest where its membrane's tension holds
 * the pressure, as Laplace's law for a spherical membrane says: Δp = 2T/r, with the gas's Δp = nRT/V − p₀ and
 * the tension of a Saint Venant–Kirchhoff membrane stretched equally both ways by λ = r/r₀, T = Y(λ² − 1)/(2(1 − ν))
 * (its second Piola–Kirchhoff stress Y·E/(1 − ν) at Green strain E = (λ² − 1)/2, which for an equal stretch both
 * ways is also the tension per length of the stretched sheet).
 */
class BalloonTest {
    static final double REST_RADIUS = 0.1, MODULUS = 500, POISSON = 0.3;

    /** The radius where nRT/V − p₀ = 2T(r)/r, by bisection. */
    static double laplaceRadius(double nRT, double ambient) {
        double lo = REST_RADIUS, hi = 10 * REST_RADIUS;
        for (int k = 0; k < 200; k++) {
            double r = 0.5 * (lo + hi), lambda = r / REST_RADIUS;
            double gauge = nRT / (4 * Math.PI / 3 * r * r * r) - ambient, tension = MODULUS * (lambda * lambda - 1) / (2 * (1 - POISSON));
            if (gauge > 2 * tension / r) lo = r; else hi = r;
        }
        return 0.5 * (lo + hi);
    }

    /** The balloon at rest: its volume and the pressure the solver applied. */
    static double[] inflate(double nRT, double ambient, int slices) {
        ClothMesh mesh = Balloon.generate(REST_RADIUS, slices, slices / 2);
        Cloth cloth = new MeshClothBuilder(mesh).arealDensity(0.2).build();
        Particles p = cloth.particles();
        Simulation sim = new Simulation(p, new SolverSettings().withMode(ConstraintMode.XPBD).withGravity(0, 0, 0)
                .withIterations(40).withSubsteps(20).withTimestep(0.01).withDamping(5));
        OrthotropicMaterial rubbery = new OrthotropicMaterial(MODULUS, MODULUS, POISSON, MODULUS / (2 * (1 + POISSON)));
        double[] warp = FabricConstraints.warpFromTextureCoordinates(p, cloth.triangles(), mesh.triangleUVs());
        for (ConstraintBlock b : FabricConstraints.build(p, cloth.triangles(), warp, rubbery, 1e-7, false)) sim.add(b);
        EnclosedGas gas = EnclosedGas.ofGas(p, cloth.triangles(), nRT, ambient);
        sim.add(gas);
        for (int s = 0; s < 80; s++) sim.step();
        return new double[] {gas.volume(p), gas.pressure()};
    }

    @Test
    void aBalloonInflatesToTheRadiusLaplacesLawGives() {
        // In a vacuum, so the membrane alone holds the gas (against air the volume is nearly nRT/p₀ whatever the membrane).
        double nRT = 18.96, r = laplaceRadius(nRT, 0), expected = 4 * Math.PI / 3 * r * r * r;
        double[] rest = inflate(nRT, 0, 24);
        System.out.printf("volume %.5g m³ against Laplace's %.5g (r %.4f against r0 %.4f); pV %.5g J against nRT %.5g%n",
                rest[0], expected, Math.cbrt(3 * rest[0] / (4 * Math.PI)), REST_RADIUS, rest[0] * rest[1], nRT);
        assertTrue(r > 1.15 * REST_RADIUS, "the case must stretch the membrane: r " + r);
        assertEquals(expected, rest[0], 0.05 * expected);
        assertEquals(nRT, rest[0] * rest[1], 0.01 * nRT);
    }
}
