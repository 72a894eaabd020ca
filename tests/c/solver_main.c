/* Runs every rendered solver of the hand-written test models once, including the batch entry
 * points and each failure path, so that a sanitizer build (-fsanitize=address,undefined)
 * exercises all of the generated C. Four models share this one translation unit, which also
 * checks that the common block of <prefix>_solvers.h is guarded. Exit status 0 = all checks
 * passed. Built and run by tests/test_solvers.py with the rendered <prefix>_solvers.[ch]. */
#include <math.h>
#include <stdio.h>

#include "osc.c"
#include "osc_solvers.c"
#include "free3.c"
#include "free3_solvers.c"
#include "blowup.c"
#include "blowup_solvers.c"
#include "tank.c"
#include "tank_solvers.c"

static int failures = 0;

#define CHECK(cond)                                                                  \
    do {                                                                             \
        if (!(cond)) {                                                               \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
            ++failures;                                                              \
        }                                                                            \
    } while (0)

#define NT 11

/* The save of a run from given starts: the states at every t[k]. */
static const derive_saveat *grid(const double *t, long n)
{
    static derive_saveat save;
    save.t_out = t;
    save.n_out = n;
    save.final = save.outputs = save.pole_check = save.lanes = 0;
    return &save;
}

static void check_osc(const double *y, double tol)
{
    int k;
    for (k = 0; k < NT; ++k) {
        double t = 0.5 * k;
        CHECK(fabs(y[2 * k] - cos(2.0 * t)) < tol);
        CHECK(fabs(y[2 * k + 1] + 2.0 * sin(2.0 * t)) < tol);
    }
}

int main(void)
{
    double t[NT], y[3 * NT * 3], y0s[3 * 3], ps[3 * 3], tt[2] = {0.0, 2.0}, yb[2];
    double y0[2] = {1.0, 0.0}, p[1] = {2.0}, w0[3] = {1.0, 0.5, -0.3}, I[3] = {1.0, 2.0, 3.5};
    double u0[1] = {1.0}, k1[1] = {1.0}, lvl[2] = {1.0, 0.0}, rate[1] = {1.0};
    derive_stats st, sts[3];
    int i, rc;

    for (i = 0; i < NT; ++i)
        t[i] = 0.5 * i;

    /* Oscillator: every method, against the exact solution. */
    CHECK(osc_run_dop853(grid(t, NT), 1, y0, p, 1e-10, 1e-12, 0.0, 100000, y, NULL, &st) == DERIVE_OK);
    check_osc(y, 1e-8);
    CHECK(st.naccept > 0 && st.nfev > 0 && st.status == 0);
    CHECK(osc_run_rk4(grid(t, NT), 1, y0, p, 1e-3, y, NULL, &st) == DERIVE_OK);
    check_osc(y, 1e-9);
    CHECK(osc_run_gauss4(grid(t, NT), 1, y0, p, 1e-2, 1e-15, 20, y, NULL, &st) == DERIVE_OK);
    check_osc(y, 1e-6);
    CHECK(st.njev > 0 && st.nlu > 0);
    CHECK(osc_run_gauss6(grid(t, NT), 1, y0, p, 1e-2, 1e-15, 20, y, NULL, &st) == DERIVE_OK);
    check_osc(y, 1e-10);
    CHECK(osc_run_dop853_fixed(grid(t, NT), 1, y0, p, 0.05, y, NULL, &st) == DERIVE_OK);
    check_osc(y, 1e-10);
    CHECK(osc_run_dop853(grid(t, 1), 1, y0, p, 1e-10, 1e-12, 0.0, 10, y, NULL, NULL) == DERIVE_OK);

    /* Batches. */
    for (i = 0; i < 3; ++i) {
        y0s[3 * i] = 1.0 + i;
        y0s[3 * i + 1] = 0.5;
        y0s[3 * i + 2] = -0.3 * i;
        ps[3 * i] = 1.0;
        ps[3 * i + 1] = 2.0 + 0.1 * i;
        ps[3 * i + 2] = 3.5;
    }
    CHECK(free3_run_dop853(grid(t, NT), 3, y0s, ps, 1e-9, 1e-12, 0.0, 100000, y, NULL, sts) == 0);
    CHECK(free3_run_rk4(grid(t, NT), 3, y0s, ps, 0.01, y, NULL, sts) == 0);
    CHECK(free3_run_gauss4(grid(t, NT), 3, y0s, ps, 0.05, 1e-15, 20, y, NULL, sts) == 0);
    CHECK(free3_run_gauss6(grid(t, NT), 3, y0s, ps, 0.05, 1e-15, 20, y, NULL, sts) == 0);
    CHECK(free3_run_dop853_fixed(grid(t, NT), 3, y0s, ps, 0.1, y, NULL, sts) == 0);
    CHECK(free3_run_rk4(grid(t, NT), 0, y0s, ps, 0.01, y, NULL, sts) == 0);
    CHECK(osc_run_dop853(grid(t, NT), 1, y0, p, 1e-9, 1e-12, 0.0, 100000, y, NULL, sts) == 0);
    CHECK(osc_run_rk4(grid(t, NT), 1, y0, p, 1e-2, y, NULL, sts) == 0);
    CHECK(osc_run_gauss4(grid(t, NT), 1, y0, p, 1e-1, 1e-15, 20, y, NULL, sts) == 0);
    CHECK(osc_run_gauss6(grid(t, NT), 1, y0, p, 1e-1, 1e-15, 20, y, NULL, sts) == 0);
    CHECK(osc_run_dop853_fixed(grid(t, NT), 1, y0, p, 1e-1, y, NULL, sts) == 0);
    CHECK(free3_run_dop853(grid(t, NT), 1, w0, I, 1e-9, 1e-12, 1e-3, 100000, y, NULL, &st) == 0);
    CHECK(free3_run_gauss6(grid(t, NT), 1, w0, I, 0.1, 1e-15, 20, y, NULL, &st) == 0);

    /* Blow-up of u' = u^2 at t = 1. */
    rc = blowup_run_dop853(grid(tt, 2), 1, u0, k1, 1e-10, 1e-12, 0.0, 100000, yb, NULL, &st);
    CHECK((rc == DERIVE_STEP_UNDERFLOW || rc == DERIVE_NONFINITE) && fabs(st.t_fail - 1.0) < 1e-3);
    rc = blowup_run_rk4(grid(tt, 2), 1, u0, k1, 0.01, yb, NULL, &st);
    CHECK(rc == DERIVE_NONFINITE && st.fail_index == 0 && fabs(st.t_fail - 1.0) < 0.1);
    rc = blowup_run_dop853_fixed(grid(tt, 2), 1, u0, k1, 0.01, yb, NULL, &st);
    CHECK(rc == DERIVE_NONFINITE && st.fail_index == 0);
    rc = blowup_run_gauss4(grid(tt, 2), 1, u0, k1, 0.01, 1e-15, 20, yb, NULL, &st);
    CHECK((rc == DERIVE_NEWTON || rc == DERIVE_NONFINITE) && fabs(st.t_fail - 1.0) < 0.1);
    rc = blowup_run_gauss6(grid(tt, 2), 1, u0, k1, 0.01, 1e-15, 20, yb, NULL, &st);
    CHECK((rc == DERIVE_NEWTON || rc == DERIVE_NONFINITE) && fabs(st.t_fail - 1.0) < 0.1);
    CHECK(blowup_run_rk4(grid(tt, 2), 1, u0, k1, 0.01, yb, NULL, sts) == DERIVE_NONFINITE);
    CHECK(blowup_run_dop853(grid(tt, 2), 1, u0, k1, 1e-10, 1e-12, 0.0, 5, yb, NULL, &st) == DERIVE_MAX_STEPS);

    /* The tank leaves its domain (level < 0) at t = 1. */
    CHECK(tank_run_dop853(grid(tt, 2), 1, lvl, rate, 1e-8, 1e-10, 0.0, 1000, y, NULL, &st) == DERIVE_DOMAIN);
    CHECK(st.rhs_code == 1);
    CHECK(tank_run_rk4(grid(tt, 2), 1, lvl, rate, 0.1, y, NULL, &st) == DERIVE_DOMAIN);
    CHECK(tank_run_dop853_fixed(grid(tt, 2), 1, lvl, rate, 0.1, y, NULL, &st) == DERIVE_DOMAIN);
    CHECK(tank_run_gauss4(grid(tt, 2), 1, lvl, rate, 0.1, 1e-15, 20, y, NULL, &st) == DERIVE_DOMAIN);
    CHECK(tank_run_gauss6(grid(tt, 2), 1, lvl, rate, 0.1, 1e-15, 20, y, NULL, &st) == DERIVE_DOMAIN);

    /* Bad arguments. */
    t[3] = t[2];
    CHECK(osc_run_dop853(grid(t, NT), 1, y0, p, 1e-10, 1e-12, 0.0, 100, y, NULL, &st) == DERIVE_BAD_ARGS);
    CHECK(osc_run_rk4(grid(t, NT), 1, y0, p, 0.1, y, NULL, &st) == DERIVE_BAD_ARGS);
    t[3] = 1.5;
    CHECK(osc_run_dop853(grid(t, NT), 1, y0, p, -1.0, 1e-12, 0.0, 100, y, NULL, &st) == DERIVE_BAD_ARGS);
    CHECK(osc_run_dop853(grid(t, NT), 1, y0, p, 0.0, 0.0, 0.0, 100, y, NULL, &st) == DERIVE_BAD_ARGS);
    CHECK(osc_run_dop853(grid(t, 0), 1, y0, p, 1e-6, 1e-6, 0.0, 100, y, NULL, &st) == DERIVE_BAD_ARGS);
    CHECK(osc_run_rk4(grid(t, NT), 1, y0, p, 0.0, y, NULL, &st) == DERIVE_BAD_ARGS);
    CHECK(osc_run_gauss4(grid(t, NT), 1, y0, p, 0.1, 0.0, 20, y, NULL, &st) == DERIVE_BAD_ARGS);
    CHECK(osc_run_gauss6(grid(t, NT), 1, y0, p, 0.1, 1e-15, 0, y, NULL, &st) == DERIVE_BAD_ARGS);
    CHECK(osc_run_rk4(grid(t, NT), -1, y0, p, 0.1, y, NULL, sts) == DERIVE_BAD_ARGS);

    if (failures)
        fprintf(stderr, "%d check(s) failed\n", failures);
    else
        printf("all solver checks passed\n");
    return failures != 0;
}
