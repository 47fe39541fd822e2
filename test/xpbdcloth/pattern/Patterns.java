package xpbdcloth.pattern;

import java.util.List;

/** Small patterns built in code for the tests: outlines with straight, arc and Bézier edges, and seams. */
final class Patterns {
    private Patterns() {}

    static Outline polygon(double... xy) {
        double[][] c = new double[xy.length / 2][];
        for (int k = 0; k < c.length; k++) c[k] = new double[] {xy[2 * k], xy[2 * k + 1]};
        Curve[] e = new Curve[c.length];
        for (int k = 0; k < c.length; k++) e[k] = Curve.line(c[k], c[(k + 1) % c.length]);
        return new Outline(c, e);
    }

    static Outline rectangle(double w, double h) { return polygon(0, 0, w, 0, w, h, 0, h); }

    /** A disc of radius r from two half-circle arcs (bulging right of travel on a clockwise walk: outward). */
    static Outline disc(double r) {
        double[][] c = {{-r, 0}, {r, 0}};
        // Counter-clockwise: from (−r, 0) along the bottom to (r, 0), then over the top; outward is right of travel.
        return new Outline(c, new Curve[] {Curve.arc(c[0], c[1], r), Curve.arc(c[1], c[0], r)});
    }

    /**
     * A T-shirt body panel, 0.5 m wide at the hem, 0.65 m long: straight sides and shoulders, armholes as
     * Bézier curves and a neckline as an arc dipping into the panel.
     */
    static Outline shirtBody() {
        double[][] c = {{0, 0}, {0.5, 0}, {0.5, 0.42}, {0.44, 0.6}, {0.33, 0.65}, {0.17, 0.65}, {0.06, 0.6}, {0, 0.42}};
        Curve[] e = new Curve[c.length];
        for (int k = 0; k < c.length; k++) e[k] = Curve.line(c[k], c[(k + 1) % c.length]);
        e[2] = Curve.bezier(c[2], new double[] {0.46, 0.47}, new double[] {0.44, 0.55}, c[3]);
        e[4] = Curve.arc(c[4], c[5], -0.06);  // walking right to left along the top, the neckline dips in (left of travel is down... inward)
        e[6] = Curve.bezier(c[6], new double[] {0.06, 0.55}, new double[] {0.04, 0.47}, c[7]);
        return new Outline(c, e);
    }

    static Panel panel(String name, Outline o) {
        return new Panel(name, o, new double[] {0, 1}, "cotton", Placement.IDENTITY);
    }

    static Panel panel(String name, Outline o, Placement at) {
        return new Panel(name, o, new double[] {0, 1}, "cotton", at);
    }

    static Pattern single(Panel p) { return new Pattern("test", List.of(p), List.of()); }
}
