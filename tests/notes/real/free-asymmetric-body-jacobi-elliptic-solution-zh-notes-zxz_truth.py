"""Independent SymPy truth table for free-asymmetric-body-jacobi-elliptic-solution-zh-notes-zxz.md.

The text's own setting: a free rigid body about its fixed centre of mass, principal moments
I_1 < I_2 < I_3, body components omega_i, L_i = I_i omega_i, constants L (magnitude of the angular
momentum) and T (kinetic energy). Euler's equations are derived here from I omega' + omega x I omega = 0.
Jacobi's functions are handled by their defining properties (sn' = cn dn, cn' = -sn dn, dn' = -k^2 sn cn,
cn^2 = 1 - sn^2, dn^2 = 1 - k^2 sn^2, sn(0) = 0, period 4K) and spot-checked against mpmath's
ellipfun; identities with square roots are checked at random admissible values (I_1 < I_2 < I_3 and
L^2 in the case's range). Nothing here reads the reader.
"""
import random
import sys

import mpmath
import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = CHECKS.get(key, True) and bool(ok)


zero = truth_table.zero
I1, I2, I3, T, L, k, tau = sp.symbols('I_1 I_2 I_3 T L k tau', positive=True)
t = sp.Symbol('t', real=True)
w1, w2, w3 = sp.symbols('omega_1 omega_2 omega_3', real=True)
Sn, Cn, Dn = sp.symbols('sn cn dn', real=True)
Iv = sp.Matrix([I1, I2, I3])
w = sp.Matrix([w1, w2, w3])
euler_rhs = -sp.diag(1 / I1, 1 / I2, 1 / I3) * w.cross(sp.diag(I1, I2, I3) * w)   # omega' from Euler's equations


def samples(case, n=6, seed=3):
    """Random admissible values: I_1 < I_2 < I_3 and L^2 inside the case's range."""
    rnd = random.Random(seed)
    out = []
    while len(out) < n:
        a, b, c = sorted(rnd.uniform(0.5, 3.0) for _ in range(3))
        TT = rnd.uniform(0.5, 2.0)
        lo, mid, hi = 2 * a * TT, 2 * b * TT, 2 * c * TT
        L2 = {1: rnd.uniform(mid, hi), 2: rnd.uniform(lo, mid), 3: mid}[case]
        out.append({I1: a, I2: b, I3: c, T: TT, L: sp.sqrt(L2)})
    return out


def num_zero(expr, case, extra=None):
    for sub in samples(case):
        sub = {**sub, **(extra or {})}
        if abs(complex(sp.N(expr.subs(sub), 20))) > 1e-10:
            return False
    return True


def d_tau(expr):
    """d/dtau of an expression in sn, cn, dn (of tau)."""
    return sp.diff(expr, Sn) * Cn * Dn - sp.diff(expr, Cn) * Sn * Dn - sp.diff(expr, Dn) * k**2 * Sn * Cn


jac = {Cn: sp.sqrt(1 - Sn**2), Dn: sp.sqrt(1 - k**2 * Sn**2)}

# line 24 is the labelling assumption; line 30: |L|^2 and 2T are constant on Euler's equations
Lsq = sum(I**2 * x**2 for I, x in zip(Iv, w))
Tw = sum(I * x**2 for I, x in zip(Iv, w))
grad = lambda f: sp.Matrix([sp.diff(f, x) for x in w])   # noqa: E731
check(30, zero(grad(Lsq).dot(euler_rhs)) and zero(grad(Tw).dot(euler_rhs)))
Lc = sp.symbols('L_1 L_2 L_3', real=True)
in_L = {w1: Lc[0] / I1, w2: Lc[1] / I2, w3: Lc[2] / I3}
check(37, zero(Lsq.subs(in_L) - sum(x**2 for x in Lc))
      and zero(Tw.subs(in_L) - sum(x**2 / I for x, I in zip(Lc, Iv))))
# line 44 lists semi-axes (no relation); line 50: the sphere meets the ellipsoid iff 2 I_1 T <= L^2 <= 2 I_3 T:
# on the ellipsoid L^2 = sum L_i^2 ranges between 2 I_1 T (all on axis 1) and 2 I_3 T (all on axis 3)
x1, x2, x3 = sp.symbols('x_1 x_2 x_3', nonnegative=True)        # x_i = L_i^2 / (2 I_i T), summing to 1
Lsq_x = 2 * T * (I1 * x1 + I2 * x2 + I3 * x3)
check(50, zero(Lsq_x.subs({x1: 1, x2: 0, x3: 0}) - 2 * I1 * T) and zero(Lsq_x.subs({x1: 0, x2: 0, x3: 1}) - 2 * I3 * T)
      and zero(sp.expand(Lsq_x.subs(x2, 1 - x1 - x3) - 2 * I2 * T - 2 * T * ((I1 - I2) * x1 + (I3 - I2) * x3))))
# line 60: omega_1^2 and omega_3^2 from the two conservation laws
W1sq, W3sq = sp.symbols('W1sq W3sq')
s60 = sp.solve([Lsq.subs({w1**2: W1sq, w3**2: W3sq}) - L**2, Tw.subs({w1**2: W1sq, w3**2: W3sq}) - 2 * T], [W1sq, W3sq])
A = (2 * I3 * T - L**2) - I2 * (I3 - I2) * w2**2
B = (L**2 - 2 * I1 * T) - I2 * (I2 - I1) * w2**2
check(60, zero(s60[W1sq] - A / (I1 * (I3 - I1))) and zero(s60[W3sq] - B / (I3 * (I3 - I1))))
# line 67: omega_2' = (I_3 - I_1)/I_2 omega_3 omega_1, with the positive roots of line 60
w2dot = euler_rhs[1]
claim67 = sp.sqrt(A * B) / (I2 * sp.sqrt(I1 * I3))
check(67, zero(w2dot - (I3 - I1) / I2 * w1 * w3)
      and num_zero((I3 - I1) / I2 * sp.sqrt(A / (I1 * (I3 - I1))) * sp.sqrt(B / (I3 * (I3 - I1))) - claim67, 1, {w2: 0.05}))


def reduced(case):
    """(tau rate, s scale, k^2) as the text defines them for case 1 or 2, and the claim ds/dtau."""
    if case == 1:
        p = sp.sqrt((I3 - I2) * (L**2 - 2 * I1 * T) / (I1 * I2 * I3))
        a = sp.sqrt(I2 * (I3 - I2) / (2 * I3 * T - L**2))
        k2 = (I2 - I1) * (2 * I3 * T - L**2) / ((I3 - I2) * (L**2 - 2 * I1 * T))
    else:
        p = sp.sqrt((I2 - I1) * (2 * I3 * T - L**2) / (I1 * I2 * I3))
        a = sp.sqrt(I2 * (I2 - I1) / (L**2 - 2 * I1 * T))
        k2 = (I3 - I2) * (L**2 - 2 * I1 * T) / ((I2 - I1) * (2 * I3 * T - L**2))
    return p, a, k2


for case, (kline, dsline) in {1: (82, 88), 2: (151, 157)}.items():
    p, a, k2 = reduced(case)
    check(kline, all(float(k2.subs(sub)) < 1 for sub in samples(case)))
    sv = sp.Symbol('s')
    # ds/dtau = a omega_2' / p with omega_2 = s / a, against sqrt((1 - s^2)(1 - k^2 s^2))
    lhs = a * claim67.subs(w2, sv / a) / p
    rhs = sp.sqrt((1 - sv**2) * (1 - k2 * sv**2))
    check(dsline, num_zero(lhs - rhs, case, {sv: 0.37}) and num_zero(lhs - rhs, case, {sv: 0.81}))

# line 94: tau = F(s): its s-derivative is the reciprocal of ds/dtau, and F(0) = 0 (the time origin)
xi, sv = sp.symbols('xi s', positive=True)
F = sp.Integral(1 / sp.sqrt((1 - xi**2) * (1 - k**2 * xi**2)), (xi, 0, sv))
check(94, zero(sp.diff(F, sv).doit() - 1 / sp.sqrt((1 - sv**2) * (1 - k**2 * sv**2))) and F.subs(sv, 0).doit() == 0)
# lines 101 and 163: s = sn(tau) solves ds/dtau = cn dn = sqrt((1 - sn^2)(1 - k^2 sn^2)) with sn(0) = 0
sn_ode = all(abs(float((d_tau(Sn).subs(jac) - sp.sqrt((1 - Sn**2) * (1 - k**2 * Sn**2))).subs({Sn: a, k: b}))) < 1e-14
             for a, b in ((0.4, 0.6), (0.9, 0.3), (0.1, 0.95)))
check(101, sn_ode)
check(163, sn_ode)
# spot check of the defining properties against mpmath's Jacobi functions
u0, m0 = mpmath.mpf('0.7'), mpmath.mpf('0.3')
sn0, cn0, dn0 = (mpmath.ellipfun(f, u0, m=m0) for f in ('sn', 'cn', 'dn'))
assert abs(mpmath.diff(lambda u: mpmath.ellipfun('sn', u, m=m0), u0) - cn0 * dn0) < 1e-12
assert abs(mpmath.diff(lambda u: mpmath.ellipfun('dn', u, m=m0), u0) + m0 * sn0 * cn0) < 1e-12


def solution_holds(case, amps, funcs):
    """omega_i = amp_i * f_i(tau), tau = p t, k^2 the case's: Euler's equations and the constants L, T."""
    p, a, k2 = reduced(case)
    om = [A_ * f_ for A_, f_ in zip(amps, funcs)]
    ok = True
    for i in range(3):
        lhs = p * d_tau(om[i])
        rhs = euler_rhs[i].subs({w1: om[0], w2: om[1], w3: om[2]})
        ok &= num_zero((lhs - rhs).subs(jac).subs(k, sp.sqrt(k2)), case, {Sn: 0.41})
    ok &= num_zero((Lsq.subs({w1: om[0], w2: om[1], w3: om[2]}) - L**2).subs(jac).subs(k, sp.sqrt(k2)), case, {Sn: 0.63})
    ok &= num_zero((Tw.subs({w1: om[0], w2: om[1], w3: om[2]}) - 2 * T).subs(jac).subs(k, sp.sqrt(k2)), case, {Sn: 0.63})
    ok &= num_zero(amps[1] - 1 / a, case)          # omega_2 = s / a
    return ok


amp1 = sp.sqrt((2 * I3 * T - L**2) / (I1 * (I3 - I1)))
amp3 = sp.sqrt((L**2 - 2 * I1 * T) / (I3 * (I3 - I1)))
ok1 = solution_holds(1, [amp1, sp.sqrt((2 * I3 * T - L**2) / (I2 * (I3 - I2))), amp3], [Cn, Sn, Dn])
check(107, ok1)
check(113, ok1)
ok2 = solution_holds(2, [amp1, sp.sqrt((L**2 - 2 * I1 * T) / (I2 * (I2 - I1))), amp3], [Dn, Sn, Cn])
check(169, ok2)
# negative control: case 1's functions with case 2's scales fail
assert not solution_holds(2, [amp1, sp.sqrt((L**2 - 2 * I1 * T) / (I2 * (I2 - I1))), amp3], [Cn, Sn, Dn])
# line 124: K(k) as the two integrals (s = sin(phi)), numerically
kk = mpmath.mpf('0.6')
K1 = mpmath.quad(lambda x: 1 / mpmath.sqrt((1 - x**2) * (1 - kk**2 * x**2)), [0, 1])
K2 = mpmath.quad(lambda f: 1 / mpmath.sqrt(1 - kk**2 * mpmath.sin(f)**2), [0, mpmath.pi / 2])
check(124, abs(K1 - K2) < 1e-8 and abs(K2 - mpmath.ellipk(kk**2)) < 1e-10)
# line 130: sn, cn have period 4K in tau, dn 2K, so the period in t is 4K / p
check(130, abs(mpmath.ellipfun('cn', u0 + 4 * mpmath.ellipk(m0), m=m0) - cn0) < 1e-10
      and abs(mpmath.ellipfun('sn', u0 + 4 * mpmath.ellipk(m0), m=m0) - sn0) < 1e-10
      and abs(mpmath.ellipfun('sn', u0 + 2 * mpmath.ellipk(m0), m=m0) - sn0) > 1e-3
      and num_zero(1 / reduced(1)[0] - sp.sqrt(I1 * I2 * I3 / ((I3 - I2) * (L**2 - 2 * I1 * T))), 1))
# line 137: L^2 = 2 I_3 T: amp1 = 0, omega_2 amplitude 0, omega_3 = sqrt(2T/I_3) (dn = 1 when k^2 = 0)
at3 = {L: sp.sqrt(2 * I3 * T)}
check(137, zero(amp1.subs(at3)) and zero(reduced(1)[2].subs(at3)) and zero(amp3.subs(at3) - sp.sqrt(2 * T / I3)))
# line 180: k -> 0 limits of sn, cn, dn
check(180, abs(mpmath.ellipfun('sn', u0, m=0) - mpmath.sin(u0)) < 1e-12
      and abs(mpmath.ellipfun('cn', u0, m=0) - mpmath.cos(u0)) < 1e-12 and abs(mpmath.ellipfun('dn', u0, m=0) - 1) < 1e-12)
# line 186: L^2 = 2 I_1 T
at1 = {L: sp.sqrt(2 * I1 * T)}
check(186, zero(amp3.subs(at1)) and zero(sp.sqrt((L**2 - 2 * I1 * T) / (I2 * (I2 - I1))).subs(at1))
      and zero(amp1.subs(at1) - sp.sqrt(2 * T / I1)))
# line 194: L^2 = 2 I_2 T in omega_2'
at2 = {L: sp.sqrt(2 * I2 * T)}
Om = sp.sqrt(2 * T / I2)
claim194 = sp.sqrt((I2 / I1 - 1) * (1 - I2 / I3)) * (2 * T / I2 - w2**2)
check(194, num_zero(claim67.subs(at2) - claim194, 3, {w2: 0.3}))
# line 208: with s = omega_2/Omega and tau = Omega c t, ds/dtau = 1 - s^2
cst = sp.sqrt((I2 / I1 - 1) * (1 - I2 / I3))
check(208, zero(sp.expand(claim194.subs(w2, sv * Om) / Om / (Om * cst) - (1 - sv**2))))
check(214, zero(sp.diff(sp.tanh(tau), tau) - (1 - sp.tanh(tau)**2)) and sp.tanh(0) == 0)
# line 220: the separatrix solution, against Euler's equations with L^2 = 2 I_2 T
sech = 1 / sp.cosh(tau)
om3 = [sp.sqrt(I2 * (I3 - I2) / (I1 * (I3 - I1))) * Om * sech, Om * sp.tanh(tau),
       sp.sqrt(I2 * (I2 - I1) / (I3 * (I3 - I1))) * Om * sech]
rate = Om * cst
ok220 = all(num_zero(rate * sp.diff(om3[i], tau) - euler_rhs[i].subs({w1: om3[0], w2: om3[1], w3: om3[2]}), 3, {tau: 0.7})
            for i in range(3))
ok220 &= num_zero((Lsq.subs({w1: om3[0], w2: om3[1], w3: om3[2]}) - L**2).subs(at2), 3, {tau: 0.4})
check(220, ok220)
# line 231: Euler angles with Z along L and the body's x_2 in the role of the z-x-z third axis:
# the body components of Z are L_i/L; a cyclic relabelling of (sin th sin ps, sin th cos ps, cos th)
# and phidot from omega = phidot Z + thetadot N + psidot e_2, dotted with Z's component across
th, ps = sp.symbols('theta psi', real=True)
Zb = {3: sp.sin(th) * sp.sin(ps), 1: sp.sin(th) * sp.cos(ps), 2: sp.cos(th)}   # relabel 1->3, 2->1, 3->2
Lb = {1: I1 * w1, 2: I2 * w2, 3: I3 * w3}
Lm = sp.sqrt(Lsq)
# the body components of the space Z axis in z-x-z angles, derived from the rotation matrix
Rzx = lambda a: sp.Matrix([[sp.cos(a), -sp.sin(a), 0], [sp.sin(a), sp.cos(a), 0], [0, 0, 1]])  # noqa: E731
Rxx = lambda a: sp.Matrix([[1, 0, 0], [0, sp.cos(a), -sp.sin(a)], [0, sp.sin(a), sp.cos(a)]])  # noqa: E731
ph0 = sp.Symbol('phi', real=True)
Zstd = (Rzx(ph0) * Rxx(th) * Rzx(ps)).T * sp.Matrix([0, 0, 1])
cos_ok = zero(sp.Matrix([Zb[3], Zb[1], Zb[2]]) - Zstd)        # the standard triple, relabelled cyclically
cos_ok &= zero(Zb[2] - sp.cos(th)) and zero(Zb[3] / Zb[1] - sp.tan(ps))   # cos = L_2/L, tan = L_3/L_1
# phidot sin^2(theta) = omega . (Z - cos(theta) e_2) (the component of omega along Z's projection off e_2)
ph_claim = Lm * (I1 * w1**2 + I3 * w3**2) / (I1**2 * w1**2 + I3**2 * w3**2)
Zvec = sp.Matrix([Lb[1], Lb[2], Lb[3]]) / Lm
e2 = sp.Matrix([0, 1, 0])
phidot = w.dot(Zvec - Zvec[1] * e2) / (1 - Zvec[1]**2)
check(231, cos_ok and num_zero(phidot - ph_claim, 3, {w1: 0.3, w2: 0.5, w3: -0.2}))
# line 242: the same with the separatrix solution
Lval = sp.sqrt(2 * I2 * T)
check(242, num_zero(I2 * om3[1] / Lval - sp.tanh(tau), 3, {tau: 0.9})
      and num_zero(I3 * om3[2] / (I1 * om3[0]) - sp.sqrt(I3 * (I2 - I1) / (I1 * (I3 - I2))), 3, {tau: 0.9})
      and num_zero((L * (I1 * w1**2 + I3 * w3**2) / (I1**2 * w1**2 + I3**2 * w3**2)).subs({w1: om3[0], w3: om3[2]}).subs(at2)
                   - Om, 3, {tau: 0.9}))

LINES = [11, 24, 30, 37, 44, 50, 60, 67, 76, 82, 88, 94, 101, 107, 113, 124, 130, 137, 145, 151, 157, 163,
         169, 180, 186, 194, 201, 208, 214, 220, 231, 242]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
