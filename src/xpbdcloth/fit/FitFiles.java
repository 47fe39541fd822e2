package xpbdcloth.fit;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import xpbdcloth.engine.ConstraintFamily;

/** What a fit leaves behind: the iterations as CSV and PNG, and the fitted compliances as a preset. */
public final class FitFiles {
    private FitFiles() {}

    static String name(ConstraintFamily f) { return ClothEnergy.name(f); }

    /** iteration, loss (m²), rms (m), |∇L|, α per family (m/N), equilibrium solves. */
    public static void writeCsv(Path file, StaticFit fit) throws IOException {
        StringBuilder s = new StringBuilder("iteration,loss_m2,rms_m,gradient_norm");
        for (ConstraintFamily f : fit.families()) s.append(",alpha_").append(name(f)).append("_m_per_N");
        s.append(",equilibrium_solves\n");
        for (StaticFit.Iteration it : fit.history()) {
            s.append(it.index).append(',').append(num(it.loss)).append(',').append(num(it.rms)).append(',').append(num(it.gradientNorm));
            for (double a : it.compliance) s.append(',').append(num(a));
            s.append(',').append(it.equilibriumSolves).append('\n');
        }
        Files.writeString(file, s);
    }

    /** Loss and each α against the iterations, on log axes. */
    public static void writePng(Path file, StaticFit fit) throws IOException {
        XYChart chart = new XYChartBuilder().width(1000).height(560).title("Static fit: loss and compliances per iteration")
                .xAxisTitle("iteration").yAxisTitle("loss (m²) / α (m/N)").build();
        chart.getStyler().setYAxisLogarithmic(true);
        chart.getStyler().setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.OutsideS);
        chart.getStyler().setLegendLayout(org.knowm.xchart.style.Styler.LegendLayout.Horizontal);
        List<Double> x = new ArrayList<>(), loss = new ArrayList<>();
        for (StaticFit.Iteration it : fit.history()) {
            x.add((double) it.index);
            loss.add(Math.max(it.loss, 1e-40)); // a log axis has no 0
        }
        chart.addSeries("loss ½Σ|x − x̂|² (m²)", x, loss);
        for (int f = 0; f < fit.families().size(); f++) {
            List<Double> a = new ArrayList<>();
            for (StaticFit.Iteration it : fit.history()) a.add(it.compliance[f]);
            chart.addSeries("α " + name(fit.families().get(f)) + " (m/N)", x, a);
        }
        BitmapEncoder.saveBitmap(chart, file.toString(), BitmapEncoder.BitmapFormat.PNG);
    }

    /**
     * The preset's own JSON with each fitted family's compliance replaced, renamed {@code name}: a file
     * the sketch and every command load as they load the original.
     */
    public static void writePreset(Path file, String presetJson, String name, StaticFit fit, String observed) throws IOException {
        ObjectMapper json = new ObjectMapper();
        ObjectNode root = (ObjectNode) json.readTree(presetJson);
        root.put("name", name);
        StringBuilder fitted = new StringBuilder();
        double[] alpha = fit.compliance();
        for (int f = 0; f < alpha.length; f++) {
            ((ObjectNode) root.with("families").with(name(fit.families().get(f)))).put("compliance", alpha[f]);
            fitted.append(f == 0 ? "" : ", ").append(name(fit.families().get(f))).append(String.format(Locale.ROOT, " %.4g m/N", alpha[f]));
        }
        root.put("description", String.format(Locale.ROOT, "Fitted by xpbd-cloth fit to %s (RMS %.3f mm after %d iterations): %s. From: %s",
                observed, fit.last().rms * 1e3, fit.last().index, fitted, root.path("description").asText("")));
        Files.writeString(file, json.writerWithDefaultPrettyPrinter().writeValueAsString(root) + "\n");
    }

    private static String num(double v) { return String.format(Locale.ROOT, "%.9g", v); }
}
