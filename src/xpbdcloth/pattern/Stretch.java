package xpbdcloth.pattern;

/**
 * A stretch of a panel's outline to be sewn: from outline position {@code from} to {@code to} (corner k is
 * position k; 1.5 is halfway along edge 1), walking with the outline's order or, {@code backward}, against it.
 */
public final class Stretch {
    public final String panel;
    public final double from, to;
    public final boolean backward;

    public Stretch(String panel, double from, double to, boolean backward) {
        this.panel = panel;
        this.from = from;
        this.to = to;
        this.backward = backward;
    }

    /** Arc length covered on the outline (m). */
    public double length(Outline o) {
        double a = o.arcLength(from), b = o.arcLength(to), total = o.length();
        double d = backward ? a - b : b - a;
        return ((d % total) + total) % total;
    }

    /** Arc length from corner 0 of the point at fraction f of this stretch. */
    public double arcLengthAt(Outline o, double f) {
        double s = o.arcLength(from) + (backward ? -f : f) * length(o);
        double total = o.length();
        return ((s % total) + total) % total;
    }

    @Override public String toString() {
        return "\"" + panel + "\" " + fmt(from) + (backward ? " back to " : " to ") + fmt(to);
    }

    private static String fmt(double t) { return t == Math.rint(t) ? String.valueOf((long) t) : String.valueOf(t); }
}
