"""Independent SymPy truth table for moore-learn-multibody-dynamics-angular-kinematics.md.

The text's own setting (Kane's notation): every vector is written by its components in a frame A
fixed for the derivation; a frame B is given by its direction cosine matrix C(t) = ^B C^A, whose
rows are B's unit vectors in A. The derivative in A of a vector is the derivative of its
A-components; the derivative in B is C^T d/dt (C u). The angular velocity of B in A is built from
its definition, omega = (b_y' . b_z) b_x + (b_z' . b_x) b_y + (b_x' . b_y) b_z with ' the
derivative in A, and the angular acceleration as its derivative in A. Frames are built by
successive turns (Rodrigues' formula) about axes fixed in the frame turned from, never from the
text's later displays.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero
t = sp.symbols("t", real=True)
# the angles as sample functions of time (generic: no special values, nonzero rates and accelerations)
psi, th, ph = sp.Rational(1, 3) + t, sp.Rational(2, 3) + t**2 / 5, sp.Rational(-1, 2) + 2 * t
E = sp.eye(3)


def turn(axis, angle):
    k = sp.Matrix(axis)
    K = sp.Matrix([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return E + sp.sin(angle) * K + (1 - sp.cos(angle)) * K * K


def turned(units, i, angle):
    """The frame ``units`` turned through ``angle`` about its own i-th unit vector: with R the matrix
    whose columns are ``units``, the turn about R e_i is R turn(e_i) R^T, so the new frame is R turn(e_i)."""
    R = sp.Matrix.hstack(*units) * turn(E[:, i], angle)
    return [R[:, j] for j in range(3)]


def d_in(units, u):
    """The derivative of u (A-components) taken in the frame whose unit vectors are ``units``."""
    C = sp.Matrix.vstack(*[v.T for v in units])
    return C.T * (C * u).diff(t)


def omega(units, seen=None):
    """The angular velocity, by its definition, of the frame ``units`` seen from ``seen`` (A by default)."""
    bx, by, bz = units
    d = [u.diff(t) if seen is None else d_in(seen, u) for u in units]
    return d[1].dot(bz) * bx + d[2].dot(bx) * by + d[0].dot(by) * bz


A = [E[:, i] for i in range(3)]
B = turned(turned(turned(A, 2, psi), 0, th), 2, ph)           # a z-x-z body fixed orientation
w = omega(B)


def at(expr):
    """``expr`` at t = 3/10 (after differentiating), as numbers."""
    return sp.Matrix(expr).xreplace({t: sp.Float("0.3", 40)}).evalf(40)


def near(m):
    """A matrix of numbers is zero to 20 digits."""
    return all(abs(x) < 1e-20 for x in sp.Matrix(m))


# 100, 106, 112: a vector fixed in B changes in A as omega x it; |omega| (omega_hat x b_x) is the same
check(100, all(near(at(B[i].diff(t) - w.cross(B[i]))) for i in range(3)))
wn = sp.sqrt(w.dot(w))
check(106, near(at(wn * ((w / wn).cross(B[0])) - B[0].diff(t))))
v = sp.Rational(7, 3)                                          # a constant measure number
check(112, near(at((v * B[0]).diff(t) - v * w.cross(B[0]))) and near(at(w.cross(v * B[0]) - v * w.cross(B[0]))))

# 128: u = u1 b_x + u2 b_y + u3 b_z with u_i(t): the product rule, then d^A u = d^B u + omega x u
us = [sp.cos(t) + 2, t**3 - t, sp.exp(t / 2)]                # generic measure numbers u_i(t)
u = sum((us[i] * B[i] for i in range(3)), sp.zeros(3, 1))
row1 = sum((us[i].diff(t) * B[i] + us[i] * B[i].diff(t) for i in range(3)), sp.zeros(3, 1))
row2 = d_in(B, u) + sum((us[i] * w.cross(B[i]) for i in range(3)), sp.zeros(3, 1))
row3 = d_in(B, u) + w.cross(u)
check(128, near(at(u.diff(t) - row1)) and near(at(u.diff(t) - row2)) and near(at(u.diff(t) - row3)))

# 149, 185: a y-x-y orientation by three simple turns: the simple angular velocities add to omega^{A D};
# the simple angular accelerations (each the derivative in its own first frame) do not add up to alpha^{A D}
Bf = turned(A, 1, psi)
Cf = turned(Bf, 0, th)
Df = turned(Cf, 1, ph)
parts_w = [omega(Bf), omega(Cf, Bf), omega(Df, Cf)]
w_AD = omega(Df)
check(149, near(at(w_AD - sum(parts_w, sp.zeros(3, 1)))))
parts_a = [parts_w[0].diff(t), d_in(Bf, parts_w[1]), d_in(Cf, parts_w[2])]
a_AD = w_AD.diff(t)
check(185, not near(at(a_AD - sum(parts_a, sp.zeros(3, 1)))))

# 171, 178: d^A omega = d^B omega + omega x omega, and so d^A omega = d^B omega
check(171, near(at(w.diff(t) - (d_in(B, w) + w.cross(w)))))
check(178, near(at(w.diff(t) - d_in(B, w))))

# the simple turn about z: omega = theta' b_z (the text's prose), as a sanity check of the definition
Bz = turned(A, 2, th)
assert near(at(omega(Bz) - th.diff(t) * Bz[2]))

# the exercise's data are a rotation matrix and a derivative consistent with it (C' C^T skew)
s2, s3, s6 = sp.sqrt(2), sp.sqrt(3), sp.sqrt(6)
Cx = sp.Matrix([[s2 / 4, s2 / 2, s6 / 4], [-s3 / 2, 0, sp.S(1) / 2], [s2 / 4, -s2 / 2, s6 / 4]])
Dx = sp.Matrix([[-s6 / 2 - 3 * s2 / 4, -s6 / 4 + 3 * s2 / 2, -3 * s6 / 4 + s2], [-1, -sp.S(1) / 2, -s3],
                [-s6 / 2 + 3 * s2 / 4, -s6 / 4 + 3 * s2 / 2, 3 * s6 / 4]])
assert zero(Cx * Cx.T - E) and zero(Dx * Cx.T + (Dx * Cx.T).T)

# negative controls: the checks can fail
assert not near(at(B[0].diff(t) + w.cross(B[0])))
assert not near(at(u.diff(t) - d_in(B, u)))
assert not near(at(a_AD - sum(parts_a, sp.zeros(3, 1))))

LINES = [26, 39, 50, 61, 86, 100, 106, 112, 122, 128, 149, 165, 171, 178, 185]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
