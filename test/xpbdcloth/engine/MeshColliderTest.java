package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/**
 * A triangle mesh as a collider, held to what the analytic colliders already satisfy: Coulomb's law on a
 * tilted mesh as on the plane, rest without jitter on a mesh table, no particle through a thin plate or a
 * zero-thickness sheet at 10 m/s, no particle inside a closed mesh, and an animated mesh that carries the
 * cloth instead of passing it.
 */
class MeshColliderTest {
    static final double MARGIN = PlaneContactTest.MARGIN;

    /** A closed box mesh (8 vertices, 12 triangles, wound outwards) of half extents e about c. */
    static double[][] boxMesh(double cx, double cy, double cz, double ex, double ey, double ez) {
        double[] v = new double[24];
        for (int k = 0; k < 8; k++) {
            v[3 * k] = cx + ((k & 1) == 0 ? -ex : ex);
            v[3 * k + 1] = cy + ((k & 2) == 0 ? -ey : ey);
            v[3 * k + 2] = cz + ((k & 4) == 0 ? -ez : ez);
        }
        double[] t = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
        return new double[][] {v, t};
    }

    static int[] ints(double[] d) {
        int[] out = new int[d.length];
        for (int i = 0; i < d.length; i++) out[i] = (int) d[i];
        return out;
    }

    /**
     * A horizontal square cloth of n² particles, width w, centred at (x, y, z), 0.2 kg/m², all three spring
     * families, at the shipped scenes' settings (2 sweeps × 10 substeps of a 20 ms step).
     */
    static Simulation lyingCloth(int n, double w, double x, double y, double z, SolverType solver) {
        Cloth c = new ClothBuilder().resolution(n, n).size(w, w).plane(ClothBuilder.Plane.HORIZONTAL).origin(x, y, z).arealDensity(0.2)
                .family(ConstraintFamily.STRUCTURAL, 1, 1e-6).family(ConstraintFamily.SHEAR, 0.5, 1e-3).family(ConstraintFamily.BEND, 0.1, 1e-2).build();
        return c.simulation(new SolverSettings().withIterations(2).withSubsteps(10).withTimestep(0.02).withSolver(solver));
    }

    static MeshCollider box(double cx, double cy, double cz, double ex, double ey, double ez, double muS, double muK) {
        double[][] m = boxMesh(cx, cy, cz, ex, ey, ez);
        return new MeshCollider(SpherePath.fixed(0, 0, 0), m[0], ints(m[1]), null, 0, false, MARGIN, muS, muK);
    }

    @Test
    void aBoxMeshIsClosedAndItsDistanceIsSigned() {
        MeshCollider b = box(0, 0, 0, 0.5, 0.25, 0.5, 0, 0);
        assertTrue(b.closed());
        assertEquals(0.25, b.signedDistance(0, 0.5, 0), 1e-12, "above the top face");
        assertEquals(-0.25, b.signedDistance(0, 0, 0), 1e-12, "at the centre, a quarter metre in");
        assertEquals(Math.sqrt(2) * 0.1, b.signedDistance(0.6, 0.35, 0), 1e-12, "off an edge: distance to the edge");
        assertEquals(-0.05, b.signedDistance(0.45, 0.2, 0.1), 1e-12, "inside near a corner: the nearest face");
        // Wound inwards, the same box is turned outwards.
        double[][] m = boxMesh(0, 0, 0, 0.5, 0.25, 0.5);
        int[] t = ints(m[1]);
        for (int k = 0; k < t.length; k += 3) { int s = t[k + 1]; t[k + 1] = t[k + 2]; t[k + 2] = s; }
        MeshCollider inward = new MeshCollider(SpherePath.fixed(0, 0, 0), m[0], t, null, 0, false, MARGIN, 0, 0);
        assertEquals(-0.25, inward.signedDistance(0, 0, 0), 1e-12);
    }

    @Test
    void theCrossingTestFindsTheExactTimeAndMissesWhatPassesBeside() {
        double[] tri = {0, 0, 0, 1, 0, 0, 0, 0, 1}; // in the plane y = 0
        double[] s = new double[9];
        assertEquals(0.25, TriangleGeometry.firstCoplanarTime(0.2, 0.1, 0.2, 0.2, -0.3, 0.2, tri, tri, 0, 1, 2, 0, s), 1e-12);
        assertEquals(-1, TriangleGeometry.firstCoplanarTime(0.8, 0.1, 0.8, 0.8, -0.3, 0.8, tri, tri, 0, 1, 2, 0, s), "beside the hypotenuse");
        double[] up = {0, 0.4, 0, 1, 0.4, 0, 0, 0.4, 1}; // the triangle rises 0.4 while the point stays at y = 0.1
        assertEquals(0.25, TriangleGeometry.firstCoplanarTime(0.2, 0.1, 0.2, 0.2, 0.1, 0.2, tri, up, 0, 1, 2, 0, s), 1e-12);
        // A triangle turning about its edge on x past a still point: the cubic's root where the plane meets it.
        double[] turned = {0, 0, 0, 1, 0, 0, 0, 1, 0}; // from y = 0 to the plane z = 0
        double t = TriangleGeometry.firstCoplanarTime(0.1, 0.3, 0.3, 0.1, 0.3, 0.3, tri, turned, 0, 1, 2, 0, s);
        assertTrue(t > 0 && t < 1, "the linearly moving corner (0, τ, 1 − τ) sweeps the point's plane at τ = 1/2: " + t);
        assertEquals(0.5, t, 1e-12);
    }

    /** Coulomb on a mesh sloped by θ (two triangles 10 m wide) gives the plane's result within 1 %, on both sides of the friction angle. */
    @Test
    void onATiltedMeshTheClothObeysCoulombAsOnThePlane() {
        double theta = Math.atan(0.7);
        double plane = PlaneContactTest.slideDownSlope(theta, 0.5, 0.3, 1.0);
        double mesh = PlaneContactTest.slideDownSlope(theta, 0.5, 0.3, 1.0, MESH);
        double stays = PlaneContactTest.slideDownSlope(Math.atan(0.4), 0.5, 0.3, 2.0, MESH);
        System.out.printf("tilted mesh: tan θ = 0.7 slid %.4f m (plane %.4f m); tan θ = 0.4 moved %.2e m%n", mesh, plane, stays);
        assertEquals(plane, mesh, 0.01 * plane);
        assertEquals(0, stays, 1e-3);
    }

    /** Two triangles 10 m wide through the origin, tilted by θ like the plane. */
    static final PlaneContactTest.Slope MESH = (sim, theta, muS, muK) -> {
        double tx = Math.cos(theta), ty = -Math.sin(theta);
        double[] v = new double[12];
        double[][] corners = {{-5, -5}, {5, -5}, {5, 5}, {-5, 5}};
        for (int k = 0; k < 4; k++) { v[3 * k] = corners[k][0] * tx; v[3 * k + 1] = corners[k][0] * ty; v[3 * k + 2] = corners[k][1]; }
        sim.add(new MeshCollider(SpherePath.fixed(0, 0, 0), v, new int[] {0, 2, 1, 0, 3, 2}, null, 0, false, MARGIN, muS, muK));
    };

    /**
     * A 32² cloth thrown down at 10 m/s onto a mesh plate 1 cm thick (a closed box mesh, half extents
     * 0.4 × 0.005 × 0.4 m) and, separately, onto a sheet of zero thickness (two triangles), substep by
     * substep at 2 ms (a particle falls 2 cm a substep, twice the plate): for 1 s no particle over the plate
     * ends a substep inside it or on the far side of where it came from.
     */
    @Test
    void clothThrownAtTenMetresASecondGoesThroughNeitherAThinPlateNorASheet() {
        int[] plate = TunnellingTest.thrownAtABoard(sim -> sim.add(box(0, 0.5, 0, 0.4, 0.005, 0.4, 0.5, 0.4)), 0.505, 0.495);
        double[] v = {-0.4, 0.5, -0.4, 0.4, 0.5, -0.4, 0.4, 0.5, 0.4, -0.4, 0.5, 0.4};
        int[] sheet = TunnellingTest.thrownAtABoard(sim -> sim.add(new MeshCollider(SpherePath.fixed(0, 0, 0), v, new int[] {0, 2, 1, 0, 3, 2}, null, 0, false, MARGIN, 0.5, 0.4)), 0.5, 0.5);
        System.out.printf("thrown at 10 m/s onto a 1 cm mesh plate: %d particle-substeps inside, %d crossings; onto a sheet: %d within 0.9 margin, %d crossings%n",
                plate[0], plate[1], sheet[0], sheet[1]);
        assertArrayEquals(new int[] {0, 0}, plate);
        assertArrayEquals(new int[] {0, 0}, sheet);
    }

    /** A 32² cloth dropped from 5 cm onto a mesh table top for 10 s comes to rest: KE below 1e-6 J, none below the top's margin. */
    @Test
    void aClothOnAMeshTableComesToRestWithoutJitter() {
        Simulation sim = lyingCloth(32, 1, 0, 0.55, 0, SolverType.GAUSS_SEIDEL);
        sim.add(box(0, 0.25, 0, 0.6, 0.25, 0.6, 0.5, 0.4));
        Particles p = sim.particles();
        for (int s = 0; s < 500; s++) sim.step();
        double ke = Metrics.kineticEnergy(p), lowest = Double.MAX_VALUE;
        for (int i = 0; i < p.count(); i++) lowest = Math.min(lowest, p.y(i));
        System.out.printf("cloth on a mesh table after 10 s: KE %.2e J, lowest particle %.5f m%n", ke, lowest);
        assertTrue(ke < 1e-6, "kinetic energy " + ke);
        assertTrue(lowest > 0.5 + MARGIN - 1e-6, "none below the top's margin: " + lowest);
    }

    /** A closed UV sphere mesh of radius r about c: rings × segments quads, two triangles each, poles fanned. */
    static MeshCollider uvSphere(double cx, double cy, double cz, double r, int rings, int segments, double muS, double muK) {
        int n = 2 + (rings - 1) * segments;
        double[] v = new double[3 * n];
        v[0] = cx; v[1] = cy + r; v[2] = cz;
        v[3] = cx; v[4] = cy - r; v[5] = cz;
        for (int i = 1; i < rings; i++)
            for (int j = 0; j < segments; j++) {
                double th = Math.PI * i / rings, ph = 2 * Math.PI * j / segments;
                int k = 3 * (2 + (i - 1) * segments + j);
                v[k] = cx + r * Math.sin(th) * Math.cos(ph); v[k + 1] = cy + r * Math.cos(th); v[k + 2] = cz + r * Math.sin(th) * Math.sin(ph);
            }
        java.util.List<Integer> t = new java.util.ArrayList<>();
        for (int j = 0; j < segments; j++) {
            int a = 2 + j, b = 2 + (j + 1) % segments;
            t.addAll(java.util.List.of(0, b, a));
            int la = 2 + (rings - 2) * segments + j, lb = 2 + (rings - 2) * segments + (j + 1) % segments;
            t.addAll(java.util.List.of(1, la, lb));
        }
        for (int i = 1; i < rings - 1; i++)
            for (int j = 0; j < segments; j++) {
                int a = 2 + (i - 1) * segments + j, b = 2 + (i - 1) * segments + (j + 1) % segments, c = a + segments, d = b + segments;
                t.addAll(java.util.List.of(a, b, d, a, d, c));
            }
        int[] tri = new int[t.size()];
        for (int k = 0; k < tri.length; k++) tri[k] = t.get(k);
        return new MeshCollider(SpherePath.fixed(0, 0, 0), v, tri, null, 0, false, MARGIN, muS, muK);
    }

    /**
     * A 32² cloth dropped over a closed sphere mesh (radius 0.3 m, 24 × 48, 2,208 triangles) for 3 s, at
     * the shipped settings (2 × 10, dt = 20 ms): in every step no particle is closer to the mesh than the
     * margin less a tenth of it, and none is inside.
     */
    @Test
    void noParticleEndsAStepInsideAClosedMesh() {
        MeshCollider ball = uvSphere(0, 0.5, 0, 0.3, 24, 48, 0.5, 0.4);
        assertTrue(ball.closed());
        Simulation sim = lyingCloth(32, 1, 0.05, 1.0, 0.03, SolverType.GAUSS_SEIDEL);
        sim.add(ball);
        Particles p = sim.particles();
        double closest = Double.MAX_VALUE;
        int touching = 0;
        for (int s = 0; s < 150; s++) {
            sim.step();
            for (int i = 0; i < p.count(); i++) {
                double d = ball.signedDistance(p.x(i), p.y(i), p.z(i));
                closest = Math.min(closest, d);
                if (s == 149 && d < 2 * MARGIN) touching++;
            }
        }
        System.out.printf("cloth over a sphere mesh for 3 s: closest particle %.5f m from the mesh (margin %.3f), %d resting on it%n", closest, MARGIN, touching);
        assertTrue(touching > 50, "the cloth lies on the ball: " + touching);
        assertTrue(closest >= MARGIN - MARGIN / 10, "closest " + closest);
    }

    /**
     * A plate (a box mesh 1 cm thick) animated by two frames, rising 0.3 m in a second and holding, under a
     * cloth lying on it: it lifts the cloth (mean height 0.3 m higher at the end) and no particle over it is
     * ever below its top plus nine tenths of the margin.
     */
    @Test
    void anAnimatedMeshCarriesTheCloth() {
        double[][] low = boxMesh(0, 0.5, 0, 0.4, 0.005, 0.4), high = boxMesh(0, 0.8, 0, 0.4, 0.005, 0.4);
        MeshCollider plate = new MeshCollider(SpherePath.fixed(0, 0, 0), low[0], ints(low[1]), new double[][] {low[0], high[0]}, 1, false, MARGIN, 0.5, 0.4);
        assertTrue(plate.animated());
        Simulation sim = lyingCloth(16, 0.6, 0, 0.51, 0, SolverType.GAUSS_SEIDEL);
        sim.add(plate);
        Particles p = sim.particles();
        double lowest = Double.MAX_VALUE;
        for (int s = 0; s < 75; s++) {
            sim.step();
            double top = 0.505 + 0.3 * Math.min(1, sim.time());
            for (int i = 0; i < p.count(); i++) lowest = Math.min(lowest, p.y(i) - top);
        }
        double mean = 0;
        for (int i = 0; i < p.count(); i++) mean += p.y(i) / p.count();
        System.out.printf("cloth on a rising mesh plate: mean height %.4f m at 1.5 s, lowest %.2e m from the top%n", mean, lowest);
        assertEquals(0.805 + MARGIN, mean, 2e-3);
        assertTrue(lowest >= MARGIN * 0.9, "lowest above the top: " + lowest);
    }

    /**
     * Frames played from a start: the plate of the test above, its rise starting at 0.5 s, holds its first frame
     * until then and is then where the unstarted plate was 0.5 s earlier (linear between the frames).
     */
    @Test
    void framesPlayFromTheirStart() {
        double[][] low = boxMesh(0, 0.5, 0, 0.4, 0.005, 0.4), high = boxMesh(0, 0.8, 0, 0.4, 0.005, 0.4);
        double[][] frames = {low[0], high[0]};
        MeshCollider now = new MeshCollider(SpherePath.fixed(0, 0, 0), low[0], ints(low[1]), frames, 1, false, MARGIN, 0.5, 0.4);
        MeshCollider later = new MeshCollider(SpherePath.fixed(0, 0, 0), low[0], ints(low[1]), frames, 1, false, 0.5, MARGIN, 0.5, 0.4);
        later.moveTo(0.4);
        assertArrayEquals(low[0], later.vertices(), 0, "the first frame, held before the start");
        for (double t : new double[] {0.25, 0.5, 0.75}) {
            now.moveTo(t);
            later.moveTo(t + 0.5);
            assertArrayEquals(now.vertices(), later.vertices(), 1e-15, "0.5 s later at " + t + " s");
            assertEquals(0.505 + 0.3 * t, maxY(later.vertices()), 1e-12, "the plate's top");
        }
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new MeshCollider(SpherePath.fixed(0, 0, 0), low[0], ints(low[1]), frames, 1, false, -1, MARGIN, 0.5, 0.4));
        assertTrue(e.getMessage().startsWith("playFrom must be"), e.getMessage());
    }

    private static double maxY(double[] v) {
        double top = -Double.MAX_VALUE;
        for (int k = 1; k < v.length; k += 3) top = Math.max(top, v[k]);
        return top;
    }
}
