"""Independent SymPy truth table for edinburgh-lagrangian-dynamics-euler-equations-free-tops.tex.

The text's own setting: a rigid body of particles m_a at body points s_a, turned by a rotation R(t)
(built here from three angles about z, x, z), so r_a = R s_a and the angular velocity omega is read
off R' R^T; J is the angular momentum about the centre of mass, I the inertia tensor of J = I omega,
I_1, I_2, I_3 its principal moments, G the external torque. A point O' a distance l from the centre
of mass along the 3-axis gives primed moments. The symmetric top has I_1 = I_2, the asymmetric top's
steady spin is omega e_3 perturbed by small eps_i (first order). Every check is built here from
these definitions, never from the text's later displays. Run with --write to regenerate the table.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero
t = sp.symbols("t", real=True)
a1, a2, a3 = [sp.Function(n)(t) for n in ("alpha", "beta", "gamma")]


def rot(axis, q):
    c, s = sp.cos(q), sp.sin(q)
    return {"z": sp.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]]),
            "x": sp.Matrix([[1, 0, 0], [0, c, -s], [0, s, c]])}[axis]


R = rot("z", a1) * rot("x", a2) * rot("z", a3)
W = sp.simplify(R.diff(t) * R.T)
om = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])              # omega, space components
om_b = sp.simplify(R.T * om)                              # omega, body components

# 41: M Rddot = F_ext and Ldot = G_ext, with central internal forces f_ab = lam_ab (r_a - r_b)
N = 3
rs = [sp.Matrix([sp.Function(f"{c}{a}")(t) for c in "xyz"]) for a in range(N)]
ms = sp.symbols(f"m0:{N}", positive=True)
Fs = [sp.Matrix(sp.symbols(f"F{a}_1:4")) for a in range(N)]
lam = {(a, b): sp.Symbol(f"lam_{min(a, b)}{max(a, b)}") for a in range(N) for b in range(N) if a != b}
acc = [(Fs[a] + sum((lam[a, b] * (rs[a] - rs[b]) for b in range(N) if b != a), sp.zeros(3, 1))) / ms[a]
       for a in range(N)]                                 # Newton for each particle
Mt = sum(ms)
Rcm = sum((ms[a] * rs[a] for a in range(N)), sp.zeros(3, 1)) / Mt
Rdd = sum((ms[a] * acc[a] for a in range(N)), sp.zeros(3, 1)) / Mt
Lsp = sum((ms[a] * rs[a].cross(rs[a].diff(t)) for a in range(N)), sp.zeros(3, 1))
Ldot = sum((ms[a] * rs[a].cross(acc[a]) for a in range(N)), sp.zeros(3, 1))   # d/dt sum m r x rdot
check(41, zero(Mt * Rdd - sum(Fs, sp.zeros(3, 1)))
      and zero(Ldot - sum((rs[a].cross(Fs[a]) for a in range(N)), sp.zeros(3, 1))))
# 45: L = J + R x P and T = T_com + M V^2 / 2 (J, T_com about and relative to the centre of mass)
P = sum((ms[a] * rs[a].diff(t) for a in range(N)), sp.zeros(3, 1))
J = sum((ms[a] * (rs[a] - Rcm).cross(rs[a].diff(t) - Rcm.diff(t)) for a in range(N)), sp.zeros(3, 1))
T = sum(ms[a] * (rs[a].diff(t).T * rs[a].diff(t))[0] for a in range(N)) / 2
Tcom = sum(ms[a] * ((rs[a].diff(t) - Rcm.diff(t)).T * (rs[a].diff(t) - Rcm.diff(t)))[0] for a in range(N)) / 2
check(45, zero(Lsp - (J + Rcm.cross(P))) and zero(T - (Tcom + Mt * (Rcm.diff(t).T * Rcm.diff(t))[0] / 2)))
# 52: 1 = det(I) = det(R R^T) = det(R) det(R^T) = [det(R)]^2, R orthogonal (a rotation of plain angles)
q1, q2, q3 = sp.symbols("q1:4", real=True)
Rq = rot("z", q1) * rot("x", q2) * rot("z", q3)
dR = sp.simplify(Rq.det())
check(52, sp.simplify((Rq * Rq.T).det() - 1) == 0 and sp.simplify(dR * Rq.T.det() - (Rq * Rq.T).det()) == 0
      and sp.simplify(dR**2 - 1) == 0)
# 56: det(-A) = (-1)^3 det A = -det A for a 3x3 A
Ag = sp.Matrix(3, 3, sp.symbols("A0:9"))
check(56, sp.expand((-Ag).det() + Ag.det()) == 0)
# 60: the chain det(R - I) = det((R - I)^T) = ... = -det(R - I), R a proper rotation
E = sp.eye(3)
Ri = Rq.T
chain = [(Rq - E).det(), ((Rq - E).T).det(), (Rq.T - E).det(), (Ri - Ri * Rq).det(), (Ri * (E - Rq)).det(),
         Ri.det() * (E - Rq).det(), (E - Rq).det(), (-(Rq - E)).det(), -(Rq - E).det()]
check(60, all(sp.simplify(sp.expand(u - v)) == 0 for u, v in zip(chain, chain[1:])))

# a body of six particles at +-a e1, +-b e2, +-c e3 (masses p, q, r): centre of mass at the origin,
# principal axes along the body axes, I = diag(I1, I2, I3)
ab, bb, cb = sp.symbols("a b c", positive=True)
pm, qm, rm = sp.symbols("p q r", positive=True)
body = [(pm, sp.Matrix([ab, 0, 0])), (pm, sp.Matrix([-ab, 0, 0])), (qm, sp.Matrix([0, bb, 0])),
        (qm, sp.Matrix([0, -bb, 0])), (rm, sp.Matrix([0, 0, cb])), (rm, sp.Matrix([0, 0, -cb]))]


def inertia(points):
    return sum((m * ((s.T * s)[0] * E - s * s.T) for m, s in points), sp.zeros(3, 3))


Ib = inertia(body)
assert zero(Ib - sp.diag(*[Ib[k, k] for k in range(3)]))
# a generic body point s (every particle is one): r = R s
sg = sp.Matrix(sp.symbols("s1:4", real=True))
rg = R * sg
# 74: rdot_a = omega x r_a
check(74, zero(rg.diff(t) - om.cross(rg)))
# 78: J = sum r x p = sum m (r x rdot) = sum m r x (omega x r) = sum m r^2 omega - sum m r (r . omega)
w = sp.Matrix(sp.symbols("w1:4", real=True))
xs = sp.Matrix(sp.symbols("x1:4", real=True))
Jw = lambda pts: sum((m * s.cross(w.cross(s)) for m, s in pts), sp.zeros(3, 1))  # noqa: E731
check(78, zero(xs.cross(w.cross(xs)) - ((xs.T * xs)[0] * w - xs * (xs.T * w)[0]))
      and zero(rg.cross(rg.diff(t)) - rg.cross(om.cross(rg))))
# 85: a x (b x c) = (a . c) b - (a . b) c
va, vb, vc = [sp.Matrix(sp.symbols(f"{n}1:4")) for n in "uvy"]
check(85, zero(va.cross(vb.cross(vc)) - ((va.T * vc)[0] * vb - (va.T * vb)[0] * vc)))
# 93: J_i = sum m r^2 omega_i - sum m x_ai sum_j x_ai omega_j  -- the true term is x_ai sum_j x_aj omega_j
Jtrue = (xs.T * xs)[0] * w - xs * (xs.T * w)[0]
Jtext = sp.Matrix([(xs.T * xs)[0] * w[i] - xs[i] * sum(xs[i] * w[j] for j in range(3)) for i in range(3)])
check(93, zero(Jtext - Jtrue))
Jfix = sp.Matrix([(xs.T * xs)[0] * w[i] - xs[i] * sum(xs[j] * w[j] for j in range(3)) for i in range(3)])
assert zero(Jfix - Jtrue)
# 97: I_ij = sum m [r^2 delta_ij - x_i x_j] gives J = I omega
Iij = sp.Matrix(3, 3, lambda i, j: (xs.T * xs)[0] * sp.KroneckerDelta(i, j) - xs[i] * xs[j])
check(97, zero(Iij * w - Jtrue))
# 101: the matrix of components, as the text sets it: (3,1) entry -x y and (3,3) entry x^2 + y_z^2
x, y, zc, yz = sp.symbols("x_a y_a z_a y_z", real=True)
Itrue = sp.Matrix([[y**2 + zc**2, -x * y, -x * zc], [-x * y, x**2 + zc**2, -y * zc], [-x * zc, -y * zc, x**2 + y**2]])
Itext = sp.Matrix([[y**2 + zc**2, -x * y, -x * zc], [-x * y, x**2 + zc**2, -y * zc], [-x * y, -y * zc, x**2 + yz**2]])
assert zero(Itrue - Iij.subs(dict(zip(xs, (x, y, zc)))))
check(101, zero(Itext - Itrue))
# 111: T = sum m (omega x r).(omega x r) / 2 (each particle's rdot^2 = (omega x r)^2)
check(111, sp.simplify((rg.diff(t).T * rg.diff(t))[0] - ((om.cross(rg)).T * om.cross(rg))[0]) == 0)
# 115: T = omega . sum m r x (omega x r) / 2 = omega . J / 2 = omega . I omega / 2
Tw = sum(m * ((w.cross(s)).T * w.cross(s))[0] for m, s in body) / 2
check(115, sp.expand(Tw - (w.T * Jw(body))[0] / 2) == 0 and sp.expand(Tw - (w.T * Ib * w)[0] / 2) == 0)
# 129: J = (I1 w1, I2 w2, I3 w3) in the principal basis; 133: T = (I1 w1^2 + I2 w2^2 + I3 w3^2)/2
I1, I2, I3 = sp.symbols("I_1 I_2 I_3", positive=True)
Id = sp.diag(I1, I2, I3)
check(129, zero(Id * w - sp.Matrix([I1 * w[0], I2 * w[1], I3 * w[2]])) and zero(Jw(body) - Ib * w))
check(133, sp.expand((w.T * Id * w)[0] / 2 - (I1 * w[0]**2 + I2 * w[1]**2 + I3 * w[2]**2) / 2) == 0)
# 140: L = J + R x P about O' (the same split as line 45)
check(140, CHECKS[45])
# O' a distance l below the centre of mass on the 3-axis: body points relative to O' are s + d
ll, Mb = sp.symbols("l M", positive=True)
d = sp.Matrix([0, 0, ll])
body_o = [(m, s + d) for m, s in body]
Ip = inertia(body_o)
Mtot = sum(m for m, _ in body)
# 144: L = I' omega about O' (body components)
Lo = sum((m * (R * v).cross((R * v).diff(t)) for m, v in body_o), sp.zeros(3, 1))
check(144, zero(R.T * Lo - Ip * om_b))
# 152: I1' = I1 + M l^2, I2' = I2 + M l^2, I3' = I3
check(152, zero(Ip - (Ib + Mtot * ll**2 * sp.diag(1, 1, 0))))
# 148: T = omega . I' omega / 2 = (I1' w1^2 + I2 w2^2 + I3 w3^2)/2  -- the 2 moment is I2', not I2
T148 = (w.T * Ip * w)[0] / 2
check(148, sp.expand(T148 - (Ip[0, 0] * w[0]**2 + Ib[1, 1] * w[1]**2 + Ib[2, 2] * w[2]**2) / 2) == 0)
assert sp.expand(T148 - (Ip[0, 0] * w[0]**2 + Ip[1, 1] * w[1]**2 + Ip[2, 2] * w[2]**2) / 2) == 0
# 159: [Adot]_S0 = [Adot]_S + omega x [A]_S (A = R A_b)
Ab = sp.Matrix([sp.Function(f"A_{k}")(t) for k in (1, 2, 3)])
check(159, zero(sp.simplify((R * Ab).diff(t) - (R * Ab.diff(t) + om.cross(R * Ab)))))
# 163: [Ldot]_S0 = G (line 41's law); 167: G = [Ldot]_S + omega x [L]_S (line 159 with A = L)
check(163, CHECKS[41])
check(167, CHECKS[159])
# 171: [L]_S = J = (I1 w1, I2 w2, I3 w3): body components of L about the centre of mass
Lc = sum((m * (R * v).cross((R * v).diff(t)) for m, v in body), sp.zeros(3, 1))
check(171, zero(R.T * Lc - Ib * om_b))
# Euler's equations from G_b = d/dt(I w_b) + w_b x I w_b in the principal frame
wv = sp.Matrix([sp.Function(f"omega_{k}")(t) for k in (1, 2, 3)])
G = Id * wv.diff(t) + wv.cross(Id * wv)
rows175 = sp.Matrix([I1 * wv[0].diff(t) + (I3 - I2) * wv[1] * wv[2], I2 * wv[1].diff(t) + (I1 - I3) * wv[2] * wv[0],
                     I3 * wv[2].diff(t) + (I2 - I1) * wv[0] * wv[1]])
check(175, zero(G - rows175))
# 181: torque free: I1 w1' = (I2 - I3) w2 w3, ...
rhs181 = sp.Matrix([(I2 - I3) * wv[1] * wv[2], (I3 - I1) * wv[2] * wv[0], (I1 - I2) * wv[0] * wv[1]])
check(181, zero(-wv.cross(Id * wv) - rhs181))          # G = 0: I omegadot = -omega x I omega
# symmetric top, I1 = I2
sym = {I2: I1}
rates = sp.Matrix([(I2 - I3) * wv[1] * wv[2] / I1, (I3 - I1) * wv[2] * wv[0] / I2,
                   (I1 - I2) * wv[0] * wv[1] / I3]).subs(sym)                    # torque-free rates
# 190: I1 w1' = (I1 - I3) w2 w3, I1 w2' = (I3 - I1) w3 w1, I3 w3' = 0
check(190, zero(sp.Matrix([I1 * rates[0] - (I1 - I3) * wv[1] * wv[2], I1 * rates[1] - (I3 - I1) * wv[2] * wv[0],
                           I3 * rates[2]])))
Om = (I1 - I3) / I1 * wv[2]
# 196: w1' = (I1 - I3)/I1 w3 w2 = Omega w2, w2' = (I3 - I1)/I1 w3 w1 = -Omega w1
check(196, zero(sp.Matrix([rates[0] - Om * wv[1], rates[1] + Om * wv[0]])))
# 205, 209: second derivatives along the torque-free flow (w3 constant)
flow = {wv[0].diff(t): rates[0], wv[1].diff(t): rates[1], wv[2].diff(t): 0}
w1dd = sp.diff(rates[0], t).subs(flow)
w2dd = sp.diff(rates[1], t).subs(flow)
check(205, sp.simplify(w1dd - Om * rates[1]) == 0 and sp.simplify(w1dd + Om**2 * wv[0]) == 0)
check(209, sp.simplify(w2dd + Om * rates[0]) == 0 and sp.simplify(w2dd + Om**2 * wv[1]) == 0)
# 213: cos tau = J.e3/|J| = I3 w3 / sqrt(I1^2 A^2 + I2^2 w3) = w3 / sqrt(I1^2/I3^2 A^2 + w3^2)
Aa, w3 = sp.symbols("A omega_3", positive=True)
cos_tau = I3 * w3 / sp.sqrt(I1**2 * Aa**2 + I3**2 * w3**2)       # |J|^2 = I1^2 A^2 + I3^2 w3^2 (I1 = I2)
mid = I3 * w3 / sp.sqrt(I1**2 * Aa**2 + I2**2 * w3)
last = w3 / sp.sqrt(I1**2 / I3**2 * Aa**2 + w3**2)
check(213, sp.simplify(mid.subs(sym) - cos_tau) == 0 and sp.simplify(last - cos_tau) == 0)
assert sp.simplify(last - cos_tau) == 0
# 217: cos zeta = omega.e3/|omega| = w3 / sqrt(A^2 + w3^2)
check(217, sp.simplify(w3 / sp.sqrt(Aa**2 + w3**2) - (sp.Matrix([Aa, 0, w3]).T * sp.Matrix([0, 0, 1]))[0]
                       / sp.sqrt(Aa**2 + w3**2)) == 0)
# 224: omega along e3 only: I1 w1' = (I2 - I3) w2 w3 = 0, I2 w2' = (I3 - I1) w3 w1 = 0, I3 w3' = (I1 - I2) w1 w3 = 0
steady = {wv[0]: 0, wv[1]: 0}
text224 = sp.Matrix([(I2 - I3) * wv[1] * wv[2], (I3 - I1) * wv[2] * wv[0], (I1 - I2) * wv[0] * wv[2]])
check(224, zero(text224 - rhs181) and zero(text224.subs(steady)))
assert zero(rhs181.subs(steady))                 # the equations themselves do give zero rates
# 230: first order in eps about omega e3
wst, eps = sp.symbols("omega epsilon", positive=True)
ee = [sp.Function(f"e_{k}")(t) for k in (1, 2, 3)]
wl = sp.Matrix([eps * ee[0], eps * ee[1], wst + eps * ee[2]])
full = sp.Matrix([(I2 - I3) * wl[1] * wl[2], (I3 - I1) * wl[2] * wl[0], (I1 - I2) * wl[0] * wl[1]])
lin = full.applyfunc(lambda q: sp.expand(q).coeff(eps, 1) * eps)
check(230, zero(lin - sp.Matrix([(I2 - I3) * wst * eps * ee[1], (I3 - I1) * wst * eps * ee[0], 0])))
# 236: I1 e1'' = (I2 - I3) w e2' = (I2 - I3) w (I3 - I1)/I2 w e1
e1dd = ((I2 - I3) * wst * (I3 - I1) * wst * ee[0] / I2) / I1     # from e1' = (I2-I3) w e2 / I1, e2' = (I3-I1) w e1 / I2
check(236, sp.simplify(I1 * e1dd - (I2 - I3) * wst * (I3 - I1) / I2 * wst * ee[0]) == 0)
# 240: I1 I2 e1'' = (I2 - I3)(I3 - I1) w^2 e1
check(240, sp.simplify(I1 * I2 * e1dd - (I2 - I3) * (I3 - I1) * wst**2 * ee[0]) == 0)
# 248: Omega^2 = (I1 - I3)(I2 - I3)/(I1 I2) w^2, so that e1'' = -Omega^2 e1
Om2 = (I1 - I3) * (I2 - I3) / (I1 * I2) * wst**2
check(248, sp.simplify(e1dd / ee[0] + Om2) == 0)
# 244: e1 = A exp(i Omega t) + B exp(-i Omega t) solves e1'' = -Omega^2 e1
Ac, Bc, Omg = sp.symbols("A B Omega")
sol = Ac * sp.exp(sp.I * Omg * t) + Bc * sp.exp(-sp.I * Omg * t)
check(244, sp.simplify(sol.diff(t, 2) + Omg**2 * sol) == 0)
# 252: Omega imaginary (Omega^2 = -k^2): the B term grows as B exp(|Omega| t)
kk = sp.symbols("k", positive=True)
check(252, sp.simplify(sp.exp(-sp.I * (sp.I * kk) * t) - sp.exp(kk * t)) == 0
      and sp.simplify((Bc * sp.exp(kk * t)).diff(t, 2) - kk**2 * Bc * sp.exp(kk * t)) == 0)

# negative controls: a check can fail
assert not zero(Jtext - Jtrue)
assert sp.simplify(mid.subs(sym) - cos_tau) != 0

LINES = [37, 41, 45, 52, 56, 60, 74, 78, 85, 89, 93, 97, 101, 111, 115, 119, 129, 133, 140, 144, 148, 152,
         159, 163, 167, 171, 175, 181, 190, 196, 201, 205, 209, 213, 217, 224, 230, 236, 240, 244, 248, 252]

ROWS = {
    37: ("not a claim", "the constraint that defines a rigid body: fixed distances rho_ab between its particles"),
    41: ("holds", "summing Newton's law over the particles, central internal forces f_ab = -f_ba along r_a - r_b cancel from the total force and the total torque: M Rddot = F_ext and Ldot = G_ext (check 41)"),
    45: ("holds", "with r_a = R + (r_a - R): L = J + R x P and T = T_com + M V^2/2, the cross terms vanishing since sum m_a (r_a - R) = 0 (check 45)"),
    52: ("holds", "for R orthogonal: det(R R^T) = det I = 1 and det(R R^T) = det R det R^T = (det R)^2 (check 52)"),
    56: ("holds", "det(-A) = (-1)^3 det A = -det A for any 3x3 matrix (check 56)"),
    60: ("holds", "each step of the chain is equal for a proper rotation (R^-1 = R^T, det R^-1 = 1), so det(R - I) = -det(R - I) = 0 (check 60)"),
    74: ("holds", "r_a = R s_a with s_a fixed in the body gives rdot_a = Rdot R^T r_a = omega x r_a (check 74)"),
    78: ("holds", "r x p = m r x rdot with rdot = omega x r, and r x (omega x r) = r^2 omega - r (r . omega) (check 78)"),
    85: ("holds", "the double cross product identity a x (b x c) = (a . c) b - (a . b) c (check 85)"),
    89: ("not a claim", "the definition of the inertia tensor I by J = I omega, J_i = sum_j I_ij omega_j"),
    93: ("typo", "the second sum's inner index is summed with x_ai instead of x_aj: sum_j x_ai omega_j is x_ai (omega_1 + omega_2 + omega_3), not r_a . omega (check 93)",
         r"J_i = \sum_a m_a r_a^2 \omega_i - \sum_a m_a x_{ai} \sum_j x_{aj}\omega_j.",
         "The line it writes out is J = sum m r^2 omega - sum m r (r . omega); the i-th component of r (r . omega) is x_ai sum_j x_aj omega_j. With x_ai in the inner sum the term would be x_ai^2 (omega_1 + omega_2 + omega_3).",
         "One particle of unit mass at (1, 0, 0) spinning with omega = (0, 0, 1): r . omega = 0, so J_1 = r^2 omega_1 - x_1 (r . omega) = 0; the written inner sum gives x_1 * x_1 * omega_3 = 1 and so J_1 = -1, a component of J along x for a spin about z by a particle on the x-axis, which is impossible (J = m r x (omega x r) = (0, 0, 1))."),
    97: ("holds", "I_ij = sum m [r^2 delta_ij - x_ai x_aj] reproduces J = sum m r^2 omega - sum m r (r . omega) (check 97)"),
    101: ("typo", "two entries are wrong: the (3,1) entry is -x_a z_a (the matrix is symmetric, the (1,3) entry is -x_a z_a), written -x_a y_a; and the (3,3) entry is x_a^2 + y_a^2, written with y_z^2 (check 101)",
          r"I = \sum_a m_a \begin{pmatrix} y_a^2 + z_a^2 & -x_ay_a & -x_az_a\\ -x_ay_a & x_a^2 + z_a^2 & -y_az_a\\ -x_az_a & -y_az_a & x_a^2 + y_a^2 \end{pmatrix}",
          "From I_ij = sum m [r^2 delta_ij - x_ai x_aj]: I_31 = -x_a3 x_a1 = -z_a x_a, and I_33 = r^2 - z_a^2 = x_a^2 + y_a^2. The display's own (1,3) entry is -x_a z_a, so its (3,1) entry -x_a y_a breaks the symmetry it states.",
          "A particle of unit mass at (0, 1, 1): I_31 should be 0 (x = 0) and I_33 = 0 + 1 = 1; the written (3,1) entry -x y is also 0 here but at (1, 1, 0) it gives -1 where I_31 = 0; and y_z is not a coordinate of the particle at all."),
    111: ("holds", "T = sum m rdot^2 / 2 with rdot = omega x r (check 111)"),
    115: ("holds", "(omega x r) . (omega x r) = omega . (r x (omega x r)) by the scalar triple product, so T = omega . J / 2 = omega . I omega / 2 (check 115)"),
    119: ("not a claim", "the inertia tensor in its principal axes: the diagonal matrix of its eigenvalues, which defines I_1, I_2, I_3"),
    129: ("holds", "in the principal basis J = I omega = (I_1 omega_1, I_2 omega_2, I_3 omega_3) (check 129)"),
    133: ("holds", "T = omega . I omega / 2 = (I_1 omega_1^2 + I_2 omega_2^2 + I_3 omega_3^2)/2 in the principal basis (check 133)"),
    140: ("holds", "the same split as before: the angular momentum about O' is J + R x P (check 140)"),
    144: ("holds", "with O' fixed, each particle moves with omega x r' about O', so L = sum m r' x (omega x r') = I' omega (check 144)"),
    148: ("typo", "the second moment is the primed one: with O' on the 3-axis a distance l from the centre of mass, I_2' = I_2 + M l^2, so T = (I_1' omega_1^2 + I_2' omega_2^2 + I_3' omega_3^2)/2; the display mixes I_2 (about the centre of mass) into the sum about O' (check 148)",
          r"T = \frac{1}{2}\vv{\omega} \cdot I' \vv{\omega} = \frac{1}{2}(I_1'\omega_1^2 + I_2'\omega_2^2 + I_3'\omega_3^2).",
          "The tensor about O' is diagonal in the same axes with entries I_1 + M l^2, I_2 + M l^2, I_3 (the next display); omega . I' omega / 2 is then the sum of I_i' omega_i^2 / 2, with I_2' and not I_2.",
          "The display's own first member is omega . I' omega / 2, symmetric in the 1 and 2 axes for a body with I_1 = I_2; the second member treats them differently (I_1' against I_2), so for a spin about the 2-axis alone the two members differ by M l^2 omega_2^2 / 2."),
    152: ("holds", "the parallel axis theorem for O' on the 3-axis: I' = I + M (l^2 delta - d d^T) with d = l e_3 (check 152)"),
    159: ("holds", "the rate of a vector seen from an inertial frame and from a frame turning with omega differ by omega x A (check 159)"),
    163: ("holds", "the torque law in the inertial frame (check 41)"),
    167: ("holds", "the rate of L in the body frame plus omega x L (check 159 with A = L)"),
    171: ("holds", "in the principal frame with the centre of mass as origin, the body components of L are I omega_b = (I_1 omega_1, I_2 omega_2, I_3 omega_3) (check 171)"),
    175: ("holds", "G = I omegadot + omega x I omega in principal axes gives G_1 = I_1 omegadot_1 + (I_3 - I_2) omega_2 omega_3 and its cyclic forms (check 175)"),
    181: ("holds", "with G = 0: I_1 omegadot_1 = (I_2 - I_3) omega_2 omega_3 and cyclic (check 181)"),
    190: ("holds", "torque-free with I_2 = I_1 (check 190)"),
    196: ("holds", "dividing by I_1 with Omega = (I_1 - I_3) omega_3 / I_1 (check 196)"),
    201: ("not a claim", "the definition of Omega"),
    205: ("holds", "differentiating omegadot_1 = Omega omega_2 with omega_3 constant and using omegadot_2 = -Omega omega_1 (check 205)"),
    209: ("holds", "the same for omega_2 (check 209)"),
    213: ("typo", "|J|^2 = I_1^2 A^2 + I_3^2 omega_3^2 (with I_2 = I_1), so the middle member's root is sqrt(I_1^2 A^2 + I_3^2 omega_3^2); it is written I_2^2 omega_3, with the wrong moment and omega_3 not squared; the last member holds (check 213)",
          r"\cos \tau = \frac{\vv{J}\cdot\ve{3}}{\abs{\vv{J}}} = \frac{I_3\omega_3}{\sqrt{I_1^2A^2 + I_3^2\omega_3^2}} = \frac{\omega_3}{\sqrt{\frac{I_1^2}{I_3^2}A^2 + \omega_3^2}}.",
          "J = (I_1 omega_1, I_1 omega_2, I_3 omega_3) with omega_1^2 + omega_2^2 = A^2, so |J| = sqrt(I_1^2 A^2 + I_3^2 omega_3^2); the text's own prose a few lines up says J^2 = I_1^2 A^2 + I_3^2 omega_3^2.",
          "Dimensions: I_1^2 A^2 has units of (kg m^2 / s)^2 and I_2^2 omega_3 has (kg m^2)^2 / s, so they cannot be added; and dividing the corrected root by I_3 gives the last member, which the written middle member does not."),
    217: ("holds", "omega = (omega_1, omega_2, omega_3) with omega_1^2 + omega_2^2 = A^2: cos zeta = omega_3 / sqrt(A^2 + omega_3^2) (check 217)"),
    224: ("typo", "Euler's third torque-free equation is I_3 omegadot_3 = (I_1 - I_2) omega_1 omega_2; the display writes omega_1 omega_3 (it is still zero when omega_1 = omega_2 = 0) (check 224)",
          r"I_3\dot{\omega}_3 &= (I_1 - I_2)\omega_1\omega_2 = 0.",
          "The torque-free equations a few displays up: I_3 omegadot_3 = (I_1 - I_2) omega_1 omega_2; the cyclic pattern (1 from 2 3, 2 from 3 1, 3 from 1 2) gives omega_1 omega_2 for the third.",
          "The linearised form two displays on writes the third equation with eps_1 eps_2, i.e. omega_1 omega_2; with omega_1 omega_3 a spin about the 3-axis with a small omega_1 would change omega_3 at first order, which the text's own next display denies."),
    230: ("holds", "putting omega = (eps_1, eps_2, omega + eps_3) into the torque-free equations and keeping first order (check 230)"),
    236: ("holds", "differentiating the first linear equation and substituting eps_2dot = (I_3 - I_1) omega eps_1 / I_2 (check 236)"),
    240: ("holds", "multiplying by I_2 (check 240)"),
    244: ("holds", "A e^{i Omega t} + B e^{-i Omega t} solves eps'' = -Omega^2 eps (check 244)"),
    248: ("holds", "from I_1 I_2 eps'' = (I_2 - I_3)(I_3 - I_1) omega^2 eps: Omega^2 = (I_1 - I_3)(I_2 - I_3) omega^2 / (I_1 I_2) (check 248)"),
    252: ("holds", "for Omega = i |Omega| the term B e^{-i Omega t} = B e^{|Omega| t} grows (check 252)"),
}


if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
