"""Independent SymPy truth table for verga-polytech-euler-angles-body-angular-velocity-fr-zxz.ipynb.

The notebook's own setting: a fixed basis (e_X, e_Y, e_Z) and a moving one (e_x, e_y, e_z), both
canonical in their own frame; the transfer matrix R has the moving basis vectors as its columns,
(e_x e_y e_z) = (e_X e_Y e_Z) R, and C = R^T changes coordinates, (x, y, z) = C (X, Y, Z).
R_X, R_Y, R_Z are the active (counter-clockwise) rotations about the axes and C_X, C_Y, C_Z their
transposes. Euler angles: phi about Z, theta about the line of nodes N, psi about the body z, so
C = C_z(psi) C_x(theta) C_z(phi) and R = R_Z(phi) R_X(theta) R_Z(psi) (the 3-1-3 sequence).
Omega = phidot e_Z + thetadot e_N + psidot e_z. Every check is built here from these definitions.
A display's line is the notebook file's line of its first row.
"""
import sys
import pathlib
import sympy as sp

import truth_table

CHECKS = {}
def check(key, ok):
    CHECKS[key] = bool(ok)

import random


def z0(expr, samples=4):
    """expr (a scalar or a matrix) vanishes: evaluated at sampled values of all its symbols and
    functions of t (with their rates), to 1e-12; an identity in the angles is tested so."""
    m = expr if hasattr(expr, 'shape') else sp.Matrix([expr])
    rng = random.Random(7)
    rates = sorted(m.atoms(sp.Derivative), key=str)
    funcs = sorted(m.atoms(sp.core.function.AppliedUndef), key=str)
    syms = sorted(m.free_symbols, key=str)
    for _ in range(samples):
        m1 = m.subs({f: sp.Float(rng.uniform(-2, 2), 30) for f in rates})      # the rates first
        m1 = m1.subs({f: sp.Float(rng.uniform(-2, 2), 30) for f in funcs})
        m1 = m1.subs({x: sp.Float(rng.uniform(-2, 2), 30) for x in syms})
        if any(abs(complex(sp.N(e, 30))) > 1e-12 for e in m1):
            return False
    return True
ph, th, ps, a = sp.symbols('phi theta psi a', real=True)
c, s = sp.cos, sp.sin

def RX(u):
    return sp.Matrix([[1, 0, 0], [0, c(u), -s(u)], [0, s(u), c(u)]])
def RY(u):
    return sp.Matrix([[c(u), 0, s(u)], [0, 1, 0], [-s(u), 0, c(u)]])
def RZ(u):
    return sp.Matrix([[c(u), -s(u), 0], [s(u), c(u), 0], [0, 0, 1]])
def CX(u):
    return RX(u).T
def CY(u):
    return RY(u).T
def CZ(u):
    return RZ(u).T

E = sp.eye(3)                                   # the canonical basis as columns
X, Y, Z = sp.symbols('X Y Z', real=True)
Xv = sp.Matrix([X, Y, Z])
n = sp.Matrix(sp.symbols('n_1:4', real=True))
Rn = RZ(ph) * RX(th) * RZ(ps)                   # a generic rotation R_n(a)
# 49: r = (e_X e_Y e_Z)(X Y Z)^T = X e_X + Y e_Y + Z e_Z = (X Y Z)^T for the canonical basis
check(49, z0(E * Xv - (X * E[:, 0] + Y * E[:, 1] + Z * E[:, 2])) and z0(E * Xv - Xv))
# 55: I_3 -> (e_X e_Y e_Z) written in the moving frame: a schematic statement (not a claim)
# 60: the moving basis is the fixed one turned by R_n(a): notation (not a claim)
# 64: (e_x e_y e_z) = (e_X e_Y e_Z) R_n(a) = R_n(a): defines the moving basis (not a claim)
# 70, 76: r = (e_x e_y e_z)(x y z)^T defines the moving coordinates (not a claim)
xv = sp.Matrix(sp.symbols('x y z', real=True))
# 80: r = R_n(a) (x y z)^T: the moving basis E R substituted into 70
check(80, z0((E * Rn) * xv - Rn * xv))
# 84: (x y z)^T = C (X Y Z)^T with C = R^T: solving R x = X with R orthogonal
sol = Rn.T * Xv
check(84, z0(Rn * sol - Xv) and z0(Rn.T * Rn - E))
# 90: C_X, C_Y, C_Z, the transposes of the elementary rotations
CY_text = sp.Matrix([[c(ph), 0, -s(ph)], [0, 1, 0], [s(ph), 1, c(ph)]])
CX_text = sp.Matrix([[1, 0, 0], [0, c(ph), s(ph)], [0, -s(ph), c(ph)]])
CZ_text = sp.Matrix([[c(ph), s(ph), 0], [-s(ph), c(ph), 0], [0, 0, 1]])
check(90, z0(CX_text - CX(ph)) and z0(CY_text - CY(ph)) and z0(CZ_text - CZ(ph)))
assert z0(CX_text - CX(ph)) and z0(CZ_text - CZ(ph))      # only C_Y's row (sin, 1, cos) is off
# 107: as 84
check(107, z0(Rn * (Rn.T * Xv) - Xv))
# 113: A-bar = R^T A R: a map X' = A X in fixed coordinates is x' = R^T A R x in moving ones
A = sp.Matrix(3, 3, sp.symbols('A_1:10', real=True))
Abar = Rn.T * A * Rn
check(113, z0(Rn.T * (A * (Rn * xv)) - Abar * xv))
# 117: A-bar = C A R
check(117, z0(Rn.T * A * Rn - Abar))
# 121: A = R A-bar R^T
check(121, z0(Rn * Abar * Rn.T - A))
# 126: e A e^T = (e R)(C A R)(C e^T) = e-bar A-bar e-bar^T with e-bar = e R
eb = E * Rn
check(126, z0(E * A * E.T - (E * Rn) * (Rn.T * A * Rn) * (Rn.T * E.T)) and z0(eb * Abar * eb.T - E * A * E.T))
# 140: X . X = X^T X = (X^T R^T) . (R X) = x . x with x = R X
xx = Rn * Xv
check(140, z0((Xv.T * Xv)[0] - (Xv.T * Rn.T * Rn * Xv)[0]) and z0((Xv.T * Xv)[0] - (xx.T * xx)[0]))
u = sp.Matrix(sp.symbols('u_1:4', real=True))
v = sp.Matrix(sp.symbols('v_1:4', real=True))
w = u.cross(v)
# 146: R w = R u ^ R v for a rotation R
check(146, z0(Rn * w - (Rn * u).cross(Rn * v)))
# 150: R w = R (L.u) R^T R v with (L.u) the antisymmetric matrix of u ^ .
Lu = sp.Matrix([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])
check(150, z0(Rn * w - Rn * Lu * Rn.T * Rn * v))
# 173, 178, 182: the three successive changes of coordinates define C (not a claim)
C = CZ(ps) * CX(th) * CZ(ph)
# 187: C(phi, theta, psi) written out
C_text = sp.Matrix([
    [-c(th) * s(ps) * s(ph) + c(ps) * c(ph), c(th) * c(ps) * s(ph) + s(ps) * c(ph), s(th) * s(ph)],
    [-c(th) * s(ps) * c(ph) - c(ps) * s(ph), c(th) * c(ps) * c(ph) - s(ps) * s(ph), s(th) * c(ph)],
    [s(th) * s(ps), -s(th) * c(ps), c(th)]])
check(187, z0(C_text - C))
assert z0(C_text - CZ(ph) * CX(th) * CZ(ps))     # the written matrix has phi and psi exchanged
assert z0(C_text.subs({ph: ps, ps: ph}, simultaneous=True) - C)     # the table's correction
# 207: R = [C_z(psi) C_x(theta) C_z(phi)]^T = R_Z(phi) R_X(theta) R_Z(psi)
R = RZ(ph) * RX(th) * RZ(ps)
check(207, z0(C.T - R))
# 211: R(phi, theta, psi) written out
R_text = sp.Matrix([
    [c(th) * s(ps) * s(ph) + c(ps) * c(ph), -c(th) * s(ps) * c(ph) - c(ps) * s(ph), s(th) * s(ps)],
    [c(th) * c(ps) * s(ph) + s(ps) * c(ph), c(th) * c(ps) * c(ph) - s(ps) * s(ph), -s(th) * c(ps)],
    [s(th) * s(ph), s(th) * c(ph), c(th)]])
check(211, z0(R_text - R))
R_fix = sp.Matrix([
    [c(ps) * c(ph) - c(th) * s(ps) * s(ph), -c(th) * c(ps) * s(ph) - s(ps) * c(ph), s(th) * s(ph)],
    [c(th) * s(ps) * c(ph) + c(ps) * s(ph), c(th) * c(ps) * c(ph) - s(ps) * s(ph), -s(th) * c(ph)],
    [s(th) * s(ps), s(th) * c(ps), c(th)]])
assert z0(R_fix - R)                                  # the table's correction
assert not z0(R_text - C_text.T) and not z0(R_text - C_text.T.subs({ph: ps, ps: ph}, simultaneous=True))
# --- angular velocity
t = sp.symbols('t', real=True)
f = {ph: sp.Function('phi')(t), th: sp.Function('theta')(t), ps: sp.Function('psi')(t)}
Rt = R.subs(f)
Wb = Rt.T * Rt.diff(t)                   # body components: R^T Rdot = [Omega]x
Om_body = sp.Matrix([Wb[2, 1], Wb[0, 2], Wb[1, 0]])
phd, thd, psd = (f[k].diff(t) for k in (ph, th, ps))
eZ_fixed = E[:, 2]
eN_fixed = RZ(f[ph]) * E[:, 0]
ez_fixed = Rt * E[:, 2]
Ws = Rt.diff(t) * Rt.T                   # fixed components: Rdot R^T = [Omega]x
Om_fixed = sp.Matrix([Ws[2, 1], Ws[0, 2], Ws[1, 0]])
# 225: Omega = phidot e_Z + thetadot e_N + psidot e_z
check(225, z0(Om_fixed - (phd * eZ_fixed + thd * eN_fixed + psd * ez_fixed)))
# 229: the same sum with each axis written in the moving frame (components by C = R^T)
Ct = Rt.T
check(229, z0(Om_body - (phd * Ct * eZ_fixed + thd * Ct * eN_fixed + psd * Ct * ez_fixed)))
# 231: e_Z in the moving basis = C e_z = C_Z(psi) C_X(theta) e_z = (sin th sin psi, sin th cos phi, cos th)
eZ_text = sp.Matrix([s(th) * s(ps), s(th) * c(ph), c(th)])
check(231, z0(C * E[:, 2] - CZ(ps) * CX(th) * E[:, 2]) and z0(CZ(ps) * CX(th) * E[:, 2] - eZ_text))
assert z0(CZ(ps) * CX(th) * E[:, 2] - eZ_text.subs(ph, ps))     # cos(phi) stands where cos(psi) belongs
# 233: e_N = C_Z(psi) C_X(theta) e_x = C_Z(psi) e_x = (cos psi, -sin psi, 0)
eN_body = (Rt.T * eN_fixed).subs({v_: k for k, v_ in f.items()})
check(233, z0(eN_body - CZ(ps) * CX(th) * E[:, 0]) and z0(CZ(ps) * CX(th) * E[:, 0] - CZ(ps) * E[:, 0])
      and z0(CZ(ps) * E[:, 0] - sp.Matrix([c(ps), -s(ps), 0])))
# 237: Omega|xyz = phidot C_Z(psi) C_X(theta) e_z + thetadot C_Z(psi) e_x + psidot e_z
check(237, z0(Om_body - (phd * (CZ(ps) * CX(th) * E[:, 2]).subs(f) + thd * (CZ(ps) * E[:, 0]).subs(f) + psd * E[:, 2])))
# 239: Omega = (phidot sin th sin psi + thetadot cos psi, phidot sin th cos psi - thetadot sin psi, phidot cos th + psidot)
Om_text = sp.Matrix([phd * s(f[th]) * s(f[ps]) + thd * c(f[ps]), phd * s(f[th]) * c(f[ps]) - thd * s(f[ps]),
                     phd * c(f[th]) + psd])
check(239, z0(Om_body - Om_text))
# 243: (e_x e_y e_z) = (e_X e_Y e_Z) R restates 64, the definition (not a claim)
# 245: (e_X e_Y e_Z) in the moving frame = (e_x e_y e_z) C = C: the fixed basis vectors in moving coordinates
check(245, z0(R.T * E - C) and z0(E * C - C))
# 247: e_X = C (1,0,0), e_Y = C (0,1,0), e_Z = C (0,0,1)
check(247, all(z0(R.T * E[:, k] - C * E[:, k]) for k in range(3)))

KEYS = [49, 55, 60, 64, 70, 76, 80, 84, 90, 107, 113, 117, 121, 126, 140, 146, 150, 173, 178, 182, 187,
        207, 211, 225, 229, 231, 233, 237, 239, 243, 245, 247]


if __name__ == "__main__":
    here = pathlib.Path(__file__)
    assert truth_table.notebook_display_lines(here.with_name('verga-polytech-euler-angles-body-angular-velocity-fr-zxz.ipynb')) == KEYS
    sys.exit(truth_table.compare(__file__, CHECKS, KEYS))
