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
}
