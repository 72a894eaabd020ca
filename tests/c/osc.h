/* Harmonic oscillator x'' = -w^2 x (hand-written test model, model ABI of derive). */
#ifndef OSC_H
#define OSC_H
#define osc_NY 2
#define osc_NP 1
extern const char *const osc_state_names[osc_NY];
extern const char *const osc_param_names[osc_NP];
int osc_rhs(double t, const double *y, const double *p, double *dydt);
int osc_jac(double t, const double *y, const double *p, double *J);
#endif
