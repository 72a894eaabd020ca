"""Independent SymPy truth table for jhu-intermediate-dynamics-disk-on-elbow-zxz-kinetic-energy-hw.tex.

The solution's conventions: the disk's orientation is R = R_z(psi) R_x(theta) R_z(phi), active right-handed
turns composed as written (body components to fixed components), with theta constant; the body angular
velocity is the vector of R^T R-dot (vect of a skew matrix W is (W_32, W_13, W_21)). The disk's centre lies a
distance s along its body Z-axis from the elbow, which sits at L along X_1 (part a) or at the origin (part b):
r = L e_1 + s R e_3 or r = s R e_3. Its inertia matrix about its centre, in the body frame, is
diag(I_x, I_x, I_z); T = (1/2) M v.v + (1/2) omega_b^T I_b omega_b.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Rz

CHECKS = {}
zero = truth_table.zero


def check(key, ok):
    CHECKS[key] = bool(ok)


def vee(W):
    return sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])


t = sp.Symbol('t')
psi, phi = sp.Function('psi')(t), sp.Function('phi')(t)
th, M, Lb, sd, Ix, Iz = sp.symbols('theta M L s I_x I_z', positive=True)     # theta is constant
s, c = sp.sin, sp.cos
pd, fd = psi.diff(t), phi.diff(t)

R = Rz(psi) * Rx(th) * Rz(phi)
R_shown = sp.Matrix([
    [c(phi) * c(psi) - c(th) * s(phi) * s(psi), -c(psi) * s(phi) - c(phi) * c(th) * s(psi), s(psi) * s(th)],
    [c(phi) * s(psi) + c(psi) * c(th) * s(phi), c(phi) * c(psi) * c(th) - s(phi) * s(psi), -c(psi) * s(th)],
    [s(phi) * s(th), c(phi) * s(th), c(th)]])
check(41, zero(R - R_shown))
wb = vee(sp.simplify(R.T * R.diff(t)))
check(57, zero(wb - sp.Matrix([s(phi) * s(th) * pd, c(phi) * s(th) * pd, fd + c(th) * pd])))
# the centre: the elbow at L e_1 (part a), the disk's centre s along its body Z-axis
r_a = sp.Matrix([Lb, 0, 0]) + sd * R[:, 2]
assert zero(r_a - sp.Matrix([Lb + sd * s(psi) * s(th), -sd * c(psi) * s(th), sd * c(th)]))
v = r_a.diff(t)
v_shown = sp.Matrix([sd * c(psi) * s(th) * pd, sd * s(psi) * s(th) * pd, 0])
check(70, zero(v - v_shown))
T_trans = M * v.dot(v) / 2
check(78, zero(T_trans - M * sd**2 * s(th)**2 * pd**2 / 2))
Ib = sp.diag(Ix, Ix, Iz)
T_rot = (wb.T * Ib * wb)[0] / 2
check(83, zero(T_rot - (Iz * (fd + c(th) * pd)**2 / 2 + Ix * s(th)**2 * pd**2 / 2)))
T_shown = Iz * (fd + c(th) * pd) / 2 + Ix * s(th)**2 * pd**2 / 2 + M * sd**2 * s(th)**2 * pd**2 / 2
check(89, zero(T_trans + T_rot - T_shown))
# part (b): the origin at b
r_b = sd * R[:, 2]
check(102, zero(r_b.diff(t) - v_shown))
check(111, zero(M * r_b.diff(t).dot(r_b.diff(t)) / 2 + T_rot - T_shown))

LINES = [33, 41, 57, 62, 70, 78, 83, 89, 94, 102, 111]
NC, H_ = "not a claim", "holds"
T_RIGHT = ("T = \\frac{1}{2}I_{z}\\,\\left(\\dot{\\phi} +\\cos\\left(\\theta \\right)\\,\\dot{\\psi} \\right)^2"
           "+\\frac{1}{2}I_{x}\\,\\sin \\left(\\theta \\right)^2\\,\\dot{\\psi}^2"
           "+\\frac{1}{2}M\\,s^2\\,\\sin \\left(\\theta \\right)^2\\,\\dot{\\psi}^2")
HAND_1 = ("By hand: T_rot = (1/2) omega_b^T diag(I_x, I_x, I_z) omega_b with omega_b = (sin(phi) sin(theta) psi-dot, "
          "cos(phi) sin(theta) psi-dot, phi-dot + cos(theta) psi-dot) is (1/2) I_x sin(theta)^2 psi-dot^2 "
          "(sin^2 + cos^2 of phi) + (1/2) I_z (phi-dot + cos(theta) psi-dot)^2, as line 83 itself writes; a "
          "kinetic energy is quadratic in the rates, and the display's I_z term is linear in them.")
HAND_2 = ("Numbers: I_z = 2, I_x = 0, M = 0, theta = pi/2, phi-dot = 3, psi-dot = 0: the spin energy is "
          "(1/2)(2)(3)^2 = 9, while the display gives (1/2)(2)(3) = 3.")
ROWS = {
    33: (NC, "the disk's inertia matrix in the body frame, given by the problem"),
    41: (H_, "R_z(psi) R_x(theta) R_z(phi) multiplied out entry by entry (check 41)"),
    57: (H_, "vect(R^T R-dot) with theta constant: (sin(phi) sin(theta) psi-dot, cos(phi) sin(theta) psi-dot, "
              "phi-dot + cos(theta) psi-dot) (check 57)"),
    62: (NC, "the position of the disk's centre, read from the figure (L along X_1, then s along the disk's axis)"),
    70: (H_, "the derivative of the position with theta and L constant: (s cos(psi) sin(theta) psi-dot, "
              "s sin(psi) sin(theta) psi-dot, 0) (check 70)"),
    78: (H_, "(1/2) M v.v = (1/2) M s^2 sin(theta)^2 psi-dot^2 (check 78)"),
    83: (H_, "(1/2) omega_b^T I_b omega_b = (1/2) I_z (phi-dot + cos(theta) psi-dot)^2 + (1/2) I_x sin(theta)^2 "
              "psi-dot^2 (check 83)"),
    89: ("typo", "the sum of lines 78 and 83 has the spin term (1/2) I_z (phi-dot + cos(theta) psi-dot)^2; the display "
                 "drops its square (check 89)", T_RIGHT, HAND_1, HAND_2),
    94: (NC, "the position of the disk's centre from b, read from the figure"),
    102: (H_, "the same velocity as line 70, since L is constant (check 102)"),
    111: ("typo", "the kinetic energy from b is the same sum as in part (a), whose spin term is squared; the display "
                  "repeats line 89 without the square (check 111)", T_RIGHT, HAND_1, HAND_2),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
