"""Independent SymPy truth table for edinburgh-vectors-tensors-passive-active-rotations-euler-zyz.tex.

The text's own setting: a passive rotation changes the axes, l_ij = e'_i . e_j and a'_i = l_ij a_j;
L_z(alpha), L_x(beta), L_y(gamma) turn the axes counter-clockwise about one axis; the z-y-z Euler
angles compose L = L_z''(gamma) L_y'(beta) L_z(alpha). An active rotation turns a vector x by
vartheta about the unit axis n into y; the generators are (T_k)_ij = -i eps_ijk. Every check is
built here from these definitions (the primed axes drawn from the turn, the rotated vector from its
geometry, the exponential summed from its series), never from the text's later displays. Run with
--write to regenerate the table.
"""
import sys

import sympy as sp
from sympy import LeviCivita as eps

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero
al, be, ga, th, d = sp.symbols("alpha beta gamma vartheta delta", real=True)
c, s = sp.cos, sp.sin
E3 = sp.eye(3)
e = [E3[:, k] for k in range(3)]


def turned_axes(axis, t):
    """The primed axes after the axes turn counter-clockwise by t about the unprimed axis `axis`."""
    k = sp.Matrix([1 if i == axis else 0 for i in range(3)])
    K = sp.Matrix([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    turn = E3 + s(t) * K + (1 - c(t)) * K * K               # the active turn of a vector about k
    return [turn * ei for ei in e]


def passive(axis, t):
    """l_ij = e'_i . e_j for the axes turned by t about `axis`."""
    ep = turned_axes(axis, t)
    return sp.Matrix(3, 3, lambda i, j: ep[i].dot(e[j]))


Lz, Lx, Ly = (lambda t: passive(2, t)), (lambda t: passive(0, t)), (lambda t: passive(1, t))

# an orthogonal matrix with exact entries (Cayley's transform of a skew matrix) and an improper one
# (a reflection), and a general matrix
S = sp.Matrix([[0, -sp.Rational(1, 2), 1], [sp.Rational(1, 2), 0, -3], [-1, 3, 0]])
A = (E3 - S) * (E3 + S).inv()
Aimp = sp.diag(1, 1, -1) * A
G = sp.Matrix(3, 3, sp.symbols("g1:10", real=True))
x = sp.Matrix(sp.symbols("x1:4", real=True))
yv = sp.Matrix(sp.symbols("y1:4", real=True))

# 45: A^T A = A A^T = I, det A = +-1, A^T = A^-1 for orthogonal matrices (proper and improper)
check(45, all(zero(B.T * B - E3) and zero(B * B.T - E3) and sp.simplify(B.det()**2) == 1
              and zero(B.T - B.inv()) for B in (A, Aimp)))
# 47: (A A^T)_ij = A_ik A_jk = rows dotted = delta_ij
rows = [A[i, :] for i in range(3)]
check(47, zero(A * A.T - sp.Matrix(3, 3, lambda i, j: rows[i].dot(rows[j])))
      and zero(sp.Matrix(3, 3, lambda i, j: rows[i].dot(rows[j])) - E3))
# 55: det(G G^T) = det G det G^T = det G^2 for any matrix
check(55, sp.expand((G * G.T).det() - G.det() * G.T.det()) == 0 and sp.expand(G.T.det() - G.det()) == 0)
# 57: det(A A^T) = det I = 1
check(57, sp.simplify((A * A.T).det()) == 1 and E3.det() == 1)
# 59: [det A]^2 = 1 gives det A = +-1
D = sp.symbols("D", real=True)
check(59, set(sp.solve(D**2 - 1, D)) == {-1, 1})
# 61, 67: from A A^T = I, A^T = A^-1 and A^T A = I
check(61, zero(A.inv() * A * A.T - A.T) and zero(A.T - A.inv()))
check(67, zero(A.inv() * A * A.T * A * (A.T).inv() - A.inv() * E3 * (A.T).inv())
      and zero(A.inv() * (A.T).inv() - (A.T * A).inv()) and zero(A.T * A - E3))
assert zero(A.inv() * A * A.T * (A.T).inv() - A.inv() * E3 * (A.T).inv())      # without the extra A it holds
# 77: (G x) . (G y) = (G x)^T (G y) = x^T G^T G y
check(77, sp.expand((G * x).dot(G * yv) - (x.T * G.T * G * yv)[0]) == 0)

# 85, 90, 102, 141: a vector in the axes turned by the Euler rotation
a = sp.Matrix(sp.symbols("a1:4", real=True))
ep = [A[i, :].T for i in range(3)]                         # e'_i written in the unprimed basis
ap = sp.Matrix([ep[i].dot(a) for i in range(3)])           # a'_i = e'_i . a
check(85, zero(sum((ap[i] * ep[i] for i in range(3)), sp.zeros(3, 1)) - a))
l = sp.Matrix(3, 3, lambda i, j: ep[i].dot(e[j]))
check(90, zero(ap - l * a))
check(102, zero(ap - l * a))
check(141, all(zero(ep[i] - sum((l[i, j] * e[j] for j in range(3)), sp.zeros(3, 1))) for i in range(3)))
# 106: the cosines of the axes turned by alpha about z
epz = turned_axes(2, al)
check(106, sp.simplify(epz[0].dot(e[0]) - c(al)) == 0 and sp.simplify(epz[0].dot(e[1]) - c(sp.pi / 2 - al)) == 0
      and sp.simplify(c(sp.pi / 2 - al) - s(al)) == 0 and sp.simplify(epz[1].dot(e[0]) - c(sp.pi / 2 + al)) == 0
      and sp.simplify(c(sp.pi / 2 + al) + s(al)) == 0 and sp.simplify(epz[1].dot(e[1]) - c(al)) == 0)
# 113, 123: the single-axis rotation matrices
check(113, zero(Lz(al) - sp.Matrix([[c(al), s(al), 0], [-s(al), c(al), 0], [0, 0, 1]])))
check(123, zero(Lx(be) - sp.Matrix([[1, 0, 0], [0, c(be), s(be)], [0, -s(be), c(be)]]))
      and zero(Ly(ga) - sp.Matrix([[c(ga), 0, -s(ga)], [0, 1, 0], [s(ga), 0, c(ga)]])))
# 152: the z-y-z product multiplied out
text152 = sp.Matrix([[c(be) * c(al) * c(ga) - s(al) * s(ga), c(be) * s(al) * c(ga) + c(al) * s(ga), -s(be) * c(ga)],
                     [-c(be) * c(al) * s(ga) - s(al) * c(ga), -c(be) * s(al) * s(ga) + c(al) * c(ga), s(be) * s(ga)],
                     [s(be) * c(al), s(be) * s(al), c(be)]])
check(152, zero(Lz(ga) * Ly(be) * Lz(al) - text152))

# active rotation of x about the unit axis n by vartheta: the turn itself, built from the axis
n = sp.Matrix([sp.Rational(2, 7), sp.Rational(3, 7), sp.Rational(6, 7)])     # a unit axis
K = sp.Matrix([[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]])
Rot = E3 + s(th) * K + (1 - c(th)) * K * K                 # Rodrigues' turn, K x = n cross x
y_true = Rot * x
xn = x.dot(n)
# 183: y = OS + ST + TQ with SP = SQ = |n x x| (the distances compared squared)
perp = x - xn * n
nx = n.cross(x)
check(183, zero(y_true - (xn * n + c(th) * perp + s(th) * nx))
      and sp.simplify(perp.dot(perp) - nx.dot(nx)) == 0)
# 189: the vector form
check(189, zero(y_true - (x * c(th) + (1 - c(th)) * xn * n + nx * s(th))))
# 191: the index form with eps_ikj n_k x_j
yi = sp.Matrix([x[i] * c(th) + (1 - c(th)) * xn * n[i]
                + sum(eps(i, k, j) * n[k] * x[j] for k in range(3) for j in range(3)) * s(th) for i in range(3)])
check(191, zero(y_true - yi))
# 195, 197: R_ij = delta_ij cos + (1 - cos) n_i n_j - eps_ijk n_k sin
Rij = sp.Matrix(3, 3, lambda i, j: E3[i, j] * c(th) + (1 - c(th)) * n[i] * n[j]
                - sum(eps(i, j, k) * n[k] for k in range(3)) * s(th))
check(195, zero(Rij - Rot))
check(197, zero(Rij - Rot))
# 193: y_i = R_ij(vartheta, n) = x_j equates y to R and R to x; y_i = R_ij x_j is what holds
check(193, zero(Rij - sp.ones(3, 1) * x.T))
assert zero(y_true - Rij * x)
# 201, 203, 205, 212, 219: the trace and the axis read back
tr = Rot.trace()
axis = sp.Matrix([-sp.Rational(1, 2) * sum(eps(i, j, k) * Rot[i, j] for i in range(3) for j in range(3))
                  for k in range(3)])
check(201, sp.simplify(tr - (1 + 2 * c(th))) == 0 and zero(axis - n * s(th)))
check(203, sp.simplify(sum(E3[i, j] * Rot[i, j] for i in range(3) for j in range(3)) - tr) == 0)
check(205, sp.simplify(3 * c(th) + (1 - c(th)) * n.dot(n) - (1 + 2 * c(th))) == 0
      and sp.simplify(sum(E3[i, j] * Rij[i, j] for i in range(3) for j in range(3)) - (3 * c(th) + 1 - c(th))) == 0)
check(212, zero(sp.Matrix([sum(eps(i, j, k) * Rij[i, j] for i in range(3) for j in range(3)) for k in range(3)])
               + 2 * n * s(th))
      and all(sum(eps(i, j, k) * eps(i, j, m) for i in range(3) for j in range(3)) == 2 * E3[m, k]
              for k in range(3) for m in range(3)))
check(219, zero(axis - n * s(th)))
# 224: the expansions of sine and cosine
check(224, sp.simplify(sp.series(s(d), d, 0, 3).removeO() - d) == 0
      and sp.simplify(sp.series(c(d), d, 0, 2).removeO() - 1) == 0)
# 226, 228, 230: the rotation to first order in delta
Rd = Rij.subs(th, d)
R1st = sp.Matrix(3, 3, lambda i, j: sp.series(Rd[i, j], d, 0, 2).removeO())
Rinf = sp.Matrix(3, 3, lambda i, j: E3[i, j] - sum(eps(i, j, k) * n[k] for k in range(3)) * d)
check(226, zero(R1st - Rinf))
check(228, zero(Rinf * x - (x + sp.Matrix([sum(eps(i, k, j) * n[k] * x[j] for k in range(3) for j in range(3))
                                           for i in range(3)]) * d)))
check(230, zero(Rinf * x - (x + nx * d)))
# 233, 235, 257: the generators (T_k)_ij = -i eps_ijk
T = [sp.Matrix(3, 3, lambda i, j, k=k: -sp.I * eps(i, j, k)) for k in range(3)]
check(233, zero(Rinf - (E3 - sp.I * sum((n[k] * T[k] for k in range(3)), sp.zeros(3, 3)) * d)))
check(235, zero(T[0] - sp.I * sp.Matrix([[0, 0, 0], [0, 0, -1], [0, 1, 0]]))
      and zero(T[1] - sp.I * sp.Matrix([[0, 0, 1], [0, 0, 0], [-1, 0, 0]]))
      and zero(T[2] - sp.I * sp.Matrix([[0, -1, 0], [1, 0, 0], [0, 0, 0]])))
nT = sum((n[k] * T[k] for k in range(3)), sp.zeros(3, 3))
check(257, zero(Rinf - (E3 - sp.I * d * nT)))
# 268, 270: the commutators
com = lambda P, Q: P * Q - Q * P                          # noqa: E731
check(268, all(zero(com(T[i], T[j]) - sp.I * sum((eps(i, j, k) * T[k] for k in range(3)), sp.zeros(3, 3)))
               for i in range(3) for j in range(3)))
check(270, zero(com(T[0] + 2 * T[1], T[2]) - (com(T[0], T[2]) + 2 * com(T[1], T[2])))
      and zero(com(T[0], T[2]) + 2 * com(T[1], T[2]) - (-sp.I * T[1] + 2 * sp.I * T[0])))
# 272: the finite rotation as the exponential of -i vartheta n.T (about the third axis, summed exactly)
Rz = sp.Matrix(3, 3, lambda i, j: E3[i, j] * c(th) + (1 - c(th)) * E3[i, 2] * E3[j, 2] - eps(i, j, 2) * s(th))
check(272, zero(sp.simplify((-sp.I * th * T[2]).exp()) - Rz))
N = sp.symbols("N", positive=True, integer=True)
# 278: (1 + x/N)^N tends to e^x
xs = sp.symbols("xs", real=True)
check(278, sp.simplify(sp.limit((1 + xs / N)**N, N, sp.oo) - sp.exp(xs)) == 0)

ROWS = {
    43: ("not a claim", "the definition of an orthogonal matrix: its rows are orthonormal"),
    45: ("holds", "A^T A = A A^T = I, det A = +-1 and A^T = A^-1 for a proper and an improper orthogonal matrix (check 45)"),
    47: ("holds", "(A A^T)_ij = A_ik A_jk is the dot product of rows i and j, delta_ij for orthonormal rows (check 47)"),
    55: ("holds", "det of a product and of a transpose, for a general matrix (check 55)"),
    57: ("holds", "A A^T = I has determinant 1 (check 57)"),
    59: ("holds", "D^2 = 1 has the roots +-1 (check 59)"),
    61: ("holds", "multiplying A A^T = I by A^-1 on the left gives A^T = A^-1 (check 61)"),
    67: ("typo", "multiplying A A^T = I by A^-1 on the left and (A^T)^-1 on the right leaves A^-1 A A^T (A^T)^-1 = I; "
                 "the second line's left side carries an extra A, A^-1 A A^T A (A^T)^-1 = A for an orthogonal A, not "
                 "I = A^-1 (A^T)^-1 (check 67); the lines after it hold",
          r"A^{-1}AA\trans(A\trans)^{-1} &= A^{-1}I(A\trans)^{-1}",
          "A^-1 (A A^T) A (A^T)^-1 with A A^T = I is A^-1 A (A^T)^-1 = (A^T)^-1 = A (A orthogonal), while the right side "
          "A^-1 I (A^T)^-1 = (A^T A)^-1 = I; the two sides differ unless A = I.",
          "The next line of the chain is I = A^-1 (A^T)^-1, which needs the left side to collapse to I: A^-1 A A^T "
          "(A^T)^-1 = I I = I does, A^-1 A A^T A (A^T)^-1 does not (for A = L_z(alpha) it is L_z(alpha))."),
    77: ("holds", "(G x).(G y) = x^T G^T G y for any matrix (check 77)"),
    81: ("not a claim", "the notation for the orthogonal group"),
    85: ("holds", "a vector is the sum of its components times the basis vectors in either basis (check 85)"),
    90: ("holds", "a'_i = e'_i . (a_j e_j) = l_ij a_j (check 90)"),
    92: ("not a claim", "the definition of the transformation matrix L = (e'_i . e_j)"),
    102: ("holds", "the components' rule a'_i = l_ij a_j (check 102)"),
    106: ("holds", "the primed axes turned by alpha about z and the cosines of pi/2 -+ alpha (check 106)"),
    113: ("holds", "l_ij = e'_i . e_j for the axes turned by alpha about z (check 113)"),
    123: ("holds", "the same for beta about x and gamma about y (check 123)"),
    141: ("holds", "e'_i = l_ij e_j, the rows of L being the primed axes (check 141)"),
    146: ("not a claim", "the notation for the special orthogonal group"),
    152: ("holds", "the z-y-z product L_z(gamma) L_y(beta) L_z(alpha) multiplied out (check 152)"),
    183: ("holds", "the rotated vector from its geometry, with SP = SQ = |n x x| (check 183)"),
    189: ("holds", "the rotation formula (check 189)"),
    191: ("holds", "its index form, (n x x)_i = eps_ikj n_k x_j (check 191)"),
    193: ("typo", "y_i = R_ij x_j, the matrix acting on x; the second '=' sets R_ij equal to x_j and y_i equal to R_ij "
                  "(check 193)",
          r"y_i = R_{ij}(\vartheta, \vh{n}) x_j",
          "The line before gives y_i = x_i cos + (1 - cos) n_j x_j n_i + eps_ikj n_k x_j sin, linear in x; it is "
          "R_ij x_j with R_ij = delta_ij cos + (1 - cos) n_i n_j - eps_ijk n_k sin, so the x_j multiplies R_ij rather "
          "than being equal to it.",
          "As written the chain says R_ij(vartheta, n) = x_j: the left side is a matrix fixed by the angle and the axis, "
          "the right a component of the vector being turned, and y_i = x_j would make every component of y the same "
          "number; for vartheta = 0, R_ij = delta_ij, which is not x_j."),
    195: ("holds", "R_ij = delta_ij cos + (1 - cos) n_i n_j - eps_ijk n_k sin is Rodrigues' turn (check 195)"),
    197: ("holds", "the same matrix stated as the definition (check 197)"),
    201: ("holds", "Tr R = 1 + 2 cos and -(1/2) eps_ijk R_ij = n_k sin (check 201)"),
    203: ("holds", "delta_ij R_ij = R_ii = Tr R (check 203)"),
    205: ("holds", "the contraction: 3 cos + (1 - cos) n.n = 1 + 2 cos (check 205)"),
    212: ("holds", "eps_ijk R_ij = -eps_ijk eps_ijl n_l sin = -2 n_k sin (check 212)"),
    219: ("holds", "rearranged (check 219)"),
    224: ("holds", "the Taylor series of sine and cosine (check 224)"),
    226: ("holds", "R_ij to first order in delta vartheta (check 226)"),
    228: ("holds", "y_i = x_i + eps_ikj n_k x_j delta vartheta (check 228)"),
    230: ("holds", "y = x + (n x x) delta vartheta (check 230)"),
    233: ("holds", "-i n_k (T_k)_ij = -n_k eps_ijk (check 233)"),
    235: ("holds", "the matrices (T_k)_ij = -i eps_ijk written out (check 235)"),
    257: ("holds", "R = I - i delta vartheta n.T to first order (check 257)"),
    259: ("not a claim", "the definition of n.T as n_1 T_1 + n_2 T_2 + n_3 T_3"),
    262: ("not a claim", "the commutator's domain and range"),
    264: ("not a claim", "the definition of the commutator"),
    268: ("holds", "[T_i, T_j] = i eps_ijk T_k for all i, j (check 268)"),
    270: ("holds", "[T_1, T_3] = -i T_2 and [T_2, T_3] = i T_1 (check 270)"),
    272: ("holds", "the limit of N turns by vartheta/N is exp(-i vartheta n.T), Rodrigues' turn (check 272, about the "
                  "third axis)"),
    278: ("holds", "the limit defining e^x (check 278)"),
    280: ("not a claim", "the power series by which the notes define a function of a matrix"),
}

LINES = sorted(ROWS)


if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
