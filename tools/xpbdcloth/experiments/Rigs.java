package xpbdcloth.experiments;

import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.DistanceConstraint;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SolverSettings;

/** The rigs the experiments measure, and how they measure a steady state. */
public final class Rigs {
    private Rigs() {}

    public static final double G = 9.81;

    /** One solver configuration: mode, k (PBD), α (XPBD), n sweeps, s substeps, dt, Müller's correction. */
    public static final class Solver {
        public final ConstraintMode mode;
        public final double stiffness, compliance, dt;
        public final int iterations, substeps;
        public final boolean muller;

        public Solver(ConstraintMode mode, double stiffness, double compliance, int iterations, int substeps, double dt, boolean muller) {
            this.mode = mode; this.stiffness = stiffness; this.compliance = compliance;
            this.iterations = iterations; this.substeps = substeps; this.dt = dt; this.muller = muller;
        }

        SolverSettings settings() {
            return new SolverSettings().withMode(mode).withIterations(iterations).withSubsteps(substeps).withTimestep(dt).withMullerCorrection(muller);
        }
    }

    /** A vertical chain of {@code links} links of rest length L, each particle of mass m, the top pinned. */
    public static Simulation chain(int links, double restLength, double mass, Solver s) {
        Particles p = new Particles(links + 1);
        for (int i = 0; i <= links; i++) {
            p.setPosition(i, 0, -i * restLength, 0);
            p.setMass(i, mass);
        }
        p.pin(0);
        Simulation sim = new Simulation(p, s.settings());
        for (int i = 0; i < links; i++) {
            DistanceConstraint c = DistanceConstraint.between(p, i, i + 1);
            c.setStiffness(s.stiffness);
            c.setCompliance(s.compliance);
            sim.add(c);
        }
        return sim;
    }

    /** A res×res vertical cloth of size × size m, 0.2 kg/m², structural edges only, pinned at its two top corners. */
    public static Cloth hangingCloth(int res, double size) {
        return new ClothBuilder().family(ConstraintFamily.STRUCTURAL, 1, 0).resolution(res, res).size(size, size).arealDensity(0.2).pinTopCorners().build();
    }

    public static Simulation hangingCloth(int res, double size, Solver s) {
        Cloth c = hangingCloth(res, size);
        Simulation sim = c.simulation(s.settings());
        sim.setStiffness(ConstraintFamily.STRUCTURAL, s.stiffness);
        sim.setCompliance(ConstraintFamily.STRUCTURAL, s.compliance);
        return sim;
    }

    /** Extension of a chain beyond its rest length (m): top-to-bottom distance − links·L. */
    public static double chainExtension(Simulation sim, int links, double restLength) {
        Particles p = sim.particles();
        return p.y(0) - p.y(links) - links * restLength;
    }

    /** Sag (m): how far the bottom-centre particle of a res×res hanging cloth sits below its rest height. */
    public static double clothSag(Simulation sim, int res, double size) {
        int i = (res - 1) * res + res / 2;
        return -size - sim.particles().y(i);
    }

    /** Something to read off a simulation. */
    @FunctionalInterface
    public interface Probe { double read(Simulation sim); }

    /**
     * Steps for {@code seconds} of simulated time and returns the probe averaged over the last quarter,
     * which smooths the small residual oscillation a lightly damped solver may keep.
     */
    public static double steady(Simulation sim, double seconds, Probe probe) {
        int steps = (int) Math.round(seconds / sim.settings().timestep());
        int from = steps - Math.max(1, steps / 4);
        double sum = 0;
        int n = 0;
        for (int s = 0; s < steps; s++) {
            sim.step();
            if (s >= from) { sum += probe.read(sim); n++; }
        }
        return sum / n;
    }
}
