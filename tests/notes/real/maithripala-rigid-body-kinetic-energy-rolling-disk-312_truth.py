"""Independent SymPy truth table for maithripala-rigid-body-kinetic-energy-rolling-disk-312.tex.

The text's own setting: frames as rows of unit vectors, b = e R, a particle of the body at X_i
(fixed) in b, the body frame's origin at o in e, V_o = R^T o-dot, the hat map with hat(a) b = a x b,
the body angular velocity Omega with hat(Omega) = R^T R-dot. R_1, R_2, R_3 are the turns about the
first, second and third axes, R_3(t) = [[cos, -sin, 0], [sin, cos, 0], [0, 0, 1]] (as the disk's
matrix the text writes out confirms). The disk: R = R_3(theta) R_1(alpha) R_2(phi). Every check is
built here from these definitions, never from the text's later displays. Run with --write to regenerate the table.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero
c, s = sp.cos, sp.sin
t = sp.symbols("t", real=True)


def R1(q):
    return sp.Matrix([[1, 0, 0], [0, c(q), -s(q)], [0, s(q), c(q)]])


def R2(q):
    return sp.Matrix([[c(q), 0, s(q)], [0, 1, 0], [-s(q), 0, c(q)]])


def R3(q):
    return sp.Matrix([[c(q), -s(q), 0], [s(q), c(q), 0], [0, 0, 1]])


def hat(v):
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def vee(W):
    return sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])


# a particle fixed at X_i in b moves in e with o-dot + R hat(Omega) X_i (hat(Omega) = R^T R-dot), so its
# energy is m_i ||R (V_o + Omega x X_i)||^2/2 = m_i ||V_o + Omega x X_i||^2/2 (R orthogonal, V_o = R^T o-dot);
# the identities below are checked in symbols for V_o, Omega and three particles X_i
a1, a2, a3 = sp.symbols("a_1:4", real=True)
Rg = R3(a1) * R1(a2) * R3(a3)
assert zero(sp.simplify(Rg.T * Rg) - sp.eye(3))
Vo = sp.Matrix(sp.symbols("V_1:4", real=True))
Om = sp.Matrix(sp.symbols("Omega_1:4", real=True))
ms = sp.symbols("m_1:4", positive=True)
Xs = [sp.Matrix(sp.symbols(f"x{i}_1:4", real=True)) for i in range(1, 4)]
E3 = sp.eye(3)
Ii = [m * ((X.T * X)[0] * E3 - X * X.T) for m, X in zip(ms, Xs)]
vel = [Rg * (Vo + Om.cross(X)) for X in Xs]
KEi = [m * (v.T * v)[0] / 2 for m, v in zip(ms, vel)]
# 25: KE_i = (m_i ||V_o||^2 + 2 m_i V_o^T hat(Omega) X_i + Omega^T I_i Omega)/2 (m read as m_i, as the notes'
# section on moving frames writes the particle's mass)
k26 = [(m * (Vo.T * Vo)[0] + 2 * m * (Vo.T * hat(Om) * X)[0] + (Om.T * I * Om)[0]) / 2
       for m, X, I in zip(ms, Xs, Ii)]
check(25, all(sp.simplify(sp.expand(a - b)) == 0 for a, b in zip(KEi, k26)))
# 35: the sum: M ||V_o||^2 + 2 M V_o^T hat(Omega) Xbar + Omega^T I Omega, with M Xbar = sum m_i X_i
Mt = sum(ms)
Xbar = sum((m * X for m, X in zip(ms, Xs)), sp.zeros(3, 1)) / Mt
Itot = sum(Ii, sp.zeros(3, 3))
k36 = (Mt * (Vo.T * Vo)[0] + 2 * Mt * (Vo.T * hat(Om) * Xbar)[0] + (Om.T * Itot * Om)[0]) / 2
check(35, sp.simplify(sum(k26) - k36) == 0)
# 43: about the centre of mass (Xbar = 0): (M ||V_o||^2 + Omega^T I Omega)/2, and ||V_o|| = ||o-dot|| for
# o-dot = R V_o
od0 = Rg * Vo
check(43, sp.simplify((k36 - (Mt * (Vo.T * Vo)[0] + (Om.T * Itot * Om)[0]) / 2).subs(
    {Xs[2][k]: -(ms[0] * Xs[0][k] + ms[1] * Xs[1][k]) / ms[2] for k in range(3)})) == 0
    and sp.simplify((Vo.T * Vo)[0] - (od0.T * od0)[0]) == 0)
# 51: dKE/dt = o-dot . M o-ddot + Omega . I Omega-dot = o-dot . f + Omega . T under M o-ddot = f and
# I Omega-dot = I Omega x Omega + T (the body-frame equation about the centre of mass)
Ic = sp.diag(*sp.symbols("J_1:4", positive=True))
W = sp.Matrix(sp.symbols("W_1:4", real=True))
Tq = sp.Matrix(sp.symbols("T_1:4", real=True))
f = sp.Matrix(sp.symbols("f_1:4", real=True))
od = sp.Matrix(sp.symbols("v_1:4", real=True))
Wdot = Ic.inv() * (Ic * W).cross(W) + Ic.inv() * Tq
odd = f / Mt
KEdot = (Mt * (od.T * odd)[0] + Mt * (odd.T * od)[0] + (Wdot.T * Ic * W)[0] + (W.T * Ic * Wdot)[0]) / 2
check(51, sp.simplify(KEdot - ((od.T * f)[0] + (W.T * Tq)[0])) == 0
      and sp.simplify(KEdot - (Mt * (od.T * odd)[0] + (W.T * Ic * Wdot)[0])) == 0)

# the falling and rolling disk
th, al, ph = [sp.Function(n)(t) for n in ("theta", "alpha", "phi")]
R = R3(th) * R1(al) * R2(ph)
R65 = sp.Matrix([[c(th) * c(ph) - s(th) * s(al) * s(ph), -s(th) * c(al), c(th) * s(ph) + s(th) * s(al) * c(ph)],
                 [s(th) * c(ph) + c(th) * s(al) * s(ph), c(th) * c(al), s(th) * s(ph) - c(th) * s(al) * c(ph)],
                 [-c(al) * s(ph), s(al), c(al) * c(ph)]])
check(64, zero(R - R65))
OmD = sp.simplify(vee(R.T * R.diff(t)))
assert zero(sp.simplify(R.T * R.diff(t) - hat(OmD)))
thd, ald, phd = th.diff(t), al.diff(t), ph.diff(t)
O72 = sp.Matrix([ald * c(ph) - thd * c(al) * s(ph), phd - thd * s(al), thd * c(al) * c(ph) + ald * s(ph)])
assert zero(OmD - sp.Matrix([O72[0], phd + thd * s(al), O72[2]]))
# 71: the text's Omega_2 has the sign of its theta-dot term reversed
check(71, zero(OmD - O72))

ROWS = {
    25: ("holds", "a particle fixed in b at X_i moves with o-dot + R hat(Omega) X_i; its energy m_i ||V_o + Omega x X_i||^2/2 "
                  "expands to the three terms, m_i ||Omega x X_i||^2 = Omega^T I_i Omega (check 25; m is the particle's mass "
                  "m_i, as the notes' section on moving frames writes it)"),
    30: ("not a claim", "the definition of a particle's moment of inertia about the origin of b"),
    35: ("holds", "summing over the particles, sum m_i X_i = M Xbar and sum I_i = I (check 35)"),
    43: ("holds", "with the origin at the centre of mass Xbar = 0; ||V_o|| = ||R^T o-dot|| = ||o-dot|| (check 43)"),
    51: ("holds", "differentiating, with M o-ddot = f^e and I Omega-dot = I Omega x Omega + T^e; Omega . (I Omega x Omega) = 0 "
                  "(check 51)"),
    64: ("holds", "the product R_3(theta) R_1(alpha) R_2(phi) (check 64)"),
    71: ("typo", "from hat(Omega) = R^T R-dot, Omega_2 = phi-dot + theta-dot sin(alpha); the text writes the theta-dot term "
                  "with a minus sign (check 71)",
         "{\\Omega}_2 & = & \\dot{\\phi}+\\dot{\\theta}\\sin{\\alpha}, \\label{eq:CoinBodyAngVel2}\\\\",
         "With alpha = phi = 0 (R = R_3(theta)) the body turns about its 3-axis at theta-dot, so Omega = (0, 0, theta-dot); "
         "with phi = 0 and alpha = pi/2 (R = R_3(theta) R_1(pi/2), the body 2-axis R e_2 = (0, 0, 1) vertical) a turn "
         "theta-dot about the vertical is a turn theta-dot about the body 2-axis: Omega_2 = phi-dot + theta-dot, so the "
         "sign of theta-dot sin(alpha) is plus.",
         "Omega = R_2(phi)^T [R_1(alpha)^T (0, 0, theta-dot) + (alpha-dot, 0, 0)] + (0, phi-dot, 0); R_1(alpha)^T (0, 0, 1) "
         "= (0, sin(alpha), cos(alpha)), and R_2(phi)^T keeps the 2-component, so Omega_2 = phi-dot + theta-dot sin(alpha); "
         "Omega_1 and Omega_3 agree with the text."),
}

LINES = sorted(ROWS)


if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
