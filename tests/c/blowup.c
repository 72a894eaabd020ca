#include "blowup.h"

const char *const blowup_state_names[blowup_NY] = {"u"};
const char *const blowup_param_names[blowup_NP] = {"k"};

int blowup_rhs(double t, const double *y, const double *p, double *dydt)
{
    (void)t;
    dydt[0] = p[0] * y[0] * y[0];
    return 0;
}

int blowup_jac(double t, const double *y, const double *p, double *J)
{
    (void)t;
    J[0] = 2.0 * p[0] * y[0];
    return 0;
}
