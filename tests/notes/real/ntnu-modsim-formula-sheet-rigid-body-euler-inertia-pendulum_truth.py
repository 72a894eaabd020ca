"""Independent SymPy truth table for ntnu-modsim-formula-sheet-rigid-body-euler-inertia-pendulum.tex.

The sheet's convention: a rigid body turns relative to the inertial frame with the angular velocity
omega_ib; its orientation is modelled by R(t) = R_z(a) R_y(b) R_x(c) with three arbitrary functions of
time, body components being R^T times inertial ones, and the body rates read off R^T dR/dt. J (M_{b/c})
is the inertia matrix about the centre of mass in body components, constant there: a general symmetric
matrix. A body is modelled by point masses about its centre of mass (their first moment zero), which is
enough: every quantity here is a sum over the mass. The products of inertia are J_xy = int xy dm (the
sign with which the usual parallel axis rule for products goes); (r x) is the skew matrix of the cross
product; R^b_0 is the transpose of R^0_b. The pendulum is a uniform rod of length L and mass m pivoted
at one end, theta measured from the downward vertical.
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
w_b = vee(R.T * R.diff(t))
J = sp.Matrix(3, 3, lambda i, j: sp.Symbol(f'J_{min(i, j)}{max(i, j)}'))
h_i = R * J * w_b
tau_b = R.T * h_i.diff(t)                        # the torque about the centre of mass, body components
euler_ok = truth_table.numeric_zero(tau_b - (J * w_b.diff(t) + w_b.cross(J * w_b)), t)
assert euler_ok

# 48: T_bc = M alpha + omega x (M omega)
check(48, euler_ok)
# 57: the torque about P is T_c + r_{c/p} x m a_c; the display joins the first two terms by a dot. Take P at the
# centre of mass (r_{c/p} = 0) and the body at rest (omega = 0) but turning up (alpha != 0): the display leaves
# omega x (M omega) = 0, the torque is M alpha.
Mbc = J
alpha = sp.Matrix(sp.symbols('alpha_x alpha_y alpha_z'))
w0 = sp.zeros(3, 1)
true_57 = sp.zeros(3, 1) + Mbc * alpha + w0.cross(Mbc * w0)
shown_57 = sp.zeros(3, 1) + w0.cross(Mbc * w0)       # r x (m a . M alpha) with r = 0 vanishes
check(57, zero(true_57 - shown_57))

# a body of point masses about its centre of mass (the origin), total mass m
ms = sp.symbols('m1:4', positive=True)
P1 = sp.Matrix(sp.symbols('x1 y1 z1'))
P2 = sp.Matrix(sp.symbols('x2 y2 z2'))
P3 = -(ms[0] * P1 + ms[1] * P2) / ms[2]
body = list(zip(ms, (P1, P2, P3)))
m = sum(ms)


def moments(points, origin):
    q = [(mi, p - origin) for mi, p in points]
    return (sum(mi * (p[1]**2 + p[2]**2) for mi, p in q), sum(mi * (p[0]**2 + p[2]**2) for mi, p in q),
            sum(mi * (p[0]**2 + p[1]**2) for mi, p in q), sum(mi * p[0] * p[1] for mi, p in q),
            sum(mi * p[1] * p[2] for mi, p in q), sum(mi * p[2] * p[0] for mi, p in q))


def inertia(points, origin):
    xx, yy, zz, xy, yz, zx = moments(points, origin)
    return sp.Matrix([[xx, -xy, -zx], [-xy, yy, -yz], [-zx, -yz, zz]])


# 88, 97, 104, 110: a point mass m0 added at r0 from the original centre of mass
m0 = sp.Symbol('m_0', positive=True)
r0 = sp.Matrix(sp.symbols('r_x r_y r_z'))
both = body + [(m0, r0)]
new_c = (m * sp.zeros(3, 1) + m0 * r0) / (m + m0)   # from the original centre to the new one
rs_shown = -m0 / (m0 + m) * r0
check(88, zero(rs_shown - new_c))
assert zero(new_c - m0 / (m0 + m) * r0)
M_old = inertia(body, sp.zeros(3, 1))
M0 = inertia(both, sp.zeros(3, 1))
check(97, zero(M0 - (M_old - m0 * skew(r0) * skew(r0))))
Mc = inertia(both, new_c)
check(104, zero(Mc - (M0 + (m + m0) * skew(rs_shown) * skew(rs_shown))))   # the sign of r_s drops out
check(110, zero(Mc - (M_old - m0 * skew(r0) * skew(r0) + (m + m0) * skew(rs_shown) * skew(rs_shown))))

# 122, 130, 138: the body's centre of mass at (x0, y0, z0) from a new origin
D = sp.Matrix(sp.symbols('x_0 y_0 z_0'))
moved = [(mi, p + D) for mi, p in body]
Jc = moments(body, sp.zeros(3, 1))
Jn = moments(moved, sp.zeros(3, 1))
check(122, zero(Jn[2] - (Jc[2] + m * (D[0]**2 + D[1]**2))))      # about z: d^2 = x0^2 + y0^2
check(130, zero(sp.Matrix(Jn[:3]) - sp.Matrix([Jc[0] + m * (D[1]**2 + D[2]**2), Jc[1] + m * (D[0]**2 + D[2]**2),
                                                 Jc[2] + m * (D[0]**2 + D[1]**2)])))
check(138, zero(sp.Matrix(Jn[3:]) - sp.Matrix([Jc[3] + m * D[0] * D[1], Jc[4] + m * D[1] * D[2],
                                                 Jc[5] + m * D[2] * D[0]])))
# 150: the body's points carried by R^0_b; their inertia in frame 0 is R^0_b J R^b_0
th = sp.Symbol('theta')
R0b = Rz(th) * Rx(sp.Rational(1, 3))
turned = [(mi, R0b * p) for mi, p in body]
check(150, zero(inertia(turned, sp.zeros(3, 1)) - R0b * inertia(body, sp.zeros(3, 1)) * R0b.T))
# 157: the rod pivoted at one end: T = (1/2)(m L^2/3) theta-dot^2, V = -m g (L/2) cos(theta)
mr, g, L = sp.symbols('m g L', positive=True)
q = sp.Function('theta')(t)
Lag = sp.Rational(1, 2) * (mr * L**2 / 3) * q.diff(t)**2 + mr * g * (L / 2) * sp.cos(q)
eom = sp.diff(Lag.diff(q.diff(t)), t) - Lag.diff(q)             # = 0
rod_I = sp.integrate(mr / L * sp.Symbol('s')**2, (sp.Symbol('s'), 0, L))
assert zero(rod_I - mr * L**2 / 3)
shown_157 = mr * L**2 / 3 * q.diff(t, 2) + mr * g * L * sp.sin(q)
check(157, zero(eom - shown_157))
assert zero(eom - (mr * L**2 / 3 * q.diff(t, 2) + mr * g * L / 2 * sp.sin(q)))
# 173, 184: J omega-dot + omega x (J omega) = T_c, the rate of h_c
check(173, euler_ok)
check(184, euler_ok)
# 180: the torque about any point A is h_c-dot + r_{c/a} x m a_c: rigid points r_c(t) + R rho_i
rc = sp.Matrix([sp.Function(f'c_{k}')(t) for k in 'xyz'])
rA = sp.Matrix([sp.Function(f'A_{k}')(t) for k in 'xyz'])
pts_t = [(mi, rc + R * p) for mi, p in [(2, sp.Matrix([1, 0, 0])), (3, sp.Matrix([0, 1, 1])),
                                        (5, sp.Matrix([-sp.Rational(2, 5), -sp.Rational(3, 5), -sp.Rational(3, 5)]))]]
mt = 10
assert zero(sum((mi * (p - rc) for mi, p in pts_t), sp.zeros(3, 1)))
T_A = sum(((p - rA).cross(mi * p.diff(t, 2)) for mi, p in pts_t), sp.zeros(3, 1))
h_c = sum(((p - rc).cross(mi * (p - rc).diff(t)) for mi, p in pts_t), sp.zeros(3, 1))
check(180, truth_table.numeric_zero(T_A - (h_c.diff(t) + (rc - rA).cross(mt * rc.diff(t, 2))), t))
# 191: the inertia about A, d from the centre of mass to A
dA = sp.Matrix(sp.symbols('d_x d_y d_z'))
J_A = inertia(body, dA)
J_cm = inertia(body, sp.zeros(3, 1))
shown_191 = J_cm + m * dA * dA.T - m * dA.dot(dA) * sp.eye(3)
check(191, zero(J_A - shown_191))
assert zero(J_A - (J_cm + m * (dA.dot(dA) * sp.eye(3) - dA * dA.T)))
# 198: A fixed, the body turning about it: h_A = J_A omega and T_A = its rate, so Euler's law holds with J_A
pts_A = [(mi, R * p) for mi, p in [(2, sp.Matrix([1, 0, 0])), (3, sp.Matrix([0, 1, 1]))]]   # A at the origin
T_fixed = sum((p.cross(mi * p.diff(t, 2)) for mi, p in pts_A), sp.zeros(3, 1))
JA_body = sum((mi * (p.dot(p) * sp.eye(3) - p * p.T) for mi, p in [(2, sp.Matrix([1, 0, 0])), (3, sp.Matrix([0, 1, 1]))]),
              sp.zeros(3, 3))
check(198, truth_table.numeric_zero(R.T * T_fixed - (JA_body * w_b.diff(t) + w_b.cross(JA_body * w_b)), t))

LINES = [25, 33, 44, 48, 53, 57, 70, 88, 97, 104, 110, 122, 130, 138, 150, 157, 164, 173, 180, 184, 191, 198]
NC, H_ = "not a claim", "holds"
ROWS = {
    25: (NC, "Newton's second law for the centre of mass, stated"),
    33: (NC, "Euler's law about a point, stated with h-dot left open: it holds when h-dot is the rate of h seen in "
             "the body (J omega-dot), while the sheet's own h_c-dot further down already holds omega x J omega; "
             "which is meant the sheet does not say, so the display is read as the law stated"),
    44: (NC, "Newton's second law for the centre of mass, stated"),
    48: (H_, "Euler's law about the centre of mass: M alpha + omega x (M omega) (check 48)"),
    53: (NC, "Newton's second law for the centre of mass, stated again"),
    57: ("typo",
         "the torque about P is r_{c/p} x m a_c + M alpha + omega x (M omega); the display joins the first two terms "
         "with a dot, which makes r x (m a_c . M alpha), a cross product with a number, and loses M alpha (check 57)",
         "\\mathbf{T}_{p} = \\vec{r}_{c/p} \\times m \\vec{a}_c + \\mathbf{M}_{b/c} \\cdot \\boldsymbol{\\alpha}_{ib} "
         "+ \\boldsymbol{\\omega}_{ib} \\times \\left( \\mathbf{M}_{b/c} \\cdot \\boldsymbol{\\omega}_{ib} \\right)",
         "By algebra: the torque about P of the forces f_k at r_k is the sum of (r_k - r_P) x f_k = sum of (r_k - r_c) "
         "x f_k + (r_c - r_P) x sum of f_k = T_c + r_{c/p} x m a_c, and T_c = M alpha + omega x (M omega): three terms "
         "added. A dot between r x m a_c and M alpha would take the scalar product of two vectors and cross r with a "
         "number, which is not defined.",
         "By numbers: P at the centre of mass (r_{c/p} = 0), the body at rest (omega = 0) and spun up with alpha = "
         "(1, 0, 0) about a principal axis with moment 2: the torque needed is M alpha = (2, 0, 0), while the "
         "display's right side is 0 + omega x (M omega) = 0."),
    70: (NC, "the inertia matrix's entries, named"),
    88: ("typo",
         "the new centre of mass lies m_0/(m + m_0) r_0 from the original one, towards the added mass; the display's "
         "minus sign gives the vector from the new centre to the old one, not the r_s the sheet defines (check 88)",
         "\\mathbf{r}_s = \\frac{m_0}{m_0 + m} \\mathbf{r}_0,",
         "By algebra: measured from the original centre of mass, the body's mass m sits at 0 and m_0 at r_0, so the "
         "centre of both is (m 0 + m_0 r_0)/(m + m_0) = m_0 r_0/(m + m_0), with the same sign as r_0 (the sheet's later "
         "displays take the total mass as m + m_0, so m is the body's own mass).",
         "By numbers: m = m_0 = 1 and r_0 = (2, 0, 0): two equal masses at 0 and at (2, 0, 0) have their centre at "
         "(1, 0, 0), while the display gives r_s = -(1/2)(2, 0, 0) = (-1, 0, 0), on the far side from the added mass."),
    97: (H_, "-m_0 (r_0 x)(r_0 x) = m_0(|r_0|^2 1 - r_0 r_0^T), the point mass's inertia about the original centre "
             "(check 97)"),
    104: (H_, "the parallel axis theorem from the original centre to the new one, (m + m_0)(r_s x)(r_s x) = -(m + m_0)"
              "(|r_s|^2 1 - r_s r_s^T); it holds whichever sign r_s carries (check 104)"),
    110: (H_, "the two steps combined (check 110)"),
    122: (H_, "the parallel axis theorem: J = J_cm + m d^2 about a parallel axis at distance d (check 122)"),
    130: (H_, "the moments about a new origin from which the centre of mass lies at (x_0, y_0, z_0) (check 130)"),
    138: (H_, "the products of inertia, int xy dm, about the new origin gain m x_0 y_0 (check 138)"),
    150: (H_, "the inertia tensor carried to frame 0 is R^0_b J (R^0_b)^T, with R^b_0 the transpose (check 150)"),
    157: ("typo",
           "a uniform rod pivoted at one end has I = m L^2/3 about the pivot, but its weight acts at its middle, L/2 "
           "from the pivot: the torque is -m g (L/2) sin(theta); the display has -m g L sin(theta) (check 157)",
           "\\frac{L^2 m}{3} \\ddot{\\theta} = -\\frac{mgL}{2} \\sin \\theta",
           "By algebra: the potential energy of the rod is -m g (L/2) cos(theta) (its centre of mass at L/2 below the "
           "pivot at theta = 0) and its kinetic energy (1/2)(m L^2/3) theta-dot^2, so Lagrange's equation is "
           "(m L^2/3) theta-ddot = -m g (L/2) sin(theta), i.e. theta-ddot = -(3g/2L) sin(theta).",
           "By numbers: a metre stick (L = 1 m, g = 9.81 m/s^2) swinging about one end has the small-swing period "
           "2 pi sqrt(2L/3g) = 1.64 s, the known 'equivalent length 2L/3'; the display gives theta-ddot = -(3g/L) "
           "theta, a period of 2 pi sqrt(L/3g) = 1.16 s."),
    164: (NC, "an example's equation (a rod about a point A with the torque of its weight) without the setting that "
              "would fix J, L and the pivot's motion"),
    173: (H_, "Euler's law about the centre of mass (check 173)"),
    180: (H_, "the torque about any point A: the rate of h_c plus r_{c/a} x m a_c (check 180)"),
    184: (H_, "the rate of h_c = J omega with J fixed in the body: J omega-dot + omega x (J omega) (check 184)"),
    191: ("typo",
          "the inertia about A is J_cm + m(|d|^2 1 - d d^T); the display has the two terms with their signs swapped, "
          "J_cm + m d d^T - m |d|^2 1 (check 191)",
          "\\mathbf{J}_A = \\mathbf{J}_{\\text{cm}} + m \\|\\mathbf{d}\\|^2 \\mathbf{I} - m \\mathbf{d} \\cdot "
          "\\mathbf{d}^T",
          "By algebra: about A each mass element at rho from the centre of mass sits at rho - d, and the inertia is "
          "the sum of dm (|rho - d|^2 1 - (rho - d)(rho - d)^T); the cross terms vanish with the first moment about the "
          "centre of mass, leaving J_cm + m(|d|^2 1 - d d^T), the scalar rule J = J_cm + m d^2 for each axis.",
          "By numbers: a point mass m = 1 at the centre of mass (J_cm = 0) and d = (1, 0, 0): about A the mass lies on "
          "the x axis at distance 1, so J_A = diag(0, 1, 1); the display gives diag(1, 0, 0) - 1 = diag(0, -1, -1), "
          "negative moments, which no mass can have."),
    198: (H_, "A fixed and the body turning about it: h_A = J_A omega and its rate J_A omega-dot + omega x (J_A omega) "
              "is the torque about A (check 198)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
