package xpbdcloth.fit;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.OrthotropicMaterial;
import xpbdcloth.fabric.Fabric;
import xpbdcloth.scene.Preset;

/** What a fit leaves behind: the iterations as CSV and the fitted compliances as a preset (the command line adds a chart, {@code FitChart}). */
public final class FitFiles {
    private FitFiles() {}

    /** A family as the fit's files name it: "structural", "shear", "bend". */
    public static String name(ConstraintFamily f) { return ClothEnergy.name(f); }

    /** iteration, loss (m²), rms (m), |∇L|, α per family (m/N), the damping (1/s) if fitted, forward solves. */
    public static void writeCsv(Path file, MaterialFit fit) throws IOException {
        StringBuilder s = new StringBuilder("iteration,loss_m2,rms_m,gradient_norm");
        for (ConstraintFamily f : fit.families()) s.append(",alpha_").append(name(f)).append("_m_per_N");
        if (fit.fitsDamping()) s.append(",damping_per_s");
        s.append(',').append(fit.solvesName()).append('\n');
        for (FitIteration it : fit.history()) {
            s.append(it.index).append(',').append(num(it.loss)).append(',').append(num(it.rms)).append(',').append(num(it.gradientNorm));
            for (double a : it.compliance) s.append(',').append(num(a));
            if (fit.fitsDamping()) s.append(',').append(num(it.damping));
            s.append(',').append(it.solves).append('\n');
        }
        Files.writeString(file, s);
    }

    /**
     * The preset's own JSON with each fitted spring family's compliance, a fitted fabric's moduli and the
     * solver's damping (if fitted) replaced, renamed {@code name}: a file the sketch and every command load
     * as they load the original. A fabric's membrane α scales as 1/(E₁, E₂, G₁₂) (ν₁₂ unchanged) and its
     * dihedral α as 1/B, so the fitted factor divides those; a catalogue fabric is written out as its
     * moduli, with its areal density moved to the cloth.
     */
    public static void writePreset(Path file, Preset preset, String presetJson, String name, MaterialFit fit, String observed) throws IOException {
        ObjectMapper json = new ObjectMapper();
        ObjectNode root = (ObjectNode) json.readTree(presetJson);
        root.put("name", name);
        StringBuilder fitted = new StringBuilder();
        double[] alpha = fit.compliance(), scale = fit.scale();
        double membraneScale = 1, dihedralScale = 1;
        for (int f = 0; f < alpha.length; f++) {
            ConstraintFamily family = fit.families().get(f);
            if (family == ConstraintFamily.MEMBRANE) membraneScale = scale[f];
            else if (family == ConstraintFamily.DIHEDRAL) dihedralScale = scale[f];
            else root.withObject("families").withObject(name(family)).put("compliance", alpha[f]);
            fitted.append(f == 0 ? "" : ", ").append(name(family)).append(String.format(Locale.ROOT, " %.4g m/N", alpha[f]));
        }
        if (membraneScale != 1 || dihedralScale != 1) writeFabric(root, preset, membraneScale, dihedralScale);
        if (fit.fitsDamping()) {
            double c = fit.last().damping;
            root.withObject("solver").put("damping", c);
            fitted.append(fitted.length() == 0 ? "" : ", ").append(String.format(Locale.ROOT, "damping %.4g /s", c));
        }
        root.put("description", String.format(Locale.ROOT, "Fitted by xpbd-cloth fit to %s (RMS %.3f mm after %d iterations): %s. From: %s",
                observed, fit.last().rms * 1e3, fit.last().index, fitted, root.path("description").asText("")));
        Files.writeString(file, json.writerWithDefaultPrettyPrinter().writeValueAsString(root) + "\n");
    }

    private static void writeFabric(ObjectNode root, Preset preset, double membraneScale, double dihedralScale) {
        Fabric fabric = preset.fabric.fabric;
        ObjectNode node = root.withObject("fabric");
        if (node.has("catalogue")) {
            node.remove("catalogue");
            root.withObject("cloth").put("arealDensity", fabric.arealDensity);
        }
        OrthotropicMaterial m = fabric.membrane;
        node.put("name", (fabric.name.isEmpty() ? "fabric" : fabric.name) + " (fitted)");
        node.put("warpModulus", m.warpModulus / membraneScale);
        node.put("weftModulus", m.weftModulus / membraneScale);
        node.put("poisson", m.poisson);
        node.put("shearModulus", m.shearModulus / membraneScale);
        node.put("bendingStiffness", fabric.bendingStiffness / dihedralScale);
    }

    private static String num(double v) { return String.format(Locale.ROOT, "%.9g", v); }
}
