/* y = body angular velocity (w1, w2, w3), p = principal moments (I1, I2, I3):
 *   I1 w1' = (I2 - I3) w2 w3 and cyclic. Invariants: |I w|^2 and w . I w. */
#include "free3.h"

const char *const free3_state_names[free3_NY] = {"w1", "w2", "w3"};
const char *const free3_param_names[free3_NP] = {"I1", "I2", "I3"};

int free3_rhs(double t, const double *y, const double *p, double *dydt)
{
    (void)t;
    dydt[0] = (p[1] - p[2]) / p[0] * y[1] * y[2];
    dydt[1] = (p[2] - p[0]) / p[1] * y[2] * y[0];
    dydt[2] = (p[0] - p[1]) / p[2] * y[0] * y[1];
    return 0;
}

int free3_jac(double t, const double *y, const double *p, double *J)
{
    double a = (p[1] - p[2]) / p[0], b = (p[2] - p[0]) / p[1], c = (p[0] - p[1]) / p[2];
    (void)t;
    J[0] = 0.0;      J[1] = a * y[2]; J[2] = a * y[1];
    J[3] = b * y[2]; J[4] = 0.0;      J[5] = b * y[0];
    J[6] = c * y[1]; J[7] = c * y[0]; J[8] = 0.0;
    return 0;
}
