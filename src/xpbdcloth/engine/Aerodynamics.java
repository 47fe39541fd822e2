package xpbdcloth.engine;

/**
 * Quadratic aerodynamic drag and lift on every triangle of a cloth moving through air (or air moving
 * past it), as a thin flat plate: for a triangle of area A and unit normal n̂, with the air's velocity
 * relative to a corner r = u − vᵢ and cos θ = r̂·n̂ (θ the angle between the flow and the normal),
 *
 * <pre>
 *   drag  F_D = ½ ρ A C_D |r| (r·n̂) n̂                    (pressure on the face: |r|² cos θ along n̂)
 *   lift  F_L = ½ ρ A C_L |r|² cos θ sin θ  l̂,   l̂ = the unit part of n̂ perpendicular to r, signed so
 *         that F_L·n̂ has the sign of r·n̂                   (zero edge-on and face-on, largest at 45°)
 * </pre>
 * each corner taking a third, from its own relative velocity. ρ is the air's density (1.2 kg/m³), C_D
 * about 1.2 for a flat plate face-on; C_L about 1 gives the lift of a flat plate at small angles of
 * attack. Sources: the flat-plate model of cloth aerodynamics in Keckeisen, Kimmerle, Thomaszewski,
 * Wacker 2004, "Modelling Effects of Wind Fields in Cloth Animations" (drag along the normal, lift in
 * the plane of flow and normal); the coefficients are textbook flat-plate values (Hoerner, "Fluid-Dynamic
 * Drag", 1965).
 *
 * <p>Like {@link Wind}, the force acts over a whole step and is integrated with the exact decay of a
 * linear drag ({@link ExactDecay}): the drag is linear in r with the rate k = ½ ρ A C_D |r| /3 per corner (kg/s), and the
 * step's force is scaled by (1 − e^(−x))/x, x = w·Σk·dt, so the air can slow a particle to the air's
 * speed but never past it (an explicit quadratic drag overshoots once x &gt; 2, and then grows). The
 * price: where something else holds the velocity steady (gravity in a steady fall), the scale still
 * takes the fraction ≈ x/2 off the drag: a 0.1 kg/m² sheet falls 2.4 % faster than its terminal
 * velocity at 10 ms steps, 0.6 % at 2.5 ms. Closed form, tested at 2.5 ms: a horizontal sheet falling
 * face-on reaches v = √(2 m g /(ρ C_D A)).
 */
public final class Aerodynamics implements ExternalForce {
    /** Air at sea level and 20 °C, kg/m³. */
    public static final double AIR_DENSITY = 1.2;
    private final int[] triangles;
    private final double density, dragCoefficient, liftCoefficient;
    private double ux, uy, uz;
    private final ExactDecay decay = new ExactDecay();
    private final double[] normal = new double[3];

    /**
     * @param triangles       three particle indices per triangle
     * @param density         ρ, kg/m³, &gt; 0
     * @param dragCoefficient C_D ≥ 0
     * @param liftCoefficient C_L ≥ 0
     */
    public Aerodynamics(int[] triangles, double density, double dragCoefficient, double liftCoefficient) {
        if (triangles == null || triangles.length % 3 != 0)
            throw new IllegalArgumentException("triangles must be a multiple of 3 indices, was " + (triangles == null ? "null" : triangles.length));
        this.triangles = triangles.clone();
        this.density = Check.inRange("density", density, Double.MIN_NORMAL, 1e4);
        this.dragCoefficient = Check.inRange("dragCoefficient", dragCoefficient, 0, 100);
        this.liftCoefficient = Check.inRange("liftCoefficient", liftCoefficient, 0, 100);
    }

    /** The air's velocity (still air by default), m/s. */
    public Aerodynamics air(double x, double y, double z) {
        Check.finite3("air", x, y, z);
        ux = x; uy = y; uz = z;
        return this;
    }

    @Override public void check(Particles p) {
        for (int k = 0; k < triangles.length; k++) Check.index("triangle " + k / 3 + " corner", triangles[k], p.count());
    }

    @Override public void apply(Particles p, double t, double dt) {
        decay.begin(p.count());
        final double[] x = p.x, v = p.v;
        for (int k = 0; k < triangles.length; k += 3) {
            int a = 3 * triangles[k], b = 3 * triangles[k + 1], c = 3 * triangles[k + 2];
            double twiceArea = ExactDecay.twiceAreaAndNormal(x, a, b, c, normal);
            if (twiceArea < 1e-18) continue;
            double perCorner = 0.5 * density * 0.5 * twiceArea / 3; // ½ ρ A / 3
            corner(triangles[k], a, perCorner, normal[0], normal[1], normal[2], v);
            corner(triangles[k + 1], b, perCorner, normal[0], normal[1], normal[2], v);
            corner(triangles[k + 2], c, perCorner, normal[0], normal[1], normal[2], v);
        }
        decay.apply(p, dt);
    }

    /** One triangle's drag and lift on one corner, from the corner's own velocity relative to the air. */
    private void corner(int i, int i3, double perCorner, double nx, double ny, double nz, double[] v) {
        double rx = ux - v[i3], ry = uy - v[i3 + 1], rz = uz - v[i3 + 2];
        double speed = Math.sqrt(rx * rx + ry * ry + rz * rz);
        if (speed == 0) return;
        double along = rx * nx + ry * ny + rz * nz; // |r| cos θ, signed
        double k = perCorner * dragCoefficient * speed;
        decay.addRate(i, k);
        double fx = k * along * nx, fy = k * along * ny, fz = k * along * nz;
        // Lift: along the part of n̂ perpendicular to r, |r|² cos θ sin θ = along · |n̂ − (n̂·r̂) r̂| · |r|.
        double px = nx - along / speed * rx / speed, py = ny - along / speed * ry / speed, pz = nz - along / speed * rz / speed;
        double pl = Math.sqrt(px * px + py * py + pz * pz); // sin θ
        if (pl > 1e-12 && liftCoefficient > 0) {
            double kl = perCorner * liftCoefficient * speed;
            double l = kl * along; // ½ρA/3 · C_L · |r|² cos θ, then · sin θ · p̂ = · p
            fx += l * px; fy += l * py; fz += l * pz;
            // Lift is bounded as drag is: its rate joins the decay, so the velocity it adds in a step is at
            // most |along| sin θ ≤ |r|. The flow cannot push a plate faster than it moves past it; applied
            // explicitly, lift flung a stretched cloth in a strong flow ever faster.
            decay.addRate(i, kl);
        }
        decay.addForce(i3, fx, fy, fz);
    }
}
