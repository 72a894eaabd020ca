"""Independent SymPy truth table for songtech-notes-rigid-body-inertia-tensor-principal-axes.md.

The notes' convention: particle i has mass m_i and position r_i = (x_i, y_i, z_i) from the centre of
mass (the origin), omega is the angular velocity, the inertia tensor is
I_ak = sum_i m_i (delta_ak r_i^2 - r_a r_k). Sums over the body are checked on three particles with
symbolic masses and positions (the centre of mass at the origin where a display needs it); the
block's moments are integrals over -a/2..a/2, -b/2..b/2, -c/2..c/2 with rho = M/(abc).
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}
zero = truth_table.zero


def check(key, ok):
    CHECKS[key] = bool(ok)


w = sp.Matrix(sp.symbols('omega_1:4', real=True))
vcm = sp.Matrix(sp.symbols('V_1:4', real=True))
ms = sp.symbols('m_1:4', positive=True)
rs = [sp.Matrix(sp.symbols(f'x{i} y{i} z{i}', real=True)) for i in range(3)]


def Imat(r):
    return r.dot(r) * sp.eye(3) - r * r.T


Itot = sum((mi * Imat(ri) for mi, ri in zip(ms, rs)), sp.zeros(3, 3))
# the centre of mass at the origin: the third particle's position fixed by sum m_i r_i = 0
cm = {c: sp.solve(sum(mi * ri[n] for mi, ri in zip(ms, rs)), c)[0]
      for n, c in enumerate(rs[2])}

# 25: the total kinetic energy; its third member writes (omega + r_i)^2 for (omega x r_i)^2
K = sum(mi * (vcm + w.cross(ri)).dot(vcm + w.cross(ri)) for mi, ri in zip(ms, rs)) / 2
third = sum(mi * (vcm.dot(vcm) + 2 * vcm.dot(w.cross(ri)) + (w + ri).dot(w + ri)) for mi, ri in zip(ms, rs)) / 2
fourth = sum(mi * vcm.dot(vcm) for mi in ms) / 2 + sum(mi * w.cross(ri).dot(w.cross(ri)) for mi, ri in zip(ms, rs)) / 2
check(34, zero(K - third) and zero((K - fourth).subs(cm)))
# 34: the rotational part by the identity for the square of a cross product
Krot = sum(mi * w.cross(ri).dot(w.cross(ri)) for mi, ri in zip(ms, rs)) / 2
check(45, zero(Krot - sum(mi * (w.dot(w) * ri.dot(ri) - w.dot(ri) ** 2) for mi, ri in zip(ms, rs)) / 2))
# 54: omega_1 picked out by the delta
check(66, zero(sum(w[k] * sp.eye(3)[0, k] for k in range(3)) - w[0]))
# 66: r.r as the double delta sum (b summed), equal to the sum of squares
r = rs[0]
check(77, zero(sum(sum(r[a] * sp.eye(3)[a, b] for a in range(3)) ** 2 for b in range(3)) - r.dot(r)))
# 77: omega^2 likewise
check(87, zero(sum(sum(w[k] * sp.eye(3)[j, k] for k in range(3)) ** 2 for j in range(3)) - w.dot(w)))
# 87: the chain for K_rot; its second member squares sum omega_k^2
second = sum(mi * (w.dot(w) ** 2 * ri.dot(ri) - ri.dot(w) ** 2) for mi, ri in zip(ms, rs)) / 2
last = (w.T * Itot * w)[0] / 2
check(99, zero(Krot - second) and zero(Krot - last))
# 111: the diagonal entries, r^2 - r_a^2
check(117, all(zero(Itot[a, a] - sum(mi * (ri.dot(ri) - ri[a] ** 2) for mi, ri in zip(ms, rs))) for a in range(3)))
# 117: the off-diagonal entries
check(123, all(zero(Itot[a, k] + sum(mi * ri[a] * ri[k] for mi, ri in zip(ms, rs)))
               for a in range(3) for k in range(3) if a != k))
# 123: K = I omega^2 / 2 with I the moment about the axis of omega
n = w / w.norm()
check(129, zero(Krot - (n.T * Itot * n)[0] * w.dot(w) / 2))
# 129: the tensor restated with delta_ak sum_a r_a (no square)
restated = sum((mi * (sum(ri) * sp.eye(3) - ri * ri.T) for mi, ri in zip(ms, rs)), sp.zeros(3, 3))
check(137, zero(restated - Itot))
# 137: entry by entry
xs = [ri[0] for ri in rs]; ys = [ri[1] for ri in rs]; zs = [ri[2] for ri in rs]
S = lambda f: sum(mi * f(i) for i, mi in enumerate(ms))
entries = sp.Matrix([[S(lambda i: ys[i]**2 + zs[i]**2), -S(lambda i: xs[i]*ys[i]), -S(lambda i: xs[i]*zs[i])],
                     [-S(lambda i: ys[i]*xs[i]), S(lambda i: xs[i]**2 + zs[i]**2), -S(lambda i: ys[i]*zs[i])],
                     [-S(lambda i: zs[i]*xs[i]), -S(lambda i: zs[i]*ys[i]), S(lambda i: xs[i]**2 + ys[i]**2)]])
check(143, zero(entries - Itot))
# 143: the double sum as the quadratic form
check(163, zero(sum(Itot[a, k] * w[a] * w[k] for a in range(3) for k in range(3)) / 2 - (w.T * Itot * w)[0] / 2)
      and zero(Krot - last))
# the block
a, b, c, M = sp.symbols('a b c M', positive=True)
x1, x2, x3 = sp.symbols('x_1 x_2 x_3', real=True)
rho = M / (a * b * c)


def box(f):
    return sp.integrate(f, (x1, -a / 2, a / 2), (x2, -b / 2, b / 2), (x3, -c / 2, c / 2))


I11 = box(rho * (x2**2 + x3**2))
# 181: the chain for I_11; its members include [x_2^2/3] at the ends (zero) and (1/2)(M/abc)(ab^3c + abc^3)
m7 = sp.Rational(1, 2) * M / (a * b * c) * (a * b**3 * c + a * b * c**3)
m6 = rho * (a * c * (x2**2 / 3).subs(x2, b / 2) - a * c * (x2**2 / 3).subs(x2, -b / 2)) \
    + (a * b * (x3**2 / 3).subs(x3, c / 2) - a * b * (x3**2 / 3).subs(x3, -c / 2))
check(187, zero(I11 - M * (b**2 + c**2) / 12) and zero(I11 - m7) and zero(I11 - m6))
# 187: the other entries
check(203, zero(box(rho * (x1**2 + x3**2)) - M * (a**2 + c**2) / 12)
      and zero(box(rho * (x1**2 + x2**2)) - M * (a**2 + b**2) / 12)
      and all(zero(box(rho * p)) for p in (x1 * x2, x1 * x3, x2 * x3)))
Ibox = sp.diag(box(rho * (x2**2 + x3**2)), box(rho * (x1**2 + x3**2)), box(rho * (x1**2 + x2**2)))
# 203: the block's tensor
check(213, zero(Ibox - M / 12 * sp.diag(b**2 + c**2, a**2 + c**2, a**2 + b**2)))
# 213: the thin plate, c -> 0
check(221, zero(sp.simplify(Ibox).subs(c, 0) - M / 12 * sp.diag(b**2, a**2, a**2 + b**2)))
# 221: K_rot and L_i = sum_j I_ij omega_j (L = sum m r x (omega x r))
L = sum((mi * ri.cross(w.cross(ri)) for mi, ri in zip(ms, rs)), sp.zeros(3, 1))
check(231, zero(L - Itot * w) and zero(Krot - (w.T * Itot * w)[0] / 2))
# 258: parallel axes: I' about the point at d from the centre of mass; I_cm = I' - M(d^2 delta - d d)
d = sp.Matrix(sp.symbols('d_1:4', real=True))
Mt = sum(ms)
Iprime = sum((mi * Imat(ri - d) for mi, ri in zip(ms, rs)), sp.zeros(3, 3))
check(258, zero((Itot - (Iprime - Mt * (d.dot(d) * sp.eye(3) - d * d.T))).subs(cm)))
# 264: a lamina in z = 0
lam = {ri[2]: 0 for ri in rs}
check(264, zero((Itot[2, 2] - Itot[0, 0] - Itot[1, 1]).subs(lam)))

LINES = [19, 25, 34, 45, 54, 66, 77, 87, 99, 111, 117, 123, 129, 137, 143, 163, 181, 187, 203, 213, 221,
         231, 240, 246, 258, 264]
NC, H_ = "not a claim", "holds"
ROWS = {
    25: (NC, "names the components of the position of particle i and of the angular velocity"),
    19: (NC, "the velocity of a point of a rigid body, v_i = v_cm + omega x r_i: the kinematics the section starts from"),
    34: ("typo",
         "the first, second and last members agree (with the origin at the centre of mass, sum m_i r_i = 0 removes the "
         "cross term), but the third member writes (omega + r_i)^2 where the expansion of the square has (omega x r_i)^2 "
         "(check 34)",
         "(\\vec \\omega \\times \\mathbf{r}_i)^2",
         "By hand: (v_cm + omega x r_i)^2 = v_cm^2 + 2 v_cm . (omega x r_i) + (omega x r_i)^2; the display's third member "
         "has (omega + r_i)^2 = omega^2 + 2 omega . r_i + r_i^2 in the last place, which is not the square of omega x r_i.",
         "Numbers: one particle, m = 1, r = (1, 0, 0), omega = (0, 0, 1), v_cm = 0: (omega x r)^2 = |(0, 1, 0)|^2 = 1, so "
         "K = 1/2; the third member gives (1/2)(omega + r)^2 = (1/2)|(1, 0, 1)|^2 = 1."),
    45: (H_, "(A x B)^2 = A^2 B^2 - (A . B)^2 summed over the particles (check 45)"),
    54: (NC, "the Kronecker delta as the entries of the identity matrix (a definition)"),
    66: (H_, "sum_k omega_k delta_1k = omega_1 (check 66)"),
    77: (H_, "with b summed, (sum_a r_a delta_ab)^2 summed over b is sum_a r_a^2 (check 77)"),
    87: (H_, "omega_j omega_j with the deltas is the sum of the squares (check 87)"),
    99: ("typo",
         "the first, third, fourth and last members agree with (1/2) omega . I . omega; the second member writes "
         "(sum_k omega_k^2)^2 where omega^2 = sum_k omega_k^2 is meant, which is fourth order in omega (check 99)",
         "\\left(\\sum_{k=1}^3 \\omega_k^2\\right) \\left(\\sum_{a = 1}^3 {r_a^{(i)}}^2\\right)",
         "By hand: omega^2 = omega . omega = sum_k omega_k^2 (the previous display), so omega^2 r_i^2 = (sum_k omega_k^2)"
         "(sum_a r_a^2); squaring the first bracket again gives omega^4 r_i^2.",
         "Numbers: one particle, m = 1, r = (1, 0, 0), omega = (0, 0, 2): K_rot = (1/2)|omega x r|^2 = (1/2) 4 = 2; the "
         "second member gives (1/2)[(4)^2 (1) - 0] = 8."),
    111: (NC, "defines the inertia tensor I_ak as the sum over particles"),
    117: (H_, "the diagonal entry is r^2 - r_a^2 summed over the particles, reading x_a^{(i)}, y_a^{(i)}, z_a^{(i)} as the "
               "particle's coordinates (check 117)"),
    123: (H_, "the off-diagonal entry -sum m_i r_a r_k (check 123)"),
    129: (H_, "K = I omega^2 / 2 with I = n . I . n the moment about the axis n of omega (check 129); the notes' gloss that "
               "it is a limit of many particles is prose, the formula holds"),
    137: ("typo",
           "the restatement writes delta_ak sum_a r_a^{(i)} where the definition (line 111) has the sum of the squares "
           "sum_a (r_a^{(i)})^2; as written the diagonal entry is linear in the coordinates (check 137)",
           "I_{ak} = \\sum_i^{N_\\text{particles}} m_i \\left[\\delta_{ak} \\sum_{a=1}^3 {r_a^{(i)}}^2 - r_a^{(i)} r_k^{(i)}\\right]",
           "By hand: the definition at line 111 has delta_ak sum_a (r_a^{(i)})^2; here the square is missing, so the "
           "bracket mixes a length with a squared length and the entry has no consistent units.",
           "Numbers: one particle, m = 1, r = (2, 0, 0): I_22 = m(x^2 + z^2) = 4; the display gives 1 (2 + 0 + 0) - 0 = 2."),
    143: (H_, "the entries written out: sums of m(y^2 + z^2), -m x y and so on (check 143)"),
    163: (H_, "the double sum equals the quadratic form omega^T I omega / 2 (check 163)"),
    181: (NC, "the continuum form of the inertia tensor, the sum replaced by the integral over the density (a definition)"),
    187: ("fails",
          "the first and last members agree (I_11 = M(b^2 + c^2)/12), but the chain passes through members that do not: the "
          "bracket [ac x_2^2/3] at -b/2 and b/2 is zero (x_2^3/3 is meant), and (1/2)(M/abc)(ab^3c + abc^3) = M(b^2 + c^2)/2, "
          "six times the result (check 187)",
          "",
          "By hand: int_{-b/2}^{b/2} x_2^2 dx_2 = b^3/12, so rho a c b^3/12 + rho a b c^3/12 with rho = M/(abc) is "
          "M(b^2 + c^2)/12; the display's coefficient 1/2 in front of (M/abc)[ab^3c + abc^3] gives M(b^2 + c^2)/2, and "
          "[(1/3) x_2^2] between -b/2 and b/2 is b^2/12 - b^2/12 = 0.",
          "Numbers: M = 1, a = b = c = 1: I_11 = 1/12 (b^2 + c^2) = 1/6; the member (1/2)(1/1)(1 + 1) = 1, not 1/6."),
    203: (H_, "I_22 = M(a^2 + c^2)/12, I_33 = M(a^2 + b^2)/12 and the products vanish for the centred block (check 203)"),
    213: (H_, "the block's tensor (check 213)"),
    221: (H_, "c -> 0 in the block's tensor (check 221)"),
    231: (H_, "K_rot = (1/2) sum I_ij omega_i omega_j and L = sum m r x (omega x r) = I omega (check 231)"),
    240: (NC, "diagonalisation by the matrix of eigenvectors: defines I_p"),
    246: (NC, "the form of the diagonal tensor, naming the principal moments"),
    258: (H_, "I' about a point at displacement r from the centre of mass is I_cm + M(r^2 delta - r r), so I_cm = I' - "
               "M(r^2 delta - r r) (check 258)"),
    264: (H_, "for a lamina in z = 0, I_zz = sum m(x^2 + y^2) = I_xx + I_yy (check 264)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
