/* The heavy symmetric top, typed by hand from the textbook: the reference that the generated
 * heavy_top_rhs (generated/c/heavy_top.c) is timed against by `derive bench`.
 *
 * Lagrangian L = 1/2 I1 (alpha_dot^2 sin^2 beta + beta_dot^2) + 1/2 I3 w3^2 - M g l cos beta,
 * z-y-z Euler angles, w3 = alpha_dot cos beta + gamma_dot (body spin). Its Euler-Lagrange
 * equations, solved for the accelerations:
 *
 *   alpha_ddot = beta_dot (I3 w3 - 2 I1 alpha_dot cos beta) / (I1 sin beta)
 *   beta_ddot  = (I1 alpha_dot^2 sin beta cos beta - I3 w3 alpha_dot sin beta + M g l sin beta) / I1
 *   gamma_ddot = -alpha_ddot cos beta + alpha_dot beta_dot sin beta
 *
 * Same state and parameter layout as heavy_top_rhs: y = (alpha, beta, gamma, alpha_dot,
 * beta_dot, gamma_dot), p = (I1, I3, M, g, l). Like a textbook transcription it has no domain
 * check: at sin beta = 0 it returns inf/nan rather than an error code.
 */
#include <math.h>

int handwritten_heavy_top_rhs(double t, const double *y, const double *p, double *dydt)
{
    const double beta = y[1], alpha_d = y[3], beta_d = y[4], gamma_d = y[5];
    const double I1 = p[0], I3 = p[1], mgl = p[2] * p[3] * p[4];
    const double sb = sin(beta), cb = cos(beta);
    const double w3 = alpha_d * cb + gamma_d;
    const double alpha_dd = beta_d * (I3 * w3 - 2.0 * I1 * alpha_d * cb) / (I1 * sb);
    const double beta_dd = (I1 * alpha_d * alpha_d * sb * cb - I3 * w3 * alpha_d * sb + mgl * sb) / I1;
    (void)t;
    dydt[0] = alpha_d;
    dydt[1] = beta_d;
    dydt[2] = gamma_d;
    dydt[3] = alpha_dd;
    dydt[4] = beta_dd;
    dydt[5] = -alpha_dd * cb + alpha_d * beta_d * sb;
    return 0;
}
