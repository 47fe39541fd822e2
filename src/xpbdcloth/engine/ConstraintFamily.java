package xpbdcloth.engine;

/** The kinds of constraint a cloth is built from; stiffness and compliance are set per family. */
public enum ConstraintFamily {
    /** Distance constraints along the mesh's edges (a grid's rows and columns, a polyline's segments). */
    STRUCTURAL,
    /** Angle constraints between the row and column edges meeting at a vertex. */
    SHEAR,
    /** Triangle bending constraints over three consecutive particles (Kelager et al. 2010). */
    BEND,
    /** Orthotropic membrane energy per triangle, from a fabric's moduli ({@link MembraneBlock}). */
    MEMBRANE,
    /** Bending from a bending stiffness: {@link BendingPatch} rows on a flat rest, {@link DihedralBlock} hinges on a bent one. */
    DIHEDRAL,
    /** Long-range attachments to the nearest pin ({@link TetherBlock}). */
    TETHER,
    /** Contacts with colliders and between the cloth's layers: always hard (k = 1, α = 0). */
    COLLISION,
    /** A particle held at a target point, e.g. by the mouse. */
    ATTACHMENT,
    /** The gas, or the held volume, inside a closed cloth ({@link EnclosedGas}): one row over the whole surface. */
    PRESSURE,
    /** A garment's seams: stitches pulled shut and held ({@link StitchBlock}), and the bending across them once closed ({@link Sewing}). */
    SEAM
}
