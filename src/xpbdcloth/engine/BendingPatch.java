package xpbdcloth.engine;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;

/**
 * The curvature of a flat cloth on each triangle, as three linear rows in the positions of the particles
 * around it: a Morley triangle whose edge slopes are read, exactly for any quadratic surface, from the
 * quadratics through each triangle and the three vertices across its edges.
 *
 * <pre>
 *   in the rest plane, z the height off it (the rows act on 3-D positions x_k the same way, per axis):
 *   q_t   the quadratic through t's corners and the vertices across its edges (six points; for a free
 *         edge, with normal m, the condition mᵀ∇²q m = 0 instead: no bending moment across it, ν = 0)
 *   s_e   the slope across edge e at its midpoint, ∂q/∂m_e, the mean of q_t's and its neighbour's: shared
 *   Morley: the quadratic on t with t's corner heights and slopes s_e at its edge midpoints,
 *         q = L + Σ_e β_e λ_p λ_q  (L the linear interpolant, e = (p, q), r the third corner, h_r its height)
 *         β_e − β_f − β_g = γ_e = 2 h_r (s_e − ∇L·m_e)   ⇒   β_e = (γ_e − Σγ)/2
 *   H_t = Σ_e β_e (∇λ_p ∇λ_qᵀ + ∇λ_q ∇λ_pᵀ)
 *   C_r = √A (H₁₁, H₂₂, √2 H₁₂)_r = Σ_k c_rk x_k ∈ ℝ³,   ½ B Σ_r |C_r|² = ½ B A |H|²  (A the rest area)
 * </pre>
 * Why: a hinge energy Σ_e k_e θ_e² cannot weight its edges so that every triangulation bends alike (bent
 * across a grid's diagonals, its axis edges fold by twice their share; a cantilever relaxes into shapes whose
 * diagonals take part of the bend); a quadratic through six points is exact for any quadratic surface but
 * each triangle's is its own, and zig-zag shapes between them lowered the energy again. Both measured
 * against the elastica in docs/fabric.md.
 * The Morley triangle (Morley 1968; the nonconforming plate element whose slopes at edge midpoints are
 * shared by the two triangles of an edge, so it passes the patch test and converges) closes that door; the
 * six-point quadratics give it slopes exact for quadratics on any mesh, so a uniformly curved sheet stores
 * exactly ½ B κ² A on every triangle however the cloth was cut. The energy is the plate's (Kirchhoff, with
 * Poisson's ratio 0: bending across the warp does not curl the weft, the usual choice for woven cloth).
 * As in Bergou et al. 2006 ("A Quadratic Bending Model for Inextensible Surfaces") the rows are a constant
 * linear map of positions: Σ_k c_rk = 0 and Σ_k c_rk x̄_k = 0, so C = 0 for any flat placement, and a rotation
 * turns C without changing |C|: for the near-isometric bending of cloth |C_r| is the curvature whatever
 * the sheet's rigid motion. The rows are turned (an orthogonal 3 × 3 change, which keeps Σ_r |C_r|²) so
 * that their coefficient vectors are orthogonal: one after another with equal masses is the block solve.
 * Degenerate cases: six points on one conic fix no quadratic; the fewest of the vertices across are left
 * out (their edges taken as free there) until they do (all three: the triangle alone, a plane).
 */
public final class BendingPatch {
    /** Particles around one triangle at most: its corners, the vertices across its edges, and theirs. */
    public static final int MAX_SLOTS = 12;

    private final double[] x;
    private final int[] triangles;
    /** For each triangle edge slot 3t + e (corner e to e + 1), the same edge's slot in the other triangle, or −1. */
    private final int[] twin;
    private final Fit[] fits;

    /** A flat mesh at rest: positions (3 per particle) and triangles (3 indices each). */
    public BendingPatch(double[] x, int particles, int[] triangles) {
        this.x = x;
        this.triangles = triangles;
        this.twin = twins(particles, triangles);
        this.fits = new Fit[triangles.length / 3];
    }

    /** Whether triangle t has a neighbour across at least one edge (a lone triangle has nothing to bend against). */
    public boolean bends(int t) {
        return twin[3 * t] >= 0 || twin[3 * t + 1] >= 0 || twin[3 * t + 2] >= 0;
    }

    /**
     * Whether triangle t and the triangles across its edges all have a neighbour across every edge: then no
     * free edge enters its rows, and they are exact for any quadratic surface.
     */
    public boolean surrounded(int t) {
        for (int e = 0; e < 3; e++) {
            int s = twin[3 * t + e];
            if (s < 0) return false;
            for (int f = 0; f < 3; f++) if (twin[s - s % 3 + f] < 0) return false;
        }
        return true;
    }

    /** The vertex across edge e of triangle t, or −1. */
    public int across(int t, int e) {
        int s = twin[3 * t + e];
        return s < 0 ? -1 : triangles[s - s % 3 + (s % 3 + 2) % 3];
    }

    /**
     * Triangle t's rows: the particles they take (stencil[0..n), returned n) and their coefficients,
     * c_rk at rows[MAX_SLOTS·r + k].
     */
    public int rows(int t, int[] stencil, double[] rows) {
        Frame f = new Frame(t);
        Map<Integer, Integer> slot = new HashMap<>();
        int n = 0;
        for (int k = 0; k < 3; k++) { stencil[n] = triangles[3 * t + k]; slot.put(stencil[n], n++); }
        // s_e per edge, as weights over the stencil.
        double[][] slope = new double[3][MAX_SLOTS];
        for (int e = 0; e < 3; e++) {
            int p = triangles[3 * t + e], q = triangles[3 * t + (e + 1) % 3];
            double[] mid = {0.5 * (x[3 * p] + x[3 * q]), 0.5 * (x[3 * p + 1] + x[3 * q + 1]), 0.5 * (x[3 * p + 2] + x[3 * q + 2])};
            double[] normal = f.inSpace(f.normalX[e], f.normalY[e]);
            int other = twin[3 * t + e];
            int[] sources = other < 0 ? new int[] {t} : new int[] {t, other / 3};
            for (int source : sources) {
                Fit fit = fit(source);
                double[] weight = fit.slope(mid, normal);
                for (int k = 0; k < Fit.POINTS; k++) {
                    int particle = fit.point[k];
                    double w = weight[k];
                    if (particle < 0 || w == 0) continue;
                    Integer s = slot.get(particle);
                    if (s == null) { stencil[n] = particle; slot.put(particle, s = n++); }
                    slope[e][s] += w / sources.length;
                }
            }
        }
        // Morley: γ_e = 2 h_r (s_e − ∇L·m_e), β_e = (γ_e − Σγ)/2, H = Σ β_e (∇λ_p∇λ_qᵀ + ∇λ_q∇λ_pᵀ).
        double[][] gamma = new double[3][MAX_SLOTS];
        for (int e = 0; e < 3; e++) {
            int r = (e + 2) % 3;
            double h = 1 / Math.hypot(f.gradX[r], f.gradY[r]);
            for (int k = 0; k < n; k++) gamma[e][k] = 2 * h * slope[e][k];
            // ∇L = Σ_c z_c ∇λ_c over the corners (slots 0..2).
            for (int c = 0; c < 3; c++) gamma[e][c] -= 2 * h * (f.gradX[c] * f.normalX[e] + f.gradY[c] * f.normalY[e]);
        }
        double[] g = new double[3 * MAX_SLOTS];
        double root = Math.sqrt(f.area);
        for (int e = 0; e < 3; e++) {
            int p = e, q = (e + 1) % 3;
            double h11 = 2 * f.gradX[p] * f.gradX[q], h22 = 2 * f.gradY[p] * f.gradY[q], h12 = f.gradX[p] * f.gradY[q] + f.gradY[p] * f.gradX[q];
            for (int k = 0; k < n; k++) {
                double beta = 0.5 * (gamma[e][k] - gamma[0][k] - gamma[1][k] - gamma[2][k]);
                g[k] += root * beta * h11;
                g[MAX_SLOTS + k] += root * beta * h22;
                g[2 * MAX_SLOTS + k] += root * Math.sqrt(2) * beta * h12;
            }
        }
        orthogonalRows(g, n, rows);
        return n;
    }

    /** Triangle t's plane: a frame (origin its centroid), its corners' barycentric gradients and its edges' outward normals. */
    private final class Frame {
        final double ox, oy, oz, e1x, e1y, e1z, e2x, e2y, e2z, area;
        final double[] gradX = new double[3], gradY = new double[3], normalX = new double[3], normalY = new double[3];

        Frame(int t) {
            int a = triangles[3 * t], b = triangles[3 * t + 1], c = triangles[3 * t + 2];
            ox = (x[3 * a] + x[3 * b] + x[3 * c]) / 3; oy = (x[3 * a + 1] + x[3 * b + 1] + x[3 * c + 1]) / 3; oz = (x[3 * a + 2] + x[3 * b + 2] + x[3 * c + 2]) / 3;
            double ux = x[3 * b] - x[3 * a], uy = x[3 * b + 1] - x[3 * a + 1], uz = x[3 * b + 2] - x[3 * a + 2];
            double vx = x[3 * c] - x[3 * a], vy = x[3 * c + 1] - x[3 * a + 1], vz = x[3 * c + 2] - x[3 * a + 2];
            double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
            double twice = Math.sqrt(nx * nx + ny * ny + nz * nz), ul = Math.sqrt(ux * ux + uy * uy + uz * uz);
            if (!(twice > 0 && ul > 0)) throw new IllegalArgumentException("triangle " + t + " (" + a + ", " + b + ", " + c + ") has no area at rest");
            area = 0.5 * twice;
            e1x = ux / ul; e1y = uy / ul; e1z = uz / ul;
            nx /= twice; ny /= twice; nz /= twice;
            e2x = ny * e1z - nz * e1y; e2y = nz * e1x - nx * e1z; e2z = nx * e1y - ny * e1x;
            double[] cx = new double[3], cy = new double[3];
            for (int k = 0; k < 3; k++) { cx[k] = px(triangles[3 * t + k]); cy[k] = py(triangles[3 * t + k]); }
            for (int k = 0; k < 3; k++) {
                // ∇λ_k = rot90(x_{k+2} − x_{k+1}) / 2A, pointing from the opposite edge toward corner k.
                int i = (k + 1) % 3, j = (k + 2) % 3;
                double det = (cx[1] - cx[0]) * (cy[2] - cy[0]) - (cx[2] - cx[0]) * (cy[1] - cy[0]);
                gradX[k] = (cy[i] - cy[j]) / det;
                gradY[k] = (cx[j] - cx[i]) / det;
            }
            for (int e = 0; e < 3; e++) {
                // Edge e (corner e to e + 1) faces corner r = e + 2: its outward normal is −∇λ_r/|∇λ_r|.
                int r = (e + 2) % 3;
                double l = Math.hypot(gradX[r], gradY[r]);
                normalX[e] = -gradX[r] / l; normalY[e] = -gradY[r] / l;
            }
        }

        /** The in-plane vector (a, b) of this frame, in space. */
        double[] inSpace(double a, double b) { return new double[] {a * e1x + b * e2x, a * e1y + b * e2y, a * e1z + b * e2z}; }

        double px(int particle) { return (x[3 * particle] - ox) * e1x + (x[3 * particle + 1] - oy) * e1y + (x[3 * particle + 2] - oz) * e1z; }
        double py(int particle) { return (x[3 * particle] - ox) * e2x + (x[3 * particle + 1] - oy) * e2y + (x[3 * particle + 2] - oz) * e2z; }
    }

    /** Triangle s's {@link Fit}, made the first time a patch asks (each is read by up to four patches). */
    private Fit fit(int s) {
        if (fits[s] == null) fits[s] = new Fit(s);
        return fits[s];
    }

    /**
     * The quadratic through triangle s's corners and the vertices across its edges, in s's affine coordinates
     * (ξ, η), the corners at (0, 0), (1, 0), (0, 1) (a quadratic in x is one in ξ; these keep the 6 × 6 system
     * well conditioned however long and thin the triangle, and need no frame): its six coefficients
     * (1, ξ, η, ξ², ξη, η²) as weights of the points' heights.
     */
    private final class Fit {
        static final int POINTS = 6;
        final int[] point = new int[POINTS];
        /** Corner a of s, and the rows of J⁻¹ (J = [b − a, c − a]) as vectors in space: ξ = r₁·(x − a), η = r₂·(x − a). */
        final double[] origin, r1, r2;
        double[][] inverse;

        Fit(int s) {
            int a = triangles[3 * s], b = triangles[3 * s + 1], c = triangles[3 * s + 2];
            origin = new double[] {x[3 * a], x[3 * a + 1], x[3 * a + 2]};
            double[] u = new double[3], v = new double[3];
            for (int k = 0; k < 3; k++) { u[k] = x[3 * b + k] - origin[k]; v[k] = x[3 * c + k] - origin[k]; }
            double uu = dot(u, u), uv = dot(u, v), vv = dot(v, v), det = uu * vv - uv * uv;
            r1 = new double[3]; r2 = new double[3];
            for (int k = 0; k < 3; k++) { r1[k] = (vv * u[k] - uv * v[k]) / det; r2[k] = (uu * v[k] - uv * u[k]) / det; }
            Frame own = new Frame(s);
            // The neighbours to leave out, fewest first: none, each one, each two, all three (the triangle alone: a plane).
            for (int drop : new int[] {0, 1, 2, 4, 3, 5, 6, 7}) {
                boolean changed = drop == 0;
                for (int k = 0; k < 3; k++) point[k] = triangles[3 * s + k];
                for (int e = 0; e < 3; e++) {
                    int across = (drop >> e & 1) != 0 ? -1 : across(s, e);
                    if (across != across(s, e)) changed = true;
                    point[3 + e] = across;
                }
                if (!changed) continue;
                double[][] rows = new double[POINTS][];
                for (int k = 0; k < POINTS; k++) {
                    if (point[k] >= 0) {
                        double[] d = {x[3 * point[k]] - origin[0], x[3 * point[k] + 1] - origin[1], x[3 * point[k] + 2] - origin[2]};
                        double xi = dot(r1, d), eta = dot(r2, d);
                        rows[k] = new double[] {1, xi, eta, xi * xi, xi * eta, eta * eta};
                    } else {
                        // A free edge of s: mᵀ∇²q m = 0 with m its outward normal, in ξ as J⁻¹m.
                        double[] m = own.inSpace(own.normalX[k - 3], own.normalY[k - 3]);
                        double p = dot(r1, m), q = dot(r2, m), l = Math.hypot(p, q);
                        p /= l; q /= l; // the condition is homogeneous: a unit row keeps the pivots comparable
                        rows[k] = new double[] {0, 0, 0, p * p, p * q, q * q};
                    }
                }
                inverse = invert(rows);
                if (inverse != null) return;
            }
            throw new IllegalArgumentException("triangle " + s + " (" + a + ", " + b + ", " + c + ") fixes no curvature even alone: its edges are not three directions");
        }

        /** The weights of the points' heights in ∂q/∂m at the point {@code at}, m a unit vector in the plane (both in space). */
        double[] slope(double[] at, double[] m) {
            double[] d = {at[0] - origin[0], at[1] - origin[1], at[2] - origin[2]};
            double xi = dot(r1, d), eta = dot(r2, d), u = dot(r1, m), w = dot(r2, m);
            // ∇_x q = J⁻ᵀ ∇_ξ q, so ∂q/∂m = (J⁻¹m)·∇_ξ q = u (q₁ + 2q₃ξ + q₄η) + w (q₂ + q₄ξ + 2q₅η).
            double[] along = {0, u, w, 2 * xi * u, eta * u + xi * w, 2 * eta * w};
            double[] out = new double[POINTS];
            for (int k = 0; k < POINTS; k++) {
                if (point[k] < 0) continue;
                for (int j = 0; j < POINTS; j++) out[k] += along[j] * inverse[j][k];
            }
            return out;
        }
    }

    private static double dot(double[] a, double[] b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

    /** For each edge slot 3t + e, the slot of the same edge in the first other triangle that has it, or −1. */
    private static int[] twins(int particles, int[] triangles) {
        TriangleEdges edges = TriangleEdges.of(triangles, particles);
        int[] out = new int[triangles.length];
        for (int s = 0; s < triangles.length; s++) {
            int e = edges.edgeOf(s), first = edges.firstSide(e);
            out[s] = s == first ? edges.secondSide(e) : first;
        }
        return out;
    }

    /** The n-column rows g turned by the eigenvectors of G Gᵀ into out: Σ_r |C_r|² unchanged, coefficient vectors orthogonal. */
    private static void orthogonalRows(double[] g, int n, double[] out) {
        double[][] m = new double[3][3];
        for (int r = 0; r < 3; r++)
            for (int s = 0; s < 3; s++)
                for (int k = 0; k < n; k++) m[r][s] += g[MAX_SLOTS * r + k] * g[MAX_SLOTS * s + k];
        double[][] q = symmetricEigenvectors(m);
        Arrays.fill(out, 0, 3 * MAX_SLOTS, 0);
        for (int r = 0; r < 3; r++)
            for (int k = 0; k < n; k++)
                for (int s = 0; s < 3; s++) out[MAX_SLOTS * r + k] += q[s][r] * g[MAX_SLOTS * s + k];
    }

    /** Eigenvectors (columns) of a symmetric 3 × 3 matrix by cyclic Jacobi rotations; m is destroyed. */
    static double[][] symmetricEigenvectors(double[][] m) {
        double[][] q = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        for (int sweep = 0; sweep < 50; sweep++) {
            double off = m[0][1] * m[0][1] + m[0][2] * m[0][2] + m[1][2] * m[1][2];
            double scale = m[0][0] * m[0][0] + m[1][1] * m[1][1] + m[2][2] * m[2][2];
            if (!(off > 1e-30 * scale)) break;
            for (int p = 0; p < 2; p++)
                for (int r = p + 1; r < 3; r++) {
                    if (m[p][r] == 0) continue;
                    double theta = (m[r][r] - m[p][p]) / (2 * m[p][r]);
                    double t = theta == 0 ? 1 : Math.signum(theta) / (Math.abs(theta) + Math.sqrt(theta * theta + 1));
                    double cs = 1 / Math.sqrt(t * t + 1), sn = t * cs;
                    for (int k = 0; k < 3; k++) { // m ← m J (columns p, r)
                        double mp = m[k][p], mr = m[k][r];
                        m[k][p] = cs * mp - sn * mr; m[k][r] = sn * mp + cs * mr;
                    }
                    for (int k = 0; k < 3; k++) { // m ← Jᵀ m (rows p, r)
                        double mp = m[p][k], mr = m[r][k];
                        m[p][k] = cs * mp - sn * mr; m[r][k] = sn * mp + cs * mr;
                    }
                    for (int k = 0; k < 3; k++) {
                        double qp = q[k][p], qr = q[k][r];
                        q[k][p] = cs * qp - sn * qr; q[k][r] = sn * qp + cs * qr;
                    }
                }
        }
        return q;
    }

    /** The inverse of a square matrix by Gauss–Jordan elimination with partial pivoting; null if singular. */
    static double[][] invert(double[][] matrix) {
        int n = matrix.length;
        double[][] a = new double[n][2 * n];
        double size = 0;
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) { a[i][j] = matrix[i][j]; size = Math.max(size, Math.abs(matrix[i][j])); }
            a[i][n + i] = 1;
        }
        for (int col = 0; col < n; col++) {
            int pivot = col;
            for (int i = col + 1; i < n; i++) if (Math.abs(a[i][col]) > Math.abs(a[pivot][col])) pivot = i;
            if (!(Math.abs(a[pivot][col]) > 1e-9 * size)) return null;
            double[] swap = a[col]; a[col] = a[pivot]; a[pivot] = swap;
            double inv = 1 / a[col][col];
            for (int j = 0; j < 2 * n; j++) a[col][j] *= inv;
            for (int i = 0; i < n; i++) {
                if (i == col || a[i][col] == 0) continue;
                double f = a[i][col];
                for (int j = 0; j < 2 * n; j++) a[i][j] -= f * a[col][j];
            }
        }
        double[][] out = new double[n][n];
        for (int i = 0; i < n; i++) System.arraycopy(a[i], n, out[i], 0, n);
        return out;
    }
}
