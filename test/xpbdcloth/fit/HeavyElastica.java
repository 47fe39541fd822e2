package xpbdcloth.fit;

/**
 * A strip clamped horizontal at one end and bent by its own weight (the cantilever of ASTM D1388), solved
 * exactly: with s the arc length from the clamp, θ(s) the angle below horizontal, w the weight per length
 * and B the bending stiffness, the moment of the weight beyond s is B θ'(s), so
 * <pre>
 *   B θ'' = −w (l − s) cos θ,   θ(0) = 0 (clamped),   θ'(l) = 0 (no moment at the free tip)
 * </pre>
 * In units of the bending length c = (B/w)^⅓ it depends on λ = l/c alone: θ'' = −(λ − σ) cos θ. Solved by
 * shooting on θ'(0) (bisection; θ'(λ) grows with it) with fourth-order Runge–Kutta at 2000 steps.
 */
final class HeavyElastica {
    /** The tip angle θ(l), and the tip's position (x, −y) from the clamp edge in units of c. */
    final double tipAngle, tipX, tipDrop;
    private final double overhang, slope;

    private HeavyElastica(double overhang, double slope, double tipAngle, double tipX, double tipDrop) {
        this.overhang = overhang;
        this.slope = slope;
        this.tipAngle = tipAngle;
        this.tipX = tipX;
        this.tipDrop = tipDrop;
    }

    /** The angle below horizontal of the chord from the clamp edge to the tip (ASTM D1388's line), rad. */
    double chordAngle() { return Math.atan2(tipDrop, tipX); }

    /** The strip of overhang λ = l/c. */
    static HeavyElastica of(double lambda) {
        double lo = 0, hi = lambda * lambda; // θ'(0) ≤ ∫ (λ − σ) dσ = λ²/2 < λ²
        for (int k = 0; k < 64; k++) {
            double mid = 0.5 * (lo + hi);
            if (integrate(lambda, mid, lambda)[1] > 0) hi = mid; else lo = mid;
        }
        double slope = 0.5 * (lo + hi);
        double[] end = integrate(lambda, slope, lambda);
        return new HeavyElastica(lambda, slope, end[0], end[2], end[3]);
    }

    /** The overhang λ whose chord angle is {@code chord} (rad), by bisection (the angle grows with λ). */
    static double overhangForChordAngle(double chord) {
        double lo = 1e-3, hi = 5;
        for (int k = 0; k < 48; k++) {
            double mid = 0.5 * (lo + hi);
            if (of(mid).chordAngle() > chord) hi = mid; else lo = mid;
        }
        return 0.5 * (lo + hi);
    }

    /** The point at arc length σ from the clamp (units of c): (x, drop below the clamp). */
    double[] at(double sigma) {
        double[] y = integrate(overhang, slope, Math.min(sigma, overhang));
        return new double[] {y[2], y[3]};
    }

    /** (θ, θ', x, y) at σ = until from θ(0) = 0, θ'(0) = slope, for the overhang λ. */
    private static double[] integrate(double lambda, double slope, double until) {
        int steps = Math.max(1, (int) Math.ceil(2000 * until / lambda));
        double h = until / steps;
        double theta = 0, bend = slope, x = 0, y = 0;
        for (int k = 0; k < steps; k++) {
            double s = k * h;
            // θ' = bend, bend' = −(λ − s) cos θ, x' = cos θ, y' = sin θ
            double t1 = bend, b1 = -(lambda - s) * Math.cos(theta);
            double th2 = theta + h / 2 * t1, t2 = bend + h / 2 * b1, b2 = -(lambda - s - h / 2) * Math.cos(th2);
            double th3 = theta + h / 2 * t2, t3 = bend + h / 2 * b2, b3 = -(lambda - s - h / 2) * Math.cos(th3);
            double th4 = theta + h * t3, t4 = bend + h * b3, b4 = -(lambda - s - h) * Math.cos(th4);
            x += h / 6 * (Math.cos(theta) + 2 * Math.cos(th2) + 2 * Math.cos(th3) + Math.cos(th4));
            y += h / 6 * (Math.sin(theta) + 2 * Math.sin(th2) + 2 * Math.sin(th3) + Math.sin(th4));
            theta += h / 6 * (t1 + 2 * t2 + 2 * t3 + t4);
            bend += h / 6 * (b1 + 2 * b2 + 2 * b3 + b4);
        }
        return new double[] {theta, bend, x, y};
    }
}
