package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/** A fast sphere does not pass through the cloth between two substeps. */
class TunnellingTest {

    /**
     * A 5 cm sphere at 20 m/s through a hanging 32² cloth, dt = 1/60 s, one substep: it jumps 33 cm a
     * step, more than its diameter. After every step, no particle inside the sphere's path (closer to
     * its line of motion than its radius) is behind its centre: the sphere carries what it meets.
     * Returns the number of particles left behind over the run.
     */
    static int particlesLeftBehind(boolean log) {
        Cloth c = new ClothBuilder().resolution(32, 32).size(1, 1).origin(-0.5, 1.6, 0).arealDensity(0.2).pinTopCorners()
                .family(ConstraintFamily.STRUCTURAL, 1, 1e-6).family(ConstraintFamily.SHEAR, 0.5, 1e-3).family(ConstraintFamily.BEND, 0.1, 1e-2).build();
        Simulation sim = c.simulation(new SolverSettings().iterations(2).substeps(1).timestep(1 / 60.0));
        double r = 0.05, margin = 0.005, R = r + margin;
        Sphere s = new Sphere(SpherePath.linear(0.013, 1.1, 0.5, 0, 0, -20), r, margin, 0.5, 0.4);
        sim.add(s);
        Particles p = c.particles();
        int behind = 0, carried = 0;
        for (int step = 0; step < 6; step++) {
            sim.step();
            for (int i = 0; i < p.count(); i++) {
                double lateral = Math.hypot(p.x(i) - s.centreX(), p.y(i) - s.centreY());
                if (lateral >= R) continue;
                if (p.z(i) > s.centreZ() + 1e-9) behind++;
                else carried++;
            }
        }
        if (log) System.out.printf("sphere at 20 m/s through a hanging cloth: %d particle-steps left behind, %d carried%n", behind, carried);
        return behind;
    }

    @Test
    void aFastSphereCarriesTheClothInsteadOfPassingThrough() {
        assertEquals(0, particlesLeftBehind(true));
    }
}
