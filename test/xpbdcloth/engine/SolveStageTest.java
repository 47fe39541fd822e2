package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/** The solve stage and the collide stage: what is kept between steps, and what is found anew. */
class SolveStageTest {

    static Simulation cloth(SolverType type) {
        return new ClothBuilder().resolution(16, 16).size(0.6, 0.6).arealDensity(0.2).pinTopCorners()
                .family(ConstraintFamily.STRUCTURAL, 1, 1e-6).build()
                .simulation(new SolverSettings().withSolver(type).withIterations(2).withSubsteps(2));
    }

    /**
     * Grabbing a particle (attach, drag, release) changes the attachments, not the cloth: the global
     * solver and its multigrid hierarchy, built from the cloth's constraints, are kept (one setup), and
     * its setup time stays the first one's.
     */
    @Test
    void grabbingKeepsTheGlobalSolverAndItsMultigrid() {
        Simulation sim = cloth(SolverType.MULTIGRID_PCG);
        sim.step();
        StepProfile profile = sim.profile();
        assertEquals(1, profile.globalSetups());
        assertTrue(profile.multigridLevels() > 1, "a multigrid hierarchy: " + profile.multigridLevels() + " levels");
        long setupNanos = profile.multigridSetupNanos();
        for (int grab = 0; grab < 3; grab++) {
            AttachmentConstraint a = sim.attach(200, 0.1, 1.2, 0.2);
            sim.step();
            sim.release(a);
            sim.step();
        }
        assertEquals(1, profile.globalSetups(), "the same solver after three grabs");
        assertEquals(setupNanos, profile.multigridSetupNanos(), "no new multigrid setup");
        assertTrue(Metrics.allFinite(sim.particles()));
    }

    /** Back on Gauss–Seidel, no CG count lingers (the HUD showed the last global solve's). */
    @Test
    void gaussSeidelReportsNoConjugateGradientIterations() {
        Simulation sim = cloth(SolverType.JACOBI_PCG);
        sim.step();
        assertTrue(sim.profile().lastPcgIterations() > 0);
        sim.settings(sim.settings().withSolver(SolverType.GAUSS_SEIDEL));
        sim.step();
        assertEquals(0, sim.profile().lastPcgIterations());
    }

    /** Adding a cloth constraint does change the system: then the solver is rebuilt. */
    @Test
    void changingTheClothRebuildsTheGlobalSolver() {
        Simulation sim = cloth(SolverType.JACOBI_PCG);
        sim.step();
        assertEquals(1, sim.profile().globalSetups());
        sim.add(DistanceConstraint.between(sim.particles(), 0, 17));
        sim.step();
        assertEquals(2, sim.profile().globalSetups());
    }

    /**
     * Contacts are transient: a sphere under a 16×16 cloth finds only the particles within its reach
     * (none before the cloth arrives, a cap once it hangs over the sphere), not 256 permanent contacts.
     * Reach grows with a particle's own motion, so while the unbent cloth whips around the sphere almost
     * every particle is a candidate for a moment (250 of 256 at 0.7 s); once it hangs, only the cap.
     */
    @Test
    void contactsAreFoundEachSubstep() {
        Simulation sim = new ClothBuilder().resolution(16, 16).size(0.8, 0.8).plane(ClothBuilder.Plane.HORIZONTAL)
                .origin(0, 1.0, 0).arealDensity(0.2).family(ConstraintFamily.STRUCTURAL, 1, 1e-6).build()
                .simulation(new SolverSettings().withIterations(2).withSubsteps(4));
        sim.add(new Sphere(SpherePath.fixed(0, 0.5, 0), 0.1, 0.01, 0.5, 0.4));
        sim.step();
        assertEquals(0, sim.profile().contactCount(), "the cloth starts 0.4 m above the sphere's top");
        for (int s = 0; s < 300; s++) sim.step();
        int hanging = sim.profile().contactCount();
        System.out.println("contacts of the hanging cloth: " + hanging + " of 256 particles");
        assertTrue(hanging > 0 && hanging < 256 / 2, "a cap of the cloth, not all of it: " + hanging);
        for (int i = 0; i < sim.particles().count(); i++) {
            double dx = sim.particles().x(i), dy = sim.particles().y(i) - 0.5, dz = sim.particles().z(i);
            assertTrue(Math.sqrt(dx * dx + dy * dy + dz * dz) > 0.11 - 1e-9, "particle " + i + " outside the sphere and its margin");
        }
    }
}
