package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;
import xpbdcloth.mesh.TriangleIntersections;

/**
 * The untangler: a cloth found passed through itself at a step's end is put back, each crossed vertex to the
 * side of the face it held when the cloth was last clean, with its centre of mass and its velocities kept.
 */
class CrossingUntanglerTest {
    /** Two 3 × 3 sheets of one mesh, 10 cm apart in x and y: the lower (particles 0–8) at z = 0, the upper (9–17) at z = 0.02. */
    static final int[] TWO_SHEETS = twoSheets();
    static final int LOWER_CENTRE = 4, UPPER_CENTRE = 13;

    static int[] twoSheets() {
        int[] t = new int[2 * 8 * 3];
        int k = 0;
        for (int sheet = 0; sheet < 2; sheet++)
            for (int r = 0; r < 2; r++)
                for (int c = 0; c < 2; c++) {
                    int a = 9 * sheet + 3 * r + c, b = a + 1, d = a + 3, e = a + 4;
                    t[k++] = a; t[k++] = b; t[k++] = e;
                    t[k++] = a; t[k++] = e; t[k++] = d;
                }
        return t;
    }

    /** The lower sheet's particles 2 kg each (or pinned), the upper's 1 kg, all moving at (0.1, −0.2, 0.3) m/s. */
    static Particles sheets(boolean lowerPinned) {
        Particles p = new Particles(18);
        for (int sheet = 0; sheet < 2; sheet++)
            for (int i = 0; i < 9; i++) {
                int n = 9 * sheet + i;
                p.setPosition(n, 0.1 * (i % 3), 0.1 * (i / 3), 0.02 * sheet);
                p.setMass(n, sheet == 0 ? 2 : 1);
                p.setVelocity(n, 0.1, -0.2, 0.3);
                if (sheet == 0 && lowerPinned) p.pin(n);
            }
        return p;
    }

    static CrossingUntangler untangler(Particles clean) {
        CrossingUntangler u = new CrossingUntangler(TWO_SHEETS, clean.positions().clone(), null, 0.01);
        assertEquals(0, u.untangle(clean), "the sheets start apart: nothing to put back, and this is the clean state");
        return u;
    }

    static double[] centreOfMass(Particles p) {
        double[] c = new double[3];
        double m = 0;
        for (int i = 0; i < p.count(); i++) {
            c[0] += p.mass(i) * p.x(i); c[1] += p.mass(i) * p.y(i); c[2] += p.mass(i) * p.z(i);
            m += p.mass(i);
        }
        for (int d = 0; d < 3; d++) c[d] /= m;
        return c;
    }

    /**
     * The upper sheet's middle vertex pushed 3 cm down, through the lower sheet (its four triangles cross the
     * lower sheet's): after untangling nothing crosses, the vertex is above the lower sheet again, the centre
     * of mass has not moved (each contact moves its particles by inverse mass) and no velocity has changed.
     */
    @Test
    void aVertexPushedThroughASheetIsPutBackAboveItWithItsCentreOfMassKept() {
        Particles p = sheets(false);
        CrossingUntangler u = untangler(p);
        p.setPosition(UPPER_CENTRE, 0.1, 0.1, -0.03);
        assertTrue(TriangleIntersections.count(p.positions(), TWO_SHEETS) > 0, "the pushed vertex's triangles cross the lower sheet");
        double[] before = centreOfMass(p), v = p.v.clone();
        assertEquals(0, u.untangle(p), "nothing left crossing");
        assertEquals(0, TriangleIntersections.count(p.positions(), TWO_SHEETS));
        assertTrue(p.z(UPPER_CENTRE) > p.z(LOWER_CENTRE), "the upper sheet's middle is above the lower's again: " + p.z(UPPER_CENTRE) + " against " + p.z(LOWER_CENTRE));
        assertArrayEquals(before, centreOfMass(p), 1e-15, "the centre of mass stays");
        assertArrayEquals(v, p.v, 0, "velocities untouched");
        assertTrue(u.pushed() > 0 && u.tangledSteps() == 1 && u.left() == 0);
    }

    /**
     * Which end of a crossing edge went through comes from the clean state, not from the tangled one: the
     * middle vertex 3 cm below the lower sheet is farther from it than its neighbours 2 cm above, so a guess
     * by the nearer end pulls the neighbours down through the sheet and leaves the middle below it. With the
     * clean state the middle goes back up; without (forgotten) the upper sheet ends below the lower.
     */
    @Test
    void theSideAVertexGoesBackToIsTheOneItHeldWhenTheClothWasClean() {
        for (boolean history : new boolean[] {true, false}) {
            Particles p = sheets(false);
            CrossingUntangler u = untangler(p);
            if (!history) u.forget();
            p.setPosition(UPPER_CENTRE, 0.1, 0.1, -0.03);
            u.untangle(p);
            if (history) assertTrue(p.z(UPPER_CENTRE) > p.z(LOWER_CENTRE), "with history the middle is back above: " + p.z(UPPER_CENTRE));
            else assertTrue(p.z(UPPER_CENTRE) < p.z(LOWER_CENTRE), "without, the nearer ends were moved and the middle stays below: " + p.z(UPPER_CENTRE));
        }
    }

    /** A pinned sheet (inverse mass 0) does not move: the crossed vertex takes the whole correction. */
    @Test
    void aPinnedSheetStaysWhereItsPinsHoldIt() {
        Particles p = sheets(true);
        CrossingUntangler u = untangler(p);
        p.setPosition(UPPER_CENTRE, 0.1, 0.1, -0.03);
        double[] lower = java.util.Arrays.copyOf(p.positions(), 27);
        assertEquals(0, u.untangle(p));
        assertArrayEquals(lower, java.util.Arrays.copyOf(p.positions(), 27), 0, "the pinned sheet unmoved");
        assertTrue(p.z(UPPER_CENTRE) > 0, "the vertex above the pinned sheet: " + p.z(UPPER_CENTRE));
    }

    /**
     * A 24² cloth collapsing onto itself in layers on a floor (the guard's test scene) with particle pairs
     * only, a tenth of its spacing thick: without untangling its triangles pass through each other (189
     * crossing pairs in its worst step); with it every step ends with none.
     */
    @Test
    void aCollapsingClothEndsEveryStepUncrossed() {
        int[] off = collapse(false), on = collapse(true);
        System.out.println("collapsing cloth, particle pairs only: most crossing pairs at a step's end " + off[0] + " without untangling, " + on[0] + " with (" + on[1] + " steps untangled)");
        assertTrue(off[0] > 0, "particle pairs alone let the thin cloth pass through itself");
        assertEquals(0, on[0], "untangled, no step ends crossed");
        assertTrue(on[1] > 0, "and the untangler had steps to untangle");
    }

    /** The most crossing pairs after any of 150 steps, and the steps the untangler found tangled. */
    static int[] collapse(boolean untangle) {
        Cloth c = CrossingGuardTest.collapsingCloth();
        Simulation sim = CrossingGuardTest.collapse(c, 1, false);
        if (untangle) sim.selfCollision().untangling(c.triangles());
        int most = 0;
        for (int step = 0; step < 150; step++) {
            sim.step();
            most = Math.max(most, TriangleIntersections.count(c.particles().positions(), c.triangles()));
        }
        return new int[] {most, untangle ? (int) sim.selfCollision().untangler().tangledSteps() : 0};
    }

    /**
     * Untangling allocates nothing once its arrays have grown: the collapsing cloth, after the 40 steps in
     * which it tangles and is put back, counted over two windows of 20 (the smaller taken, as AllocationTest does).
     */
    @Test
    void untanglingStepsAllocateNothing() {
        Cloth c = CrossingGuardTest.collapsingCloth();
        Simulation sim = CrossingGuardTest.collapse(c, 1, false);
        sim.selfCollision().untangling(c.triangles());
        for (int step = 0; step < 40; step++) sim.step();
        assertTrue(sim.selfCollision().untangler().tangledSteps() > 0, "the warm-up steps had crossings to put back");
        double perStep = CrossingGuardTest.leastBytesPerStep(sim);
        assertEquals(0, perStep, 0, "bytes allocated per step");
    }

    /**
     * A cloth whose every particle is thrown 100 m in its own direction in one step crosses nearly all of
     * itself: every edge's box would read every face. Past {@link CrossingUntangler#MOST_CANDIDATES} faces an
     * edge the untangler leaves the step as it is (counted), to the bit what the step is without it.
     */
    @Test
    void aClothFlungAcrossItselfWholesaleIsLeftAsItIs() {
        double[][] ends = new double[2][];
        for (int untangle = 0; untangle < 2; untangle++) {
            Cloth c = new ClothBuilder().resolution(40, 40).size(1, 1).origin(0, 1, 0).arealDensity(0.2).family(ConstraintFamily.STRUCTURAL, 1, 0).build();
            Particles p = c.particles();
            Simulation sim = c.simulation(new SolverSettings().withIterations(1).withSubsteps(1).withGravity(0, 0, 0));
            SelfCollision self = new SelfCollision(p.positions().clone(), 1e-3, 0, 0);
            sim.selfCollision(untangle == 1 ? self.untangling(c.triangles()) : self);
            java.util.Random r = new java.util.Random(5);
            for (int i = 0; i < p.count(); i++) p.setVelocity(i, 5000 * r.nextGaussian(), 5000 * r.nextGaussian(), 5000 * r.nextGaussian());
            sim.step(0.02);
            if (untangle == 1) assertEquals(1, self.untangler().overloads(), "the step left as it was");
            ends[untangle] = p.positions().clone();
        }
        assertArrayEquals(ends[0], ends[1], 0, "the same positions with the untangler and without");
    }

    /** Bad input names the field and the value. */
    @Test
    void badInputIsRefusedByName() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new CrossingUntangler(new int[] {0, 1}, new double[9], null, 0.01));
        assertTrue(e.getMessage().startsWith("triangles must hold 3"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> new CrossingUntangler(new int[] {0, 1, 3}, new double[9], null, 0.01));
        assertTrue(e.getMessage().contains("triangles") && e.getMessage().contains("was 3"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> new CrossingUntangler(new int[] {0, 1, 2}, new double[9], null, 0));
        assertTrue(e.getMessage().contains("thickness"), e.getMessage());
    }
}
