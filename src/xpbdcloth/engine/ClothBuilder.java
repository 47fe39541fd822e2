package xpbdcloth.engine;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import xpbdcloth.mesh.ClothMesh;

/**
 * Builds a grid cloth: columns × rows particles spanning width × height metres, hanging in the x–y plane
 * (top edge at the origin's height) or lying in the x–z plane, with the constraint families asked for.
 * A rope is a cloth of one column. The grid is one generator of a {@link ClothMesh} ({@link #mesh()});
 * {@link MeshClothBuilder} derives the constraints from it as from any other mesh.
 *
 * <p>Mass: either an areal density (kg/m²) or a total mass (kg), lumped to the particles by the grid area
 * (or length) each one stands for, so edge particles weigh half an interior one and corners a quarter.
 *
 * <p>Constraint order (the Gauss–Seidel order), as the mesh's sorted topology gives it: structural
 * row-major (each particle's right then lower edge), then shear per quad, then bend (each particle's row
 * run then its column run).
 */
public final class ClothBuilder {
    /** Orientation of the rest shape. */
    public enum Plane { VERTICAL, HORIZONTAL }

    private int columns = 16, rows = 16;
    private double width = 1, height = 1;
    private double originX = 0, originY = 0, originZ = 0;
    private Plane plane = Plane.VERTICAL;
    private double arealDensity = 0.1;
    private double totalMass = Double.NaN;
    private final Map<ConstraintFamily, Material> families = new EnumMap<>(ConstraintFamily.class);
    private final List<int[]> pins = new ArrayList<>();

    /** Particle counts along the width (columns ≥ 1) and the height (rows ≥ 2), at least 2 particles. */
    public ClothBuilder resolution(int columns, int rows) {
        Check.atLeast("columns", columns, 1);
        Check.atLeast("rows", rows, 1);
        long n = columns * (long) rows;
        if (n < 2) throw new IllegalArgumentException("columns*rows must be >= 2, was " + n);
        if (n > EngineRange.MAX_PARTICLES)
            throw new IllegalArgumentException("columns*rows must be <= " + EngineRange.MAX_PARTICLES + " (2048 x 2048), was " + columns + " x " + rows + " = " + n);
        this.columns = columns;
        this.rows = rows;
        return this;
    }

    /** Size in metres (a size along a single-particle direction is ignored). */
    public ClothBuilder size(double width, double height) {
        this.width = Check.nonNegative("width", width);
        this.height = Check.nonNegative("height", height);
        return this;
    }

    /** Centre of the top edge (vertical) or of the cloth (horizontal), metres. */
    public ClothBuilder origin(double x, double y, double z) {
        Check.finite3("origin", x, y, z);
        originX = x; originY = y; originZ = z;
        return this;
    }

    public ClothBuilder plane(Plane p) {
        if (p == null) throw new IllegalArgumentException("plane must not be null, was null");
        plane = p;
        return this;
    }

    /** kg/m², &gt; 0. Replaces any total mass. */
    public ClothBuilder arealDensity(double kgPerSquareMetre) {
        arealDensity = Check.positive("arealDensity", kgPerSquareMetre);
        totalMass = Double.NaN;
        return this;
    }

    /** kg, &gt; 0, shared by the particles by lumped area. Replaces any areal density. */
    public ClothBuilder totalMass(double kg) {
        totalMass = Check.positive("totalMass", kg);
        return this;
    }

    /** Includes a family with PBD stiffness k ∈ [0,1] and XPBD compliance α ≥ 0 (m/N). */
    public ClothBuilder family(ConstraintFamily family, double stiffness, double compliance) {
        return family(family, new Material(stiffness, compliance));
    }

    /** Includes a family of the given material; the cloth has exactly the families it is given (none: no constraints). */
    public ClothBuilder family(ConstraintFamily family, Material m) {
        families.put(MeshClothBuilder.checkedFamily(family), java.util.Objects.requireNonNull(m, "material must not be null"));
        return this;
    }

    /** Includes every family of the map with its material. */
    public ClothBuilder families(Map<ConstraintFamily, Material> materials) {
        materials.forEach(this::family);
        return this;
    }

    /** Pins particle (row, col); checked against the resolution at {@link #build}. */
    public ClothBuilder pin(int row, int col) {
        pins.add(new int[] {row, col});
        return this;
    }

    public ClothBuilder pinTopCorners() {
        pins.add(new int[] {0, 0});
        pins.add(new int[] {0, -1});
        return this;
    }

    public Cloth build() {
        for (int[] pin : pins) {
            int col = pin[1] < 0 ? columns + pin[1] : pin[1];
            Check.index("pin row", pin[0], rows);
            Check.index("pin col", col, columns);
        }
        if (Double.isNaN(totalMass) && area() == 0)
            throw new IllegalArgumentException("arealDensity needs a cloth of non-zero area (use totalMass for a zero-area cloth), area was 0.0");
        MeshClothBuilder b = new MeshClothBuilder(mesh()).masses(masses()).families(families);
        for (int[] pin : pins) b.pin(pin[0] * columns + (pin[1] < 0 ? columns + pin[1] : pin[1]));
        return b.build(columns, rows);
    }

    /**
     * The grid as a mesh: quads (i, i + columns, i + columns + 1, i + 1), counter-clockwise seen from the
     * front, split along alternating diagonals so the mesh has no preferred shear direction; a single row
     * or column is a polyline.
     */
    public ClothMesh mesh() {
        double dx = columns > 1 ? width / (columns - 1) : 0;
        double dy = rows > 1 ? height / (rows - 1) : 0;
        double[] x = new double[3 * columns * rows];
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < columns; c++) {
                int i = 3 * (r * columns + c);
                double u = c * dx - 0.5 * width * (columns > 1 ? 1 : 0), t = r * dy;
                if (plane == Plane.VERTICAL) { x[i] = originX + u; x[i + 1] = originY - t; x[i + 2] = originZ; }
                else { x[i] = originX + u; x[i + 1] = originY; x[i + 2] = originZ - 0.5 * height * (rows > 1 ? 1 : 0) + t; }
            }
        }
        if (columns == 1 || rows == 1) return ClothMesh.polyline(x);
        int[][] quads = new int[(columns - 1) * (rows - 1)][];
        int[] tris = new int[quads.length * 6];
        int q = 0, n = 0;
        for (int r = 0; r + 1 < rows; r++)
            for (int c = 0; c + 1 < columns; c++) {
                int i = r * columns + c;
                quads[q++] = new int[] {i, i + columns, i + columns + 1, i + 1};
                if (((r + c) & 1) == 0) {
                    tris[n++] = i; tris[n++] = i + columns; tris[n++] = i + 1;
                    tris[n++] = i + 1; tris[n++] = i + columns; tris[n++] = i + columns + 1;
                } else {
                    tris[n++] = i; tris[n++] = i + columns; tris[n++] = i + columns + 1;
                    tris[n++] = i; tris[n++] = i + columns + 1; tris[n++] = i + 1;
                }
            }
        return ClothMesh.of(x, quads, tris, null, null);
    }

    /** Mass lumped by the grid area (or length) each particle stands for: half on an edge, a quarter at a corner. */
    private double[] masses() {
        double mass = Double.isNaN(totalMass) ? arealDensity * area() : totalMass;
        double weightSum = lumpWeightSum(columns) * lumpWeightSum(rows);
        double[] m = new double[columns * rows];
        for (int r = 0; r < rows; r++)
            for (int c = 0; c < columns; c++) m[r * columns + c] = mass * lumpWeight(c, columns) * lumpWeight(r, rows) / weightSum;
        return m;
    }

    private double area() {
        double w = columns > 1 ? width : 1, h = rows > 1 ? height : 1;
        return w * h;
    }

    /** Share of a particle along one grid direction: half at the ends, whole inside, 1 for a single one. */
    private static double lumpWeight(int i, int count) {
        if (count == 1) return 1;
        return i == 0 || i == count - 1 ? 0.5 : 1;
    }

    private static double lumpWeightSum(int count) {
        return count == 1 ? 1 : count - 1;
    }
}
