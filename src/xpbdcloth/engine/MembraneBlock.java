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
 * Why three scalar rows and not one constraint with a 3×3 compliance block: the Cholesky factor turns
 * the coupled block into rows with the same scalar compliance, so each row is an ordinary XPBD
 * constraint (one λ, the shared Δλ of {@link Constraint#deltaLambda}, every solver including the global
 * one), and the energy, hence XPBD's equilibrium, is exactly the block's. Gauss–Seidel over the rows
 * converges to it a little more slowly than a 3×3 solve per triangle would.
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
        super(family, 3, 3 * Math.max(triangleCapacity, 1));
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
        double scale = Math.max(q[0], q[4]);
        // Q/scale = L Lᵀ with L lower triangular (Q has no normal–shear coupling in the material frame).
        double l00 = Math.sqrt(q[0] / scale), l10 = q[1] / scale / l00, l11 = Math.sqrt(q[4] / scale - l10 * l10), l22 = Math.sqrt(q[8] / scale);
        // Row r of Lᵀ: (Lᵀε)_0 = l00 ε₀ + l10 ε₁, (Lᵀε)_1 = l11 ε₁, (Lᵀε)_2 = l22 ε₂.
        double[][] rows = {{l00, l10, 0}, {0, l11, 0}, {0, 0, l22}};
        for (int r = 0; r < 3; r++) {
            int i = 3 * t + r;
            System.arraycopy(rows[r], 0, row, 3 * i, 3);
            setCompliance(i, 1 / (scale * area[i]));
        }
    }

    /** The triangle's Green strain (E_uu, E_vv, γ) in the material frame. */
    public double[] strain(int t, Particles p) {
        double[] f = new double[6], eps = new double[3];
        deformation(3 * t, p.x, f);
        strain(f, eps);
        return eps;
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

    @Override void project(int i, Particles p, SolverContext ctx) {
        final double[] x = p.x;
        final int i0 = particles[3 * i], i1 = particles[3 * i + 1], i2 = particles[3 * i + 2];
        final int a = 3 * i0, b = 3 * i1, c = 3 * i2;
        final double P = restInverse[4 * i], Q = restInverse[4 * i + 1], R = restInverse[4 * i + 2], S = restInverse[4 * i + 3];
        final double r0 = row[3 * i], r1 = row[3 * i + 1], r2 = row[3 * i + 2];
        double e1x = x[b] - x[a], e1y = x[b + 1] - x[a + 1], e1z = x[b + 2] - x[a + 2];
        double e2x = x[c] - x[a], e2y = x[c + 1] - x[a + 1], e2z = x[c + 2] - x[a + 2];
        double fux = e1x * P + e2x * R, fuy = e1y * P + e2y * R, fuz = e1z * P + e2z * R;
        double fvx = e1x * Q + e2x * S, fvy = e1y * Q + e2y * S, fvz = e1z * Q + e2z * S;
        double euu = 0.5 * (fux * fux + fuy * fuy + fuz * fuz - 1), evv = 0.5 * (fvx * fvx + fvy * fvy + fvz * fvz - 1);
        double gamma = fux * fvx + fuy * fvy + fuz * fvz;
        double C = r0 * euu + r1 * evv + r2 * gamma;
        double gux = r0 * fux + r2 * fvx, guy = r0 * fuy + r2 * fvy, guz = r0 * fuz + r2 * fvz;
        double gvx = r1 * fvx + r2 * fux, gvy = r1 * fvy + r2 * fuy, gvz = r1 * fvz + r2 * fuz;
        double g1x = P * gux + Q * gvx, g1y = P * guy + Q * gvy, g1z = P * guz + Q * gvz;
        double g2x = R * gux + S * gvx, g2y = R * guy + S * gvy, g2z = R * guz + S * gvz;
        double g0x = -g1x - g2x, g0y = -g1y - g2y, g0z = -g1z - g2z;
        double w0 = p.w[i0], w1 = p.w[i1], w2 = p.w[i2];
        double wGradSq = w0 * (g0x * g0x + g0y * g0y + g0z * g0z) + w1 * (g1x * g1x + g1y * g1y + g1z * g1z) + w2 * (g2x * g2x + g2y * g2y + g2z * g2z);
        double dLambda = deltaLambda(i, C, wGradSq, ctx);
        double s0 = w0 * dLambda, s1 = w1 * dLambda, s2 = w2 * dLambda;
        x[a] += s0 * g0x; x[a + 1] += s0 * g0y; x[a + 2] += s0 * g0z;
        x[b] += s1 * g1x; x[b + 1] += s1 * g1y; x[b + 2] += s1 * g1z;
        x[c] += s2 * g2x; x[c + 1] += s2 * g2y; x[c + 2] += s2 * g2z;
    }

    @Override void projectRange(int from, int to, Particles p, SolverContext ctx) {
        for (int i = from; i < to; i++) project(i, p, ctx);
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
