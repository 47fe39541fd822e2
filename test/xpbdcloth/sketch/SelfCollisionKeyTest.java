package xpbdcloth.sketch;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;
import xpbdcloth.engine.SelfCollision;
import xpbdcloth.scene.PresetLoader;

/** The z key cycles self-collision through off, particle pairs, pairs and point–triangle contacts, and pairs and the guard, on the running cloth. */
class SelfCollisionKeyTest {
    @Test
    void zCyclesThroughPairsPointTriangleAndTheGuard() {
        SketchState s = new SketchState(PresetLoader.builtIn("drop-fold"));
        assertEquals("particle pairs", s.selfCollisionState(), "drop-fold's preset: particle pairs");
        s.cycleSelfCollision();
        SelfCollision self = s.first().selfCollision();
        assertEquals("point-triangle", s.selfCollisionState());
        assertTrue(self.pointTriangle() && self.guard() == null, "vertices kept from faces, no guard");
        s.cycleSelfCollision();
        self = s.first().selfCollision();
        assertEquals("continuous", s.selfCollisionState());
        assertTrue(!self.pointTriangle() && self.guard() != null, "the guard on particle pairs");
        s.cycleSelfCollision();
        assertEquals("off", s.selfCollisionState());
        assertNull(s.first().selfCollision());
        s.cycleSelfCollision();
        assertEquals("particle pairs", s.selfCollisionState());
        self = s.first().selfCollision();
        assertTrue(!self.pointTriangle() && self.guard() == null);
    }
}
