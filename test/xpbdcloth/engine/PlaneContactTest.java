package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/** Cloth on a fixed plane (and on the top of a tilted box): Coulomb's law on a slope, and rest without jitter on a floor. */
class PlaneContactTest {
    static final double MARGIN = 0.005;

    /** What the cloth lies on: a surface through the origin tilted by θ about z, its normal (sin θ, cos θ, 0). */
    interface Slope {
        void addTo(Simulation sim, double theta, double staticFriction, double kineticFriction);
    }

    static final Slope PLANE = (sim, theta, muS, muK) -> sim.add(new Plane(new double[] {0, 0, 0}, new double[] {Math.sin(theta), Math.cos(theta), 0}, MARGIN, muS, muK));

    /** The top face of a box 10 m wide and 20 cm thick: centre half a thickness below it along −n, local +y turned onto n. */
    static final Slope BOX = (sim, theta, muS, muK) -> sim.add(new Box(SpherePath.fixed(-0.1 * Math.sin(theta), -0.1 * Math.cos(theta), 0),
            new double[] {5, 0.1, 5}, new double[] {0, 0, -Math.toDegrees(theta)}, MARGIN, muS, muK));

    /**
     * A 4 × 4 cloth (15 cm square, all families) lying on a slope tilted by θ, with μₛ and μₖ: the
     * returned value is its centroid's travel down the slope after {@code seconds}.
     */
    static double slideDownSlope(double theta, double staticFriction, double kineticFriction, double seconds) {
        return slideDownSlope(theta, staticFriction, kineticFriction, seconds, PLANE);
    }

    static double slideDownSlope(double theta, double staticFriction, double kineticFriction, double seconds, Slope slope) {
        Cloth c = new ClothBuilder().resolution(4, 4).size(0.15, 0.15).plane(ClothBuilder.Plane.HORIZONTAL).origin(0, 0, 0).arealDensity(0.2)
                .family(ConstraintFamily.STRUCTURAL, 1, 1e-6).family(ConstraintFamily.SHEAR, 0.5, 1e-3).family(ConstraintFamily.BEND, 0.1, 1e-2).build();
        Particles p = c.particles();
        // The slope: normal n = (sin θ, cos θ, 0); down the slope t = (cos θ, −sin θ, 0); across it b = z.
        double nx = Math.sin(theta), ny = Math.cos(theta), tx = Math.cos(theta), ty = -Math.sin(theta);
        for (int i = 0; i < p.count(); i++) {
            double u = p.x(i), v = p.z(i);
            p.setPosition(i, u * tx + MARGIN * nx, u * ty + MARGIN * ny, v);
        }
        Simulation sim = c.simulation(new SolverSettings().withIterations(2).withSubsteps(10).withTimestep(0.02));
        slope.addTo(sim, theta, staticFriction, kineticFriction);
        double start = centroidAlong(p, tx, ty);
        int steps = (int) Math.round(seconds / 0.02);
        for (int s = 0; s < steps; s++) sim.step();
        return centroidAlong(p, tx, ty) - start;
    }

    static double centroidAlong(Particles p, double tx, double ty) {
        double sum = 0;
        for (int i = 0; i < p.count(); i++) sum += p.x(i) * tx + p.y(i) * ty;
        return sum / p.count();
    }

    /** tan θ = 0.4 below μₛ = 0.5: the cloth stays where it was put (under a millimetre in 2 s). */
    @Test
    void belowTheFrictionAngleTheClothStays() {
        double moved = slideDownSlope(Math.atan(0.4), 0.5, 0.3, 2.0);
        System.out.printf("slope tan θ = 0.4, μs = 0.5: moved %.2e m in 2 s%n", moved);
        assertEquals(0, moved, 1e-3);
    }

    /**
     * tan θ = 0.7 above μₛ = 0.5: it slides with Coulomb's acceleration a = g (sin θ − μₖ cos θ), so it
     * travels a t²/2 in t = 1 s (1.608 m for μₖ = 0.3), within 2 %.
     */
    @Test
    void aboveTheFrictionAngleTheClothSlidesAsCoulombSays() {
        double theta = Math.atan(0.7), muK = 0.3;
        double a = 9.81 * (Math.sin(theta) - muK * Math.cos(theta));
        double moved = slideDownSlope(theta, 0.5, muK, 1.0);
        System.out.printf("slope tan θ = 0.7, μs = 0.5, μk = 0.3: moved %.4f m in 1 s, Coulomb %.4f m%n", moved, a / 2);
        assertEquals(a / 2, moved, 0.02 * a / 2);
        // Frictionless, for contrast: g sin θ.
        double free = slideDownSlope(theta, 0, 0, 1.0);
        assertEquals(9.81 * Math.sin(theta) / 2, free, 0.02 * 9.81 * Math.sin(theta) / 2);
    }

    /** Coulomb's law on both sides of the threshold holds on a tilted box's face as on the plane (shared friction, the box's own contact). */
    @Test
    void onATiltedBoxTheClothObeysCoulombToo() {
        double stays = slideDownSlope(Math.atan(0.4), 0.5, 0.3, 2.0, BOX);
        double theta = Math.atan(0.7), a = 9.81 * (Math.sin(theta) - 0.3 * Math.cos(theta));
        double slides = slideDownSlope(theta, 0.5, 0.3, 1.0, BOX);
        System.out.printf("tilted box: tan θ = 0.4 < μs moved %.2e m in 2 s; tan θ = 0.7 slid %.4f m in 1 s, Coulomb %.4f m%n", stays, slides, a / 2);
        assertEquals(0, stays, 1e-3);
        assertEquals(a / 2, slides, 0.02 * a / 2);
    }

    /**
     * A 32² cloth dropped flat from 5 cm onto a floor, at the shipped scenes' settings (all families,
     * 2 × 10, dt = 20 ms), for 10 s: kinetic energy below 1e-6 J at the end and no particle moving more
     * than 0.1 mm in the last second (no jitter at rest).
     */
    @Test
    void aClothOnTheFloorComesToRestWithoutJitter() {
        Cloth c = new ClothBuilder().resolution(32, 32).size(1, 1).plane(ClothBuilder.Plane.HORIZONTAL).origin(0, 0.05, 0).arealDensity(0.2)
                .family(ConstraintFamily.STRUCTURAL, 1, 1e-6).family(ConstraintFamily.SHEAR, 0.5, 1e-3).family(ConstraintFamily.BEND, 0.1, 1e-2).build();
        Simulation sim = c.simulation(new SolverSettings().withIterations(2).withSubsteps(10).withTimestep(0.02));
        sim.add(Plane.floor(0, MARGIN, 0.5, 0.4));
        Particles p = c.particles();
        for (int s = 0; s < 450; s++) sim.step();
        double[] before = p.positions().clone();
        for (int s = 0; s < 50; s++) sim.step();
        double moved = 0;
        for (int i = 0; i < p.count(); i++) {
            double dx = p.x(i) - before[3 * i], dy = p.y(i) - before[3 * i + 1], dz = p.z(i) - before[3 * i + 2];
            moved = Math.max(moved, Math.sqrt(dx * dx + dy * dy + dz * dz));
        }
        double ke = Metrics.kineticEnergy(p), lowest = Double.MAX_VALUE;
        for (int i = 0; i < p.count(); i++) lowest = Math.min(lowest, p.y(i));
        System.out.printf("cloth on the floor after 10 s: KE %.2e J, largest move in the last second %.2e m, lowest particle %.5f m%n", ke, moved, lowest);
        assertTrue(ke < 1e-6, "kinetic energy " + ke);
        assertTrue(moved < 1e-4, "largest move in the last second " + moved);
        assertTrue(lowest > MARGIN - 1e-6, "no particle below the margin: " + lowest);
    }
}
