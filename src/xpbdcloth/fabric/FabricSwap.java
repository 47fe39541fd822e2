package xpbdcloth.fabric;

import java.util.List;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.DihedralBlock;
import xpbdcloth.engine.MembraneBlock;
import xpbdcloth.engine.QuadraticBendBlock;
import xpbdcloth.engine.Particles;

/**
 * Makes a running cloth another fabric without a reset: every membrane triangle takes the new moduli,
 * every dihedral bend the new bending stiffness, and every particle's mass scales so the cloth has the
 * new areal density. Rest shapes, warp directions, tethers, positions and velocities stay, so the cloth
 * carries on from where it is as the new material (XPBD's λ restart each step, so nothing stale remains).
 */
public final class FabricSwap {
    private FabricSwap() {}

    /**
     * @param blocks the simulation's blocks (its membrane and dihedral blocks are changed)
     * @return the cloth's areal density after the swap, kg/m² (NaN if it has no membrane to measure area by)
     */
    public static double apply(List<ConstraintBlock> blocks, Particles p, Fabric fabric) {
        if (fabric == null) throw new IllegalArgumentException("fabric must not be null, was null");
        double area = 0;
        for (ConstraintBlock b : blocks) {
            if (b instanceof MembraneBlock) {
                MembraneBlock m = (MembraneBlock) b;
                for (int t = 0; t < m.triangleCount(); t++) {
                    m.setMaterial(t, fabric.membrane);
                    area += m.area(t);
                }
            } else if (b instanceof DihedralBlock && b.family() != ConstraintFamily.SEAM) {  // a seam's hinges: Sewing.useBendingStiffness
                DihedralBlock d = (DihedralBlock) b;
                for (int i = 0; i < d.count(); i++) d.setBendingStiffness(i, fabric.bendingStiffness);
            } else if (b instanceof QuadraticBendBlock) {
                QuadraticBendBlock q = (QuadraticBendBlock) b;
                for (int u = 0; u < q.hingeCount(); u++) q.setBendingStiffness(u, fabric.bendingStiffness);
            }
        }
        if (area == 0) return Double.NaN;
        double mass = 0;
        for (int i = 0; i < p.count(); i++) mass += p.mass(i);
        if (Double.isNaN(fabric.arealDensity)) return mass / area;
        double scale = fabric.arealDensity * area / mass;
        for (int i = 0; i < p.count(); i++) p.setMass(i, p.mass(i) * scale);
        return fabric.arealDensity;
    }
}
