package xpbdcloth.experiments;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import xpbdcloth.fabric.Fabric;
import xpbdcloth.scene.FabricCatalogue;

/**
 * Denim's membrane with its measured stretching curve: a sheet stretched along the warp, the weft and the bias by
 * 1 %, 5 % and 10 %, and at 30° between two samples (held at its width, a wide strip's test) pulls with the force the data's model gives, written
 * here from the tabulated rows, not from the project's conversion: the energy per area ½(K₀E_uu² + K₂E_vv² +
 * 2K₁E_uuE_vv) + K₃E_uv² with K twice the sample, the sample interpolated linearly in the stretch between the
 * zero-strain row and that direction's row at 1/6 (the shear term is the one ARCSim's stretching_force applies,
 * 2K₃E_uv ∂E_uv; its stretching_energy writes half of it). The linear model it replaces is measurably softer.
 */
class MeasuredStretchingTest {
    static final Fabric DENIM = FabricCatalogue.named("denim");
    static final double[] PERCENT = {1, 5, 10};
    /** Warp, bias, weft, and 30° (between the 22.5° and 45° rows). */
    static final double[] ANGLE = {0, 45, 90, 30};

    /** Denim's six tabulated rows of (k₀, k₁, k₂, k₃): the zero-strain one, then 0°, 22.5°, 45°, 67.5°, 90° at 1/6. */
    static double[][] denimRows() throws Exception {
        JsonNode denim = null;
        for (JsonNode f : new ObjectMapper().readTree(Files.readString(Path.of("data", FabricCatalogue.FILE))).get("fabrics"))
            if (f.get("name").asText().equals("denim")) denim = f;
        double[][] rows = new double[6][4];
        for (int k = 0; k < 4; k++) rows[0][k] = denim.get("stretching").get(k).asDouble();
        for (int j = 0; j < 5; j++) for (int k = 0; k < 4; k++) rows[j + 1][k] = denim.get("stretchingCurve").get(j).get(k).asDouble();
        return rows;
    }

    /** The data's force per unit width (N/m) of a sheet stretched by e along angle φ (degrees) to the warp, lateral held. */
    static double dataForce(double[][] rows, double e, double phi, boolean curve) {
        // The largest principal stretch is 1 + e along φ (the width is held); its samples are 22.5° apart.
        double s = curve ? Math.min(1, 6 * e) : 0, a = phi / 22.5;
        int j = Math.min(3, (int) a);
        double[] k = new double[4];
        for (int i = 0; i < 4; i++) k[i] = 2 * ((1 - s) * rows[0][i] + s * ((1 - (a - j)) * rows[1 + j][i] + (a - j) * rows[2 + j][i]));
        // W(e) per area at that K; f = dW/de (K held: a secant stiffness, as the data's model is used).
        double h = 1e-7 * Math.max(e, 1e-3);
        return (energy(k, e + h, phi) - energy(k, e - h, phi)) / (2 * h);
    }

    static double energy(double[] k, double e, double phi) {
        double g = 0.5 * ((1 + e) * (1 + e) - 1), c = Math.cos(Math.toRadians(phi)), s = Math.sin(Math.toRadians(phi));
        double guu = g * c * c, gvv = g * s * s, guv = g * c * s;
        return 0.5 * (k[0] * guu * guu + k[2] * gvv * gvv + 2 * k[1] * guu * gvv) + k[3] * guv * guv;
    }

    @Test
    void denimPullsAsItsMeasuredCurveAlongWarpWeftAndBias() throws Exception {
        double[][] rows = denimRows();
        for (int d = 0; d < ANGLE.length; d++)
            for (double percent : PERCENT) {
                double e = percent / 100, data = dataForce(rows, e, ANGLE[d], true), engine = MeasuredStretching.force(DENIM, e, ANGLE[d], true);
                double linear = MeasuredStretching.force(DENIM, e, ANGLE[d], false);
                System.out.printf("%4.0f° %4.0f %%: data %9.4f N/m, engine %9.4f (%+.4f %%), linear model %9.4f (%+.2f %%)%n",
                        ANGLE[d], percent, data, engine, 100 * (engine / data - 1), linear, 100 * (linear / data - 1));
                assertEquals(data, engine, 0.02 * data, ANGLE[d] + "° at " + percent + " %");
            }
        // What the curve changes: at 10 % along the warp the linear model (the slope at zero) is softer by more than 5 %.
        double data = dataForce(rows, 0.1, 0, true), linear = MeasuredStretching.force(DENIM, 0.1, 0, false);
        assertTrue(linear < 0.95 * data, "linear " + linear + " against the data's " + data);
        // At zero strain the curve is the linear fabric: the same force at a stretch too small to move along it.
        assertEquals(MeasuredStretching.force(DENIM, 1e-7, 30, false), MeasuredStretching.force(DENIM, 1e-7, 30, true), 1e-6 * Math.abs(MeasuredStretching.force(DENIM, 1e-7, 30, false)));
    }
}
