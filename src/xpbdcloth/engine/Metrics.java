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
        for (int k = 0; k < sim.blocks().size(); k++) {
            ConstraintBlock b = sim.blocks().get(k);
            ConstraintFamily f = b.family();
            if (f == ConstraintFamily.COLLISION || f == ConstraintFamily.ATTACHMENT) continue;
            for (int i = 0; i < b.count(); i++) {
                if (b.compliance(i) == 0) continue;
                double C = b.evaluate(i, p);
                e += C * C / (2 * b.compliance(i));
            }
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
        for (int k = 0; k < sim.blocks().size(); k++) {
            ConstraintBlock b = sim.blocks().get(k);
            if (b instanceof DistanceBlock && b.family() == family)
                for (int i = 0; i < b.count(); i++) max = Math.max(max, Math.abs(((DistanceBlock) b).strain(i, sim.particles())));
        }
        return max;
    }

    /** The mean strain (signed) over distance constraints of a family (0 if none). */
    public static double meanStrain(Simulation sim, ConstraintFamily family) {
        double sum = 0;
        int n = 0;
        for (int k = 0; k < sim.blocks().size(); k++) {
            ConstraintBlock b = sim.blocks().get(k);
            if (b instanceof DistanceBlock && b.family() == family)
                for (int i = 0; i < b.count(); i++) {
                    sum += ((DistanceBlock) b).strain(i, sim.particles());
                    n++;
                }
        }
        return n == 0 ? 0 : sum / n;
    }

    /**
     * The cloth's largest strain, whatever it is made of: the structural springs' |x|/L − 1 where it has
     * them, else its membrane triangles' largest principal stretch less one ({@link MembraneBlock#principalStrain}).
     */
    public static double maxClothStrain(Simulation sim) {
        if (has(sim, ConstraintFamily.STRUCTURAL)) return maxStrain(sim, ConstraintFamily.STRUCTURAL);
        double max = 0;
        for (int k = 0; k < sim.blocks().size(); k++)
            if (sim.blocks().get(k) instanceof MembraneBlock) {
                MembraneBlock m = (MembraneBlock) sim.blocks().get(k);
                for (int t = 0; t < m.triangleCount(); t++) max = Math.max(max, Math.abs(m.principalStrain(t, sim.particles())));
            }
        return max;
    }

    /** The mean of the same strain over the cloth's springs or membrane triangles (signed; 0 if it has neither). */
    public static double meanClothStrain(Simulation sim) {
        if (has(sim, ConstraintFamily.STRUCTURAL)) return meanStrain(sim, ConstraintFamily.STRUCTURAL);
        double sum = 0;
        int n = 0;
        for (int k = 0; k < sim.blocks().size(); k++)
            if (sim.blocks().get(k) instanceof MembraneBlock) {
                MembraneBlock m = (MembraneBlock) sim.blocks().get(k);
                for (int t = 0; t < m.triangleCount(); t++, n++) sum += m.principalStrain(t, sim.particles());
            }
        return n == 0 ? 0 : sum / n;
    }

    /** The largest normal Green strain (E_uu or E_vv, along warp or weft) over the membrane's triangles (0 if none). */
    public static double largestGreenStrain(Simulation sim) {
        double max = 0;
        for (int k = 0; k < sim.blocks().size(); k++)
            if (sim.blocks().get(k) instanceof MembraneBlock) {
                MembraneBlock m = (MembraneBlock) sim.blocks().get(k);
                for (int t = 0; t < m.triangleCount(); t++) max = Math.max(max, m.largestNormalStrain(t, sim.particles()));
            }
        return max;
    }

    /** Whether the simulation has distance constraints of this family. */
    static boolean has(Simulation sim, ConstraintFamily family) {
        for (int k = 0; k < sim.blocks().size(); k++) {
            ConstraintBlock b = sim.blocks().get(k);
            if (b instanceof DistanceBlock && b.family() == family && b.count() > 0) return true;
        }
        return false;
    }

    /** The largest |λ|/h² over a family's constraints in the last substep: the force its most loaded one carries (N). */
    public static double maxForce(Simulation sim, ConstraintFamily family) {
        double h = sim.settings().timestep() / sim.settings().substeps(), max = 0;
        for (int k = 0; k < sim.blocks().size(); k++) {
            ConstraintBlock b = sim.blocks().get(k);
            if (b.family() == family)
                for (int i = 0; i < b.count(); i++) max = Math.max(max, Math.abs(b.lambda[i]) / (h * h));
        }
        return max;
    }

    /** True when every position and velocity is finite. */
    public static boolean allFinite(Particles p) {
        for (int k = 0; k < 3 * p.count(); k++)
            if (!Double.isFinite(p.x[k]) || !Double.isFinite(p.v[k])) return false;
        return true;
    }

    /**
     * ‖C + α̃λ‖₂ over the equality constraints (contacts and attachments left out): the residual of
     * XPBD's constraint equation, zero when every constraint holds at its compliant equilibrium. In PBD
     * mode α̃ is taken as 0, so it is ‖C‖₂.
     */
    public static double residual(Simulation sim) {
        double sum = 0, h = sim.substep(), inverseH2 = 1.0 / (h * h);
        Particles particles = sim.particles();
        boolean xpbd = sim.settings().mode() == ConstraintMode.XPBD;
        for (ConstraintBlock b : sim.blocks()) {
            ConstraintFamily f = b.family();
            if (f == ConstraintFamily.COLLISION || f == ConstraintFamily.ATTACHMENT) continue;
            for (int i = 0; i < b.count(); i++) {
                double r = b.evaluate(i, particles) + (xpbd ? b.compliance(i) * inverseH2 * b.lambda[i] : 0);
                sum += r * r;
            }
        }
        return Math.sqrt(sum);
    }
}
