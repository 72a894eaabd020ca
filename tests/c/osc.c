/* y = (x, v), p = (w): x' = v, v' = -w^2 x. Exact: x = x0 cos wt + v0/w sin wt. */
#include "osc.h"

const char *const osc_state_names[osc_NY] = {"x", "v"};
const char *const osc_param_names[osc_NP] = {"w"};

int osc_rhs(double t, const double *y, const double *p, double *dydt)
{
    (void)t;
    dydt[0] = y[1];
    dydt[1] = -p[0] * p[0] * y[0];
    return 0;
}

int osc_jac(double t, const double *y, const double *p, double *J)
{
    (void)t;
    (void)y;
    J[0] = 0.0;
    J[1] = 1.0;
    J[2] = -p[0] * p[0];
    J[3] = 0.0;
    return 0;
}
