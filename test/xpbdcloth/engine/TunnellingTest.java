package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import java.util.function.DoubleSupplier;
import org.junit.jupiter.api.Test;

/** A fast collider does not pass through the cloth between two substeps, nor fast cloth through a thin collider. */
class TunnellingTest {
    /** What a collider sweeps: whether world (x, y) lies in its footprint across its motion along −z. */
    interface Footprint { boolean covers(double x, double y); }

    /**
     * A 5 cm collider at 20 m/s through a hanging 32² cloth, dt = 1/60 s, one substep: it jumps 33 cm a
     * step, more than its diameter. No particle goes through it: none that was ahead of its centre at the
     * start of a step is behind it at the end inside its footprint (the collider carries what it meets;
     * cloth that went round it and trails behind it is not counted). Returns the particles that went
     * through, over the run.
     */
    static int particlesLeftBehind(String name, java.util.function.Consumer<Simulation> addCollider, DoubleSupplier centreZ, Footprint footprint) {
        Cloth c = new ClothBuilder().resolution(32, 32).size(1, 1).origin(-0.5, 1.6, 0).arealDensity(0.2).pinTopCorners()
                .family(ConstraintFamily.STRUCTURAL, 1, 1e-6).family(ConstraintFamily.SHEAR, 0.5, 1e-3).family(ConstraintFamily.BEND, 0.1, 1e-2).build();
        Simulation sim = c.simulation(new SolverSettings().withIterations(2).withSubsteps(1).withTimestep(1 / 60.0));
        addCollider.accept(sim);
        Particles p = c.particles();
        int through = 0, carried = 0;
        double[] ahead = new double[p.count()];
        for (int step = 0; step < 6; step++) {
            for (int i = 0; i < p.count(); i++) ahead[i] = centreZ.getAsDouble() - p.z(i);
            sim.step();
            for (int i = 0; i < p.count(); i++) {
                if (!footprint.covers(p.x(i), p.y(i)) || ahead[i] <= 0) continue;
                if (p.z(i) > centreZ.getAsDouble() + 1e-9) through++;
                else carried++;
            }
        }
        System.out.printf("%s at 20 m/s through a hanging cloth: %d particles went through, %d carried%n", name, through, carried);
        return through;
    }

    static final double R = 0.05 + 0.005; // radius + margin

    @Test
    void aFastSphereCarriesTheClothInsteadOfPassingThrough() {
        Sphere s = new Sphere(SpherePath.linear(0.013, 1.1, 0.5, 0, 0, -20), 0.05, 0.005, 0.5, 0.4);
        assertEquals(0, particlesLeftBehind("sphere", sim -> sim.add(s), s::centreZ,
                (x, y) -> Math.hypot(x - s.centreX(), y - s.centreY()) < R));
    }

    /** The same for a capsule lying across the cloth (axis along x, 30 cm long between its caps' centres). */
    @Test
    void aFastCapsuleCarriesTheClothInsteadOfPassingThrough() {
        Capsule s = new Capsule(SpherePath.linear(0.013, 1.1, 0.5, 0, 0, -20), new double[] {1, 0, 0}, 0.15, 0.05, 0.005, 0.5, 0.4);
        assertEquals(0, particlesLeftBehind("capsule", sim -> sim.add(s), s::centreZ,
                (x, y) -> Math.hypot(Math.max(0, Math.abs(x - s.centreX()) - 0.15), y - s.centreY()) < R));
    }

    /**
     * A horizontal 32² cloth thrown down at 10 m/s onto a board 1 cm thick (half extents 0.4 × 0.005 ×
     * 0.4 m; the cloth overhangs it by 10 cm), at the shipped scenes' 2 sweeps and 2 ms substeps (stepped
     * substep by substep, dt = 2 ms: the same arithmetic as 10 substeps of a 20 ms step under gravity, and
     * every substep seen): a particle falls 2 cm a substep, twice the board's thickness. For 1 s, no
     * particle over the board is ever inside it, nor crosses from above it to below it between two
     * substeps. (The overhang whips round the edges and under the board; that is going round, not through.)
     */
    @Test
    void clothFallingFastOntoAThinBoardNeverGoesThroughIt() {
        int[] r = thrownAtABoard(sim -> sim.add(new Box(SpherePath.fixed(0, 0.5, 0), new double[] {0.4, 0.005, 0.4}, new double[3], 0.005, 0.5, 0.4)), 0.505, 0.495);
        System.out.printf("cloth at 10 m/s onto a 1 cm board: %d particle-substeps inside it, %d crossings through it%n", r[0], r[1]);
        assertEquals(0, r[0], "inside the board");
        assertEquals(0, r[1], "through the board");
    }

    /**
     * A horizontal 32² cloth thrown down at 10 m/s, substep by substep at 2 ms, for 1 s at a board over
     * |x|, |z| &lt; 0.4 whose faces are at y = top and y = bottom (equal for a sheet of no thickness, whose
     * margin is 5 mm): returns {particle-substeps over the board inside it (for a sheet: within 0.9 of the
     * margin), crossings from above it to below it or back, counted across any substeps spent inside}.
     */
    static int[] thrownAtABoard(java.util.function.Consumer<Simulation> board, double top, double bottom) {
        Cloth c = new ClothBuilder().resolution(32, 32).size(1, 1).plane(ClothBuilder.Plane.HORIZONTAL).origin(0, 0.8, 0).arealDensity(0.2)
                .family(ConstraintFamily.STRUCTURAL, 1, 1e-6).family(ConstraintFamily.SHEAR, 0.5, 1e-3).family(ConstraintFamily.BEND, 0.1, 1e-2).build();
        Simulation sim = c.simulation(new SolverSettings().withIterations(2).withSubsteps(1).withTimestep(0.002));
        board.accept(sim);
        Particles p = c.particles();
        for (int i = 0; i < p.count(); i++) p.setVelocity(i, 0, -10, 0);
        int[] side = new int[p.count()]; // +1 over the board above it, -1 under it, 0 elsewhere or not yet seen
        int inside = 0, crossed = 0;
        for (int substep = 0; substep < 500; substep++) {
            sim.step();
            for (int i = 0; i < p.count(); i++) {
                boolean over = Math.abs(p.x(i)) < 0.4 && Math.abs(p.z(i)) < 0.4;
                int now = !over ? 0 : p.y(i) >= top ? 1 : p.y(i) <= bottom ? -1 : 2;
                if (now == 2 || (top == bottom && over && Math.abs(p.y(i) - top) < 0.9 * 0.005)) inside++;
                if (now != 0 && now != 2 && side[i] != 0 && now != side[i]) crossed++;
                side[i] = now == 2 ? side[i] : now;
            }
        }
        return new int[] {inside, crossed};
    }
}
