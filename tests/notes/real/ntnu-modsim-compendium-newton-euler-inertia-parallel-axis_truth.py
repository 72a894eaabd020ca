"""Independent SymPy truth table for ntnu-modsim-compendium-newton-euler-inertia-parallel-axis.tex.

The compendium's convention: a rigid body b turns relative to the inertial frame i with the angular
velocity omega_ib; its orientation is modelled by R(t) = R_z(a) R_y(b) R_x(c) with three arbitrary
functions of time, so that body components of a vector are R^T times its inertial components and the
body rates are read off R^T dR/dt. J_{b/c} (J_c, J_cm) is the inertia matrix about the centre of mass
in body components, constant there: a general symmetric matrix. The moments are J_xx = int (y^2 + z^2) dm,
..., the products J_xy = int xy dm, ..., and the inertia matrix holds the products with a minus sign.
A body is modelled by point masses about its centre of mass (their first moment zero), which is enough:
every quantity here is a sum over the mass. x^cross is the skew matrix of the cross product.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Ry, Rz

CHECKS = {}
zero = truth_table.zero


def check(key, ok):
    CHECKS[key] = bool(ok)


def vee(W):
    return sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])


def skew(v):
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


t = sp.Symbol('t')
a, b, c = (sp.Function(n)(t) for n in 'abc')
R = Rz(a) * Ry(b) * Rx(c)
w_b = vee(R.T * R.diff(t))                      # omega_ib in body components
w_i = R * w_b                                   # and in inertial components
Jxx, Jyy, Jzz, Jxy, Jxz, Jyz = sp.symbols('J_xx J_yy J_zz J_xy J_xz J_yz')
J = sp.Matrix([[Jxx, -Jxy, -Jxz], [-Jxy, Jyy, -Jyz], [-Jxz, -Jyz, Jzz]])

# Euler's law about the centre of mass: tau = inertial rate of h = R J w_b, in body components
h_i = R * J * w_b
tau_b = R.T * h_i.diff(t)
alpha_b = w_b.diff(t)                           # the rate of omega seen in the body
alpha_b_inertial = R.T * w_i.diff(t)            # the inertial rate of omega, in body components
euler_ok = truth_table.numeric_zero(tau_b - (J * alpha_b + w_b.cross(J * w_b)), t)
alpha_same = truth_table.numeric_zero(alpha_b - alpha_b_inertial, t)
transport_ok = truth_table.numeric_zero(tau_b - ((J * w_b).diff(t) + w_b.cross(J * w_b)), t)
assert euler_ok and alpha_same and transport_ok

# 46: [F; tau] = diag(m I_3, J_cm) [a_cm; alpha] + [0; omega x J_cm omega]
m = sp.Symbol('m', positive=True)
acm = sp.Matrix(sp.symbols('a_x a_y a_z'))
F = m * acm                                     # Newton's second law for the centre of mass
lhs = sp.Matrix.vstack(F, tau_b)
rhs = sp.diag(m * sp.eye(3), J) * sp.Matrix.vstack(acm, alpha_b) + sp.Matrix.vstack(sp.zeros(3, 1), w_b.cross(J * w_b))
check(46, truth_table.numeric_zero(lhs - rhs, t))
# 63: h = J omega; tau = inertial rate = body rate + omega x h = J alpha + omega x J omega
check(63, transport_ok and euler_ok and alpha_same)
# 79: p = m v, p-dot = m a (constant mass)
v = sp.Matrix([sp.Function(f'v_{k}')(t) for k in 'xyz'])
check(79, zero((m * v).diff(t) - m * v.diff(t)))
# 86: h_c = J_c omega; its rate J d(omega)/dt + omega x J omega (= the torque)
check(86, euler_ok and alpha_same)

# a body of point masses about its centre of mass
ms = sp.symbols('m1:4', positive=True)
P1 = sp.Matrix(sp.symbols('x1 y1 z1'))
P2 = sp.Matrix(sp.symbols('x2 y2 z2'))
P3 = -(ms[0] * P1 + ms[1] * P2) / ms[2]
pts = list(zip(ms, (P1, P2, P3)))
M = sum(ms)
assert zero(sum((mi * p for mi, p in pts), sp.zeros(3, 1)))


def moments(points, origin):
    """J_xx, J_yy, J_zz, J_xy, J_xz, J_yz of the points about origin, by the text's definitions."""
    q = [(mi, p - origin) for mi, p in points]
    return (sum(mi * (p[1]**2 + p[2]**2) for mi, p in q), sum(mi * (p[0]**2 + p[2]**2) for mi, p in q),
            sum(mi * (p[0]**2 + p[1]**2) for mi, p in q), sum(mi * p[0] * p[1] for mi, p in q),
            sum(mi * p[0] * p[2] for mi, p in q), sum(mi * p[1] * p[2] for mi, p in q))


def matrix(mo):
    xx, yy, zz, xy, xz, yz = mo
    return sp.Matrix([[xx, -xy, -xz], [-xy, yy, -yz], [-xz, -yz, zz]])


# 106: h_c = sum m r x (omega x r) equals J_c omega with the matrix of moments and (minus) products
w = sp.Matrix(sp.symbols('w_x w_y w_z'))
h_sum = sum((mi * p.cross(w.cross(p)) for mi, p in pts), sp.zeros(3, 1))
Jc = matrix(moments(pts, sp.zeros(3, 1)))
check(106, zero(h_sum - Jc * w))
# 148: the body's centre of mass at (x, y, z); moments about the point (x', y', z'), same frame
X = sp.Matrix(sp.symbols('x y z'))
Xp = sp.Matrix(sp.symbols("x' y' z'"))
body = [(mi, X + p) for mi, p in pts]
Jc_xx, Jc_yy, Jc_zz = moments(body, X)[:3]
Jp_xx, Jp_yy, Jp_zz = moments(body, Xp)[:3]
dx, dy, dz = Xp - X
rows_148 = (zero(Jp_xx - (Jc_xx + M * (dy**2 + dz**2))), zero(Jp_yy - (Jc_yy + M * (dx**2 + dz**2))),
            zero(Jp_zz - (Jc_xx + M * (dx**2 + dy**2))))
assert rows_148[0] and rows_148[1] and not rows_148[2]
assert zero(Jp_zz - (Jc_zz + M * (dx**2 + dy**2)))           # the third row with J_zz
check(148, all(rows_148))
# 164: M_{b/o} = M_{b/c} - m (r_g x)(r_g x), r_g from o to c
O = sp.Matrix(sp.symbols('o_x o_y o_z'))
Mo = matrix(moments(body, O))
Mc = matrix(moments(body, X))
rg = X - O
check(164, zero(Mo - (Mc - M * skew(rg) * skew(rg))))

LINES = [46, 63, 79, 86, 95, 106, 122, 134, 148, 164]
NC, H_ = "not a claim", "holds"
ROWS = {
    46: (H_, "Newton's law for the centre of mass and Euler's law about it, J_cm alpha + omega x J_cm omega, stacked "
             "(check 46)"),
    63: (H_, "h = J omega; its inertial rate is the rate seen in the body plus omega x h, and with J fixed in the body "
             "that is J alpha + omega x (J omega), alpha the rate of omega (the same in either frame) (check 63)"),
    79: (H_, "p = m v and, the mass constant, p-dot = m a (= the sum of the forces, Newton's law) (check 79)"),
    86: (H_, "h_c = J_c omega and its rate J omega-dot + omega x J omega, equal to the torque about the centre of "
             "mass (check 86)"),
    95: (NC, "the centre of mass, defined"),
    106: (H_, "h_c = sum of m r x (omega x r) = J_c omega with the moments on the diagonal and minus the products "
              "off it (check 106)"),
    122: (NC, "the moments of inertia, defined"),
    134: (NC, "the products of inertia, defined"),
    148: ("typo",
          "about a point (x', y', z') the moments of a body whose centre of mass is at (x, y, z) are J + m (sum of the "
          "squared offsets across the axis); the first two rows hold, but the third row has J_xx where J_zz belongs "
          "(check 148)",
          "\\begin{align}\n    \\begin{split}\n        J_{x'x'} &= J_{xx} + m((y' - y)^2 + (z' - z)^2)\n        \\\\\n"
          "        J_{y'y'} &= J_{yy} + m((x' - x)^2 + (z' - z)^2)\n        \\\\\n"
          "        J_{z'z'} &= J_{zz} + m((x' - x)^2 + (y' - y)^2)\n    \\end{split}\n\\end{align}",
          "By algebra: the moment about the z' axis is the sum of dm times ((x_p - x')^2 + (y_p - y')^2); writing "
          "x_p - x' = (x_p - x) - (x' - x) and using that the first moment about the centre of mass vanishes gives "
          "the sum of dm ((x_p - x)^2 + (y_p - y)^2) + m((x' - x)^2 + (y' - y)^2) = J_zz + m((x' - x)^2 + (y' - y)^2): "
          "the moment about the parallel z axis through the centre, J_zz, not J_xx.",
          "By numbers: a thin rod of mass m and length l along z through its centre has J_xx = m l^2/12 and J_zz = 0. "
          "Moved so that x' - x = 1, y' - y = 0, all its mass lies at distance 1 from the z' axis, so J_z'z' = m; the "
          "display gives m l^2/12 + m."),
    164: (H_, "the parallel axis theorem in cross-product form: -m (r x)(r x) = m(|r|^2 1 - r r^T), so M_o = M_c + "
              "m(|r_g|^2 1 - r_g r_g^T) (check 164)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
