/* Torque-free Euler equations (hand-written test model, model ABI of derive). */
#ifndef FREE3_H
#define FREE3_H
#define free3_NY 3
#define free3_NP 3
extern const char *const free3_state_names[free3_NY];
extern const char *const free3_param_names[free3_NP];
int free3_rhs(double t, const double *y, const double *p, double *dydt);
int free3_jac(double t, const double *y, const double *p, double *J);
#endif
