package xpbdcloth.tools;

import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.Metrics;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SimulationDivergedException;
import xpbdcloth.scene.Scene;

/**
 * Runs scenes for many steps and checks the promise of position-based dynamics: nothing blows up.
 * {@code gradle soak} runs corners and spinning-sphere for 100 000 steps each, prints one summary line
 * per scene and exits non-zero on any violation; the test suite runs a short version.
 */
@Command(name = "soak", mixinStandardHelpOptions = true, showDefaultValues = true, description = "Long runs that must stay finite and bounded.")
public final class Soak implements Callable<Integer> {
    /** Largest structural strain a scene may reach during a soak (the stated bound). */
    public static final double MAX_STRAIN = 0.5;
    /** Largest rise of mechanical energy (kinetic + gravitational) above its start, J. */
    public static final double MAX_ENERGY_RISE = 1.0;

    /** What a soak measured. */
    public static final class Result {
        public final String scene;
        public final long steps;
        public final boolean finite;
        /** Steps the engine undid because they went non-finite (each one a failure). */
        public final int divergences;
        public final double maxStrain, energyStart, energyMin, energyMax;

        Result(String scene, long steps, boolean finite, int divergences, double maxStrain, double energyStart, double energyMin, double energyMax) {
            this.scene = scene; this.steps = steps; this.finite = finite; this.divergences = divergences; this.maxStrain = maxStrain;
            this.energyStart = energyStart; this.energyMin = energyMin; this.energyMax = energyMax;
        }

        public boolean ok() { return finite && divergences == 0 && maxStrain < MAX_STRAIN && energyMax - energyStart < MAX_ENERGY_RISE; }

        @Override public String toString() {
            return String.format(Locale.ROOT, "soak %s: %d steps, finite %b, divergences %d, max strain %.4f (bound %.2f), energy start %.4f J, min %.4f J, max %.4f J (rise %.4f, bound %.1f J): %s",
                    scene, steps, finite, divergences, maxStrain, MAX_STRAIN, energyStart, energyMin, energyMax, energyMax - energyStart, MAX_ENERGY_RISE, ok() ? "OK" : "FAILED");
        }
    }

    static double energy(Simulation sim) {
        return Metrics.kineticEnergy(sim.particles()) + Metrics.gravitationalEnergy(sim.particles(), sim.settings());
    }

    /** Steps a built-in scene {@code steps} times; strain and energy are sampled every step. */
    public static Result run(String scene, long steps) {
        Simulation sim = Scene.builtIn(scene).simulation();
        double e0 = energy(sim), eMin = e0, eMax = e0, maxStrain = 0;
        boolean finite = true;
        int divergences = 0;
        for (long s = 0; s < steps && finite; s++) {
            try {
                sim.step();
            } catch (SimulationDivergedException e) {
                System.out.println("soak " + scene + ": " + e.getMessage());
                divergences++;
                break; // the state is restored, so stepping on would only repeat the same step
            }
            finite = Metrics.allFinite(sim.particles());
            maxStrain = Math.max(maxStrain, Metrics.maxStrain(sim, ConstraintFamily.STRUCTURAL));
            double e = energy(sim);
            eMin = Math.min(eMin, e);
            eMax = Math.max(eMax, e);
        }
        return new Result(scene, steps, finite, divergences, maxStrain, e0, eMin, eMax);
    }

    @Option(names = "--steps", description = "steps per scene", defaultValue = "100000")
    long steps;

    @Option(names = "--scenes", split = ",", description = "scenes to soak", defaultValue = "corners,spinning-sphere")
    java.util.List<String> scenes;

    public static void main(String[] args) {
        System.exit(new CommandLine(new Soak()).execute(args));
    }

    @Override public Integer call() {
        if (steps < 1) throw new IllegalArgumentException("steps must be >= 1, was " + steps);
        boolean ok = true;
        for (String s : scenes) {
            long t0 = System.nanoTime();
            Result r = run(s, steps);
            System.out.println(r + String.format(Locale.ROOT, " (%.0f s)", (System.nanoTime() - t0) / 1e9));
            ok &= r.ok();
        }
        // The self-collision measure: crossing triangle pairs of drop-fold over its 10 s, with and without.
        long t0 = System.nanoTime();
        int[] on = dropFold(true, 500), off = dropFold(false, 500);
        System.out.printf(Locale.ROOT, "soak drop-fold: 500 steps, crossing triangle pairs with self-collision at most %d (%d steps with any), without at most %d (%d steps): %s (%.0f s)%n",
                on[0], on[1], off[0], off[1], on[0] == 0 ? "OK" : "FAILED", (System.nanoTime() - t0) / 1e9);
        return ok && on[0] == 0 ? 0 : 1;
    }

    /**
     * The built-in drop-fold scene for {@code steps} steps, with its self-collision or without: after every
     * step, the pairs of vertex-disjoint triangles that pass through each other. Returns {most in a step, steps with any}.
     */
    public static int[] dropFold(boolean selfCollision, int steps) {
        xpbdcloth.scene.Scene scene = xpbdcloth.scene.Scene.builtIn("drop-fold");
        if (!selfCollision) scene.simulation().selfCollision(null);
        int worst = 0, stepsWithAny = 0;
        for (int s = 0; s < steps; s++) {
            scene.simulation().step();
            int c = xpbdcloth.mesh.TriangleIntersections.count(scene.cloth().particles().positions(), scene.cloth().triangles());
            worst = Math.max(worst, c);
            if (c > 0) stepsWithAny++;
        }
        return new int[] {worst, stepsWithAny};
    }
}
