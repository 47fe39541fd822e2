package xpbdcloth.pattern;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import xpbdcloth.mesh.ClothMesh;

/**
 * A pattern cut into triangles: each panel meshed on its own ({@link PanelMesher}) at a target edge length,
 * placed around the body, with its stitches: the vertex pairs each seam will pull together.
 *
 * <p>The outlines are sampled first, all together, because a seam's two sides must have matching vertices:
 * a seam gets round(mean length / edge) stitches at equal fractions of each side's length (so an eased side,
 * the shorter one, gets shorter segments), and a corner inside a stretch moves the nearest stitch onto it
 * (a corner is never cut off). Outline between seams is cut into segments near the target length, every
 * corner kept. Vertices are numbered panel by panel, each panel's outline samples first.
 */
public final class PatternMesh {
    public final Pattern pattern;
    /** The target edge length (m). */
    public final double edge;
    /** Placed positions (x, y, z per vertex). */
    private final double[] positions;
    /** Pattern-plane positions (x, y per vertex): the flat rest shape. */
    private final double[] flat;
    /** Fabric coordinates (u along the grain, v across; per vertex). */
    private final double[] uvs;
    private final int[] triangles;
    /** First vertex and first triangle (index into triangles / 3) of each panel, and the totals last. */
    private final int[] panelVertices, panelTriangles;
    /** Per seam: the stitched vertex pairs (a, b, a, b, …), start to end. */
    private final Map<String, int[]> stitches = new LinkedHashMap<>();

    private PatternMesh(Pattern pattern, double edge, double[] positions, double[] flat, double[] uvs, int[] triangles, int[] panelVertices, int[] panelTriangles) {
        this.pattern = pattern;
        this.edge = edge;
        this.positions = positions;
        this.flat = flat;
        this.uvs = uvs;
        this.triangles = triangles;
        this.panelVertices = panelVertices;
        this.panelTriangles = panelTriangles;
    }

    /** A stitch position on a panel's outline: arc length from corner 0, and the seam stitches that land there. */
    private static final class Sample {
        double along;
        final List<int[]> stitches = new ArrayList<>();  // (seam index, side 0|1, stitch k)

        Sample(double along) { this.along = along; }
    }

    /**
     * @param edge target edge length (m), at most a quarter of the smallest panel's outline length
     * @throws IllegalArgumentException naming the panel when an edge length cannot mesh it
     */
    public static PatternMesh of(Pattern pattern, double edge) {
        if (!(edge > 0) || Double.isInfinite(edge)) throw new IllegalArgumentException("edge length must be > 0 m, was " + edge);
        List<Panel> panels = pattern.panels();
        Map<String, List<Sample>> samples = new LinkedHashMap<>();
        for (Panel p : panels) samples.put(p.name, new ArrayList<>());
        List<Seam> seams = pattern.seams();
        int[] stitchCount = new int[seams.size()];
        for (int s = 0; s < seams.size(); s++) {
            Seam seam = seams.get(s);
            double[] fractions = stitchFractions(pattern, seam, edge);
            stitchCount[s] = fractions.length;
            Stretch[] sides = {seam.a, seam.b};
            for (int side = 0; side < 2; side++) {
                Outline o = pattern.panel(sides[side].panel).outline;
                for (int k = 0; k < fractions.length; k++) {
                    Sample x = new Sample(sides[side].arcLengthAt(o, fractions[k]));
                    x.stitches.add(new int[] {s, side, k});
                    samples.get(sides[side].panel).add(x);
                }
            }
        }

        List<double[]> positions = new ArrayList<>(), flat = new ArrayList<>(), uvs = new ArrayList<>();
        List<int[]> triangles = new ArrayList<>();
        int[] panelVertices = new int[panels.size() + 1], panelTriangles = new int[panels.size() + 1];
        int[][][] stitchVertex = new int[seams.size()][2][];
        for (int s = 0; s < seams.size(); s++) { stitchVertex[s][0] = new int[stitchCount[s]]; stitchVertex[s][1] = new int[stitchCount[s]]; }
        double[] p2 = new double[2], p3 = new double[6], uv = new double[2];
        for (int pi = 0; pi < panels.size(); pi++) {
            Panel panel = panels.get(pi);
            Outline o = panel.outline;
            List<Sample> outline = sampleOutline(panel, samples.get(panel.name), pattern, edge);
            boolean reverse = !o.counterClockwise();
            int nb = outline.size();
            double[] boundary = new double[2 * nb];
            for (int i = 0; i < nb; i++) {
                o.pointAt(outline.get(reverse ? nb - 1 - i : i).along, p2);
                boundary[2 * i] = p2[0]; boundary[2 * i + 1] = p2[1];
            }
            PanelMesher.Result mesh;
            try {
                mesh = PanelMesher.mesh(boundary, edge);
            } catch (RuntimeException e) {
                throw new IllegalArgumentException("panel \"" + panel.name + "\" could not be meshed at edge " + edge + " m: " + e.getMessage(), e);
            }
            int base = positions.size();
            panelVertices[pi] = base;
            panelTriangles[pi] = triangles.size();
            var env = o.polygon(8).getEnvelopeInternal();
            double cx = (env.getMinX() + env.getMaxX()) / 2, cy = (env.getMinY() + env.getMaxY()) / 2;
            for (int i = 0; i < mesh.pointCount(); i++) {
                double x = mesh.points[2 * i], y = mesh.points[2 * i + 1];
                panel.placement.place(x, y, cx, cy, 0, 0, p3);
                positions.add(new double[] {p3[0], p3[1], p3[2]});
                flat.add(new double[] {x, y});
                panel.fabricCoordinates(x, y, uv);
                uvs.add(uv.clone());
            }
            for (int t = 0; t < mesh.triangles.length; t += 3)
                triangles.add(new int[] {base + mesh.triangles[t], base + mesh.triangles[t + 1], base + mesh.triangles[t + 2]});
            for (int i = 0; i < nb; i++)
                for (int[] st : outline.get(i).stitches)
                    stitchVertex[st[0]][st[1]][st[2]] = base + (reverse ? nb - 1 - i : i);
        }
        panelVertices[panels.size()] = positions.size();
        panelTriangles[panels.size()] = triangles.size();

        PatternMesh m = new PatternMesh(pattern, edge, flatten(positions, 3), flatten(flat, 2), flatten(uvs, 2),
                flattenIndices(triangles, 3), panelVertices, panelTriangles);
        for (int s = 0; s < seams.size(); s++) {
            int[] pairs = new int[2 * stitchCount[s]];
            for (int k = 0; k < stitchCount[s]; k++) { pairs[2 * k] = stitchVertex[s][0][k]; pairs[2 * k + 1] = stitchVertex[s][1][k]; }
            m.stitches.put(seams.get(s).name, pairs);
        }
        return m;
    }

    /**
     * The fractions (0 … 1 of each side's length) at which a seam is stitched: uniform, round(mean length /
     * edge) segments, with the stitch nearest each corner inside either stretch moved onto it (or one added
     * when that stitch is taken by another corner).
     */
    private static double[] stitchFractions(Pattern pattern, Seam seam, double edge) {
        Outline oa = pattern.panel(seam.a.panel).outline, ob = pattern.panel(seam.b.panel).outline;
        double la = seam.a.length(oa), lb = seam.b.length(ob);
        int n = Math.max(1, (int) Math.round((la + lb) / 2 / edge));
        double[] a = innerCorners(seam.a, oa), b = innerCorners(seam.b, ob);
        // Uniform stitches, then each corner onto the nearest inner stitch not yet moved, or one more stitch after them.
        double[] out = new double[n + 1 + a.length + b.length];
        for (int k = 0; k <= n; k++) out[k] = (double) k / n;
        boolean[] moved = new boolean[n + 1];
        int count = n + 1;
        for (double[] corners : new double[][] {a, b})
            for (double c : corners) {
                int k = (int) Math.round(c * n);
                if (k > 0 && k < n && !moved[k]) { out[k] = c; moved[k] = true; }
                else out[count++] = c;
            }
        out = Arrays.copyOf(out, count);
        Arrays.sort(out);
        // Two corners at the same fraction (both sides cornered alike) are one stitch.
        int w = 1;
        for (int i = 1; i < out.length; i++) if (out[i] - out[w - 1] > 1e-9) out[w++] = out[i];
        return Arrays.copyOf(out, w);
    }

    /** Fractions of the stretch's length at which it passes a corner of its outline (ends excluded). */
    private static double[] innerCorners(Stretch st, Outline o) {
        double length = st.length(o), start = o.arcLength(st.from), total = o.length();
        double[] corners = o.cornerArcLengths(), out = new double[corners.length];
        int count = 0;
        for (double corner : corners) {
            double d = st.backward ? start - corner : corner - start;
            d = ((d % total) + total) % total;
            if (d > 1e-9 * total && d < length - 1e-9 * total) out[count++] = d / length;
        }
        return Arrays.copyOf(out, count);
    }

    /**
     * A panel's outline samples in order from corner 0: its seams' stitches, its corners, and between them,
     * where no seam runs, segments near the target length.
     */
    private static List<Sample> sampleOutline(Panel panel, List<Sample> stitched, Pattern pattern, double edge) {
        Outline o = panel.outline;
        double total = o.length(), tolerance = 1e-9 * total;
        List<Sample> all = new ArrayList<>(stitched);
        List<double[]> sewn = new ArrayList<>();  // (start, length) of each stretch on this panel
        for (Seam s : pattern.seams())
            for (Stretch st : new Stretch[] {s.a, s.b})
                if (st.panel.equals(panel.name)) {
                    double l = st.length(o);
                    sewn.add(new double[] {st.backward ? st.arcLengthAt(o, 1) : st.arcLengthAt(o, 0), l});
                }
        List<Double> breaks = new ArrayList<>();
        for (double c : o.cornerArcLengths()) breaks.add(c);
        for (double[] s : sewn) { breaks.add(s[0]); breaks.add((s[0] + s[1]) % total); }
        breaks.sort(null);
        for (int i = 0; i < breaks.size(); i++) {
            double a = breaks.get(i), b = i + 1 < breaks.size() ? breaks.get(i + 1) : breaks.get(0) + total;
            all.add(new Sample(a));
            if (b - a <= tolerance || isSewn((a + b) / 2, sewn, total)) continue;
            int pieces = Math.max(1, (int) Math.round((b - a) / edge));
            for (int j = 1; j < pieces; j++) all.add(new Sample((a + (b - a) * j / pieces) % total));
        }
        // A stitch computed onto a corner lands there to rounding; the corner's own position is the exact one.
        double[] corners = o.cornerArcLengths();
        for (Sample s : all) {
            if (s.along > total - tolerance) s.along = 0;
            for (double c : corners) if (Math.abs(s.along - c) <= tolerance) s.along = c;
        }
        all.sort((x, y) -> Double.compare(x.along, y.along));
        List<Sample> merged = new ArrayList<>();
        for (Sample s : all) {
            Sample last = merged.isEmpty() ? null : merged.get(merged.size() - 1);
            if (last != null && s.along - last.along <= tolerance) last.stitches.addAll(s.stitches);
            else merged.add(s);
        }
        return merged;
    }

    private static boolean isSewn(double along, List<double[]> sewn, double total) {
        for (double[] s : sewn) {
            double d = ((along - s[0]) % total + total) % total;
            if (d < s[1]) return true;
        }
        return false;
    }

    private static double[] flatten(List<double[]> rows, int width) {
        double[] out = new double[rows.size() * width];
        for (int i = 0; i < rows.size(); i++) System.arraycopy(rows.get(i), 0, out, i * width, width);
        return out;
    }

    private static int[] flattenIndices(List<int[]> rows, int width) {
        int[] out = new int[rows.size() * width];
        for (int i = 0; i < rows.size(); i++) System.arraycopy(rows.get(i), 0, out, i * width, width);
        return out;
    }

    public int vertexCount() { return positions.length / 3; }

    public int triangleCount() { return triangles.length / 3; }

    public double[] positions() { return positions.clone(); }

    /** The flat rest shape: each vertex where it lies on its panel's pattern (x, y). */
    public double[] flatPositions() { return flat.clone(); }

    /** Fabric coordinates per vertex (u along the grain, v across). */
    public double[] fabricCoordinates() { return uvs.clone(); }

    public int[] triangles() { return triangles.clone(); }

    /** Vertices [first, last) of the i-th panel (in the pattern's order). */
    public int[] panelVertexRange(int i) { return new int[] {panelVertices[i], panelVertices[i + 1]}; }

    /** Triangles [first, last) of the i-th panel. */
    public int[] panelTriangleRange(int i) { return new int[] {panelTriangles[i], panelTriangles[i + 1]}; }

    /** Each vertex's panel (its index in the pattern's order). */
    public int[] panelOfVertex() { return panelOf(panelVertices); }

    /** Each triangle's panel. */
    public int[] panelOfTriangle() { return panelOf(panelTriangles); }

    /** Each item's panel, from the panels' first items (and the total last). */
    private static int[] panelOf(int[] firsts) {
        int[] out = new int[firsts[firsts.length - 1]];
        for (int p = 0; p + 1 < firsts.length; p++) java.util.Arrays.fill(out, firsts[p], firsts[p + 1], p);
        return out;
    }

    /** The seam's stitches: vertex pairs (side a, side b), start to end. */
    public int[] stitches(String seam) { return stitches.get(seam).clone(); }

    /**
     * Each vertex's representative once every seam is closed: stitched vertices (a corner where three panels
     * meet is stitched twice over) share the smallest index among them; every other vertex is its own.
     */
    public int[] welded() {
        int[] root = new int[vertexCount()];
        for (int v = 0; v < root.length; v++) root[v] = v;
        for (int[] pairs : stitches.values())
            for (int k = 0; k < pairs.length; k += 2) {
                int a = find(root, pairs[k]), b = find(root, pairs[k + 1]);
                if (a != b) root[Math.max(a, b)] = Math.min(a, b);
            }
        for (int v = 0; v < root.length; v++) root[v] = find(root, v);
        return root;
    }

    private static int find(int[] root, int v) {
        while (root[v] != v) v = root[v] = root[root[v]];
        return v;
    }

    /** The hinges across the seams: four particles each, and each one's (A₀ + A₁)/|e|² in the flat pattern. */
    public static final class SeamHinges {
        /** (o0, o1, e0, e1) per hinge. */
        public final int[] particles;
        public final double[] restAreaOverEdgeSquared;

        SeamHinges(int[] particles, double[] restAreaOverEdgeSquared) {
            this.particles = particles;
            this.restAreaOverEdgeSquared = restAreaOverEdgeSquared;
        }
    }

    /** Every seam's stitches, in the pattern's order, as one list of pairs (a, b, a, b, …). */
    public int[] allStitches() {
        return stitches.values().stream().flatMapToInt(java.util.Arrays::stream).toArray();
    }

    /**
     * The hinges across the seams once closed: per pair of consecutive stitches, the two outline triangles on
     * either side, as (o0, o1, e0, e1) with the edge e0–e1 on side a (o0's triangle wound e0, e1, o0 and o1's
     * e1, e0, o1 counter-clockwise: a flat seam is a dihedral angle of 0), with (A₀ + A₁)/|e|² in the flat
     * pattern (|e|² the mean of the two sides', eased or not). A seam whose triangles on its two sides share
     * their far corner is refused (IllegalArgumentException naming the seam): the mesh is too coarse for it.
     */
    public SeamHinges seamHinges() {
        closeSeams();
        if (seamProblem != null) throw new IllegalArgumentException(seamProblem);
        return seamHinges;
    }

    /**
     * Why the seams cannot close as meshed (the message {@link #seamHinges} throws), or null when they can:
     * one check for the loader, the fuzzer and the {@code pattern} command, computed once per mesh.
     */
    public String seamProblem() {
        closeSeams();
        return seamProblem;
    }

    private SeamHinges seamHinges;
    private String seamProblem;

    private void closeSeams() {
        if (seamHinges != null || seamProblem != null) return;
        try {
            seamHinges = buildSeamHinges();
        } catch (IllegalArgumentException tooCoarse) {
            seamProblem = tooCoarse.getMessage();
        }
    }

    private SeamHinges buildSeamHinges() {
        int count = 0;
        for (int[] pairs : stitches.values()) count += Math.max(0, pairs.length / 2 - 1);
        int[] hinge = new int[4 * count];
        double[] rest = new double[count];
        Map<Long, Integer> opposite = new java.util.HashMap<>();  // directed boundary edge a→b (CCW) → opposite vertex
        Map<Long, Integer> uses = new java.util.HashMap<>();
        for (int t = 0; t < triangles.length; t += 3)
            for (int k = 0; k < 3; k++) {
                int a = triangles[t + k], b = triangles[t + (k + 1) % 3];
                uses.merge(undirected(a, b), 1, Integer::sum);
                opposite.put((long) a << 32 | b, triangles[t + (k + 2) % 3]);
            }
        int h = 0;
        for (Map.Entry<String, int[]> seam : stitches.entrySet()) {
            int[] pairs = seam.getValue();
            for (int k = 0; k + 3 < pairs.length; k += 2) {
                int a0 = pairs[k], b0 = pairs[k + 1], a1 = pairs[k + 2], b1 = pairs[k + 3];
                boolean forward = opposite.containsKey((long) a0 << 32 | a1);
                int e0 = forward ? a0 : a1, e1 = forward ? a1 : a0, f0 = forward ? b1 : b0, f1 = forward ? b0 : b1;
                Integer o0 = opposite.get((long) e0 << 32 | e1), o1 = opposite.get((long) f0 << 32 | f1);
                if (o0 == null || o1 == null || uses.get(undirected(e0, e1)) != 1 || uses.get(undirected(f0, f1)) != 1)
                    throw new IllegalArgumentException("seam \"" + seam.getKey() + "\": stitches " + k / 2 + " and " + (k / 2 + 1) + " are not joined by an outline edge on both sides");
                // One triangle reaching from one side of a seam to the other (a sleeve meshed two edges round):
                // closed, the seam would lay its two triangles face to face as one.
                if (o0.equals(o1))
                    throw new IllegalArgumentException("seam \"" + seam.getKey() + "\" would close two triangles into one (vertex " + o0
                            + " is the far corner of the triangles on both its sides, at stitches " + k / 2 + " and " + (k / 2 + 1)
                            + "): the panels are meshed too coarsely for it; a shorter edge gives the seam room");
                double e2 = (flatDistance2(e0, e1) + flatDistance2(f0, f1)) / 2;
                rest[h] = (flatArea(o0, e0, e1) + flatArea(o1, f0, f1)) / e2;
                hinge[4 * h] = o0; hinge[4 * h + 1] = o1; hinge[4 * h + 2] = e0; hinge[4 * h + 3] = e1;
                h++;
            }
        }
        return new SeamHinges(hinge, rest);
    }

    private static long undirected(int a, int b) { return (long) Math.min(a, b) << 32 | Math.max(a, b); }

    private double flatDistance2(int a, int b) {
        double dx = flat[2 * a] - flat[2 * b], dy = flat[2 * a + 1] - flat[2 * b + 1];
        return dx * dx + dy * dy;
    }

    private double flatArea(int a, int b, int c) {
        return Math.abs((flat[2 * b] - flat[2 * a]) * (flat[2 * c + 1] - flat[2 * a + 1]) - (flat[2 * c] - flat[2 * a]) * (flat[2 * b + 1] - flat[2 * a + 1])) / 2;
    }

    /**
     * As a cloth mesh: the placed positions, the triangles with the fabric coordinates as their texture
     * coordinates, and a vertex group per panel (its name) and per seam ("seam NAME", both sides), spaces
     * in names written as underscores (an OBJ group name is one word).
     */
    public ClothMesh toClothMesh() {
        int[][] faces = new int[triangleCount()][];
        double[][] faceUVs = new double[faces.length][];
        for (int t = 0; t < faces.length; t++) {
            faces[t] = Arrays.copyOfRange(triangles, 3 * t, 3 * t + 3);
            faceUVs[t] = new double[6];
            for (int k = 0; k < 3; k++) {
                faceUVs[t][2 * k] = uvs[2 * faces[t][k]];
                faceUVs[t][2 * k + 1] = uvs[2 * faces[t][k] + 1];
            }
        }
        Map<String, int[]> groups = new LinkedHashMap<>();
        List<Panel> panels = pattern.panels();
        for (int i = 0; i < panels.size(); i++) {
            int[] range = panelVertexRange(i);
            int[] g = new int[range[1] - range[0]];
            for (int v = 0; v < g.length; v++) g[v] = range[0] + v;
            groups.put(oneWord(panels.get(i).name), g);
        }
        for (Map.Entry<String, int[]> e : stitches.entrySet()) groups.put(oneWord("seam " + e.getKey()), e.getValue().clone());
        return ClothMesh.withTextureCoordinates(positions, faces, faceUVs, null, groups);
    }

    private static String oneWord(String name) { return name.trim().replaceAll("\\s+", "_"); }
}
