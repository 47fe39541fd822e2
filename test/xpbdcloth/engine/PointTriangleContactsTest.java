package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;
import xpbdcloth.mesh.TriangleIntersections;

/**
 * Point–triangle contacts: a vertex kept the thickness from the faces of other parts of the cloth, on the
 * side it began the substep on, where particle pairs alone let it through between three far-apart particles.
 */
class PointTriangleContactsTest {
    static final double T = 0.01;
    /** A large fixed triangle in z = 0 (particles 0–2) and a small one (3–5) 5 cm above its middle. */
    static final double[] LARGE = {-1, -1, 0, 1, -1, 0, 0, 1, 0}, SMALL = {-0.05, -0.05, 0.05, 0.05, -0.05, 0.05, 0, 0.05, 0.05};
    static final int[] TWO = {0, 1, 2, 3, 4, 5};

    static Simulation smallOnLarge(SolverType solver, boolean pointTriangle) {
        Particles p = new Particles(6);
        for (int i = 0; i < 3; i++) {
            p.setPosition(i, LARGE[3 * i], LARGE[3 * i + 1], LARGE[3 * i + 2]);
            p.pin(i);
            p.setPosition(3 + i, SMALL[3 * i], SMALL[3 * i + 1], SMALL[3 * i + 2]);
        }
        Simulation sim = new Simulation(p, new SolverSettings().withSubsteps(5).withIterations(4).withGravity(0, 0, -9.81).withSolver(solver));
        SelfCollision self = new SelfCollision(p.positions().clone(), T, 0.5, 0.4);
        sim.selfCollision(pointTriangle ? self.withPointTriangle(TWO) : self);
        return sim;
    }

    /**
     * The small triangle falls onto the large one's face, 0.5 m or more from any of its particles. Particle
     * pairs alone let it fall through; with point–triangle contacts it comes to rest the thickness above the
     * face (within a micrometre) under Gauss–Seidel, vertex block descent and Jacobi-PCG alike, and no pair
     * of triangles crosses in any step.
     */
    @Test
    void aSmallTriangleDroppedOnALargeOneRestsAThicknessAboveItsFace() {
        for (SolverType solver : new SolverType[] {SolverType.GAUSS_SEIDEL, SolverType.VERTEX_BLOCK_DESCENT, SolverType.JACOBI_PCG}) {
            Simulation off = smallOnLarge(solver, false), on = smallOnLarge(solver, true);
            int crossed = 0;
            for (int step = 0; step < 100; step++) {
                off.step(0.02);
                on.step(0.02);
                crossed = Math.max(crossed, TriangleIntersections.count(on.particles().positions(), TWO));
            }
            Particles a = off.particles(), b = on.particles();
            for (int i = 3; i < 6; i++) {
                assertTrue(a.z(i) < -1, solver + ": particle pairs alone let it through: z " + a.z(i));
                assertEquals(T, b.z(i), 1e-6, solver + ": with the faces, vertex " + i + " rests a thickness above");
                assertEquals(0, Math.hypot(b.vx(i), Math.hypot(b.vy(i), b.vz(i))), 1e-6, solver + ": at rest");
            }
            assertEquals(0, crossed, solver + ": no crossing pair in any step");
        }
    }

    /** The large triangle free (2 kg a particle) and the small one's first vertex (1 kg) carried into it, each moving; returns the contacts, listed. */
    static PointTriangleContacts carriedInto(Particles p, double startZ, double endZ) {
        for (int i = 0; i < 3; i++) {
            p.setPosition(i, LARGE[3 * i], LARGE[3 * i + 1], LARGE[3 * i + 2]);
            p.setMass(i, 2);
            p.setPosition(3 + i, SMALL[3 * i], SMALL[3 * i + 1], 0.5);
            p.setMass(3 + i, 1);
        }
        p.setPosition(3, 0, -1.0 / 3, startZ); // over the face's centroid: its three corners share a push alike
        System.arraycopy(p.x, 0, p.prev, 0, p.x.length);
        PointTriangleContacts c = new PointTriangleContacts(TWO, p.positions().clone(), null, T, 0, 0);
        p.x[11] = endZ; // the prediction carries vertex 3 from startZ to endZ
        double[] reach = new double[6];
        reach[3] = Math.abs(endZ - startZ); // each particle's motion in the prediction
        c.list(p, reach);
        c.findContacts(p, 1e-3, new ContactSet());
        return c;
    }

    static double[] momentum(Particles p) {
        double[] m = new double[3];
        for (int i = 0; i < p.count(); i++)
            for (int d = 0; d < 3; d++) m[d] += p.mass(i) * p.x[3 * i + d];
        return m;
    }

    /**
     * A vertex that began 2 cm above the face and was carried 5 mm through it is put back on the side it came
     * from, a thickness above the face (not pushed on through), by inverse-mass moves that keep the centre of
     * mass to round-off; one carried deeper than the thickness has crossed and is left alone.
     */
    @Test
    void aVertexCarriedThroughIsPutBackOnItsSideWithMomentumKept() {
        Particles p = new Particles(6);
        PointTriangleContacts c = carriedInto(p, 0.02, -0.005);
        assertEquals(1, c.pairCount(), "vertex 3 against the large face (the small face's own vertices are its neighbours)");
        double[] before = momentum(p);
        c.project(p, 0, 1e-3);
        double face = (p.z(0) + p.z(1) + p.z(2)) / 3; // the face's point under the vertex
        assertEquals(T, p.z(3) - face, 1e-12, "a thickness above the face, on the side it began");
        assertTrue(face < 0, "the face pushed down by its share");
        assertArrayEquals(before, momentum(p), 1e-15, "momentum kept");

        Particles deep = new Particles(6);
        PointTriangleContacts d = carriedInto(deep, 0.02, -0.015);
        double[] x = deep.x.clone();
        d.project(deep, 0, 1e-3);
        assertArrayEquals(x, deep.x, 0, "1.5 thicknesses through: crossed, left alone");
    }

    /**
     * The 24² cloth collapsing onto itself in layers with a thickness a tenth of its spacing (CrossingGuardTest's):
     * particle pairs alone let its triangles pass through each other between the particles; with point–triangle
     * contacts no pair crosses in any step; and a step allocates nothing once the lists have grown.
     */
    @Test
    void aClothCollapsingOntoItselfDoesNotCrossWithPointTriangleContacts() {
        int[] off = collapse(false), on = collapse(true);
        System.out.println("collapsing cloth: most crossing pairs in a step " + off[0] + " with particle pairs, " + on[0] + " with point-triangle contacts (" + on[1] + " listed at most)");
        assertTrue(off[0] > 0, "particle pairs alone let the thin cloth through itself");
        assertEquals(0, on[0], "no triangle pair crosses in any step");
        assertTrue(on[1] > 0, "the layers met: vertices were listed against faces");
    }

    /** The most crossing pairs after any of 75 steps, and the most (vertex, face) pairs listed. */
    static int[] collapse(boolean pointTriangle) {
        Cloth c = CrossingGuardTest.collapsingCloth();
        Simulation sim = CrossingGuardTest.collapse(c, 1, false);
        if (pointTriangle) sim.selfCollision().withPointTriangle(c.triangles());
        int most = 0, listed = 0;
        for (int step = 0; step < 75; step++) {
            sim.step();
            most = Math.max(most, TriangleIntersections.count(c.particles().positions(), c.triangles()));
            listed = Math.max(listed, sim.selfCollision().pointTrianglePairs());
        }
        if (pointTriangle) assertEquals(0, CrossingGuardTest.leastBytesPerStep(sim), 0, "a step allocates nothing");
        return new int[] {most, listed};
    }

    @Test
    void badInputIsNamed() {
        double[] rest = new double[18];
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new PointTriangleContacts(new int[] {0, 1, 6}, rest, null, T, 0, 0));
        assertTrue(e.getMessage().contains("triangles[2]") && e.getMessage().contains("6"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> new PointTriangleContacts(new int[] {0, 1}, rest, null, T, 0, 0));
        assertTrue(e.getMessage().contains("triangles"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> new PointTriangleContacts(TWO, rest, new int[3], T, 0, 0));
        assertTrue(e.getMessage().contains("same"), e.getMessage());
    }
}
