package xpbdcloth.experiments;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

/**
 * Experiment 2: the same rope and cloth at fixed n = 10 for dt = 1/30 … 1/240 s. The PBD explainer
 * claims PBD goes limp as the frame rate rises (30 → 60 fps); XPBD's stretch should not move.
 */
final class StiffnessVsTimestep implements Experiment {
    static final int N = 10;
    static final double[] RATES = {30, 50, 60, 120, 240};

    @Override public String name() { return "stiffness-vs-timestep"; }

    @Override public String claim() { return "PBD's stiffness changes with the timestep; XPBD's does not"; }

    @Override public List<String> run(Context ctx) throws IOException {
        Table t = new Table(name(), "rig", "solver", "steps_per_s", "dt_s", "stretch_relative", "cloth_sag_m");
        double seconds = ctx.quick ? 4 : 12;
        double[] rates = ctx.quick ? new double[] {30, 60, 240} : RATES;
        List<List<Double>> rope = new ArrayList<>(), cloth = new ArrayList<>();
        for (int j = 0; j < 3; j++) { rope.add(new ArrayList<>()); cloth.add(new ArrayList<>()); }
        List<Double> xs = new ArrayList<>();
        for (double rate : rates) {
            ctx.progress(name(), "dt = 1/" + (int) rate);
            double dt = 1 / rate;
            xs.add(rate);
            Rigs.Solver[] rs = {
                    new Rigs.Solver(xpbdcloth.engine.ConstraintMode.PBD, StiffnessVsIterations.K, 0, N, 1, dt, false),
                    new Rigs.Solver(xpbdcloth.engine.ConstraintMode.PBD, StiffnessVsIterations.K, 0, N, 1, dt, true),
                    new Rigs.Solver(xpbdcloth.engine.ConstraintMode.XPBD, 1, StiffnessVsIterations.ALPHA_ROPE, N, 1, dt, true)};
            Rigs.Solver[] cs = {rs[0], rs[1], new Rigs.Solver(xpbdcloth.engine.ConstraintMode.XPBD, 1, StiffnessVsIterations.ALPHA_CLOTH, N, 1, dt, true)};
            for (int j = 0; j < 3; j++) {
                double r = StiffnessVsIterations.ropeStretch(rs[j], seconds), c = StiffnessVsIterations.clothSag(cs[j], seconds);
                rope.get(j).add(r);
                cloth.get(j).add(c);
                t.add("rope", StiffnessVsIterations.LABELS[j], rate, dt, r, "");
                t.add("cloth", StiffnessVsIterations.LABELS[j], rate, dt, "", c);
            }
        }
        ctx.save(t);
        Plot p = new Plot("Rope stretch vs steps per second (n = 10)", "steps per second (1/dt)", "steady stretch (extension / rest length)", true, true);
        for (int j = 0; j < 3; j++) p.line(StiffnessVsIterations.LABELS[j], xs, rope.get(j));
        ctx.save(p, name());
        List<String> out = new ArrayList<>();
        int last = rates.length - 1;
        for (int j = 0; j < 3; j++)
            out.add(String.format("rope %s: dt 1/%.0f -> 1/%.0f: stretch %.4g -> %.4g (x%.2f); cloth sag %.4g -> %.4g m",
                    StiffnessVsIterations.LABELS[j], rates[0], rates[last], rope.get(j).get(0), rope.get(j).get(last),
                    rope.get(j).get(last) / rope.get(j).get(0), cloth.get(j).get(0), cloth.get(j).get(last)));
        return out;
    }
}
