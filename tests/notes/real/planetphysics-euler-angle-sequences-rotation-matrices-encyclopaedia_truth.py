"""Independent SymPy truth table for planetphysics-euler-angle-sequences-rotation-matrices-encyclopaedia.tex.

Names as the entries': R_i(a) turns the frame about axis i by the angle a (a passive rotation, the
matrix that takes a vector's components in the old frame to those in the turned frame), so
R_3(a) = [[c, s, 0], [-s, c, 0], [0, 0, 1]], R_2(a) = [[c, 0, -s], [0, 1, 0], [s, 0, c]],
R_1(a) = [[1, 0, 0], [0, c, s], [0, -s, c]]; the passive matrix about an axis is built here as the
transpose of the turn of a vector about it (Rodrigues' formula), never copied from the entries.
c and s with an angle below are its cosine and sine. Each entry's sequence R_ijk(phi, theta, psi)
= R_k(psi) R_j(theta) R_i(phi) is its definition; the products the entries print are checked
entry by entry against the product of the true elementary matrices.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


def zero(e):
    return truth_table.zero(e)


phi, th, psi = sp.symbols('phi theta psi', real=True)
c, s = sp.cos, sp.sin


def passive(axis, a):
    """The frame turned about the unit axis by a: the transpose of the active turn of a vector."""
    n = sp.Matrix(sp.eye(3)[:, axis - 1])
    K = sp.Matrix([[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]])
    active = sp.eye(3) + sp.sin(a) * K + (1 - sp.cos(a)) * K * K
    return active.T


R = {i: (lambda a, i=i: passive(i, a)) for i in (1, 2, 3)}
# the printed elementary matrices, as the entries write them
P1 = lambda a: sp.Matrix([[1, 0, 0], [0, c(a), s(a)], [0, -s(a), c(a)]])   # noqa: E731
P2 = lambda a: sp.Matrix([[c(a), 0, -s(a)], [0, 1, 0], [s(a), 0, c(a)]])   # noqa: E731
P3 = lambda a: sp.Matrix([[c(a), s(a), 0], [-s(a), c(a), 0], [0, 0, 1]])   # noqa: E731
PRINTED = {1: P1, 2: P2, 3: P3}

# the elementary matrices each entry lists: line -> (axis, angle)
ELEMENTARY = {35: (1, phi), 43: (2, th), 51: (3, psi),
              85: (3, psi), 93: (1, th), 101: (2, phi),
              135: (1, phi), 143: (2, th), 151: (3, psi),
              183: (1, psi), 191: (3, th), 199: (1, phi),
              230: (1, psi), 238: (3, th), 246: (2, phi),
              279: (3, psi), 287: (2, th), 295: (3, phi)}
for line, (axis, a) in ELEMENTARY.items():
    check(line, zero(PRINTED[axis](a) - R[axis](a)))

# the products of the first two factors: line -> (left axis, left angle, right axis, right angle,
# the printed result)
cp, sp_, ct, st = c(phi), s(phi), c(th), s(th)
PRODUCTS = {
    61: (2, th, 1, phi, sp.Matrix([[ct, st * sp_, -st * cp], [0, cp, sp_], [st, -ct * sp_, ct * cp]])),
    111: (1, th, 2, phi, sp.Matrix([[cp, 0, -sp_], [st * sp_, ct, st * cp], [ct * sp_, -st, ct * cp]])),
    161: (1, th, 3, phi, sp.Matrix([[cp, sp_, 0], [-sp_ * ct, ct * cp, st], [st * sp_, -st * cp, ct]])),
    209: (3, th, 1, phi, sp.Matrix([[ct, st * cp, st * sp_], [-st, ct * cp, ct * sp_], [0, -sp_, cp]])),
    256: (3, th, 2, phi, sp.Matrix([[ct * cp, st, -ct * sp_], [-st * cp, ct, st * sp_], [sp_, 0, cp]])),
    305: (2, th, 3, phi, sp.Matrix([[ct * cp, ct * sp_, st], [-sp_, cp, 0], [-st * cp, -st * sp_, ct]])),
}
for line, (i, a, j, b, printed) in PRODUCTS.items():
    # the middle member (the two printed factors) and the result, both against the true product
    true = R[i](a) * R[j](b)
    check(line, zero(PRINTED[i](a) * PRINTED[j](b) - true) and zero(printed - true))

# the 3-2-3 product as it should read: the signs of s_theta in its (1,3), (3,1), (3,2) entries flip
right303 = sp.Matrix([[ct * cp, ct * sp_, -st], [-sp_, cp, 0], [st * cp, st * sp_, ct]])
assert zero(right303 - R[2](th) * R[3](phi))

DEFINITIONS = [31, 81, 130, 179, 226, 275]
LINES = sorted(DEFINITIONS + list(ELEMENTARY) + list(PRODUCTS))

AXIS = {1: "axis 1", 2: "axis 2", 3: "axis 3"}
ROWS = {}
for line in DEFINITIONS:
    ROWS[line] = ("not a claim", "the entry's definition of its sequence: the rotation matrix it names is the product of the three elementary frame rotations in that order")
for line, (axis, a) in ELEMENTARY.items():
    ROWS[line] = ("holds", f"the frame rotation about {AXIS[axis]} by {a}, the transpose of the turn of a vector about that axis (check {line})")
for line, (i, a, j, b, _) in PRODUCTS.items():
    ROWS[line] = ("holds", f"R_{i}({a}) R_{j}({b}) multiplied out, entry by entry, both the printed factors and the printed result (check {line})")
ROWS[305] = ("fails",
             "R_2(theta) R_3(phi) has first row (c_theta c_phi, c_theta s_phi, -s_theta) and third row (s_theta c_phi, s_theta s_phi, c_theta); the printed result has +s_theta, -s_theta c_phi and -s_theta s_phi there, the product with R_2(theta) transposed, though the printed left factor is R_2(theta) itself (check 305)",
             None,
             "by hand: the first row of R_2(theta) is (c_theta, 0, -s_theta); times the third column of R_3(phi), (0, 0, 1), it gives -s_theta, not the printed s_theta; the third row (s_theta, 0, c_theta) times the first column (c_phi, -s_phi, 0) gives s_theta c_phi, not -s_theta c_phi",
             "by hand at a point: theta = pi/2, phi = 0 makes R_3(phi) the identity, so the product must equal R_2(pi/2) = [[0, 0, -1], [0, 1, 0], [1, 0, 0]], but the printed result gives [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]")

if __name__ == "__main__":
    if sys.argv[1:] == ["--write"]:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
