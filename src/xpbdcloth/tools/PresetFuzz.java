package xpbdcloth.tools;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import xpbdcloth.engine.Metrics;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.SimulationDivergedException;
import xpbdcloth.scene.Limits;
import xpbdcloth.scene.PresetException;
import xpbdcloth.scene.PresetLoader;
import xpbdcloth.scene.Scene;

/**
 * Random preset files: every numeric field drawn across its {@link Limits} range, an edge of the range
 * one time in four, the whole scene loaded and stepped; it must stay finite. One case in five also puts
 * one field just outside its range, and the loader must refuse it naming that field and the range.
 *
 * <p>What is not drawn jointly: a case's work (particles × iterations × substeps × steps) is held under
 * a budget so a case costs a fraction of a second, so the largest cloths run with few sweeps and the
 * most sweeps run on small cloths; global solvers are drawn on cloths up to 32 × 32.
 */
final class PresetFuzz {
    private PresetFuzz() {}

    /** Particle-sweeps a case may cost over all its steps (a global iteration counts 100 sweeps). */
    static final double WORK_BUDGET = 3e6;

    /** One case: null if it passed, else why not. */
    static String runCase(long seed) {
        Random r = new Random(seed);
        Case c = new Case(r);
        String text = c.json();
        if (c.brokenField != null) {
            try {
                PresetLoader.parse("fuzz.json", text);
                return "preset seed " + seed + ": " + c.brokenField + " outside its range was accepted";
            } catch (PresetException e) {
                if (!e.field().equals(c.brokenField) || !e.problem().contains(c.brokenRange))
                    return "preset seed " + seed + ": expected " + c.brokenField + " " + c.brokenRange + ", got " + e.getMessage();
                return null;
            }
        }
        try {
            Simulation sim = Scene.of(PresetLoader.parse("fuzz.json", text)).simulation();
            for (int s = 0; s < c.steps; s++) sim.step();
            return Metrics.allFinite(sim.particles()) ? null : "preset seed " + seed + ": non-finite";
        } catch (SimulationDivergedException e) {
            return "preset seed " + seed + ": diverged: " + e.getMessage() + "\n" + text;
        } catch (RuntimeException | Error e) {
            return "preset seed " + seed + ": " + e + "\n" + text;
        }
    }

    /** A drawn preset. Fields are written in the order the README documents them. */
    private static final class Case {
        final Random r;
        final List<String[]> numbers = new ArrayList<>(); // {path, value}
        String brokenField, brokenRange;
        int steps;
        final StringBuilder json = new StringBuilder();

        Case(Random r) { this.r = r; }

        /** Uniform in the range, or one of its edges one time in four; log-uniform for positive ranges. */
        double draw(Limits.Range range, boolean log) {
            if (r.nextInt(4) == 0) return r.nextBoolean() ? range.lo : range.hi;
            if (log && range.lo > 0) return Math.exp(Math.log(range.lo) + r.nextDouble() * (Math.log(range.hi) - Math.log(range.lo)));
            return range.lo + r.nextDouble() * (range.hi - range.lo);
        }

        String num(double v) { return Double.toString(v); }

        /** A collider's path: fixed, linear, circle or oscillation. */
        String path() {
            switch (r.nextInt(4)) {
                case 0: return "{ \"type\": \"fixed\", \"centre\": " + vec(Limits.POSITION) + " }";
                case 1: return "{ \"type\": \"linear\", \"start\": " + vec(Limits.POSITION) + ", \"velocity\": " + vec(Limits.SPEED) + " }";
                case 2: return "{ \"type\": \"circle\", \"centre\": " + vec(Limits.POSITION) + ", \"radius\": " + num(draw(Limits.PATH_RADIUS, false))
                        + ", \"angularSpeed\": " + num(draw(Limits.ANGULAR_SPEED, false)) + " }";
                default: return "{ \"type\": \"oscillation\", \"centre\": " + vec(Limits.POSITION) + ", \"amplitude\": " + vec(Limits.DISPLACEMENT)
                        + ", \"frequency\": " + num(draw(Limits.FREQUENCY, false)) + " }";
            }
        }

        String vec(Limits.Range range) { return "[" + num(draw(range, false)) + ", " + num(draw(range, false)) + ", " + num(draw(range, false)) + "]"; }

        String json() {
            boolean global = r.nextInt(3) == 0;
            int maxSide = global ? 32 : (int) Limits.RESOLUTION.hi;
            int columns = (int) Math.round(Math.min(maxSide, draw(Limits.RESOLUTION, true)));
            int rows = (int) Math.round(Math.min(maxSide, draw(Limits.RESOLUTION, true)));
            if (columns * rows < 2) rows = 2;
            double width = columns > 1 ? draw(Limits.SIZE, true) : 0, height = rows > 1 ? draw(Limits.SIZE, true) : 0;
            boolean byDensity = r.nextBoolean();
            double density = draw(Limits.AREAL_DENSITY, true), mass = draw(Limits.TOTAL_MASS, true);
            boolean pbd = !global && r.nextBoolean();
            int iterations = (int) Math.round(draw(Limits.ITERATIONS, true)), substeps = (int) Math.round(draw(Limits.SUBSTEPS, true));
            double dt = draw(Limits.DT, true);
            long particles = (long) columns * rows;
            double budget = global ? WORK_BUDGET / 100 : WORK_BUDGET;
            while (particles * (double) iterations * substeps > budget && iterations * substeps > 1) {
                if (iterations >= substeps) iterations = Math.max(1, iterations / 2); else substeps = Math.max(1, substeps / 2);
            }
            steps = (int) Math.max(1, Math.min(20, budget / (particles * (double) iterations * substeps)));

            json.append("{ \"name\": \"fuzz\", \"cloth\": { \"columns\": ").append(columns).append(", \"rows\": ").append(rows)
                .append(", \"width\": ").append(num(width)).append(", \"height\": ").append(num(height))
                .append(", \"plane\": \"").append(r.nextBoolean() ? "vertical" : "horizontal").append("\", \"origin\": ").append(vec(Limits.POSITION))
                .append(byDensity ? ", \"arealDensity\": " + num(density) : ", \"totalMass\": " + num(mass))
                .append(", \"pins\": [");
            String[] pinNames = {"top-left", "top-right", "bottom-left", "bottom-right", "top-edge", "left-edge"};
            int pins = r.nextInt(4);
            List<String> corners = new ArrayList<>();
            for (int k = 0; k < pins; k++) {
                String p = pinNames[r.nextInt(pinNames.length)];
                json.append(k == 0 ? "" : ", ").append('"').append(p).append('"');
                if (!p.endsWith("edge")) corners.add(p);
            }
            json.append("] }, \"families\": { ");
            String[] families = {"structural", "shear", "bend"};
            boolean first = true;
            for (String f : families) {
                if (!f.equals("structural") && r.nextBoolean()) continue;
                double alpha = r.nextInt(5) == 0 ? 0 : draw(new LogCompliance().range, true);
                json.append(first ? "" : ", ").append('"').append(f).append("\": { \"stiffness\": ").append(num(draw(Limits.STIFFNESS, false)))
                    .append(", \"compliance\": ").append(num(alpha)).append(" }");
                first = false;
            }
            json.append(" }, \"solver\": { \"mode\": \"").append(pbd ? "PBD" : "XPBD").append("\", \"iterations\": ").append(iterations)
                .append(", \"substeps\": ").append(substeps).append(", \"dt\": ").append(num(dt))
                .append(", \"mullerCorrection\": ").append(r.nextBoolean()).append(", \"gravity\": ").append(vec(Limits.GRAVITY))
                .append(", \"damping\": ").append(num(draw(Limits.DAMPING, false)))
                .append(", \"type\": \"").append(global ? (r.nextBoolean() ? "jacobi-pcg" : "multigrid-pcg") : "gauss-seidel").append("\" }");
            // A collider's margin is half the cloth's thickness, which may not exceed the cloth's spacing.
            double halfEdge = 0.5 * Math.min(columns > 1 ? width / (columns - 1) : Double.POSITIVE_INFINITY, rows > 1 ? height / (rows - 1) : Double.POSITIVE_INFINITY);
            int spheres = r.nextInt(3);
            if (spheres > 0) {
                json.append(", \"spheres\": [");
                for (int k = 0; k < spheres; k++) {
                    json.append(k == 0 ? "" : ", ").append("{ \"radius\": ").append(num(draw(Limits.SPHERE_RADIUS, true)))
                        .append(", \"margin\": ").append(num(Math.min(halfEdge, draw(Limits.MARGIN, false))))
                        .append(", \"staticFriction\": ").append(num(draw(Limits.FRICTION, false)))
                        .append(", \"kineticFriction\": ").append(num(draw(Limits.FRICTION, false)))
                        .append(", \"angularVelocity\": ").append(vec(Limits.ANGULAR_VELOCITY)).append(", \"path\": ").append(path()).append(" }");
                }
                json.append("]");
            }
            int solids = r.nextInt(3);
            if (solids > 0) {
                json.append(", \"colliders\": [");
                for (int k = 0; k < solids; k++) {
                    json.append(k == 0 ? "" : ", ");
                    if (r.nextBoolean()) json.append("{ \"type\": \"box\", \"halfExtents\": ").append(vec(Limits.SPHERE_RADIUS)).append(", \"rotation\": ").append(vec(Limits.ROTATION));
                    else json.append("{ \"type\": \"capsule\", \"axis\": [0, ").append(num(0.5 + 0.5 * r.nextDouble())).append(", ").append(num(r.nextDouble() - 0.5))
                            .append("], \"halfLength\": ").append(num(draw(Limits.PATH_RADIUS, false))).append(", \"radius\": ").append(num(draw(Limits.SPHERE_RADIUS, true)));
                    json.append(", \"margin\": ").append(num(Math.min(halfEdge, draw(Limits.MARGIN, false))))
                        .append(", \"staticFriction\": ").append(num(draw(Limits.FRICTION, false)))
                        .append(", \"kineticFriction\": ").append(num(draw(Limits.FRICTION, false)))
                        .append(", \"angularVelocity\": ").append(vec(Limits.ANGULAR_VELOCITY)).append(", \"path\": ").append(path()).append(" }");
                }
                json.append("]");
            }
            if (!corners.isEmpty() && r.nextBoolean()) {
                json.append(", \"pinMotions\": [{ \"pin\": \"").append(corners.get(0)).append("\", \"displacement\": ").append(vec(Limits.DISPLACEMENT))
                    .append(", \"start\": ").append(num(r.nextInt(4) == 0 ? 0 : draw(Limits.START_TIME, true) * 1e-6))
                    .append(", \"duration\": ").append(num(draw(Limits.DURATION, true))).append(" }]");
            }
            if (r.nextBoolean()) {
                double drag = draw(Limits.DRAG, false);
                json.append(", \"wind\": { \"velocity\": ").append(vec(Limits.WIND_SPEED)).append(", \"drag\": ").append(num(drag))
                    .append(", \"gust\": ").append(num(draw(Limits.GUST, false))).append(" }");
            }
            json.append(" }");
            if (r.nextInt(5) == 0) breakOneField();
            return json.toString();
        }

        /** Puts one field just outside its range. */
        void breakOneField() {
            String[][] fields = {
                    {"solver.dt", "\"dt\": ", Limits.DT.text(), "1e-300"},
                    {"solver.dt", "\"dt\": ", Limits.DT.text(), "0.2"},
                    {"solver.iterations", "\"iterations\": ", Limits.ITERATIONS.text(), "1001"},
                    {"solver.substeps", "\"substeps\": ", Limits.SUBSTEPS.text(), "0"},
                    {"solver.damping", "\"damping\": ", Limits.DAMPING.text(), "-1"},
                    {"solver.gravity[0]", "\"gravity\": [", Limits.GRAVITY.text(), "-1e6"},
                    {"cloth.origin[0]", "\"origin\": [", Limits.POSITION.text(), "1e5"},
                    {"families.structural.compliance", "\"structural\": { \"stiffness\": ", Limits.COMPLIANCE.text(), null},
                    {"cloth.columns", "\"columns\": ", Limits.RESOLUTION.text(), "513"},
            };
            String[] f = fields[r.nextInt(fields.length)];
            int at = json.indexOf(f[1]);
            if (f[3] == null) {
                int c = json.indexOf("\"compliance\": ", at) + "\"compliance\": ".length();
                int end = json.indexOf(" ", c);
                json.replace(c, end, "1e6");
            } else {
                int from = at + f[1].length();
                int end = from;
                while (end < json.length() && "0123456789.eE+-".indexOf(json.charAt(end)) >= 0) end++;
                json.replace(from, end, f[3]);
            }
            brokenField = f[0];
            brokenRange = f[2];
        }
    }

    /** Compliance drawn log-uniformly from the smallest non-zero value the sketch offers to the maximum. */
    private static final class LogCompliance {
        final Limits.Range range = new Limits.Range(Limits.SMALLEST_NONZERO_COMPLIANCE, Limits.COMPLIANCE.hi, "m/N");
    }

    static String summary(int cases, long seed, int failed, double seconds) {
        return String.format(Locale.ROOT, "fuzz presets: %d cases from seed %d, %d failed, %.1f s", cases, seed, failed, seconds);
    }
}
