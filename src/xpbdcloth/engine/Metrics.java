package xpbdcloth.engine;

/** Measurements over a simulation's state, allocation-free: energies, momentum, strain. */
public final class Metrics {
    private Metrics() {}

    /** Σ ½ m |v|² over free particles (J). Pinned particles have no finite mass to count. */
    public static double kineticEnergy(Particles p) {
        double e = 0;
        for (int i = 0; i < p.count(); i++) {
            if (p.w[i] == 0) continue;
            int k = 3 * i;
            e += 0.5 * p.mass[i] * (p.v[k] * p.v[k] + p.v[k + 1] * p.v[k + 1] + p.v[k + 2] * p.v[k + 2]);
        }
        return e;
    }

    /** −Σ m g·x over free particles (J), zero at the origin. */
    public static double gravitationalEnergy(Particles p, SolverSettings s) {
        double e = 0;
        for (int i = 0; i < p.count(); i++) {
            if (p.w[i] == 0) continue;
            int k = 3 * i;
            e -= p.mass[i] * (s.gravityX() * p.x[k] + s.gravityY() * p.x[k + 1] + s.gravityZ() * p.x[k + 2]);
        }
        return e;
    }

    /** Σ C²/(2α) over equality constraints with α &gt; 0 (J): XPBD's elastic potential. */
    public static double elasticEnergy(Simulation sim) {
        double e = 0;
        Particles p = sim.particles();
        for (Constraint c : sim.constraints()) {
            ConstraintFamily f = c.family();
            if (f == ConstraintFamily.COLLISION || f == ConstraintFamily.ATTACHMENT || c.compliance() == 0) continue;
            double C = c.evaluate(p);
            e += C * C / (2 * c.compliance());
        }
        return e;
    }

    /** Σ m v along one axis (0 = x, 1 = y, 2 = z) over free particles (kg·m/s). */
    public static double momentum(Particles p, int axis) {
        double m = 0;
        for (int i = 0; i < p.count(); i++) if (p.w[i] != 0) m += p.mass[i] * p.v[3 * i + axis];
        return m;
    }

    /** The largest |strain| over distance constraints of a family (0 if none). */
    public static double maxStrain(Simulation sim, ConstraintFamily family) {
        double max = 0;
        for (Constraint c : sim.constraints())
            if (c instanceof DistanceConstraint && c.family() == family)
                max = Math.max(max, Math.abs(((DistanceConstraint) c).strain(sim.particles())));
        return max;
    }

    /** The mean strain (signed) over distance constraints of a family (0 if none). */
    public static double meanStrain(Simulation sim, ConstraintFamily family) {
        double sum = 0;
        int n = 0;
        for (Constraint c : sim.constraints())
            if (c instanceof DistanceConstraint && c.family() == family) {
                sum += ((DistanceConstraint) c).strain(sim.particles());
                n++;
            }
        return n == 0 ? 0 : sum / n;
    }

    /** True when every position and velocity is finite. */
    public static boolean allFinite(Particles p) {
        for (int k = 0; k < 3 * p.count(); k++)
            if (!Double.isFinite(p.x[k]) || !Double.isFinite(p.v[k])) return false;
        return true;
    }
}
