package xpbdcloth.pattern;

/**
 * A piece of fabric as it is cut: a named outline, the grain (the fabric's warp, a direction in the pattern
 * plane), the fabric's name (resolved by whoever builds the cloth: a catalogue name here) and where the
 * panel starts around the body.
 */
public final class Panel {
    public final String name;
    public final Outline outline;
    /** Unit warp direction (x, y) in the pattern plane. */
    private final double grainX, grainY;
    public final String fabric;
    public final Placement placement;

    public Panel(String name, Outline outline, double[] grain, String fabric, Placement placement) {
        if (name == null || name.isBlank()) throw new IllegalArgumentException("a panel needs a name");
        if (fabric == null || fabric.isBlank()) throw new IllegalArgumentException("panel \"" + name + "\" has no fabric");
        double g = grain.length == 2 ? Math.hypot(grain[0], grain[1]) : Double.NaN;
        if (!(g > 0) || Double.isInfinite(g))
            throw new IllegalArgumentException("panel \"" + name + "\": grain must be a direction [x, y] in the pattern plane, was " + java.util.Arrays.toString(grain));
        this.name = name;
        this.outline = outline;
        this.grainX = grain[0] / g;
        this.grainY = grain[1] / g;
        this.fabric = fabric;
        this.placement = placement;
    }

    public double[] grain() { return new double[] {grainX, grainY}; }

    /**
     * Texture coordinates of a pattern point: the fabric's own coordinates, u along the grain and v across it
     * (the print on a fabric runs with its warp, and the UV-warp path reads the warp as the direction u grows).
     */
    public void fabricCoordinates(double x, double y, double[] out) {
        out[0] = x * grainX + y * grainY;
        out[1] = -x * grainY + y * grainX;
    }
}
