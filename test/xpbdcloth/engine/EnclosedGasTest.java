package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import xpbdcloth.mesh.Balloon;
import xpbdcloth.mesh.Pillow;

/**
 * The gas inside a closed cloth: the volume it measures, the surfaces it refuses, a held volume held, and a
 * squeezed pillow's gas obeying Boyle's law in the pressure the solver actually applied (λ/h², not the formula).
 */
class EnclosedGasTest {
    /** A cube of side a with its corner at (o, o, o): 8 particles, 12 triangles wound outwards (or inwards). */
    static int[] cube(Particles p, double o, double a, boolean inwards) {
        for (int i = 0; i < 8; i++) p.setPosition(i, o + a * (i & 1), o + a * (i >> 1 & 1), o + a * (i >> 2 & 1));
        int[][] quads = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
        int[] t = new int[36];
        int k = 0;
        for (int[] q : quads)
            for (int[] tri : new int[][] {{q[0], q[1], q[2]}, {q[0], q[2], q[3]}}) {
                t[k++] = tri[0];
                t[k++] = inwards ? tri[2] : tri[1];
                t[k++] = inwards ? tri[1] : tri[2];
            }
        return t;
    }

    @Test
    void aCubeEnclosesItsVolumeWoundEitherWayAndFarFromTheOrigin() {
        for (boolean inwards : new boolean[] {false, true})
            for (double o : new double[] {0, -3, 1e3}) {
                Particles p = new Particles(8);
                int[] t = cube(p, o, 0.3, inwards);
                EnclosedGas gas = EnclosedGas.ofGas(p, t, 100, 0);
                assertEquals(0.027, gas.restVolume(), 1e-15 * Math.max(1, o * o * o));
                assertEquals(0.027, gas.volume(p), 1e-12 * Math.max(1, o * o * o));
            }
        // A latitude–longitude sphere's volume tends to 4/3 π r³ from below, as its inscribed polyhedron's must.
        double previous = 0;
        for (int slices : new int[] {8, 16, 32, 64}) {
            xpbdcloth.mesh.ClothMesh m = Balloon.generate(1, slices, slices / 2);
            Cloth c = new MeshClothBuilder(m).arealDensity(0.1).build();
            double v = EnclosedGas.ofGas(c.particles(), c.triangles(), 1, 0).restVolume();
            assertTrue(v > previous && v < 4 * Math.PI / 3, "volume " + v + " at " + slices + " slices");
            previous = v;
        }
        assertEquals(4 * Math.PI / 3, previous, 0.005 * 4 * Math.PI / 3);
    }

    @Test
    void surfacesThatEncloseNothingAreRefusedByTheirEdge() {
        Particles p = new Particles(8);
        int[] t = cube(p, 0, 1, false);
        int[] open = java.util.Arrays.copyOf(t, 33);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> EnclosedGas.ofGas(p, open, 1, 0));
        assertTrue(e.getMessage().contains("borders one triangle only"), e.getMessage());
        int[] turned = t.clone();
        turned[1] = t[2];
        turned[2] = t[1];
        e = assertThrows(IllegalArgumentException.class, () -> EnclosedGas.ofGas(p, turned, 1, 0));
        assertTrue(e.getMessage().contains("runs the same way in two triangles"), e.getMessage());
        // Two triangles back to back: closed, but flat.
        e = assertThrows(IllegalArgumentException.class, () -> EnclosedGas.ofHeldVolume(p, new int[] {0, 1, 2, 0, 2, 1}, 1));
        assertTrue(e.getMessage().contains("must enclose a volume, enclose"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> EnclosedGas.ofGas(p, t, -1, 0));
        assertTrue(e.getMessage().contains("nRT"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> EnclosedGas.ofGas(p, t, 1, Double.NaN));
        assertTrue(e.getMessage().contains("ambient"), e.getMessage());
    }

    /** A pillow of springs: 2 × 12² cells, 0.5 m wide, 4 cm puff. */
    static Cloth pillow() {
        return new MeshClothBuilder(Pillow.generate(0.5, 0.04, 12)).arealDensity(0.2)
                .family(ConstraintFamily.STRUCTURAL, 1, 1e-5).build();
    }

    @Test
    void aHeldVolumeIsHeld() {
        Cloth c = pillow();
        Particles p = c.particles();
        Simulation sim = new Simulation(p, new SolverSettings().withGravity(0, 0, 0).withIterations(10).withSubsteps(5).withTimestep(0.01).withDamping(2));
        for (ConstraintBlock b : c.blocks()) sim.add(b);
        EnclosedGas held = EnclosedGas.ofHeldVolume(p, c.triangles(), 1.3);
        double target = 1.3 * held.restVolume();
        sim.add(held);
        for (int s = 0; s < 200; s++) sim.step();
        assertEquals(target, held.volume(p), 1e-4 * target);
        assertTrue(held.pressure() > 0, "it takes an outward push to hold a puffed-up pillow: " + held.pressure());
    }

    /**
     * The pillow squeezed between a floor and a ceiling at ±gap/2, at rest: {volume, pressure}. Small steps: the
     * contacts take back some of each sweep's push, and at 10 × 10 the row's λ lagged 4 % behind the gas law
     * (0.96 nRT; 10 × 40 reads 0.999, 40 × 10 0.985, as Macklin et al. 2019 find substeps worth more than sweeps).
     */
    static double[] squeeze(double gap, double nRT, int threads, SolverType solver) {
        Cloth c = pillow();
        Particles p = c.particles();
        Simulation sim = new Simulation(p, new SolverSettings().withGravity(0, -9.81, 0).withIterations(10).withSubsteps(40)
                .withTimestep(0.01).withDamping(5).withThreads(threads).withOrder(ConstraintOrder.COLOURED).withSolver(solver));
        for (ConstraintBlock b : c.blocks()) sim.add(b);
        sim.add(new Plane(new double[] {0, -gap / 2, 0}, new double[] {0, 1, 0}, 0.002, 0.5, 0.4));
        sim.add(new Plane(new double[] {0, gap / 2, 0}, new double[] {0, -1, 0}, 0.002, 0.5, 0.4));
        EnclosedGas gas = EnclosedGas.ofGas(p, c.triangles(), nRT, 101325);
        sim.add(gas);
        for (int s = 0; s < 300; s++) sim.step();
        assertEquals(SolverType.GAUSS_SEIDEL, sim.solverInUse());
        return new double[] {gas.volume(p), gas.pressure(), gas.restVolume()};
    }

    @Test
    void aSqueezedPillowsGasObeysBoylesLaw() {
        double v0 = EnclosedGas.ofGas(pillow().particles(), pillow().triangles(), 1, 0).restVolume(), nRT = 101325 * v0;
        double[] loose = squeeze(1, nRT, 1, SolverType.GAUSS_SEIDEL), tight = squeeze(0.04, nRT, 1, SolverType.GAUSS_SEIDEL);
        System.out.printf("rest volume %.6g m³; loose: V %.6g m³, p %.6g Pa, pV/nRT %.6f; squeezed to 4 cm: V %.6g m³, p %.6g Pa, pV/nRT %.6f%n",
                v0, loose[0], loose[1], loose[0] * loose[1] / nRT, tight[0], tight[1], tight[0] * tight[1] / nRT);
        assertEquals(nRT, loose[0] * loose[1], 0.01 * nRT);
        assertEquals(nRT, tight[0] * tight[1], 0.01 * nRT);
        // The squeeze must matter: the pressure the solver applied rose as the volume fell.
        assertTrue(tight[1] > loose[1] + 100, "pressure " + tight[1] + " against " + loose[1]);
        // The same bits on two threads, and vertex block descent hands a gas to Gauss–Seidel.
        assertArrayEquals(tight, squeeze(0.04, nRT, 2, SolverType.GAUSS_SEIDEL));
        assertArrayEquals(tight, squeeze(0.04, nRT, 1, SolverType.VERTEX_BLOCK_DESCENT));
    }
}
