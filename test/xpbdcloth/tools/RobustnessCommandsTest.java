package xpbdcloth.tools;

import static org.junit.jupiter.api.Assertions.*;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import xpbdcloth.TwoAtATime;
import xpbdcloth.engine.SolverType;

/** The short versions of `gradle soak` and the fuzzer, as CI runs them. */
@Tag("slow")
class RobustnessCommandsTest {
    /** corners and spinning-sphere for 3000 steps (60 s of simulated time) each stay within the soak's bounds. */
    @Test
    void shortSoak() {
        for (String scene : new String[] {"corners", "spinning-sphere"}) {
            Soak.Result r = Soak.run(scene, 3000);
            System.out.println(r);
            assertTrue(r.finite, scene + " finite");
            assertTrue(r.maxStrain < Soak.MAX_STRAIN, scene + " strain " + r.maxStrain);
            assertTrue(r.energyMax - r.energyStart < Soak.MAX_ENERGY_RISE, scene + " energy rise " + (r.energyMax - r.energyStart));
        }
    }

    /**
     * Seeded random cases for each solver (more with `gradle fuzz -Pcases=N`): 1000 under Gauss–Seidel,
     * 200 under Jacobi-PCG and 100 under multigrid-PCG (which cost more per case; before the fix 8 % of
     * such cases went non-finite, so either count would have caught it) and 100 under vertex block descent,
     * each held to the energy bound too (Plausibility: no more kinetic energy than gravity, hands, colliders,
     * the wind and the strain a solver switch found can have given); a failure names its seed.
     */
    @Test
    void fuzzCasesForEverySolver() throws Exception {
        StringBuilder failures = new StringBuilder();
        // Each case is its own simulation: two at a time, reported in seed order.
        for (SolverType t : SolverType.values()) {
            int cases = t == SolverType.GAUSS_SEIDEL ? 1000 : t == SolverType.JACOBI_PCG ? 200 : 100;
            long t0 = System.nanoTime();
            List<Callable<String>> runs = new ArrayList<>();
            for (long seed = 1; seed <= cases; seed++) {
                final long s = seed;
                runs.add(() -> Fuzz.runCase(s, t, true));
            }
            for (String why : TwoAtATime.results(runs))
                if (why != null) failures.append(t.label()).append(": ").append(why).append('\n');
            System.out.printf("fuzz %s: %d cases, %.1f s%n", t.label(), cases, (System.nanoTime() - t0) / 1e9);
        }
        assertEquals("", failures.toString());
    }

    /**
     * Fresh seeds that a switch from Gauss–Seidel to Jacobi-PCG took over the energy bound: the switch solves
     * the cloth further than the sweeps did, finds it stretched and lets the stretch go as speed (1002797:
     * 1.9 MJ of strain after six steps, 94 J of kinetic energy, then 8 kJ in the first step under Jacobi-PCG;
     * 1003447: 23 J of strain, then 12.7 J of kinetic energy where gravity gave 10.8 J). Within the bound now
     * that a switch's strain is credited ({@link Plausibility#switchedSolver}); both failed before.
     */
    @Test
    void speedFromTheStrainASolverSwitchLetsGoIsWithinTheBound() {
        for (long seed : new long[] {1002797, 1003447}) assertNull(Fuzz.runCase(seed, SolverType.GAUSS_SEIDEL, true), "seed " + seed);
    }

    /** Random presets with every field drawn across its documented range, edges included. */
    /**
     * The engine fuzzer adds wind and runs two threads (it used to do neither), and draws what the engine
     * has beyond springs and solids, each in about one case of four: a fabric membrane, aerodynamics,
     * self-collision and a floor (it drew none of them before the hostile-input report).
     */
    @Test
    void theFuzzerDrawsWindThreadsAndEveryEngineFeature() {
        int wind = 0, threads = 0, aerodynamics = 0, fabric = 0, self = 0, floor = 0, cases = 200;
        for (long seed = 0; seed < cases; seed++) {
            xpbdcloth.engine.Simulation sim = Fuzz.build(new java.util.Random(seed), null, SolverType.GAUSS_SEIDEL);
            for (xpbdcloth.engine.ExternalForce f : sim.forces()) {
                if (f instanceof xpbdcloth.engine.Wind) wind++;
                if (f instanceof xpbdcloth.engine.Aerodynamics) aerodynamics++;
            }
            if (sim.settings().threads() > 1) threads++;
            for (xpbdcloth.engine.Constraint c : sim.constraints())
                if (c.family() == xpbdcloth.engine.ConstraintFamily.MEMBRANE) { fabric++; break; }
            if (sim.selfCollision() != null) self++;
            if (!sim.planes().isEmpty()) floor++;
            sim.close();
        }
        assertTrue(wind >= 20 && wind <= 90, "wind in about one case of four: " + wind);
        assertTrue(threads >= 6 && threads <= 40, "two threads in about one case of ten: " + threads);
        // A fabric and aerodynamics need a cloth with area (not a rope or a line of particles): fewer than one in four.
        assertTrue(fabric >= 15 && fabric <= 60, "a fabric in about one case of four with area: " + fabric);
        assertTrue(aerodynamics >= 15 && aerodynamics <= 60, "aerodynamics in about one case of four with area: " + aerodynamics);
        assertTrue(self >= 20 && self <= 80, "self-collision in about one case of four: " + self);
        assertTrue(floor >= 30 && floor <= 70, "a floor in about one case of four: " + floor);
    }

    static int structural(xpbdcloth.engine.Simulation sim) {
        int n = 0;
        for (xpbdcloth.engine.Constraint c : sim.constraints()) if (c.family() == xpbdcloth.engine.ConstraintFamily.STRUCTURAL) n++;
        return n;
    }

    /**
     * One case in three is a triangle mesh (the global solvers had never been fuzzed on one, and the
     * multigrid was broken there): the same draws, more structural edges (the diagonals).
     */
    @Test
    void theFuzzerDrawsTriangleMeshes() {
        int drawn = 0, meshes = 0;
        for (long seed = 1; seed <= 300; seed++) {
            if (!Fuzz.drawsTriangles(seed)) continue;
            drawn++;
            xpbdcloth.engine.Simulation grid = Fuzz.build(new java.util.Random(seed), null, SolverType.GAUSS_SEIDEL, false);
            xpbdcloth.engine.Simulation mesh = Fuzz.build(new java.util.Random(seed), null, SolverType.GAUSS_SEIDEL, true);
            int gridEdges = structural(grid), meshEdges = structural(mesh);
            assertEquals(grid.particles().count(), mesh.particles().count(), "seed " + seed + ": the same vertices");
            if (meshEdges > gridEdges) meshes++;
            grid.close();
            mesh.close();
        }
        assertTrue(drawn >= 70 && drawn <= 130, "a triangle mesh in about one case of three: " + drawn + " of 300");
        assertTrue(meshes >= drawn / 2, "cases that are really triangle meshes (some have no area): " + meshes + " of " + drawn);
    }

    /**
     * The preset fuzzer draws every field the loader reads: the fields are taken from the loader's own
     * lists of the keys each object may have (its Set.of(…) and List.of(…) calls), not written out here, so
     * a field added to the loader and not to the fuzzer fails this test. The fabric catalogue's own fields
     * (a different file) are left out.
     */
    @Test
    void thePresetFuzzerDrawsEveryFieldTheLoaderReads() throws Exception {
        String loader = java.nio.file.Files.readString(java.nio.file.Path.of("src/xpbdcloth/scene/PresetLoader.java"));
        java.util.Set<String> fields = new java.util.TreeSet<>();
        java.util.regex.Matcher list = java.util.regex.Pattern.compile("(?:Set|List)\\.of\\(([^)]*)\\)").matcher(loader);
        while (list.find()) {
            java.util.regex.Matcher word = java.util.regex.Pattern.compile("\"([a-zA-Z]+)\"").matcher(list.group(1));
            while (word.find()) fields.add(word.group(1));
        }
        fields.removeAll(java.util.Set.of("fabrics", "source", "sample", "stretching", "bending", "stretchingCurve", "bendingCurve"));
        fields.removeAll(xpbdcloth.scene.PresetLoader.BUILT_IN); // the list of scene names, not fields
        assertTrue(fields.size() > 60, "the loader's fields: " + fields);
        java.util.Set<String> drawn = new java.util.TreeSet<>();
        for (long seed = 1; seed <= 400; seed++) {
            java.util.regex.Matcher key = java.util.regex.Pattern.compile("\"([a-zA-Z]+)\"\\s*:").matcher(PresetFuzz.text(seed));
            while (key.find()) drawn.add(key.group(1));
        }
        java.util.Set<String> missing = new java.util.TreeSet<>(fields);
        missing.removeAll(drawn);
        assertEquals(java.util.Set.of(), missing, "fields the loader reads that no fuzz case draws");
    }

    @Test
    void fuzzPresets() {
        StringBuilder failures = new StringBuilder();
        long t0 = System.nanoTime();
        for (long seed = 1; seed <= 100; seed++) {
            String why = Fuzz.runPresetCase(seed);
            if (why != null) failures.append(why).append('\n');
        }
        System.out.printf("fuzz presets: 100 cases, %.1f s%n", (System.nanoTime() - t0) / 1e9);
        assertEquals("", failures.toString());
    }
}
