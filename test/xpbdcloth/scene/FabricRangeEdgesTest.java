package xpbdcloth.scene;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;
import xpbdcloth.engine.Metrics;
import xpbdcloth.engine.Simulation;

/**
 * The fabric fields' documented ranges hold at their edges on a regular grid: the softest bending (B = 1e-6
 * N·m, whose hinges on a grid have α = 1/B = 1e6 exactly) and the softest membrane build and step. The
 * hostile-input report found B = 1e-6 refused by the engine's compliance bound by one rounding.
 */
class FabricRangeEdgesTest {
    static final String FABRIC = "{\"name\":\"soft\",\"cloth\":{\"columns\":%d,\"rows\":%d,\"width\":1.0,\"height\":1.0,\"plane\":\"vertical\","
            + "\"origin\":[0,1.6,0],\"arealDensity\":0.2,\"pins\":[\"top-left\",\"top-right\"]},"
            + "\"fabric\":{\"warpModulus\":%s,\"weftModulus\":%s,\"poisson\":0,\"shearModulus\":%s,\"bendingStiffness\":%s,\"warp\":[1,0,0]},"
            + "\"solver\":{\"mode\":\"XPBD\",\"iterations\":2,\"substeps\":10,\"dt\":0.02,\"mullerCorrection\":true,\"gravity\":[0,-9.81,0],\"type\":\"vertex-block-descent\"}}";

    /** A fabric or aerodynamics on a cloth with no triangles (one row of particles) is refused naming the field (the fuzzer found it reported as "(building the scene)"). */
    @Test
    void aFabricOrAirOnARopeIsRefusedByName() {
        String rope = String.format(FABRIC, 30, 1, "410", "2027", "53", "2e-5").replace("\"height\":1.0", "\"height\":0");
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.parse("rope.json", rope));
        assertEquals("fabric", e.field(), e.getMessage());
        assertTrue(e.problem().contains("single row or column"), e.getMessage());
        String air = String.format(FABRIC, 30, 1, "410", "2027", "53", "2e-5").replace("\"height\":1.0", "\"height\":0")
                .replaceFirst("\"fabric\":\\{[^}]*\\},", "\"families\":{\"structural\":{\"stiffness\":1,\"compliance\":0}},\"aerodynamics\":{\"density\":1.2,\"drag\":1,\"lift\":1,\"air\":[5,0,0]},");
        PresetException a = assertThrows(PresetException.class, () -> PresetLoader.parse("rope.json", air));
        assertEquals("aerodynamics", a.field(), a.getMessage());
    }

    @Test
    void theSoftestDocumentedFabricBuildsAndSteps() {
        for (int n : new int[] {32, 64, 128}) {
            String bending = String.format(FABRIC, n, n, "410", "2027", "53", Limits.BENDING_STIFFNESS.lo);
            String membrane = String.format(FABRIC, n, n, Limits.MODULUS.lo, Limits.MODULUS.lo, Limits.MODULUS.lo, "2e-5");
            for (String text : new String[] {bending, membrane}) {
                Simulation sim = Scene.of(PresetLoader.parse("soft.json", text)).simulation();
                for (int s = 0; s < 3; s++) sim.step();
                assertTrue(Metrics.allFinite(sim.particles()), n + "²");
            }
        }
    }
}
