package xpbdcloth.engine;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import xpbdcloth.mesh.ClothMesh;
import xpbdcloth.mesh.MeshTopology;

/**
 * Builds a cloth from any manifold triangle (or polygon) mesh with boundary: one particle per vertex at
 * its rest position, and the constraint families derived from the mesh's topology ({@link MeshTopology}):
 * <ul>
 * <li>structural: a distance constraint on every edge (polygon side or polyline segment);</li>
 * <li>shear: the angle at each face's first corner between its two sides (on a grid, the right angle
 *     between a particle's row and column threads; on a triangle whose three sides are kept, the angle is
 *     already fixed, so this family then only matters where the structural family is soft);</li>
 * <li>bend: a triangle bend constraint along every straight run b₀–v–b₁ (on a grid, the rows and
 *     columns; on a polar mesh, the rings and spokes).</li>
 * </ul>
 * Mass: an areal density lumped by faces (each face's area shared equally by its corners), a total mass
 * shared in the same proportions (by segment length for a polyline), or one mass per vertex as given.
 * Constraint order (the Gauss–Seidel order): structural by edge, shear by face, bend by run.
 */
public final class MeshClothBuilder {
    private final ClothMesh mesh;
    private double arealDensity = 0.1;
    private double totalMass = Double.NaN;
    private double[] masses;
    private final Map<ConstraintFamily, Material> families = new EnumMap<>(ConstraintFamily.class);
    private final List<Integer> pins = new ArrayList<>();

    public MeshClothBuilder(ClothMesh mesh) {
        if (mesh == null) throw new IllegalArgumentException("mesh must not be null, was null");
        if (mesh.vertexCount() < 2) throw new IllegalArgumentException("mesh must have at least 2 vertices, was " + mesh.vertexCount());
        this.mesh = mesh;
    }

    /** kg/m², &gt; 0, lumped to the vertices by face area. Replaces a total mass or given masses. */
    public MeshClothBuilder arealDensity(double kgPerSquareMetre) {
        arealDensity = Check.positive("arealDensity", kgPerSquareMetre);
        totalMass = Double.NaN;
        masses = null;
        return this;
    }

    /** kg, &gt; 0, shared by the vertices in proportion to their lumped area (or length). */
    public MeshClothBuilder totalMass(double kg) {
        totalMass = Check.positive("totalMass", kg);
        masses = null;
        return this;
    }

    /** One mass per vertex (kg, &gt; 0), used as given. */
    public MeshClothBuilder masses(double[] kg) {
        if (kg == null || kg.length != mesh.vertexCount())
            throw new IllegalArgumentException("masses must have one entry per vertex (" + mesh.vertexCount() + "), was " + (kg == null ? "null" : kg.length));
        for (int i = 0; i < kg.length; i++) Check.positive("masses[" + i + "]", kg[i]);
        masses = kg.clone();
        return this;
    }

    /** Includes a family with PBD stiffness k ∈ [0,1] and XPBD compliance α ≥ 0 (m/N). */
    public MeshClothBuilder family(ConstraintFamily family, double stiffness, double compliance) {
        return family(family, new Material(stiffness, compliance));
    }

    /**
     * Includes a family of the given material. The cloth has exactly the families it is given: none given,
     * it is particles without constraints.
     */
    public MeshClothBuilder family(ConstraintFamily family, Material m) {
        families.put(checkedFamily(family), java.util.Objects.requireNonNull(m, "material must not be null"));
        return this;
    }

    /** Includes every family of the map with its material (a preset's families, or another builder's). */
    public MeshClothBuilder families(Map<ConstraintFamily, Material> materials) {
        materials.forEach(this::family);
        return this;
    }

    static ConstraintFamily checkedFamily(ConstraintFamily family) {
        if (family != ConstraintFamily.STRUCTURAL && family != ConstraintFamily.SHEAR && family != ConstraintFamily.BEND)
            throw new IllegalArgumentException("family must be STRUCTURAL, SHEAR or BEND, was " + family);
        return family;
    }

    /** Pins vertices by index; checked at once. */
    public MeshClothBuilder pin(int... vertices) {
        for (int v : vertices) pins.add(Check.index("pin vertex", v, mesh.vertexCount()));
        return this;
    }

    public Cloth build() { return build(0, 0); }

    /** The cloth, remembering a grid's shape when the mesh is one (for row/column addressing). */
    Cloth build(int gridColumns, int gridRows) {
        int n = mesh.vertexCount();
        double[] m = masses != null ? masses : lumpedMasses();
        Particles p = new Particles(n);
        for (int i = 0; i < n; i++) {
            p.setPosition(i, mesh.x(i), mesh.y(i), mesh.z(i));
            p.setMass(i, m[i]);
        }
        for (int i : pins) p.pin(i);

        MeshTopology topology = MeshTopology.of(mesh);
        List<ConstraintBlock> blocks = new ArrayList<>();
        Material structural = families.get(ConstraintFamily.STRUCTURAL);
        if (structural != null) {
            int[] e = topology.edges();
            DistanceBlock b = tuned(new DistanceBlock(ConstraintFamily.STRUCTURAL, e.length / 2), structural, blocks);
            for (int k = 0; k < e.length; k += 2) b.addAtCurrentLength(p, e[k], e[k + 1]);
        }
        Material shear = families.get(ConstraintFamily.SHEAR);
        if (shear != null) {
            int[] c = topology.corners();
            ShearBlock b = tuned(new ShearBlock(ConstraintFamily.SHEAR, c.length / 3), shear, blocks);
            // A corner with a side of zero length (a cloth of no width or height: its columns or rows on one
            // another) has no angle at rest to keep. Given one (π/2), its energy would leap from nothing to
            // ½(θ − π/2)²/α the moment the side opened: a grab's 0.1 mm flung such a cloth at 8 m/s.
            for (int k = 0; k < c.length; k += 3)
                if (ShearBlock.hasAngle(p, c[k], c[k + 1], c[k + 2])) b.addAtCurrentAngle(p, c[k], c[k + 1], c[k + 2]);
        }
        Material bend = families.get(ConstraintFamily.BEND);
        if (bend != null) {
            int[] r = topology.straightRuns();
            BendBlock b = tuned(new BendBlock(ConstraintFamily.BEND, r.length / 3), bend, blocks);
            for (int k = 0; k < r.length; k += 3) b.addAtCurrentShape(p, r[k], r[k + 1], r[k + 2]);
        }
        return new Cloth(p, mesh, gridColumns, gridRows, blocks);
    }

    /** Face area shared equally by each face's corners; a polyline's length by each segment's ends. */
    private double[] lumpedMasses() {
        int n = mesh.vertexCount();
        double[] share = new double[n];
        double total = 0;
        for (int k = 0; k < mesh.faceCount(); k++) {
            int[] f = mesh.face(k);
            double a = mesh.faceArea(k);
            for (int v : f) share[v] += a / f.length;
            total += a;
        }
        boolean byArea = total > 0;
        if (!byArea) {
            if (Double.isNaN(totalMass))
                throw new IllegalArgumentException("arealDensity needs a mesh of non-zero area (use totalMass for a polyline or a flat-collapsed mesh), area was " + total);
            int[] s = mesh.segments();
            for (int k = 0; k < mesh.segmentCount(); k++) {
                double l = mesh.segmentLength(k);
                share[s[2 * k]] += l / 2;
                share[s[2 * k + 1]] += l / 2;
                total += l;
            }
        }
        double mass = Double.isNaN(totalMass) ? arealDensity * total : totalMass;
        double[] m = new double[n];
        for (int i = 0; i < n; i++) {
            if (total == 0) m[i] = mass / n;
            else if (share[i] == 0)
                throw new IllegalArgumentException("vertex " + i + " belongs to no face or segment, so it has no mass; remove it from the mesh");
            else m[i] = mass * share[i] / total;
        }
        return m;
    }

    /** The block, given the family's k and α and added to the list. */
    private static <B extends ConstraintBlock> B tuned(B block, Material m, List<ConstraintBlock> blocks) {
        block.setMaterial(m);
        blocks.add(block);
        return block;
    }
}
