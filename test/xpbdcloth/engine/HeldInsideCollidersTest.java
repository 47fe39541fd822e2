package xpbdcloth.engine;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/**
 * A pin or a grab holding cloth inside a solid is counted (Simulation.heldInsideColliders): past each kind of
 * solid's surface it counts, outside it or merely within the margin it does not, and free particles inside a
 * solid are not "held" (they are the pinched count's).
 */
class HeldInsideCollidersTest {
    static final double MARGIN = 0.01;

    /** A 6 × 6 cloth lying at y = 1 with its first corner pinned; returns the simulation. */
    static Simulation pinnedCloth() {
        Cloth c = new ClothBuilder().resolution(6, 6).size(0.5, 0.5).plane(ClothBuilder.Plane.HORIZONTAL).origin(0, 1, 0).arealDensity(0.2)
                .family(ConstraintFamily.STRUCTURAL, 1, 1e-6).pin(0, 0).build();
        return c.simulation(new SolverSettings().withIterations(2).withSubsteps(2).withTimestep(0.01));
    }

    @Test
    void aPinPastAFloorsSurfaceIsCountedAndOneOnItsMarginIsNot() {
        Simulation sim = pinnedCloth();
        Particles p = sim.particles();
        assertEquals(0, p.inverseMass(0));
        double y = p.y(0);
        assertEquals(0, sim.heldInsideColliders(), "no collider, nothing held inside one");
        // The floor's surface 1 cm above the pin: the pin is past it (and so is every free particle of the cloth,
        // which lies at the same height; they are not held, so they do not count).
        sim.add(Plane.floor(y + 0.01, MARGIN, 0, 0));
        assertEquals(1, sim.heldInsideColliders(), "the pinned corner under the floor's surface");
        Simulation touching = pinnedCloth();
        touching.add(Plane.floor(y - 0.5 * MARGIN, MARGIN, 0, 0)); // within the margin above the surface: touching, not inside
        assertEquals(0, touching.heldInsideColliders());
        sim.close();
        touching.close();
    }

    @Test
    void everyKindOfSolidCountsAPinInsideItAndNotOneBesideIt() {
        for (int kind = 0; kind < 4; kind++)
            for (double offset : new double[] {0, 0.3}) {
                Simulation sim = pinnedCloth();
                Particles p = sim.particles();
                double x = p.x(0) + offset, y = p.y(0), z = p.z(0);
                SpherePath at = SpherePath.fixed(x, y, z);
                String name;
                switch (kind) {
                    case 0: sim.add(new Sphere(at, 0.1, MARGIN, 0, 0)); name = "sphere"; break;
                    case 1: sim.add(new Box(at, new double[] {0.1, 0.05, 0.1}, new double[] {0, 30, 0}, MARGIN, 0, 0)); name = "box"; break;
                    case 2: sim.add(new Capsule(at, new double[] {0, 0, 1}, 0.1, 0.05, MARGIN, 0, 0)); name = "capsule"; break;
                    default: {
                        double[][] m = MeshColliderTest.boxMesh(x, y, z, 0.1, 0.05, 0.1);
                        sim.add(new MeshCollider(SpherePath.fixed(0, 0, 0), m[0], MeshColliderTest.ints(m[1]), null, 0, false, MARGIN, 0, 0));
                        name = "closed mesh";
                    }
                }
                // Centred on the pin: it is inside. 30 cm along x: the pin is outside, and the free particles now
                // inside the solid are not held.
                assertEquals(offset == 0 ? 1 : 0, sim.heldInsideColliders(), name + " at " + offset + " m from the pin");
                sim.close();
            }
    }

    @Test
    void aClosedMeshsClearanceByItsPseudonormalsIsItsSignedDistanceLessTheMargin() {
        double[][] m = MeshColliderTest.boxMesh(0.1, 0.2, -0.1, 0.3, 0.1, 0.2);
        MeshCollider box = new MeshCollider(SpherePath.fixed(0, 0, 0), m[0], MeshColliderTest.ints(m[1]), null, 0, false, MARGIN, 0, 0);
        java.util.Random r = new java.util.Random(5);
        int inside = 0;
        for (int k = 0; k < 2000; k++) {
            double x = 0.1 + 0.8 * (r.nextDouble() - 0.5), y = 0.2 + 0.4 * (r.nextDouble() - 0.5), z = -0.1 + 0.6 * (r.nextDouble() - 0.5);
            double exact = box.signedDistance(x, y, z); // the winding number's side
            if (exact < 0) inside++;
            assertEquals(exact - MARGIN, box.clearanceAt(x, y, z), 1e-12, "at (" + x + ", " + y + ", " + z + ")");
        }
        assertTrue(inside > 500 && inside < 1500, "points on both sides: " + inside + " inside of 2000");
    }

    @Test
    void aGrabHoldingAFreeParticleInsideASphereIsCountedUntilItLetsGo() {
        Simulation sim = pinnedCloth();
        Particles p = sim.particles();
        int i = p.count() - 1; // the far corner, free
        sim.add(new Sphere(SpherePath.fixed(p.x(i), p.y(i), p.z(i)), 0.05, MARGIN, 0, 0));
        assertEquals(0, sim.heldInsideColliders(), "a free particle inside a solid is not held");
        AttachmentConstraint grab = sim.attach(i, p.x(i), p.y(i), p.z(i));
        assertEquals(1, sim.heldInsideColliders(), "held by the grab, at the sphere's centre");
        sim.release(grab);
        assertEquals(0, sim.heldInsideColliders(), "let go");
        sim.close();
    }
}
