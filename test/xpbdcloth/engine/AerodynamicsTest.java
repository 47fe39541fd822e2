package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * Flat-plate aerodynamics in numbers: a sheet falling face-on reaches √(2mg/(ρ C_D A)); a plate at an
 * angle to the flow feels ½ρA U² (C_D cos θ along its normal, C_L cos θ sin θ across the flow).
 */
class AerodynamicsTest {
    @Test
    void aSheetFallingFaceOnReachesItsTerminalVelocity() {
        double density = 0.1, cd = 1.2;
        Cloth cloth = new ClothBuilder().resolution(9, 9).size(0.5, 0.5).plane(ClothBuilder.Plane.HORIZONTAL).origin(0, 10, 0)
                .arealDensity(density).family(ConstraintFamily.STRUCTURAL, 1, 1e-8).family(ConstraintFamily.SHEAR, 1, 1e-6)
                .family(ConstraintFamily.BEND, 1, 1e-6).build();
        // Short steps: the exact-decay scale takes a fraction x/2 off the drag in steady fall (see the class).
        Simulation sim = cloth.simulation(new SolverSettings().withIterations(10).withSubsteps(1).withTimestep(0.0025).withGravity(0, -9.81, 0));
        // No lift: a falling plate with lift tumbles (as real paper does), and the closed form is for face-on.
        sim.add(new Aerodynamics(cloth.triangles(), Aerodynamics.AIR_DENSITY, cd, 0));
        for (int s = 0; s < 800; s++) sim.step();
        Particles p = cloth.particles();
        double vy = 0;
        for (int i = 0; i < p.count(); i++) vy += p.vy(i) / p.count();
        double lo = Double.MAX_VALUE, hi = -Double.MAX_VALUE;
        for (int i = 0; i < p.count(); i++) { lo = Math.min(lo, p.y(i)); hi = Math.max(hi, p.y(i)); }
        System.out.printf("falling sheet after 2 s: mean vy %.4f m/s, heights spread %.4f m%n", vy, hi - lo);
        double expected = Math.sqrt(2 * density * 9.81 / (Aerodynamics.AIR_DENSITY * cd));
        assertEquals(-expected, vy, 0.02 * expected, "terminal velocity (m/s)");
    }

    @Test
    void aPlateAtAnAngleFeelsDragAlongItsNormalAndLiftAcrossTheFlow() {
        double theta = Math.toRadians(60), area = 0.5, speed = 10, cd = 1.2, cl = 0.9;
        // A unit square (two triangles) whose normal makes θ with the flow along +x.
        Particles p = new Particles(4);
        double nx = Math.cos(theta), ny = Math.sin(theta); // unit normal in the x–y plane
        double[][] corners = {{0, 0, 0}, {0, 0, 1}, {-ny, nx, 1}, {-ny, nx, 0}}; // spans z and (−ny, nx)
        for (int i = 0; i < 4; i++) { p.setPosition(i, corners[i][0], corners[i][1], corners[i][2]); p.setMass(i, 1e6); }
        int[] triangles = {0, 1, 2, 0, 2, 3};
        Aerodynamics air = new Aerodynamics(triangles, Aerodynamics.AIR_DENSITY, cd, cl).air(speed, 0, 0);
        air.apply(p, 0, 1e-9);
        double fx = 0, fy = 0;
        for (int i = 0; i < 4; i++) { fx += p.force[3 * i]; fy += p.force[3 * i + 1]; }
        double q = 0.5 * Aerodynamics.AIR_DENSITY * 2 * area * speed * speed; // ½ρ A U², A = 1 m²
        double cos = Math.cos(theta), sin = Math.sin(theta);
        // Drag C_D cos θ along n̂ = (cos θ, sin θ); lift C_L cos θ sin θ along n̂'s part across the flow, +y.
        double expectedX = q * cd * cos * nx, expectedY = q * cd * cos * ny + q * cl * cos * sin;
        assertEquals(expectedX, fx, 1e-9 * q, "force along the flow (N)");
        assertEquals(expectedY, fy, 1e-9 * q, "force across the flow (N)");
        assertTrue(fy > 0 && fx > 0, "pushed downstream and lifted");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new Aerodynamics(triangles, 0, 1, 1));
        assertTrue(e.getMessage().startsWith("density"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> new Aerodynamics(triangles, 1.2, -1, 1));
        assertTrue(e.getMessage().startsWith("dragCoefficient"), e.getMessage());
    }

    /**
     * A 500 m sheet of 1.2 t particles, pinned at two corners, in a 140 m/s flow of air 60 times as dense as
     * ours, at 0.1 ms steps (the preset fuzzer's seed 5116, made small): each corner's force is 1e10 N, past
     * the range a caller may push (±1e9, Particles.addForce), and so is what the exact decay lets through on
     * the heavy particles. The step goes on; the pins take no force; no free particle's velocity changes by
     * more than the flow's speed past it plus gravity's part.
     */
    @Test
    void aHeavySheetInADenseFastFlowIsBoundedByTheFlowNotByTheForceRange() {
        Cloth cloth = new ClothBuilder().resolution(4, 4).size(500, 500).origin(0, 0, 0).totalMass(16 * 1200)
                .family(ConstraintFamily.STRUCTURAL, 1, 1e-6).pinTopCorners().build();
        double dt = 1e-4, g = 9.81;
        Simulation sim = cloth.simulation(new SolverSettings().withIterations(2).withSubsteps(1).withTimestep(dt).withGravity(0, -g, 0));
        double ux = 70, uy = 100, uz = -66;
        sim.add(new Aerodynamics(cloth.triangles(), 72, 10, 0.9).air(ux, uy, uz));
        Particles p = cloth.particles();
        double flow = Math.sqrt(ux * ux + uy * uy + uz * uz);
        double cornerForce = 0.5 * 72 * 0.5 * (500.0 / 3) * (500.0 / 3) * 10 * flow * flow / 3; // ½ρ A C_D |r|² / 3, face-on at most
        double mass = 1 / p.inverseMass(5);
        assertTrue(mass * flow / dt > 1e9, "the decayed force on a free particle, about m|r|/dt, is past the caller's range: " + mass * flow / dt + " N");
        double[] x0 = p.positions().clone();
        sim.step();
        for (int i = 0; i < p.count(); i++) {
            double dv = Math.sqrt(p.vx(i) * p.vx(i) + p.vy(i) * p.vy(i) + p.vz(i) * p.vz(i));
            if (p.inverseMass(i) == 0) assertEquals(0, Math.abs(p.x(i) - x0[3 * i]) + Math.abs(p.y(i) - x0[3 * i + 1]), 0.0, "pin " + i);
            // Each corner's drag and lift rates each bound what they add by the flow's speed; the structure's pull on top.
            else assertTrue(dv <= 2 * flow + g * dt, "particle " + i + ": " + dv + " m/s after one step in a " + flow + " m/s flow");
        }
        System.out.printf("a corner's face-on force %.3g N; the step stays within the flow%n", cornerForce);
    }
}
