package xpbdcloth.tools;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import xpbdcloth.fit.FitFiles;
import xpbdcloth.fit.FitIteration;
import xpbdcloth.fit.MaterialFit;

/** The fit command's chart of a fit (XChart, a command-line dependency the simulator does not carry). */
final class FitChart {
    private FitChart() {}

    /** Loss, each α (and the damping) against the iterations, on log axes. */
    public static void writePng(Path file, MaterialFit fit) throws IOException {
        String kind = Character.toUpperCase(fit.kind().charAt(0)) + fit.kind().substring(1);
        XYChart chart = new XYChartBuilder().width(1000).height(560).title(kind + " fit: loss and parameters per iteration")
                .xAxisTitle("iteration").yAxisTitle(fit.fitsDamping() ? "loss (m²) / α (m/N) / c (1/s)" : "loss (m²) / α (m/N)").build();
        chart.getStyler().setYAxisLogarithmic(true);
        chart.getStyler().setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.OutsideS);
        chart.getStyler().setLegendLayout(org.knowm.xchart.style.Styler.LegendLayout.Horizontal);
        List<Double> x = new ArrayList<>(), loss = new ArrayList<>();
        for (FitIteration it : fit.history()) {
            x.add((double) it.index);
            loss.add(Math.max(it.loss, 1e-40)); // a log axis has no 0
        }
        chart.addSeries("loss ½Σ|x − x̂|² (m²)", x, loss);
        for (int f = 0; f < fit.families().size(); f++) {
            List<Double> a = new ArrayList<>();
            for (FitIteration it : fit.history()) a.add(it.compliance[f]);
            chart.addSeries("α " + FitFiles.name(fit.families().get(f)) + " (m/N)", x, a);
        }
        if (fit.fitsDamping()) {
            List<Double> c = new ArrayList<>();
            for (FitIteration it : fit.history()) c.add(it.damping);
            chart.addSeries("damping c (1/s)", x, c);
        }
        BitmapEncoder.saveBitmap(chart, file.toString(), BitmapEncoder.BitmapFormat.PNG);
    }
}
