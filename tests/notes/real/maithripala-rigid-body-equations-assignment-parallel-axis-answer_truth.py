"""Independent SymPy truth table for maithripala-rigid-body-equations-assignment-parallel-axis-answer.ipynb.

The notebooks' own setting: an inertial frame e, a body frame b = e R(t) with origin O' at o(t),
hat(Omega) = R^T Rdot, omega = R Omega, hat(omega) = R hat(Omega) R^T; particles of mass m_i at
x_i = o + R X_i (X_i fixed in b for a rigid body); p = sum m_i xdot_i, pi = sum (x_i - o) x m_i xdot_i;
the inertia tensor about O' in b, I = sum m_i (|X_i|^2 1 - X_i X_i^T) = -sum m_i hat(X_i)^2, and
I_c = I + M hat(Xbar)^2; the external force and moment f^e = sum f_i^e, tau^e = sum (x_i - o) x f_i^e,
F^e = R^T f^e, T^e = R^T tau^e. The motions are built here from Newton's law for each particle
(internal forces along the lines joining the particles); the rigid body's equations are checked at
an instant in exact rationals (R an exact rotation, Rdot = R hat(Omega), Rddot = R(hat(Omega)^2 +
hat(Omegadot)), the origin's rates and three particles given), the parallel axis algebra symbolically. A display's line is the
notebook file's line of its first row. Run with --write to regenerate the table.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero
E3 = sp.eye(3)


def hat(v):
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


Q = sp.Rational


def vec(*a):
    return sp.Matrix([Q(v) for v in a])


ms = [Q(2), Q(3), Q(5, 2)]
M = sum(ms)

# --- Q1: particles in any motion at one instant (positions, velocities, accelerations), internal forces
# lam_ij (x_i - x_j) with lam symmetric; Newton gives the external force m_i xddot_i - internal_i
xs = [vec(1, 0, 2), vec(-1, 3, 1), vec(2, -2, -1)]
vs = [vec(0, 1, -1), vec(2, 1, 0), vec(-1, 0, 3)]
acs = [vec(1, 1, 1), vec(0, -2, 1), vec(3, 0, -1)]
lam = {(0, 1): Q(3, 2), (0, 2): Q(-1, 3), (1, 2): Q(5)}
lam.update({(j, i): v for (i, j), v in list(lam.items())})
internal = [sum((lam[(i, j)] * (xs[i] - xs[j]) for j in range(3) if j != i), sp.zeros(3, 1)) for i in range(3)]
fe = [ms[i] * acs[i] - internal[i] for i in range(3)]
o1, o1d = vec(1, 2, 0), vec(0, -1, 2)
xbar_dd = sum((ms[i] * acs[i] for i in range(3)), sp.zeros(3, 1)) / M
xbar_d = sum((ms[i] * vs[i] for i in range(3)), sp.zeros(3, 1)) / M
pdot1 = sum((ms[i] * acs[i] for i in range(3)), sp.zeros(3, 1))
pidot1 = sum(((vs[i] - o1d).cross(ms[i] * vs[i]) + (xs[i] - o1).cross(ms[i] * acs[i]) for i in range(3)),
             sp.zeros(3, 1))
tau1 = sum(((xs[i] - o1).cross(fe[i]) for i in range(3)), sp.zeros(3, 1))
check(31, zero(pdot1 - M * xbar_dd) and zero(M * xbar_dd - sum(fe, sp.zeros(3, 1)))
      and zero(pidot1 - (-M * o1d.cross(xbar_d) + tau1)))

# --- a rigid body at one instant: R an exact rotation (Cayley's transform of a skew matrix), Rdot = R hat(Omega),
# Rddot = R (hat(Omega)^2 + hat(Omegadot)); the origin's position, velocity and acceleration; three particles
S = hat(vec(Q(1, 2), -1, 2))
R = (E3 - S) * (E3 + S).inv()
assert zero(R.T * R - E3) and R.det() == 1
Om, Omd = vec(1, -2, Q(1, 2)), vec(Q(-3, 2), 1, 2)
Rd = R * hat(Om)
Rdd = R * (hat(Om)**2 + hat(Omd))
o, od, odd = vec(1, 0, -1), vec(2, 1, 0), vec(0, -1, 3)
Xs = [vec(1, 0, 2), vec(-1, 3, 0), vec(2, -1, -1)]
Xbar = sum((ms[i] * Xs[i] for i in range(3)), sp.zeros(3, 1)) / M
om, omd = R * Om, R * Omd                                   # omega = R Omega and its rate (R hat(Omega) Omega = 0)
x = [o + R * X for X in Xs]
xd = [od + Rd * X for X in Xs]
xdd = [odd + Rdd * X for X in Xs]
p = sum((ms[i] * xd[i] for i in range(3)), sp.zeros(3, 1))
pd = sum((ms[i] * xdd[i] for i in range(3)), sp.zeros(3, 1))
pi = sum(((x[i] - o).cross(ms[i] * xd[i]) for i in range(3)), sp.zeros(3, 1))
pid = sum(((xd[i] - od).cross(ms[i] * xd[i]) + (x[i] - o).cross(ms[i] * xdd[i]) for i in range(3)),
          sp.zeros(3, 1))
II = sum((ms[i] * (X.dot(X) * E3 - X * X.T) for i, X in enumerate(Xs)), sp.zeros(3, 3))
Ic = II + M * hat(Xbar)**2
IcR = R * Ic * R.T
f = pd                                                      # the internal forces cancel in the sum
tau = sum(((x[i] - o).cross(ms[i] * xdd[i]) for i in range(3)), sp.zeros(3, 1))   # and in the moment
xbar_r, xbar_rd = o + R * Xbar, od + Rd * Xbar
xbp = xbar_r - o
F, T = R.T * f, R.T * tau
# 53: p = M(odot + R hat(Omega) Xbar) = M(odot + hat(omega) R Xbar) = M xbar-dot
check(53, zero(p - M * (od + R * hat(Om) * Xbar)) and zero(p - M * (od + hat(om) * R * Xbar))
      and zero(p - M * xbar_rd))
# 64: odot = p/M - omega x R Xbar
check(64, zero(od - (p / M - om.cross(R * Xbar))))
# 75, 79, 83: the three forms of pi
check(75, zero(pi - R * (II * Om + M * Xbar.cross(R.T * od))))
check(79, zero(pi - R * (Ic * Om + Xbar.cross(R.T * p))))
check(83, zero(pi - (IcR * om + (R * Xbar).cross(p))))
# 104: the e-frame equations, the last read (omega x xbar') x p
check(104, zero(od - (p / M - om.cross(xbp))) and zero(Rd - hat(om) * R) and zero(pd - f)
      and zero(pid - (om.cross(xbp).cross(p) + tau)))
assert not zero(pid - (om.cross(xbp.cross(p)) + tau))       # the other grouping does not hold
# 118: moments about the centre of mass (the body frame's origin moved to it)
Xc = [X - Xbar for X in Xs]
xc = [xbar_r + R * X for X in Xc]
xcd = [xbar_rd + Rd * X for X in Xc]
xcdd = [odd + Rdd * Xbar + Rdd * X for X in Xc]
pc = sum((ms[i] * xcd[i] for i in range(3)), sp.zeros(3, 1))
pcd = sum((ms[i] * xcdd[i] for i in range(3)), sp.zeros(3, 1))
picd = sum(((xcd[i] - xbar_rd).cross(ms[i] * xcd[i]) + (xc[i] - xbar_r).cross(ms[i] * xcdd[i]) for i in range(3)),
           sp.zeros(3, 1))
tauc = sum(((xc[i] - xbar_r).cross(ms[i] * xcdd[i]) for i in range(3)), sp.zeros(3, 1))
check(118, zero(xbar_rd - pc / M) and zero(Rd - hat(om) * R) and zero(pcd - f) and zero(picd - tauc))
# 140: the b-frame equations, with T_c = -Xbar x F + T
Tc = -Xbar.cross(F) + T
check(140, zero(Rd - R * hat(Om))
      and zero(M * R.T * odd - M * hat(Xbar) * Omd - (-M * hat(Om)**2 * Xbar + F))
      and zero(Ic * Omd - (Ic * Om).cross(Om) - Tc))
# 166: a pivot at O' (o fixed: odot = oddot = 0)
xp = [R * X for X in Xs]
xpd = [Rd * X for X in Xs]
xpdd = [Rdd * X for X in Xs]
ppd = sum((ms[i] * xpdd[i] for i in range(3)), sp.zeros(3, 1))
pipd = sum((xpd[i].cross(ms[i] * xpd[i]) + xp[i].cross(ms[i] * xpdd[i]) for i in range(3)), sp.zeros(3, 1))
taup = sum((xp[i].cross(ms[i] * xpdd[i]) for i in range(3)), sp.zeros(3, 1))
check(166, zero(ppd - M * R * (hat(Om)**2 * Xbar + hat(Omd) * Xbar))
      and zero(pipd - R * (II * Omd - (II * Om).cross(Om))) and zero(pipd - taup))
# 171: I = sum -m_i hat(X_i)^2 = sum m_i(|X_i|^2 1 - X_i X_i^T)
Xg = sp.Matrix(sp.symbols("X1:4", real=True))
check(171, zero(-hat(Xg)**2 - (Xg.dot(Xg) * E3 - Xg * Xg.T))
      and zero(II - sum((-ms[i] * hat(X)**2 for i, X in enumerate(Xs)), sp.zeros(3, 3))))

# --- the parallel axis theorem, symbolically: x_i = xbar + X_i
xb = sp.Matrix(sp.symbols("xb1:4", real=True))
Xv = [sp.Matrix(sp.symbols(f"X{i}_1:4", real=True)) for i in range(3)]
mv = sp.symbols("m0:3", positive=True)
n2 = lambda v: v.dot(v)                                     # noqa: E731
Ix = [mv[i] * (n2(xb + Xv[i]) * E3 - (xb + Xv[i]) * (xb + Xv[i]).T) for i in range(3)]
Ib = [mv[i] * (n2(Xv[i]) * E3 - Xv[i] * Xv[i].T) for i in range(3)]
X0, m0 = Xv[0], mv[0]
x0 = xb + X0
check(233, zero(Ix[0] - m0 * (n2(x0) * E3 - x0 * x0.T)))
check(237, sp.expand(n2(xb + X0) - (n2(xb) + n2(X0) + 2 * (xb.T * X0)[0])) == 0)
check(241, zero(Ix[0] - m0 * ((n2(xb) + n2(X0) + 2 * (xb.T * X0)[0]) * E3
                             - (xb * xb.T + xb * X0.T + X0 * xb.T + X0 * X0.T))))
cross = lambda i: 2 * (xb.T * Xv[i])[0] * E3 - xb * Xv[i].T - Xv[i] * xb.T   # noqa: E731
check(252, zero(Ix[0] - (m0 * (n2(X0) * E3 - X0 * X0.T) + m0 * (n2(xb) * E3 - xb * xb.T) + m0 * cross(0))))
check(256, zero(Ix[0] - (Ib[0] + m0 * (n2(xb) * E3 - xb * xb.T) + m0 * cross(0))))
Mv = sum(mv)
Xbv = sum((mv[i] * Xv[i] for i in range(3)), sp.zeros(3, 1)) / Mv
Ixs = sum(Ix, sp.zeros(3, 3))
Ibs = sum(Ib, sp.zeros(3, 3))
mid = Ibs + Mv * (n2(xb) * E3 - xb * xb.T) + sum((mv[i] * cross(i) for i in range(3)), sp.zeros(3, 3))
last = Ibs + Mv * (n2(xb) * E3 - xb * xb.T) + Mv * (2 * (xb.T * Xbv)[0] * E3 - xb * Xbv.T - Xbv * xb.T)
check(267, zero(Ixs - mid) and zero(mid - last))
# 277: with the centre of mass at the origin of b (X_2 fixed by sum m_i X_i = 0)
sub = {Xv[2][k]: -(mv[0] * Xv[0][k] + mv[1] * Xv[1][k]) / mv[2] for k in range(3)}
check(277, zero((Ixs - (Ibs + Mv * (n2(xb) * E3 - xb * xb.T))).subs(sub)))

ROWS = {
    31: ("holds", "Newton's law for each particle with internal forces along the joining lines: the internal forces cancel "
                  "in p-dot and their moments in pi-dot, and (xdot_i - odot) x m_i xdot_i sums to -M odot x xbar-dot "
                  "(check 31)"),
    53: ("holds", "xdot_i = odot + R hat(Omega) X_i and R hat(Omega) = hat(omega) R (check 53)"),
    64: ("holds", "the line before solved for odot (check 64)"),
    75: ("holds", "pi = sum R X_i x m_i (odot + R hat(Omega) X_i) (check 75)"),
    79: ("holds", "I_c Omega + Xbar x R^T p equals I Omega + M Xbar x R^T odot, the hat(Xbar)^2 terms cancelling (check 79)"),
    83: ("holds", "R I_c Omega = I_c^R omega and R(Xbar x R^T p) = R Xbar x p (check 83)"),
    104: ("holds", "the e-frame equations; pi-dot = -odot x p + tau^e with odot = p/M - omega x xbar' gives "
                   "(omega x xbar') x p + tau^e, the cross products taken from the left (check 104)"),
    118: ("holds", "with the origin at the centre of mass, xbar' = 0 (check 118)"),
    140: ("holds", "R^T of p-dot = f^e, and Euler's equation about the centre of mass in b (check 140)"),
    146: ("not a claim", "the definition of I_c"),
    166: ("holds", "a fixed pivot: p = M R hat(Omega) Xbar and pi = R I Omega differentiated (check 166)"),
    171: ("holds", "the definitions of M, f^e, tau^e and I, with -hat(X)^2 = |X|^2 1 - X X^T (check 171)"),
    195: ("not a claim", "the definition of a particle's moment of inertia about the origin of e"),
    214: ("not a claim", "the definition restated in e"),
    218: ("not a claim", "the same definition in b"),
    229: ("not a claim", "the relation of the positions in two parallel frames, the setting"),
    233: ("holds", "x_i = xbar + X_i substituted (check 233)"),
    237: ("holds", "the squared norm of a sum (check 237)"),
    241: ("holds", "both expansions put in (check 241)"),
    252: ("holds", "the terms regrouped (check 252)"),
    256: ("holds", "the first group is I_{b_i} (check 256)"),
    267: ("holds", "summed over the particles with M and Xbar (check 267)"),
    272: ("not a claim", "the definitions of the total mass and the centre of mass in b"),
    277: ("holds", "the parallel axis theorem when sum m_i X_i = 0 (check 277)"),
    289: ("not a claim", "the definition of the moment of inertia of a continuum as the limit of sums, an integral"),
}

LINES = sorted(ROWS)


if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
