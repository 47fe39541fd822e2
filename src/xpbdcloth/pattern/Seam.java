package xpbdcloth.pattern;

/**
 * Two stretches of outline to be joined, start to start and end to end. Stretches of different lengths are
 * eased: both get the same stitches at equal fractions of their lengths, so the shorter side is stretched to
 * meet the longer as the seam closes.
 */
public final class Seam {
    public final String name;
    public final Stretch a, b;

    public Seam(String name, Stretch a, Stretch b) {
        this.name = name;
        this.a = a;
        this.b = b;
    }
}
