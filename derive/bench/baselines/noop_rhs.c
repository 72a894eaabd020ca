/* A right-hand side that does nothing but copy the rates: the cost of the timing loop itself
 * (call through a pointer, state rotation, accumulation), subtracted by nobody, shown by
 * `derive bench` so that the kernels' ns/call can be read against it. */
int noop_rhs(double t, const double *y, const double *p, double *dydt)
{
    (void)t;
    (void)p;
    dydt[0] = y[3];
    dydt[1] = y[4];
    dydt[2] = y[5];
    dydt[3] = y[3];
    dydt[4] = y[4];
    dydt[5] = y[5];
    return 0;
}
