"""Independent SymPy truth table for lawrence-phys162-euler-angles-zyz-rotation-operator-spin-half-spin-one.md.

The notes' convention: R(n, theta) turns counterclockwise about the unit vector n; the Euler angles
turn the frame about z by alpha, about the new y' by beta, about the newest Z by gamma. A rotation is
represented by U = exp(-i theta n.J/hbar); in the vector representation J_k = i hbar (the generator
of R_k), so exp(-i theta J_z/hbar) = R_z(theta). The spin-1/2 states are (1, 0), (0, 1) for m = 1/2,
-1/2; the spin-1 matrices are judged in the basis e1, e2, e3 for m = 1, 0, -1, the basis in which the
raising and lowering formulas give them. Numbers stand in for the angles where symbols are slow.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}
zero = truth_table.zero


def check(key, ok):
    CHECKS[key] = bool(ok)


VALS = [(0.37, 1.21, -0.83), (-1.9, 0.52, 2.6)]
al, be, ga, hb = sp.symbols('alpha beta gamma hbar', positive=True)


def numzero(expr) -> bool:
    """``expr`` (a matrix in alpha, beta, gamma) vanishes at two sets of numbers."""
    for a, b, c in VALS:
        m = expr.subs({al: a, be: b, ga: c, hb: 1.3})
        if max(abs(complex(sp.N(v))) for v in m) > 1e-9:
            return False
    return True


def rot(n, q):
    """The counterclockwise rotation by q about the unit vector n (Rodrigues)."""
    K = sp.Matrix([[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]])
    return sp.eye(3) + sp.sin(q) * K + (1 - sp.cos(q)) * K * K


x_, y_, z_ = sp.eye(3)[:, 0], sp.eye(3)[:, 1], sp.eye(3)[:, 2]
Rza = rot(z_, al)
yp = Rza * y_                       # y' after the first turn
zpp = rot(yp, be) * z_              # Z = z'' after the second
R_def = rot(zpp, ga) * rot(yp, be) * rot(z_, al)       # line 30, the definition

# 37: R(Z, gamma) = R(y', beta) R(z, gamma) R(y', -beta); R(y', beta) = R(z, alpha) R(y, beta) R(z, -alpha)
check(37, numzero(rot(zpp, ga) - rot(yp, be) * rot(z_, ga) * rot(yp, -be))
      and numzero(rot(yp, be) - rot(z_, al) * rot(y_, be) * rot(z_, -al)))
# 47: the chain down to R(z, alpha) R(y, beta) R(z, gamma), each link
links = [R_def,
         rot(yp, be) * rot(z_, ga) * rot(yp, -be) * rot(yp, be) * rot(z_, al),
         rot(yp, be) * rot(z_, ga) * rot(z_, al),
         rot(z_, al) * rot(y_, be) * rot(z_, -al) * rot(z_, ga) * rot(z_, al),
         rot(z_, al) * rot(y_, be) * rot(z_, ga) * rot(z_, -al) * rot(z_, al),
         rot(z_, al) * rot(y_, be) * rot(z_, ga)]
check(47, all(numzero(p - q) for p, q in zip(links, links[1:])))
# 66: U(R(alpha, beta, gamma)) = e^{-i alpha J_z} e^{-i beta J_y} e^{-i gamma J_z} (hbar = 1 in the exponents'
# ratio): in the vector representation and in spin 1/2, the product represents R(z,alpha) R(y,beta) R(z,gamma)
Jz3 = sp.I * hb * sp.Matrix([[0, -1, 0], [1, 0, 0], [0, 0, 0]])
Jy3 = sp.I * hb * sp.Matrix([[0, 0, 1], [0, 0, 0], [-1, 0, 0]])
U3 = (-sp.I * al * Jz3 / hb).exp() * (-sp.I * be * Jy3 / hb).exp() * (-sp.I * ga * Jz3 / hb).exp()
check(66, numzero(U3 - R_def))
# 72: d^j_{m',m} = e^{-i m' alpha - i m gamma} <j,m| e^{-i beta J_y} |j,m>, as written (the bra should be <j,m'|);
# spin 1/2, m' = 1/2, m = -1/2
sx, sy, sz = sp.Matrix([[0, 1], [1, 0]]), sp.Matrix([[0, -sp.I], [sp.I, 0]]), sp.Matrix([[1, 0], [0, -1]])
Jx2, Jy2, Jz2 = hb / 2 * sx, hb / 2 * sy, hb / 2 * sz
ey = (-sp.I * be * Jy2 / hb).exp()
U2 = (-sp.I * al * Jz2 / hb).exp() * ey * (-sp.I * ga * Jz2 / hb).exp()
ms = [sp.Rational(1, 2), -sp.Rational(1, 2)]
full = sp.Matrix(2, 2, lambda r, c: sp.exp(-sp.I * ms[r] * al - sp.I * ms[c] * ga) * ey[r, c])
assert numzero(full - U2)                                               # with <j,m'| it holds
written = sp.Matrix(2, 2, lambda r, c: sp.exp(-sp.I * ms[r] * al - sp.I * ms[c] * ga) * ey[c, c])
check(72, numzero(written - U2))
# 82: J_z = hbar/2 diag(1, -1) = hbar/2 sigma_z
check(82, zero(hb / 2 * sp.diag(1, -1) - Jz2))
# 88: J_+ and J_- from J_+|j,m> = hbar sqrt((j-m)(j+m+1)) |j,m+1>, J_-|j,m> = hbar sqrt((j+m)(j-m+1)) |j,m-1>


def ladder(j):
    ml = [j - k for k in range(int(2 * j) + 1)]
    d = len(ml)
    Jp, Jm = sp.zeros(d), sp.zeros(d)
    for c, m in enumerate(ml):
        if c > 0:
            Jp[c - 1, c] = hb * sp.sqrt((j - m) * (j + m + 1))
        if c < d - 1:
            Jm[c + 1, c] = hb * sp.sqrt((j + m) * (j - m + 1))
    return Jp, Jm, hb * sp.diag(*ml)


Jp2, Jm2, _ = ladder(sp.Rational(1, 2))
check(88, zero(Jp2 - hb * sp.Matrix([[0, 1], [0, 0]])) and zero(Jm2 - hb * sp.Matrix([[0, 0], [1, 0]])))
# 97: J_x = (J_+ + J_-)/2 = hbar/2 sigma_x, J_y = (J_+ - J_-)/(2i) = hbar/2 sigma_y
check(97, zero((Jp2 + Jm2) / 2 - Jx2) and zero((Jp2 - Jm2) / (2 * sp.I) - Jy2)
      and zero((Jp2 + Jm2) / 2 - hb / 2 * sp.Matrix([[0, 1], [1, 0]]))
      and zero((Jp2 - Jm2) / (2 * sp.I) - hb / 2 * sp.Matrix([[0, -sp.I], [sp.I, 0]])))
# 107: the spin-1/2 matrix as written ("alpha = gamma" read as alpha - gamma, as the rest of the entry needs;
# the last entry has beta where gamma belongs)
c2, s2 = sp.cos(be / 2), sp.sin(be / 2)
D_written = sp.Matrix([[sp.exp(-sp.I * (al + ga) / 2) * c2, -sp.exp(-sp.I * (al - ga) / 2) * s2],
                       [sp.exp(sp.I * (al - ga) / 2) * s2, sp.exp(sp.I * (al + be) / 2) * c2]])
check(107, numzero(D_written - U2))
# 126: spin 1: J_z, J_+, J_-, J_x = hbar/sqrt2 [[0,1,0],[1,0,1],[0,1,0]], J_y = hbar/sqrt2 [[0,-i,0],[i,0,-i],[0,i,0]];
# the J_x row writes "hbar/sqrt2 & = matrix" (the scalar set equal to the matrix) and J_y has the letter o
Jp3, Jm3, Jz1 = ladder(1)
o = sp.Symbol('o')
Jx1, Jy1 = (Jp3 + Jm3) / 2, (Jp3 - Jm3) / (2 * sp.I)
ok_z = zero(Jz1 - hb * sp.diag(1, 0, -1))
ok_pm = zero(Jp3 - sp.sqrt(2) * hb * sp.Matrix([[0, 1, 0], [0, 0, 1], [0, 0, 0]])) and zero(
    Jm3 - sp.sqrt(2) * hb * sp.Matrix([[0, 0, 0], [1, 0, 0], [0, 1, 0]]))
ok_x = zero(Jx1 - sp.Matrix([[0, 1, 0], [1, 0, 1], [0, 1, 0]]))           # as written: no factor on the matrix
ok_y = zero(Jy1 - hb / sp.sqrt(2) * sp.Matrix([[0, -sp.I, 0], [sp.I, 0, -sp.I], [0, sp.I, o]]))
assert ok_z and ok_pm and zero(Jx1 - hb / sp.sqrt(2) * sp.Matrix([[0, 1, 0], [1, 0, 1], [0, 1, 0]]))
check(126, ok_z and ok_pm and ok_x and ok_y)

LINES = [17, 30, 37, 47, 60, 66, 72, 82, 88, 97, 107, 116, 126]
NC, H_ = "not a claim", "holds"
ROWS = {
    17: (NC, "the book's macro definitions (\\ket, \\bra, \\half) copied from its _config.yml"),
    30: (NC, "defines the rotation of the Euler angles as three turns about moved axes"),
    37: (H_, "a rotation about a moved axis is the conjugate of the rotation about the axis it was moved from: "
              "Z = R(y', beta) z and y' = R(z, alpha) y (check 37)"),
    47: (H_, "each link: the first relation, R(y',-beta) R(y',beta) = 1, the second relation, rotations about z "
              "commute, R(z,-alpha) R(z,alpha) = 1; the result R(z,alpha) R(y,beta) R(z,gamma) (check 47)"),
    60: (NC, "defines the matrix elements of a rotation in an irreducible representation"),
    66: (H_, "the representation of R(z,alpha) R(y,beta) R(z,gamma), each factor exp(-i angle J_k/hbar); in the "
              "vector representation the product is the rotation matrix of line 47 (check 66)"),
    72: ("typo",
         "with e^{-i gamma J_z}|j,m> = e^{-i m gamma}|j,m> and <j,m'| e^{-i alpha J_z} = e^{-i m' alpha}<j,m'|, the "
         "element is e^{-i m' alpha - i m gamma} <j,m'| e^{-i beta J_y/hbar} |j,m>; the display writes the bra "
         "<j,m|, a diagonal element (check 72)",
         "d^j_{m',m}(\\alpha,\\beta,\\gamma) = e^{-i m' \\alpha - i m\\gamma} \\bra{j,m'} e^{-i \\beta J_y/\\hbar} \\ket{j,m}",
         "By hand: the two outer exponentials act on the bra <j,m'| and the ket |j,m> as phases, leaving the middle "
         "factor between the same bra and ket; the display's <j,m| ... |j,m> has lost m'.",
         "Numbers: spin 1/2, m' = 1/2, m = -1/2, alpha = gamma = 0, beta = pi/2: the element is "
         "<1/2| e^{-i beta sigma_y/2} |-1/2> = -sin(pi/4) = -0.7071; the display gives <-1/2| ... |-1/2> = "
         "cos(pi/4) = 0.7071."),
    82: (H_, "J_z |1/2, +-1/2> = +-hbar/2 |1/2, +-1/2> (check 82)"),
    88: (H_, "J_+ |1/2,-1/2> = hbar |1/2,1/2> and J_- |1/2,1/2> = hbar |1/2,-1/2> (check 88)"),
    97: (H_, "J_x = (J_+ + J_-)/2 and J_y = (J_+ - J_-)/(2i) give hbar/2 times the Pauli matrices (check 97)"),
    107: ("typo",
          "the elements e^{-i m' alpha} d_{m'm}(beta) e^{-i m gamma} are [[e^{-i(alpha+gamma)/2} cos, "
          "-e^{-i(alpha-gamma)/2} sin], [e^{i(alpha-gamma)/2} sin, e^{i(alpha+gamma)/2} cos]]; the display writes "
          "\"alpha = gamma\" for alpha - gamma in the first row and alpha + beta for alpha + gamma in the last entry "
          "(check 107)",
          "\\begin{pmatrix} e^{-i(\\alpha + \\gamma)/2} \\cos\\frac{\\beta}{2} & - e^{-i(\\alpha - \\gamma)/2} \\sin\\frac{\\beta}{2}\\\\ "
          "e^{i(\\alpha - \\gamma)/2}\\sin \\frac{\\beta}{2} & e^{i(\\alpha + \\gamma)/2} \\cos\\frac{\\beta}{2} \\end{pmatrix}",
          "By hand: e^{-i beta sigma_y/2} = [[cos(beta/2), -sin(beta/2)], [sin(beta/2), cos(beta/2)]]; the entry "
          "m' = m = -1/2 takes the phases e^{i alpha/2} e^{i gamma/2} = e^{i(alpha+gamma)/2}, with no beta in it.",
          "Numbers: alpha = 0, beta = pi/2, gamma = 0: the last entry is cos(pi/4) = 0.7071; the display's is "
          "e^{i pi/4} 0.7071 = 0.5 + 0.5 i."),
    116: (NC, "chooses the columns that represent the spin-1 states"),
    126: ("typo",
          "in the basis of the raising and lowering formulas J_z = hbar diag(1, 0, -1), J_+ and J_- as written, "
          "J_x = hbar/sqrt2 [[0,1,0],[1,0,1],[0,1,0]] and J_y = hbar/sqrt2 [[0,-i,0],[i,0,-i],[0,i,0]]; the J_x row "
          "writes \"\\frac{\\hbar}{\\sqrt{2}} & = \" (the factor set equal to the matrix, which then lacks it), and J_y's "
          "last entry is the letter o where 0 belongs (check 126)",
          "J_x & = \\frac{\\hbar}{\\sqrt{2}} \\begin{pmatrix} 0 & 1 & 0 \\\\ 1 & 0 & 1 \\\\ 0 & 1 & 0 \\end{pmatrix}\\\\ "
          "J_y & = \\frac{\\hbar}{\\sqrt{2}} \\begin{pmatrix} 0 & -i & 0 \\\\ i & 0 & -i \\\\ 0 & i & 0 \\end{pmatrix}",
          "By hand: J_x = (J_+ + J_-)/2 = (sqrt2 hbar/2)[[0,1,0],[1,0,1],[0,1,0]] = (hbar/sqrt2)[[...]]; the display's "
          "J_x line reads J_x = hbar/sqrt2 = [[...]], a number set equal to a matrix, and the matrix alone lacks "
          "hbar/sqrt2; J_y's (3,3) entry is (J_+ - J_-)/(2i) there, 0, not o.",
          "Numbers: hbar = 1: J_x's (1,2) entry is 1/sqrt2 = 0.7071; the display's matrix has 1 there. J_y's (3,3) "
          "entry is 0; the display's is the letter o."),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
