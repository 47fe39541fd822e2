package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import java.util.Random;
import java.util.function.Function;
import org.junit.jupiter.api.Test;

/** Each constraint: C = 0 in its rest shape, and its analytical ∇C matches central differences. */
class GradientTest {

    static Particles randomParticles(int n, long seed) {
        Random r = new Random(seed);
        Particles p = new Particles(n);
        for (int i = 0; i < n; i++) p.setPosition(i, r.nextDouble(), r.nextDouble(), r.nextDouble());
        return p;
    }

    static void assertGradientMatchesDifferences(Constraint c, Particles p) {
        assertGradientMatchesDifferences(c.getClass().getSimpleName(), c.particles(), c::evaluate, c::gradient, p);
    }

    static void assertGradientMatchesDifferences(SphereContact c, Particles p) {
        assertGradientMatchesDifferences("SphereContact", c.particles(), c::evaluate, c::gradient, p);
    }

    static void assertGradientMatchesDifferences(String name, int[] ids, java.util.function.ToDoubleFunction<Particles> value,
            java.util.function.BiConsumer<Particles, double[]> gradient, Particles p) {
        double[] g = new double[3 * ids.length];
        gradient.accept(p, g);
        double eps = 1e-6;
        for (int j = 0; j < ids.length; j++)
            for (int a = 0; a < 3; a++) {
                double[] x = p.positions();
                int k = 3 * ids[j] + a;
                double keep = x[k];
                x[k] = keep + eps;
                double plus = value.applyAsDouble(p);
                x[k] = keep - eps;
                double minus = value.applyAsDouble(p);
                x[k] = keep;
                double fd = (plus - minus) / (2 * eps);
                assertEquals(fd, g[3 * j + a], 1e-6, name + " dC/dx[" + j + "][" + a + "]");
            }
    }

    @Test
    void distance() {
        for (long seed = 0; seed < 20; seed++) {
            Particles p = randomParticles(2, seed);
            DistanceConstraint c = new DistanceConstraint(ConstraintFamily.STRUCTURAL, 0, 1, 0.3);
            assertGradientMatchesDifferences(c, p);
            assertEquals(0.0, DistanceConstraint.between(p, 0, 1).evaluate(p), 1e-15);
        }
    }

    @Test
    void shear() {
        for (long seed = 0; seed < 20; seed++) {
            Particles p = randomParticles(3, seed);
            ShearConstraint c = new ShearConstraint(ConstraintFamily.SHEAR, 0, 1, 2, Math.PI / 2);
            assertGradientMatchesDifferences(c, p);
            assertEquals(0.0, ShearConstraint.atCurrentAngle(ConstraintFamily.SHEAR, p, 0, 1, 2).evaluate(p), 1e-12);
        }
    }

    @Test
    void bend() {
        for (long seed = 0; seed < 20; seed++) {
            Particles p = randomParticles(3, seed);
            BendConstraint c = new BendConstraint(ConstraintFamily.BEND, 0, 1, 2, 0.05);
            assertGradientMatchesDifferences(c, p);
            assertEquals(0.0, BendConstraint.atCurrentShape(ConstraintFamily.BEND, p, 0, 1, 2).evaluate(p), 1e-15);
        }
    }

    @Test
    void sphereAndAttachment() {
        for (long seed = 0; seed < 20; seed++) {
            Particles p = randomParticles(1, seed);
            Sphere s = new Sphere(SpherePath.fixed(0.2, 0.3, 0.1), 0.25, 0.01, 0.5, 0.3);
            assertGradientMatchesDifferences(new SphereContact(0, s), p);
            assertGradientMatchesDifferences(new AttachmentConstraint(0, 0.9, -0.2, 0.4), p);
        }
    }

    /**
     * One projection of each constraint moves its particles along ∇C and at least halves |C| (PBD, k = 1).
     * Not to zero: the projection solves the linearised constraint, and the angle is far from linear.
     */
    @Test
    void projectionReducesViolation() {
        SolverContext ctx = new SolverContext();
        ctx.load(new SolverSettings().withMode(ConstraintMode.PBD).withIterations(1), 0.01);
        Function<Particles, Constraint[]> make = p -> new Constraint[] {
                new DistanceConstraint(ConstraintFamily.STRUCTURAL, 0, 1, 0.3),
                new ShearConstraint(ConstraintFamily.SHEAR, 0, 1, 2, 1.2),
                new BendConstraint(ConstraintFamily.BEND, 0, 1, 2, 0.05)};
        for (long seed = 0; seed < 20; seed++) {
            Particles p = randomParticles(3, seed);
            for (Constraint c : make.apply(p)) {
                double before = Math.abs(c.evaluate(p));
                c.beginSubstep(ctx);
                c.project(p, ctx);
                double after = Math.abs(c.evaluate(p));
                assertTrue(after < 0.5 * before + 1e-12, c.getClass().getSimpleName() + " " + before + " -> " + after);
            }
        }
    }
}
