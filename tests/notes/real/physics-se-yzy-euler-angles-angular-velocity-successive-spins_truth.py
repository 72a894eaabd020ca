"""Independent SymPy truth table for physics-se-yzy-euler-angles-angular-velocity-successive-spins.md.

The thread's convention: R_y, R_z and rot(n, theta) are active rotation matrices about fixed axes
(right-handed), the orientation of a Y-Z-Y sequence is the product R_y(a) R_z(b) R_y(c) of its
three rotations, the angle named first standing outermost, and the angular velocity is in space
components, the vector of the antisymmetric R-dot R^T. Each writer states the order of the angles:
the question and the first comment take roll, pitch, yaw (R_y(theta_r) R_z(theta_p) R_y(theta_y)),
the asker's reply and the answer take yaw outermost (R_y(theta_y) R_z(theta_p) R_y(theta_r)); a
display is judged against its writer's order, and the question's display against both orders.
The angles are functions of time.
Run as a program it compares its verdicts with the table; ``--write`` writes the table.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Ry, Rz
from truth_table import zero

t = sp.symbols('t', real=True)
tr, tp, ty = (sp.Function(n)(t) for n in ('theta_r', 'theta_p', 'theta_y'))
dr, dp, dy = tr.diff(t), tp.diff(t), ty.diff(t)

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


def omega(R):
    """The space angular velocity of the orientation R: the vector of R-dot R^T."""
    W = sp.simplify(R.diff(t) * R.T)
    assert zero(W + W.T)
    return sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])


yh, zh = sp.Matrix([0, 1, 0]), sp.Matrix([0, 0, 1])
om_rpy = omega(Ry(tr) * Rz(tp) * Ry(ty))        # roll outermost
om_ypr = omega(Ry(ty) * Rz(tp) * Ry(tr))        # yaw outermost

# line 19: the question's omega = rdot y + R_z(p)(pdot z + R_y(y)(ydot y)), against either order
q19 = dr * yh + Rz(tp) * (dp * zh + Ry(ty) * (dy * yh))
check(19, zero(q19 - om_rpy) or zero(q19 - om_ypr))
# line 28: the first comment's omega for roll outermost
check(28, zero(dr * yh + Ry(tr) * (dp * zh + Rz(tp) * (dy * yh)) - om_rpy))
# line 33: the asker's reply, yaw outermost
check(33, zero(dy * yh + Ry(ty) * (dp * zh + Rz(tp) * (dr * yh)) - om_ypr))
# line 37: components in a, b, c, d, defined only in an image the text does not keep: not a claim

# the answer: E_y = rot(j, y), E_p = E_y rot(k, p), E = E_p rot(j, r)
Ey = Ry(ty)
Ep = Ey * Rz(tp)
E = Ep * Ry(tr)
# line 48 (1): omega_y = ydot j is the angular velocity of E_y
check(48, zero(omega(Ey) - dy * yh))
# line 54 (2): omega_p = ydot j + pdot E_y k is the angular velocity of E_p = E_y rot(k, p)
check(54, zero(omega(Ep) - (dy * yh + dp * Ey * zh)))
# line 61 (3): omega = ydot j + pdot E_y k + rdot E_p j is the angular velocity of E
check(61, zero(omega(E) - (dy * yh + dp * Ey * zh + dr * Ep * yh)))
# line 67 (4): E is the product of the three rotations, omega the nested form
check(67, zero(E - Ry(ty) * Rz(tp) * Ry(tr))
      and zero(omega(E) - (dy * yh + Ry(ty) * (zh * dp + Rz(tp) * yh * dr))))
# line 74 (5): the Jacobian times (ydot, pdot, rdot)
J = sp.Matrix([[0, sp.sin(ty), -sp.sin(tp) * sp.cos(ty)],
               [1, 0, sp.cos(tp)],
               [0, sp.cos(ty), sp.sin(tp) * sp.sin(ty)]])
check(74, zero(omega(E) - J * sp.Matrix([dy, dp, dr])))

LINES = [19, 28, 33, 37, 48, 54, 61, 67, 74]

H19_1 = ("Take thetadot_r = thetadot_y = 0, thetadot_p = 1, theta_r = theta_y = pi/2, theta_p = 0: the "
         "question's display gives omega = R_z(0) z = z. With roll outermost the angular velocity is "
         "thetadot_p R_y(theta_r) z = R_y(pi/2) z = x; with yaw outermost it is thetadot_p R_y(theta_y) z = x too. "
         "Neither is z, so the display fails for both orders.")
H19_2 = ("Term by term: for any product R_y(a) R_z(b) R_y(c) the angular velocity is adot y + bdot R_y(a) z + "
         "cdot R_y(a) R_z(b) y. The display's middle term is pdot R_z(p) z = pdot z, with no R_y in front, and "
         "its last term is ydot R_z(p) R_y(y) y = ydot R_z(p) y: both need R_y(a) = I with a the outermost angle, "
         "which neither order gives; the matrices are shifted one place from where the method puts them.")

ROWS = {
    19: ("fails", "for either order of the three rotations the angular velocity is adot y + bdot R_y(a) z + cdot R_y(a) R_z(b) y with a the outermost angle; the question's display puts R_z(theta_p) where R_y of the outermost angle belongs and R_y(theta_y) where R_z(theta_p) does (check 19)",
         None, H19_1, H19_2),
    28: ("holds", "the vector of R-dot R^T for R = R_y(theta_r) R_z(theta_p) R_y(theta_y), roll outermost as the comment takes it (check 28)"),
    33: ("holds", "the vector of R-dot R^T for R = R_y(theta_y) R_z(theta_p) R_y(theta_r), the order the asker states (check 33)"),
    37: ("not a claim", "its coefficients a, b, c, d are defined only in the question's image, which the text does not keep"),
    48: ("holds", "E_y = rot(j, theta_y) is a definition; its angular velocity is thetadot_y j (check 48)"),
    54: ("holds", "the vector of E_p-dot E_p^T for E_p = rot(j, theta_y) rot(k, theta_p) (check 54)"),
    61: ("holds", "the vector of E-dot E^T for E = E_p rot(j, theta_r) (check 61)"),
    67: ("holds", "E is the product of (1)-(3), and the nested form is (3) with E_y, E_p written out (check 67)"),
    74: ("holds", "the Jacobian's columns are j, E_y k and E_p j (check 74)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
