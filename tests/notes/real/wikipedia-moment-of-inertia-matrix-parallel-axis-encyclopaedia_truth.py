"""Independent SymPy truth table for wikipedia-moment-of-inertia-matrix-parallel-axis-encyclopaedia.md.

The article's convention: particles of masses m_i at r_i form a rigid system turning with angular
velocity omega; R is a reference point moving with velocity V_R, so v_i = omega x (r_i - R) + V_R;
[b] is the skew-symmetric matrix with [b] y = b x y; the inertia matrix about a point S is
[I_S] = -sum m_i [r_i - S][r_i - S]; R in the parallel-axis section is the centre of mass, M the
total mass and d = R - S. Everything is checked with symbolic positions, masses, omega, V_R and S
(three particles), so no formula of the text is assumed.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


def skew(b):
    """The matrix that takes the cross product with b, built from the cross product itself."""
    return sp.Matrix.hstack(*[b.cross(e) for e in (sp.eye(3)[:, k] for k in range(3))])


def vec(name):
    return sp.Matrix(sp.symbols(f'{name}x {name}y {name}z'))


N = 3
m = sp.symbols(f'm1:{N + 1}', positive=True)
r = [vec(f'r{k}') for k in range(1, N + 1)]
w, V, S, y, b = vec('w'), vec('V'), vec('S'), vec('y'), vec('b')
M = sum(m)
C = sum((mi * ri for mi, ri in zip(m, r)), sp.zeros(3, 1)) / M      # the centre of mass

# line 29: b x y = [b] y with [b] = [[0, -b_z, b_y], [b_z, 0, -b_x], [-b_y, b_x, 0]]
printed = sp.Matrix([[0, -b[2], b[1]], [b[2], 0, -b[0]], [-b[1], b[0], 0]])
check(29, truth_table.zero(skew(b) - printed) and truth_table.zero(b.cross(y) - printed * y))

# line 34: L = sum m dr x v = sum m dr x (omega x dr + V_R) = (-sum m dr x (dr x omega)) + (sum m dr x V_R),
# with the reference point at the centre of mass and v the rigid velocity field
dr = [ri - C for ri in r]
v = [w.cross(d) + V for d in dr]
L0 = sum((mi * d.cross(vi) for mi, d, vi in zip(m, dr, v)), sp.zeros(3, 1))
L1 = sum((mi * d.cross(w.cross(d) + V) for mi, d in zip(m, dr)), sp.zeros(3, 1))
L2 = (-sum((mi * d.cross(d.cross(w)) for mi, d in zip(m, dr)), sp.zeros(3, 1))
      + sum((mi * d.cross(V) for mi, d in zip(m, dr)), sp.zeros(3, 1)))
check(34, truth_table.zero(L0 - L1) and truth_table.zero(L1 - L2))
# and the V_R terms the prose after it drops do vanish about the centre of mass
assert truth_table.zero(sum((mi * d.cross(V) for mi, d in zip(m, dr)), sp.zeros(3, 1)))

# line 46: the inertia matrix about S, the article's definition (no check); it is the matrix of L about S
I_S = -sum((mi * skew(ri - S) * skew(ri - S) for mi, ri in zip(m, r)), sp.zeros(3, 3))
assert truth_table.zero(I_S * w - sum((mi * (ri - S).cross(w.cross(ri - S)) for mi, ri in zip(m, r)),
                                      sp.zeros(3, 1)))

# line 51: [r_i - S] y = (r_i - S) x y
check(51, all(truth_table.zero(skew(ri - S) * y - (ri - S).cross(y)) for ri in r))

# line 55: R = (R - S) + S = d + S, d the vector from S to the centre of mass
d = C - S
check(55, truth_table.zero(C - ((C - S) + S)) and truth_table.zero(C - (d + S)))

# line 60: [I_S] = -sum m [r_i - R + d][r_i - R + d]
I60 = -sum((mi * skew(ri - C + d) * skew(ri - C + d) for mi, ri in zip(m, r)), sp.zeros(3, 3))
check(60, truth_table.zero(I_S - I60))

# line 64: the expansion in four terms
A = sum((mi * skew(ri - C) for mi, ri in zip(m, r)), sp.zeros(3, 3))
I_R = -sum((mi * skew(ri - C) * skew(ri - C) for mi, ri in zip(m, r)), sp.zeros(3, 3))
I64 = I_R + (-A) * skew(d) + skew(d) * (-A) + (-M) * skew(d) * skew(d)
check(64, truth_table.zero(I_S - I64))

# line 69: sum m (r_i - R) = 0, the definition of the centre of mass (no check)

# line 74: [I_S] = [I_R] - M [d]^2
check(74, truth_table.zero(I_S - (I_R - M * skew(d) ** 2)))

LINES = [29, 34, 46, 51, 55, 60, 64, 69, 74]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
