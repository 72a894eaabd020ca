/* y' = k y^2: blows up at t = 1/(k y0) (hand-written test model, model ABI of derive). */
#ifndef BLOWUP_H
#define BLOWUP_H
#define blowup_NY 1
#define blowup_NP 1
extern const char *const blowup_state_names[blowup_NY];
extern const char *const blowup_param_names[blowup_NP];
int blowup_rhs(double t, const double *y, const double *p, double *dydt);
int blowup_jac(double t, const double *y, const double *p, double *J);
#endif
