"""Independent SymPy truth table for c4dynamics-rotmat-dcm321-docstrings.md.

The text's own setting: direction cosine matrices that turn a vector's components into those along
rotated axes (passive, frame rotations); a positive (right-hand) turn of the axes by a about x, y, z;
the 3-2-1 sequence turns first about z by psi (yaw), then about the new y by theta (pitch), then about
the new x by phi (roll, written varphi in the matrices), so the body-from-reference matrix is
R1(phi) R2(theta) R3(psi) and the reference-from-body matrix its transpose. Each single-axis matrix is
built here from the rotated axes' components (new axis . old components), never from the text.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero
c, s = sp.cos, sp.sin
ph, th, ps = sp.symbols("varphi theta psi", real=True)


def frame(axis, a):
    """Rows: the new axes after a right-hand turn of the frame by a about old axis 0, 1 or 2,
    in old components (a passive matrix: new components = rows . old components)."""
    E = sp.eye(3)
    K = sp.Matrix([[0, -E[2, axis], E[1, axis]], [E[2, axis], 0, -E[0, axis]],
                   [-E[1, axis], E[0, axis], 0]])
    active = E + s(a) * K + (1 - c(a)) * K * K       # Rodrigues: turns a vector by a about the axis
    return active.T                                  # the axes turn by a, components by -a


R1, R2, R3 = frame(0, ph), frame(1, th), frame(2, ps)
BR = R1 * R2 * R3

check(22, zero(sp.Matrix([[1, 0, 0], [0, c(ph), s(ph)], [0, -s(ph), c(ph)]]) - R1))
check(32, zero(sp.Matrix([[c(th), 0, -s(th)], [0, 1, 0], [s(th), 0, c(th)]]) - R2))
check(42, zero(sp.Matrix([[c(ps), s(ps), 0], [-s(ps), c(ps), 0], [0, 0, 1]]) - R3))
cf, sf, ct, st, cp, sp_ = c(ph), s(ph), c(th), s(th), c(ps), s(ps)
dcm321 = sp.Matrix([[ct * cp, ct * sp_, -st],
                    [sf * st * cp - cf * sp_, sf * st * sp_ + cf * cp, sf * ct],
                    [cf * st * cp + sf * sp_, cf * st * sp_ - sf * cp, cf * ct]])
check(57, zero(dcm321 - BR))
# lines 76, 80, 84: the example's attitude (values given, not claims)
euler_form = sp.Matrix([[ct * cp, ct * sp_, -st],
                        [sf * st * cp - cf * sp_, sf * st * sp_ - cf * cp, sf * ct],
                        [sf * st * sp_ + sf * sp_, sf * st * sp_ - sf * cp, cf * ct]])
check(94, zero(euler_form - BR))
check(121, zero(dcm321 - BR))
RB = sp.Matrix([[ct * cp, sf * st * cp - cf * sp_, cf * st * cp + sf * sp_],
                [ct * sp_, sf * st * sp_ + cf * cp, cf * st * sp_ - sf * cp],
                [-st, sf * ct, cf * ct]])
check(138, zero(RB - BR.T))

# the example: 150 along x, pitch 30 degrees: body components (150 cos 30, 0, 150 sin 30) = (129.9, 0, 75)
vb = BR.subs({ph: 0, th: sp.pi / 6, ps: 0}) * sp.Matrix([150, 0, 0])
assert zero(vb - sp.Matrix([75 * sp.sqrt(3), 0, 75]))
# the extraction the code uses recovers the angles from BR (away from 90 degrees of pitch)
vals = {ph: sp.Rational(3, 10), th: sp.Rational(-2, 5), ps: sp.Rational(7, 5)}
B = BR.subs(vals)
assert abs(float(sp.atan2(B[0, 1], B[0, 0]) - vals[ps])) < 1e-12
assert abs(float(-sp.asin(B[0, 2]) - vals[th])) < 1e-12
assert abs(float(sp.atan2(B[1, 2], B[2, 2]) - vals[ph])) < 1e-12
# at 90 degrees of pitch only psi - phi is left (the singularity the docstring names)
B90 = sp.simplify(BR.subs(th, sp.pi / 2))
assert zero(B90.subs({ph: ph + 1, ps: ps + 1}) - B90)

# negative controls
assert not zero(BR.T - BR)
assert not zero(R3.T - R3)

LINES = [22, 32, 42, 57, 76, 80, 84, 94, 121, 138]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
