"""Independent SymPy truth table for moore-learn-multibody-dynamics-orientation-dcm.md.

The text's own setting (Kane's notation): the unit vectors of N are the columns of the identity;
a frame A is given by its direction cosine matrix C = ^A C^N, whose i-th row holds the components
in N of the i-th unit vector of A (a = C n). A simple orientation of A through theta about an axis
shared with N turns N's unit vectors actively about that axis; a rotation matrix is built here from
Rodrigues' formula for a turn about a unit axis, never from the text's matrices. Every check is
built from these definitions.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero


def near(expr):
    """A matrix of numbers (no free symbols) is zero to 30 digits: for the sampled orientations."""
    return all(abs(sp.N(e, 30)) < 1e-20 for e in sp.Matrix(expr))
th, al, be, ga = sp.symbols("theta alpha beta gamma", real=True)
E = sp.eye(3)
n = [E[:, i] for i in range(3)]


def turn(axis, angle):
    """Active rotation of vectors through ``angle`` about the unit ``axis`` (Rodrigues)."""
    k = sp.Matrix(axis)
    K = sp.Matrix([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return E + sp.sin(angle) * K + (1 - sp.cos(angle)) * K * K


def dcm(units):
    """^A C^N from A's unit vectors written in N: its rows are those vectors."""
    return sp.Matrix.vstack(*[u.T for u in units])


def simple(i, angle):
    """A's unit vectors after turning N's through ``angle`` about N's i-th axis, and ^A C^N."""
    R = turn(n[i], angle)
    units = [R * v for v in n]
    return units, dcm(units)


# 22: a right-handed set: x cross y = z, y cross z = x, z cross x = y
check(22, n[0].cross(n[1]) == n[2] and n[1].cross(n[2]) == n[0] and n[2].cross(n[0]) == n[1])

# 36, 44: the simple turn about z: a_x = cos n_x + sin n_y, a_y = -sin n_x + cos n_y, a_z = n_z
az, Cz = simple(2, th)
rows36 = [sp.Matrix([sp.cos(th), sp.sin(th), 0]), sp.Matrix([-sp.sin(th), sp.cos(th), 0]), sp.Matrix([0, 0, 1])]
check(36, all(zero(u - w) for u, w in zip(az, rows36)))
M44 = sp.Matrix([[sp.cos(th), sp.sin(th), 0], [-sp.sin(th), sp.cos(th), 0], [0, 0, 1]])
check(44, zero(Cz - M44) and zero(dcm(az) - M44))

# 83, 101: n = C^{-1} a, and ^N C^A (rows: n in a) = C^{-1} = C^T
a_cols = Cz * E                               # a_i as a column of components: rows of C
check(83, zero(Cz.inv() * a_cols - E))
NCA = sp.Matrix.vstack(*[sp.Matrix([[v.dot(u) for u in az]]) for v in n])   # n_i . a_j
check(101, zero(NCA - Cz.inv()) and zero(Cz.inv() - Cz.T))

# 108, 118: simple turns about x and about y
_, Cx = simple(0, th)
_, Cy = simple(1, th)
check(108, zero(Cx - sp.Matrix([[1, 0, 0], [0, sp.cos(th), sp.sin(th)], [0, -sp.sin(th), sp.cos(th)]])))
check(118, zero(Cy - sp.Matrix([[sp.cos(th), 0, -sp.sin(th)], [0, 1, 0], [sp.sin(th), 0, sp.cos(th)]])))

# a general orientation: three successive turns about body axes (z, then new x, then new z)
sample = {al: sp.Rational(3, 10), be: sp.Rational(7, 10), ga: sp.Rational(-6, 5)}
R1 = turn(n[2], sample[al]).evalf(40)
R2 = (turn(R1 * n[0], sample[be]) * R1).evalf(40)
R3 = (turn(R2 * n[2], sample[ga]) * R2).evalf(40)
ag = [R3 * v for v in n]
Cg = dcm(ag)

# 132: a_i = sum_j cos(alpha_ij) n_j with alpha_ij the angle between a_i and n_j
ok132 = True
for i in range(3):
    angles = [sp.acos(ag[i].dot(n[j])) for j in range(3)]
    ok132 &= near(sum((sp.cos(angles[j]) * n[j] for j in range(3)), sp.zeros(3, 1)) - ag[i])
check(132, ok132)

# 140: rows 1, 2: a_i = sum (a_i . n_j) n_j; row 3 says a_x = sum (a_z . n_j) n_j, which is a_z
proj = [sum((ag[i].dot(n[j]) * n[j] for j in range(3)), sp.zeros(3, 1)) for i in range(3)]
rows12 = near(proj[0] - ag[0]) and near(proj[1] - ag[1])
row3_as_written = near(proj[2] - ag[0])
row3_corrected = near(proj[2] - ag[2])
check(140, rows12 and row3_as_written)
assert rows12 and row3_corrected and not row3_as_written

# 165: ^A C^N has the entries a_i . n_j
check(165, near(Cg - sp.Matrix(3, 3, lambda i, j: ag[i].dot(n[j]))))

# 217, 235: B turned from A about the shared z through alpha: b = ^B C^A a = ^B C^A ^A C^N n
bz = [turn(az[2], al) * u for u in az]
BCN = dcm(bz)
BCA = sp.Matrix(3, 3, lambda i, j: bz[i].dot(az[j]))
check(217, zero(BCN * E - BCA * Cz * E))
check(235, zero(BCN - BCA * Cz))

# 244: a chain of four frames A, B, C, Z with general relative turns: ^Z C^A = ^Z C^C ^C C^B ^B C^A
def frame_from(units, axis_index, angle):
    R = turn(units[axis_index], angle).evalf(40)
    return [(R * u).evalf(40) for u in units]


def rel(f, g):
    """^F C^G: the entries f_i . g_j."""
    return sp.Matrix(3, 3, lambda i, j: f[i].dot(g[j]))


fa = ag
fb = frame_from(fa, 0, sp.Rational(7, 10))
fc = frame_from(fb, 1, sp.Rational(-6, 5))
fz = frame_from(fc, 2, sp.Rational(2, 5))
check(244, near(rel(fz, fa) - rel(fz, fc) * rel(fc, fb) * rel(fb, fa)))

# 258: ^B C^N = ^B C^A ^A C^N, and ^A C^B = (^B C^N (^A C^N)^T)^T = ^A C^N (^B C^N)^T
ACB = rel(az, bz)
check(258, zero(BCN - BCA * Cz) and zero(ACB - (BCN * Cz.T).T) and zero(ACB - Cz * BCN.T))

# negative controls: the checks can fail
assert not zero(Cz - Cz.T)
assert not zero(BCN - Cz * BCA.T)
assert not zero(Cy - Cx)

LINES = [22, 36, 44, 65, 83, 101, 108, 118, 132, 140, 148, 165, 185, 200, 217, 235, 244, 258, 287, 294,
         308, 314]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
