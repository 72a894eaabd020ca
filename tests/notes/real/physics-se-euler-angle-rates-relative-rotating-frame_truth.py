"""Independent SymPy truth table for physics-se-euler-angle-rates-relative-rotating-frame.md.

The question's convention: extrinsic x-y-z Euler angles, a turn phi about the fixed x axis, then
theta about the fixed y axis, then psi about the fixed z axis, so the orientation is
R = R_z(psi) R_y(theta) R_x(phi) (body components to those of the frame); omega_B is the body's
angular velocity in its own axes, read off R^T R' = [omega_B]_x. The rates of the angles follow by
solving that linear relation for (phi', theta', psi').
Run as a program it compares its verdicts with the table; ``--write`` writes the table.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Ry, Rz
from truth_table import zero

t = sp.symbols('t')
ph, th, ps = [sp.Function(n)(t) for n in ('phi', 'theta', 'psi')]

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


R = Rz(ps) * Ry(th) * Rx(ph)
S = sp.simplify(R.T * R.diff(t))
assert zero(S + S.T)
omega_B = sp.Matrix([S[2, 1], S[0, 2], S[1, 0]])

rates = sp.Matrix([ph.diff(t), th.diff(t), ps.diff(t)])
M = sp.Matrix([[1, sp.sin(ph) * sp.tan(th), sp.cos(ph) * sp.tan(th)],
               [0, sp.cos(ph), -sp.sin(ph)],
               [0, sp.sin(ph) / sp.cos(th), sp.cos(ph) / sp.cos(th)]])

# line 21: the rates are M(phi, theta) omega_B for a frame at rest
check(21, zero(M * omega_B - rates))

LINES = [17, 21]

ROWS = {
    17: ("not a claim", "the definition of the matrix M(phi, theta)"),
    21: ("holds", "for R = R_z(psi) R_y(theta) R_x(phi) and omega_B from R^T R', M omega_B = (phi', theta', psi'): the rates of extrinsic x-y-z angles relative to a frame at rest (the asker's own caveat, that it no longer holds when F turns, is about applying it with the gyro rate omega_B in place of the rate relative to F) (check 21)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
