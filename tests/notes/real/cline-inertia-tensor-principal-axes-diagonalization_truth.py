"""Independent SymPy truth table for cline-inertia-tensor-principal-axes-diagonalization.md.

The text's own setting: a rigid body of point masses m_alpha (two generic ones here, enough for sums that are
linear in their summand), positions r_alpha = (x_alpha,1, x_alpha,2, x_alpha,3) in the body frame about a
point O, angular velocity omega; the body frame turns with Q(t) = Rz(phi) Rx(theta) Rz(psi) (the z-x-z
angles) and its origin moves with V. The inertia tensor is I_ij = sum m (delta_ij r^2 - x_i x_j) and the
angular momentum L = sum m r x (omega x r). The eigenvalue displays are the conditions the text imposes
(not claims). Every check is built from these definitions, never from the text's later displays.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero
t = sp.Symbol('t', real=True)
E3 = sp.eye(3)
m1, m2, k = sp.symbols('m_1 m_2 k', positive=True)
ms = [m1, m2]

# Newton's laws for two particles with external forces and a central internal pair force
r1 = sp.Matrix([sp.Function(f'x1{c}')(t) for c in 'abc'])
r2 = sp.Matrix([sp.Function(f'x2{c}')(t) for c in 'abc'])
F1, F2 = sp.Matrix(sp.symbols('F1:4', real=True)), sp.Matrix(sp.symbols('G1:4', real=True))
f12 = k * (r1 - r2)
acc = {**{r1.diff(t, 2)[i]: ((F1 + f12) / m1)[i] for i in range(3)},
       **{r2.diff(t, 2)[i]: ((F2 - f12) / m2)[i] for i in range(3)}}
P = m1 * r1.diff(t) + m2 * r2.diff(t)
Lt = m1 * r1.cross(r1.diff(t)) + m2 * r2.cross(r2.diff(t))
check(23, zero(P.diff(t).subs(acc) - (F1 + F2)))
check(29, zero(Lt.diff(t).subs(acc) - (r1.cross(F1) + r2.cross(F2))))

# velocity of a point seen from a moving, turning frame: r = R + Q r'_b
ph, th, ps = [sp.Function(n)(t) for n in ('phi', 'theta', 'psi')]
Q = truth_table.Rz(ph) * truth_table.Rx(th) * truth_table.Rz(ps)
Rc = sp.Matrix([sp.Function(f'R{c}')(t) for c in 'abc'])
rb = sp.Matrix([sp.Function(f'b{c}')(t) for c in 'abc'])
Sk = Q.diff(t) * Q.T
w_space = sp.Matrix([Sk[2, 1], Sk[0, 2], Sk[1, 0]])
v_total = (Rc + Q * rb).diff(t)
check(49, truth_table.numeric_zero(v_total - (Rc.diff(t) + Q * rb.diff(t) + w_space.cross(Q * rb)), t))
rb0 = sp.Matrix(sp.symbols('c1:4', real=True))       # fixed in the body: v'' = 0
check(55, truth_table.numeric_zero((Rc + Q * rb0).diff(t) - (Rc.diff(t) + w_space.cross(Q * rb0)), t))

# point masses in the body frame, omega
w = sp.Matrix(sp.symbols('omega_1:4', real=True))
X = [sp.Matrix(sp.symbols(f'x_{a}1:4', real=True)) for a in 'pq']
alpha = sp.Symbol('alpha', positive=True)             # the written factor 'alpha' of r\alpha
check(61, truth_table.numeric_zero(m1 * (Q * rb0).diff(t) - m1 * w_space.cross(Q * rb0), t))   # V = 0, r = r'
Ltrue = sum((m * p.cross(w.cross(p)) for m, p in zip(ms, X)), sp.zeros(3, 1))
Lwritten = sum((m * p.cross(w.cross(alpha * p)) for m, p in zip(ms, X)), sp.zeros(3, 1))
check(67, zero(Lwritten - Ltrue))
SLIP_67_FIXED = zero(sum((m * p.cross(w.cross(p)) for m, p in zip(ms, X)), sp.zeros(3, 1)) - Ltrue)
A, B = sp.Matrix(sp.symbols('A1:4', real=True)), sp.Matrix(sp.symbols('B1:4', real=True))
check(73, zero(A.cross(B.cross(A)) - (A.dot(A) * B - A * A.dot(B))))
check(79, zero(sum((m * (p.dot(p) * w - p * p.dot(w)) for m, p in zip(ms, X)), sp.zeros(3, 1)) - Ltrue))
L9 = sp.Matrix([sum(m * (w[i] * sum(p[kk] ** 2 for kk in range(3)) - p[i] * sum(p[j] * w[j] for j in range(3)))
                    for m, p in zip(ms, X)) for i in range(3)])
check(85, zero(L9 - Ltrue))
d = lambda i, j: 1 if i == j else 0
check(91, all(zero(w[i] - sum(w[j] * d(i, j) for j in range(3))) for i in range(3)))
Iten = sp.Matrix(3, 3, lambda i, j: sum(m * (d(i, j) * sum(p[kk] ** 2 for kk in range(3)) - p[i] * p[j])
                                        for m, p in zip(ms, X)))
line1 = sp.Matrix([sum(m * sum(w[j] * d(i, j) * sum(p[kk] ** 2 for kk in range(3)) - w[j] * p[i] * p[j]
                                   for j in range(3)) for m, p in zip(ms, X)) for i in range(3)])
check(103, zero(line1 - Ltrue) and zero(Iten * w - Ltrue))

# the tensor's entries in cartesian names
x_, y_, z_ = [[p[i] for p in X] for i in range(3)]
Ixx = sum(m * (a ** 2 + b ** 2 + c ** 2 - a ** 2) for m, a, b, c in zip(ms, x_, y_, z_))
check(129, zero(Ixx - sum(m * (b ** 2 + c ** 2) for m, b, c in zip(ms, y_, z_))) and zero(Ixx - Iten[0, 0]) and
      zero(sum(m * (a ** 2 + b ** 2 + c ** 2 - b ** 2) for m, a, b, c in zip(ms, x_, y_, z_)) - Iten[1, 1]) and
      zero(sum(m * (a ** 2 + b ** 2 + c ** 2 - c ** 2) for m, a, b, c in zip(ms, x_, y_, z_)) - Iten[2, 2]))
check(143, zero(Iten[1, 0] - Iten[0, 1]) and zero(Iten[0, 1] + sum(m * a * b for m, a, b in zip(ms, x_, y_))) and
      zero(Iten[2, 0] - Iten[0, 2]) and zero(Iten[2, 1] - Iten[1, 2]))
check(149, zero(Iten - Iten.T))
check(155, zero(Iten * w - Ltrue))
check(161, zero(Iten * w - Ltrue))
check(186, zero(Iten * w - Ltrue))

# principal axes: omega along a principal axis j
I1, I2, I3 = sp.symbols('I_1 I_2 I_3', positive=True)
wj = sp.Symbol('omega_j', real=True)
check(208, all(zero(sp.diag(I1, I2, I3) * (wj * E3[:, j]) - [I1, I2, I3][j] * wj * E3[:, j]) for j in range(3)))
# the angular momentum in components (its link = I omega_i is the condition imposed)
check(247, zero(Iten * w - Ltrue))

# negative controls: the checks can fail, and the slip's correction holds
assert SLIP_67_FIXED
assert not zero(A.cross(B.cross(A)) - (A.dot(A) * B + A * A.dot(B)))

LINES = [23, 29, 40, 49, 55, 61, 67, 73, 79, 85, 91, 97, 103, 117, 123, 129, 143, 149, 155, 161, 172, 178, 186,
         192, 201, 208, 216, 222, 228, 234, 241, 247, 253, 259, 266]

ROWS = {
    23: ("holds", "sum of m a = sum of the external forces, the central internal pair cancelling (check 23)"),
    29: ("holds", "d/dt sum r x m v = sum r x F_ext with central internal forces (check 29)"),
    40: ("not a claim", "defines the angular momentum about O"),
    49: ("holds", "velocity in the fixed frame of a point moving in a frame that moves with V and turns with omega (check 49, numeric)"),
    55: ("holds", "the same with the point fixed in the body (check 55, numeric)"),
    61: ("holds", "p = m v and, with V = 0 and r = r', v = omega x r (check 61)"),
    67: ("typo", "the last factor is written \\mathbf{ r}\\alpha, r times alpha, for the particle's r_alpha",
         "\\mathbf{L} = \\sum^N_{\\alpha} \\mathbf{r}_{\\alpha} \\times \\mathbf{ p}_{\\alpha} = \\sum^N_{\\alpha} m_{\\alpha} \\mathbf{r}_{\\alpha} \\times (\\boldsymbol{\\omega} \\times\\mathbf{r}_{\\alpha} )",
         "hand-checked twice: the subscript's underscore is missing, so the display multiplies the vector r by the index alpha; with p_alpha = m_alpha omega x r_alpha the sum is sum m_alpha r_alpha x (omega x r_alpha), which the written one equals only when alpha = 1",
         "hand-checked twice: for one particle (alpha = 1 only) the two agree, but for the second particle the written term is 2 m_2 r_2 x (omega x r_2), twice the particle's angular momentum: L would not be sum r x p, the display's own first member"),
    73: ("holds", "A x (B x A) = A^2 B - A (A . B) (check 73)"),
    79: ("holds", "sum m [r^2 omega - r (r . omega)] = sum m r x (omega x r) (check 79)"),
    85: ("holds", "the component form of the previous display (check 85)"),
    91: ("holds", "the Kronecker delta picks omega_i out of the sum (check 91)"),
    97: ("not a claim", "defines the Kronecker delta"),
    103: ("holds", "13.10 put into 13.9, then the sums over alpha and j exchanged (check 103)"),
    117: ("not a claim", "defines the inertia tensor"),
    123: ("not a claim", "the definition for a continuous body"),
    129: ("holds", "the moments of inertia: x^2 + y^2 + z^2 - x^2 = y^2 + z^2, and the entries are the tensor's diagonal (check 129)"),
    143: ("holds", "the products of inertia: the tensor's off-diagonal entries, -sum m x y and so on, are symmetric (check 143)"),
    149: ("holds", "the tensor is symmetric (check 149)"),
    155: ("holds", "L_i = sum_j I_ij omega_j (check 155)"),
    161: ("holds", "the same written out in cartesian components (check 161)"),
    172: ("not a claim", "names the tensor's matrix"),
    178: ("not a claim", "writes omega and L as columns"),
    186: ("holds", "L = I . omega (check 186)"),
    192: ("not a claim", "the text's figure of speech: the tensor as the 'ratio' of L to omega"),
    201: ("not a claim", "the form of the tensor in principal axes"),
    208: ("holds", "with omega along a principal axis j, L = I_j omega_j j-hat (check 208)"),
    216: ("not a claim", "the eigenvalue problem to be solved"),
    222: ("not a claim", "the eigenvalue problem with the unit tensor"),
    228: ("not a claim", "defines the unit tensor"),
    234: ("not a claim", "the eigenvalue problem rewritten"),
    241: ("not a claim", "the secular equation to be solved for the principal moments I"),
    247: ("holds", "L_i = sum_j I_ij omega_j in components; = I omega_i is the condition the text imposes (check 247)"),
    253: ("not a claim", "the imposed condition rewritten"),
    259: ("not a claim", "the secular determinant set to zero, to be solved for I"),
    266: ("not a claim", "the conditions on the direction numbers of the principal axis of I_1"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, {k: (v[0], v[1], v[2] if len(v) > 2 else None, *(v[3:5] if len(v) > 3 else ()))
                                           for k, v in ROWS.items()}, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
