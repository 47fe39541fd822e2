package xpbdcloth.fabric;

import java.util.List;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.Particles;

/**
 * Makes a running cloth another fabric without a reset: every membrane triangle takes the new moduli,
 * every dihedral bend the new bending stiffness, and every particle's mass scales so the cloth has the
 * new areal density. Rest shapes, warp directions, tethers, positions and velocities stay, so the cloth
 * carries on from where it is as the new material (XPBD's λ restart each step, so nothing stale remains).
 * The masses scale rather than being weighed again, so a distribution the cloth was given (a total mass,
 * masses per vertex) stays; a garment, weighed panel by panel from its cut areas, is made one fabric by
 * {@link PanelFabrics} instead.
 */
public final class FabricSwap {
    private FabricSwap() {}

    /**
     * @param blocks the simulation's blocks (its membrane and dihedral blocks are changed)
     * @return the cloth's areal density after the swap, kg/m² (NaN if it has no membrane to measure area by)
     */
    public static double apply(List<ConstraintBlock> blocks, Particles p, Fabric fabric) {
        if (fabric == null) throw new IllegalArgumentException("fabric must not be null, was null");
        double area = PanelFabrics.materials(blocks, t -> fabric, i -> fabric);
        if (area == 0) return Double.NaN;
        double mass = 0;
        for (int i = 0; i < p.count(); i++) mass += p.mass(i);
        if (Double.isNaN(fabric.arealDensity)) return mass / area;
        double scale = fabric.arealDensity * area / mass;
        for (int i = 0; i < p.count(); i++) p.setMass(i, p.mass(i) * scale);
        return fabric.arealDensity;
    }
}
