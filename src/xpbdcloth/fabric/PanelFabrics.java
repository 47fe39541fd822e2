package xpbdcloth.fabric;

import java.util.List;
import java.util.function.IntFunction;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.DihedralBlock;
import xpbdcloth.engine.MembraneBlock;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.QuadraticBendBlock;

/**
 * A cloth cut from panels of different fabrics (a garment): each panel's membrane triangles take its
 * fabric's moduli, its bending hinges its fabric's bending stiffness, and every particle the mass of its
 * share of its triangles' cut areas at their panels' densities,
 * <pre>
 *   m_i = Σ_{t ∋ i} ρ_t A_t / 3
 * </pre>
 * (A_t the triangle's rest area, as the membrane holds it: the flat pattern's), so the cloth weighs
 * Σ_p ρ_p A_p, its panels' cut areas at their densities. A hinge never spans two panels: panels meet only
 * at seams, whose hinges the sewing keeps ({@link xpbdcloth.engine.Sewing}). Every panel of one fabric is a
 * cloth of that fabric; the sketch's F key makes a garment that.
 */
public final class PanelFabrics {
    private PanelFabrics() {}

    /**
     * @param blocks          the cloth's fabric blocks (one membrane block over all its triangles, in order)
     * @param panelOfParticle each particle's panel
     * @param panelOfTriangle each triangle's panel
     * @param fabrics         each panel's fabric; if any has no areal density (moduli given without one), the
     *                        particles keep the masses they were given
     */
    public static void apply(List<ConstraintBlock> blocks, Particles p, int[] panelOfParticle, int[] panelOfTriangle, Fabric[] fabrics) {
        if (panelOfParticle.length != p.count())
            throw new IllegalArgumentException("panelOfParticle must have one entry per particle (" + p.count() + "), was " + panelOfParticle.length);
        MembraneBlock membrane = null;
        for (ConstraintBlock b : blocks) {
            if (!(b instanceof MembraneBlock)) continue;
            if (membrane != null) throw new IllegalArgumentException("blocks must hold one membrane block, had two");
            membrane = (MembraneBlock) b;
        }
        if (membrane == null) throw new IllegalArgumentException("blocks must hold the cloth's membrane block, had none");
        if (membrane.triangleCount() != panelOfTriangle.length)
            throw new IllegalArgumentException("panelOfTriangle must have one entry per membrane triangle (" + membrane.triangleCount() + "), was " + panelOfTriangle.length);
        materials(blocks, t -> fabrics[panelOfTriangle[t]], i -> fabrics[panelOfParticle[i]]);
        for (Fabric f : fabrics) if (Double.isNaN(f.arealDensity)) return;
        double[] mass = new double[p.count()];
        for (int t = 0; t < membrane.triangleCount(); t++) {
            double share = fabrics[panelOfTriangle[t]].arealDensity * membrane.area(t) / 3;
            for (int c = 0; c < 3; c++) mass[membrane.particle(3 * t, c)] += share;
        }
        for (int i = 0; i < mass.length; i++) if (mass[i] > 0) p.setMass(i, mass[i]);
    }

    /**
     * The fabric's materials on a cloth's blocks: each membrane triangle t takes the moduli of
     * {@code ofTriangle(t)}, each bending hinge (not a seam's: {@link xpbdcloth.engine.Sewing#useBendingStiffness})
     * the bending stiffness of {@code ofParticle} at its first particle. Returns the membrane's rest area (m²,
     * 0 without one). {@link FabricSwap} is this with one fabric everywhere.
     */
    static double materials(List<ConstraintBlock> blocks, IntFunction<Fabric> ofTriangle, IntFunction<Fabric> ofParticle) {
        double area = 0;
        for (ConstraintBlock b : blocks) {
            if (b instanceof MembraneBlock) {
                MembraneBlock m = (MembraneBlock) b;
                for (int t = 0; t < m.triangleCount(); t++) {
                    m.setMaterial(t, ofTriangle.apply(t).membrane);
                    area += m.area(t);
                }
            } else if (b instanceof DihedralBlock && b.family() != ConstraintFamily.SEAM) {
                DihedralBlock d = (DihedralBlock) b;
                for (int i = 0; i < d.count(); i++) d.setBendingStiffness(i, ofParticle.apply(d.particle(i, 0)).bendingStiffness);
            } else if (b instanceof QuadraticBendBlock) {
                QuadraticBendBlock q = (QuadraticBendBlock) b;
                for (int u = 0; u < q.hingeCount(); u++) q.setBendingStiffness(u, ofParticle.apply(q.particle(3 * u, 0)).bendingStiffness);
            }
        }
        return area;
    }
}
