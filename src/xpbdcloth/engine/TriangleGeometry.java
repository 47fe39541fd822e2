package xpbdcloth.engine;

/**
 * A point against a triangle: the closest point of the triangle and which feature it lies on, and the
 * first time a moving point meets a moving triangle's plane inside the triangle. Static maths on flat
 * arrays (vertex k at 3k), nothing allocated.
 */
final class TriangleGeometry {
    private TriangleGeometry() {}

    /** Features of a triangle a closest point can lie on: its face, an edge (ab, bc, ca), or a vertex. */
    static final int FACE = 0, EDGE_AB = 1, EDGE_BC = 2, EDGE_CA = 3, VERTEX_A = 4, VERTEX_B = 5, VERTEX_C = 6;

    /**
     * The point of triangle (a, b, c) closest to p, into out[0..2], its barycentric weights of a, b, c into
     * out[3..5]; returns the feature it lies on. Ericson 2005, "Real-Time Collision Detection", §5.1.5
     * (Voronoi regions of the vertices, then the edges, else the face).
     */
    static int closestPoint(double px, double py, double pz, double[] v, int a, int b, int c, double[] out) {
        double ax = v[3 * a], ay = v[3 * a + 1], az = v[3 * a + 2];
        double abx = v[3 * b] - ax, aby = v[3 * b + 1] - ay, abz = v[3 * b + 2] - az;
        double acx = v[3 * c] - ax, acy = v[3 * c + 1] - ay, acz = v[3 * c + 2] - az;
        double apx = px - ax, apy = py - ay, apz = pz - az;
        double d1 = abx * apx + aby * apy + abz * apz, d2 = acx * apx + acy * apy + acz * apz;
        if (d1 <= 0 && d2 <= 0) return at(out, 1, 0, 0, v, a, b, c, VERTEX_A);
        double bpx = px - v[3 * b], bpy = py - v[3 * b + 1], bpz = pz - v[3 * b + 2];
        double d3 = abx * bpx + aby * bpy + abz * bpz, d4 = acx * bpx + acy * bpy + acz * bpz;
        if (d3 >= 0 && d4 <= d3) return at(out, 0, 1, 0, v, a, b, c, VERTEX_B);
        double vc = d1 * d4 - d3 * d2;
        if (vc <= 0 && d1 >= 0 && d3 <= 0) {
            double t = d1 / (d1 - d3);
            return at(out, 1 - t, t, 0, v, a, b, c, EDGE_AB);
        }
        double cpx = px - v[3 * c], cpy = py - v[3 * c + 1], cpz = pz - v[3 * c + 2];
        double d5 = abx * cpx + aby * cpy + abz * cpz, d6 = acx * cpx + acy * cpy + acz * cpz;
        if (d6 >= 0 && d5 <= d6) return at(out, 0, 0, 1, v, a, b, c, VERTEX_C);
        double vb = d5 * d2 - d1 * d6;
        if (vb <= 0 && d2 >= 0 && d6 <= 0) {
            double t = d2 / (d2 - d6);
            return at(out, 1 - t, 0, t, v, a, b, c, EDGE_CA);
        }
        double va = d3 * d6 - d5 * d4;
        if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
            double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
            return at(out, 0, 1 - t, t, v, a, b, c, EDGE_BC);
        }
        double denom = 1 / (va + vb + vc);
        double sb = vb * denom, sc = vc * denom;
        return at(out, 1 - sb - sc, sb, sc, v, a, b, c, FACE);
    }

    private static int at(double[] out, double wa, double wb, double wc, double[] v, int a, int b, int c, int feature) {
        for (int d = 0; d < 3; d++) out[d] = wa * v[3 * a + d] + wb * v[3 * b + d] + wc * v[3 * c + d];
        out[3] = wa; out[4] = wb; out[5] = wc;
        return feature;
    }

    /**
     * The first time τ ∈ [0, 1] at which the point moving from p0 to p1 lies in the plane of the triangle
     * whose vertices move from v0 to v1 (all linearly over the substep) and inside it (barycentric weights ≥
     * −{@code slack}); −1 if never. The coplanarity of (x₁ − x₀, x₂ − x₀, p − x₀) is a cubic in τ (Provot
     * 1997, "Collision and self-collision handling in cloth model dedicated to design garments"; Bridson et
     * al. 2002, "Robust treatment of collisions, contact and friction for cloth animation", §4): its roots
     * are bracketed between the roots of its derivative and refined by bisection.
     */
    static double firstCoplanarTime(double p0x, double p0y, double p0z, double p1x, double p1y, double p1z,
                                    double[] v0, double[] v1, int a, int b, int c, double slack, double[] scratch) {
        coplanarCubic(v0, v1, a, b, c, p0x, p0y, p0z, p1x, p1y, p1z, scratch);
        return firstRootInside(p0x, p0y, p0z, p1x, p1y, p1z, v0, v1, a, b, c, slack, -1, -1, scratch);
    }

    /**
     * With {@link #coplanarCubic} in k[0..3]: its first root τ &gt; {@code after} at which the point is inside
     * the triangle (weights ≥ −slack); else 1 if the cubic ends within {@code endNoise} of 0 with the point
     * inside then (touching at the end, which round-off can hide from the roots); −1 if neither. A mesh body
     * takes every root in [0, 1] and no end touch (after = endNoise = −1); the cloth's guard takes τ &gt; 0
     * (a root at the start is a touch, not a crossing) and its round-off bound.
     */
    static double firstRootInside(double p0x, double p0y, double p0z, double p1x, double p1y, double p1z,
                                  double[] v0, double[] v1, int a, int b, int c, double slack, double after, double endNoise, double[] k) {
        final double end = k[0] + k[1] + k[2] + k[3];
        final int roots = coplanarRoots(k);
        final double t0 = k[4], t1 = k[5], t2 = k[6]; // insideAt writes over the scratch
        for (int r = 0; r < roots; r++) {
            final double t = r == 0 ? t0 : r == 1 ? t1 : t2;
            if (t > after && insideAt(t, p0x, p0y, p0z, p1x, p1y, p1z, v0, v1, a, b, c, slack, k)) return t;
        }
        return Math.abs(end) <= endNoise && insideAt(1, p0x, p0y, p0z, p1x, p1y, p1z, v0, v1, a, b, c, slack, k) ? 1 : -1;
    }

    /**
     * The coefficients k₀..k₃ (into k[0..3]) of the cubic det(e₁, e₂, q)(τ) whose roots are the times the
     * point p (moving p0 → p1) and the vertices a, b, c (moving v0 → v1) are coplanar: e₁ = b − a, e₂ = c − a,
     * q = p − a, each linear in τ. With a, b the ends of one edge, c and p of another, the same cubic gives
     * the times two edges are coplanar.
     */
    static void coplanarCubic(double[] v0, double[] v1, int a, int b, int c,
                              double p0x, double p0y, double p0z, double p1x, double p1y, double p1z, double[] k) {
        // e1 = A + τB, e2 = C + τD, q = E + τF.
        double Ax = v0[3 * b] - v0[3 * a], Ay = v0[3 * b + 1] - v0[3 * a + 1], Az = v0[3 * b + 2] - v0[3 * a + 2];
        double Bx = (v1[3 * b] - v1[3 * a]) - Ax, By = (v1[3 * b + 1] - v1[3 * a + 1]) - Ay, Bz = (v1[3 * b + 2] - v1[3 * a + 2]) - Az;
        double Cx = v0[3 * c] - v0[3 * a], Cy = v0[3 * c + 1] - v0[3 * a + 1], Cz = v0[3 * c + 2] - v0[3 * a + 2];
        double Dx = (v1[3 * c] - v1[3 * a]) - Cx, Dy = (v1[3 * c + 1] - v1[3 * a + 1]) - Cy, Dz = (v1[3 * c + 2] - v1[3 * a + 2]) - Cz;
        double Ex = p0x - v0[3 * a], Ey = p0y - v0[3 * a + 1], Ez = p0z - v0[3 * a + 2];
        double Fx = (p1x - v1[3 * a]) - Ex, Fy = (p1y - v1[3 * a + 1]) - Ey, Fz = (p1z - v1[3 * a + 2]) - Ez;
        // e1 × e2 = AC + τ(AD + BC) + τ² BD
        double acx = Ay * Cz - Az * Cy, acy = Az * Cx - Ax * Cz, acz = Ax * Cy - Ay * Cx;
        double adx = Ay * Dz - Az * Dy, ady = Az * Dx - Ax * Dz, adz = Ax * Dy - Ay * Dx;
        double bcx = By * Cz - Bz * Cy, bcy = Bz * Cx - Bx * Cz, bcz = Bx * Cy - By * Cx;
        double bdx = By * Dz - Bz * Dy, bdy = Bz * Dx - Bx * Dz, bdz = Bx * Dy - By * Dx;
        double mx = adx + bcx, my = ady + bcy, mz = adz + bcz;
        k[0] = acx * Ex + acy * Ey + acz * Ez;
        k[1] = acx * Fx + acy * Fy + acz * Fz + mx * Ex + my * Ey + mz * Ez;
        k[2] = mx * Fx + my * Fy + mz * Fz + bdx * Ex + bdy * Ey + bdz * Ez;
        k[3] = bdx * Fx + bdy * Fy + bdz * Fz;
    }

    /**
     * The roots in [0, 1] of the cubic k[0..3], ascending, into k[4..6] (at most one per monotone piece,
     * the pieces split at the derivative's roots, each refined by bisection; a piece starting or ending at
     * a zero gives that end); returns how many.
     */
    static int coplanarRoots(double[] k) {
        final double k0 = k[0], k1 = k[1], k2 = k[2], k3 = k[3];
        // Monotone pieces of [0, 1]: split at the derivative's roots 3k3 τ² + 2k2 τ + k1 = 0.
        double s1 = 2, s2 = 2;
        double qa = 3 * k3, qb = 2 * k2, qc = k1;
        if (Math.abs(qa) > 1e-300) {
            double disc = qb * qb - 4 * qa * qc;
            if (disc > 0) {
                double r = Math.sqrt(disc), q = -0.5 * (qb + Math.copySign(r, qb));
                double r1 = q / qa, r2 = q != 0 ? qc / q : r1;
                s1 = Math.min(r1, r2);
                s2 = Math.max(r1, r2);
            }
        } else if (Math.abs(qb) > 1e-300) {
            s1 = -qc / qb;
        }
        int roots = 0;
        double lo = 0;
        for (int piece = 0; piece < 3; piece++) {
            double hi = piece == 0 ? s1 : piece == 1 ? s2 : 1;
            if (!(hi > lo)) continue;
            hi = Math.min(hi, 1);
            double fl = cubic(k0, k1, k2, k3, lo), fh = cubic(k0, k1, k2, k3, hi);
            if (fl == 0 || fh == 0 || (fl < 0) != (fh < 0))
                k[4 + roots++] = fl == 0 ? lo : fh == 0 ? hi : bisect(k0, k1, k2, k3, lo, hi, fl);
            lo = hi;
            if (lo >= 1) break;
        }
        return roots;
    }

    private static double cubic(double k0, double k1, double k2, double k3, double t) { return ((k3 * t + k2) * t + k1) * t + k0; }

    private static double bisect(double k0, double k1, double k2, double k3, double lo, double hi, double flo) {
        boolean negativeLo = flo < 0;
        for (int it = 0; it < 50; it++) {
            double mid = 0.5 * (lo + hi), f = cubic(k0, k1, k2, k3, mid);
            if (f == 0) return mid;
            if ((f < 0) == negativeLo) lo = mid; else hi = mid;
        }
        return 0.5 * (lo + hi);
    }

    /** Whether the point at τ lies inside the triangle at τ (barycentric weights ≥ −slack), in the triangle's plane; uses s[0..8]. */
    static boolean insideAt(double t, double p0x, double p0y, double p0z, double p1x, double p1y, double p1z,
                                    double[] v0, double[] v1, int a, int b, int c, double slack, double[] s) {
        double u = 1 - t;
        for (int d = 0; d < 3; d++) {
            s[d] = u * v0[3 * a + d] + t * v1[3 * a + d];
            s[3 + d] = u * v0[3 * b + d] + t * v1[3 * b + d];
            s[6 + d] = u * v0[3 * c + d] + t * v1[3 * c + d];
        }
        double px = u * p0x + t * p1x, py = u * p0y + t * p1y, pz = u * p0z + t * p1z;
        double e1x = s[3] - s[0], e1y = s[4] - s[1], e1z = s[5] - s[2];
        double e2x = s[6] - s[0], e2y = s[7] - s[1], e2z = s[8] - s[2];
        double qx = px - s[0], qy = py - s[1], qz = pz - s[2];
        double d11 = e1x * e1x + e1y * e1y + e1z * e1z, d12 = e1x * e2x + e1y * e2y + e1z * e2z, d22 = e2x * e2x + e2y * e2y + e2z * e2z;
        double q1 = qx * e1x + qy * e1y + qz * e1z, q2 = qx * e2x + qy * e2y + qz * e2z;
        double det = d11 * d22 - d12 * d12;
        if (!(det > 0)) return false;
        double wb = (d22 * q1 - d12 * q2) / det, wc = (d11 * q2 - d12 * q1) / det;
        return wb >= -slack && wc >= -slack && wb + wc <= 1 + slack;
    }
}
