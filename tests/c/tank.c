/* y = (level, outflow): level' = -rate, outflow' = rate. Returns 1 when level < 0, which
 * happens after t = level0 / rate. */
#include "tank.h"

const char *const tank_state_names[tank_NY] = {"level", "outflow"};
const char *const tank_param_names[tank_NP] = {"rate"};

int tank_rhs(double t, const double *y, const double *p, double *dydt)
{
    (void)t;
    if (y[0] < 0.0)
        return 1;
    dydt[0] = -p[0];
    dydt[1] = p[0];
    return 0;
}

int tank_jac(double t, const double *y, const double *p, double *J)
{
    (void)t;
    (void)p;
    if (y[0] < 0.0)
        return 1;
    J[0] = J[1] = J[2] = J[3] = 0.0;
    return 0;
}
