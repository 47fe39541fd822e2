package xpbdcloth.engine;

/**
 * Wind on a triangle mesh: each triangle of area A and unit normal n̂ feels a linear drag
 * F = c·A·((u − v̄)·n̂) n̂ along its normal, where u is the wind velocity, v̄ the triangle's mean velocity and
 * c the drag coefficient (kg/(m²·s)); a third of F goes to each corner. Only the normal part pushes, so
 * cloth edge-on to the wind feels nothing. A slow gust modulates |u| by 1 + gust·sin(0.7t)·sin(1.9t),
 * two incommensurate frequencies so the motion does not look periodic.
 */
public final class Wind implements ExternalForce {
    private final int[] triangles;
    private double ux, uy, uz;
    private final double drag, gust;

    public Wind(int[] triangles, double ux, double uy, double uz, double drag, double gust) {
        if (triangles == null || triangles.length % 3 != 0)
            throw new IllegalArgumentException("triangles must be a multiple of 3 indices, was " + (triangles == null ? "null" : triangles.length));
        Check.finite3("wind", ux, uy, uz);
        this.triangles = triangles;
        this.ux = ux; this.uy = uy; this.uz = uz;
        this.drag = Check.nonNegative("drag", drag);
        this.gust = Check.inRange("gust", gust, 0, 1);
    }

    public double velocityX() { return ux; }
    public double velocityY() { return uy; }
    public double velocityZ() { return uz; }
    public double drag() { return drag; }
    public double gust() { return gust; }

    public void setVelocity(double x, double y, double z) {
        Check.finite3("wind", x, y, z);
        ux = x; uy = y; uz = z;
    }

    @Override public void apply(Particles p, double t) {
        final double[] x = p.x, v = p.v;
        final double g = 1 + gust * Math.sin(0.7 * t) * Math.sin(1.9 * t);
        final double wx = ux * g, wy = uy * g, wz = uz * g;
        for (int k = 0; k < triangles.length; k += 3) {
            int a = 3 * triangles[k], b = 3 * triangles[k + 1], c = 3 * triangles[k + 2];
            double e1x = x[b] - x[a], e1y = x[b + 1] - x[a + 1], e1z = x[b + 2] - x[a + 2];
            double e2x = x[c] - x[a], e2y = x[c + 1] - x[a + 1], e2z = x[c + 2] - x[a + 2];
            double nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
            double twiceArea = Math.sqrt(nx * nx + ny * ny + nz * nz);
            if (twiceArea < 1e-18) continue;
            nx /= twiceArea; ny /= twiceArea; nz /= twiceArea;
            double rx = wx - (v[a] + v[b] + v[c]) / 3, ry = wy - (v[a + 1] + v[b + 1] + v[c + 1]) / 3, rz = wz - (v[a + 2] + v[b + 2] + v[c + 2]) / 3;
            double f = drag * 0.5 * twiceArea * (rx * nx + ry * ny + rz * nz) / 3;
            double fx = f * nx, fy = f * ny, fz = f * nz;
            p.addForce(triangles[k], fx, fy, fz);
            p.addForce(triangles[k + 1], fx, fy, fz);
            p.addForce(triangles[k + 2], fx, fy, fz);
        }
    }
}
