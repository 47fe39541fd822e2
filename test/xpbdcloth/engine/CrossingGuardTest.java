package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;
import xpbdcloth.mesh.TriangleIntersections;

/**
 * The continuous triangle guard: no substep makes the cloth pass through itself, by a vertex through a face
 * or by an edge through an edge, however fast, where particle pairs alone let it through.
 */
class CrossingGuardTest {

    /** Two triangles of one cloth: A fixed in the plane z = 0, B thrown at it along −z at the given speed. */
    static Simulation twoTriangles(double[] a, double[] b, double speed, boolean guarded) {
        Particles p = new Particles(6);
        for (int i = 0; i < 3; i++) {
            p.setPosition(i, a[3 * i], a[3 * i + 1], a[3 * i + 2]);
            p.pin(i);
            p.setPosition(3 + i, b[3 * i], b[3 * i + 1], b[3 * i + 2]);
            p.setVelocity(3 + i, 0, 0, -speed);
        }
        Simulation sim = new Simulation(p, new SolverSettings().withSubsteps(2).withGravity(0, 0, 0));
        int[] triangles = {0, 1, 2, 3, 4, 5};
        sim.selfCollision(new SelfCollision(p.positions().clone(), guarded ? triangles : null, 1e-3, 0, 0));
        return sim;
    }

    /** The lower z of B's first edge (particles 3 and 4) after a second, and the most crossing triangle pairs in any step. */
    static double[] throwB(double[] a, double[] b, boolean guarded) {
        Simulation sim = twoTriangles(a, b, 10, guarded);
        int most = 0;
        for (int step = 0; step < 50; step++) {
            sim.step(0.02);
            most = Math.max(most, TriangleIntersections.count(sim.particles().positions(), new int[] {0, 1, 2, 3, 4, 5}));
        }
        Particles p = sim.particles();
        return new double[] {Math.min(p.z(3), p.z(4)), most};
    }

    /** B is a small triangle above A's middle: its vertices would pass through A's face (vertex–face). */
    @Test
    void aTriangleThrownAtAnotherFaceOnStopsAboveIt() {
        assertStopsAbove(new double[] {-0.1, -0.1, 0.05, 0.1, -0.1, 0.05, 0, 0.1, 0.05});
    }

    /**
     * B is a sliver whose long edge spans A but none of whose vertices is over A, and none of A's vertices
     * under B: only edges meet edges (and edges faces), so a vertex–face test alone would let it through.
     */
    @Test
    void anEdgeSweptAcrossAnotherEdgeStopsAtIt() {
        assertStopsAbove(new double[] {-2, -0.5, 0.05, 2, -0.5, 0.05, 2, -0.6, 0.05});
    }

    /** B thrown at the fixed A = (−1, −1, 0), (1, −1, 0), (0, 1, 0) flies through without the guard and stays above A with it, no pair crossing. */
    static void assertStopsAbove(double[] b) {
        double[] a = {-1, -1, 0, 1, -1, 0, 0, 1, 0};
        double[] off = throwB(a, b, false), on = throwB(a, b, true);
        assertTrue(off[0] < -1, "without the guard B passes through A at 10 m/s (0.2 m a step): its first edge at z " + off[0]);
        assertTrue(on[0] > 0, "with it B stays on its side of A: z " + on[0]);
        assertEquals(0, on[1], "no crossing pair in any step");
    }

    /**
     * A 24² cloth whose rows are pushed different ways so that it collapses onto itself in layers on a floor,
     * with a thickness a tenth of its spacing: particle pairs alone let its triangles pass through each other
     * between the particles (189 crossing pairs in a step); with the guard no pair of triangles crosses in any
     * step, layers pressed flat on the floor included, and every event is resolved within the passes.
     */
    @Test
    void aClothCollapsingOntoItselfNeverCrossesItself() {
        int off = mostCrossings(false), on = mostCrossings(true);
        System.out.println("collapsing cloth: most crossing pairs in a step " + off + " without the guard, " + on + " with");
        assertTrue(off > 0, "particle pairs alone let a thin cloth pass through itself");
        assertEquals(0, on, "with the guard no triangle pair crosses in any step");
    }

    static int mostCrossings(boolean guarded) {
        Cloth c = collapsingCloth();
        Simulation sim = collapse(c, 1, guarded);
        int most = 0;
        for (int step = 0; step < 75; step++) {
            sim.step();
            most = Math.max(most, TriangleIntersections.count(c.particles().positions(), c.triangles()));
        }
        if (guarded) assertEquals(0, sim.selfCollision().guard().unresolved(), "every event resolved within the passes");
        return most;
    }

    static final int N = 24;

    /** Bytes the caller's thread allocates per step of sim, the smaller over two windows of 20 steps (as AllocationTest counts). */
    static double leastBytesPerStep(Simulation sim) {
        com.sun.management.ThreadMXBean bean = (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        double perStep = Double.MAX_VALUE;
        for (int window = 0; window < 2; window++) {
            long before = bean.getCurrentThreadAllocatedBytes();
            for (int step = 0; step < 20; step++) sim.step();
            perStep = Math.min(perStep, (bean.getCurrentThreadAllocatedBytes() - before) / 20.0);
        }
        return perStep;
    }

    /**
     * A cloth whose every particle is thrown 100 m in its own direction within one substep: every feature may
     * meet every other, and listing them all would take memory without bound. The guard lists at most
     * {@link CrossingGuard#MOST_CANDIDATES} per feature and, past that, puts the whole substep back: every
     * particle ends exactly where it began, at rest, and the cloth is uncrossed.
     */
    @Test
    void aClothThrownAcrossItselfWholesaleIsPutBackWhole() {
        Cloth c = new ClothBuilder().resolution(40, 40).size(1, 1).origin(0, 1, 0).arealDensity(0.2).family(ConstraintFamily.STRUCTURAL, 1, 0).build();
        Particles p = c.particles();
        Simulation sim = c.simulation(new SolverSettings().withIterations(1).withSubsteps(1).withGravity(0, 0, 0));
        sim.selfCollision(new SelfCollision(p.positions().clone(), c.triangles(), 1e-3, 0, 0));
        double[] before = p.positions().clone();
        java.util.Random r = new java.util.Random(5);
        for (int i = 0; i < p.count(); i++) p.setVelocity(i, 5000 * r.nextGaussian(), 5000 * r.nextGaussian(), 5000 * r.nextGaussian());
        sim.step(0.02);
        assertEquals(1, sim.selfCollision().guard().overloads(), "the substep put back whole");
        assertArrayEquals(before, p.positions(), 0, "every particle where it began");
        for (int i = 0; i < p.count(); i++) assertEquals(0, Math.abs(p.vx(i)) + Math.abs(p.vy(i)) + Math.abs(p.vz(i)), 0, "particle " + i + " at rest");
        assertEquals(0, TriangleIntersections.count(p.positions(), c.triangles()));
    }

    static Cloth collapsingCloth() {
        return new ClothBuilder().resolution(N, N).size(1, 1).origin(0, 1.02, 0).arealDensity(0.2)
                .family(ConstraintFamily.STRUCTURAL, 1, 1e-6).family(ConstraintFamily.SHEAR, 0.5, 1e-3).family(ConstraintFamily.BEND, 0.1, 1e-2).build();
    }

    /** Cloth c on a floor with a thickness a tenth of its spacing, its rows pushed along z by 0.6 sin(5y) m/s, so it collapses in layers. */
    static Simulation collapse(Cloth c, int threads, boolean guarded) {
        Simulation sim = c.simulation(new SolverSettings().withIterations(2).withSubsteps(5).withThreads(threads));
        sim.add(Plane.floor(0, 0.005, 0.6, 0.45));
        Particles p = c.particles();
        sim.selfCollision(new SelfCollision(p.positions().clone(), guarded ? c.triangles() : null, 0.1 / (N - 1), 0.3, 0.2));
        for (int i = 0; i < p.count(); i++) p.setVelocity(i, 0, 0, 0.6 * Math.sin(5 * p.y(i)));
        return sim;
    }

    /**
     * The candidate lists kept across substeps lose nothing: the collapsing cloth guarded with lists made with
     * no skin (made again whenever a particle moves out of its last motion's box), the default skin, and a skin
     * of two edges (long lists, seldom made) ends bit for bit in the same place after 75 steps, on one thread
     * and on two (each against itself: Gauss–Seidel sweeps a coloured order on two).
     */
    @Test
    void whatTheGuardFindsDoesNotDependOnHowItsCandidatesAreKept() {
        for (int threads = 1; threads <= 2; threads++) {
            double[] reference = null;
            for (double skin : new double[] {CrossingGuard.SKIN_EDGES, 0, 2}) {
                Cloth c = collapsingCloth();
                Simulation sim = collapse(c, threads, true);
                sim.selfCollision().guard().skinEdges(skin);
                for (int step = 0; step < 75; step++) sim.step();
                sim.close();
                assertTrue(sim.selfCollision().guard().events() > 0, "the guard had events to cut");
                if (reference == null) reference = c.particles().positions().clone();
                else assertArrayEquals(reference, c.particles().positions(), 0.0, "skin " + skin + " edges, " + threads + " thread(s)");
            }
        }
    }

    /**
     * The lists hold while the cloth moves as a whole: a 16² cloth falling freely for a second (4.9 m, some 300
     * skins) is listed at most twice, since no two of its features move against each other (the second time
     * only because a substep's own motion, which each reach spans, grows with the speed: 3.9 cm by the end,
     * against a skin of 1.7 cm); the same cloth pinned at one corner swings, its parts moving against each
     * other, and is listed again and again as they pass the skin.
     */
    @Test
    void aClothFallingAsAWholeKeepsItsLists() {
        for (boolean pinned : new boolean[] {false, true}) {
            Cloth c = new ClothBuilder().resolution(16, 16).size(1, 1).origin(0, 1, 0).arealDensity(0.2).family(ConstraintFamily.STRUCTURAL, 1, 0).build();
            Particles p = c.particles();
            if (pinned) p.pin(0);
            Simulation sim = c.simulation(new SolverSettings().withIterations(2).withSubsteps(5));
            sim.selfCollision(new SelfCollision(p.positions().clone(), c.triangles(), 1e-3, 0, 0));
            double top = p.y(p.count() - 1);
            for (int step = 0; step < 50; step++) sim.step(0.02);
            long listings = sim.selfCollision().guard().listings();
            if (!pinned) {
                assertEquals(-4.9, p.y(p.count() - 1) - top, 0.1, "fell freely");
                assertTrue(listings <= 2, "listed at most twice in free fall: " + listings + " times");
            } else assertTrue(listings > 10, "a swinging cloth is listed again: " + listings + " times");
        }
    }

    /**
     * Steps of a guarded cloth allocate nothing once its arrays have grown: the collapsing cloth, after its
     * first 40 steps, counted over two windows of 20 (the smaller taken, as AllocationTest does), on one
     * thread and on two (the caller's thread is counted; the shares are made once).
     */
    @Test
    void aGuardedClothStepsWithoutAllocating() {
        for (int threads = 1; threads <= 2; threads++) {
            Simulation sim = collapse(collapsingCloth(), threads, true);
            for (int step = 0; step < 40; step++) sim.step();
            double perStep = leastBytesPerStep(sim);
            sim.close();
            assertTrue(sim.selfCollision().guard().events() > 0, "the guard had events to cut");
            assertTrue(perStep < 16, threads + " thread(s): " + perStep + " bytes a step");
        }
    }
}
