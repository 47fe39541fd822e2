package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A hinge held bent: its rest angle follows the overstress flow's closed form θ₀(t) = (θ − θ_y)(1 − e^(−r t)),
 * stays put below the yield, keeps its rest through an undone step, and refuses what has no meaning.
 */
class HingePlasticityTest {
    /** Edge (2, 3) along x, one wing in the x–z plane, the other turned by θ about the edge; edge length 0.1, wings 0.05 out. */
    static Particles hinge() {
        Particles p = new Particles(4);
        p.setPosition(0, 0.05, 0, -0.05);
        p.setPosition(1, 0.05, 0, 0.05);
        p.setPosition(2, 0, 0, 0);
        p.setPosition(3, 0.1, 0, 0);
        for (int i = 0; i < 4; i++) p.setMass(i, 1e-3);
        return p;
    }

    /** Turns the second wing so the block measures θ (its sign convention: a wing turned toward −y is positive). */
    static void bend(Particles p, double theta) {
        p.setPosition(1, 0.05, -0.05 * Math.sin(theta), 0.05 * Math.cos(theta));
    }

    /** A simulation of the four particles, all pinned, with the hinge at rest flat and the plasticity made at rest. */
    static Simulation held(Particles p, double yieldCurvature, double rate) {
        DihedralBlock d = new DihedralBlock(ConstraintFamily.DIHEDRAL, 1);
        d.addAtCurrentShape(p, 0, 1, 2, 3, 1e-5);
        Simulation sim = new Simulation(p, new SolverSettings().withMode(ConstraintMode.XPBD).withIterations(2).withSubsteps(2).withTimestep(0.01));
        sim.add(d);
        sim.add(new HingePlasticity(sim.blocks(), p, yieldCurvature, rate));
        for (int i = 0; i < 4; i++) p.pin(i);
        return sim;
    }

    static double restAngle(Simulation sim) { return ((DihedralBlock) sim.blocks().get(0)).restAngle(0); }

    @Test
    void aHingeHeldPastItsYieldCreepsAsTheClosedFormSays() {
        for (double theta : new double[] {1.2, -2.5}) {
            Particles p = hinge();
            Simulation sim = held(p, 20, 3);
            // w = (A₀ + A₁)/|e| = (2 · ½ · 0.1 · 0.05)/0.1 = 0.05 m, so θ_y = 20 · 0.05 = 1 rad, below both bends.
            double yield = ((HingePlasticity) sim.afterSteps().get(0)).yieldAngle(0, 0);
            assertEquals(1.0, yield, 1e-12);
            bend(p, theta);
            assertEquals(theta, ((DihedralBlock) sim.blocks().get(0)).angle(0, p), 1e-12);
            for (int s = 1; s <= 50; s++) {
                sim.step();
                double expected = Math.copySign(Math.abs(theta) - yield, theta) * -Math.expm1(-3 * 0.01 * s);
                assertEquals(expected, restAngle(sim), 1e-12, "θ = " + theta + ", step " + s);
            }
        }
    }

    @Test
    void aBendBelowTheYieldLeavesTheRestFlat() {
        Particles p = hinge();
        Simulation sim = held(p, 20, 1e4);
        bend(p, 0.99);
        for (int s = 0; s < 20; s++) sim.step();
        assertEquals(0.0, restAngle(sim), 0.0);
    }

    @Test
    void anInstantYieldLeavesExactlyTheYieldAngleToSpringBack() {
        Particles p = hinge();
        Simulation sim = held(p, 10, 1e4); // θ_y = 0.5 rad; r·dt = 100: e^(−100) is nothing
        bend(p, 3.0);
        sim.step();
        assertEquals(2.5, restAngle(sim), 1e-12);
        // Through ±π: bent to −3.0 from a rest of 2.5 is 2π − 5.5 = 0.78 the short way, 0.28 past the yield.
        bend(p, -3.0);
        sim.step();
        double expected = 2.5 + (2 * Math.PI - 5.5 - 0.5);
        assertEquals(expected > Math.PI ? expected - 2 * Math.PI : expected, restAngle(sim), 1e-12);
    }

    @Test
    void anUndoneStepLeavesTheRestAnglesAsTheyWere() {
        Particles p = hinge();
        Simulation sim = held(p, 10, 1e4);
        p.unpin(0);
        bend(p, 2.0);
        sim.add(new ExternalForce() {
            @Override public void apply(Particles q, double time, double dt) { throw new IllegalStateException("a force that fails"); }
        });
        assertThrows(SimulationDivergedException.class, sim::step);
        assertEquals(0.0, restAngle(sim), 0.0);
    }

    @Test
    void nonsenseIsRefusedByName() {
        Particles p = hinge();
        DihedralBlock d = new DihedralBlock(ConstraintFamily.DIHEDRAL, 1);
        d.addAtCurrentShape(p, 0, 1, 2, 3, 1e-5);
        List<ConstraintBlock> blocks = List.of(d);
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new HingePlasticity(blocks, p, 0, 1)).getMessage().contains("yieldCurvature"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new HingePlasticity(blocks, p, 1, -1)).getMessage().contains("rate"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new HingePlasticity(List.of(), p, 1, 1)).getMessage().contains("no dihedral hinge"));
        Simulation other = new Simulation(p, new SolverSettings());
        assertTrue(assertThrows(IllegalArgumentException.class, () -> other.add(new HingePlasticity(blocks, p, 1, 1))).getMessage().contains("does not hold"));
    }
}
