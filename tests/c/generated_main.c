/* Runs the generated heavy-top kernels under the sanitizers: rhs, Jacobian, observables and
 * every solver, including states at the poles (the Euler-angle kernel must refuse beta = 0;
 * the reduced kernel must stay finite there with p_alpha = p_gamma). Exit 0 when all behave. */
#include <math.h>
#include <stdio.h>
#include "heavy_top_solvers.h"
#include "heavy_top_reduced_solvers.h"

#define CHECK(cond) do { if (!(cond)) { fprintf(stderr, "failed: %s (line %d)\n", #cond, __LINE__); return 1; } } while (0)

/* The save of a run from given starts: the states at every t[k]. */
static const derive_saveat *grid(const double *t, long n)
{
    static derive_saveat save;
    save.t_out = t;
    save.n_out = n;
    save.final = save.outputs = save.pole_check = save.lanes = 0;
    return &save;
}

int main(void)
{
    double p[5] = {1.0, 0.4, 1.0, 9.81, 0.1};
    const double y[6] = {0.1, 0.7, 0.2, 1.5, 0.3, 25.0};
    const double pole[6] = {0.1, 0.0, 0.2, 1.5, 0.3, 25.0};
    const double t0 = 0.0;
    double f[6], J[36], obs[heavy_top_NOBS], t_out[11], y_out[11 * 6];
    derive_stats st;
    int k;

    CHECK(heavy_top_rhs(0.0, y, p, f) == 0);
    CHECK(heavy_top_jac(0.0, y, p, J) == 0);
    CHECK(heavy_top_observables_at(1, &t0, y, p, obs) == 0);
    CHECK(heavy_top_rhs(0.0, pole, p, f) != 0);  /* the singular set is refused */
    for (k = 0; k < 11; ++k)
        t_out[k] = 0.1 * k;
    CHECK(heavy_top_run_dop853(grid(t_out, 11), 1, y, p, 1e-10, 1e-12, 0.0, 100000, y_out, NULL, &st) == 0);
    CHECK(heavy_top_run_rk4(grid(t_out, 11), 1, y, p, 1e-3, y_out, NULL, &st) == 0);
    CHECK(heavy_top_run_gauss4(grid(t_out, 11), 1, y, p, 1e-3, 1e-15, 20, y_out, NULL, &st) == 0);
    CHECK(heavy_top_run_gauss6(grid(t_out, 11), 1, y, p, 1e-3, 1e-15, 20, y_out, NULL, &st) == 0);
    for (k = 0; k < 66; ++k)
        CHECK(isfinite(y_out[k]));

    {
        /* Reduced top exactly at the pole, p_alpha = p_gamma: regular (no 0/0 evaluated). */
        double pr[7] = {1.0, 0.4, 1.0, 9.81, 0.1, 3.0, 3.0};
        const double yr[4] = {0.0, 0.0, 0.0, 0.5};
        double fr[4], Jr[16], ys[11 * 4];
        CHECK(heavy_top_reduced_rhs(0.0, yr, pr, fr) == 0);
        CHECK(heavy_top_reduced_jac(0.0, yr, pr, Jr) == 0);
        for (k = 0; k < 4; ++k)
            CHECK(isfinite(fr[k]));
        CHECK(heavy_top_reduced_run_dop853(grid(t_out, 11), 1, yr, pr, 1e-10, 1e-12, 0.0, 100000, ys, NULL, &st) == 0);
        CHECK(heavy_top_reduced_run_gauss6(grid(t_out, 11), 1, yr, pr, 1e-3, 1e-15, 20, ys, NULL, &st) == 0);
        for (k = 0; k < 44; ++k)
            CHECK(isfinite(ys[k]));
    }
    return 0;
}
