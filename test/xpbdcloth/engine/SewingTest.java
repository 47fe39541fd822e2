package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/**
 * Sewing: two strips of cloth a gap apart, their facing edges stitched. The stitches' rest lengths shrink
 * linearly to zero over the sewing time; at that time the seam closes (hard stitches, each pair welded with
 * its momentum kept) and the hinges across it take the seam's bending stiffness; while sewing weightless
 * there is no gravity and the motion is damped, both restored at the close.
 */
class SewingTest {
    static final int N = 6;
    static final double GAP = 0.1, SPACING = 0.05, B = 1e-4;

    /**
     * Two N × 2 strips in the plane y = 1, the left one's right column facing the right one's left column
     * GAP apart; each a square grid of distance constraints. Particles: left 0..2N−1, right 2N..4N−1, column
     * major (particle c·N + r in column c, row r).
     */
    static Simulation strips(SolverSettings s) {
        Particles p = new Particles(4 * N);
        for (int side = 0; side < 2; side++)
            for (int c = 0; c < 2; c++)
                for (int r = 0; r < N; r++) {
                    int i = side * 2 * N + c * N + r;
                    double x = side == 0 ? c * SPACING : SPACING + GAP + c * SPACING;
                    p.setPosition(i, x, 1, r * SPACING);
                    p.setMass(i, 0.01);
                }
        Simulation sim = new Simulation(p, s);
        DistanceBlock d = new DistanceBlock(ConstraintFamily.STRUCTURAL, 64);
        for (int side = 0; side < 2; side++) {
            int o = side * 2 * N;
            for (int r = 0; r < N; r++) d.addAtCurrentLength(p, o + r, o + N + r);
            for (int c = 0; c < 2; c++) for (int r = 0; r + 1 < N; r++) d.addAtCurrentLength(p, o + c * N + r, o + c * N + r + 1);
        }
        sim.add(d);
        return sim;
    }

    /** Stitches: the left strip's right column (N..2N−1) to the right strip's left column (2N..3N−1), row by row. */
    static int[] stitchPairs() {
        int[] pairs = new int[2 * N];
        for (int r = 0; r < N; r++) { pairs[2 * r] = N + r; pairs[2 * r + 1] = 2 * N + r; }
        return pairs;
    }

    /** One hinge per pair of rows across the seam: wings the far columns, edge on the left strip's right column. */
    static int[] hinges() {
        int[] h = new int[4 * (N - 1)];
        for (int r = 0; r + 1 < N; r++) { h[4 * r] = r; h[4 * r + 1] = 3 * N + r; h[4 * r + 2] = N + r; h[4 * r + 3] = N + r + 1; }
        return h;
    }

    static double[] hingeRest() {
        double[] a = new double[N - 1];
        // Two right triangles of legs SPACING across a SPACING edge: (A₀ + A₁)/|e|² = 1.
        java.util.Arrays.fill(a, 1.0);
        return a;
    }

    static Sewing sew(Simulation sim, double time) {
        Sewing s = new Sewing(sim.particles(), stitchPairs(), hinges(), hingeRest(), time, 1e-6, B, 3);
        for (ConstraintBlock b : s.blocks()) sim.add(b);
        sim.add(s.weightless(sim));
        return s;
    }

    @Test
    void theRestLengthsShrinkLinearlyAndTheSeamClosesWithinTheSewingTime() {
        SolverSettings settings = new SolverSettings().withMode(ConstraintMode.XPBD).withIterations(10).withSubsteps(10).withTimestep(0.01);
        Simulation sim = strips(settings);
        double time = 0.5;
        Sewing sewing = sew(sim, time);
        // Weightless: a step leaves the panels' centre of mass where it was (their weight held up, the stitches internal).
        double y0 = centreHeight(sim.particles());
        sim.step();
        assertEquals(y0, centreHeight(sim.particles()), 1e-12, "no fall while sewing");
        for (int step = 2; step <= 25; step++) sim.step();
        // The rest lengths reach zero at PULLING of the time: halfway through, 1 − 0.5/PULLING of the gap is left.
        for (int k = 0; k < N; k++) assertEquals(GAP * (1 - 0.5 / Sewing.PULLING), sewing.stitches().restLength(k), 1e-12, "halfway through the sewing");
        double[] largest = new double[1];
        for (int step = 26; step <= 50; step++) {
            sim.step();
            largest[0] = sewing.largestGap(sim.particles());
        }
        assertTrue(sewing.closed(), "closed at the sewing time");
        assertEquals(0.0, largest[0], 0.0, "closed stitches are welded: the two sides one point");
        // Closed, it falls again: gravity is the simulation's own.
        double before = centreHeight(sim.particles());
        for (int step = 0; step < 5; step++) sim.step();
        assertTrue(centreHeight(sim.particles()) < before - 0.5 * 9.81 * 0.05 * 0.05 * 0.5, "falls once closed");
        for (int k = 0; k < N; k++) assertEquals(0.0, sewing.stitches().compliance(k), 0.0, "a closed stitch is hard");
        // The hinges across it bend at three times the fabric's stiffness: α = (A₀ + A₁)/(3B|e|²).
        for (int h = 0; h < N - 1; h++) assertEquals(1.0 / (3 * B), sewing.hinges().compliance(h), 1e-9 / B);
    }

    @Test
    void theWeldKeepsMomentumAndAPinnedParticleHoldsItsPlace() {
        Simulation sim = strips(new SolverSettings().withMode(ConstraintMode.XPBD).withGravity(0, 0, 0));
        Particles p = sim.particles();
        p.setMass(N, 0.03);  // unequal masses across the first stitch
        for (int i = 0; i < p.count(); i++) p.setVelocity(i, 0.1 * (i % 3), -0.2, 0.05 * i);
        p.pin(2 * N + 1);  // the second stitch's right particle pinned
        double[] before = momentum(p);
        double[] pinned = {p.x(2 * N + 1), p.y(2 * N + 1), p.z(2 * N + 1)};
        Sewing sewing = new Sewing(p, stitchPairs(), hinges(), hingeRest(), 0, 1e-6, B, 1);  // closed from the start
        sewing.afterStep(p, 0.01);
        double[] after = momentum(p);
        // Welded pairs without a pin keep their momentum; the pinned one's partner moves on with the pin.
        int partner = N + 1, pin = 2 * N + 1;
        double m = p.mass(partner);
        assertEquals(before[0] - m * (0.1 * (partner % 3) - p.vx(pin)), after[0], 1e-15);
        assertEquals(before[1] - m * (-0.2 - p.vy(pin)), after[1], 1e-15);
        assertEquals(before[2] - m * (0.05 * partner - p.vz(pin)), after[2], 1e-15);
        assertArrayEquals(pinned, new double[] {p.x(N + 1), p.y(N + 1), p.z(N + 1)}, 0.0);
        assertEquals(0.0, sewing.largestGap(p), 0.0);
        // The heavier particle of the first pair (3:1) takes the pair three quarters of the way to itself.
        assertEquals(0.75 * SPACING + 0.25 * (SPACING + GAP), p.x(N), 1e-15);
    }

    static double centreHeight(Particles p) {
        double m = 0, my = 0;
        for (int i = 0; i < p.count(); i++) { m += p.mass(i); my += p.mass(i) * p.y(i); }
        return my / m;
    }

    static double[] momentum(Particles p) {
        double[] m = new double[3];
        for (int i = 0; i < p.count(); i++) {
            if (p.inverseMass(i) == 0) continue;
            m[0] += p.mass(i) * p.vx(i); m[1] += p.mass(i) * p.vy(i); m[2] += p.mass(i) * p.vz(i);
        }
        return m;
    }
}
