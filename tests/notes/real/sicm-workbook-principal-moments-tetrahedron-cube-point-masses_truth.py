"""Independent SymPy truth table for sicm-workbook-principal-moments-tetrahedron-cube-point-masses.md.

The notes' conventions: the inertia matrix about the centre of mass has the moments sum m (|r|^2 - r_i^2) on
its diagonal and the products -sum m r_i r_j off it (part a writes them with the minus sign); the principal
moments are its eigenvalues. (a) Four masses m at (+-1, 0, -1/sqrt 2), (0, +-1, 1/sqrt 2). (b) A uniform cube
of side L and mass M about its centre. (c) Five masses m at (-1,0,0), (1,0,0), (1,1,0), (0,0,0), (0,0,1).
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}
zero = truth_table.zero


def check(key, ok):
    CHECKS[key] = bool(ok)


def inertia(points, mass):
    """The inertia matrix of equal point masses about their centre of mass."""
    P = [sp.Matrix(p) for p in points]
    c = sum(P, sp.zeros(3, 1)) / len(P)
    return sum(((p - c).dot(p - c) * sp.eye(3) - (p - c) * (p - c).T for p in P), sp.zeros(3)) * mass


m, M, L = sp.symbols('m M L', positive=True)
x, y, z = sp.symbols('x y z', real=True)
s2 = 1 / sp.sqrt(2)
# (a) the tetrahedron, masses in the order the sums of line 23 take them
tet = [(1, 0, -s2), (-1, 0, -s2), (0, 1, s2), (0, -1, s2)]
Ia = inertia(tet, m)
terms = {  # line 23's sums term by term, one term per mass
    (0, 0): [0 + sp.Rational(1, 2), 0 + sp.Rational(1, 2), 1 + sp.Rational(1, 2), 1 + sp.Rational(1, 2)],
    (0, 1): [0, 0, 0, 0], (0, 2): [-s2, s2, 0, 0], (1, 0): [0, 0, 0, 0],
    (1, 1): [1 + sp.Rational(1, 2), 1 + sp.Rational(1, 2), 0 + sp.Rational(1, 2), 0 + sp.Rational(1, 2)],
    (1, 2): [0, 0, s2, -s2], (2, 0): [-s2, s2, 0, 0], (2, 1): [0, 0, s2, -s2], (2, 2): [1, 1, 1, 1]}
sign = {k: (1 if k[0] == k[1] else -1) for k in terms}
values = {(0, 0): 4 * m, (1, 1): 4 * m, (2, 2): 4 * m}
ok = True
for k, ts in terms.items():
    i, j = k
    per_mass = [((sp.Matrix(p).dot(sp.Matrix(p)) - sp.Matrix(p)[i]**2) if i == j else sp.Matrix(p)[i] * sp.Matrix(p)[j])
                for p in tet]
    ok &= all(zero(a - b) for a, b in zip(per_mass, ts))
    ok &= zero(sign[k] * m * sum(ts) - values.get(k, 0)) and zero(Ia[i, j] - values.get(k, 0))
check(23, ok)
check(50, zero(Ia - sp.diag(4 * m, 4 * m, 4 * m)))
check(60, all(zero(ev - 4 * m) for ev in Ia.eigenvals()))
# (b) the cube
rho = M / L**3
box = [(x, -L / 2, L / 2), (y, -L / 2, L / 2), (z, -L / 2, L / 2)]
Ib = sp.Matrix(3, 3, lambda i, j: rho * sp.integrate(
    ((x**2 + y**2 + z**2) - [x, y, z][i]**2) if i == j else -[x, y, z][i] * [x, y, z][j], *box))
check(90, zero(Ib - sp.eye(3) * M * L**2 / 6))
# (c) the five masses
five = [(-1, 0, 0), (1, 0, 0), (1, 1, 0), (0, 0, 0), (0, 0, 1)]
Ic = inertia(five, m)
assert zero(Ic - m * sp.Matrix([[8, -4, 1], [-4, 18, 1], [1, 1, 18]]) / 5)
moments = sorted(float(sp.re(sp.N(ev / m, 20))) for ev in Ic.eigenvals())
check(112, all(abs(a - b) < 1e-9 for a, b in zip(moments, [1.6, 3.6, 3.6])))
assert [round(float(v), 4) for v in moments] == [1.2912, 3.5790, 3.9299]

LINES = [17, 23, 50, 60, 70, 80, 90, 96, 104, 108, 112]
NC, H_ = "not a claim", "holds"
HAND_1 = ("By hand: about the centre of mass (1/5, 1/5, 1/5) the offsets (x, y) of the five masses are "
          "(-6/5, -1/5), (4/5, -1/5), (4/5, 4/5), (-1/5, -1/5), (-1/5, -1/5), whose products sum to "
          "(6 - 4 + 16 + 1 + 1)/25 = 4/5, so I_xy = -4m/5; likewise I_xz = I_yz = m/5, and the moments are "
          "8m/5, 18m/5, 18m/5. The matrix m[[8/5, -4/5, 1/5], [-4/5, 18/5, 1/5], [1/5, 1/5, 18/5]] does not "
          "map x-hat to a multiple of x-hat, so 1.6m, its xx entry, is not an eigenvalue; its eigenvalues are "
          "1.2912m, 3.5790m, 3.9299m.")
HAND_2 = ("Numbers: the true matrix times x-hat is m(1.6, -0.8, 0.2), not a multiple of x-hat, so x-hat is not a "
          "principal axis; and the determinant of the true matrix is 454/25 m^3 = 18.16 m^3 "
          "(= 1.2912 x 3.5790 x 3.9299), while the notes' moments give 1.6 x 3.6 x 3.6 = 20.736.")
ROWS = {
    17: (NC, "the positions of the four masses, chosen by the notes"),
    23: (H_, "each moment and product summed mass by mass: the terms listed are the four masses' y^2+z^2, "
              "x y, x z, x^2+z^2, y z, x^2+y^2, giving 4m on the diagonal and 0 off it (check 23)"),
    50: (H_, "the matrix of line 23's sums (check 50)"),
    60: (H_, "the eigenvalues of 4m times the identity (check 60)"),
    70: (NC, "the moments of inertia of the cube as integrals, not yet evaluated"),
    80: (NC, "the products of inertia of the cube as integrals, not yet evaluated"),
    90: (H_, "rho times the integral of y^2 + z^2 over the cube is (M/L^3)(2 L^5/12) = M L^2/6, the products "
              "vanish (check 90)"),
    96: (NC, "a printed matrix, with no relation written in the display"),
    104: (NC, "a printed matrix, with no relation written in the display (the claim it feeds is line 112's)"),
    108: (NC, "a printed vector, with no relation written in the display"),
    112: ("fails", "the inertia matrix of the five masses about their centre of mass is m[[8/5, -4/5, 1/5], "
                   "[-4/5, 18/5, 1/5], [1/5, 1/5, 18/5]], whose eigenvalues are 1.2912m, 3.5790m, 3.9299m; the "
                   "notes' matrix has wrong products of inertia (a coordinate squared in each, no minus sign, the "
                   "lower triangle unset), so its eigenvalues 1.6m, 3.6m, 3.6m are not the principal moments "
                   "(check 112)", None, HAND_1, HAND_2),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
