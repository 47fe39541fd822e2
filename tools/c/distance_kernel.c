/*
 * The engine-core benchmark's work as a plain scalar C program, to measure the Java engine's distance
 * kernel against (docs/performance.md, "The distance kernel against C"): an N x N grid of structural
 * distance constraints (each particle to its right and lower neighbour), 1 cm spacing, 0.1 g particles,
 * the two top corners pinned, XPBD with alpha = 1e-7 m/N, g = 9.81 m/s^2, dt = 1/60 s, 10 iterations,
 * one substep, the constraints in their natural (as-built) order, doubles, one thread: what
 * `gradle -q bench` steps for its `n` rows. Each projection is XPBD's (Macklin et al. 2016, eq. 18):
 *   dlambda = (-C - alpha~ lambda) / (w_a + w_b + alpha~),  x_a += w_a dlambda n,  x_b -= w_b dlambda n.
 *
 *   gcc -O2 -o /tmp/distance_kernel tools/c/distance_kernel.c -lm && /tmp/distance_kernel 128
 *
 * prints "n,particles,constraints,ms_per_step,projections_per_s" after at least 2 s of warm-up and 3 s measured.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

int main(int argc, char **argv) {
    int n = argc > 1 ? atoi(argv[1]) : 128;
    if (n < 2 || n > 4096) { fprintf(stderr, "n must be in [2, 4096], was %d\n", n); return 2; }
    int count = n * n, edges = 2 * n * (n - 1);
    double *x = malloc(3 * sizeof(double) * count), *prev = malloc(3 * sizeof(double) * count);
    double *v = calloc(3 * count, sizeof(double)), *w = malloc(sizeof(double) * count);
    int *ends = malloc(2 * sizeof(int) * edges);
    double *rest = malloc(sizeof(double) * edges), *lambda = malloc(sizeof(double) * edges);
    for (int r = 0; r < n; r++)
        for (int c = 0; c < n; c++) {
            int i = r * n + c;
            x[3 * i] = 0.01 * c; x[3 * i + 1] = -0.01 * r; x[3 * i + 2] = 0;
            w[i] = (r == 0 && (c == 0 || c == n - 1)) ? 0 : 1e4;
        }
    int e = 0;
    for (int r = 0; r < n; r++)
        for (int c = 0; c < n; c++) {
            int i = r * n + c;
            if (c + 1 < n) { ends[2 * e] = i; ends[2 * e + 1] = i + 1; rest[e++] = 0.01; }
            if (r + 1 < n) { ends[2 * e] = i; ends[2 * e + 1] = i + n; rest[e++] = 0.01; }
        }
    const double h = 1.0 / 60, g = -9.81, alphaTilde = 1e-7 / (h * h);
    long steps = 0, measured = 0;
    double start = now(), t0 = 0;
    for (;;) {
        for (int i = 0; i < count; i++) {
            prev[3 * i] = x[3 * i]; prev[3 * i + 1] = x[3 * i + 1]; prev[3 * i + 2] = x[3 * i + 2];
            if (w[i] == 0) continue;
            v[3 * i + 1] += h * g;
            x[3 * i] += h * v[3 * i]; x[3 * i + 1] += h * v[3 * i + 1]; x[3 * i + 2] += h * v[3 * i + 2];
        }
        for (int k = 0; k < edges; k++) lambda[k] = 0;
        for (int it = 0; it < 10; it++)
            for (int k = 0; k < edges; k++) {
                int a = ends[2 * k], b = ends[2 * k + 1];
                double dx = x[3 * a] - x[3 * b], dy = x[3 * a + 1] - x[3 * b + 1], dz = x[3 * a + 2] - x[3 * b + 2];
                double len = sqrt(dx * dx + dy * dy + dz * dz);
                if (len < 1e-12) continue;
                double wa = w[a], wb = w[b], denominator = wa + wb + alphaTilde;
                double s = (-(len - rest[k]) - alphaTilde * lambda[k]) / (denominator * len);
                lambda[k] += s * len;
                x[3 * a] += wa * s * dx; x[3 * a + 1] += wa * s * dy; x[3 * a + 2] += wa * s * dz;
                x[3 * b] -= wb * s * dx; x[3 * b + 1] -= wb * s * dy; x[3 * b + 2] -= wb * s * dz;
            }
        for (int i = 0; i < 3 * count; i++) v[i] = (x[i] - prev[i]) / h;
        steps++;
        double t = now();
        if (t0 == 0 && t - start >= 2 && steps >= 500) { t0 = t; measured = steps; }
        if (t0 > 0 && t - t0 >= 3) {
            double ms = (t - t0) * 1e3 / (steps - measured);
            printf("%d,%d,%d,%.4f,%.0f\n", n, count, edges, ms, edges * 10.0 / (ms / 1e3));
            break;
        }
    }
    if (!isfinite(x[0])) return 1;
    free(x); free(prev); free(v); free(w); free(ends); free(rest); free(lambda);
    return 0;
}
