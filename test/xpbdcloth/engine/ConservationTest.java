package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** Laws every projection must keep, in both modes. */
class ConservationTest {

    static Cloth freeCloth() {
        return new ClothBuilder().resolution(12, 10).size(0.6, 0.5).arealDensity(0.2)
                .family(ConstraintFamily.STRUCTURAL, 0.9, 1e-6)
                .family(ConstraintFamily.SHEAR, 0.5, 1e-3)
                .family(ConstraintFamily.BEND, 0.3, 1e-2)
                .build();
    }

    /**
     * With no external force, each projection moves particles by wᵢ∇ᵢC Δλ; since Σᵢ ∇ᵢC = 0 for any
     * translation-invariant C, Σ mᵢΔxᵢ = Δλ Σ ∇ᵢC = 0: linear momentum is conserved to round-off.
     */
    @Test
    void freeClothConservesLinearMomentum() {
        for (ConstraintMode mode : ConstraintMode.values()) {
            Cloth cloth = freeCloth();
            Particles p = cloth.particles();
            Random rnd = new Random(7);
            for (int i = 0; i < p.count(); i++)
                p.setVelocity(i, rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
            Simulation sim = cloth.simulation(new SolverSettings().withMode(mode).withGravity(0, 0, 0).withIterations(4).withTimestep(1 / 60.0));
            double[] before = {Metrics.momentum(p, 0), Metrics.momentum(p, 1), Metrics.momentum(p, 2)};
            double scale = 0;
            for (int i = 0; i < p.count(); i++)
                scale += p.mass(i) * Math.sqrt(p.vx(i) * p.vx(i) + p.vy(i) * p.vy(i) + p.vz(i) * p.vz(i));
            for (int s = 0; s < 1000; s++) sim.step();
            assertTrue(Metrics.allFinite(p), "finite");
            for (int a = 0; a < 3; a++) {
                double drift = Math.abs(Metrics.momentum(p, a) - before[a]) / scale;
                assertTrue(drift < 1e-9, mode + " axis " + a + " relative drift " + drift);
            }
        }
    }

    /** Pinned particles stay bit-for-bit where they were; nothing goes NaN. */
    @Test
    void pinnedParticlesNeverMove() {
        for (ConstraintMode mode : ConstraintMode.values()) {
            Cloth cloth = new ClothBuilder().family(ConstraintFamily.STRUCTURAL, 1, 0).resolution(16, 16).size(1, 1).pinTopCorners()
                    .family(ConstraintFamily.SHEAR, 1, 1e-4).family(ConstraintFamily.BEND, 0.5, 1e-2).build();
            Particles p = cloth.particles();
            int left = cloth.index(0, 0), right = cloth.index(0, 15);
            double lx = p.x(left), ly = p.y(left), rx = p.x(right), ry = p.y(right);
            Simulation sim = cloth.simulation(new SolverSettings().withMode(mode));
            for (int s = 0; s < 1000; s++) {
                sim.step();
                assertEquals(lx, p.x(left), 0.0);
                assertEquals(ly, p.y(left), 0.0);
                assertEquals(rx, p.x(right), 0.0);
                assertEquals(ry, p.y(right), 0.0);
            }
            assertTrue(Metrics.allFinite(p));
            assertTrue(p.y(cloth.index(15, 8)) < -0.9, mode + ": the cloth hangs below its pins");
        }
    }

    /** A free particle under gravity alone gains exactly g·dt of speed per step (no constraint active). */
    @Test
    void freeFallGainsGDtPerStep() {
        Particles p = new Particles(2);
        p.setPosition(1, 1, 0, 0);
        Simulation sim = new Simulation(p, new SolverSettings().withTimestep(0.01).withSubsteps(3));
        for (int s = 1; s <= 100; s++) {
            double before = p.vy(0);
            sim.step();
            assertEquals(-9.81 * 0.01, p.vy(0) - before, 1e-12);
        }
    }
}
