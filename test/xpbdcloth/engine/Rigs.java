package xpbdcloth.engine;

/** Small scenes the engine tests share. */
final class Rigs {
    private Rigs() {}

    static final double G = 9.81;

    /** A pinned particle at the origin with a particle of mass m hanging at rest length L below it. */
    static Simulation spring(double mass, double restLength, SolverSettings settings, double stiffness, double compliance) {
        Particles p = new Particles(2);
        p.setPosition(0, 0, 0, 0);
        p.setPosition(1, 0, -restLength, 0);
        p.setMass(1, mass);
        p.pin(0);
        DistanceConstraint c = DistanceConstraint.between(p, 0, 1);
        c.setStiffness(stiffness);
        c.setCompliance(compliance);
        return new Simulation(p, settings).add(c);
    }

    /** A vertical chain of {@code links} links of length L, each particle of mass m, the top one pinned. */
    static Simulation chain(int links, double mass, double restLength, SolverSettings settings, double stiffness, double compliance) {
        Particles p = new Particles(links + 1);
        for (int i = 0; i <= links; i++) {
            p.setPosition(i, 0, -i * restLength, 0);
            p.setMass(i, mass);
        }
        p.pin(0);
        Simulation sim = new Simulation(p, settings);
        for (int i = 0; i < links; i++) {
            DistanceConstraint c = DistanceConstraint.between(p, i, i + 1);
            c.setStiffness(stiffness);
            c.setCompliance(compliance);
            sim.add(c);
        }
        return sim;
    }

    /**
     * A 32 × 32 cloth with all three families and one sphere, like the shipped scenes: hanging from its
     * top corners with a sphere passing through it, or lying flat and dropped on a sphere spinning about y.
     */
    static Simulation clothWithSphere(boolean spinning) {
        ClothBuilder b = new ClothBuilder().resolution(32, 32).arealDensity(0.2)
                .family(ConstraintFamily.STRUCTURAL, 1.0, 1e-6).family(ConstraintFamily.SHEAR, 0.5, 1e-3).family(ConstraintFamily.BEND, 0.1, 1e-2);
        if (spinning) b.size(1.2, 1.2).plane(ClothBuilder.Plane.HORIZONTAL).origin(0, 1.4, 0);
        else b.size(1, 1).origin(0, 1.6, 0).pinTopCorners();
        Simulation sim = b.build().simulation(new SolverSettings().withSubsteps(10));
        if (spinning) sim.add(new Sphere(SpherePath.fixed(0, 0.9, 0), 0.3, 0.01, 0.8, 0.6).spin(0, 2, 0));
        else sim.add(new Sphere(SpherePath.linear(0, 1.05, 0.8, 0, 0, -0.25), 0.2, 0.01, 0.5, 0.35));
        return sim;
    }

    /** Runs until the largest speed falls below {@code speed} m/s or maxSteps pass; returns steps run. */
    static int settle(Simulation sim, double speed, int maxSteps) {
        Particles p = sim.particles();
        for (int s = 1; s <= maxSteps; s++) {
            sim.step();
            double max = 0;
            for (int i = 0; i < p.count(); i++)
                max = Math.max(max, Math.abs(p.vx(i)) + Math.abs(p.vy(i)) + Math.abs(p.vz(i)));
            if (max < speed && s > 10) return s;
        }
        return maxSteps;
    }

    /** Distance from the chain's top to its bottom particle minus the rest length of all links. */
    static double totalExtension(Simulation sim, int links, double restLength) {
        Particles p = sim.particles();
        return p.y(0) - p.y(links) - links * restLength;
    }
}
