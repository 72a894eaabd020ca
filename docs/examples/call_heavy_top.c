/* Evaluate the generated heavy-top right-hand side from plain C (docs/c-abi.md).
 * Build:  cc -std=c99 -I generated/c docs/examples/call_heavy_top.c generated/c/heavy_top.c -lm */
#include <stdio.h>
#include "heavy_top.h"

int main(void)
{
    /* y = (alpha, beta, gamma, alpha_dot, beta_dot, gamma_dot), p = (I1, I3, M, g, l) */
    const double y[heavy_top_NY] = {0.0, 0.8, 0.0, -0.4, 0.3, 6.0};
    const double p[heavy_top_NP] = {1.0, 0.5, 1.0, 1.0, 1.0};
    double dydt[heavy_top_NY];
    int i;

    if (heavy_top_rhs(0.0, y, p, dydt) != 0) {
        fprintf(stderr, "state outside the model's domain (sin(beta) = 0)\n");
        return 1;
    }
    for (i = 0; i < heavy_top_NY; ++i)
        printf("d%s/dt = %.17g\n", heavy_top_state_names[i], dydt[i]);
    return 0;
}
