package xpbdcloth.engine;

/**
 * Validation at the API edge. Every rule throws {@link IllegalArgumentException} whose message starts
 * with the parameter's name and ends with the rejected value, so a user who typed the value can find it.
 * Checks run before any state is touched, so a rejected call changes nothing.
 */
public final class Check {
    private Check() {}

    /** A finite number (not NaN, not ±Inf). */
    public static double finite(String name, double value) {
        if (!Double.isFinite(value)) throw fail(name, "must be a finite number", value);
        return value;
    }

    /** A finite number ≥ 0. */
    public static double nonNegative(String name, double value) {
        if (!(Double.isFinite(value) && value >= 0)) throw fail(name, "must be finite and >= 0", value);
        return value;
    }

    /** A finite number &gt; 0. */
    public static double positive(String name, double value) {
        if (!(Double.isFinite(value) && value > 0)) throw fail(name, "must be finite and > 0", value);
        return value;
    }

    /** A finite number in [lo, hi]. */
    public static double inRange(String name, double value, double lo, double hi) {
        if (!(value >= lo && value <= hi)) throw fail(name, "must be in [" + lo + ", " + hi + "]", value);
        return value;
    }

    /** An integer in [lo, hi] (said as integers). */
    public static int inRange(String name, long value, long lo, long hi) {
        if (value < lo || value > hi) throw new IllegalArgumentException(name + " must be in [" + lo + ", " + hi + "], was " + value);
        return (int) value;
    }

    /** An integer ≥ min. */
    public static int atLeast(String name, int value, int min) {
        if (value < min) throw new IllegalArgumentException(name + " must be >= " + min + ", was " + value);
        return value;
    }

    /** An index in [0, size). */
    public static int index(String name, int value, int size) {
        if (value < 0 || value >= size)
            throw new IllegalArgumentException(name + " must be in [0, " + size + "), was " + value);
        return value;
    }

    /** Three finite components, reported as name.x / name.y / name.z. */
    public static void finite3(String name, double x, double y, double z) {
        // The names are built only on failure: this guards calls made per particle per step.
        if (Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z)) return;
        finite(name + ".x", x);
        finite(name + ".y", y);
        finite(name + ".z", z);
    }

    private static IllegalArgumentException fail(String name, String rule, double value) {
        return new IllegalArgumentException(name + " " + rule + ", was " + value);
    }
}
