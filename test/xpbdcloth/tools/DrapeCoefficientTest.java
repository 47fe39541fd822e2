package xpbdcloth.tools;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Cusick's drape test on two measured fabrics: the stiffer (denim, bending length (B/wg)^(1/3) 1.85 cm) has
 * the higher drape coefficient than the limper (interlock, 1.37 cm), both lie within 0.30–0.85, the range the
 * 30 cm specimen is meant for (BS 5058 takes a 24 cm specimen below it and a 36 cm one above), both have
 * settled, and each hem hangs clear of the disc in folds. The folds are counted by hysteresis: a cosine hem
 * of k lobes has k nodes, ripples shallower than the threshold none.
 */
class DrapeCoefficientTest {
    @Test
    @Tag("slow")
    void theStifferFabricDrapesLessAndBothLieInTheTestersRange() throws java.io.IOException {
        DrapeCoefficientCommand.Result denim = DrapeCoefficientCommand.measure("denim", null, 10);
        DrapeCoefficientCommand.Result interlock = DrapeCoefficientCommand.measure("interlock", null, 10);
        for (DrapeCoefficientCommand.Result r : new DrapeCoefficientCommand.Result[] {denim, interlock}) {
            assertTrue(r.coefficient > 0.30 && r.coefficient < 0.85, r.fabric + ": DC " + r.coefficient);
            assertTrue(r.rest.startsWith("converged"), r.fabric + " has settled: " + r.rest);
            assertTrue(r.innermostHem > DrapeCoefficientCommand.SUPPORT, r.fabric + ": the hem hangs outside the disc, innermost at " + r.innermostHem);
            assertTrue(r.outermostHem < DrapeCoefficientCommand.RADIUS, r.fabric + ": nothing reaches out as far as the flat specimen");
            assertTrue(r.nodes >= 3, r.fabric + " drapes in folds: " + r.nodes + " nodes");
        }
        assertTrue(denim.coefficient > interlock.coefficient + 0.1, "denim " + denim.coefficient + " against interlock " + interlock.coefficient);
    }

    @Test
    void nodesAreTheHemsSwingsOutAndBackDeeperThanTheThreshold() {
        for (int k : new int[] {4, 7, 10}) {
            double[] radii = new double[360];
            for (int i = 0; i < radii.length; i++) radii[i] = 0.12 + 0.01 * Math.cos(k * 2 * Math.PI * (i + 0.3) / radii.length) + 0.001 * Math.sin(37 * i);
            assertEquals(k, DrapeCoefficientCommand.nodes(radii, 0.005), k + " lobes");
        }
        double[] ripples = new double[360];
        for (int i = 0; i < ripples.length; i++) ripples[i] = 0.12 + 0.002 * Math.cos(9 * 2 * Math.PI * i / ripples.length);
        assertEquals(0, DrapeCoefficientCommand.nodes(ripples, 0.005), "ripples of 4 mm peak to trough are no nodes at 5 mm");
    }
}
