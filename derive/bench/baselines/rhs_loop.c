/* Time right-hand sides of the heavy top in a C loop: generated vs hand-written (vs no-op).
 *
 *   rhs_loop N REPEATS
 *
 * Each function lives in its own translation unit and is called through a pointer, so the
 * compiler can neither inline it nor hoist it out of the loop. The loop walks through K
 * different states (beta across (0.1, pi - 0.1), rates of both signs) and adds every output
 * into an accumulator that ends in a volatile sink, so no call is dead code. Each repeat times
 * all functions back to back, in an order that rotates from repeat to repeat, so slow drifts of
 * the machine (frequency, other load) hit them alike; `derive bench` takes medians.
 *
 * Output, one line each:
 *   check <max relative difference generated vs hand-written over the K states>
 *   rep <r> <name> <ns per call>      (for every repeat and function)
 */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "heavy_top.h"

int handwritten_heavy_top_rhs(double t, const double *y, const double *p, double *dydt);
int noop_rhs(double t, const double *y, const double *p, double *dydt);

typedef int (*rhs_fn)(double, const double *, const double *, double *);

#define K 4096 /* states in the rotation (a power of two), 6 doubles each: 192 kB, in L2 */

static double states[K * 6];
volatile double sink;

static double uniform(unsigned long long *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) / 9007199254740992.0; /* [0, 1) */
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static double time_loop(rhs_fn f, long n, const double *p)
{
    double d[6], acc = 0.0, t = 0.0;
    double t0 = now();
    for (long i = 0; i < n; ++i) {
        f(t, states + 6 * (i & (K - 1)), p, d);
        acc += d[3] + d[4] + d[5];
        t += 1e-6;
    }
    double t1 = now();
    sink = acc;
    return (t1 - t0) / (double)n * 1e9;
}

int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : 2000000;
    int repeats = argc > 2 ? atoi(argv[2]) : 11;
    /* The toy top of the heavy-top scenes (scenes/looping_top.toml). */
    const double p[5] = {1.8e-4, 4.0e-5, 0.1, 9.81, 0.04};
    unsigned long long seed = 12345;
    for (int k = 0; k < K; ++k) {
        double *y = states + 6 * k;
        y[0] = 6.283185307179586 * uniform(&seed);
        y[1] = 0.1 + (3.141592653589793 - 0.2) * uniform(&seed);
        y[2] = 6.283185307179586 * uniform(&seed);
        y[3] = 20.0 * (uniform(&seed) - 0.5);
        y[4] = 20.0 * (uniform(&seed) - 0.5);
        y[5] = 150.0 + 100.0 * (uniform(&seed) - 0.5);
    }

    double worst = 0.0;
    for (int k = 0; k < K; ++k) {
        double a[6], b[6];
        heavy_top_rhs(0.0, states + 6 * k, p, a);
        handwritten_heavy_top_rhs(0.0, states + 6 * k, p, b);
        for (int i = 0; i < 6; ++i) {
            double scale = fabs(b[i]) > 1.0 ? fabs(b[i]) : 1.0;
            double e = fabs(a[i] - b[i]) / scale;
            if (!(e <= worst)) worst = e; /* also catches NaN */
        }
    }
    printf("check %.3e\n", worst);

    static const char *names[3] = {"generated", "handwritten", "noop"};
    rhs_fn fns[3] = {heavy_top_rhs, handwritten_heavy_top_rhs, noop_rhs};
    time_loop(fns[0], n / 10 + 1, p); /* warm up: caches, clock frequency */
    for (int r = 0; r < repeats; ++r) {
        for (int j = 0; j < 3; ++j) {
            int i = (r + j) % 3;
            printf("rep %d %s %.4f\n", r, names[i], time_loop(fns[i], n, p));
        }
    }
    return 0;
}
