"""Independent SymPy truth table for cline-cube-angular-momentum-rotational-kinetic-energy-worked-examples.md.

Names as the text's: a uniform solid cube of side b and mass M has the inertia tensor (M b^2/6) 1
about its centre of mass and (M b^2/12) [[8, -3, -3], [-3, 8, -3], [-3, -3, 8]] about a corner, with
the axes along the edges (both computed here by integration, not taken from the text); the angular
velocity has the size omega. For section 13.12 a body of two particles with symbolic masses m_a and
body vectors r'_a turns with angular velocity omega about a point moving with V. Run as a program,
the script compares its verdicts with the table; with --write it writes the table from ROWS.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


def zero(e):
    return truth_table.zero(e)


b, rho, w = sp.symbols('b rho omega', positive=True)
x1, x2, x3 = sp.symbols('x_1 x_2 x_3', real=True)
X = [x1, x2, x3]
M = rho * b ** 3


def cube(lo, hi):
    return sp.Matrix(3, 3, lambda i, j: rho * sp.integrate((x1 ** 2 + x2 ** 2 + x3 ** 2 if i == j else 0) - X[i] * X[j],
                                                             (x3, lo, hi), (x2, lo, hi), (x1, lo, hi)))


Icm, Ico = cube(-b / 2, b / 2), cube(0, b)
assert zero(Icm - M * b ** 2 / 6 * sp.eye(3))
assert zero(Ico - M * b ** 2 / 12 * sp.Matrix([[8, -3, -3], [-3, 8, -3], [-3, -3, 8]]))
K = sp.Matrix([[8, -3, -3], [-3, 8, -3], [-3, -3, 8]])

# line 13: L = I . omega, the relation that defines the angular momentum in tensor form (no claim)
wx = w * sp.Matrix([1, 0, 0])
check(24, zero(Icm * wx - M * b ** 2 * w / 6 * sp.Matrix([1, 0, 0]))
      and zero(M * b ** 2 * w / 6 * sp.eye(3) * sp.Matrix([1, 0, 0]) - Icm * wx))
wd = w / sp.sqrt(3) * sp.Matrix([1, 1, 1])
check(30, zero(Icm * wd - M * b ** 2 / 6 * wd)
      and zero(M * b ** 2 * w / 6 / sp.sqrt(3) * sp.Matrix([1, 1, 1]) - Icm * wd))
# line 42: (M b^2 omega/12) K (1,0,0) = (M b^2 omega/12)(8,-3,-3); the last member's bold omega is
# the rate omega of the member before it
check(42, zero(Ico * wx - M * b ** 2 * w / 12 * K * sp.Matrix([1, 0, 0]))
      and zero(Ico * wx - M * b ** 2 * w / 12 * sp.Matrix([8, -3, -3])))
check(48, zero(Ico * wd - M * b ** 2 * w / 12 / sp.sqrt(3) * sp.Matrix([2, 2, 2])) and zero(Ico * wd - M * b ** 2 / 6 * wd))
# line 54: the last member drops the 1/sqrt(2) of the member before it
wp = w / sp.sqrt(2) * sp.Matrix([-1, 1, 0])
mid = M * b ** 2 * w / 12 / sp.sqrt(2) * sp.Matrix([-11, 11, 0])
last = sp.Rational(11, 12) * M * b ** 2 * w * sp.Matrix([-1, 1, 0])
check(54, zero(Ico * wp - mid) and zero(mid - last))
assert zero(Ico * wp - mid) and zero(Ico * wp - sp.Rational(11, 12) * M * b ** 2 * wp) and not zero(mid - last)

# 13.12: two particles
m = sp.symbols('m1:3', positive=True)
r = [sp.Matrix(sp.symbols(f'r{a}_1:4', real=True)) for a in (1, 2)]
V = sp.Matrix(sp.symbols('V_1:4', real=True))
om = sp.Matrix(sp.symbols('omega_1:4', real=True))
v = [V + om.cross(ra) for ra in r]                 # the rigid body's velocity: v'' = 0
# line 65: the velocity seen from the fixed frame (the rule of chapter 12.4, no claim)
check(71, all(zero(v[a] - (V + om.cross(r[a]))) for a in range(2)))
T = sum(m[a] * v[a].dot(v[a]) for a in range(2)) / 2
T58 = (sum(m[a] for a in range(2)) * V.dot(V) / 2 + sum(m[a] * V.dot(om.cross(r[a])) for a in range(2))
       + sum(m[a] * om.cross(r[a]).dot(om.cross(r[a])) for a in range(2)) / 2)
check(77, zero(T - T58))
check(83, zero(sum(m[a] * V.dot(om.cross(r[a])) for a in range(2)) - V.dot(om.cross(m[0] * r[0] + m[1] * r[1]))))
# lines 89-105: the centre of mass's definition, the names of the split and of its two parts (no claims)
A_, B_ = sp.Matrix(sp.symbols('A_1:4', real=True)), sp.Matrix(sp.symbols('B_1:4', real=True))
check(111, zero(A_.cross(B_).dot(A_.cross(B_)) - (A_.dot(A_) * B_.dot(B_) - A_.dot(B_) ** 2)))
Trot = sum(m[a] * om.cross(r[a]).dot(om.cross(r[a])) for a in range(2)) / 2
check(117, zero(Trot - sum(m[a] * (om.dot(om) * r[a].dot(r[a]) - om.dot(r[a]) ** 2) for a in range(2)) / 2))
comp = sum(m[a] * (sum(om[i] ** 2 for i in range(3)) * sum(r[a][k] ** 2 for k in range(3))
                   - sum(om[i] * r[a][i] for i in range(3)) * sum(om[j] * r[a][j] for j in range(3))) for a in range(2)) / 2
check(123, zero(Trot - comp))
check(129, all(zero(om[i] - sum(om[j] * (1 if i == j else 0) for j in range(3))) for i in range(3)))
d = lambda i, j: 1 if i == j else 0
second = sum(m[a] * sum(om[i] * om[j] * d(i, j) * sum(r[a][k] ** 2 for k in range(3)) - om[i] * r[a][i] * om[j] * r[a][j]
                        for i in range(3) for j in range(3)) for a in range(2)) / 2
I = sp.Matrix(3, 3, lambda i, j: sum(m[a] * (d(i, j) * r[a].dot(r[a]) - r[a][i] * r[a][j]) for a in range(2)))
third = sum(om[i] * om[j] * I[i, j] for i in range(3) for j in range(3)) / 2
check(135, zero(comp - second) and zero(second - third))
check(141, zero(Trot - third))
Id = sp.diag(*sp.symbols('I_1:4', positive=True))       # a diagonal tensor
check(147, zero((om.T * Id * om)[0] / 2 - sum(Id[i, i] * om[i] ** 2 for i in range(3)) / 2))
L = I * om
check(153, zero(third - sum(om[i] * sum(I[i, j] * om[j] for j in range(3)) for i in range(3)) / 2)
      and zero(third - om.dot(L) / 2))
check(159, zero(Trot - (om.T * I * om)[0] / 2))
check(163, zero(Trot - om.dot(I * om) / 2))
check(169, zero(Trot - om.dot(L) / 2))

LINES = [13, 24, 30, 42, 48, 54, 65, 71, 77, 83, 89, 95, 101, 105, 111, 117, 123, 129, 135, 141, 147, 153, 159, 163, 169]

NC = "not a claim"
H = "holds"
ROWS = {
    13: (NC, "L = I . omega in matrix form: how the text writes the angular momentum from the inertia tensor"),
    24: (H, "(M b^2/6) 1 applied to omega (1, 0, 0) is (M b^2 omega/6)(1, 0, 0) (check 24)"),
    30: (H, "with omega = omega (1, 1, 1)/sqrt 3: (M b^2 omega/6)(1, 1, 1)/sqrt 3 = (M b^2/6) omega (check 30)"),
    42: (H, "the corner tensor applied to omega (1, 0, 0) is (M b^2 omega/12)(8, -3, -3) (check 42); read with the bold omega of the last member as the rate omega of the member before it"),
    48: (H, "K (1, 1, 1) = (2, 2, 2), so L = (M b^2 omega/12)(2, 2, 2)/sqrt 3 = (M b^2/6) omega along the diagonal (check 48)"),
    54: ("typo", "K (-1, 1, 0) = (-11, 11, 0) and the middle member is right, but the last member drops its 1/sqrt 2: (M b^2 omega/12)(1/sqrt 2)(-11, 11, 0) = (11/12) M b^2 omega (-1, 1, 0)/sqrt 2 = (11/12) M b^2 omega-vector, not (11/12) M b^2 omega (-1, 1, 0), which is sqrt 2 times too large (check 54)",
         "\\begin{align*} \\mathbf{L} &= \\frac{1}{12} Mb^2\\omega \\frac{1}{\\sqrt{2}} \\begin{pmatrix} +8 & -3 & -3 \\\\ -3 & +8 & -3 \\\\ -3 & -3 & +8 \\end{pmatrix} \\cdot \\begin{pmatrix} -1 \\\\ +1 \\\\ 0 \\end{pmatrix} \\\\[4pt] &= \\frac{1}{12} Mb^2 \\omega \\frac{1}{\\sqrt{2}} \\begin{pmatrix} -11 \\\\ +11 \\\\ 0 \\end{pmatrix} \\\\[4pt] &= \\frac{11}{12}Mb^2 \\omega \\frac{1}{\\sqrt{2}} \\begin{pmatrix} -1 \\\\ +1 \\\\ 0 \\end{pmatrix} \\end{align*}",
         "(1/12)(1/sqrt 2)(-11, 11, 0) = (11/12)(1/sqrt 2)(-1, 1, 0): taking 11 out of the column leaves the factor 1/sqrt 2 in front. The display's last member (11/12)(-1, 1, 0) has lost it; its first component is -11/12 = -0.917 where the member before gives -11/(12 sqrt 2) = -0.648.",
         "Sizes: the angular velocity has the size omega and the axis is principal with the moment 11 M b^2/12, so |L| must be (11/12) M b^2 omega. The last member's column (-1, 1, 0) has length sqrt 2, giving |L| = sqrt 2 (11/12) M b^2 omega, too large by sqrt 2; with the 1/sqrt 2 kept the size is right."),
    65: (NC, "the velocity of a particle seen from the fixed frame, the rule of chapter 12.4 the section starts from"),
    71: (H, "with no motion relative to the body, v = V + omega x r' (check 71)"),
    77: (H, "expanding (V + omega x r').(V + omega x r') (check 77, two particles)"),
    83: (H, "V . omega x r' is linear in r': the sum moves inside (check 83)"),
    89: (NC, "the definition of the centre of mass"),
    95: (NC, "names the two parts of the kinetic energy that the next two displays define"),
    101: (NC, "defines the translational kinetic energy"),
    105: (NC, "defines the rotational kinetic energy"),
    111: (H, "Lagrange's identity (A x B).(A x B) = A^2 B^2 - (A.B)^2 (check 111)"),
    117: (H, "the identity applied to omega x r' (check 117)"),
    123: (H, "the same in components (check 123)"),
    129: (H, "the Kronecker delta picks omega_i out of the sum (check 129)"),
    135: (H, "the three members agree; the last bracket is the inertia tensor (check 135)"),
    141: (H, "T_rot = (1/2) sum I_ij omega_i omega_j (check 141)"),
    147: (H, "for a diagonal tensor only the squares remain (check 147)"),
    153: (H, "sum_j I_ij omega_j = L_i (check 153)"),
    159: (H, "the same quadratic form as a row, the matrix and a column (check 159)"),
    163: (H, "T_rot = (1/2) omega . I . omega (check 163)"),
    169: (H, "T_rot = (1/2) omega . L (check 169)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
