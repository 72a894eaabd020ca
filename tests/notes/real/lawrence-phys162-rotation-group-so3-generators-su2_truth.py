"""Independent SymPy truth table for lawrence-phys162-rotation-group-so3-generators-su2.md.

The notes' convention: a rotation acts on a vector's components, (V')^I = R^I_J V^J, with indices
raised and lowered by the identity; the rotation by theta about the unit vector n turns V
counterclockwise about n (the Rodrigues form of the display at line 101). The generators are read
from R = 1 - i theta J.n/hbar. SU(2) elements are [[a, b], [-b*, a*]] with a = a_r + i a_i,
b = b_r + i b_i. Everything is built here from explicit matrices; nothing comes from the reader.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Ry, Rz

CHECKS = {}
zero = truth_table.zero


def check(key, ok):
    CHECKS[key] = bool(ok)


POINTS = [{'alpha': 0.37, 'beta': 1.21, 'gamma': -0.83, 'theta': 0.71, 'u': 0.45, 'w': 2.2, 'V1': 1.3, 'V2': -0.4,
           'V3': 2.1},
          {'alpha': -1.9, 'beta': 0.52, 'gamma': 2.6, 'theta': 2.3, 'u': 1.7, 'w': -0.9, 'V1': -0.6, 'V2': 1.8,
           'V3': 0.7}]


def numzero(expr) -> bool:
    """``expr`` (a scalar or a matrix in the angles and V's components) vanishes at two sets of numbers."""
    m = expr if hasattr(expr, "shape") else sp.Matrix([expr])
    for pt in POINTS:
        sub = {sym: pt[sym.name] for sym in m.free_symbols if sym.name in pt}
        if max(abs(complex(sp.N(v.subs(sub)))) for v in m) > 1e-9:
            return False
    return True


th, al, be, ga, hb = sp.symbols('theta alpha beta gamma hbar', positive=True)
I3 = sp.eye(3)


def eps(i, j, k):
    return sp.LeviCivita(i, j, k)


# a general rotation (z-y-z Euler angles) and a general vector
R = Rz(al) * Ry(be) * Rz(ga)
V = sp.Matrix(sp.symbols('V1:4', real=True))
assert numzero(R.T * R - I3)

# 33: (V')^I (V')_I = V^J R^I_J (R^T)^K_I V_K = V^K V_K for orthogonal R
Vp = R * V
mid = sum(V[j] * R[i, j] * R.T[k, i] * V[k] for i in range(3) for j in range(3) for k in range(3))
check(33, numzero(Vp.dot(Vp) - mid) and numzero(mid - V.dot(V)))
# 40: (R1 R2)^T = R2^T R1^T = R2^-1 R1^-1 = (R1 R2)^-1
R1, R2 = Rx(al) * Rz(be), Ry(ga) * Rx(th)
P = R1 * R2
check(40, numzero(P.T - R2.T * R1.T) and numzero(R2.T * R1.T - R2.inv() * R1.inv())
      and numzero(R2.inv() * R1.inv() - P.inv()))
# 46: det(R^T R) = (det R)^2 = det 1 = 1 (orthogonal R; a reflection too)
F = sp.diag(1, 1, -1) * R
check(46, all(numzero((M.T * M).det() - M.det() ** 2) and numzero(M.det() ** 2 - 1) for M in (R, F)))

# the rotation by theta about the unit vector n (spherical angles u, w): Rodrigues, counterclockwise
u, w = sp.symbols('u w', real=True)
n = sp.Matrix([sp.sin(u) * sp.cos(w), sp.sin(u) * sp.sin(w), sp.cos(u)])
K = sp.Matrix([[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]])   # K V = n x V
Rn = I3 + sp.sin(th) * K + (1 - sp.cos(th)) * K * K
assert numzero(Rn.subs({u: 0}) - Rz(th))                                    # about z it is R_z(theta)
Vn = Rn * V
Vpar = V.dot(n) * n
Vperp = V - Vpar
nxV = n.cross(V)
norm = lambda x: sp.sqrt(x.dot(x))  # noqa: E731

# 79: the expansion of V' along n, V_perp/|V_perp| and n x V / |n x V|, as written
# (a number vector at numbers: the second term is a scalar, the third lacks a division by |n x V|)
e2, e3 = Vperp / norm(Vperp), nxV / norm(nxV)
right = Vn.dot(n) * n + Vn.dot(e2) * e2 + Vn.dot(e3) * e3
assert numzero(Vn - right)
# the written second term is the scalar V'.e2; even granting it the direction e2, the third term
# (V'.e3)(n x V) is |n x V| times the part along e3
granted = Vn.dot(n) * n + Vn.dot(e2) * e2 + Vn.dot(e3) * nxV
check(79, numzero(Vn - granted))
# 86: |V'| = |V| = |n x V|: the second equality fails unless V is across the axis
check(86, numzero(norm(Vn) - norm(nxV)) and numzero(norm(Vn) - norm(V)))
# 92: V'.V_perp = |V| |V_perp| cos theta and V'.(n x V) = |V| |n x V| sin theta, as written
lhs1, lhs2 = Vn.dot(Vperp), Vn.dot(nxV)
assert numzero(lhs1 - Vperp.dot(Vperp) * sp.cos(th))     # the true projections
assert numzero(lhs2 - nxV.dot(nxV) * sp.sin(th))
check(92, numzero(lhs1 - norm(V) * norm(Vperp) * sp.cos(th)) and numzero(lhs2 - norm(V) * norm(nxV) * sp.sin(th)))
# 101: V' = cos(theta) V + (1 - cos theta)(n.V) n + \sin theta (n x V); the source breaks the line
# between \sin and "theta" without its backslash, which sets sin of the letters t h e t a
assert numzero(Vn - (sp.cos(th) * V + (1 - sp.cos(th)) * V.dot(n) * n + sp.sin(th) * nxV))
t_, h_, e_, a_ = sp.symbols('t h e a', positive=True)
check(101, zero((Vn - (sp.cos(th) * V + (1 - sp.cos(th)) * V.dot(n) * n
                       + sp.sin(t_ * h_ * e_ * t_ * a_) * nxV)).subs({u: 0, w: 0})))
# 109: R^I_J = cos(theta) delta + (1 - cos theta) n^I n_J + sin(theta) eps^I_{JK} n^K
Rw = sp.Matrix(3, 3, lambda i, j: sp.cos(th) * int(i == j) + (1 - sp.cos(th)) * n[i] * n[j]
               + sp.sin(th) * sum(eps(i, j, k) * n[k] for k in range(3)))
check(109, numzero(Rw - Rn))
# 121: to first order R ~ delta + theta eps^I_{JK} n^K (the true first order has minus eps)
R1st = sp.Matrix(3, 3, lambda i, j: int(i == j) + th * sum(eps(i, j, k) * n[k] for k in range(3)))
Rtrue1 = I3 + th * K                                     # the Rodrigues form to first order in theta
check(121, numzero(R1st - Rtrue1))
# 128: the generators from R = 1 - i theta J.n/hbar: J = i hbar dR/dtheta at theta = 0
Jx = sp.I * hb * sp.Matrix([[0, 0, 0], [0, 0, -1], [0, 1, 0]])
Jy = sp.I * hb * sp.Matrix([[0, 0, 1], [0, 0, 0], [-1, 0, 0]])
Jz = sp.I * hb * sp.Matrix([[0, -1, 0], [1, 0, 0], [0, 0, 0]])
gen = lambda Rq: sp.I * hb * Rq(th).diff(th).subs(th, 0)  # noqa: E731
check(128, zero(Jx - gen(Rx)) and zero(Jy - gen(Ry)) and zero(Jz - gen(Rz)))
# 138: [J_I, J_J] = i hbar eps_IJK J_K
J = [Jx, Jy, Jz]
check(138, all(zero(J[i] * J[j] - J[j] * J[i] - sp.I * hb * sum((eps(i, j, k) * J[k] for k in range(3)),
                                                                   sp.zeros(3)))
               for i in range(3) for j in range(3)))
# 145: R(theta/N) = 1 - i (theta/N) hbar (J.n)/hbar, as written (the first order is 1 - i (theta/N) J.n/hbar)
N = sp.Symbol('N', positive=True)
Jn = n[0] * Jx + n[1] * Jy + n[2] * Jz
zax = {u: 0, w: 0}
small = I3 - sp.I * (th / N) * Jn.subs(zax) / hb
exact = Rn.subs(zax).subs(th, th / N)
assert zero((exact - small).applyfunc(lambda x: sp.limit(x * N, N, sp.oo)))          # agree to O(1/N^2)
written = I3 - sp.I * (th / N) * hb * Jn.subs(zax) / hb
check(145, zero((exact - written).applyfunc(lambda x: sp.limit(x * N, N, sp.oo))))
# 151: lim (1 + x/N)^N = lim e^{N ln(1 + x/N)} = lim e^{N(x/N + x^2/(2N^2) + ...)} = e^x;
# the log's second term is -x^2/(2N^2), written with a plus
x = sp.Symbol('x', real=True)
ser = sp.series(N * sp.log(1 + x / N), N, sp.oo, 3).removeO()
check(151, zero(sp.expand(ser - N * (x / N + x ** 2 / (2 * N ** 2)))))
# 162: the limit of R(theta/N)^N is exp(-i theta J.n/hbar): exp(theta K) is the Rodrigues matrix
check(162, zero(sp.simplify((-sp.I * th * Jn / hb).subs({u: 0, w: 0}).exp()) - Rn.subs({u: 0, w: 0}))
      and zero(sp.simplify((-sp.I * th * Jn / hb).subs({u: sp.pi / 2, w: 0}).exp()) - Rn.subs({u: sp.pi / 2, w: 0})))

# SU(2)
ar, ai, br, bi = sp.symbols('a_r a_i b_r b_i', real=True)
a, b = ar + sp.I * ai, br + sp.I * bi
sx, sy, sz = sp.Matrix([[0, 1], [1, 0]]), sp.Matrix([[0, -sp.I], [sp.I, 0]]), sp.Matrix([[1, 0], [0, -1]])
M = sp.Matrix([[a, b], [-sp.conjugate(b), sp.conjugate(a)]])
# 171: the second row written "- b^* a^*" without its &, one entry (the product) where two belong
check(171, list(M.row(1)) == [-sp.conjugate(b) * sp.conjugate(a)])
assert zero(M * M.H - sp.eye(2).subs({}) * (ar**2 + ai**2 + br**2 + bi**2)) and zero(M.det() - (ar**2 + ai**2 + br**2 + bi**2))
# 178: M = a_r 1 + i b_i sigma_x + i b_r sigma_y + i a_i sigma_z
check(178, zero(M - (ar * sp.eye(2) + sp.I * bi * sx + sp.I * br * sy + sp.I * ai * sz)))
# 185: with a_i, b_r, b_i small and a_r = 1 to second order, M ~ 1 + i alpha n.sigma,
# alpha n = (b_i, b_r, a_i) (line 191)
es = sp.Symbol('epsilon', positive=True)
Mlin = (M.subs({ai: es * ai, br: es * br, bi: es * bi, ar: sp.sqrt(1 - es**2 * (ai**2 + br**2 + bi**2))})
        .applyfunc(lambda z: sp.series(z, es, 0, 2).removeO()))
check(185, zero(Mlin - (sp.eye(2) + sp.I * es * (bi * sx + br * sy + ai * sz))))
# 197: J = hbar sigma/2 satisfy [J_I, J_J] = i hbar eps J_K
S = [hb / 2 * s for s in (sx, sy, sz)]
check(197, all(zero(S[i] * S[j] - S[j] * S[i] - sp.I * hb * sum((eps(i, j, k) * S[k] for k in range(3)),
                                                                   sp.zeros(2)))
               for i in range(3) for j in range(3)))
# 203: with theta = 2 alpha, 1 + i alpha n.sigma = 1 + i theta (J.n)/hbar
nn = sp.Matrix(sp.symbols('n1:4', real=True))
check(203, zero(sp.I * al * (nn[0] * sx + nn[1] * sy + nn[2] * sz)
                - sp.I * (2 * al) * (nn[0] * S[0] + nn[1] * S[1] + nn[2] * S[2]) / hb))

LINES = [14, 27, 33, 40, 46, 57, 68, 79, 86, 92, 101, 109, 121, 128, 138, 145, 151, 162, 171, 178, 185, 191,
         197, 203]
NC, H_ = "not a claim", "holds"
ROWS = {
    14: (NC, "the book's macro definitions (\\half, \\eps, \\CC, \\CR, \\cO) copied from its _config.yml"),
    27: (NC, "defines how a rotation acts on a vector's components"),
    33: (H_, "for an orthogonal R, sum_I R^I_J R^I_K = delta_JK, so the length is kept (check 33)"),
    40: (H_, "the transpose of a product and R^T = R^-1 for orthogonal matrices (check 40)"),
    46: (H_, "det(R^T R) = det(R)^2 = det 1 = 1 for an orthogonal matrix (check 46)"),
    57: (NC, "defines the parity matrix"),
    68: (NC, "defines the parts of V along and across the axis"),
    79: ("fails",
         "in an orthonormal basis V' = (V'.n) n + (V'.e2) e2 + (V'.e3) e3 with e2 = V_perp/|V_perp| and e3 = n x V/|n x V|; "
         "the display's second term V'.e2 is a number, not a vector (it lacks e2), and its third term multiplies by "
         "n x V where the unit vector n x V/|n x V| belongs (check 79)",
         "",
         "By hand: the second term \\vec V'\\cdot \\vec V_perp/||V_perp|| is a dot product, a scalar, added to vectors; "
         "and (V'.e3)(n x V) = (V'.e3)|n x V| e3 is |n x V| times the component along e3, so the sum is not V' "
         "unless |n x V| = 1 and the second term is given its direction.",
         "Numbers: n = z, V = (0, 2, 1), theta = pi/2, so V' = (-2, 0, 1), V_perp = (0, 2, 0), n x V = (-2, 0, 0); "
         "the second term is the number V'.V_perp/|V_perp| = 0, and the third is (V'.(-1, 0, 0)) (-2, 0, 0) = "
         "2 (-2, 0, 0) = (-4, 0, 0); the sum (even granting the second term its direction) is (-4, 0, 1), not "
         "V' = (-2, 0, 1)."),
    86: ("fails",
         "|V'| = |V| holds (a rotation keeps lengths), but |n x V| = |V_perp| equals |V| only when V is across the "
         "axis (check 86)",
         "",
         "By hand: |n x V| = |V| sin(angle between n and V) = |V_perp|, which is less than |V| whenever V has a part "
         "along n.",
         "Numbers: n = z, V = (1, 0, 1): |V| = sqrt 2, n x V = (0, 1, 0), |n x V| = 1."),
    92: ("fails",
         "V' = V_par + V'_perp with V'_perp the turned V_perp, so V'.V_perp = |V_perp|^2 cos theta and "
         "V'.(n x V) = |n x V|^2 sin theta; the display has |V| where |V_perp| (= |n x V|) belongs in both lines "
         "(check 92)",
         "",
         "By hand: V_par is orthogonal to V_perp and to n x V, and V'_perp makes the angle theta with V_perp in the "
         "plane across n with |V'_perp| = |V_perp| = |n x V|; so each product is |V_perp|^2 times cos or sin theta.",
         "Numbers: n = z, V = (1, 0, 1), theta = 0: V' = V, V'.V_perp = (1,0,1).(1,0,0) = 1, the display gives "
         "|V| |V_perp| = sqrt 2."),
    101: ("typo",
          "the rotation formula V' = cos(theta) V + (1 - cos theta)(n.V) n + sin(theta) n x V holds, but the source "
          "breaks the line between \\sin and theta and writes theta without its backslash, which sets sin of the "
          "letters t h e t a (check 101)",
          "{\\vec V}' = \\cos\\theta {\\vec V} + (1 - \\cos\\theta){\\hat n}\\cdot{\\vec V} {\\hat n} + \\sin\\theta {\\hat n}\\times{\\vec V}",
          "By hand: the TeX reads \\sin followed by a line break and the letters theta; TeX sets the operator sin "
          "applied to the product t h e t a, not to the angle \\theta used everywhere else in the display.",
          "Numbers: n = z, V = (1, 0, 0), theta = pi/2: V' = (0, 1, 0); the display's last term is sin(t h e t a) "
          "(0, 1, 0), which depends on the letters t, h, e, a, and is (0, 1, 0) only if their product's sine is 1."),
    109: ("typo",
          "with (n x V)^I = eps^I_{KJ} n^K V^J the matrix of the rotation formula has - sin(theta) eps^I_{JK} n^K; "
          "the display's + sin(theta) eps^I_{JK} n^K turns V the other way, against the formula before it and the "
          "generators after it (check 109)",
          "R^I_J = \\cos\\theta \\delta^I_J + (1 - \\cos\\theta) n^I n_J + \\sin\\theta \\epsilon^I{}_{KJ} n^K",
          "By hand: eps^I_{JK} n^K V^J = eps_{IJK} V_J n_K = (V x n)_I = -(n x V)_I, so the display gives "
          "V' = cos(theta) V + (1 - cos theta)(n.V) n - sin(theta) n x V, the rotation by -theta.",
          "Numbers: n = z, theta = pi/2, V = (1, 0, 0): the formula before gives V' = (0, 1, 0); the display's matrix "
          "has R^2_1 = sin(theta) eps_{213} = -1, so V' = (0, -1, 0)."),
    121: ("fails",
          "to first order the rotation is delta^I_J - theta eps^I_{JK} n^K; the display keeps the sign of the matrix "
          "before it (line 109) and so has + theta eps^I_{JK} n^K, the inverse rotation, against the generators at "
          "line 128 (check 121)",
          "",
          "By hand: expanding the Rodrigues form V' = V + theta n x V + O(theta^2), and (n x V)^I = -eps^I_{JK} n^K V^J.",
          "Numbers: n = z, V = (1, 0, 0), theta small: V' is about (1, theta, 0); the display gives "
          "R^2_1 = theta eps_{213} = -theta, V' = (1, -theta, 0)."),
    128: (H_, "J_I = i hbar dR_I/dtheta at theta = 0 for the rotations about x, y and z (check 128)"),
    138: (H_, "the matrices of line 128 satisfy [J_I, J_J] = i hbar eps_IJK J_K (check 138)"),
    145: ("typo",
          "an infinitesimal rotation by theta/N is 1 - i (theta/N) J.n/hbar; the display writes an extra factor hbar, "
          "(theta/N) hbar (J.n)/hbar = (theta/N) J.n, which has the dimension of hbar (check 145)",
          "R(\\theta/N, {\\hat n}) = {\\bf 1} - i \\frac{\\theta}{N} \\frac{{\\vec J}\\cdot{\\hat n}}{\\hbar}",
          "By hand: R(n) = 1 - i theta J.n/hbar was the definition at line 128's prose; putting theta/N for theta "
          "gives 1 - i (theta/N) J.n/hbar, and the display's hbar times (J.n/hbar) cancels the 1/hbar.",
          "Numbers: n = z, N = 1, small theta: R = 1 + theta [[0,-1,0],[1,0,0],[0,0,0]]; the display gives "
          "1 - i theta J_z = 1 + theta hbar [[0,-1,0],[1,0,0],[0,0,0]], off by the factor hbar (hbar = 2: twice)."),
    151: ("typo",
          "ln(1 + u) = u - u^2/2 + ..., so N ln(1 + x/N) = N(x/N - x^2/(2N^2) + ...); the display writes + x^2/(2N^2) "
          "(the limit e^x is right; the source also writes \\to infty without its backslash) (check 151)",
          "\\lim_{N\\to\\infty} e^{N \\left( \\frac{x}{N} - \\frac{x^2}{2 N^2} + \\ldots\\right)}",
          "By hand: d/du ln(1 + u) = 1/(1 + u) = 1 - u + ..., integrating gives u - u^2/2 + ..., so the second term "
          "has a minus sign.",
          "Numbers: x = 1, N = 10: N ln(1.1) = 0.953102; N(x/N + x^2/(2N^2)) = 1.05 and N(x/N - x^2/(2N^2)) = 0.95."),
    162: (H_, "the limit of (1 - i theta J.n/(N hbar))^N is the exponential, and exp(-i theta J.n/hbar) is the "
               "rotation matrix (check 162)"),
    171: ("typo",
          "an SU(2) matrix is [[a, b], [-b^*, a^*]]; the second row written \"- b^* a^*\" lacks its &, so it sets one "
          "entry, the product -b^* a^*, where two belong (check 171)",
          "M = \\begin{pmatrix} a & b \\\\ - b^* & a^* \\end{pmatrix}",
          "By hand: in pmatrix, & separates the entries of a row; \"- b^* a^*\" is one entry, the product of -b^* and "
          "a^*, so the array has two entries in its first row and one in its second, not a 2 by 2 matrix.",
          "Numbers: a = 1, b = 0: the SU(2) element is the identity [[1, 0], [0, 1]]; the display's second row is the "
          "single entry -0 * 1 = 0, with no entry 1 on the diagonal."),
    178: (H_, "a_r 1 + i a_i sigma_z gives the diagonal a, a^*, and i b_i sigma_x + i b_r sigma_y the off-diagonal "
               "b and -b^* (check 178)"),
    185: (H_, "with a_i, b_r, b_i of order epsilon and a_r = sqrt(1 - ...) = 1 + O(epsilon^2), M = 1 + i(b_i sigma_x "
               "+ b_r sigma_y + a_i sigma_z) to first order (check 185)"),
    191: (NC, "defines the unit vector n-hat from (b_i, b_r, a_i)"),
    197: (H_, "the Pauli matrices times hbar/2 satisfy the angular-momentum commutators (check 197)"),
    203: (H_, "i alpha n.sigma = i (2 alpha)(n.(hbar sigma/2))/hbar (check 203)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
