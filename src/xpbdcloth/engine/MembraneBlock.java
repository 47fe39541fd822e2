package xpbdcloth.engine;

import java.util.Arrays;

/**
 * An orthotropic elastic membrane: the in-plane strain energy of each triangle (Saint Venant–Kirchhoff
 * with a plane-stress orthotropic stiffness), written as three scalar XPBD constraints per triangle.
 *
 * <pre>
 *   D = rest edges [x̄₁−x̄₀, x̄₂−x̄₀] in the material frame (u along warp, v along weft), 2×2
 *   F = [x₁−x₀, x₂−x₀] D⁻¹ = [f_u f_v] (3×2),   Green strain E = ½(FᵀF − I)
 *   ε = (E_uu, E_vv, γ = 2E_uv),   U = ½ A εᵀ Q ε      (A rest area, Q in N/m)
 *   Q = 1/(1−ν₁₂ν₂₁) [[E₁, ν₂₁E₁, 0], [ν₁₂E₂, E₂, 0], [0, 0, (1−ν₁₂ν₂₁)G₁₂]] × thickness,   ν₂₁ = ν₁₂E₂/E₁
 *   Q = q L Lᵀ (Cholesky, q = the larger of Q_uu, Q_vv)  ⇒  U = Σ_r ½ C_r²/α with
 *   C_r = (Lᵀε)_r,   α = 1/(q A)
 *   ∇ε: ∂E_uu/∂x₁ = D⁻¹₀₀ f_u, ∂E_uu/∂x₂ = D⁻¹₁₀ f_u;  ∂E_vv/∂x₁ = D⁻¹₀₁ f_v, ∂E_vv/∂x₂ = D⁻¹₁₁ f_v;
 *       ∂γ/∂x₁ = D⁻¹₀₀ f_v + D⁻¹₀₁ f_u,  ∂γ/∂x₂ = D⁻¹₁₀ f_v + D⁻¹₁₁ f_u;  ∂/∂x₀ = −(∂/∂x₁ + ∂/∂x₂)
 *   ∇C_r = Σ_k L_kr ∇ε_k
 * </pre>
 * Why three rows: the Cholesky factor turns the coupled block into rows with one scalar compliance each,
 * so each row is an ordinary XPBD constraint row (its own λ, evaluated and differentiated alone: the
 * global solver, the fit and the residual take rows), and the energy, hence XPBD's equilibrium, is
 * exactly the block's. A projection solves a triangle's three rows together ({@link #project}), the
 * block form of Macklin et al. 2016, eq. 11: F is computed once, and the rows no longer undo each other
 * in turn, so a sweep converges further than three scalar projections would.
 * Sources: the constitutive model is the textbook orthotropic plane-stress law (e.g. Jones, "Mechanics of
 * Composite Materials", ch. 2); strain energy as XPBD constraints with compliance the inverse stiffness:
 * Macklin, Müller, Chentanez 2016, "XPBD", §4 and §6; the Green-strain triangle as in Müller, Chentanez,
 * Kim, Macklin 2014, "Strain Based Dynamics". Green strain makes U invariant under rigid motion (tested);
 * at the small strains of woven cloth it is Hooke's law (tested against E·t·W/L, ν and G).
 * Degenerate case: a zero-area rest triangle has no D⁻¹ and is refused when added.
 */
public final class MembraneBlock extends ConstraintBlock {
    /** D⁻¹ per constraint (the three rows of one triangle share it), row-major: a, b, c, d. */
    double[] restInverse;
    /** The row of Lᵀ each constraint takes: coefficients of (E_uu, E_vv, γ). */
    double[] row;
    /** Rest area per constraint, m². */
    double[] area;

    public MembraneBlock(ConstraintFamily family, int triangleCapacity) {
        super(family, 3, 3, 3 * Math.max(triangleCapacity, 1));
        restInverse = new double[4 * lambda.length];
        row = new double[3 * lambda.length];
        area = new double[lambda.length];
    }

    /** Triangles in the block (three constraints each). */
    public int triangleCount() { return count / 3; }

    /**
     * Adds triangle (i0, i1, i2) at the particles' current (rest) shape, its warp along the given
     * direction projected into the triangle's plane (weft perpendicular to it, in the plane).
     * Returns the triangle's index.
     */
    public int addTriangle(Particles p, int i0, int i1, int i2, double warpX, double warpY, double warpZ, OrthotropicMaterial m) {
        if (i0 == i1 || i1 == i2 || i0 == i2)
            throw new IllegalArgumentException("triangle particles must be distinct, was " + i0 + ", " + i1 + ", " + i2);
        double[] x = p.x;
        double e1x = x[3 * i1] - x[3 * i0], e1y = x[3 * i1 + 1] - x[3 * i0 + 1], e1z = x[3 * i1 + 2] - x[3 * i0 + 2];
        double e2x = x[3 * i2] - x[3 * i0], e2y = x[3 * i2 + 1] - x[3 * i0 + 1], e2z = x[3 * i2 + 2] - x[3 * i0 + 2];
        double nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
        double twiceArea = Math.sqrt(nx * nx + ny * ny + nz * nz);
        double longest = Math.max(Math.sqrt(e1x * e1x + e1y * e1y + e1z * e1z), Math.sqrt(e2x * e2x + e2y * e2y + e2z * e2z));
        if (!(twiceArea > 1e-12 * longest * longest))
            throw new IllegalArgumentException("triangle (" + i0 + ", " + i1 + ", " + i2 + ") has zero area at rest");
        nx /= twiceArea; ny /= twiceArea; nz /= twiceArea;
        // Warp: the given direction with its normal part removed.
        double along = warpX * nx + warpY * ny + warpZ * nz;
        double ux = warpX - along * nx, uy = warpY - along * ny, uz = warpZ - along * nz;
        double ul = Math.sqrt(ux * ux + uy * uy + uz * uz);
        if (!(ul > 1e-9 * Math.sqrt(warpX * warpX + warpY * warpY + warpZ * warpZ)))
            throw new IllegalArgumentException("warp direction (" + warpX + ", " + warpY + ", " + warpZ + ") is normal to triangle ("
                    + i0 + ", " + i1 + ", " + i2 + "): it has no direction in the cloth there");
        ux /= ul; uy /= ul; uz /= ul;
        double vx = ny * uz - nz * uy, vy = nz * ux - nx * uz, vz = nx * uy - ny * ux; // v = n × u
        double d00 = e1x * ux + e1y * uy + e1z * uz, d01 = e2x * ux + e2y * uy + e2z * uz;
        double d10 = e1x * vx + e1y * vy + e1z * vz, d11 = e2x * vx + e2y * vy + e2z * vz;
        double det = d00 * d11 - d01 * d10;
        int triangle = count / 3;
        for (int r = 0; r < 3; r++) {
            int i = newSlot();
            particles[3 * i] = i0; particles[3 * i + 1] = i1; particles[3 * i + 2] = i2;
            restInverse[4 * i] = d11 / det; restInverse[4 * i + 1] = -d01 / det;
            restInverse[4 * i + 2] = -d10 / det; restInverse[4 * i + 3] = d00 / det;
            area[i] = 0.5 * twiceArea;
        }
        setMaterial(triangle, m);
        return triangle;
    }

    /** Gives triangle t the material m (rows and compliance; its rest shape and frame stay). */
    public void setMaterial(int t, OrthotropicMaterial m) {
        double[] q = m.stiffness();
        setStiffness(t, q[0], q[1], q[4], q[8]);
    }

    /**
     * Gives triangle t the plane-stress stiffness Q (N/m) = [[q11, q12, 0], [q12, q22, 0], [0, 0, shear]] for
     * ε = (E_uu, E_vv, γ); positive definite (q11, q22, shear > 0, q12² &lt; q11·q22). Allocation-free, for a
     * stiffness that follows the strain ({@code MeasuredStiffening}).
     */
    public void setStiffness(int t, double q11, double q12, double q22, double shear) {
        if (!(q11 > 0 && q22 > 0 && shear > 0 && q12 * q12 < q11 * q22))
            throw new IllegalArgumentException("stiffness must be positive definite, was q11 " + q11 + ", q12 " + q12 + ", q22 " + q22 + ", shear " + shear);
        double scale = Math.max(q11, q22);
        // Q/scale = L Lᵀ with L lower triangular (Q has no normal–shear coupling in the material frame).
        double l00 = Math.sqrt(q11 / scale), l10 = q12 / scale / l00, l11 = Math.sqrt(q22 / scale - l10 * l10), l22 = Math.sqrt(shear / scale);
        // Row r of Lᵀ: (Lᵀε)_0 = l00 ε₀ + l10 ε₁, (Lᵀε)_1 = l11 ε₁, (Lᵀε)_2 = l22 ε₂.
        final int i = 3 * t, k = 3 * i;
        row[k] = l00; row[k + 1] = l10; row[k + 2] = 0;
        row[k + 3] = 0; row[k + 4] = l11; row[k + 5] = 0;
        row[k + 6] = 0; row[k + 7] = 0; row[k + 8] = l22;
        for (int r = 0; r < 3; r++) setCompliance(i + r, 1 / (scale * area[i + r]));
        materialChanged(); // the rows too, whatever the compliances did
    }

    /**
     * Triangle t's right Cauchy–Green tensor C = FᵀF in the material frame, (C_uu, C_vv, C_uv) into out[0..2]
     * (C = I + 2E). Allocation-free; not for the solver's threads (it uses the block's scratch).
     */
    public void rightCauchyGreen(int t, Particles p, double[] out) {
        System.arraycopy(gram(t, p), 0, out, 0, 3);
    }

    /** The triangle's Green strain (E_uu, E_vv, γ) in the material frame. */
    public double[] strain(int t, Particles p) {
        double[] f = new double[6], eps = new double[3];
        deformation(3 * t, p.x, f);
        strain(f, eps);
        return eps;
    }

    /**
     * Triangle t's largest principal stretch less one: √(1 + 2E₁) − 1 with E₁ the larger eigenvalue of the
     * Green strain tensor [[E_uu, γ/2], [γ/2, E_vv]]. It is the engineering strain along the direction the
     * triangle stretches most, the number a spring's |x|/L − 1 reads, so springs and fabric compare.
     * Allocation-free (the HUD calls it every frame); not for the solver's threads (it uses the block's scratch).
     */
    public double principalStrain(int t, Particles p) {
        final double[] g = gram(t, p);
        double euu = 0.5 * (g[0] - 1), evv = 0.5 * (g[1] - 1), half = 0.5 * (euu - evv);
        double largest = 0.5 * (euu + evv) + Math.sqrt(half * half + 0.25 * g[2] * g[2]);
        return Math.sqrt(Math.max(0, 1 + 2 * largest)) - 1;
    }

    /** Triangle t's larger normal Green strain, max(E_uu, E_vv): along the warp or the weft. Allocation-free, as above. */
    public double largestNormalStrain(int t, Particles p) {
        final double[] g = gram(t, p);
        return 0.5 * (Math.max(g[0], g[1]) - 1);
    }

    private final double[] gramScratch = new double[3];

    /** f_u·f_u, f_v·f_v, f_u·f_v of triangle t (Fᵀ F), in the block's scratch. */
    private double[] gram(int t, Particles p) {
        final double[] x = p.x;
        final int i = 3 * t, a = 3 * particles[3 * i], b = 3 * particles[3 * i + 1], c = 3 * particles[3 * i + 2];
        final double P = restInverse[4 * i], Q = restInverse[4 * i + 1], R = restInverse[4 * i + 2], S = restInverse[4 * i + 3];
        double uu = 0, vv = 0, uv = 0;
        for (int k = 0; k < 3; k++) {
            double e1 = x[b + k] - x[a + k], e2 = x[c + k] - x[a + k];
            double fu = e1 * P + e2 * R, fv = e1 * Q + e2 * S;
            uu += fu * fu;
            vv += fv * fv;
            uv += fu * fv;
        }
        gramScratch[0] = uu;
        gramScratch[1] = vv;
        gramScratch[2] = uv;
        return gramScratch;
    }

    /** Rest area of triangle t, m². */
    public double area(int t) { return area[3 * t]; }

    /** f_u, f_v (the columns of F) of constraint i into f[0..5]. */
    private void deformation(int i, double[] x, double[] f) {
        final int a = 3 * particles[3 * i], b = 3 * particles[3 * i + 1], c = 3 * particles[3 * i + 2];
        final double p = restInverse[4 * i], q = restInverse[4 * i + 1], r = restInverse[4 * i + 2], s = restInverse[4 * i + 3];
        for (int k = 0; k < 3; k++) {
            double e1 = x[b + k] - x[a + k], e2 = x[c + k] - x[a + k];
            f[k] = e1 * p + e2 * r;
            f[3 + k] = e1 * q + e2 * s;
        }
    }

    private static void strain(double[] f, double[] eps) {
        eps[0] = 0.5 * (f[0] * f[0] + f[1] * f[1] + f[2] * f[2] - 1);
        eps[1] = 0.5 * (f[3] * f[3] + f[4] * f[4] + f[5] * f[5] - 1);
        eps[2] = f[0] * f[3] + f[1] * f[4] + f[2] * f[5];
    }

    /** C of constraint i: its row of Lᵀ times the Green strain (no scratch arrays: the HUD's residual calls it every frame). */
    @Override public double evaluate(int i, Particles p) {
        final double[] x = p.x;
        final int a = 3 * particles[3 * i], b = 3 * particles[3 * i + 1], c = 3 * particles[3 * i + 2];
        final double P = restInverse[4 * i], Q = restInverse[4 * i + 1], R = restInverse[4 * i + 2], S = restInverse[4 * i + 3];
        double uu = 0, vv = 0, uv = 0;
        for (int k = 0; k < 3; k++) {
            double e1 = x[b + k] - x[a + k], e2 = x[c + k] - x[a + k], fu = e1 * P + e2 * R, fv = e1 * Q + e2 * S;
            uu += fu * fu; vv += fv * fv; uv += fu * fv;
        }
        return row[3 * i] * 0.5 * (uu - 1) + row[3 * i + 1] * 0.5 * (vv - 1) + row[3 * i + 2] * uv;
    }

    @Override public void gradient(int i, Particles p, double[] out) {
        double[] f = new double[6];
        deformation(i, p.x, f);
        rowGradient(i, f, out);
    }

    /**
     * ∇C of constraint i into out[0..8] (x₀, x₁, x₂), from f and the row r: with g_u = r₀ f_u + r₂ f_v
     * and g_v = r₁ f_v + r₂ f_u, ∂C/∂x₁ = D⁻¹₀₀ g_u + D⁻¹₀₁ g_v and ∂C/∂x₂ = D⁻¹₁₀ g_u + D⁻¹₁₁ g_v
     * (the header's ∇ε summed with the row's weights).
     */
    private void rowGradient(int i, double[] f, double[] out) {
        final double r0 = row[3 * i], r1 = row[3 * i + 1], r2 = row[3 * i + 2];
        final double p = restInverse[4 * i], q = restInverse[4 * i + 1], r = restInverse[4 * i + 2], s = restInverse[4 * i + 3];
        for (int k = 0; k < 3; k++) {
            double gu = r0 * f[k] + r2 * f[3 + k], gv = r1 * f[3 + k] + r2 * f[k];
            double g1 = p * gu + q * gv, g2 = r * gu + s * gv;
            out[3 + k] = g1;
            out[6 + k] = g2;
            out[k] = -g1 - g2;
        }
    }

    /** Solved with its compliance in PBD mode too: its rows' compliances are the fabric's moduli. */
    @Override boolean compliantInAnyMode() { return true; }

    /**
     * One projection of triangle t: its three rows solved together (Macklin et al. 2016, eq. 11 for one
     * triangle; Gauss–Seidel over triangles), so a triangle's rows no longer undo each other in turn and
     * its deformation gradient is computed once, not three times.
     * <pre>
     *   g_{r,v} = a_v gu_r + b_v gv_r     (a, b) = (−P−R, −Q−S), (P, Q), (R, S) for x₀, x₁, x₂
     *   A_rs = Σ_v w_v g_{r,v}·g_{s,v} = W_aa gu_r·gu_s + W_ab (gu_r·gv_s + gv_r·gu_s) + W_bb gv_r·gv_s   (+ α̃_r on the diagonal)
     *   A Δλ = −C − α̃λ (in either mode: {@link #compliantInAnyMode}),   Δx_v = w_v (a_v Σ_r Δλ_r gu_r + b_v Σ_r Δλ_r gv_r)
     * </pre>
     * A is solved by LDLᵀ; a row whose pivot vanishes (nothing can move it) takes Δλ = 0.
     */
    @Override void project(int t, Particles p, SolverContext ctx) {
        final double[] x = p.x, w = p.w;
        final int i = 3 * t;
        final int i0 = particles[3 * i], i1 = particles[3 * i + 1], i2 = particles[3 * i + 2];
        final int a = 3 * i0, b = 3 * i1, c = 3 * i2;
        final double P = restInverse[4 * i], Q = restInverse[4 * i + 1], R = restInverse[4 * i + 2], S = restInverse[4 * i + 3];
        double e1x = x[b] - x[a], e1y = x[b + 1] - x[a + 1], e1z = x[b + 2] - x[a + 2];
        double e2x = x[c] - x[a], e2y = x[c + 1] - x[a + 1], e2z = x[c + 2] - x[a + 2];
        double fux = e1x * P + e2x * R, fuy = e1y * P + e2y * R, fuz = e1z * P + e2z * R;
        double fvx = e1x * Q + e2x * S, fvy = e1y * Q + e2y * S, fvz = e1z * Q + e2z * S;
        double uu = fux * fux + fuy * fuy + fuz * fuz, vv = fvx * fvx + fvy * fvy + fvz * fvz, uv = fux * fvx + fuy * fvy + fuz * fvz;
        double euu = 0.5 * (uu - 1), evv = 0.5 * (vv - 1);
        final double w0 = w[i0], w1 = w[i1], w2 = w[i2];
        final double a0 = -P - R, b0 = -Q - S;
        final double waa = w0 * a0 * a0 + w1 * P * P + w2 * R * R;
        final double wab = w0 * a0 * b0 + w1 * P * Q + w2 * R * S;
        final double wbb = w0 * b0 * b0 + w1 * Q * Q + w2 * S * S;
        // The rows are Lᵀ's (setMaterial writes no other): r₀ = (l₀₀, l₁₀, 0), r₁ = (0, l₁₁, 0), r₂ = (0, 0, l₂₂).
        // Row r's gradient at vertex v is a_v gu_r + b_v gv_r with gu_r = r₀ f_u + r₂ f_v and gv_r = r₂ f_u + r₁ f_v,
        // so every A_rs is a combination of the Gram entries uu, uv, vv.
        final double l00 = row[3 * i], l10 = row[3 * i + 1], l11 = row[3 * i + 4], l22 = row[3 * i + 8];
        double C0 = l00 * euu + l10 * evv, C1 = l11 * evv, C2 = l22 * uv;
        double A00 = waa * l00 * l00 * uu + 2 * wab * l00 * l10 * uv + wbb * l10 * l10 * vv;
        double A01 = l11 * (wab * l00 * uv + wbb * l10 * vv);
        double A02 = l22 * (waa * l00 * uv + wab * (l00 * uu + l10 * vv) + wbb * l10 * uv);
        double A11 = wbb * l11 * l11 * vv;
        double A12 = l11 * l22 * (wab * vv + wbb * uv);
        double A22 = l22 * l22 * (waa * vv + 2 * wab * uv + wbb * uu);
        final double t0 = compliance(i) * ctx.inverseH2, t1 = compliance(i + 1) * ctx.inverseH2, t2 = compliance(i + 2) * ctx.inverseH2;
        A00 += t0; A11 += t1; A22 += t2;
        final double r0 = -C0 - t0 * lambda[i], r1 = -C1 - t1 * lambda[i + 1], r2 = -C2 - t2 * lambda[i + 2];
        // LDLᵀ of the 3×3 symmetric A; a pivot at or below round-off of the diagonal drops its row.
        double tiny = 1e-14 * (A00 + A11 + A22);
        if (!(tiny > 0)) return;
        double d0 = A00, m10 = 0, m20 = 0;
        if (d0 > tiny) { m10 = A01 / d0; m20 = A02 / d0; } else d0 = 0;
        double d1 = A11 - m10 * m10 * d0, m21 = 0;
        if (d1 > tiny) m21 = (A12 - m20 * m10 * d0) / d1; else d1 = 0;
        double d2 = A22 - m20 * m20 * d0 - m21 * m21 * d1;
        if (!(d2 > tiny)) d2 = 0;
        double y0 = r0, y1 = r1 - m10 * y0, y2 = r2 - m20 * y0 - m21 * y1;
        double dl2 = d2 > 0 ? y2 / d2 : 0, dl1 = d1 > 0 ? y1 / d1 - m21 * dl2 : 0, dl0 = d0 > 0 ? y0 / d0 - m10 * dl1 - m20 * dl2 : 0;
        lambda[i] += dl0; lambda[i + 1] += dl1; lambda[i + 2] += dl2;
        // Σ_r Δλ_r gu_r and Σ_r Δλ_r gv_r, in the basis (f_u, f_v).
        double uCoefU = dl0 * l00, uCoefV = dl2 * l22, vCoefU = dl2 * l22, vCoefV = dl0 * l10 + dl1 * l11;
        double gux = uCoefU * fux + uCoefV * fvx, guy = uCoefU * fuy + uCoefV * fvy, guz = uCoefU * fuz + uCoefV * fvz;
        double gvx = vCoefU * fux + vCoefV * fvx, gvy = vCoefU * fuy + vCoefV * fvy, gvz = vCoefU * fuz + vCoefV * fvz;
        double s0a = w0 * a0, s0b = w0 * b0, s1a = w1 * P, s1b = w1 * Q, s2a = w2 * R, s2b = w2 * S;
        x[a] += s0a * gux + s0b * gvx; x[a + 1] += s0a * guy + s0b * gvy; x[a + 2] += s0a * guz + s0b * gvz;
        x[b] += s1a * gux + s1b * gvx; x[b + 1] += s1a * guy + s1b * gvy; x[b + 2] += s1a * guz + s1b * gvz;
        x[c] += s2a * gux + s2b * gvx; x[c + 1] += s2a * guy + s2b * gvy; x[c + 2] += s2a * guz + s2b * gvz;
    }

    @Override void projectRange(int from, int to, Particles p, SolverContext ctx) {
        for (int t = from; t < to; t++) project(t, p, ctx);
    }

    @Override void projectListed(int[] order, int from, int to, Particles p, SolverContext ctx) {
        for (int k = from; k < to; k++) project(order[k], p, ctx);
    }

    @Override Constraint view(int i) { return new BlockConstraint(this, i); }

    @Override MembraneBlock emptyLike(int capacity) { return new MembraneBlock(family(), (capacity + 2) / 3); }

    @Override void copyRest(int i, ConstraintBlock from, int j) {
        MembraneBlock m = (MembraneBlock) from;
        System.arraycopy(m.restInverse, 4 * j, restInverse, 4 * i, 4);
        System.arraycopy(m.row, 3 * j, row, 3 * i, 3);
        area[i] = m.area[j];
    }

    @Override void grow(int capacity) {
        super.grow(capacity);
        restInverse = Arrays.copyOf(restInverse, 4 * capacity);
        row = Arrays.copyOf(row, 3 * capacity);
        area = Arrays.copyOf(area, capacity);
    }
}
