"""Independent SymPy truth table for physics-se-angular-velocity-skew-matrix-rdot-rt.md.

The answer's convention: R(t) a rotation matrix depending on time, p = R(t) p' a vector carried by
the rotation with p' fixed, S(omega) the matrix of the cross product with omega (S(omega) x =
omega x x), omega the angular velocity in space components. Any rotation stands for R(t): the
asker's product R_x(c) R_y(b) R_z(a) of yaw a, pitch b and roll c, each a function of time.
Run as a program it compares its verdicts with the table; ``--write`` writes the table.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Ry, Rz
from truth_table import zero

t = sp.symbols('t', real=True)
a, b, c = (sp.Function(n)(t) for n in ('a', 'b', 'c'))

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


def cross_matrix(v):
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


R = Rx(c) * Ry(b) * Rz(a)
Rd = R.diff(t)
S = sp.simplify(Rd * R.T)

# line 26: I = R R^T
check(26, zero(R * R.T - sp.eye(3)))
# line 30: 0 = d(R R^T)/dt = R-dot R^T + R (R^T)-dot = R-dot R^T + (R-dot R^T)^T
check(30, zero((R * R.T).diff(t))
      and zero((R * R.T).diff(t) - (Rd * R.T + R * R.T.diff(t)))
      and zero(R * R.T.diff(t) - (Rd * R.T).T)
      and zero(Rd * R.T + (Rd * R.T).T))
# line 34: S = R-dot R^T, a definition (its skew symmetry is line 29's last equality)
assert zero(S + S.T)
# line 38: R-dot = S R
check(38, zero(Rd - S * R))
# line 43: p-dot = R-dot p' = S R p' = S p
pp = sp.Matrix(sp.symbols('p_1:4', real=True))        # p', fixed
p = R * pp
check(43, zero(p.diff(t) - Rd * pp) and zero(Rd * pp - S * R * pp) and zero(S * R * pp - S * p))
# line 44: p-dot = omega x p = S(omega) p, omega the space angular velocity (the vector of S)
om = sp.Matrix([S[2, 1], S[0, 2], S[1, 0]])
check(44, zero(p.diff(t) - om.cross(p)) and zero(om.cross(p) - cross_matrix(om) * p))
# line 48: S(omega) = R-dot R^T
check(48, zero(cross_matrix(om) - S))

LINES = [26, 30, 34, 38, 43, 44, 48]

ROWS = {
    26: ("holds", "a rotation matrix is orthogonal (check 26)"),
    30: ("holds", "the product rule, (R^T)-dot = (R-dot)^T so R (R^T)-dot = (R-dot R^T)^T, and the derivative of the constant I vanishes (check 30)"),
    34: ("not a claim", "names S(t) = R-dot R^T; its skew symmetry is the previous display"),
    38: ("holds", "S R = R-dot R^T R = R-dot (check 38)"),
    43: ("holds", "p' is fixed, so p-dot = R-dot p' = S R p' = S p (check 43)"),
    44: ("holds", "a vector carried by the rotation moves as omega x p, and S(omega) p = omega x p (check 44)"),
    48: ("holds", "the cross-product matrix of the space angular velocity is R-dot R^T (check 48)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
