package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/** The cloth keeps its thickness from itself, conserves momentum doing so, and allocates nothing per step. */
class SelfCollisionTest {
    static final int N = 32;
    static final double SPACING = 1.0 / (N - 1), THICKNESS = 0.5 * SPACING;

    /**
     * A 1 m vertical 32² cloth released just above a floor, its rows pushed sideways by different speeds,
     * so that it collapses onto itself in layers (2 s). Every 5 steps, the closest approach of particles that
     * were more than two spacings apart at rest. Returns it as a fraction of the thickness.
     */
    static double closestNonNeighbours(boolean selfCollision) {
        Cloth c = new ClothBuilder().resolution(N, N).size(1, 1).origin(0, 1.02, 0).arealDensity(0.2)
                .family(ConstraintFamily.STRUCTURAL, 1, 1e-6).family(ConstraintFamily.SHEAR, 0.5, 1e-3).family(ConstraintFamily.BEND, 0.1, 1e-2).build();
        Simulation sim = c.simulation(new SolverSettings().withIterations(2).withSubsteps(10));
        sim.add(Plane.floor(0, 0.005, 0.6, 0.45));
        Particles p = c.particles();
        double[] rest = p.positions().clone();
        if (selfCollision) sim.selfCollision(new SelfCollision(rest, THICKNESS, 0.3, 0.2));
        for (int i = 0; i < p.count(); i++) p.setVelocity(i, 0, 0, 0.3 * Math.sin(3 * p.y(i)));
        double closest = Double.POSITIVE_INFINITY;
        for (int step = 1; step <= 100; step++) {
            sim.step();
            if (step % 5 != 0) continue;
            double[] x = p.positions();
            for (int i = 0; i < p.count(); i++)
                for (int j = i + 1; j < p.count(); j++) {
                    double rx = rest[3 * i] - rest[3 * j], ry = rest[3 * i + 1] - rest[3 * j + 1], rz = rest[3 * i + 2] - rest[3 * j + 2];
                    if (rx * rx + ry * ry + rz * rz < 4 * SPACING * SPACING) continue;
                    double dx = x[3 * i] - x[3 * j], dy = x[3 * i + 1] - x[3 * j + 1], dz = x[3 * i + 2] - x[3 * j + 2];
                    closest = Math.min(closest, Math.sqrt(dx * dx + dy * dy + dz * dz));
                }
        }
        return closest / THICKNESS;
    }

    @Test
    void aClothCollapsingOntoItselfKeepsItsThickness() {
        double off = closestNonNeighbours(false), on = closestNonNeighbours(true);
        System.out.printf("cloth collapsing onto itself: closest non-neighbours %.2f t without self-collision, %.2f t with%n", off, on);
        assertTrue(off < 0.5, "without self-collision the layers pass through each other: " + off + " t");
        assertTrue(on > 0.95, "with it they keep the thickness: " + on + " t");
    }

    /**
     * The pairs are listed once and used while no particle has drifted half the skin (the thickness) from
     * where the list saw it: a cloth settling on a floor rebuilds its hash rarely, and its layers still never
     * come closer than the thickness (the collapsing cloth above, listed the same way).
     */
    @Test
    void theListIsKeptWhileNoParticleDriftsHalfTheSkin() {
        Cloth c = new ClothBuilder().resolution(24, 24).size(1, 1).plane(ClothBuilder.Plane.HORIZONTAL).origin(0, 0.3, 0).arealDensity(0.2)
                .family(ConstraintFamily.STRUCTURAL, 1, 1e-6).build();
        Simulation sim = c.simulation(new SolverSettings().withIterations(2).withSubsteps(10).withDamping(2));
        sim.add(Plane.floor(0, 0.005, 0.6, 0.45));
        SelfCollision self = new SelfCollision(c.particles().positions().clone(), 0.02, 0.3, 0.2);
        sim.selfCollision(self);
        for (int s = 0; s < 150; s++) sim.step();
        long settled = self.builds();
        for (int s = 0; s < 50; s++) sim.step();
        // 1500 substeps falling and settling, then 500 at rest.
        assertTrue(settled < 300, "hash builds while falling onto the floor and settling: " + settled + " in 1500 substeps");
        assertEquals(settled, self.builds(), "no build at rest");
    }

    /** Two free particles meeting head on: pushed apart to the thickness, total momentum unchanged. */
    @Test
    void aPairIsPushedApartWithoutChangingMomentum() {
        Particles p = new Particles(2);
        p.setMass(0, 1);
        p.setMass(1, 3);
        p.setPosition(0, -0.05, 0, 0);
        p.setPosition(1, 0.05, 0, 0.001);
        p.setVelocity(0, 2, 0, 0);
        p.setVelocity(1, -1, 0, 0.5);
        double[] rest = {-10, 0, 0, 10, 0, 0}; // far apart at rest: not neighbours
        Simulation sim = new Simulation(p, new SolverSettings().withGravity(0, 0, 0).withIterations(2).withSubsteps(4));
        sim.selfCollision(new SelfCollision(rest, 0.02, 0.5, 0.4));
        double px = 1 * 2 + 3 * -1, pz = 3 * 0.5;
        for (int s = 0; s < 10; s++) {
            sim.step();
            assertEquals(px, p.vx(0) + 3 * p.vx(1), 1e-12, "momentum x");
            assertEquals(pz, p.vz(0) + 3 * p.vz(1), 1e-12, "momentum z");
            double d = Math.hypot(Math.hypot(p.x(0) - p.x(1), p.y(0) - p.y(1)), p.z(0) - p.z(1));
            assertTrue(d >= 0.02 - 1e-12, "apart by the thickness: " + d);
        }
    }

    /**
     * A 60² cloth of 0.3 m falling 0.5 m in its one substep: each particle's reach through its motion spans
     * the whole cloth, where listing every pair (6.5 million) is what ran a 16,590-particle cloth out of
     * memory. The build lists at most {@link SelfCollision#MOST_PAIRS} a particle, the same with two threads
     * as with one, and since no pair is closer than t the cloth falls exactly as free fall says,
     * y = y₀ − g h² after one symplectic Euler substep.
     */
    @Test
    void aClothFallingFarAcrossItselfInOneSubstepListsAtMostTheBound() {
        double[][] ends = new double[2][];
        for (int threads = 1; threads <= 2; threads++) {
            Cloth c = new ClothBuilder().resolution(60, 60).size(0.3, 0.3).plane(ClothBuilder.Plane.HORIZONTAL).origin(0, 1, 0).arealDensity(0.2)
                    .family(ConstraintFamily.STRUCTURAL, 1, 0).build();
            double g = 50, h = 0.1;
            Simulation sim = c.simulation(new SolverSettings().withGravity(0, -g, 0).withTimestep(h).withSubsteps(1).withIterations(2).withThreads(threads));
            Particles p = c.particles();
            double[] start = p.positions().clone();
            SelfCollision self = new SelfCollision(start, 0.2 * 0.3 / 59, 0.3, 0.2);
            sim.selfCollision(self);
            sim.step();
            assertEquals(1, self.overloads(), "builds past the bound");
            assertTrue(self.pairCount() <= SelfCollision.MOST_PAIRS * p.count(), "pairs listed: " + self.pairCount());
            for (int i = 0; i < p.count(); i++) {
                assertEquals(start[3 * i + 1] - g * h * h, p.y(i), 1e-12, "particle " + i + " falls freely");
                assertEquals(start[3 * i], p.x(i), 1e-12, "particle " + i + " x");
            }
            ends[threads - 1] = p.positions().clone();
        }
        assertArrayEquals(ends[0], ends[1], "one thread and two, bit for bit");
    }

    /**
     * Two 40² layers of free particles 0.5 t apart (far apart at rest, so they collide), moving together at
     * 100 m/s: a substep's motion of 1 m reaches every particle, so the build is past the bound and lists
     * again without the motion. The pairs already too close are still in that list: every particle ends
     * exactly t from its partner across the layers, pushed apart by equal masses, the layers' common
     * velocity unchanged.
     */
    @Test
    void aBuildPastTheBoundStillPushesApartWhatIsAlreadyTooClose() {
        final int side = 40, layer = side * side;
        final double spacing = 0.01, t = 0.5 * spacing, v = -100;
        Particles p = new Particles(2 * layer);
        double[] rest = new double[6 * layer];
        for (int k = 0; k < 2 * layer; k++) {
            int i = k % layer, up = k / layer;
            p.setMass(k, 1e-3);
            p.setPosition(k, spacing * (i % side), up * 0.5 * t, spacing * (i / side));
            p.setVelocity(k, 0, v, 0);
            rest[3 * k] = spacing * (i % side);
            rest[3 * k + 1] = 10 * up;
            rest[3 * k + 2] = spacing * (i / side);
        }
        Simulation sim = new Simulation(p, new SolverSettings().withGravity(0, 0, 0).withTimestep(0.01).withSubsteps(1).withIterations(2));
        SelfCollision self = new SelfCollision(rest, t, 0.3, 0.2);
        sim.selfCollision(self);
        sim.step();
        assertEquals(1, self.overloads(), "builds past the bound");
        assertEquals(layer, self.pairCount(), "the pairs within reach now: one across the layers per particle");
        double[] x = p.positions();
        double sumVy = 0;
        for (int i = 0; i < layer; i++) {
            int a = 3 * i, b = 3 * (i + layer);
            assertEquals(t, x[b + 1] - x[a + 1], 1e-12, "pair " + i + " apart by the thickness");
            assertEquals(-1 - 0.25 * t, x[a + 1], 1e-12, "lower particle " + i + " moved 1 m and half the overlap");
            sumVy += p.vy(i) + p.vy(i + layer);
        }
        assertEquals(2 * layer * v, sumVy, 1e-9, "momentum (equal masses: the sum of velocities)");
    }

    @Test
    void steppingWithSelfCollisionAllocatesNothing() {
        Cloth c = new ClothBuilder().resolution(24, 24).size(1, 1).plane(ClothBuilder.Plane.HORIZONTAL).origin(0, 0.3, 0).arealDensity(0.2)
                .family(ConstraintFamily.STRUCTURAL, 1, 1e-6).build();
        Simulation sim = c.simulation(new SolverSettings().withIterations(2).withSubsteps(10));
        sim.add(Plane.floor(0, 0.005, 0.6, 0.45));
        sim.selfCollision(new SelfCollision(c.particles().positions().clone(), 0.02, 0.3, 0.2));
        for (int s = 0; s < 100; s++) sim.step(); // lying on the floor: the pairs' arrays are as large as they get
        com.sun.management.ThreadMXBean bean = (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        long before = bean.getCurrentThreadAllocatedBytes();
        for (int s = 0; s < 50; s++) sim.step();
        assertEquals(0, bean.getCurrentThreadAllocatedBytes() - before, "bytes allocated in 50 steps");
    }

    @Test
    void badSelfCollisionIsNamed() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new SelfCollision(new double[6], 0, 0.3, 0.2));
        assertTrue(e.getMessage().startsWith("thickness must be"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> new SelfCollision(new double[6], 0.01, -1, 0.2));
        assertTrue(e.getMessage().startsWith("staticFriction"), e.getMessage());
        Simulation sim = new Simulation(new Particles(3), new SolverSettings());
        e = assertThrows(IllegalArgumentException.class, () -> sim.selfCollision(new SelfCollision(new double[6], 0.01, 0.3, 0.2)));
        assertEquals("self-collision was made for 2 particles, the simulation has 3", e.getMessage());
    }
}
