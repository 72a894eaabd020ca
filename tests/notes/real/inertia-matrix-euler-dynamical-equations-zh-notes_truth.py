"""Independent SymPy truth table for inertia-matrix-euler-dynamical-equations-zh-notes.tex.

The text's own setting: a rigid body of density rho turning about a point O with angular velocity
omega, a point of it at r moving with rdot = omega x r; the angular momentum L = int rho r x rdot dV
and the kinetic energy T = 1/2 int rho rdot . rdot dV. An integral over the body is linear, so an
identity between integrals is checked on its integrand at a generic point (x, y, z) with generic
omega; the parallel-axis theorem, which uses the centre of mass, is checked on the integrals
themselves written as moments of the mass about the centre of mass (int rho dV = M, int rho x'_i dV
= 0, int rho x'_i x'_j dV = Q_ij). Euler's dynamical equations are checked from
dL/dt = (relative rate) + omega x L with L = I omega in body components, I constant and symmetric.
Every check is built here from these definitions, never from the text's later displays.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Rz

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero

x, y, z, rho = sp.symbols("x y z rho", real=True)
w1, w2, w3, om = sp.symbols("omega_1 omega_2 omega_3 omega", real=True)
r = sp.Matrix([x, y, z])
w = sp.Matrix([w1, w2, w3])
rdot = w.cross(r)
xs = [x, y, z]


def Iel(i, j, pt=xs):
    """The integrand of I_ij: rho (delta_ij sum x_k^2 - x_i x_j)."""
    return rho * ((1 if i == j else 0) * sum(c**2 for c in pt) - pt[i] * pt[j])


Imat = sp.Matrix(3, 3, lambda i, j: Iel(i, j))
# 34: sum r_i x Delta m_i rdot_i = sum r_i x rho_i rdot_i Delta V_i with Delta m_i = rho_i Delta V_i
dV = sp.symbols("DeltaV", positive=True)
check(34, zero(r.cross((rho * dV) * rdot) - r.cross(rho * rdot * dV)))
# 38: rho r x rdot = rho r x (omega x r) = rho [r^2 omega - (r . omega) r]
Ld = rho * r.cross(rdot)
check(38, zero(Ld - rho * r.cross(w.cross(r))) and zero(Ld - rho * ((r.dot(r)) * w - r.dot(w) * r)))
# 44: the three components
check(44, sp.expand(Ld[0] - rho * ((y**2 + z**2) * w1 - x * y * w2 - x * z * w3)) == 0
      and sp.expand(Ld[0] - rho * ((x**2 + y**2 + z**2) * w1 - (x * w1 + y * w2 + z * w3) * x)) == 0
      and sp.expand(Ld[1] - rho * (-x * y * w1 + (x**2 + z**2) * w2 - y * z * w3)) == 0
      and sp.expand(Ld[2] - rho * (-x * z * w1 - y * z * w2 + (x**2 + y**2) * w3)) == 0)
# 54, 73: L = I omega with I_ij of the definition (60)
check(54, zero(Ld - Imat * w))
check(73, zero(Ld - Imat * w))
# 80: T = 1/2 rho rdot.rdot = 1/2 rho rdot.(omega x r) = 1/2 omega.(r x rho rdot) = 1/2 omega . L
Td = sp.Rational(1, 2) * rho * rdot.dot(rdot)
check(80, sp.expand(Td - sp.Rational(1, 2) * rho * rdot.dot(w.cross(r))) == 0
      and sp.expand(Td - sp.Rational(1, 2) * w.dot(r.cross(rho * rdot))) == 0
      and sp.expand(Td - sp.Rational(1, 2) * w.dot(Ld)) == 0)
# 86: T = 1/2 omega^T I omega
check(86, sp.expand(Td - sp.Rational(1, 2) * (w.T * Imat * w)[0]) == 0)

# 120, 126: parallel axes, on the integrals as moments about the centre of mass
M = sp.symbols("M", positive=True)
X = sp.symbols("X_1:4", real=True)
xp = sp.symbols("xp_1:4", real=True)
Q = sp.Matrix(3, 3, lambda i, j: sp.Symbol(f"Q_{min(i, j) + 1}{max(i, j) + 1}"))


def integrate(expr):
    """int rho (polynomial in x') dV: 1 -> M, x'_i -> 0 (centre of mass), x'_i x'_j -> Q_ij."""
    poly = sp.Poly(sp.expand(expr), *xp)
    total = 0
    for powers, coeff in poly.terms():
        deg = sum(powers)
        if deg == 0:
            total += coeff * M
        elif deg == 2:
            idx = [k for k, p in enumerate(powers) for _ in range(p)]
            total += coeff * Q[idx[0], idx[1]]
        elif deg != 1:
            raise ValueError(powers)
    return total


ptO = [X[k] + xp[k] for k in range(3)]
I_O = sp.Matrix(3, 3, lambda i, j: integrate(Iel(i, j, ptO) / rho))
I_C = sp.Matrix(3, 3, lambda i, j: integrate(Iel(i, j, list(xp)) / rho))
I_pt = sp.Matrix(3, 3, lambda i, j: M * ((1 if i == j else 0) * sum(c**2 for c in X) - X[i] * X[j]))
check(120, zero(I_O - (I_pt + I_C)))
check(126, zero(I_O - I_C - I_pt))
assert not zero(I_O - I_C)

# the axis n: omega = om n with |n| = 1
n1, n2, n3 = sp.symbols("n_1:4", real=True)
n = sp.Matrix([n1, n2, n3])
wn = om * n
rdn = wn.cross(r)
Ln = rho * r.cross(rdn)
unit = {n3**2: 1 - n1**2 - n2**2}


def on_unit(e):
    return sp.simplify(sp.expand(e).subs(unit))


# 136: n . L = rho r x (omega x r) . n = rho (n x r).(n x r) omega
check(136, on_unit(n.dot(Ln) - rho * (r.cross(wn.cross(r))).dot(n)) == 0
      and on_unit(n.dot(Ln) - rho * (n.cross(r)).dot(n.cross(r)) * om) == 0)
# 142: L_n = I_n omega with I_n = rho |n x r|^2 (148)
In = rho * (n.cross(r)).dot(n.cross(r))
check(142, on_unit(n.dot(Ln) - In * om) == 0)
# 160: L_n = n^T L = n^T I omega = n^T I n omega
check(160, on_unit(n.dot(Ln) - (n.T * Imat * wn)[0]) == 0
       and on_unit((n.T * Imat * wn)[0] - (n.T * Imat * n)[0] * om) == 0)
# 166: I_n = n^T I n
check(166, on_unit(In - (n.T * Imat * n)[0]) == 0)
# 173: T = 1/2 omega^T I omega = 1/2 I_n omega^2
check(173, on_unit((wn.T * Imat * wn)[0] / 2 - In * om**2 / 2) == 0)

# 189, 195: omega = U omega' with U orthogonal: T = 1/2 omega'^T U^T I U omega', I' = U^T I U
a = sp.symbols("a", real=True)
U = sp.Matrix([[sp.cos(a), -sp.sin(a), 0], [sp.sin(a), sp.cos(a), 0], [0, 0, 1]])
Isym = sp.Matrix(3, 3, lambda i, j: sp.Symbol(f"I_{min(i, j) + 1}{max(i, j) + 1}"))
wp = sp.Matrix(sp.symbols("wp_1:4", real=True))
wU = U * wp
Ip = U.T * Isym * U
check(189, sp.simplify((wU.T * Isym * wU)[0] - (wp.T * U.T * Isym * U * wp)[0]) == 0
      and sp.simplify((wU.T * Isym * wU)[0] - (wp.T * Ip * wp)[0]) == 0)
check(195, zero((wU.T * Isym * wU) - (wp.T * Ip * wp)))
# 207: principal axes: L = sum I_i omega_i e_i, T = 1/2 sum I_i omega_i^2
I1, I2, I3 = sp.symbols("I_1 I_2 I_3", positive=True)
D = sp.diag(I1, I2, I3)
check(207, zero(D * w - sp.Matrix([I1 * w1, I2 * w2, I3 * w3]))
      and sp.expand((w.T * D * w)[0] / 2 - (I1 * w1**2 + I2 * w2**2 + I3 * w3**2) / 2) == 0)
# 216: Euler's kinematic equations at theta = 0 or pi put in T
th, ph, ps, thd, phd, psd = sp.symbols("theta phi psi thetadot phidot psidot", real=True)
wk = sp.Matrix([phd * sp.sin(th) * sp.sin(ps) + thd * sp.cos(ps),
                phd * sp.sin(th) * sp.cos(ps) - thd * sp.sin(ps), phd * sp.cos(th) + psd])
Tk = (wk.T * D * wk)[0] / 2
T0 = (I1 * sp.cos(ps)**2 + I2 * sp.sin(ps)**2) * thd**2 / 2 + I3 * (phd + psd)**2 / 2
Tpi = (I1 * sp.cos(ps)**2 + I2 * sp.sin(ps)**2) * thd**2 / 2 + I3 * (phd - psd)**2 / 2
check(216, sp.simplify(Tk.subs(th, 0) - T0) == 0 and sp.simplify(Tk.subs(th, sp.pi) - Tpi) == 0)
# 222: the determinant of the quadratic form's matrix (as written, and with the factor I3) is 0
for sgn in (1, -1):
    H = sp.hessian(T0 if sgn == 1 else Tpi, (thd, phd, psd))
    assert H.det() == 0
check(222, all(sp.Matrix([[I1 * sp.cos(ps)**2 + I2 * sp.sin(ps)**2, 0, 0], [0, 1, s], [0, s, 1]]).det() == 0
               for s in (1, -1)))

# the theorem of kinetic energy and the centre-of-mass splitting
f = sp.Matrix(sp.symbols("f_1:4", real=True))
# 250: T = 1/2 omega . L (the integrand identity of 80)
check(250, sp.expand(Td - sp.Rational(1, 2) * w.dot(Ld)) == 0)
# 256: f . rdot = f . (omega x r) = omega . (r x f), so dT/dt = int f . rdot = omega . M
check(256, sp.expand(f.dot(rdot) - f.dot(w.cross(r))) == 0 and sp.expand(f.dot(w.cross(r)) - w.dot(r.cross(f))) == 0)
# 286, 292: r = R + r' with int rho r' = 0: L = R x M V + L', T = 1/2 M V^2 + T' = 1/2 V.P + 1/2 omega.L'
R = sp.Matrix(sp.symbols("R_1:4", real=True))
V = sp.Matrix(sp.symbols("V_1:4", real=True))
rp = sp.Matrix(xp)
vpt = V + w.cross(rp)


def integrate_vec(vec):
    return sp.Matrix([integrate(c) for c in vec])


Ltot = integrate_vec((R + rp).cross(vpt))
Lp = integrate_vec(rp.cross(w.cross(rp)))
check(286, zero(Ltot - (R.cross(M * V) + Lp)))
Ttot = integrate(vpt.dot(vpt) / 2)
Tp = integrate((w.cross(rp)).dot(w.cross(rp)) / 2)
check(292, sp.expand(Ttot - (M * V.dot(V) / 2 + Tp)) == 0
      and sp.expand(Ttot - (V.dot(M * V) / 2 + w.dot(Lp) / 2)) == 0)

# Euler's dynamical equations: body basis e = E U(t), L = e Lbar
t = sp.symbols("t", real=True)
q1, q2, q3 = (sp.Function(s)(t) for s in ("q1", "q2", "q3"))


Ut = Rz(q1) * Rx(q2) * Rz(q3)
Om = sp.simplify(Ut.T * Ut.diff(t))
wt = sp.Matrix([Om[2, 1], Om[0, 2], Om[1, 0]])
Lb = sp.Matrix([sp.Function(f"L{k}")(t) for k in (1, 2, 3)])
# 319: d(U Lbar)/dt = U Lbar' + U (U^T U') Lbar = U [Lbar' + omega x Lbar]
lhs = (Ut * Lb).diff(t)
check(319, zero(lhs - (Ut * Lb.diff(t) + Ut * (Ut.T * Ut.diff(t)) * Lb))
      and zero(lhs - Ut * (Lb.diff(t) + wt.cross(Lb))))
# 326 and 344: the same for L = M and for any vector A
check(326, zero(lhs - Ut * (Lb.diff(t) + wt.cross(Lb))))
check(344, zero(lhs - Ut * (Lb.diff(t) + wt.cross(Lb))))
# 333: components with products of inertia: I omega' + omega x (I omega) = M, I symmetric
wd = sp.Matrix(sp.symbols("wd_1:4", real=True))
I = sp.Matrix(3, 3, lambda i, j: sp.Symbol(f"I_{i + 1}{j + 1}"))
sym = {sp.Symbol("I_21"): sp.Symbol("I_12"), sp.Symbol("I_31"): sp.Symbol("I_13"),
       sp.Symbol("I_32"): sp.Symbol("I_23")}
Ms = I * wd + w.cross(I * w)
S = lambda n: sp.Symbol(n)  # noqa: E731
I11, I12, I13, I21, I22, I23, I31, I32, I33 = (S(f"I_{a}{b}") for a in "123" for b in "123")
text_rows = [
    I11 * wd[0] + I12 * wd[1] + I13 * wd[2] - (I22 - I33) * w2 * w3 + I23 * (w2**2 - w3**2) - w1 * (I12 * w3 - I13 * w2),
    I21 * wd[0] + I22 * wd[1] + I23 * wd[2] - (I33 - I11) * w3 * w1 + I31 * (w3**2 - w1**2) - w2 * (I23 * w1 - I12 * w3),
    I31 * wd[0] + I32 * wd[1] + I33 * wd[2] - (I11 - I22) * w1 * w2 + I13 * (w1**2 - w2**2) - w3 * (I13 * w2 - I23 * w1)]
diffs = [sp.expand((Ms[k] - text_rows[k]).subs(sym)) for k in range(3)]
check(333, all(d == 0 for d in diffs))
assert diffs[0] == 0 and diffs[1] == 0 and diffs[2] != 0
assert sp.expand((Ms[2] - text_rows[2].subs(I13 * (w1**2 - w2**2), I12 * (w1**2 - w2**2))).subs(sym)) == 0
# 353, 359: principal axes: L_i = I_i omega_i and Euler's equations
Mp = D * wd + w.cross(D * w)
check(353, zero(D * w - sp.Matrix([I1 * w1, I2 * w2, I3 * w3])))
check(359, zero(Mp - sp.Matrix([I1 * wd[0] - (I2 - I3) * w2 * w3, I2 * wd[1] - (I3 - I1) * w3 * w1,
                                I3 * wd[2] - (I1 - I2) * w1 * w2])))

LINES = [34, 38, 44, 54, 60, 67, 73, 80, 86, 96, 102, 108, 114, 120, 126, 136, 142, 148, 154, 160, 166, 173,
         183, 189, 195, 201, 207, 216, 222, 238, 244, 250, 256, 262, 268, 274, 280, 286, 292, 300, 307, 313,
         319, 326, 333, 344, 353, 359]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
