"""Independent SymPy truth table for maithripala-rigid-body-momenta-euler-equations-spatial-body-frames.tex.

The text's own setting (matrix notation, no Euler angles): an inertial frame e, a body frame
b = e R(t) with origin O' at OO' = e o(t); particle i of mass m_i at x_i = o + R X_i, X_i its
position in b (constant for a rigid body); the hat map hat(a) b = a x b; the body angular velocity
Omega with hat(Omega) = R^T Rdot and the spatial one omega = R Omega. Total mass M = sum m_i, centre
of mass Xbar = sum m_i X_i / M in b and xbar = o + R Xbar in e, xbar' = xbar - o = R Xbar; linear
momentum p = sum m_i xdot_i, angular momentum about O' pi = sum (x_i - o) x m_i xdot_i, Pi = R^T pi;
inertia about O' in b, I = sum -m_i hat(X_i)^2; about the centre of mass, I_c = I + M hat(Xbar)^2,
I_c^R = R I_c R^T. External forces f_i^e (resultant f^e = R F^e), moment about O' tau^e = R T^e,
about the centre of mass tau_c^e = R T_c^e; internal forces central and pairwise opposite.

The checks build R(t) as a product of three turns of unknown angles (any rotation), o(t) and the
particles' X_i (constant or, where the text's particles are not rigid, functions of t) and compute
every momentum from its definition, never from the text's later displays; an identity in t is
tested by `truth_table.numeric_zero` (concrete smooth functions, rational values), an algebraic
one by simplification. A product written a x b x c is read with the grouping its own derivation
in the display needs (see rows 98, 175, 218). Run with --write to regenerate the table.
"""
import sys

import mpmath
import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


t = sp.symbols("t", real=True)
zero = truth_table.zero


def nz(expr):
    """expr (a vector or matrix in t) vanishes at three instants, to 25 digits."""
    m = expr if hasattr(expr, "shape") else sp.Matrix([expr])
    f = sp.lambdify(t, list(m), "mpmath", cse=True)
    with mpmath.workdps(40):
        return all(max(abs(x) for x in f(mpmath.mpf(t0))) < mpmath.mpf(10) ** -25 for t0 in ("0.31", "0.77", "1.4"))


def hat(v):
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def vee(W):
    return sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])


def svec(name):
    return sp.Matrix(sp.symbols(f"{name}_1:4", real=True))


# a concrete motion: any rotation (three turns of smooth angles), any origin path, rational masses and
# body positions; an identity of the text holds for every motion, so it holds for this one, and a slip shows
q1 = sp.sin(2 * t / 3) + t ** 2 / 5
q2 = sp.Rational(7, 10) + sp.sin(t) / 3
q3 = sp.cos(t / 2) + t
R = truth_table.Rz(q1) * truth_table.Rx(q2) * truth_table.Rz(q3)
Rd = R.diff(t)
Om = vee(R.T * Rd)                     # hat(Omega) = R^T Rdot
om = R * Om                            # omega = R Omega
o = sp.Matrix([sp.sin(t), t ** 2 / 3, sp.cos(3 * t / 4)])
od, odd = o.diff(t), o.diff(t, 2)
I3 = sp.eye(3)

N = 3
ms = (sp.Rational(2, 3), sp.Rational(5, 4), sp.Rational(7, 5))
M = sum(ms)
Xc = [sp.Matrix([sp.Rational(3, 7), -sp.Rational(2, 5), sp.Rational(1, 3)]),
      sp.Matrix([-sp.Rational(1, 4), sp.Rational(5, 6), sp.Rational(2, 9)]),
      sp.Matrix([sp.Rational(4, 5), sp.Rational(1, 6), -sp.Rational(3, 4)])]          # rigid: constant in b
Xf = [Xc[0] + sp.Matrix([sp.sin(t) / 4, t ** 2 / 7, 0]),
      Xc[1] + sp.Matrix([0, sp.cos(2 * t) / 5, t / 3]),
      Xc[2] + sp.Matrix([t ** 3 / 11, 0, sp.sin(t / 3)])]                            # any particles: X_i(t)


def positions(Xs):
    return [o + R * X for X in Xs]


def momenta(Xs):
    xs = positions(Xs)
    p = sum((m * x.diff(t) for m, x in zip(ms, xs)), sp.zeros(3, 1))
    pi = sum(((x - o).cross(m * x.diff(t)) for m, x in zip(ms, xs)), sp.zeros(3, 1))
    return xs, p, pi


def inertia(Xs, pts_ms=ms):
    return sum((-m * hat(X) ** 2 for m, X in zip(pts_ms, Xs)), sp.zeros(3, 3))


Xbar = sum((m * X for m, X in zip(ms, Xc)), sp.zeros(3, 1)) / M
xs, p, pi = momenta(Xc)
xbar = o + R * Xbar
xbp = R * Xbar                         # xbar' = xbar - o
Ibody = inertia(Xc)
Ic = Ibody + M * hat(Xbar) ** 2
IcR = R * Ic * R.T

# 31: E = [[R, o], [0, 1]] names the 4x4 matrix of the configuration: no claim
# 41: Rdot = R hat(Omega) with hat(Omega) = R^T Rdot (R R^T = 1)
check(41, nz(Rd - R * hat(Om)) and nz(R * R.T - I3))
# 46: Rdot = hat(omega) R with omega = R Omega
check(46, nz(Rd - hat(om) * R))
# 51: any particles: p = sum m_i (odot + R (hat(Omega) X_i + X_i dot))
_, pf, pif = momenta(Xf)
check(51, nz(pf - sum((m * (od + R * (hat(Om) * X + X.diff(t))) for m, X in zip(ms, Xf)), sp.zeros(3, 1))))
# 56: rigid: p = M (odot + R hat(Omega) Xbar) = M (odot + hat(omega) R Xbar) = M xbar dot
check(56, nz(p - M * (od + R * hat(Om) * Xbar)) and nz(p - M * (od + hat(om) * R * Xbar))
      and nz(p - M * xbar.diff(t)))
# 61: odot = p/M - omega x R Xbar
check(61, nz(od - (p / M - om.cross(R * Xbar))))
# 66, 71: one particle, X_i(t): pi_i = (x_i - o) x m_i x_i dot = R (I_i Omega + m_i X_i x (R^T odot + X_i dot)),
# Pi_i = R^T pi_i, with I_i = -m_i hat(X_i)^2
mi, Yi = ms[0], Xf[0]
xi = o + R * Yi
pi_i = (xi - o).cross(mi * xi.diff(t))
Ii = -mi * hat(Yi) ** 2
body_i = Ii * Om + mi * Yi.cross(R.T * od + Yi.diff(t))
check(66, nz(pi_i - R * body_i))
check(71, nz(R.T * pi_i - (Ii * Om + mi * Yi.cross(Yi.diff(t) + R.T * od))))
# 76: -m hat(X)^2 = m (|X|^2 1 - X X^T)
Xs_ = svec("X")
msym = sp.symbols("m", positive=True)
check(76, zero(-msym * hat(Xs_) ** 2 - msym * (Xs_.dot(Xs_) * I3 - Xs_ * Xs_.T)))
# 81: rigid particle (X_i dot = 0): pi_i = R (I_i Omega + m_i X_i x R^T odot)
xc1 = o + R * Xc[0]
check(81, nz((xc1 - o).cross(ms[0] * xc1.diff(t))
             - R * (-ms[0] * hat(Xc[0]) ** 2 * Om + ms[0] * Xc[0].cross(R.T * od))))
# 86: pi = sum pi_i = R (I Omega + M Xbar x R^T odot)
check(86, nz(pi - R * (Ibody * Om + M * Xbar.cross(R.T * od))))
# 91: I = sum -m_i hat(X_i)^2 = sum m_i (|X_i|^2 1 - X_i X_i^T)
check(91, zero(Ibody - sum((m * (X.dot(X) * I3 - X * X.T) for m, X in zip(ms, Xc)), sp.zeros(3, 3))))
# 98: pi = R(I Omega + M Xbar x R^T(p/M - R(Omega x Xbar))) = R(I Omega + Xbar x R^T p + M Xbar x (Xbar x Omega))
#       = R((I + M hat(Xbar)^2) Omega + Xbar x R^T p) = R(I_c Omega + Xbar x R^T p); the third member's
#     M Xbar x Xbar x Omega is Xbar x (Xbar x Omega), the grouping the next member needs; the fourth and fifth
#     members carry a stray ")" before \right), which changes nothing
l1 = R * (Ibody * Om + M * Xbar.cross(R.T * (p / M - R * Om.cross(Xbar))))
l2 = R * (Ibody * Om + Xbar.cross(R.T * p) + M * Xbar.cross(Xbar.cross(Om)))
l3 = R * ((Ibody + M * hat(Xbar) ** 2) * Om + Xbar.cross(R.T * p))
l4 = R * (Ic * Om + Xbar.cross(R.T * p))
check(98, all(nz(pi - e) for e in (l1, l2, l3, l4)))
# 106: I_c := I + M hat(Xbar)^2: a definition
# 113: parallel axis theorem: I = I_c - M hat(Xbar)^2 with I_c the inertia about the centre of mass
Ic_cm = inertia([X - Xbar for X in Xc])
check(113, zero(Ibody - (Ic_cm - M * hat(Xbar) ** 2)) and zero(Ic - Ic_cm))
# 120: pi = R(I_c Omega + Xbar x R^T p) = (R I_c R^T) omega + R Xbar x p = I_c^R omega + R Xbar x p (stray ")" again)
check(120, nz(pi - l4) and nz(pi - ((R * Ic * R.T) * om + (R * Xbar).cross(p)))
      and nz(pi - (IcR * om + (R * Xbar).cross(p))))
# 127: I_c^R := R I_c R^T = R (I + M hat(Xbar)^2) R^T, the inertia about the centre of mass in axes parallel to e
check(127, nz(R * Ic * R.T - R * (Ibody + M * hat(Xbar) ** 2) * R.T)
      and nz(IcR - inertia([R * (X - Xbar) for X in Xc])))
# 136, 141, 146: the three forms of pi about O'
check(136, CHECKS[86])
check(141, nz(pi - l4))
check(146, nz(pi - (IcR * om + (R * Xbar).cross(p))))
# 153: moments about the centre of mass (Xbar = 0): pi = R I_c Omega = I_c^R omega
Xcm = [Xc[0], Xc[1], -(ms[0] * Xc[0] + ms[1] * Xc[1]) / ms[2]]
_, p0, pi0 = momenta(Xcm)
Ic0 = inertia(Xcm)
check(153, zero(sum((m * X for m, X in zip(ms, Xcm)), sp.zeros(3, 1)))
      and nz(pi0 - R * Ic0 * Om) and nz(pi0 - (R * Ic0 * R.T) * om))

# 160: any particles, internal forces central and pairwise opposite: pdot = M xbar ddot = f^e and
# pidot = -M odot x xbar dot + tau_e
xsf = positions(Xf)
fe = [sp.Matrix([sp.Rational(1, 2), -sp.sin(t), sp.Rational(3, 5)]), sp.Matrix([t / 4, sp.Rational(2, 3), -1]),
      sp.Matrix([-sp.Rational(5, 7), sp.cos(t), t ** 2 / 9])]                              # external forces
lam = {(0, 1): sp.Rational(3, 11), (0, 2): -sp.Rational(5, 13), (1, 2): sp.Rational(7, 17)}   # central pair forces


def lam_of(i, j):
    return lam[(min(i, j), max(i, j))]


acc = [(fe[i] + sum((lam_of(i, j) * (xsf[i] - xsf[j]) for j in range(N) if j != i), sp.zeros(3, 1))) / ms[i]
       for i in range(N)]                       # Newton for each particle
xbarf = sum((m * x for m, x in zip(ms, xsf)), sp.zeros(3, 1)) / M
pdot_newton = sum((ms[i] * acc[i] for i in range(N)), sp.zeros(3, 1))
pidot_newton = sum(((xsf[i].diff(t) - od).cross(ms[i] * xsf[i].diff(t)) + (xsf[i] - o).cross(ms[i] * acc[i])
                    for i in range(N)), sp.zeros(3, 1))
fsum = sum(fe, sp.zeros(3, 1))
tau = sum(((xsf[i] - o).cross(fe[i]) for i in range(N)), sp.zeros(3, 1))
check(160, nz(pdot_newton - fsum) and nz(pidot_newton - (-M * od.cross(xbarf.diff(t)) + tau)))
# the same for the rigid body (used below): pidot = -M odot x xbar dot + tau
# 170: xbar' = R Xbar: its rate R (Omega x Xbar) = omega x xbar'
check(170, nz(xbp.diff(t) - R * Om.cross(Xbar)) and nz(xbp.diff(t) - om.cross(xbp)))
# 175: -M odot x xbar dot = M xbar' dot x xbar dot = (omega x xbar') x p (the grouping of M xbar' dot x xbar dot)
lhs175 = -M * od.cross(xbar.diff(t))
check(175, nz(lhs175 - M * xbp.diff(t).cross(xbar.diff(t))) and nz(lhs175 - om.cross(xbp).cross(p)))
# 181: odot = p/M - omega x xbar', Rdot = hat(omega) R, pdot = f^e, pidot = (omega x xbar') x p + tau_e
check(181, nz(od - (p / M - om.cross(xbp))) and CHECKS[46] and CHECKS[160] and CHECKS[175])
# 189: omega = (I_c^R)^{-1}(pi - xbar' x p), i.e. pi - xbar' x p = I_c^R omega
check(189, nz(pi - xbp.cross(p) - IcR * om))
# 196: about the centre of mass (xbar' = 0): odot = p/M, Rdot = hat(omega) R, pdot = f^e, pidot = tau_e
xs0 = positions(Xcm)
xbar0 = sum((m * x for m, x in zip(ms, xs0)), sp.zeros(3, 1)) / M
check(196, nz(xbar0 - o) and nz(od - p0 / M) and nz(M * od.cross(xbar0.diff(t))) and CHECKS[46])
# 204: omega = (I_c^R)^{-1} pi there
check(204, CHECKS[153])

# 213: pdot = M oddot + R (M (hat(Omega)^2 + hat(Omega) dot) Xbar) (= R F^e = f^e)
W = hat(Om)
check(213, nz(p.diff(t) - (M * odd + R * (M * (W ** 2 + W.diff(t)) * Xbar))))
# 218: pidot = R(I Omegadot - I Omega x Omega - M R^T odot x (Omega x Xbar) + M Xbar x R^T oddot)
#            = R(-M R^T odot x (Omega x Xbar) + T^e) = -M odot x xbar dot + tau^e
#   (R^T odot x Omega x Xbar grouped as R^T odot x (Omega x Xbar); with T^e = R^T tau^e the second member is
#    the law of row 160 written in b)
Omd = Om.diff(t)
V = R.T * od
first = R * (Ibody * Omd - (Ibody * Om).cross(Om) - M * V.cross(Om.cross(Xbar)) + M * Xbar.cross(R.T * odd))
check(218, nz(pi.diff(t) - first) and nz(R * (-M * V.cross(Om.cross(Xbar))) - (-M * od.cross(xbar.diff(t)))))
# 224: in b: M R^T oddot + M (hat(Omega)^2 + hat(Omega) dot) Xbar = F^e and
#      I Omegadot - I Omega x Omega + M Xbar x R^T oddot = T^e: R^T pdot and R^T (pidot + M odot x xbar dot)
check(224, nz(R.T * p.diff(t) - (M * R.T * odd + M * (W ** 2 + W.diff(t)) * Xbar))
      and nz(R.T * (pi.diff(t) + M * od.cross(xbar.diff(t)))
             - (Ibody * Omd - (Ibody * Om).cross(Om) + M * Xbar.cross(R.T * odd))))
# 230 ... 252: algebra on generic symbols: A = R^T oddot, Omega, Omegadot, Xbar, F, T, a symmetric I
Ao, Os, Ods, Xs, Fs, Ts = svec("A"), svec("Omega"), svec("Omegad"), svec("Xb"), svec("F"), svec("T")
Mm = sp.symbols("M", positive=True)
Isym = sp.Matrix(3, 3, lambda i, j: sp.Symbol(f"I_{min(i, j) + 1}{max(i, j) + 1}"))
Hs = hat(Os)
eq1 = Mm * Ao + Mm * (Hs ** 2 * Xs + Ods.cross(Xs)) - Fs          # row 224, first (hat(Omega) dot Xbar = Omegadot x Xbar)
eq2 = Isym * Ods - (Isym * Os).cross(Os) + Mm * Xs.cross(Ao) - Ts  # row 224, second
assert nz(W.diff(t) - hat(Omd))                                    # hat(Omega) dot = hat(Omega dot)
# 230: M A - M hat(Xbar) Omegadot = -M hat(Omega)^2 Xbar + F and I Omegadot = I Omega x Omega - M Xbar x A + T
e230a = (Mm * Ao - Mm * hat(Xs) * Ods) - (-Mm * Hs ** 2 * Xs + Fs)
e230b = Isym * Ods - ((Isym * Os).cross(Os) - Mm * Xs.cross(Ao) + Ts)
check(230, zero(e230a - eq1) and zero(e230b - eq2))
# 236: with M A from the first: I Omegadot = I Omega x Omega - Xbar x (M hat(Xbar) Omegadot - M hat(Omega)^2 Xbar + F) + T
A_sol = (Mm * hat(Xs) * Ods - Mm * Hs ** 2 * Xs + Fs) / Mm
e236 = Isym * Ods - ((Isym * Os).cross(Os) - Xs.cross(Mm * hat(Xs) * Ods - Mm * Hs ** 2 * Xs + Fs) + Ts)
check(236, zero(e236 - e230b.subs(dict(zip(Ao, A_sol)))) and zero(eq1.subs(dict(zip(Ao, A_sol)))))
# 241: (I + M hat(Xbar)^2) Omegadot = I Omega x Omega + M Xbar x hat(Omega)^2 Xbar - Xbar x F + T
e241 = (Isym + Mm * hat(Xs) ** 2) * Ods - ((Isym * Os).cross(Os) + Mm * Xs.cross(Hs ** 2 * Xs) - Xs.cross(Fs) + Ts)
check(241, zero(e241 - e236))
# 246: Xbar x hat(Omega)^2 Xbar = hat(Xbar)(Omega Omega^T - |Omega|^2 1) Xbar = hat(Xbar) Omega (Omega . Xbar)
#   = -hat(Omega) Xbar Xbar^T Omega = -hat(Omega)(Xbar Xbar^T - |Xbar|^2 1) Omega = -Omega x hat(Xbar)^2 Omega:
#   the text writes \widehat{X}^T for \bar{X}^T in the fourth and fifth members; as written Xbar (3x1) times
#   \widehat{X}^T (3x3) is no product at all
chain = [Xs.cross(Hs ** 2 * Xs), hat(Xs) * (Os * Os.T - Os.dot(Os) * I3) * Xs, hat(Xs) * Os * Os.dot(Xs),
         -Hs * Xs * Xs.T * Os, -Hs * (Xs * Xs.T - Xs.dot(Xs) * I3) * Os, -Os.cross(hat(Xs) ** 2 * Os)]
intended = all(zero(chain[0] - c) for c in chain[1:])
assert intended
written_is_a_product = Xs.shape[1] == hat(Xs).T.shape[0]       # Xbar \widehat{X}^T: (3x1)(3x3)
check(246, intended and written_is_a_product)
# 252: I_c Omegadot + Omega x I_c Omega = -Xbar x F + T^e with I_c = I + M hat(Xbar)^2
Ics = Isym + Mm * hat(Xs) ** 2
e252 = Ics * Ods + Os.cross(Ics * Os) - (-Xs.cross(Fs) + Ts)
check(252, zero(e252 - e241))
# 257: I_c := I + M hat(Xbar)^2 again: a definition
# 264: tau^e = sum (x_i - o) x f_i = sum (x_i - o_c + o_c - o) x f_i = tau_c^e + R Xbar x f^e = tau_c^e + R(Xbar x F^e)
fi = [sp.Matrix([1, -sp.Rational(1, 3), sp.sin(t)]), sp.Matrix([sp.Rational(2, 5), t / 2, -sp.Rational(3, 4)]),
      sp.Matrix([-sp.cos(t), sp.Rational(5, 8), sp.Rational(1, 7)])]
oc = o + R * Xbar
tau_O = sum(((x - o).cross(f) for x, f in zip(xs, fi)), sp.zeros(3, 1))
tau_C = sum(((x - oc).cross(f) for x, f in zip(xs, fi)), sp.zeros(3, 1))
ftot = sum(fi, sp.zeros(3, 1))
check(264, nz(tau_O - sum(((x - oc + oc - o).cross(f) for x, f in zip(xs, fi)), sp.zeros(3, 1)))
      and nz(tau_O - (tau_C + (R * Xbar).cross(ftot))) and nz(tau_O - (tau_C + R * Xbar.cross(R.T * ftot))))
# 269: I_c Omegadot + Omega x I_c Omega = T_c^e with T_c^e := -Xbar x F^e + T^e, which is R^T tau_c^e
check(269, CHECKS[252] and nz(R.T * tau_C - (-Xbar.cross(R.T * ftot) + R.T * tau_O)))
# 275: Rdot = R hat(Omega); M R^T oddot - M hat(Xbar) Omegadot = -M hat(Omega)^2 Xbar + F^e;
#      I_c Omegadot = I_c Omega x Omega + T_c^e
check(275, CHECKS[41] and CHECKS[230] and CHECKS[252]
      and zero((Ics * Ods - ((Ics * Os).cross(Os) + Ts - Xs.cross(Fs))) - e252))
# 284: about the centre of mass (Xbar = 0): Rdot = R hat(Omega), M oddot = f^e, I_c Omegadot = I_c Omega x Omega + T_c^e
check(284, CHECKS[41] and nz(p0.diff(t) - M * odd) and CHECKS[275])
# 293: I_c = diag(I_1, I_2, I_3): the principal frame chosen, no claim
# 300: Euler's equations in principal axes: I_1 Omega_1 dot = (I_2 - I_3) Omega_2 Omega_3 + T_1^e, cyclic
J1, J2, J3 = sp.symbols("I_1 I_2 I_3", positive=True)
Jd = sp.diag(J1, J2, J3)
euler = Jd * Ods - ((Jd * Os).cross(Os) + Ts)
rows300 = sp.Matrix([J1 * Ods[0] - ((J2 - J3) * Os[1] * Os[2] + Ts[0]),
                     J2 * Ods[1] - ((J3 - J1) * Os[2] * Os[0] + Ts[1]),
                     J3 * Ods[2] - ((J1 - J2) * Os[0] * Os[1] + Ts[2])])
check(300, zero(euler - rows300))
# 312: a fixed point O' (odot = 0): Rdot = hat(omega) R and pidot = tau_e (row 160 with odot = 0)
check(312, CHECKS[46] and CHECKS[160])
# 318: in b, odot = oddot = 0: Rdot = R hat(Omega) and I Omegadot = I Omega x Omega + T^e (row 224's second)
piF = sum(((R * X).cross(m * (R * X).diff(t)) for m, X in zip(ms, Xc)), sp.zeros(3, 1))   # O' = O fixed
check(318, CHECKS[41] and nz(R.T * piF.diff(t) - (Ibody * Omd - (Ibody * Om).cross(Om))))
# 327: Rdot = R hat(I^{-1} Pi), Pidot = Pi x I^{-1} Pi + T_c^e with Pi = I Omega (Omega = I^{-1} Pi)
Pis = Jd * Os
check(327, zero(Jd.inv() * Pis - Os) and zero((Jd * Ods - (Pis.cross(Jd.inv() * Pis) + Ts)) - euler))
# 333: in principal axes: Pi_1 dot = (I_2 - I_3)/(I_2 I_3) Pi_2 Pi_3 + T_1^e, cyclic
P = svec("Pi")
rhs = P.cross(Jd.inv() * P) + Ts
rows333 = sp.Matrix([(J2 - J3) / (J2 * J3) * P[1] * P[2] + Ts[0], (J3 - J1) / (J3 * J1) * P[2] * P[0] + Ts[1],
                     (J1 - J2) / (J1 * J2) * P[0] * P[1] + Ts[2]])
check(333, zero(rhs - rows333))
# 344: d/dt ||Pi|| = Pi . Pidot / sqrt(Pi . Pi) = Pi . (Pi x I^{-1} Pi + T^e)/sqrt(Pi . Pi) = Pi . T^e / ||Pi||
Pt = sp.Matrix([sp.sin(t) + 2, t ** 2 / 3 + 1, sp.cos(t)])
nrm = sp.sqrt(Pt.dot(Pt))
check(344, nz(nrm.diff(t) - Pt.dot(Pt.diff(t)) / nrm)
      and zero(P.dot(P.cross(Jd.inv() * P) + Ts) - P.dot(Ts)))

# negative controls: the checks can fail
assert not nz(Rd - hat(Om) * R)                                   # Rdot is not hat(Omega) R
assert not nz(pi - R * (Ibody * Om - M * Xbar.cross(R.T * od)))   # a sign slip is seen
assert not zero(chain[0] - Xs.cross(Xs.cross(Hs ** 2 * Os)))
assert not nz(lhs175 - om.cross(xbp.cross(p)))                    # the other grouping differs

LINES = [31, 41, 46, 51, 56, 61, 66, 71, 76, 81, 86, 91, 98, 106, 113, 120, 127, 136, 141, 146, 153, 160, 170,
         175, 181, 189, 196, 204, 213, 218, 224, 230, 236, 241, 246, 252, 257, 264, 269, 275, 284, 293, 300, 312,
         318, 327, 333, 344]

ROWS = {
    31: ("not a claim", "packs the configuration (o, R) into one 4x4 matrix E of SE(3): a name, no equation to check"),
    41: ("holds", "with hat(Omega) = R^T Rdot and R R^T = 1, Rdot = R hat(Omega): the kinematic equation restates the definition (check 41)"),
    46: ("holds", "hat(R^T omega) = R^T hat(omega) R, so R hat(Omega) = hat(omega) R with omega = R Omega (check 46)"),
    51: ("holds", "x_i = o + R X_i(t), so xdot_i = odot + R(hat(Omega) X_i + Xdot_i) and p = sum m_i xdot_i (check 51)"),
    56: ("holds", "for constant X_i: p = M(odot + R hat(Omega) Xbar) = M(odot + hat(omega) R Xbar) = M d/dt(o + R Xbar) (check 56)"),
    61: ("holds", "solving p = M(odot + omega x R Xbar) for odot (check 61)"),
    66: ("holds", "pi_i = (x_i - o) x m_i xdot_i = R X_i x m_i(odot + R(Omega x X_i + Xdot_i)) = R(I_i Omega + m_i X_i x (R^T odot + Xdot_i)) with I_i = -m_i hat(X_i)^2 (check 66)"),
    71: ("holds", "Pi_i = R^T pi_i, the body-frame form of the same (check 71)"),
    76: ("holds", "hat(X)^2 = X X^T - |X|^2 1, so -m hat(X)^2 = m(|X|^2 1 - X X^T) (check 76)"),
    81: ("holds", "the same with Xdot_i = 0 (check 81)"),
    86: ("holds", "summing: sum m_i X_i = M Xbar and sum -m_i hat(X_i)^2 = I (check 86)"),
    91: ("holds", "the particle identity summed over the body (check 91)"),
    98: ("holds", "R^T odot = R^T p/M - Omega x Xbar; M Xbar x (Xbar x Omega) = M hat(Xbar)^2 Omega; every member equals pi computed from the particles (check 98). The third member's M Xbar x Xbar x Omega is read as Xbar x (Xbar x Omega), the grouping the next member needs; the fourth and fifth members carry a stray ')' before \\right), which changes nothing"),
    106: ("not a claim", "defines I_c = I + M hat(Xbar)^2 (the prose names it the inertia about the centre of mass, checked in row 113)"),
    113: ("holds", "parallel axis theorem: with Y_i = X_i - Xbar (sum m_i Y_i = 0), I = sum -m_i hat(Xbar + Y_i)^2 = I_c - M hat(Xbar)^2 where I_c = sum -m_i hat(Y_i)^2 (check 113)"),
    120: ("holds", "R(a x b) = Ra x Rb and Omega = R^T omega: R(I_c Omega + Xbar x R^T p) = R I_c R^T omega + R Xbar x p (check 120; the first member's stray ')' again changes nothing)"),
    127: ("holds", "R I_c R^T = R(I + M hat(Xbar)^2)R^T by the definition of I_c, and it is the inertia about the centre of mass in axes parallel to e, sum -m_i hat(R Y_i)^2 (check 127)"),
    136: ("holds", "pi about O' with I about O' (check 86)"),
    141: ("holds", "pi = R(I_c Omega + Xbar x R^T p) (check 98)"),
    146: ("holds", "pi = I_c^R omega + R Xbar x p (check 120)"),
    153: ("holds", "about the centre of mass Xbar = 0: pi = R I_c Omega = I_c^R omega (check 153)"),
    160: ("holds", "for any particles with central pairwise internal forces: pdot = sum m_i xddot_i = f^e, and pidot = sum (xdot_i - odot) x m_i xdot_i + sum (x_i - o) x m_i xddot_i = -M odot x xbar dot + tau_e (check 160)"),
    170: ("holds", "xbar' = R Xbar with Xbar constant: its rate is R hat(Omega) Xbar = R(Omega x Xbar) = omega x xbar' (check 170)"),
    175: ("holds", "odot = xbar dot - xbar' dot, so -M odot x xbar dot = M xbar' dot x xbar dot = (omega x xbar') x p; omega x xbar' x p is read as (omega x xbar') x p, the grouping of the member before it (check 175)"),
    181: ("holds", "the translational kinematics odot = p/M - omega x xbar', Rdot = hat(omega) R, pdot = f^e and pidot = (omega x xbar') x p + tau_e (checks 46, 160, 175, 181)"),
    189: ("holds", "pi = I_c^R omega + xbar' x p solved for omega (check 189)"),
    196: ("holds", "about the centre of mass xbar' = 0: odot = p/M, and -M odot x xbar dot = 0 since xbar dot = odot (check 196)"),
    204: ("holds", "pi = I_c^R omega about the centre of mass (check 153)"),
    213: ("holds", "p = M(odot + R hat(Omega) Xbar): pdot = M oddot + M R(hat(Omega)^2 + hat(Omega) dot) Xbar, and pdot = f^e = R F^e (check 213)"),
    218: ("holds", "differentiating pi = R(I Omega + M Xbar x R^T odot): R(I Omegadot - I Omega x Omega - M R^T odot x (Omega x Xbar) + M Xbar x R^T oddot) (R^T odot x Omega x Xbar read as R^T odot x (Omega x Xbar)); and R(-M R^T odot x (Omega x Xbar)) = -M odot x xbar dot, so with T^e = R^T tau^e the law of row 160 gives the rest (check 218)"),
    224: ("holds", "R^T pdot = F^e and R^T(pidot + M odot x xbar dot) = T^e written out with the rates of row 213 and 218 (check 224)"),
    230: ("holds", "hat(Omega) dot Xbar = Omegadot x Xbar = -hat(Xbar) Omegadot; both equations are the previous pair rearranged (check 230)"),
    236: ("holds", "M R^T oddot = M hat(Xbar) Omegadot - M hat(Omega)^2 Xbar + F^e from the first, put into the second (check 236)"),
    241: ("holds", "Xbar x (M hat(Xbar) Omegadot) = M hat(Xbar)^2 Omegadot moved to the left (check 241)"),
    246: ("typo", "every member equals Xbar x hat(Omega)^2 Xbar once \\widehat{X}^T is read \\bar{X}^T; as written the fourth and fifth members multiply the column Xbar (3x1) by the 3x3 matrix \\widehat{X}^T, which is no product, and the bracket must be Xbar Xbar^T - ||Xbar||^2 1 = hat(Xbar)^2 for the last member (check 246)",
          '\\bar{X}\\times \\widehat{\\Omega}^2\\bar{X}&=\\widehat{\\bar{X}}\\left(\\Omega\\Omega^T-||\\Omega||^2I_{3\\times 3}\\right)\\bar{X}=\\widehat{\\bar{X}}\\Omega(\\Omega\\cdot \\bar{X})=-\\widehat{\\Omega}\\bar{X}\\bar{X}^T\\Omega\\\\\n&=-\\widehat{\\Omega}\\left(\\bar{X}\\bar{X}^T-||\\bar{X}||^2I_{3\\times 3}\\right)\\Omega=-\\Omega\\times \\widehat{\\bar{X}}^2\\Omega',
          "Shapes: Xbar is a 3x1 column and \\widehat{X}^T a 3x3 matrix, so Xbar \\widehat{X}^T is undefined; with Xbar^T, -hat(Omega) Xbar Xbar^T Omega = -(Omega x Xbar)(Xbar . Omega) = hat(Xbar) Omega (Omega . Xbar), the member before it, and Xbar Xbar^T - ||Xbar||^2 1 = hat(Xbar)^2 gives the last member -Omega x hat(Xbar)^2 Omega (hat(Omega) Omega = 0).",
          "Numbers: Xbar = (1,0,0), Omega = (1,1,0): Omega x Xbar = (0,0,-1), hat(Omega)^2 Xbar = Omega x (0,0,-1) = (-1,1,0), Xbar x (-1,1,0) = (0,0,1); -hat(Omega) Xbar Xbar^T Omega = -(0,0,-1)(1) = (0,0,1); hat(Xbar)^2 Omega = Xbar x (Xbar x Omega) = (0,-1,0) and -Omega x (0,-1,0) = (0,0,1): all agree with Xbar^T in place of \\widehat{X}^T."),
    252: ("holds", "with M Xbar x hat(Omega)^2 Xbar = -M Omega x hat(Xbar)^2 Omega and I Omega x Omega = -Omega x I Omega: (I + M hat(Xbar)^2) Omegadot + Omega x (I + M hat(Xbar)^2) Omega = -Xbar x F^e + T^e (check 252)"),
    257: ("not a claim", "restates the definition I_c = I + M hat(Xbar)^2"),
    264: ("holds", "o_c - o = R Xbar: tau^e = tau_c^e + R Xbar x f^e = tau_c^e + R(Xbar x F^e) with f^e = R F^e (check 264)"),
    269: ("holds", "the previous equation with T_c^e = -Xbar x F^e + T^e, which is R^T tau_c^e (check 269)"),
    275: ("holds", "Rdot = R hat(Omega), the translational equation of row 230, and I_c Omega x Omega = -Omega x I_c Omega (checks 41, 230, 252)"),
    284: ("holds", "with Xbar = 0: p = M odot so M oddot = f^e, and I_c Omegadot = I_c Omega x Omega + T_c^e (check 284)"),
    293: ("not a claim", "the body frame chosen along the principal axes: I_c = diag(I_1, I_2, I_3)"),
    300: ("holds", "the components of I_c Omegadot = I_c Omega x Omega + T^e with I_c diagonal (check 300)"),
    312: ("holds", "with O' fixed, odot = 0: Rdot = hat(omega) R and pidot = tau_e (row 160) (check 312)"),
    318: ("holds", "with odot = oddot = 0 the body-frame equation of row 224 is I Omegadot = I Omega x Omega + T^e (check 318)"),
    327: ("holds", "Pi = I Omega: Omega = I^-1 Pi and Pidot = I Omegadot = I Omega x Omega + T = Pi x I^-1 Pi + T (check 327)"),
    333: ("holds", "components of Pi x I^-1 Pi with I diagonal: Pi_2 Pi_3 (1/I_3 - 1/I_2) = (I_2 - I_3)/(I_2 I_3) Pi_2 Pi_3, cyclic (check 333)"),
    344: ("holds", "d/dt sqrt(Pi . Pi) = Pi . Pidot / sqrt(Pi . Pi), and Pi . (Pi x I^-1 Pi) = 0 (check 344)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
