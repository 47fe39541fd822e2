package xpbdcloth.fabric;

import xpbdcloth.engine.OrthotropicMaterial;

/**
 * A named fabric: its in-plane elasticity, its bending stiffness and (when known) its areal density,
 * with where the numbers come from. Everything a cloth needs to be that fabric except its shape.
 */
public final class Fabric {
    public final String name;
    /** What it is (garment, fibre content), for people. */
    public final String description;
    /** Where the numbers come from; empty for a fabric typed into a preset. */
    public final String source;
    /** kg/m²; NaN when the fabric does not say (the cloth's own mass then stands). */
    public final double arealDensity;
    public final OrthotropicMaterial membrane;
    /** B, N·m per unit width. */
    public final double bendingStiffness;
    /** The measured stretching beyond small strain, or null (the fabric is the linear membrane alone). */
    public final StretchingCurve stretchingCurve;
    /** The measured bending beyond small curvature, or null (the fabric bends linearly with B alone). */
    public final BendingCurve bendingCurve;

    public Fabric(String name, String description, String source, double arealDensity, OrthotropicMaterial membrane, double bendingStiffness) {
        this(name, description, source, arealDensity, membrane, bendingStiffness, null, null);
    }

    public Fabric(String name, String description, String source, double arealDensity, OrthotropicMaterial membrane, double bendingStiffness,
                  StretchingCurve stretchingCurve, BendingCurve bendingCurve) {
        if (name == null) throw new IllegalArgumentException("name must not be null, was null");
        if (membrane == null) throw new IllegalArgumentException("membrane must not be null, was null");
        if (!Double.isNaN(arealDensity) && !(arealDensity > 0 && arealDensity < 1e3))
            throw new IllegalArgumentException("arealDensity must be in (0, 1000) kg/m² or unknown (NaN), was " + arealDensity);
        if (!(bendingStiffness > 0 && bendingStiffness < 1e6))
            throw new IllegalArgumentException("bendingStiffness must be in (0, 1e6) N·m, was " + bendingStiffness);
        this.name = name;
        this.description = description == null ? "" : description;
        this.source = source == null ? "" : source;
        this.arealDensity = arealDensity;
        this.membrane = membrane;
        this.bendingStiffness = bendingStiffness;
        this.stretchingCurve = stretchingCurve;
        this.bendingCurve = bendingCurve;
    }

    @Override public String toString() { return name; }
}
