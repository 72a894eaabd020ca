"""Independent SymPy truth table for edinburgh-lagrangian-dynamics-heavy-top-lagrange-zyz.tex.

The text's own setting: a top with one point O fixed, its body axes 1, 2, 3 principal about O, the
centre of mass a distance l up the 3-axis. The orientation is R = R_z(varphi) R_y(vartheta)
R_z(psi) (the course's "y convention": a turn by vartheta about y, then by varphi about the space
z-axis, then by psi about the body 3-axis), the columns of R the body axes in space; the primed
axes are the columns of R_z(varphi) R_y(vartheta). omega is read off R' R^T. The symmetric top has
A = I_1 = I_2, C = I_3, potential M g l cos(vartheta). Every check is built here from these
definitions (the Lagrangian is derived here), never from the text's later displays. Run with
--write to regenerate the table.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero
t = sp.symbols("t", real=True)
th, ph, ps = [sp.Function(n)(t) for n in ("vartheta", "varphi", "psi")]
c, s = sp.cos, sp.sin


def Rz(q):
    return sp.Matrix([[c(q), -s(q), 0], [s(q), c(q), 0], [0, 0, 1]])


def Ry(q):
    return sp.Matrix([[c(q), 0, s(q)], [0, 1, 0], [-s(q), 0, c(q)]])


Rp = Rz(ph) * Ry(th)                 # after the second turn: the primed axes
R = Rp * Rz(ps)                      # the body axes
W = sp.simplify(R.diff(t) * R.T)
om = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])
om_b = sp.simplify(R.T * om)         # body components
om_p = sp.simplify(Rp.T * om)        # primed components
e = [R[:, k] for k in range(3)]
ep = [Rp[:, k] for k in range(3)]
zhat = sp.Matrix([0, 0, 1])
dot = lambda u, v: sp.simplify((u.T * v)[0])  # noqa: E731

# a body of six particles at +-a e1, +-b e2 (masses p, q) and two at heights h1, h2 on the 3-axis:
# principal axes along the body axes about the fixed point O at the origin
ab, bb, h1, h2 = sp.symbols("a b h_1 h_2", positive=True)
pm, qm, m1, m2 = sp.symbols("p q m_1 m_2", positive=True)
body = [(pm, sp.Matrix([ab, 0, 0])), (pm, sp.Matrix([-ab, 0, 0])), (qm, sp.Matrix([0, bb, 0])),
        (qm, sp.Matrix([0, -bb, 0])), (m1, sp.Matrix([0, 0, h1])), (m2, sp.Matrix([0, 0, h2]))]
E3 = sp.eye(3)
IO = sum((m * ((v.T * v)[0] * E3 - v * v.T) for m, v in body), sp.zeros(3, 3))
assert zero(IO - sp.diag(IO[0, 0], IO[1, 1], IO[2, 2]))
# 30: L = I omega about O (body components)
L = sum((m * (R * v).cross((R * v).diff(t)) for m, v in body), sp.zeros(3, 1))
check(30, zero(sp.simplify(R.T * L - IO * om_b)))
# 34, 47: T = omega . I omega / 2 = (I1 w1^2 + I2 w2^2 + I3 w3^2)/2 (principal axes about O)
Tp = sum(m * ((R * v).diff(t).T * (R * v).diff(t))[0] for m, v in body) / 2
T34 = sum(IO[k, k] * om_b[k]**2 for k in range(3)) / 2
check(34, sp.simplify(Tp - T34) == 0 and sp.simplify(Tp - (om_b.T * IO * om_b)[0] / 2) == 0)
check(47, CHECKS[34])
# 43: V = M g l cos(vartheta): the centre of mass at l e3 has height l (e3 . zhat)
M, g, l = sp.symbols("M g l", positive=True)
check(43, sp.simplify(M * g * l * dot(e[2], zhat) - M * g * l * c(th)) == 0)
# 51: e1.e1' = cos psi, e1.e2' = sin psi, e2.e1' = -sin psi, e2.e2' = cos psi
check(51, all(sp.simplify(u - v) == 0 for u, v in
              [(dot(e[0], ep[0]), c(ps)), (dot(e[0], ep[1]), s(ps)), (dot(e[1], ep[0]), -s(ps)),
               (dot(e[1], ep[1]), c(ps))]))
# 58: omega = varthetadot e2' + varphidot zhat + psidot e3'
check(58, zero(sp.simplify(om - (th.diff(t) * ep[1] + ph.diff(t) * zhat + ps.diff(t) * ep[2]))))
# 62: zhat = (zhat.e3') e3' + (zhat.e1') e1' = e3' cos - e1' sin, written with the '=' lost and e1' e3'
# set side by side (a product of two vectors, no vector at all)
intended = zero(sp.simplify(zhat - (dot(zhat, ep[2]) * ep[2] + dot(zhat, ep[0]) * ep[0])))
intended = intended and zero(sp.simplify(zhat - (ep[2] * c(th) - ep[0] * s(th))))
assert intended
check(62, False)
# 66: omega = -varphidot sin e1' + varthetadot e2' + (psidot + varphidot cos) e3'
check(66, zero(sp.simplify(om_p - sp.Matrix([-ph.diff(t) * s(th), th.diff(t), ps.diff(t) + ph.diff(t) * c(th)]))))
# 70: the body components; the text's omega_2 ends with the rate of (vartheta cos varphi)
w1 = -ph.diff(t) * s(th) * c(ps) + th.diff(t) * s(ps)
w2 = ph.diff(t) * s(th) * s(ps) + (th * c(ph)).diff(t)
w3 = ph.diff(t) * c(th) + ps.diff(t)
check(70, zero(sp.simplify(om_b - sp.Matrix([w1, w2, w3]))))
assert zero(sp.simplify(om_b - sp.Matrix([w1, ph.diff(t) * s(th) * s(ps) + th.diff(t) * c(ps), w3])))
# 76: T in the three rates
I1, I2, I3 = sp.symbols("I_1 I_2 I_3", positive=True)
Tgen = (I1 * om_b[0]**2 + I2 * om_b[1]**2 + I3 * om_b[2]**2) / 2
T76 = (I1 * (-ph.diff(t) * s(th) * c(ps) + th.diff(t) * s(ps))**2
       + I2 * (ph.diff(t) * s(th) * s(ps) + th.diff(t) * c(ps))**2 + I3 * (ph.diff(t) * c(th) + ps.diff(t))**2) / 2
check(76, sp.simplify(Tgen - T76) == 0)
# symmetric top: I1 = I2 = A, I3 = C
A, C = sp.symbols("A C", positive=True)
Tsym = sp.simplify(Tgen.subs({I1: A, I2: A, I3: C}))
Tlast = (A * (th.diff(t)**2 + ph.diff(t)**2 * s(th)**2) + C * (ph.diff(t) * c(th) + ps.diff(t))) / 2
Tfix = (A * (th.diff(t)**2 + ph.diff(t)**2 * s(th)**2) + C * (ph.diff(t) * c(th) + ps.diff(t))**2) / 2
first = sp.simplify(Tsym - (A * (om_b[0]**2 + om_b[1]**2) + C * om_b[2]**2) / 2) == 0
second = sp.simplify(Tsym - (A * (om_p[0]**2 + om_p[1]**2) + C * om_b[2]**2) / 2) == 0
# 83: the three lines; the last drops the square on the C term
check(83, first and second and sp.simplify(Tsym - Tlast) == 0)
assert sp.simplify(Tsym - Tfix) == 0
# the Lagrangian in plain symbols
q, qd = sp.symbols("vartheta varphi psi", real=True), sp.symbols("thetadot phidot psidot", real=True)
TH, PH, PS = q
THd, PHd, PSd = qd
sub = {th.diff(t): THd, ph.diff(t): PHd, ps.diff(t): PSd}
sub2 = {th: TH, ph: PH, ps: PS}
Tq = sp.simplify(Tsym.subs(sub).subs(sub2))
Lag = Tq - M * g * l * c(TH)
# 89: the Lagrangian
check(89, sp.simplify(Lag - ((A * (THd**2 + PHd**2 * s(TH)**2) + C * (PHd * c(TH) + PSd)**2) / 2 - M * g * l * c(TH))) == 0)
n = sp.symbols("n", real=True)
ppsi, pphi, pth = sp.diff(Lag, PSd), sp.diff(Lag, PHd), sp.diff(Lag, THd)
w3q = PHd * c(TH) + PSd
# 94: p_psi = C (psidot + varphidot cos) = I3 w3
check(94, sp.simplify(ppsi - C * (PSd + PHd * c(TH))) == 0 and sp.simplify(ppsi - C * w3q) == 0)
# 98: n = w3 = p_psi / I3 = psidot + varphidot cos
check(98, sp.simplify(ppsi / C - w3q) == 0)
# 102: p_varphi = A varphidot sin^2 + C (psidot + varphidot cos) cos = A varphidot sin^2 + C n cos
check(102, sp.simplify(pphi - (A * PHd * s(TH)**2 + C * (PSd + PHd * c(TH)) * c(TH))) == 0)
# 106: p_vartheta = A varthetadot
check(106, sp.simplify(pth - A * THd) == 0)
# 114, 118, 210: A varthetaddot = A varphidot^2 sin cos - C n varphidot sin + M g l sin
dLdth = sp.diff(Lag, TH)
check(114, sp.simplify(dLdth - (A * PHd**2 * s(TH) * c(TH) - C * (PSd + PHd * c(TH)) * PHd * s(TH) + M * g * l * s(TH))) == 0)
dLdth_n = dLdth.subs(PSd, n - PHd * c(TH))
rhs118 = A * PHd**2 * s(TH) * c(TH) - C * n * PHd * s(TH) + M * g * l * s(TH)
check(118, sp.simplify(dLdth_n - rhs118) == 0)
# 126: the energy function equals T + V = A/2 (...) + C n^2 / 2 + M g l cos
h = THd * pth + PHd * pphi + PSd * ppsi - Lag
E126 = A / 2 * (THd**2 + PHd**2 * s(TH)**2) + C / 2 * n**2 + M * g * l * c(TH)
check(126, sp.simplify((h - E126).subs(n, w3q)) == 0)
Es = sp.symbols("E", real=True)
Lz = sp.symbols("L_z", real=True)
# 130: varthetadot^2 + varphidot^2 sin^2 = (2E - C n^2)/A - 2 M g l cos / A  (on E = E126)
check(130, sp.simplify((THd**2 + PHd**2 * s(TH)**2) - ((2 * Es - C * n**2) / A - 2 * M * g * l * c(TH) / A))
      .subs(Es, E126) == 0)
# 134: with varphidot = (L_z - C n cos)/(A sin^2)
phd_L = (Lz - C * n * c(TH)) / (A * s(TH)**2)
th2 = ((2 * Es - C * n**2) / A - 2 * M * g * l * c(TH) / A) - phd_L**2 * s(TH)**2
check(134, sp.simplify(th2 - ((2 * Es - C * n**2) / A - 2 * M * g * l * c(TH) / A
                              - (Lz - C * n * c(TH))**2 / (A**2 * s(TH)**2))) == 0)
# 141: udot^2 = f(u), u = cos: udot^2 = sin^2 varthetadot^2
u = sp.symbols("u", real=True)
f141 = (2 * Es - C * n**2) / A * (1 - u**2) - (Lz - C * n * u)**2 / A**2 - 2 * M * g * l / A * u * (1 - u**2)
check(141, sp.simplify((s(TH)**2 * th2).subs(c(TH), u).subs(s(TH)**2, 1 - u**2) - f141) == 0
      or sp.simplify(s(TH)**2 * th2 - f141.subs(u, c(TH))) == 0)
# 148: A varthetadot^2 / 2 = E - C n^2/2 - M g l cos - (L_z - C n cos)^2 / (2 A sin^2)
Ueff = M * g * l * c(TH) + (Lz - C * n * c(TH))**2 / (2 * A * s(TH)**2)
check(148, sp.simplify(A * th2 / 2 - (Es - C * n**2 / 2 - Ueff)) == 0)
# 160: L_z = A varphidot sin^2 + C n cos and n = psidot + varphidot cos
check(160, sp.simplify((pphi - (A * PHd * s(TH)**2 + C * n * c(TH))).subs(n, w3q)) == 0 and CHECKS[98])
# 164: steady precession: varthetaddot = 0 in Lagrange's equation at vartheta_0
t0 = sp.symbols("vartheta_0", real=True)
check(164, sp.simplify(rhs118.subs(TH, t0) - s(t0) * (PHd**2 * A * c(t0) - PHd * C * n + M * g * l)) == 0)
# 168: the roots of A cos varphidot^2 - C n varphidot + M g l = 0
quad = A * c(t0) * PHd**2 - C * n * PHd + M * g * l
roots = [(C * n + sg * sp.sqrt(C**2 * n**2 - 4 * A * M * g * l * c(t0))) / (2 * A * c(t0)) for sg in (1, -1)]
check(168, all(sp.simplify(quad.subs(PHd, r)) == 0 for r in roots))
# 172: real roots need the discriminant C^2 n^2 - 4 A M g l cos >= 0
check(172, sp.simplify(sp.discriminant(quad, PHd) - (C**2 * n**2 - 4 * A * M * g * l * c(t0))) == 0)
# 179: first order in x = 4 A M g l cos / (C^2 n^2): sqrt(1 - x) ~ 1 - x/2
xx = sp.symbols("x", positive=True)
check(179, sp.series(sp.sqrt(1 - xx), xx, 0, 2).removeO() - (1 - xx / 2) == 0
      and sp.simplify((C * n * sp.sqrt(1 - xx)).subs(xx, 4 * A * M * g * l * c(t0) / (C**2 * n**2))**2
                      - (C**2 * n**2 - 4 * A * M * g * l * c(t0))) == 0)
slow = sp.simplify(C * n / (2 * A * c(t0)) * (1 - (1 - 2 * A * M * g * l * c(t0) / (C**2 * n**2))))
fast = sp.simplify(C * n / (2 * A * c(t0)) * (1 + (1 - 2 * A * M * g * l * c(t0) / (C**2 * n**2))))
# 184: the slow root is a precession rate varphidot = M g l / (C n); the text calls it varthetadot,
# which is zero in steady precession
assert sp.simplify(slow - M * g * l / (C * n)) == 0
check(184, False)
# 188: the fast root ~ C n / (A cos vartheta_0) (leading order in the small M g l)
check(188, sp.limit(fast * A * c(t0) / (C * n), M, 0) == 1)
# 195: small oscillation of A varthetadot^2 / 2 + U = E': A varthetaddot = -U'(vartheta), frequency sqrt(U''/A)
# Lagrange's equation with varphidot from L_z is A varthetaddot = -dU/dvartheta for the U of line 148,
# a particle of mass A in U: near the minimum it oscillates at sqrt(U''(vartheta_0)/A)
check(195, sp.simplify(rhs118.subs(PHd, phd_L) + sp.diff(Ueff, TH)) == 0)
# 206: Lagrange's equation again (line 118)
check(206, CHECKS[118])
# 210: small vartheta: A varthetaddot = (A varphidot^2 - C n varphidot + M g l) vartheta to first order
eps = sp.symbols("epsilon", positive=True)
lin = sp.series(rhs118.subs(TH, eps), eps, 0, 2).removeO()
check(210, sp.simplify(lin - (A * PHd**2 - C * n * PHd + M * g * l) * eps) == 0)
# 214: started upright, L_z = C n, and L_z = A varphidot sin^2 + C n cos (line 102)
check(214, sp.simplify((pphi - (A * PHd * s(TH)**2 + C * n * c(TH))).subs(n, w3q)) == 0)
# 218: to second order, C n (1 - cos) = A varphidot sin^2 gives C n vartheta^2 / 2 = A varphidot vartheta^2
diff218 = sp.series(C * n * (1 - c(eps)) - A * PHd * s(eps)**2, eps, 0, 3).removeO()
check(218, sp.simplify(diff218 - (C * n / 2 - A * PHd) * eps**2) == 0)
# 222: so varphidot = C n / (2 A); the text calls it varthetadot
assert sp.solve(sp.Eq(C * n / 2, A * PHd), PHd) == [C * n / (2 * A)]
check(222, False)
# 226: A varthetaddot = (M g l - C^2 n^2 / (4 A)) vartheta with varphidot = C n / (2 A)
check(226, sp.simplify((A * PHd**2 - C * n * PHd + M * g * l).subs(PHd, C * n / (2 * A))
                       - (M * g * l - C**2 * n**2 / (4 * A))) == 0)

# negative controls: a check can fail
assert sp.simplify(Tsym - Tlast) != 0
assert not zero(sp.simplify(om_b - sp.Matrix([w1, w2, w3])))

LINES = [30, 34, 43, 47, 51, 58, 62, 66, 70, 76, 83, 89, 94, 98, 102, 106, 110, 114, 118, 122, 126, 130, 134,
         141, 148, 152, 156, 160, 164, 168, 172, 179, 184, 188, 195, 199, 206, 210, 214, 218, 222, 226]

ROWS = {
    30: ("holds", "about the fixed point each particle moves with omega x r, so L = sum m r x (omega x r) = I omega with I about O (check 30)"),
    34: ("holds", "T = sum m rdot^2 / 2 = omega . I omega / 2 = (I_1 omega_1^2 + I_2 omega_2^2 + I_3 omega_3^2)/2 in the principal axes about O (check 34)"),
    43: ("holds", "the centre of mass sits at l e_3, whose height is l e_3 . z = l cos(vartheta) (check 43)"),
    47: ("holds", "the same kinetic energy as before (check 34)"),
    51: ("holds", "e_1, e_2 are e_1', e_2' turned by psi about e_3' = e_3 (check 51)"),
    58: ("holds", "the angular velocity of R_z(varphi) R_y(vartheta) R_z(psi) is varphidot z + varthetadot e_2' + psidot e_3' (check 58)"),
    62: ("typo", "the two forms of the decomposition have lost the '=' between them: zhat = (zhat . e_3') e_3' + (zhat . e_1') e_1' = e_3' cos(vartheta) - e_1' sin(vartheta); as written the middle sets two vectors e_1' e_3' side by side, which is no vector (check 62)",
         r"\vh{z} = (\vh{z} \cdot \ve{3}') \ve{3}' + (\vh{z} \cdot \ve{1}') \ve{1}' = \ve{3}'\cos\vartheta - \ve{1}'\sin\vartheta.",
         "zhat has no component along e_2' (the axis of the vartheta turn is horizontal), zhat . e_3' = cos(vartheta) and zhat . e_1' = -sin(vartheta); so zhat = (zhat . e_3') e_3' + (zhat . e_1') e_1' = cos(vartheta) e_3' - sin(vartheta) e_1', the two members the display runs together.",
         "The next display uses exactly zhat = cos(vartheta) e_3' - sin(vartheta) e_1' (its e_1' component -varphidot sin(vartheta) and the varphidot cos(vartheta) in its e_3' component); a product (zhat . e_1') e_1' e_3' cos(vartheta) has two vectors in one term and cannot be added to the vector (zhat . e_3') e_3'."),
    66: ("holds", "putting zhat = cos(vartheta) e_3' - sin(vartheta) e_1' into the angular velocity (check 66)"),
    70: ("typo", "the last term of omega_2 is varthetadot cos(psi); it is written \\dot{\\vartheta\\cos\\varphi}, the rate of vartheta cos(varphi), with varphi for psi and the dot over the product (check 70)",
         r"\omega_2 &= \ve{2} \cdot \vv{\omega} = \hphantom{-}\dot{\varphi}\sin\vartheta\sin\psi + \dot{\vartheta}\cos\psi,\\",
         "omega_2 = e_2 . omega with e_2 . e_1' = -sin(psi), e_2 . e_2' = cos(psi): omega_2 = varphidot sin(vartheta) sin(psi) + varthetadot cos(psi).",
         "The kinetic energy on the next lines squares (varphidot sin(vartheta) sin(psi) + varthetadot cos(psi)) for the I_2 term, with cos(psi); and the first row pairs varthetadot with sin(psi), so the second must pair it with cos(psi) (omega_1^2 + omega_2^2 must not depend on psi)."),
    76: ("holds", "T = (I_1 omega_1^2 + I_2 omega_2^2 + I_3 omega_3^2)/2 with the body components derived here (check 76)"),
    83: ("typo", "with A = I_1 = I_2 the first two lines hold, but the last line drops the square of the spin term: C (varphidot cos(vartheta) + psidot)^2 (check 83)",
         r"&= \frac{1}{2}[A(\dot{\vartheta}^2 + \dot{\varphi}^2\sin^2\vartheta) + C(\dot{\varphi}\cos\vartheta + \dot{\psi})^2].",
         "The line before has C omega_3^2 with omega_3 = varphidot cos(vartheta) + psidot, so the last line needs (varphidot cos(vartheta) + psidot)^2; the Lagrangian written next has the square.",
         "Dimensions: A varthetadot^2 is an energy (kg m^2/s^2) but C (varphidot cos + psidot) has units kg m^2/s; the two cannot be added in one bracket."),
    89: ("holds", "L = T - V with T from the corrected last line and V = M g l cos(vartheta) (check 89)"),
    94: ("holds", "dL/dpsidot = C (psidot + varphidot cos(vartheta)) = I_3 omega_3 (check 94)"),
    98: ("holds", "n = p_psi / C = omega_3 (check 98)"),
    102: ("holds", "dL/dvarphidot = A varphidot sin^2 + C (psidot + varphidot cos) cos = A varphidot sin^2 + C n cos (check 102)"),
    106: ("holds", "dL/dvarthetadot = A varthetadot (check 106)"),
    110: ("not a claim", "Lagrange's equation for vartheta in its general form"),
    114: ("holds", "dL/dvartheta = A varphidot^2 sin cos - C (psidot + varphidot cos) varphidot sin + M g l sin (check 114)"),
    118: ("holds", "the same with psidot + varphidot cos = n (check 118)"),
    122: ("not a claim", "the definition of the energy function h"),
    126: ("holds", "h = sum qdot p - L equals T + V for a T quadratic in the rates: A (varthetadot^2 + varphidot^2 sin^2)/2 + C n^2/2 + M g l cos (check 126)"),
    130: ("holds", "solving the energy for the A terms (check 130)"),
    134: ("holds", "varphidot = (L_z - C n cos)/(A sin^2) from L_z (check 134)"),
    141: ("holds", "udot = -varthetadot sin(vartheta), so udot^2 = (1 - u^2) varthetadot^2, a cubic in u (check 141)"),
    148: ("holds", "A varthetadot^2 / 2 = E - C n^2/2 - M g l cos - (L_z - C n cos)^2/(2 A sin^2) (check 148)"),
    152: ("not a claim", "the condition for steady precession, E' at the minimum of U, stated as a definition"),
    156: ("not a claim", "names the tilt at the minimum of U; no equation to check"),
    160: ("holds", "the conserved L_z and n in terms of the rates (checks 102 and 98)"),
    164: ("holds", "varthetaddot = 0 in Lagrange's equation at vartheta_0: sin(vartheta_0) [A cos(vartheta_0) varphidot^2 - C n varphidot + M g l] = 0 (check 164)"),
    168: ("holds", "the roots of the quadratic in varphidot (check 168)"),
    172: ("holds", "the roots are real when the discriminant C^2 n^2 - 4 A M g l cos(vartheta_0) is not negative (check 172)"),
    179: ("holds", "for a large spin (C^2 n^2 - 4 A M g l cos)^{1/2} = C n (1 - x)^{1/2} ~ C n (1 - x/2) with x = 4 A M g l cos/(C^2 n^2) (check 179)"),
    184: ("typo", "the slow root is the precession rate varphidot = M g l/(C n); the display calls it varthetadot, which is zero in steady precession (check 184)",
          r"\dot{\varphi} = \frac{Mgl}{Cn}.",
          "The lower sign: C n/(2 A cos) [1 - 1 + 2 A M g l cos/(C^2 n^2)] = M g l/(C n), a value of varphidot from the formula for varphidot above it.",
          "The section is about steady precession, where vartheta is constant and varthetadot = 0; the gyroscope's precession rate M g l/(C n) = torque/spin angular momentum is the rate of varphi."),
    188: ("holds", "the upper sign gives C n/(A cos(vartheta_0)) to leading order (check 188)"),
    195: ("holds", "Lagrange's equation with varphidot eliminated through L_z is A varthetaddot = -dU/dvartheta for the U of the energy equation, a particle of mass A in the potential U; near its minimum it oscillates at sqrt(U''(vartheta_0)/A) (check 195)"),
    199: ("not a claim", "the condition of a large spin, an assumption"),
    206: ("holds", "Lagrange's equation for vartheta (check 118)"),
    210: ("holds", "to first order in a small vartheta: sin ~ vartheta, sin cos ~ vartheta (check 210)"),
    214: ("holds", "started upright L_z = C n, and L_z = A varphidot sin^2 + C n cos is conserved (check 214)"),
    218: ("holds", "to second order C n (1 - cos vartheta) = C n vartheta^2/2 and A varphidot sin^2 = A varphidot vartheta^2 (check 218)"),
    222: ("typo", "the rate found is varphidot = C n/(2A), the precession rate of the nudged top; the display calls it varthetadot (check 222)",
          r"\dot{\varphi} = \frac{Cn}{2A}.",
          "Dividing the line before by A vartheta^2 gives varphidot = C n/(2A); the text's next sentence calls it the frequency at which the top precesses, and the next display substitutes it for varphidot.",
          "A check by the next display: putting varphidot = C n/(2A) into A varphidot^2 - C n varphidot + M g l gives M g l - C^2 n^2/(4A), the bracket written there; with varthetadot nothing would change in that bracket."),
    226: ("holds", "varphidot = C n/(2A) in the linearised equation gives (M g l - C^2 n^2/(4A)) vartheta (check 226)"),
}


if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
