"""Independent SymPy truth table for kindr-cheatsheet-zyx-euler-rates-quaternion-rotation-matrix.tex.

The sheet's convention: C_IB takes body coordinates to inertial ones, C_IB = C_BI^T; its elementary
matrices are the active turns (about z: rows (cos, -sin, 0), (sin, cos, 0), (0, 0, 1)); the ZYX
angles chi = (z, y, x) compose as C_IB = C_z(z) C_y(y) C_x(x); a Hamiltonian unit quaternion
q = (q_0, q) (scalar first) has the rotation matrix of the turn it performs; the angular velocity
of the body relative to the inertial frame is omega_I in inertial coordinates ([omega_I]x =
C-dot C^T) and omega_B = C^T omega_I in body coordinates. Each map is rebuilt here from C(t) with the
angles as functions of time, not from the sheet's matrices.
Run as a program it compares its verdicts with the table; ``--write`` writes the table.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Ry, Rz
from truth_table import zero

t = sp.symbols('t', real=True)
z, y, x = (sp.Function(n)(t) for n in ('z', 'y', 'x'))
zs, ys, xs = sp.symbols('z y x', real=True)
c, s = sp.cos, sp.sin

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


def hat(v):
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def unskew(M):
    return sp.Matrix([M[2, 1], M[0, 2], M[1, 0]])


def qmul(a, b):
    """Hamilton product, scalar first."""
    a0, av = a[0], sp.Matrix(a[1:])
    b0, bv = b[0], sp.Matrix(b[1:])
    return sp.Matrix([a0 * b0 - av.dot(bv), *(a0 * bv + b0 * av + av.cross(bv))])


# ---- the quaternion's rotation matrix: the matrix of v -> q v q* --------------------------------
q0, q1, q2, q3 = sp.symbols('q_0:4', real=True)
qv = sp.Matrix([q1, q2, q3])
Q = sp.Matrix([q0, q1, q2, q3])
Qc = sp.Matrix([q0, -q1, -q2, -q3])
C_q = sp.Matrix.hstack(*[sp.Matrix(qmul(qmul(Q, sp.Matrix([0, *e])), Qc)[1:])
                         for e in sp.eye(3).columnspace()])
unit = {q0: sp.sqrt(1 - q1**2 - q2**2 - q3**2)}
I3 = sp.eye(3)

# line 47: C_IB = 1 + 2 q0 qhat + 2 qhat^2 = (2 q0^2 - 1) 1 + 2 q0 qhat + 2 q q^T = the written matrix
M47 = sp.Matrix([[q0**2 + q1**2 - q2**2 - q3**2, 2*q1*q2 - 2*q0*q3, 2*q0*q2 + 2*q1*q3],
                 [2*q0*q3 + 2*q1*q2, q0**2 - q1**2 + q2**2 - q3**2, 2*q2*q3 - 2*q0*q1],
                 [2*q1*q3 - 2*q0*q2, 2*q0*q1 + 2*q2*q3, q0**2 - q1**2 - q2**2 + q3**2]])
ok = zero((I3 + 2 * q0 * hat(qv) + 2 * hat(qv)**2 - C_q).subs(unit))
ok &= zero(((2 * q0**2 - 1) * I3 + 2 * q0 * hat(qv) + 2 * qv * qv.T - C_q).subs(unit))
ok &= zero((M47 - C_q).subs(unit))
check(47, ok)

# line 56: C_IB^-1 = C_BI = 1 - 2 q0 qhat + 2 qhat^2 = the written matrix
M56 = sp.Matrix([[q0**2 + q1**2 - q2**2 - q3**2, 2*q0*q3 + 2*q1*q2, 2*q1*q3 - 2*q0*q2],
                 [2*q1*q2 - 2*q0*q3, q0**2 - q1**2 + q2**2 - q3**2, 2*q0*q1 + 2*q2*q3],
                 [2*q0*q2 + 2*q1*q3, 2*q2*q3 - 2*q0*q1, q0**2 - q1**2 - q2**2 + q3**2]])
Cinv = C_q.T
ok = zero((C_q * Cinv - I3).subs(unit))
ok &= zero((I3 - 2 * q0 * hat(qv) + 2 * hat(qv)**2 - Cinv).subs(unit))
ok &= zero((M56 - Cinv).subs(unit))
check(56, ok)

# ---- the ZYX maps, from C(t) ----------------------------------------------------------------------
C = Rz(z) * Ry(y) * Rx(x)
w_I = unskew(C.diff(t) * C.T)
w_B = C.T * w_I
rates = sp.Matrix([z.diff(t), y.diff(t), x.diff(t)])
E_true = w_I.jacobian(rates)                      # omega_I = E chi-dot (linear in the rates)
B_true = w_B.jacobian(rates)
assert zero(E_true * rates - w_I) and zero(B_true * rates - w_B)
plain = {z: zs, y: ys, x: xs}
E0, B0 = E_true.subs(plain), B_true.subs(plain)

# line 71: chi-dot = M omega_B, M the written matrix: M must be the inverse of the body map
M71 = sp.Matrix([[0, s(xs) / c(ys), c(xs) / c(ys)],
                 [0, c(xs), -s(xs)],
                 [1, s(xs) * s(ys) / c(ys), c(xs) * s(ys) / c(ys)]])
check(71, zero(M71 * B0 - I3))
# line 84: chi-dot = Ebar omega_I, the written matrix the inverse of the inertial map
M84 = sp.Matrix([[c(zs) * s(ys) / c(ys), s(ys) * s(zs) / c(ys), 1],
                 [-s(zs), c(zs), 0],
                 [c(zs) / c(ys), s(zs) / c(ys), 0]])
check(84, zero(M84 * E0 - I3))
# line 97: omega_B = written matrix chi-dot
M97 = sp.Matrix([[-s(ys), 0, 1], [c(ys) * s(xs), c(xs), 0], [c(xs) * c(ys), -s(xs), 0]])
check(97, zero(M97 - B0))
# line 107: omega_I = written matrix chi-dot
M107 = sp.Matrix([[0, -s(zs), c(ys) * c(zs)], [0, c(zs), c(ys) * s(zs)], [1, 0, -s(ys)]])
check(107, zero(M107 - E0))

# line 119: omega_I = E chi-dot, the definition of E
# line 127: the first axis, e_z = 1 (0, 0, 1) = (0, 0, 1)
ez = sp.Matrix([0, 0, 1])
check(127, zero(I3 * ez - ez))
# line 141: e_y' = C(z) (0, 1, 0) = written matrix times it = (-sin z, cos z, 0)
Cz_written = sp.Matrix([[c(zs), -s(zs), 0], [s(zs), c(zs), 0], [0, 0, 1]])
ey = Rz(zs) * sp.Matrix([0, 1, 0])
check(141, zero(Cz_written - Rz(zs)) and zero(Cz_written * sp.Matrix([0, 1, 0]) - ey)
      and zero(ey - sp.Matrix([-s(zs), c(zs), 0])))
# line 165: e_x'' = C(z) C(y) (1, 0, 0) = (as written) ... = (cos y cos z, cos y sin z, -sin z)
ex_true = Rz(zs) * Ry(ys) * sp.Matrix([1, 0, 0])
Cy_written = sp.Matrix([[c(ys), 0, s(ys)], [0, 1, 0], [-s(ys), 0, c(zs)]])
ex_written = sp.Matrix([c(ys) * c(zs), c(ys) * s(zs), -s(zs)])
check(165, zero(Cz_written * Cy_written * sp.Matrix([1, 0, 0]) - ex_written) and zero(ex_written - ex_true))
# line 194: E = [e_z e_y' e_x''] = the written matrix, the true axes as columns
M194 = sp.Matrix([[0, -s(zs), c(ys) * c(zs)], [0, c(zs), c(ys) * s(zs)], [1, 0, -s(ys)]])
check(194, zero(sp.Matrix.hstack(ez, ey, ex_true) - E0) and zero(M194 - E0))
# line 210: Ebar = E^-1 = the written matrix
M210 = sp.Matrix([[c(zs) * s(ys) / c(ys), s(ys) * s(zs) / c(ys), 1],
                  [-s(zs), c(zs), 0],
                  [c(zs) / c(ys), s(zs) / c(ys), 0]])
check(210, zero(M210 * E0 - I3))
# line 224: omega_B = C^T E chi-dot
check(224, zero(C.T * E_true * rates - w_B))
# line 228: chi-dot = Ebar C omega_B
check(228, zero(E_true.inv() * C * w_B - rates))

# negative controls: a sign or a column swapped is rejected
assert not zero(M107.T - E0)
assert not zero(M71 * E0 - I3)

LINES = [47, 56, 71, 84, 97, 107, 119, 127, 141, 165, 194, 210, 224, 228]

ROWS = {
    47: ("holds", "the matrix of v -> q v q* for a unit Hamilton quaternion, in its vector forms and written out (check 47)"),
    56: ("holds", "its inverse is its transpose, 1 - 2 q0 qhat + 2 qhat^2, written out (check 56)"),
    71: ("holds", "the written matrix is the inverse of the map from the ZYX rates to the body angular velocity (check 71)"),
    84: ("holds", "the written matrix is the inverse of the map from the ZYX rates to the inertial angular velocity (check 84)"),
    97: ("holds", "omega_B = C^T omega_I for C = C_z(z) C_y(y) C_x(x), linear in the rates with this matrix (check 97)"),
    107: ("holds", "omega_I from [omega_I]x = C-dot C^T, linear in the rates with this matrix (check 107)"),
    119: ("not a claim", "names E(chi), the map from the Euler rates to omega_I"),
    127: ("holds", "the identity times (0, 0, 1) (check 127)"),
    141: ("holds", "the turn about z applied to (0, 1, 0) gives (-sin z, cos z, 0) (check 141)"),
    165: ("typo", "the new x'' axis C_z(z) C_y(y) (1, 0, 0) is (cos y cos z, cos y sin z, -sin y); the display ends in -sin(z) (and writes cos(z) for the turn about y's last entry, which the product does not use) (check 165)",
         "\\begin{bmatrix}\n\\cos(y)\\cos(z) \\\\ \\cos(y)\\sin(z) \\\\ -\\sin(y)\n\\end{bmatrix} (and \\cos(y) for the last entry of the turn about y)",
         "algebra: the turn about y sends (1, 0, 0) to its first column (cos y, 0, -sin y), and the turn about z leaves the third entry alone, so the third entry is -sin y; the display's own next line, E's last column, has -sin(y)",
         "numbers: z = 0.5, y = 0.2: C_z C_y (1, 0, 0) = (0.8601, 0.4699, -0.1987), while the display's last column ends in -sin 0.5 = -0.4794; the vector (0.8601, 0.4699, -0.4794) is not even a unit vector (its length is 1.091)"),
    194: ("holds", "the three axes as columns give E, with the third column's last entry -sin(y) (check 194)"),
    210: ("holds", "the written matrix times E is the identity (det E = -cos y) (check 210)"),
    224: ("holds", "omega_B = C^T omega_I = C^T E chi-dot (check 224)"),
    228: ("holds", "inverting line 224: chi-dot = E^-1 C omega_B (check 228)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
