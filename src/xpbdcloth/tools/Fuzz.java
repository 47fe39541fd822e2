package xpbdcloth.tools;

import java.util.Locale;
import java.util.Random;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import xpbdcloth.engine.AttachmentConstraint;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.Metrics;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SolverSettings;
import xpbdcloth.engine.Sphere;
import xpbdcloth.engine.SpherePath;

/**
 * Seeded random simulations: sizes, pins, families, k, α, iterations, substeps, dt, masses from 1e-6 to
 * 1e3 kg, fast and spinning spheres, grabbed particles, and in one case of ten an illegal parameter.
 * Every case must end with finite positions, or, for the illegal one, with an IllegalArgumentException
 * that names the parameter and its value. A failing case prints its seed; {@code --seed} replays it.
 */
@Command(name = "fuzz", mixinStandardHelpOptions = true, description = "Random simulations that must stay finite.")
public final class Fuzz implements Callable<Integer> {

    /** One case's outcome: null if it passed, else why it failed. */
    public static String runCase(long seed) {
        Random r = new Random(seed);
        String[] illegal = r.nextInt(10) == 0 ? pickIllegal(r) : null;
        try {
            Simulation sim = build(r, illegal);
            AttachmentConstraint grab = null;
            int steps = 10 + r.nextInt(40);
            for (int s = 0; s < steps; s++) {
                if (grab == null && r.nextInt(8) == 0) {
                    int i = r.nextInt(sim.particles().count());
                    grab = sim.attach(i, sim.particles().x(i), sim.particles().y(i), sim.particles().z(i));
                }
                if (grab != null) grab.moveTarget(grab.targetX() + r.nextGaussian() * 0.05, grab.targetY() + r.nextGaussian() * 0.05, grab.targetZ());
                if (grab != null && r.nextInt(10) == 0) { sim.release(grab); grab = null; }
                if (r.nextInt(20) == 0) sim.settings().mode(sim.settings().mode() == ConstraintMode.PBD ? ConstraintMode.XPBD : ConstraintMode.PBD);
                sim.step();
            }
            if (illegal != null) return "seed " + seed + ": illegal " + illegal[0] + " = " + illegal[1] + " was accepted";
            if (!Metrics.allFinite(sim.particles())) return "seed " + seed + ": non-finite position or velocity";
            return null;
        } catch (IllegalArgumentException e) {
            if (illegal == null) return "seed " + seed + ": unexpected " + e.getMessage();
            String m = e.getMessage();
            if (!m.startsWith(illegal[0]) || !m.endsWith(illegal[1]))
                return "seed " + seed + ": message does not name " + illegal[0] + " and " + illegal[1] + ": " + m;
            return null;
        }
    }

    /** {parameter name as the message gives it, value as the message prints it}. */
    static String[] pickIllegal(Random r) {
        String[][] choices = {
                {"iterations", "0"}, {"substeps", "-3"}, {"dt", "NaN"}, {"dt", "-0.01"}, {"stiffness", "1.5"},
                {"compliance", "-1.0E-6"}, {"compliance", "NaN"}, {"mass", "-1.0"}, {"radius", "0.0"},
                {"arealDensity", "Infinity"}, {"gravity.y", "NaN"}, {"pin row", "99"}, {"staticFriction", "-0.5"}};
        return choices[r.nextInt(choices.length)];
    }

    static double logUniform(Random r, double lo, double hi) {
        return Math.exp(Math.log(lo) + r.nextDouble() * (Math.log(hi) - Math.log(lo)));
    }

    static double bad(String[] illegal, String name, double good) {
        return illegal != null && illegal[0].equals(name) ? Double.parseDouble(illegal[1]) : good;
    }

    static Simulation build(Random r, String[] illegal) {
        int columns = 1 + r.nextInt(12), rows = 2 + r.nextInt(11);
        double width = r.nextInt(10) == 0 ? 0 : 2 * r.nextDouble(), height = r.nextInt(10) == 0 ? 0 : 2 * r.nextDouble();
        ClothBuilder b = new ClothBuilder().resolution(columns, rows).size(width, height)
                .plane(r.nextBoolean() ? ClothBuilder.Plane.VERTICAL : ClothBuilder.Plane.HORIZONTAL)
                .origin(r.nextGaussian(), 1 + r.nextDouble(), r.nextGaussian())
                .arealDensity(bad(illegal, "arealDensity", logUniform(r, 1e-3, 10)));
        // A zero-area cloth (all particles on a line or a point) has no area to spread a density over.
        if ((columns > 1 && width == 0) || (rows > 1 && height == 0)) b.totalMass(logUniform(r, 1e-3, 10));
        for (ConstraintFamily f : new ConstraintFamily[] {ConstraintFamily.STRUCTURAL, ConstraintFamily.SHEAR, ConstraintFamily.BEND}) {
            if (f != ConstraintFamily.STRUCTURAL && r.nextBoolean()) continue;
            double alpha = r.nextInt(5) == 0 ? 0 : logUniform(r, 1e-10, 1e3);
            b.family(f, bad(illegal, "stiffness", r.nextDouble()), bad(illegal, "compliance", alpha));
        }
        int pins = r.nextInt(5);
        for (int k = 0; k < pins; k++) b.pin(r.nextInt(rows), r.nextInt(columns));
        if (illegal != null && illegal[0].equals("pin row")) b.pin(99, 0);
        Cloth cloth = b.build();
        Particles p = cloth.particles();
        if (r.nextInt(4) == 0) for (int i = 0; i < p.count(); i++) p.setMass(i, logUniform(r, 1e-6, 1e3));
        if (illegal != null && illegal[0].equals("mass")) p.setMass(0, -1);
        SolverSettings s = new SolverSettings()
                .mode(r.nextBoolean() ? ConstraintMode.PBD : ConstraintMode.XPBD)
                // Up to 1000 sweeps or up to 100 substeps, not both, so a case costs milliseconds.
                .iterations(illegal != null && illegal[0].equals("iterations") ? 0 : r.nextInt(20) == 0 ? 200 + r.nextInt(800) : 1 + r.nextInt(30))
                .substeps(illegal != null && illegal[0].equals("substeps") ? -3 : 1 + r.nextInt(r.nextInt(10) == 0 ? 100 : 10))
                .timestep(bad(illegal, "dt", logUniform(r, 1e-5, 0.1)))
                .mullerCorrection(r.nextBoolean())
                .gravity(0, bad(illegal, "gravity.y", -9.81), 0);
        if (s.iterations() > 30) s.substeps(1);
        else if (s.substeps() > 10) s.iterations(Math.min(s.iterations(), 3));
        Simulation sim = cloth.simulation(s);
        int spheres = r.nextInt(3);
        for (int k = 0; k < spheres; k++) {
            double cx = r.nextGaussian(), cy = r.nextDouble() * 2, cz = r.nextGaussian();
            SpherePath path;
            switch (r.nextInt(4)) {
                case 0: path = SpherePath.fixed(cx, cy, cz); break;
                case 1: path = SpherePath.linear(cx, cy, cz, 100 * r.nextGaussian(), 10 * r.nextGaussian(), 100 * r.nextGaussian()); break;
                case 2: path = SpherePath.circle(cx, cy, cz, r.nextDouble(), 100 * r.nextGaussian()); break;
                default: path = SpherePath.oscillation(cx, cy, cz, r.nextDouble(), r.nextDouble(), r.nextDouble(), 10 * r.nextDouble());
            }
            Sphere sphere = new Sphere(path, bad(illegal, "radius", 0.05 + r.nextDouble()), 0.01 * r.nextDouble(),
                    bad(illegal, "staticFriction", 2 * r.nextDouble()), 2 * r.nextDouble())
                    .spin(100 * r.nextGaussian(), 100 * r.nextGaussian(), 100 * r.nextGaussian());
            sim.add(sphere);
        }
        if (illegal != null && illegal[0].equals("radius") && spheres == 0) new Sphere(SpherePath.fixed(0, 0, 0), 0, 0, 0, 0);
        if (illegal != null && illegal[0].equals("staticFriction") && spheres == 0) new Sphere(SpherePath.fixed(0, 0, 0), 1, 0, -0.5, 0);
        return sim;
    }

    @Option(names = "--cases", description = "number of cases", defaultValue = "1000")
    int cases;

    @Option(names = "--seed", description = "first seed (replay a failing case with --seed S --cases 1)", defaultValue = "1")
    long seed;

    public static void main(String[] args) {
        System.exit(new CommandLine(new Fuzz()).execute(args));
    }

    @Override public Integer call() {
        long t0 = System.nanoTime();
        int failed = 0;
        for (long s = seed; s < seed + cases; s++) {
            String why = runCase(s);
            if (why != null) { System.out.println(why); failed++; }
        }
        System.out.printf(Locale.ROOT, "fuzz: %d cases from seed %d, %d failed, %.1f s%n", cases, seed, failed, (System.nanoTime() - t0) / 1e9);
        return failed == 0 ? 0 : 1;
    }
}
