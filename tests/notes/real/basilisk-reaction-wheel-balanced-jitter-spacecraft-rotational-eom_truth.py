"""Independent SymPy truth table for basilisk-reaction-wheel-balanced-jitter-spacecraft-rotational-eom.tex
(Basilisk's reaction wheel module, model description: balanced wheels and simple jitter).

The text's setting: a rigid hub carrying N reaction wheels; B a point fixed in the hub, C the
centre of mass of the whole spacecraft, c = r_{C/B}; every vector is written in body (B-frame)
components, a prime is the rate seen in the body frame, [x~] the cross-product matrix. Wheel i
spins at Omega_i relative to the hub about the body-fixed unit axis g_i, with moment J_i about it
and J_ti across it (a balanced wheel: g_i a principal axis, its centre of mass on the axis), so
the hub with the wheels has a constant inertia [I_sc,B] about B and the wheels add J_i Omega_i g_i
to the angular momentum. The model is built here from first principles, with two wheels: the
hub's attitude R(t) from three turns about z, x, z (the angles, the wheel speeds and B's path
written-out smooth functions of t, the masses, inertias, offsets and axes generic numbers, so that a
slip shows at the instants where the checks are evaluated), its angular velocity from R^T R';
Newton's law m r_C'' = F, Euler's
law about the moving point B, L_B = dH_B/dt + m c x r_B'' (H_B = [I]w + sum J Omega g), and each
wheel's own law about its spin axis, u_i = g_i . dH_Wi/dt (H_Wi = [I_Wi](w + Omega_i g_i)), the
inertial rates taken through R; never from the text's displays. The back-substitution pieces are
checked against the spacecraft module's split (its hub pieces m[I3], -m[c~], m[c~], [I_sc,B],
F - 2m[w~]c' - m[w~]^2 c and L_B - [I_sc,B]'w - [w~][I_sc,B]w, written in that module's model
description): a wheel's contribution is what the correct equations have beyond the hub's.
Simple jitter adds, for each wheel, the external force U_si Omega_i^2 u_i at the wheel's point W_i
and the external torque U_di Omega_i^2 v_i; the text writes these terms for wheel i without the
sum over the wheels (as all through that part), read here as summed.
Run as a program it compares its verdicts with the table; ``--write`` writes the table.
"""
import sys

import mpmath
import sympy as sp

import truth_table
from truth_table import Rx, Rz, numeric_zero

t = sp.Symbol('t', real=True)
CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


def skew(v):
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def vee(S):
    return sp.Matrix([S[2, 1], S[0, 2], S[1, 0]])


def vec(name):
    return sp.Matrix(sp.symbols(f'{name}_1:4', real=True))


D = lambda e: e.diff(t)  # noqa: E731
E3 = sp.eye(3)

# ---- the hub: attitude, angular velocity, the path of B, c = r_{C/B} -------------------------------
# arbitrary smooth motions, written out (an identity that holds for every motion holds for these; a
# slip shows at the sample points numeric_zero takes)
al, be, ga = sp.sin(2 * t / 3) + t**2 / 5, sp.cos(t) / 2 + t / 7 + 1, t**3 / 9 - sp.sin(t)
R = Rz(al) * Rx(be) * Rz(ga)                       # body -> inertial components
w = vee(R.T * D(R))                                # angular velocity, body components
wd = D(w)                                          # its rate (the same seen from either frame)
rB = sp.Matrix([sp.cos(t) + t**2, t**3 / 4 - 1, sp.sin(3 * t / 2)])   # B's inertial path
aB = R.T * D(D(rB))                                # r_B'' in body components
# the parameters: generic numbers (an identity in them holds for these; a slip shows)
r = lambda *x: sp.Matrix([sp.Rational(v) for v in x])  # noqa: E731
c = r('2/7', '-3/5', '5/11') + r('1/3', '2/9', '-1/4') * t   # c with a constant body rate c' (c'' = 0)
cp = D(c)
m = sp.Rational(7, 3)
Isc = sp.Matrix([[5, sp.Rational(1, 3), -sp.Rational(1, 4)], [sp.Rational(1, 3), 4, sp.Rational(1, 5)],
                 [-sp.Rational(1, 4), sp.Rational(1, 5), 3]])   # about B; constant: balanced wheels

# ---- two balanced wheels ------------------------------------------------------------------------------
wheels = []
for k in (1, 2):
    p, q = sp.Rational(k, 3), sp.Rational(7, 5) - sp.Rational(k, 2)
    g = sp.Matrix([sp.sin(q) * sp.cos(p), sp.sin(q) * sp.sin(p), sp.cos(q)])   # unit spin axis
    J, Jt, Us, Ud = sp.Rational(3, 7) * k, sp.Rational(2, 9) + k, sp.Rational(1, 11) * k, sp.Rational(2, 13) + k
    Om = k * t + sp.sin(k * t) / (k + 1)             # the wheel's speed relative to the hub
    IW = Jt * (E3 - g * g.T) + J * g * g.T           # the wheel's inertia about its centre
    HW = IW * (w + Om * g)
    u = (g.T * (R.T * D(R * HW)))[0]                 # the motor torque: the spin component of dH_W/dt
    uh, vh = r(k, '1/2', -1) / sp.sqrt(k**2 + sp.Rational(5, 4)), r('-1/3', k, '1/4') / sp.sqrt(k**2 + sp.Rational(25, 144))
    rW = r(k, -2 * k, '3/4')                         # jitter directions, W_i's place
    wheels.append(dict(g=g, J=J, Om=Om, u=u, Us=Us, Ud=Ud, uh=uh, vh=vh, rW=rW))

HB = Isc * w + sum((W['J'] * W['Om'] * W['g'] for W in wheels), sp.zeros(3, 1))
Ftot = m * R.T * D(D(rB + R * c))                  # Newton's law: the total external force
Ltot = R.T * D(R * HB) + m * c.cross(aB)           # Euler's law about the moving point B: the total torque
fj = [W['Us'] * W['Om']**2 * W['uh'] for W in wheels]                        # jitter forces
tj = [W['rW'].cross(f) + W['Ud'] * W['Om']**2 * W['vh'] for W, f in zip(wheels, fj)]   # jitter torques
S = lambda terms, n=1: sum(terms, sp.zeros(3, n))  # noqa: E731

# sanity of the derivation: the transport theorem that turns inertial rates into body ones
assert numeric_zero(R.T * D(R * c) - (cp + w.cross(c)), t)
assert numeric_zero(R.T * D(R * HB) - (Isc * wd + S(W['J'] * D(W['Om']) * W['g'] for W in wheels) + w.cross(HB)), t)


def sumJ(f):
    terms = [f(W) for W in wheels]
    return S(terms, terms[0].shape[1])


# The motion's long expressions (through R) are evaluated once, numerically, at three instants; the
# checks below are written in stand-ins for them and evaluated with their values there (30 digits).
HEAVY = dict(w=w, wd=wd, aB=aB, F=Ftot, L=Ltot, **{f'u{k}': sp.Matrix([W['u']]) for k, W in zip((1, 2), wheels)})
INSTANTS = [sp.Rational(31, 100), sp.Rational(77, 100), sp.Rational(7, 5)]
STAND = {k: sp.Matrix(sp.symbols(f'{k}S_1:{len(v) + 1}', real=True)) for k, v in HEAVY.items()}
with mpmath.workdps(30):
    VALUES = [{s_: mpmath.mpf(x) for k, v in HEAVY.items()
               for s_, x in zip(STAND[k], sp.lambdify(t, list(v), 'mpmath')(mpmath.mpf(t0)))} for t0 in INSTANTS]
w, wd, aB, Ftot, Ltot = (STAND[k] for k in ('w', 'wd', 'aB', 'F', 'L'))
for k, W in zip((1, 2), wheels):
    W['u'] = STAND[f'u{k}'][0]


def nz(e):
    """e (a matrix) vanishes at the three instants, every other name given a rational value."""
    e = sp.Matrix(e)
    rest = sorted(e.free_symbols - {t} - set().union(*(set(v) for v in STAND.values())), key=str)
    vals = {x: sp.Rational(3 + 2 * i, 7 + i) for i, x in enumerate(rest)}
    f = sp.lambdify([t, *VALUES[0].keys(), *vals], list(e), 'mpmath')
    with mpmath.workdps(30):
        for t0, V in zip(INSTANTS, VALUES):
            if max(abs(x) for x in f(mpmath.mpf(t0), *V.values(), *[mpmath.mpf(v) for v in vals.values()])) > mpmath.mpf(10)**-20:
                return False
    return True


# ================================ balanced wheels (F, L_B the whole external force and torque) =========
F, LB = Ftot, Ltot
trans = m * aB - m * skew(c) * wd - (F - 2 * m * skew(w) * cp - m * skew(w) * skew(w) * c)
check(35, nz(trans))
rot7 = (m * skew(c) * aB + Isc * wd + sumJ(lambda W: W['J'] * W['g'] * D(W['Om']))
        - (-skew(w) * Isc * w - sumJ(lambda W: w.cross(W['J'] * W['Om'] * W['g'])) + LB))
check(43, nz(rot7))
check(52, all(nz(sp.Matrix([D(W['Om']) - (W['u'] / W['J'] - (W['g'].T * wd)[0])])) for W in wheels))
Iprime = sp.zeros(3, 3)                            # [I_sc,B]' = 0: balanced wheels keep the mass properties
rot72 = (m * skew(c) * aB + (Isc - sumJ(lambda W: W['J'] * W['g'] * W['g'].T)) * wd
         - (-skew(w) * Isc * w - sumJ(lambda W: W['g'] * W['u'] + w.cross(W['J'] * W['Om'] * W['g']))
            - Iprime * w + LB))
check(58, nz(rot72))

# the back-substitution pieces: the correct equations with r_B'', w' (a, b below), F, L_B, u_i as
# free symbols, built from the laws above (Omega_i' = u_i/J_i - g_i . w' from the wheel's law)
a_, b_ = vec('a'), vec('b')
Fs, Ls = vec('F'), vec('L')
us = [sp.Symbol(f'u{k}') for k in (1, 2)]


def pieces(fj_, tj_):
    T = m * a_ - m * skew(c) * b_ - (Fs + S(fj_) - 2 * m * skew(w) * cp - m * skew(w) * skew(w) * c)
    Omd = [ui / W['J'] - (W['g'].T * b_)[0] for ui, W in zip(us, wheels)]
    Rr = (m * skew(c) * a_ + Isc * b_ + S(W['J'] * W['g'] * o for W, o in zip(wheels, Omd))
          + w.cross(Isc * w + S(W['J'] * W['Om'] * W['g'] for W in wheels)) - (Ls + S(tj_)))
    zero = {**{x: 0 for x in a_}, **{x: 0 for x in b_}}
    hub = dict(A=m * E3, B=-m * skew(c), C=m * skew(c), D=Isc,
               vt=Fs - 2 * m * skew(w) * cp - m * skew(w) * skew(w) * c,
               vr=Ls - Iprime * w - skew(w) * Isc * w)
    return dict(A=T.jacobian(a_) - hub['A'], B=T.jacobian(b_) - hub['B'],
                C=Rr.jacobian(a_) - hub['C'], D=Rr.jacobian(b_) - hub['D'],
                vt=-T.subs(zero) - hub['vt'], vr=-Rr.subs(zero) - hub['vr'])


def same(x, y):
    return nz(sp.Matrix(x - y).subs({ui: W['u'] for ui, W in zip(us, wheels)}))


P = pieces([], [])
Dc = -sumJ(lambda W: W['J'] * W['g'] * W['g'].T)
vr_bal = -sumJ(lambda W: W['g'] * W['u'] + w.cross(W['J'] * W['Om'] * W['g']))
check(67, same(P['A'], sp.zeros(3, 3)))
check(71, same(P['B'], sp.zeros(3, 3)))
check(75, same(P['C'], sp.zeros(3, 3)))
check(79, same(P['D'], Dc))
check(83, same(P['vt'], sp.zeros(3, 1)))
check(87, same(P['vr'], vr_bal))

# ================================ simple jitter (F_ext, L_B without the jitter force and torque) =======
F, LB = Ftot - S(fj), Ltot - S(tj)
trans_j = m * aB - m * skew(c) * wd - (F - 2 * m * skew(w) * cp - m * skew(w) * skew(w) * c + S(fj))
check(95, nz(trans_j))
rot7_j = (m * skew(c) * aB + Isc * wd + sumJ(lambda W: W['J'] * W['g'] * D(W['Om']))
          - (-skew(w) * Isc * w - sumJ(lambda W: w.cross(W['J'] * W['Om'] * W['g']))
             + S(W['Us'] * W['Om']**2 * skew(W['rW']) * W['uh'] + W['Ud'] * W['Om']**2 * W['vh'] for W in wheels)
             + LB))
check(103, nz(rot7_j))
check(113, all(nz(sp.Matrix([D(W['Om']) - (W['u'] / W['J'] - (W['g'].T * wd)[0])])) for W in wheels))
vhat = vec('vhat')                                 # the display's v-hat, without the wheel's index (a name)


def rot72_j(v_of):
    return (m * skew(c) * aB + (Isc - sumJ(lambda W: W['J'] * W['g'] * W['g'].T)) * wd
            - (-skew(w) * Isc * w - sumJ(lambda W: W['g'] * W['u'] + w.cross(W['J'] * W['Om'] * W['g']))
               - Iprime * w + S(W['Us'] * W['Om']**2 * skew(W['rW']) * W['uh'] + W['Ud'] * W['Om']**2 * v_of(W)
                                for W in wheels) + LB))


check(119, nz(rot72_j(lambda W: vhat)))
assert nz(rot72_j(lambda W: W['vh']))             # with v_i, the wheel's own direction, it holds

Pj = pieces(fj, tj)
check(127, same(Pj['A'], sp.zeros(3, 3)))
check(131, same(Pj['B'], sp.zeros(3, 3)))
check(135, same(Pj['C'], sp.zeros(3, 3)))
check(139, same(Pj['D'], Dc))
check(143, same(Pj['vt'], S(fj)))
jit = lambda v_of: S(W['Us'] * W['Om']**2 * skew(W['rW']) * W['uh'] + W['Ud'] * W['Om']**2 * v_of(W)  # noqa: E731
                     for W in wheels)
check(147, same(Pj['vr'], jit(lambda W: vhat)))    # the display: the jitter torques alone
assert same(Pj['vr'], vr_bal + jit(lambda W: W['vh']))   # the wheels' own part as at balanced wheels, plus them

ROWS = {
    35: ("holds", "Newton's law for the centre of mass C = B + c in body components: m(r_B'' + c'' + 2 w x c' + w' x c + "
                  "w x (w x c)) = F with c'' = 0 (balanced wheels do not move C), and w' x c = -[c~] w' (check 35)"),
    43: ("holds", "Euler's law about the moving point B, L_B = dH_B/dt + m c x r_B'', with H_B = [I_sc,B] w + sum J_i "
                  "Omega_i g_i and [I_sc,B] constant (balanced wheels): m[c~]r_B'' + [I]w' + sum J g Omega' = -[w~][I]w "
                  "- sum w x J Omega g + L_B (check 43)"),
    52: ("holds", "the wheel's spin component of its own Euler law: u_i = J_i (g_i . w' + Omega_i'), its transverse "
                  "inertia dropping out (check 52)"),
    58: ("holds", "the display before with Omega_i' = u_i/J_i - g_i^T w': -sum g u moves to the right and -J g g^T w' "
                  "joins [I]; the added -[I'_sc,B] w is zero for balanced wheels (check 58)"),
    67: ("holds", "the translational equation has no wheel term beside the hub's m[I3] r_B'' (check 67)"),
    71: ("holds", "nor beside the hub's -m[c~] w' (check 71)"),
    75: ("holds", "the rotational equation's r_B'' term is the hub's m[c~] alone (check 75)"),
    79: ("holds", "the wheels' part of the w' coefficient after eliminating Omega': -sum J g g^T (check 79)"),
    83: ("holds", "balanced wheels add no force (check 83)"),
    87: ("holds", "the wheels' part of the rotational right-hand side: -sum (g u + w x J Omega g) (check 87)"),
    95: ("holds", "Newton's law as at the balanced wheels plus the jitter force U_s Omega^2 u-hat of each wheel "
                  "(the text writes it for wheel i without the sum over the wheels; read as summed) (check 95)"),
    103: ("holds", "Euler's law about B with the jitter force's moment r_{W_i/B} x U_s Omega^2 u_i and the torque "
                   "U_d Omega^2 v_i added to L_B (terms for wheel i, read as summed) (check 103)"),
    113: ("holds", "the same motor torque equation as for balanced wheels (check 113)"),
    119: ("typo", "putting Omega' in changes only the J g Omega' terms, so the dynamic-imbalance torque must stay "
                  "U_{d_i} Omega_i^2 v_i as in the display before; here v-hat has lost its index i (check 119)",
           r"m_{\text{sc}}[\tilde{\bm{c}}] \ddot{\bm r}_{B/N}"
           r"+([I_{\text{sc},B}]-\sum_{i=1}^{N}J_{\text{s}_i} \hat{\bm g}_{\text{s}_i} \hat{\bm g}_{\text{s}_i}^T) \dot{\bm\omega}_{\cal B/N}"
           r"= -[\bm{\tilde{\omega}}_{\cal B/N}] [I_{\text{sc},B}] \bm\omega_{\cal B/N} - \sum_{i=1}^{N}(\hat{\bm g}_{\text{s}_i} u_{\text{s}_i}"
           r" + \bm\omega_{\cal B/N}\times J_{\text{s}_i}\Omega_i\hat{\bm g}_{\text{s}_i})"
           r"- [I'_{\text{sc},B}] \bm\omega_{\cal B/N} + U_{s_i}\Omega_i^2[\tilde{\bm{r}}_{W_i/B}]\hat{\bm{u}}_i"
           r" + U_{d_i}\Omega_i^2\hat{\bm{v}}_i + \bm{L}_B",
           "The rotational equation just before (its last line) has + U_{d_i}Omega_i^2 v_i, the torque along the "
           "wheel's own unit vector v_i; Omega_i' = u_i/J_i - g_i^T w' enters only through the sum of J_i g_i Omega_i', "
           "so the substitution leaves that torque as it was. With one wheel, U_d = 1, Omega_1 = 2 and v_1 = (0, 1, 0) "
           "the torque is (0, 4, 0); the display's U_d Omega^2 v-hat names a vector v-hat the text never defines and "
           "gives (0, 4, 0) only if v-hat is v_1.",
           "The module's own code (reactionWheelStateEffector.cpp, the JitterSimple branch) adds to the rotational "
           "right-hand side, wheel by wheel, rWB_B.cross(tempF) + U_d*OmegaSquared*w2Hat_B: each wheel's torque along "
           "its own unit vector, the v_i of the equation before; and in the same display the static term keeps its "
           "index (u_i), as the translational equation and v_trans,contr do."),
    127: ("holds", "no wheel term beside the hub's m[I3] r_B'' (check 127)"),
    131: ("holds", "nor beside the hub's -m[c~] w' (check 131)"),
    135: ("holds", "the r_B'' term of the rotational equation is the hub's alone (check 135)"),
    139: ("holds", "as for balanced wheels: -sum J g g^T (check 139)"),
    143: ("holds", "the jitter force U_s Omega^2 u_i (for wheel i, read as summed) (check 143)"),
    147: ("fails", "the simple-jitter rotational equation above (after eliminating Omega') has on its right, beside the "
                   "hub's L_B - [I']w - [w~][I]w, the wheels' -sum (g u + w x J Omega g) and the jitter torques U_s Omega^2 "
                   "[r~_{W_i/B}] u_i + U_{d_i} Omega_i^2 v_i; the display keeps only the jitter torques (the wheels' own part, "
                   "the balanced contribution, is lost) and its v-hat has lost the index i (check 147)",
           "",
           "Reading the pieces off the rotational equation just above: its right-hand side is -[w~][I]w - sum (g u + w x J "
           "Omega g) - [I']w + jitter torques + L_B, and the spacecraft module's hub piece is L_B - [I']w - [w~][I]w, so "
           "the wheels contribute -sum (g u + w x J Omega g) + jitter torques: the balanced contribution (the text's own "
           "display at the balanced wheels) plus the imbalance. In numbers: one wheel along g = (0, 0, 1), J = 1, Omega = "
           "2, w = (1, 0, 0), u = 0 and no imbalance (U_s = U_d = 0): -w x J Omega g = -((1, 0, 0) x (0, 0, 2)) = (0, 2, "
           "0), while the display gives 0.",
           "Limiting case U_s = U_d = 0: simple jitter becomes the balanced wheels, whose contribution the text itself "
           "gives as -sum (g u + w x J Omega g), not zero as this display would make it. The module's code agrees: "
           "JitterSimple shares the BalancedWheels branch, which first subtracts gsHat_B (u + friction) + Js Omega "
           "omega x gsHat_B from vecRot and only then adds rWB_B x F_s + U_d Omega^2 w2Hat_B, the wheel's own vector "
           "(v_i, not one v-hat for all wheels)."),
}

LINES = sorted(ROWS)


if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
