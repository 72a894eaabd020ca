"""Independent SymPy truth table for cline-parallel-axis-theorem-cube-inertia-tensor-worked-examples.md.

Names as the text's: I_ij is the inertia tensor about the centre of mass O (its equation 13.4.1,
I_ij = sum_a m_a [delta_ij sum_k x_ak^2 - x_ai x_aj]), J_ij the tensor about a point Q whose axes
are parallel, a the vector from Q to O, so that a mass at r from O is at R = a + r from Q. The
general steps are checked on three point masses with symbolic coordinates placed about their own
centre of mass (the third mass's coordinates are fixed by that); the cube's integrals are done
exactly. Run as a program, the script compares its verdicts with the table; with --write it writes
the table from ROWS.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


def zero(e):
    return truth_table.zero(e)


# three masses about their centre of mass: sum_a m_a r_a = 0
m = sp.symbols('m1:4', positive=True)
x = [[sp.Symbol(f'x{a}{k}', real=True) for k in range(1, 4)] for a in range(1, 3)]
x.append([-(m[0] * x[0][k] + m[1] * x[1][k]) / m[2] for k in range(3)])
a = sp.symbols('a1:4', real=True)
M = sum(m)
d = lambda i, j: 1 if i == j else 0


def tensor(pts):
    return sp.Matrix(3, 3, lambda i, j: sum(m[al] * (d(i, j) * sum(c ** 2 for c in pts[al]) - pts[al][i] * pts[al][j])
                                            for al in range(3)))


I = tensor(x)
X = [[a[k] + x[al][k] for k in range(3)] for al in range(3)]     # X_i = a_i + x_i
J = tensor(X)

# line 33: the expansion. Its second line is right; its first writes a_i where a_k and a_j belong
second = sp.Matrix(3, 3, lambda i, j: I[i, j] + sum(m[al] * (d(i, j) * sum(2 * x[al][k] * a[k] + a[k] ** 2 for k in range(3))
                                                             - (a[i] * x[al][j] + a[j] * x[al][i] + a[i] * a[j])) for al in range(3)))
first = sp.Matrix(3, 3, lambda i, j: sum(m[al] * (d(i, j) * sum((x[al][k] + a[i]) ** 2 for k in range(3))
                                                  - (x[al][i] + a[i]) * (x[al][j] + a[i])) for al in range(3)))
check(33, zero(second - J) and zero(first - J))
assert zero(second - J) and not zero(first - J)

# line 45: regrouped (before the centre-of-mass sums are used)
grouped = sp.Matrix(3, 3, lambda i, j: I[i, j] + sum(m[al] * (d(i, j) * sum(c ** 2 for c in a) - a[i] * a[j]) for al in range(3))
                    + sum(m[al] * (2 * d(i, j) * sum(x[al][k] * a[k] for k in range(3)) - a[i] * x[al][j] - a[j] * x[al][i])
                          for al in range(3)))
check(45, zero(grouped - J))
# lines 51, 57: the centre-of-mass condition (the text's definition of O), no claim
# lines 63, 69: the parallel-axis theorem
steiner = sp.Matrix(3, 3, lambda i, j: I[i, j] + M * (sum(c ** 2 for c in a) * d(i, j) - a[i] * a[j]))
check(63, zero(steiner - J))
check(69, zero(steiner - J))
# line 75: J_11 with a_3^3 where a_3^2 belongs; its right end is right
printed75 = I[0, 0] + M * ((a[0] ** 2 + a[1] ** 2 + a[2] ** 3) - a[0] ** 2)
check(75, zero(printed75 - J[0, 0]) and zero(I[0, 0] + M * (a[1] ** 2 + a[2] ** 2) - J[0, 0]))
assert zero(I[0, 0] + M * (a[1] ** 2 + a[2] ** 2) - J[0, 0])

# the cube: side b, density rho, M = rho b^3
b, rho = sp.symbols('b rho', positive=True)
x1, x2, x3 = sp.symbols('x_1 x_2 x_3', real=True)
Mc = rho * b ** 3


def integral(f, lo, hi):
    return sp.integrate(f, (x3, lo, hi), (x2, lo, hi), (x1, lo, hi))


# line 86: the definition in integral form, no claim
Icm11 = integral(x2 ** 2 + x3 ** 2, -b / 2, b / 2) * rho
check(92, zero(Icm11 - rho * b ** 5 / 6) and zero(Icm11 - Mc * b ** 2 / 6))
check(98, zero(-rho * integral(x1 * x2, -b / 2, b / 2)))
Icm = sp.Matrix(3, 3, lambda i, j: rho * integral(d(i, j) * (x1 ** 2 + x2 ** 2 + x3 ** 2) - [x1, x2, x3][i] * [x1, x2, x3][j], -b / 2, b / 2))
check(104, zero(Icm - Mc * b ** 2 / 6 * sp.eye(3)))

# corner
Ico = sp.Matrix(3, 3, lambda i, j: rho * integral(d(i, j) * (x1 ** 2 + x2 ** 2 + x3 ** 2) - [x1, x2, x3][i] * [x1, x2, x3][j], 0, b))
check(118, zero(Ico[0, 0] - 2 * rho * b ** 5 / 3) and zero(Ico[0, 0] - 2 * Mc * b ** 2 / 3))
# line 122: rho times the integral of x1 x2 is +b^5/4 rho; the product of inertia is minus that
raw = rho * integral(x1 * x2, 0, b)
check(122, zero(raw - (-rho * b ** 5 / 4)) and zero(Ico[0, 1] + Mc * b ** 2 / 4))
assert zero(raw - rho * b ** 5 / 4) and zero(Ico[0, 1] + Mc * b ** 2 / 4)
check(128, zero(Ico - Mc * b ** 2 / 12 * sp.Matrix([[8, -3, -3], [-3, 8, -3], [-3, -3, 8]])))
# line 136: a_i = b/2, the geometry of the corner (no claim)
ac = [b / 2] * 3
Jc = Icm + Mc * (sum(c ** 2 for c in ac) * sp.eye(3) - sp.Matrix(3, 3, lambda i, j: ac[i] * ac[j]))
check(142, zero(Jc[0, 0] - 2 * Mc * b ** 2 / 3) and zero(Icm[0, 0] + Mc * (ac[1] ** 2 + ac[2] ** 2) - Jc[0, 0])
      and zero(Mc * (ac[1] ** 2 + ac[2] ** 2) - Mc * b ** 2 / 2))
check(148, zero(Jc[0, 1] + Mc * b ** 2 / 4) and zero(Icm[0, 1] - Mc * ac[0] * ac[1] - Jc[0, 1]))
check(154, zero(Jc - Ico) and zero(Jc - Mc * b ** 2 / 12 * sp.Matrix([[8, -3, -3], [-3, 8, -3], [-3, -3, 8]])))

# the secular determinant
Iv = sp.Symbol('I')
A = Ico - Iv * sp.eye(3)
# line 164: the secular equation itself, no claim
# line 170: row 2 minus row 1 gives (I - 11/12 M b^2, 11/12 M b^2 - I, 0); the display drops the I
B = A.copy()
B[1, :] = A[1, :] - A[0, :]
printed = A.copy()
printed[1, :] = sp.Matrix([[-sp.Rational(11, 12) * Mc * b ** 2, sp.Rational(11, 12) * Mc * b ** 2 - Iv, 0]])
check(170, zero(printed - B))
assert zero(B.det() - A.det()) and not zero(printed.det() - A.det())
check(176, zero(sp.factor(A.det()) - (Mc * b ** 2 / 6 - Iv) * (sp.Rational(11, 12) * Mc * b ** 2 - Iv) ** 2))
ev = Ico.eigenvals()
check(182, ev == {Mc * b ** 2 / 6: 1, sp.Rational(11, 12) * Mc * b ** 2: 2})
w = sp.symbols('omega_1:4')
wv = sp.Matrix(w)
check(188, zero(Ico - Mc * b ** 2 / 6 * sp.eye(3) - Mc * b ** 2 / 12 * sp.Matrix([[6, -3, -3], [-3, 6, -3], [-3, -3, 6]])))
rows1 = (Ico - Mc * b ** 2 / 6 * sp.eye(3)) * wv / (Mc * b ** 2 / 4)
check(194, zero(rows1 - sp.Matrix([2 * w[0] - w[1] - w[2], -w[0] + 2 * w[1] - w[2], -w[0] - w[1] + 2 * w[2]])))
check(200, zero(Ico - sp.Rational(11, 12) * Mc * b ** 2 * sp.eye(3) - Mc * b ** 2 / 12 * sp.Matrix(3, 3, lambda i, j: -3)))
rows2 = (Ico - sp.Rational(11, 12) * Mc * b ** 2 * sp.eye(3)) * wv / (-Mc * b ** 2 / 4)
check(206, all(zero(r - (w[0] + w[1] + w[2])) for r in rows2))
e1 = sp.Matrix([1, 1, 1]) / sp.sqrt(3)
assert zero((Ico - Mc * b ** 2 / 6 * sp.eye(3)) * e1)
check(212, zero(wv.dot(e1) * sp.sqrt(3) - (w[0] + w[1] + w[2])))

# 13.9: a body of three masses with coordinates (x, y, z) about principal axes
Ix = sum(m[al] * (x[al][1] ** 2 + x[al][2] ** 2) for al in range(3))
Iy = sum(m[al] * (x[al][0] ** 2 + x[al][2] ** 2) for al in range(3))
Iz = sum(m[al] * (x[al][0] ** 2 + x[al][1] ** 2) for al in range(3))
z2 = sum(m[al] * x[al][2] ** 2 for al in range(3))
check(223, zero(Ix + Iy - (Iz + 2 * z2)))          # and 2 sum m z^2 >= 0
flat = {x[0][2]: 0, x[1][2]: 0}                      # a lamina: every z is 0 (the third follows)
check(229, zero((Ix + Iy - Iz).subs(flat)))

LINES = [15, 21, 27, 33, 45, 51, 57, 63, 69, 75, 86, 92, 98, 104, 118, 122, 128, 136, 142, 148, 154, 164, 170, 176,
         182, 188, 194, 200, 206, 212, 223, 229]

NC = "not a claim"
ROWS = {
    15: (NC, "defines a, the vector from Q to the centre of mass O: R = a + r"),
    21: (NC, "the inertia tensor about Q, the definition 13.4.1 written in the coordinates X"),
    27: (NC, "the components of R = a + r"),
    33: ("typo", "the second line is the right expansion of J_ij with X_k = a_k + x_k; the first line writes (x_k + a_i)^2 under the sum over k and (x_j + a_i) for (x_j + a_j), which is a different tensor: its diagonal gets 3 a_i^2 instead of a^2 and its off-diagonal a_i^2 instead of a_i a_j (check 33, three masses about their centre of mass)",
         "J_{i j} &=\\sum_{\\alpha}^{N} m_{\\alpha}\\left[\\delta_{i j}\\left(\\sum_{k}^{3}\\left(x_{\\alpha, k}+a_{k}\\right)^{2}\\right)-\\left(x_{\\alpha, i}+a_{i}\\right)\\left(x_{\\alpha, j}+a_{j}\\right)\\right]",
         "Take one mass m at x = 0 (all its coordinates zero) and a = (1, 2, 0). Then J_11 = m (X_2^2 + X_3^2) = m (4 + 0) = 4m. The first line gives m [(0 + a_1)^2 + (0 + a_1)^2 + (0 + a_1)^2 - (0 + a_1)(0 + a_1)] = m (3 - 1) = 2m; the second line gives m [a^2 - a_1^2] = m (5 - 1) = 4m.",
         "Off the diagonal, same mass: J_12 = -m X_1 X_2 = -m (1)(2) = -2m. The first line gives -(x_1 + a_1)(x_2 + a_1) m = -m (1)(1) = -m, because a_1 stands where a_2 belongs; the second line gives -(a_1 a_2) m = -2m."),
    45: ("holds", "regrouping the expansion: the centre-of-mass tensor, the terms in a alone, and the terms linear in x (check 45)"),
    51: (NC, "the centre of mass as origin: the condition that defines O"),
    57: (NC, "the same condition component by component"),
    63: ("holds", "the terms linear in x vanish about the centre of mass (check 63)"),
    69: ("holds", "Steiner's theorem J_ij = I_ij + M (a^2 delta_ij - a_i a_j) (check 69)"),
    75: ("typo", "a^2 = a_1^2 + a_2^2 + a_3^2; the display writes a^3_3 (a cube) for a^2_3, so its middle member is not J_11 while its right end I_11 + M (a_2^2 + a_3^2) is (check 75)",
         "J_{11} \\equiv I_{11} + M((a^2_1 + a^2_2 + a^2_3) \\delta_{11} - a^2_1) = I_{11} + M(a^2_2 + a^2_3)",
         "With a = (0, 0, 2): the middle member is I_11 + M((0 + 0 + 8) - 0) = I_11 + 8M, the right end I_11 + M(0 + 4) = I_11 + 4M. The two sides of the display's second = disagree, and Steiner's theorem gives J_11 = I_11 + M (a^2 - a_1^2) = I_11 + 4M.",
         "Dimensions: a^2_1 and a^2_2 are lengths squared but a^3_3 is a length cubed, so the bracket (a^2_1 + a^2_2 + a^3_3) cannot be a^2; the display's own right end needs a^2_3 there."),
    86: (NC, "the definition of the inertia tensor as an integral, restated"),
    92: ("holds", "rho times the integral of x_2^2 + x_3^2 over the cube [-b/2, b/2]^3 is rho b^5/6 = M b^2/6 (check 92)"),
    98: ("holds", "x_1 x_2 is odd over the symmetric cube: the product of inertia is 0 (check 98)"),
    104: ("holds", "all nine components: M b^2/6 times the unit matrix (check 104)"),
    118: ("holds", "rho times the integral of x_2^2 + x_3^2 over [0, b]^3 is 2 rho b^5/3 = 2 M b^2/3 (check 118)"),
    122: ("typo", "the product of inertia is I_12 = -rho times the integral of x_1 x_2; as written, rho times the integral of x_1 x_2 over [0, b]^3 is +rho b^5/4, not -rho b^5/4 (the value -M b^2/4 of I_12 is right); the minus sign before rho is missing, as the centre-of-mass example writes it (check 122)",
         "I_{12} = -\\rho \\int^b_0 \\int^b_0 \\int^b_0 (x_1 x_2) dx_3 dx_2 dx_1 = -\\frac{1}{4} \\rho b^5 = - \\frac{1}{4} Mb^2 \\notag",
         "The integrand x_1 x_2 is positive everywhere inside [0, b]^3, so its integral is positive: int_0^b x_1 dx_1 int_0^b x_2 dx_2 int_0^b dx_3 = (b^2/2)(b^2/2)(b) = b^5/4. rho times it is +rho b^5/4, while the display says -rho b^5/4.",
         "From the definition I_ij = int rho (delta_ij r^2 - x_i x_j) dV, the off-diagonal I_12 = -int rho x_1 x_2 dV = -rho b^5/4 = -M b^2/4, the value the display ends with and the matrix that follows (-3/12 M b^2) uses; the sign belongs in front of the integral, as in the centre-of-mass example's I_12 = -rho int x_1 x_2."),
    128: ("holds", "the nine components about the corner: (M b^2/12) [[8, -3, -3], [-3, 8, -3], [-3, -3, 8]] (check 128)"),
    136: (NC, "the vector from the corner to the centre of the cube, given by the geometry"),
    142: ("holds", "J_11 = I_11 + M (a_2^2 + a_3^2) = M b^2/6 + M b^2/2 = 2 M b^2/3 (check 142)"),
    148: ("holds", "J_12 = I_12 - M a_1 a_2 = 0 - M b^2/4 (check 148)"),
    154: ("holds", "Steiner's theorem reproduces the tensor found by integration (check 154)"),
    164: (NC, "the secular equation to be solved for the principal moments I"),
    170: ("typo", "subtracting row 1 from row 2 gives the row (-1/4 M b^2 - (2/3 M b^2 - I), (2/3 M b^2 - I) + 1/4 M b^2, 0) = (I - 11/12 M b^2, 11/12 M b^2 - I, 0); the display's first entry drops the I, which changes the determinant (check 170)",
         "\\begin{vmatrix} (\\frac{2}{3} Mb^2 - I) & -\\frac{1}{4} Mb^2 & -\\frac{1}{4} Mb^2 \\\\ (I -\\frac{11}{12} Mb^2) & (\\frac{11}{12} Mb^2 - I) & 0 \\\\ -\\frac{1}{4} Mb^2 & -\\frac{1}{4} Mb^2 & (\\frac{2}{3} Mb^2 - I) \\end{vmatrix} = 0 \\notag",
         "Row 2 minus row 1, entry by entry (in units of M b^2, with I in the same units): first entry -1/4 - (2/3 - I) = -11/12 + I; second (2/3 - I) - (-1/4) = 11/12 - I; third -1/4 - (-1/4) = 0. The display has -11/12 for the first entry, without + I.",
         "At I = M b^2/6, a root of the secular equation (the next display), the original determinant is 0. The display's matrix there, in units of M b^2, has rows (1/2, -1/4, -1/4), (-11/12, 3/4, 0), (-1/4, -1/4, 1/2); expanding along the first row: 1/2 (3/8 - 0) + 1/4 (-11/24 - 0) - 1/4 (11/48 + 3/16) = 3/16 - 11/96 - 5/48 = -1/32, not 0. With the corrected row (-3/4, 3/4, 0) the same expansion gives 1/2 (3/8) + 1/4 (-3/8) - 1/4 (3/16 + 3/16) = 3/16 - 3/32 - 3/32 = 0"),
    176: ("holds", "the determinant factors as (M b^2/6 - I)(11 M b^2/12 - I)^2 (check 176)"),
    182: ("holds", "the eigenvalues of the corner tensor: M b^2/6 once, 11 M b^2/12 twice (check 182)"),
    188: ("holds", "the corner tensor minus M b^2/6 is (M b^2/12) [[6, -3, -3], [-3, 6, -3], [-3, -3, 6]] (check 188)"),
    194: ("holds", "the rows of that matrix divided by 3 (times M b^2/12) (check 194)"),
    200: ("holds", "the corner tensor minus 11 M b^2/12 has every entry -3 M b^2/12 (check 200)"),
    206: ("holds", "each row of that matrix is -M b^2/4 (omega_1 + omega_2 + omega_3) (check 206)"),
    212: ("holds", "omega_12 + omega_22 + omega_32 = 0 says the axis is perpendicular to e_1 = (1, 1, 1)/sqrt 3 (check 212)"),
    223: ("holds", "I_x + I_y = int rho (x^2 + y^2) + 2 int rho z^2 >= I_z (check 223)"),
    229: ("holds", "with z = 0 throughout a lamina the extra term vanishes (check 229)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
