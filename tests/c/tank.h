/* A draining tank, level' = -rate, defined only for level >= 0 (hand-written test model:
 * the rhs reports states outside the domain). */
#ifndef TANK_H
#define TANK_H
#define tank_NY 2
#define tank_NP 1
extern const char *const tank_state_names[tank_NY];
extern const char *const tank_param_names[tank_NP];
int tank_rhs(double t, const double *y, const double *p, double *dydt);
int tank_jac(double t, const double *y, const double *p, double *J);
#endif
