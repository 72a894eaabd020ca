"""Independent SymPy truth table for jhu-intermediate-dynamics-zxz-zyz-euler-rates-football-kinetic-energy-hw.tex.

The solutions' conventions: the Euler angle rotations are active right-handed turns composed as written,
R_ZXZ = R_z(psi) R_x(theta) R_z(phi) and R_ZYZ = R_z(psi) R_y(theta) R_z(phi), mapping body components to
space components; the spatial angular velocity is the vector of R-dot R^T and the body angular velocity the
vector of R^T R-dot (vect of a skew matrix W is (W_32, W_13, W_21)). The football's inertia matrix in its
body frame is m diag(0.04^2, 0.07^2, 0.04^2) (radii of gyration in metres); its speed is 25 m/s along the
body y-axis, and one revolution is 2 pi radians.
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


t = sp.Symbol('t')
psi, th, phi = (sp.Function(n)(t) for n in ('psi', 'theta', 'phi'))
s, c = sp.sin, sp.cos
pd, td, fd = psi.diff(t), th.diff(t), phi.diff(t)

# ---- problem 1: Z-X-Z ----
R = Rz(psi) * Rx(th) * Rz(phi)
R_shown = sp.Matrix([
    [c(phi) * c(psi) - c(th) * s(phi) * s(psi), -c(psi) * s(phi) - c(phi) * c(th) * s(psi), s(psi) * s(th)],
    [c(phi) * s(psi) + c(psi) * c(th) * s(phi), c(phi) * c(psi) * c(th) - s(phi) * s(psi), -c(psi) * s(th)],
    [s(phi) * s(th), c(phi) * s(th), c(th)]])
check(33, zero(R - R_shown))
w_s = vee(sp.simplify(R.diff(t) * R.T))
check(50, zero(w_s - sp.Matrix([c(psi) * td + s(psi) * s(th) * fd, s(psi) * td - c(psi) * s(th) * fd,
                                c(th) * fd + pd])))
w_b = vee(sp.simplify(R.T * R.diff(t)))
check(57, zero(w_b - sp.Matrix([c(phi) * td + s(phi) * s(th) * pd, c(phi) * s(th) * pd - s(phi) * td,
                                c(th) * pd + fd])))

# ---- problem 2: the football, Z-Y-Z ----
m = sp.Symbol('m', positive=True)
Ib = sp.diag(m * sp.Rational(4, 100)**2, m * sp.Rational(7, 100)**2, m * sp.Rational(4, 100)**2)
check(68, zero(Ib - m * sp.diag(sp.Rational(16, 10000), sp.Rational(49, 10000), sp.Rational(16, 10000))))
v = sp.Matrix([0, 25, 0])
T_trans = m * v.dot(v) / 2
check(87, zero(T_trans - sp.Rational(3125, 10) * m))
R2 = Rz(psi) * Ry(th) * Rz(phi)
R2_shown = sp.Matrix([
    [c(phi) * c(psi) * c(th) - s(phi) * s(psi), -c(phi) * s(psi) - c(psi) * c(th) * s(phi), c(psi) * s(th)],
    [c(psi) * s(phi) + c(phi) * c(th) * s(psi), c(phi) * c(psi) - c(th) * s(phi) * s(psi), s(psi) * s(th)],
    [-c(phi) * s(th), s(phi) * s(th), c(th)]])
check(91, zero(R2 - R2_shown))
wb2 = vee(sp.simplify(R2.T * R2.diff(t)))
check(107, zero(wb2 - sp.Matrix([s(phi) * td - c(phi) * s(th) * pd, c(phi) * td + s(phi) * s(th) * pd,
                                 c(th) * pd + fd])))
T_rot = sp.expand((wb2.T * Ib * wb2)[0] / 2)
T_rot_shown = m / 20000 * (16 * fd**2 + 49 * pd**2 + 16 * td**2 - 33 * c(phi)**2 * pd**2 + 33 * c(phi)**2 * td**2
                           - 33 * c(th)**2 * pd**2 + 33 * c(phi)**2 * c(th)**2 * pd**2 + 32 * c(th) * pd * fd
                           + 66 * c(phi) * s(phi) * s(th) * td * pd)
check(112, zero(T_rot - T_rot_shown))
check(123, zero(T_trans + T_rot - (sp.Rational(3125, 10) * m + T_rot_shown)))
# part (b): 5 rev/s about the body y axis
wb_rev = sp.Matrix([0, 5, 0])
wb_rad = 2 * sp.pi * wb_rev
check(136, zero(wb_rad - sp.Matrix([0, 10 * sp.pi, 0])))
T_rot_b = (wb_rad.T * Ib * wb_rad)[0] / 2
check(141, zero(T_rot_b - sp.Rational(245, 1000) * m * sp.pi**2))
check(152, zero(T_trans + T_rot_b - (sp.Rational(3125, 10) * m + sp.Rational(245, 1000) * m * sp.pi**2)))

LINES = [30, 33, 50, 57, 68, 83, 87, 91, 107, 112, 123, 136, 141, 152]
NC, H_ = "not a claim", "holds"
ROWS = {
    30: (NC, "the Z-X-Z Euler angle rotation as the problem defines it, R_3(psi) R_1(theta) R_3(phi)"),
    33: (H_, "R_z(psi) R_x(theta) R_z(phi) multiplied out entry by entry (check 33)"),
    50: (H_, "the spatial angular velocity vect(R-dot R^T) = (cos(psi) theta-dot + sin(psi) sin(theta) phi-dot, "
              "sin(psi) theta-dot - cos(psi) sin(theta) phi-dot, cos(theta) phi-dot + psi-dot) (check 50)"),
    57: (H_, "the body angular velocity vect(R^T R-dot) = (cos(phi) theta-dot + sin(phi) sin(theta) psi-dot, "
              "cos(phi) sin(theta) psi-dot - sin(phi) theta-dot, cos(theta) psi-dot + phi-dot) (check 57)"),
    68: (H_, "the inertia matrix m k^2 from the radii of gyration: 0.04^2 = 0.0016 and 0.07^2 = 0.0049 (check 68)"),
    83: (NC, "the translational kinetic energy, (1/2) m v.v (a definition)"),
    87: (H_, "(1/2) m 25^2 = 312.5 m joules (check 87)"),
    91: (H_, "R_z(psi) R_y(theta) R_z(phi) multiplied out entry by entry (check 91)"),
    107: (H_, "the Z-Y-Z body angular velocity vect(R^T R-dot) = (sin(phi) theta-dot - cos(phi) sin(theta) psi-dot, "
               "cos(phi) theta-dot + sin(phi) sin(theta) psi-dot, cos(theta) psi-dot + phi-dot) (check 107)"),
    112: (H_, "(1/2) omega_b^T I_b omega_b expanded over 20000: the coefficients 16, 49, 33 = 49 - 16 and 32 "
               "(check 112)"),
    123: (H_, "the total kinetic energy is 312.5 m plus the rotational energy of line 112 (check 123)"),
    136: (H_, "5 rev/s is 10 pi rad/s (check 136)"),
    141: (H_, "(1/2) m 0.0049 (10 pi)^2 = 0.245 m pi^2 joules (check 141)"),
    152: (H_, "the total kinetic energy 312.5 m + 0.245 m pi^2 (check 152)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
