package xpbdcloth.tools;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import xpbdcloth.engine.AttachmentConstraint;
import xpbdcloth.engine.Box;
import xpbdcloth.engine.Capsule;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.ConstraintMode;
import xpbdcloth.engine.EngineRange;
import xpbdcloth.engine.MeshClothBuilder;
import xpbdcloth.engine.Metrics;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SimulationDivergedException;
import xpbdcloth.engine.SolverSettings;
import xpbdcloth.engine.SolverType;
import xpbdcloth.engine.Sphere;
import xpbdcloth.engine.SpherePath;
import xpbdcloth.engine.Wind;
import xpbdcloth.mesh.ClothMesh;

/**
 * Seeded random simulations: sizes, pins, families, k, α, iterations, substeps, dt, damping, masses from
 * 1e-6 to 1e3 kg, fast and spinning spheres, boxes and capsules, wind, two threads, grabbed particles,
 * switches of mode and solver, and in one case of ten an illegal parameter; on top, each in one case of
 * four, a measured-fabric membrane and bending, aerodynamics, self-collision and a floor ({@link #addExtras}).
 * Every case must end with finite positions, or, for the illegal one, with an IllegalArgumentException
 * that names the parameter and its value. A failing case prints its seed; {@code --seed} replays it.
 */
@Command(name = "fuzz", mixinStandardHelpOptions = true, showDefaultValues = true, description = "Random simulations that must stay finite.")
public final class Fuzz implements Callable<Integer> {

    /** One case's outcome with the solver drawn from its seed: null if it passed, else why it failed. */
    public static String runCase(long seed) { return runCase(seed, null); }

    /**
     * One case's outcome: null if it passed, else why it failed. {@code solver} forces the solver the
     * case starts with (null: drawn from the seed like everything else). Mid-run the case may switch
     * mode and solver; a switch the settings must refuse (PBD with a global solver) is tried too, and
     * must be refused with a message naming the parameter while changing nothing.
     */
    public static String runCase(long seed, SolverType solver) { return runCase(seed, solver, false); }

    /** The standard deviation of a grabbing hand's speed on each axis, m/s: a quick flick of the wrist. */
    static final double HAND_SPEED = 5;

    /**
     * The same; with {@code plausible}, a case whose kinetic energy exceeds what gravity and its drivers can
     * have given ({@link Plausibility}) fails too. The CI cases run with it; from seeds beyond them it still
     * finds cases vertex block descent does not meet (docs/robustness.md).
     */
    public static String runCase(long seed, SolverType solver, boolean plausible) {
        Random r = new Random(seed);
        String[] illegal = r.nextInt(10) == 0 ? pickIllegal(r) : null;
        Simulation sim = null;
        try {
            double[] drive = new double[1];
            sim = build(r, illegal, solver, drawsTriangles(seed), drive);
            Plausibility bound = new Plausibility(sim);
            AttachmentConstraint grab = null;
            int steps = 10 + r.nextInt(40);
            // A mode switch changes the cloth's energy function under load (PBD's k has none, XPBD's α another):
            // like stiffening a loaded spring it does work the bound does not count, so the bound judges a case
            // up to its first switch (and up to a hold inside a solid, below).
            boolean judged = plausible;
            for (int k = 0; k < steps; k++) {
                if (grab == null && r.nextInt(8) == 0) {
                    int i = r.nextInt(sim.particles().count());
                    // A particle flung beyond the engine's range (finite, but 1e9 m away) cannot be grabbed:
                    // the target is refused, as it should be, so the fuzzer grabs only what is in range.
                    if (inRange(sim.particles(), i)) grab = sim.attach(i, sim.particles().x(i), sim.particles().y(i), sim.particles().z(i));
                }
                if (grab != null) {
                    // A hand's move in a step: up to about 5 cm, as fast as a hand goes (a step of 10 µs moving 5 cm
                    // would be a hand at 5 km/s, whose work no bound can credit as a user's).
                    double reach = Math.min(0.05, HAND_SPEED * sim.settings().timestep());
                    double dx = r.nextGaussian() * reach, dy = r.nextGaussian() * reach;
                    grab.moveTarget(grab.targetX() + dx, grab.targetY() + dy, grab.targetZ()); // its work is counted by the engine
                }
                if (grab != null && r.nextInt(10) == 0) { sim.release(grab); grab = null; }
                if (r.nextInt(20) == 0) {
                    ConstraintMode before = sim.settings().mode();
                    String refused = switchMode(sim);
                    if (refused != null) return "seed " + seed + ": " + refused;
                    if (sim.settings().mode() != before) judged = false;
                }
                if (r.nextInt(20) == 0) {
                    SolverType to = SolverType.values()[r.nextInt(3)];
                    SolverType from = sim.settings().solver();
                    if (to != SolverType.GAUSS_SEIDEL) sim.settings(capForGlobal(sim.settings()));
                    String refused = switchSolver(sim, to);
                    if (refused != null) return "seed " + seed + ": " + refused;
                    // The new solver may solve the cloth further and let go of the strain the old one left: credited.
                    if (sim.settings().solver() != from) bound.switchedSolver();
                }
                // A pin or a hand holding cloth inside a solid: the two fight through the cloth with no bound on the
                // work they do (Simulation.heldInsideColliders), so the bound judges a case up to that too.
                if (judged && sim.heldInsideColliders() > 0) judged = false;
                sim.step();
                if (judged && sim.heldInsideColliders() > 0) judged = false;
                String implausible = judged ? bound.check(drive[0]) : null;
                if (implausible != null && illegal == null) return "seed " + seed + ": step " + (k + 1) + ": " + implausible + " [" + describe(sim) + "]";
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
        } catch (SimulationDivergedException e) {
            return "seed " + seed + ": diverged: " + e.getMessage();
        } catch (RuntimeException | Error e) {
            return "seed " + seed + ": " + e;
        } finally {
            if (sim != null) sim.close(); // a failed case must not leave its helper threads behind
        }
    }

    /** The mode, solver and families of a case (for a report). */
    static String describe(Simulation sim) {
        java.util.Set<String> families = new java.util.TreeSet<>();
        for (xpbdcloth.engine.ConstraintBlock b : sim.blocks()) families.add(b.family().name().toLowerCase(Locale.ROOT));
        return sim.settings().mode() + " " + sim.settings().solver().label() + " " + families + (sim.selfCollision() != null ? " self" : "")
                + (sim.colliderCount() > 0 ? " colliders " + sim.colliderCount() : "");
    }

    /** One case in three is a triangle mesh, decided apart from the case's own draws so that they stay the seed's. */
    static boolean drawsTriangles(long seed) { return new Random(~seed).nextInt(3) == 0; }

    /** Whether particle i is within the engine's position range (so a grab target there is legal). */
    private static boolean inRange(xpbdcloth.engine.Particles p, int i) {
        double max = xpbdcloth.engine.EngineRange.MAX_POSITION;
        return Math.abs(p.x(i)) < max && Math.abs(p.y(i)) < max && Math.abs(p.z(i)) < max;
    }

    /** A global iteration is a whole linear solve: at most 10 × 10 of them per step, so a case costs < 1 s. */
    static SolverSettings capForGlobal(SolverSettings s) {
        return s.withIterations(Math.min(s.iterations(), 10)).withSubsteps(Math.min(s.substeps(), 10));
    }

    /** PBD ⇄ XPBD; to PBD under a global solver must be refused, naming the mode. Returns why the refusal was wrong, or null. */
    static String switchMode(Simulation sim) {
        SolverSettings s = sim.settings();
        ConstraintMode to = s.mode() == ConstraintMode.PBD ? ConstraintMode.XPBD : ConstraintMode.PBD;
        if (to == ConstraintMode.PBD && s.solver() != SolverType.GAUSS_SEIDEL) {
            try {
                s.withMode(to);
                return "PBD under " + s.solver().label() + " was accepted";
            } catch (IllegalArgumentException e) {
                return e.getMessage().startsWith("mode") ? null : "refusal of PBD: " + e.getMessage();
            }
        }
        sim.settings(s.withMode(to));
        return null;
    }

    /** Switches the solver; a global solver in PBD mode must be refused, naming the solver. Returns why the refusal was wrong, or null. */
    static String switchSolver(Simulation sim, SolverType to) {
        SolverSettings s = sim.settings();
        if (to != SolverType.GAUSS_SEIDEL && s.mode() == ConstraintMode.PBD) {
            try {
                s.withSolver(to);
                return to.label() + " in PBD mode was accepted";
            } catch (IllegalArgumentException e) {
                return e.getMessage().startsWith("solver") ? null : "refusal of " + to.label() + ": " + e.getMessage();
            }
        }
        sim.settings(s.withSolver(to));
        return null;
    }

    /** {parameter name as the message gives it, value as the message prints it}. */
    static String[] pickIllegal(Random r) {
        String[][] choices = {
                {"iterations", "0"}, {"substeps", "-3"}, {"dt", "NaN"}, {"dt", "-0.01"}, {"stiffness", "1.5"},
                {"compliance", "-1.0E-6"}, {"compliance", "NaN"}, {"mass", "-1.0"}, {"radius", "0.0"},
                {"arealDensity", "Infinity"}, {"gravity.y", "NaN"}, {"pin row", "99"}, {"staticFriction", "-0.5"},
                {"damping", "-2.0"}};
        return choices[r.nextInt(choices.length)];
    }

    static double logUniform(Random r, double lo, double hi) {
        return Math.exp(Math.log(lo) + r.nextDouble() * (Math.log(hi) - Math.log(lo)));
    }

    static double bad(String[] illegal, String name, double good) {
        return illegal != null && illegal[0].equals(name) ? Double.parseDouble(illegal[1]) : good;
    }

    static Simulation build(Random r, String[] illegal, SolverType forced) { return build(r, illegal, forced, false); }

    /**
     * {@code triangles}: a cloth with area and no illegal parameter is built as a triangle mesh (the same
     * grid's triangles through {@link MeshClothBuilder}, the same families, pins and density) instead of
     * a grid; every other draw is the same, so a seed's grid case and its triangle case differ only there.
     */
    static Simulation build(Random r, String[] illegal, SolverType forced, boolean triangles) { return build(r, illegal, forced, triangles, new double[1]); }

    /** The same, with {@code drive[0]} set to the fastest any collider's surface, the wind or the air moves ({@link Plausibility}). */
    static Simulation build(Random r, String[] illegal, SolverType forced, boolean triangles, double[] drive) {
        int columns = 1 + r.nextInt(12), rows = 2 + r.nextInt(11);
        double width = r.nextInt(10) == 0 ? 0 : 2 * r.nextDouble(), height = r.nextInt(10) == 0 ? 0 : 2 * r.nextDouble();
        ClothBuilder b = new ClothBuilder().resolution(columns, rows).size(width, height)
                .plane(r.nextBoolean() ? ClothBuilder.Plane.VERTICAL : ClothBuilder.Plane.HORIZONTAL)
                .origin(r.nextGaussian(), 1 + r.nextDouble(), r.nextGaussian());
        double density = bad(illegal, "arealDensity", logUniform(r, 1e-3, 10));
        b.arealDensity(density);
        // A zero-area cloth (all particles on a line or a point) has no area to spread a density over.
        boolean flat = (columns > 1 && width == 0) || (rows > 1 && height == 0);
        if (flat) b.totalMass(logUniform(r, 1e-3, 10));
        boolean asTriangles = triangles && illegal == null && !flat && columns > 1 && rows > 1;
        MeshClothBuilder mb = asTriangles ? new MeshClothBuilder(trianglesOf(b.mesh())).arealDensity(density) : null;
        for (ConstraintFamily f : new ConstraintFamily[] {ConstraintFamily.STRUCTURAL, ConstraintFamily.SHEAR, ConstraintFamily.BEND}) {
            if (f != ConstraintFamily.STRUCTURAL && r.nextBoolean()) continue;
            double alpha = r.nextInt(5) == 0 ? 0 : logUniform(r, 1e-10, 1e3);
            double k = bad(illegal, "stiffness", r.nextDouble());
            b.family(f, k, bad(illegal, "compliance", alpha));
            if (mb != null) mb.family(f, k, alpha);
        }
        int pins = r.nextInt(5);
        for (int k = 0; k < pins; k++) {
            int row = r.nextInt(rows), col = r.nextInt(columns);
            b.pin(row, col);
            if (mb != null) mb.pin(row * columns + col);
        }
        if (illegal != null && illegal[0].equals("pin row")) b.pin(99, 0);
        Cloth cloth = mb != null ? mb.build() : b.build();
        Particles p = cloth.particles();
        if (r.nextInt(4) == 0) for (int i = 0; i < p.count(); i++) p.setMass(i, logUniform(r, 1e-6, 1e3));
        if (illegal != null && illegal[0].equals("mass")) p.setMass(0, -1);
        SolverType solver = SolverType.values()[r.nextInt(3)];
        if (forced != null) solver = forced;
        ConstraintMode mode = r.nextBoolean() ? ConstraintMode.PBD : ConstraintMode.XPBD;
        if (solver != SolverType.GAUSS_SEIDEL) mode = ConstraintMode.XPBD;
        SolverSettings s = new SolverSettings()
                .withMode(mode)
                .withSolver(solver)
                // Up to 1000 sweeps or up to 100 substeps, not both, so a case costs milliseconds.
                .withIterations(illegal != null && illegal[0].equals("iterations") ? 0 : r.nextInt(20) == 0 ? 200 + r.nextInt(800) : 1 + r.nextInt(30))
                .withSubsteps(illegal != null && illegal[0].equals("substeps") ? -3 : 1 + r.nextInt(r.nextInt(10) == 0 ? 100 : 10))
                .withTimestep(bad(illegal, "dt", logUniform(r, 1e-5, 0.1)))
                .withMullerCorrection(r.nextBoolean())
                .withGravity(0, bad(illegal, "gravity.y", -9.81), 0)
                .withDamping(bad(illegal, "damping", r.nextInt(4) == 0 ? logUniform(r, 1e-3, EngineRange.MAX_DAMPING) : 0));
        if (s.iterations() > 30) s = s.withSubsteps(1);
        else if (s.substeps() > 10) s = s.withIterations(Math.min(s.iterations(), 3));
        if (solver != SolverType.GAUSS_SEIDEL) s = capForGlobal(s);
        Simulation sim = cloth.simulation(s);
        int spheres = r.nextInt(3);
        for (int k = 0; k < spheres; k++) {
            double cx = r.nextGaussian(), cy = r.nextDouble() * 2, cz = r.nextGaussian();
            SpherePath path;
            double pathSpeed;
            switch (r.nextInt(4)) {
                case 0: path = SpherePath.fixed(cx, cy, cz); pathSpeed = 0; break;
                case 1: {
                    double vx = 100 * r.nextGaussian(), vy = 10 * r.nextGaussian(), vz = 100 * r.nextGaussian();
                    path = SpherePath.linear(cx, cy, cz, vx, vy, vz);
                    pathSpeed = Math.sqrt(vx * vx + vy * vy + vz * vz);
                    break;
                }
                case 2: {
                    double radius = r.nextDouble(), angular = 100 * r.nextGaussian();
                    path = SpherePath.circle(cx, cy, cz, radius, angular);
                    pathSpeed = radius * Math.abs(angular);
                    break;
                }
                default: {
                    double ax = r.nextDouble(), ay = r.nextDouble(), az = r.nextDouble(), f = 10 * r.nextDouble();
                    path = SpherePath.oscillation(cx, cy, cz, ax, ay, az, f);
                    pathSpeed = 2 * Math.PI * f * Math.sqrt(ax * ax + ay * ay + az * az);
                }
            }
            int kind = r.nextInt(3);
            // An illegal radius is drawn for a sphere or a capsule, whose size is a radius (a box's is named halfExtents).
            if (kind == 1 && illegal != null && illegal[0].equals("radius")) kind = 2;
            double size = bad(illegal, "radius", 0.05 + r.nextDouble()), margin = 0.01 * r.nextDouble();
            double mus = bad(illegal, "staticFriction", 2 * r.nextDouble()), muk = 2 * r.nextDouble();
            double wx = 100 * r.nextGaussian(), wy = 100 * r.nextGaussian(), wz = 100 * r.nextGaussian();
            // The surface's fastest point: the path's speed, the spin times the farthest reach from the centre
            // (a box's corner, a capsule's cap), and the speed it pushes out a particle found inside it.
            double reach = 2 * Math.abs(size) + 0.01;
            drive[0] = Math.max(drive[0], pathSpeed + Math.sqrt(wx * wx + wy * wy + wz * wz) * reach + xpbdcloth.engine.Collider.MAX_DEPENETRATION_SPEED);
            // A sphere, a box or a capsule of about that size, on that path, spinning.
            switch (kind) {
                case 0: sim.add(new Sphere(path, size, margin, mus, muk).spin(wx, wy, wz)); break;
                case 1: sim.add(new Box(path, new double[] {size, size * r.nextDouble() + 1e-3, size}, new double[] {360 * r.nextDouble(), 360 * r.nextDouble(), 0}, margin, mus, muk).spin(wx, wy, wz)); break;
                default: sim.add(new Capsule(path, new double[] {r.nextGaussian(), r.nextGaussian() + 1e-3, r.nextGaussian()}, size * r.nextDouble(), size, margin, mus, muk).spin(wx, wy, wz));
            }
        }
        // Wind in one case of four (within the presets' ranges), two threads in one of ten.
        if (r.nextInt(4) == 0) {
            Wind wind = new Wind(cloth.triangles(), 20 * r.nextGaussian(), 5 * r.nextGaussian(), 20 * r.nextGaussian(), 10 * r.nextDouble(), r.nextDouble());
            sim.add(wind);
            double u = Math.sqrt(wind.velocityX() * wind.velocityX() + wind.velocityY() * wind.velocityY() + wind.velocityZ() * wind.velocityZ());
            drive[0] = Math.max(drive[0], u * (1 + wind.gust()));
        }
        if (r.nextInt(10) == 0) sim.settings(s.withThreads(2));
        if (illegal == null) drive[0] = Math.max(drive[0], addExtras(new Random(extrasSeed(r)), cloth, sim));
        if (illegal != null && illegal[0].equals("radius") && spheres == 0) new Sphere(SpherePath.fixed(0, 0, 0), 0, 0, 0, 0);
        if (illegal != null && illegal[0].equals("staticFriction") && spheres == 0) new Sphere(SpherePath.fixed(0, 0, 0), 1, 0, -0.5, 0);
        return sim;
    }

    /**
     * The seed of a case's later features, drawn once from the case's stream so that the draws above stay
     * what they were for every seed (a failing seed from before still replays its cloth, solver and colliders).
     */
    private static long extrasSeed(Random r) { return r.nextLong(); }

    /**
     * What the engine has beyond springs and solids, each in one case of four: a measured-fabric membrane
     * with its bending (on a cloth with triangles; in one of two yielding, in one of two stiffening as a
     * catalogue fabric's measured curve), aerodynamic drag and lift, self-collision, and a fixed
     * plane (a floor, tilted); the ranges are the presets' ({@link xpbdcloth.scene.Limits}). Returns the
     * fastest they drive the cloth: the air's speed, a floor's push-out speed.
     */
    static double addExtras(Random r, Cloth cloth, Simulation sim) {
        double drive = 0;
        int[] triangles = cloth.triangles();
        boolean area = triangles != null && triangles.length > 0 && hasArea(cloth.particles(), triangles);
        if (area && r.nextInt(4) == 0) {
            double e1 = logUniform(r, 1e-1, 1e7), e2 = logUniform(r, 1e-1, 1e7);
            // |ν12| < √(E1/E2) for a positive-definite stiffness.
            double nu = (2 * r.nextDouble() - 1) * 0.9 * Math.min(0.99, Math.sqrt(e1 / e2));
            xpbdcloth.engine.OrthotropicMaterial membrane = new xpbdcloth.engine.OrthotropicMaterial(e1, e2, nu, logUniform(r, 1e-1, 1e7));
            double angle = 2 * Math.PI * r.nextDouble();
            double[] warp = cloth.particles().count() > 0 ? inPlane(cloth.particles(), triangles, angle) : new double[] {1, 0, 0};
            double bending = logUniform(r, 1e-6, 1);
            boolean tethers = r.nextBoolean();
            // Bending that yields in one fabric of two, drawn from a stream of its own so the case's other draws stay.
            Random own = new Random(Double.doubleToLongBits(e1) ^ Double.doubleToLongBits(bending));
            boolean yielding = own.nextBoolean();
            for (xpbdcloth.engine.ConstraintBlock b : xpbdcloth.fabric.FabricConstraints.build(cloth.particles(), triangles, warp, membrane,
                    bending, tethers, yielding))
                sim.add(b);
            boolean hinges = false;
            for (xpbdcloth.engine.ConstraintBlock b : sim.blocks()) hinges |= b instanceof xpbdcloth.engine.DihedralBlock;
            if (yielding && hinges)
                sim.add(new xpbdcloth.engine.HingePlasticity(sim.blocks(), cloth.particles(), logUniform(own, 0.1, 1e4), logUniform(own, 1e-4, 1e4)));
            // A measured fabric's stiffening in one of two, from the same stream.
            if (own.nextBoolean()) {
                java.util.List<xpbdcloth.fabric.Fabric> catalogue = xpbdcloth.scene.FabricCatalogue.all();
                xpbdcloth.fabric.StretchingCurve curve = catalogue.get(own.nextInt(catalogue.size())).stretchingCurve;
                if (curve != null) sim.add(new xpbdcloth.fabric.MeasuredStiffening(sim.blocks(), curve));
            }
            // Dihedral hinges following a measured bending curve in one of two such cases, from the same stream.
            boolean fabricHinges = false;
            for (xpbdcloth.engine.ConstraintBlock b : sim.blocks())
                fabricHinges |= b instanceof xpbdcloth.engine.DihedralBlock && b.family() == xpbdcloth.engine.ConstraintFamily.DIHEDRAL;
            if (fabricHinges && own.nextBoolean()) {
                java.util.List<xpbdcloth.fabric.Fabric> catalogue = xpbdcloth.scene.FabricCatalogue.all();
                sim.add(new xpbdcloth.fabric.MeasuredBending(sim.blocks(), cloth.particles(), triangles, warp, catalogue.get(own.nextInt(catalogue.size())).bendingCurve));
            }
        }
        if (area && r.nextInt(4) == 0) {
            xpbdcloth.engine.Aerodynamics air = new xpbdcloth.engine.Aerodynamics(triangles, logUniform(r, 1e-3, 1e3), 10 * r.nextDouble(), 10 * r.nextDouble());
            double ax = 30 * r.nextGaussian(), ay = 10 * r.nextGaussian(), az = 30 * r.nextGaussian();
            sim.add(air.air(ax, ay, az));
            drive = Math.sqrt(ax * ax + ay * ay + az * az);
        }
        if (r.nextInt(4) == 0) {
            double edge = cloth.mesh().shortestEdge();
            // At most the shortest edge, as the loader demands, and in the presets' range (a line of particles has no face to measure).
            double most = Math.min(edge, 1);
            if (most >= 1e-4) {
                double thickness = Math.max(1e-4, most * r.nextDouble()), staticFriction = 2 * r.nextDouble(), kineticFriction = 2 * r.nextDouble();
                // The continuous triangle guard in one such case of two, drawn from a stream of its own so that
                // the case's other draws stay what they were.
                boolean continuous = cloth.triangles().length > 0 && new Random(Double.doubleToLongBits(thickness)).nextBoolean();
                // The untangler likewise, from another stream of its own, in one case of two with triangles.
                boolean untangle = cloth.triangles().length > 0 && new Random(~Double.doubleToLongBits(thickness)).nextBoolean();
                xpbdcloth.engine.SelfCollision self = new xpbdcloth.engine.SelfCollision(cloth.mesh().positions(), continuous ? cloth.triangles() : null,
                        thickness, staticFriction, kineticFriction);
                // Point–triangle contacts likewise, from a third stream.
                if (cloth.triangles().length > 0 && new Random(Double.doubleToLongBits(thickness) ^ 0x9E3779B97F4A7C15L).nextBoolean())
                    self.withPointTriangle(cloth.triangles());
                sim.selfCollision(untangle ? self.untangling(cloth.triangles()) : self);
            }
        }
        if (r.nextInt(4) == 0) {
            sim.add(new xpbdcloth.engine.Plane(new double[] {0, 2 * r.nextDouble() - 0.5, 0},
                    new double[] {0.3 * r.nextGaussian(), 1, 0.3 * r.nextGaussian()}, 0.01 * r.nextDouble(), 2 * r.nextDouble(), 2 * r.nextDouble()));
            drive = Math.max(drive, xpbdcloth.engine.Collider.MAX_DEPENETRATION_SPEED); // a cloth that starts under it
        }
        return drive;
    }

    /** Whether any triangle has area (a grid of zero width or height has none, and a fabric needs some). */
    private static boolean hasArea(Particles p, int[] t) {
        for (int k = 0; k < t.length; k += 3) if (triangleArea(p, t[k], t[k + 1], t[k + 2]) > 1e-12) return true;
        return false;
    }

    private static double triangleArea(Particles p, int a, int b, int c) {
        double ux = p.x(b) - p.x(a), uy = p.y(b) - p.y(a), uz = p.z(b) - p.z(a);
        double vx = p.x(c) - p.x(a), vy = p.y(c) - p.y(a), vz = p.z(c) - p.z(a);
        double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
        return 0.5 * Math.sqrt(nx * nx + ny * ny + nz * nz);
    }

    /** A warp at {@code angle} in the plane of the cloth's first triangle with area. */
    private static double[] inPlane(Particles p, int[] t, double angle) {
        for (int k = 0; k < t.length; k += 3) {
            if (triangleArea(p, t[k], t[k + 1], t[k + 2]) <= 1e-12) continue;
            int a = t[k], b = t[k + 1], c = t[k + 2];
            double[] u = {p.x(b) - p.x(a), p.y(b) - p.y(a), p.z(b) - p.z(a)}, v = {p.x(c) - p.x(a), p.y(c) - p.y(a), p.z(c) - p.z(a)};
            double[] n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
            double[] w = {n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]};
            double lu = Math.sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]), lw = Math.sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
            double cs = Math.cos(angle) / lu, sn = Math.sin(angle) / lw;
            return new double[] {cs * u[0] + sn * w[0], cs * u[1] + sn * w[1], cs * u[2] + sn * w[2]};
        }
        return new double[] {1, 0, 0};
    }

    /** The mesh's triangles as its faces: a grid's quads become a triangle mesh of the same vertices. */
    static ClothMesh trianglesOf(ClothMesh grid) {
        int[] t = grid.triangles();
        int[][] faces = new int[t.length / 3][];
        for (int k = 0; k < faces.length; k++) faces[k] = new int[] {t[3 * k], t[3 * k + 1], t[3 * k + 2]};
        return ClothMesh.of(grid.positions(), faces, null, null, null);
    }

    @Option(names = "--cases", description = "number of cases per solver (1 to 10 000 000)", defaultValue = "1000")
    int cases;

    @Option(names = "--seed", description = "first seed (replay a failing case with --seed S --cases 1)", defaultValue = "1")
    long seed;

    @Option(names = "--solver", description = "all (every case once per solver) or one of gauss-seidel, jacobi-pcg, multigrid-pcg, vertex-block-descent", defaultValue = "all")
    String solver;

    @Option(names = "--plausible", description = "also fail a case whose kinetic energy exceeds what gravity and its drivers can give")
    boolean plausible;

    @Option(names = "--presets", description = "random preset files to load and step (0 to 10 000 000)", defaultValue = "300")
    int presets;

    public static void main(String[] args) {
        System.exit(new CommandLine(new Fuzz()).execute(args));
    }

    private CommandLine.ParameterException bad(String message) { return new CommandLine.ParameterException(spec.commandLine(), message); }

    /** One preset case (see {@link PresetFuzz}): null if it passed, else why not. */
    public static String runPresetCase(long seed) { return PresetFuzz.runCase(seed); }

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override public Integer call() {
        // Every option is checked before any case runs: a bad --presets must not wait for the engine cases.
        if (cases < 1 || cases > 10_000_000) throw bad("--cases must be in [1, 10000000], was " + cases);
        if (presets < 0 || presets > 10_000_000) throw bad("--presets must be in [0, 10000000], was " + presets);
        if (seed > Long.MAX_VALUE - Math.max(cases, presets))
            throw bad("--seed must be <= " + (Long.MAX_VALUE - Math.max(cases, presets)) + " so that seed + cases does not overflow, was " + seed);
        List<SolverType> solvers = new ArrayList<>();
        for (SolverType t : SolverType.values()) if (solver.equals("all") || solver.equals(t.label())) solvers.add(t);
        if (solvers.isEmpty()) throw bad("--solver must be all, gauss-seidel, jacobi-pcg, multigrid-pcg or vertex-block-descent, was " + solver);
        int failed = 0;
        long ran = 0;
        for (SolverType t : solvers) {
            long t0 = System.nanoTime();
            int failedHere = 0;
            for (long k = 0; k < cases; k++) {
                String why = runCase(seed + k, t, plausible);
                ran++;
                if (why != null) { System.out.println(t.label() + ": " + why); failedHere++; }
            }
            System.out.printf(Locale.ROOT, "fuzz %s: %d cases from seed %d, %d failed, %.1f s%n", t.label(), cases, seed, failedHere, (System.nanoTime() - t0) / 1e9);
            failed += failedHere;
        }
        long t0 = System.nanoTime();
        int failedPresets = 0;
        for (long k = 0; k < presets; k++) {
            String why = PresetFuzz.runCase(seed + k);
            ran++;
            if (why != null) { System.out.println(why); failedPresets++; }
        }
        System.out.println(PresetFuzz.summary(presets, seed, failedPresets, (System.nanoTime() - t0) / 1e9));
        failed += failedPresets;
        if (ran != (long) cases * solvers.size() + presets) {
            System.out.println("fuzz: ran " + ran + " cases, asked for " + ((long) cases * solvers.size() + presets));
            return 1;
        }
        return failed == 0 ? 0 : 1;
    }
}
