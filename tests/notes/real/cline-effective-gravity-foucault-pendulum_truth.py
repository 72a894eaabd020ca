"""Independent SymPy truth table for cline-effective-gravity-foucault-pendulum.md
(Cline, Variational Principles in Classical Mechanics, ch. 12, sections 12.10 and 12.13, MyST edition).

The text's convention: a ground frame (i', j', k') at latitude lambda (colatitude theta = pi/2 - lambda),
i' east, j' north, k' up, turning with the Earth at the constant angular velocity omega (called Omega in
section 12.13) along the polar axis, so that omega has ground components (0, omega cos lambda,
omega sin lambda); R is the vector from the Earth's centre to the ground frame's origin (R k'), r' the
position in the ground frame, r = R + r'. Everything is built from the inertial motion: the position
X(t) = Rz(omega t) C (R k' + r'(t)) in axes through the Earth's centre (C the constant matrix whose
columns are i', j', k'), differentiated twice and carried back into ground components; for the
general law (12.10's first law) a frame turned by z-x-z Euler angles that are any functions of time,
its origin moving in any way. The pendulum: a bob on a string of length l hung from (0, 0, l), the
tension along the string, linearised in the small displacement. No formula of the text is assumed.
Run as a program it compares its verdicts with the table; ``--write`` writes the table.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Rz, numeric_zero, zero

t = sp.Symbol('t', real=True)
w, Rr, g, m, l, lam, th = sp.symbols('omega R g m l lambda theta', positive=True)
eps = sp.Symbol('epsilon')
D = lambda e: sp.diff(e, t)  # noqa: E731

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


def vee(S):
    return sp.Matrix([S[2, 1], S[0, 2], S[1, 0]])


def cross(a, b):
    return a.cross(b)


# ---- the general law in a frame that turns and translates in any way (line 29)
ph, tht, ps = [sp.Function(n)(t) for n in ('phi', 'vartheta', 'psi')]
Q = Rz(ph) * Rx(tht) * Rz(ps)                       # rotating axes in inertial ones (active)
W = sp.simplify(vee(Q.T * D(Q)))                    # the frame's angular velocity, rotating components
X0 = sp.Matrix([sp.Function(f'X0{i}')(t) for i in range(3)])     # the frame's origin, inertial
rp = sp.Matrix([sp.Function(f'x{i}')(t) for i in range(3)])      # r', rotating components
Fm = sp.Matrix(sp.symbols('F_1:4')) / m                         # F/m, rotating components
gv = sp.Matrix(sp.symbols('g_1:4'))                             # g, rotating components
X = X0 + Q * rp
A_rot = Q.T * D(D(X0))                              # the origin's acceleration in rotating components
# Newton in the inertial frame, Q^T X'' = F/m + g; so a' = rp'' = F/m + g - (A + the frame's terms)
# exactly when Q^T X'' = A + rp'' + 2 W x rp' + W x (W x rp) + W' x rp for every motion
check(29, numeric_zero(Q.T * D(D(X)) - (A_rot + D(D(rp)) + 2 * cross(W, D(rp)) + cross(W, cross(W, rp))
                                        + cross(D(W), rp)), t))

# ---- the Earth: constant rotation, the ground frame at latitude lambda (lines 35-98)
kp = sp.Matrix([sp.cos(lam), 0, sp.sin(lam)])      # up, in Earth-fixed axes (Z polar)
ip = sp.Matrix([0, 1, 0])                           # east
jp = sp.Matrix([-sp.sin(lam), 0, sp.cos(lam)])     # north
C = sp.Matrix.hstack(ip, jp, kp)
assert zero(ip.cross(jp) - kp)
Qe = Rz(w * t) * C                                  # ground axes in inertial ones
We = sp.simplify(vee(Qe.T * D(Qe)))                 # omega in ground components
assert zero(We - sp.Matrix([0, w * sp.cos(lam), w * sp.sin(lam)]))
Rv = sp.Matrix([0, 0, Rr])                          # R in ground components
Xo = Qe * Rv                                        # the origin, inertial
# line 35: V = (dR/dt)_fixed = (dR/dt)_rot + w x R = w x R
V_true = Qe.T * D(Xo)
check(35, zero(V_true - (D(Rv) + cross(We, Rv))) and zero(D(Rv)) and zero(V_true - cross(We, Rv)))
# line 42: A = (dV/dt)_fixed = (dV/dt)_rot + w x V = w x (w x R), V in ground components constant
A_true = Qe.T * D(D(Xo))
check(42, zero(A_true - (D(V_true) + cross(We, V_true))) and zero(D(V_true))
      and zero(A_true - cross(We, cross(We, Rv))))
# line 48: a' = F/m + g - (2 w x v' + w x (w x [r' + R]) + w' x r') = ... w x (w x r), r = R + r'
Xe = Qe * (Rv + rp)
Wd = D(We)
assert zero(Wd)
kin = Qe.T * D(D(Xe)) - (D(D(rp)) + 2 * cross(We, D(rp)) + cross(We, cross(We, rp + Rv)) + cross(Wd, rp))
# on the motion Qe^T X'' = F/m + g (Newton), so a' = rp'' = F/m + g - (the frame terms) exactly when kin = 0
row1 = Fm + gv - (2 * cross(We, D(rp)) + cross(We, cross(We, rp + Rv)) + cross(Wd, rp))
rv = Rv + rp
row2 = Fm + gv - (2 * cross(We, D(rp)) + cross(We, cross(We, rv)) + cross(Wd, rp))
check(48, zero(kin) and zero(row1 - row2))
# line 55: (12.52) a' = F/m + [g - w x (w x r)] - 2 w x v', w' = 0
check(55, zero(kin) and zero(row2 - (Fm + (gv - cross(We, cross(We, rv))) - 2 * cross(We, D(rp)))))
# line 79: |w x (w x r)| ~ w^2 R sin(theta) = w^2 R cos(lambda) with r ~ R, theta = pi/2 - lambda
cf = cross(We, cross(We, Rv))
check(79, zero(cf.dot(cf) - (w**2 * Rr * sp.cos(lam))**2)      # both sides >= 0 for 0 < lambda < pi/2
      and zero((w**2 * Rr * sp.sin(th)).subs(th, sp.pi / 2 - lam) - w**2 * Rr * sp.cos(lam)))
# lines 86, 92, 98: g_eff = -g k' - w x (w x R k') near the surface
geff = sp.Matrix([0, 0, -g]) - cf
gh = sp.sqrt(sp.simplify(geff[0]**2 + geff[1]**2))
gvert = -geff[2]
check(86, zero(gh**2 - (w**2 * Rr * sp.cos(lam) * sp.sin(lam))**2))      # both sides >= 0 for 0 < lambda < pi/2
check(92, zero(gvert - (g - w**2 * Rr * sp.cos(lam)**2)))
# alpha: the angle between g_eff and -k' (the line to the centre): tan(alpha) = horizontal / vertical
tan_alpha = gh / gvert
check(98, zero(tan_alpha**2 - ((w**2 * Rr * sp.cos(lam) * sp.sin(lam)) / (g - w**2 * Rr * sp.cos(lam)**2))**2)
      and sp.series(sp.tan(eps), eps, 0, 3).removeO() == eps)    # alpha ~ tan(alpha) for the small angle

# ---- section 12.13: the Foucault pendulum in the ground frame, Omega = (0, Omega sin th, Omega cos th)
Om, g0s, w0 = sp.symbols('Omega g_0 omega_0', positive=True)
Wf = sp.Matrix([0, Om * sp.sin(th), Om * sp.cos(th)])
Qf = Rz(Om * t) * C.subs(lam, sp.pi / 2 - th)
assert zero(sp.simplify(vee(Qf.T * D(Qf))) - Wf)
x, y, z = [sp.Function(n)(t) for n in ('x', 'y', 'z')]
r3 = sp.Matrix([x, y, z])
Tv = sp.Matrix(sp.symbols('T_1:4'))                 # tension, ground components
g0v = sp.Matrix(sp.symbols('g0_1:4'))               # true gravity at the bob, ground components
Xf = Qf * (Rv + r3)
rdd_true = Qf.T * D(D(Xf)) - 2 * cross(Wf, D(r3)) - cross(Wf, cross(Wf, r3 + Rv)) - D(D(r3))
assert zero(rdd_true)                               # the kinematics: Qf^T X'' = r'' + 2 W x r' + W x (W x (r+R))
# Newton: Qf^T X'' = g0 + T/m, so r'' = g0 - W x (W x (r + R)) + T/m - 2 W x r'
geff_f = g0v - cross(Wf, cross(Wf, r3 + Rv))        # (12.78) the effective gravity
rdd = g0v + Tv / m - 2 * cross(Wf, D(r3)) - cross(Wf, cross(Wf, r3 + Rv))
# line 115: r'' = g + T/m - 2 Omega x r'
check(115, zero(rdd - (geff_f + Tv / m - 2 * cross(Wf, D(r3)))))
# lines 132, 136: the tension along the string from the bob (x, y, z) to the pivot (0, 0, l), T ~ m g,
# to first order in the small displacement (x, y) = eps (X, Y), z of second order
Xs, Ys, Tm = sp.symbols('X Y T', real=True)
bob = sp.Matrix([eps * Xs, eps * Ys, l - sp.sqrt(l**2 - eps**2 * (Xs**2 + Ys**2))])
Tvec = Tm * (sp.Matrix([0, 0, l]) - bob) / l
Tlin = Tvec.applyfunc(lambda e: sp.series(e, eps, 0, 2).removeO()).subs(Tm, m * g)
check(132, zero(Tlin[2] - (-m * g * eps * Xs / l)))          # the display's T_z; T_z ~ T = m g
assert zero(Tlin[0] - (-m * g * eps * Xs / l))               # -m g x / l is T_x
check(136, zero(Tlin[1] - (-m * g * eps * Ys / l)))
# lines 143, 147: horizontal equations, g vertical, z' dropped, T from the linearised tension
sub_h = {D(z): 0}
xdd = (Tlin[0] / m).subs(eps * Xs, x) - 2 * cross(Wf, D(r3))[0].subs(sub_h)
ydd = (Tlin[1] / m).subs(eps * Ys, y) - 2 * cross(Wf, D(r3))[1].subs(sub_h)
check(143, zero(xdd - (-g * x / l + 2 * D(y) * Om * sp.cos(th))))
check(147, zero(ydd - (-g * y / l + 2 * D(x) * Om * sp.cos(th))))
assert zero(ydd - (-g * y / l - 2 * D(x) * Om * sp.cos(th)))  # the sign the cross product gives
# line 153: theta is the colatitude, lambda = pi/2 - theta
check(153, zero(sp.cos(th) - sp.sin(sp.pi / 2 - th)))
# line 165: Omega_z, the vertical (k') component of the Earth's angular velocity
Omz = Wf[2]
check(165, zero(Omz - Om * sp.cos(th)))
# line 171: (12.86) with omega_0^2 = g / l; the true residuals of x'' = xdd, y'' = ydd
Oz = sp.Symbol('Omega_z', positive=True)
Ex = (D(D(x)) - xdd).subs({g: w0**2 * l, Om * sp.cos(th): Oz})
Ey = (D(D(y)) - ydd).subs({g: w0**2 * l, Om * sp.cos(th): Oz})
row_x = D(D(x)) - 2 * Oz * D(y) + w0**2 * x
row_y = D(D(y)) - 2 * Oz * D(x) + w0**2 * y
check(171, zero(sp.expand(Ex - row_x)) and zero(sp.expand(Ey - row_y)))
assert zero(sp.expand(Ex - row_x)) and not zero(sp.expand(Ey - row_y))   # the first row holds
# line 184: (x'' + i y'') + 2 i Omega_z (x' + i y') + omega_0^2 (x + i y) = 0 is E_x + i E_y
I = sp.I
combo = (D(D(x)) + I * D(D(y))) + 2 * I * Oz * (D(x) + I * D(y)) + w0**2 * (x + I * y)
check(184, zero(sp.expand(combo - (Ex + I * Ey))))
# line 190: (12.88), the same with eta = x + i y
eta = x + I * y
check(190, zero(sp.expand(D(D(eta)) + 2 * I * Oz * D(eta) + w0**2 * eta - combo)))
# line 204: eta = A e^{-i alpha t} in (12.88): (-alpha^2 + 2 Omega_z alpha + omega_0^2) A e^{-i alpha t}
al, Aa = sp.symbols('alpha A')
trial = Aa * sp.exp(-I * al * t)
charp = sp.simplify((D(D(trial)) + 2 * I * Oz * D(trial) + w0**2 * trial) / trial)
check(204, zero(sp.expand(charp + (al**2 - 2 * Oz * al - w0**2))))
# line 210: the roots
roots = sp.solve(al**2 - 2 * Oz * al - w0**2, al)
check(210, len(roots) == 2 and all(any(zero(r_ - (Oz + s * sp.sqrt(Oz**2 + w0**2))) for r_ in roots) for s in (1, -1)))
# line 216: to first order in Omega_z / omega_0
k = sp.Symbol('kappa')
approx = [sp.series((Oz + s * sp.sqrt(Oz**2 + w0**2)).subs(Oz, k * w0), k, 0, 2).removeO() for s in (1, -1)]
check(216, all(zero(a - (k * w0 + s * w0)) for a, s in zip(approx, (1, -1))))
# line 222: the general solution must be the sum of the two independent modes e^{-i alpha_pm t},
# alpha_pm ~ Omega_z pm omega_0: the two printed terms must be independent (non-zero Wronskian)
Ap, Am = sp.symbols('A_p A_m')
u1 = sp.exp(-I * Oz * t) * sp.exp(I * w0 * t)
u2 = sp.exp(-I * Oz * t) * sp.exp(I * w0 * t)            # as printed, the second term's exponent
wr = sp.simplify(u1 * D(u2) - u2 * D(u1))
modes_true = [sp.exp(-I * (Oz + w0) * t), sp.exp(-I * (Oz - w0) * t)]
check(222, not zero(wr))
assert not zero(sp.simplify(modes_true[0] * D(modes_true[1]) - modes_true[1] * D(modes_true[0])))
# line 228: A e^{-i Omega_z t} cos(omega_0 t + delta) solves (12.88) to first order in Omega_z
dl = sp.Symbol('delta', real=True)
sol = Aa * sp.exp(-I * Oz * t) * sp.cos(w0 * t + dl)
res = sp.simplify((D(D(sol)) + 2 * I * Oz * D(sol) + w0**2 * sol) / sp.exp(-I * Oz * t))
check(228, zero(sp.series(res.subs(Oz, k * w0), k, 0, 2).removeO())
      and zero(sp.expand(sp.exp(-I * Oz * t) * (Aa / 2 * sp.exp(I * dl) * sp.exp(I * w0 * t)
                                                 + Aa / 2 * sp.exp(-I * dl) * sp.exp(-I * w0 * t))
                         - sol.rewrite(sp.exp))))
# line 236: Omega_z = Omega cos(theta) = Omega sin(lambda)
check(236, zero(Omz - Om * sp.cos(th)) and zero((Om * sp.cos(th)).subs(th, sp.pi / 2 - lam) - Om * sp.sin(lam)))

LINES = [21, 29, 35, 42, 48, 55, 64, 79, 86, 92, 98, 115, 123, 132, 136, 143, 147, 153, 159, 165, 171,
         178, 184, 190, 198, 204, 210, 216, 222, 228, 236]

ROWS = {
    21: ("not a claim", "the split of the position from the Earth's centre into the ground frame's origin R and the position r' in the ground frame: the naming the section starts from"),
    29: ("holds", "for a frame turned by any time-dependent rotation Q and translated in any way, Q^T X'' = A + r'' + 2 w x r' + w x (w x r') + w' x r' identically, so Newton's F/m + g = Q^T X'' gives the display with a' = r'' (check 29)"),
    35: ("holds", "R has constant ground components, so (dR/dt)_rot = 0, and Q^T d(Q R)/dt = w x R for the Earth's turning ground frame (check 35)"),
    42: ("holds", "V = w x R has constant ground components too, and Q^T d^2(Q R)/dt^2 = w x (w x R) = (dV/dt)_rot + w x V (check 42)"),
    48: ("holds", "with A = w x (w x R) the two centrifugal terms join, w x (w x r') + w x (w x R) = w x (w x [r' + R]), and r' + R = r; the whole follows from Q^T X'' = r'' + 2 w x r' + w x (w x (R + r')) for the Earth's constant rotation (check 48)"),
    55: ("holds", "the row above with w' = 0 for the Earth's constant rotation, the terms regrouped (check 55)"),
    64: ("not a claim", "the definition of the effective gravity, the bracket of (12.52)"),
    79: ("holds", "with w = w(0, cos lambda, sin lambda) in the ground frame (east, north, up) and r ~ R k', w x (w x R k') = w^2 R (0, sin lambda cos lambda, -cos^2 lambda), of length w^2 R cos lambda, and sin theta = cos lambda for the colatitude theta = pi/2 - lambda (check 79)"),
    86: ("holds", "g_eff = -g k' - w x (w x R k') = (0, -w^2 R sin lambda cos lambda, -g + w^2 R cos^2 lambda): its horizontal part has length w^2 R cos lambda sin lambda (check 86)"),
    92: ("holds", "the vertical (downward) part of the same g_eff is g - w^2 R cos^2 lambda (check 92)"),
    98: ("holds", "the angle between g_eff and the line to the centre (-k') has tan alpha = horizontal / vertical part, and alpha ~ tan alpha for the small angle (check 98)"),
    115: ("holds", "the ground frame turns at the constant Omega: Q^T X'' = r'' + 2 Omega x r' + Omega x (Omega x (r + R)), and Newton's Q^T X'' = g_0 + T/m, with g = g_0 - Omega x [Omega x (r + R)], gives r'' = g + T/m - 2 Omega x r' (check 115)"),
    123: ("not a claim", "the definition of the effective gravity g used in the pendulum's equation: the true field with the centrifugal correction"),
    132: ("typo", "the tension T ~ m g along the string from the bob to the point of suspension has, to first order in the displacement, components (-m g x/l, -m g y/l, m g): -m g x/l is its x component, while its z component is ~ m g, as the text's own sentence before says; the subscript z stands for x (check 132)",
          "T_x = −mg \\frac{x}{l}",
          "Numbers: l = 10 m, the bob at x = 1 m, y = 0. The string points from the bob to the suspension along (-1, 0, sqrt 99)/10, so with T = m g the tension has T_x = -0.1 m g and T_z = 0.995 m g. The display's -m g x/l = -0.1 m g is T_x, not T_z.",
          "Limiting case: at x = 0 (the bob hanging at rest below the suspension) the vertical tension must carry the weight, T_z = m g, but -m g x/l gives 0. The next display, T_y = -m g y/l, is the other horizontal component: the pair is (T_x, T_y)."),
    136: ("holds", "the y component of the linearised tension, T ~ m g along the string (check 136)"),
    143: ("holds", "the x component of r'' = g + T/m - 2 Omega x r' with g vertical and z' dropped: -2(Omega_y z' - Omega_z y') = 2 Omega cos(theta) y', plus the tension's -g x/l (check 143)"),
    147: ("typo", "the y component of -2 Omega x r' is -2(Omega_z x' - Omega_x z') = -2 Omega cos(theta) x' with z' dropped; the display prints +2 x' Omega cos(theta): the sign of the Coriolis term is flipped, while the x row (12.81) has the right one (check 147)",
          "\\ddot{y} = −g\\frac{y}{l} − 2\\dot{x}\\Omega \\cos \\theta \\label{12.82}",
          "Cross product by hand with only the vertical part Omega_z of the Earth's rotation (the others multiply z', dropped): -2 Omega_z k x (x', y', 0) = -2 Omega_z (-y', x', 0) = (2 Omega_z y', -2 Omega_z x', 0). The x entry matches (12.81); the y entry is -2 Omega_z x'. Numbers: x' = 1, y' = 0, Omega_z = 1, x = y = 0: y'' = -2 (deflection to the right of the motion, as in the northern hemisphere); the display gives +2, to the left.",
          "Energy: the Coriolis force does no work, so E = (x'^2 + y'^2)/2 + omega_0^2 (x^2 + y^2)/2 must stay constant. With the corrected rows dE/dt = x'(2 Omega_z y') + y'(-2 Omega_z x') = 0; with the printed rows dE/dt = 4 Omega_z x' y' != 0, and u = x + y obeys u'' - 2 Omega_z u' + omega_0^2 u = 0, a swing growing like e^(Omega_z t)."),
    153: ("holds", "theta is the colatitude, lambda = pi/2 - theta, so cos theta = sin lambda (check 153)"),
    159: ("not a claim", "the definition of the pendulum's natural angular frequency"),
    165: ("holds", "the vertical (k') component of Omega = Omega(0, sin theta, cos theta) in the ground frame is Omega cos theta; the source's control space '\\ cos' only sets cos in italics, the formula is the right one (check 165)"),
    171: ("typo", "with omega_0^2 = g/l the x row of (12.81) is x'' - 2 Omega_z y' + omega_0^2 x = 0 and holds; the y row carries the sign slip of (12.82): the true row is y'' + 2 Omega_z x' + omega_0^2 y = 0 (check 171)",
          "\\begin{align} \\notag \\ddot{x} - 2\\Omega_z \\dot{y} + \\omega^2_0 x = 0 \\\\ \\ddot{y} + 2\\Omega_z \\dot{x} + \\omega^2_0 y = 0 \\label{12.86} \\end{align}",
          "Numbers at one instant: y = 0, x' = 1, Omega_z = 1, omega_0 = 1. The cross product -2 Omega_z k x (x', y', 0) gives y'' = -2 Omega_z x' = -2, i.e. y'' + 2 Omega_z x' + omega_0^2 y = 0; the printed row gives y'' = +2 Omega_z x' = +2.",
          "The text's own next step: i times the second row plus the first should give (x'' + i y'') + 2 i Omega_z (x' + i y') + omega_0^2 (x + i y) = 0. With +2 Omega_z x' in the second row, i(2 Omega_z x') - 2 Omega_z y' = 2 i Omega_z (x' + i y'), as the text writes; with the printed -2 Omega_z x' it is -2 i Omega_z (x' - i y'), the conjugate velocity, which is not the next display."),
    178: ("not a claim", "the definition of the complex coordinate eta"),
    184: ("holds", "the true rows x'' - 2 Omega_z y' + omega_0^2 x = 0 and y'' + 2 Omega_z x' + omega_0^2 y = 0, the first plus i times the second, give exactly this equation (it does not follow from the printed second row of (12.86)) (check 184)"),
    190: ("holds", "the line above written with eta = x + i y (check 190)"),
    198: ("not a claim", "the trial solution, its amplitude written A_e"),
    204: ("holds", "eta = A e^{-i alpha t} in (12.88) gives (-alpha^2 + 2 Omega_z alpha + omega_0^2) A e^{-i alpha t} = 0; the display writes omega_0 with a letter o as omega_o (check 204)"),
    210: ("holds", "the two roots of alpha^2 - 2 Omega_z alpha - omega_0^2 = 0 (check 210)"),
    216: ("holds", "to first order in Omega_z/omega_0 the roots are Omega_z +- omega_0 (the display writes Omega_Z with a capital Z) (check 216)"),
    222: ("typo", "the roots alpha ~ Omega_z +- omega_0 give the modes e^{-i Omega_z t} e^{-+ i omega_0 t}, exponents of opposite sign; the display prints e^{i omega_0 t} in both terms, one and the same mode, so it is not the general solution of the second-order equation (their Wronskian vanishes) and cannot be the cos form that follows (check 222)",
          "\\eta (t) = e^{−i\\Omega_zt} (A_+ e^{i\\omega_0 t} + A_- e^{−i\\omega_0 t} )",
          "Initial conditions: as printed eta = (A_+ + A_-) e^{i(omega_0 - Omega_z) t}, one constant; eta(0) = 1, eta'(0) = 0 needs A_+ + A_- = 1 and i(omega_0 - Omega_z)(A_+ + A_-) = 0, impossible. With e^{-i omega_0 t} in the second term: A_+ + A_- = 1 and (omega_0 - Omega_z) A_+ = (omega_0 + Omega_z) A_-, which has a solution.",
          "The next display: A e^{-i Omega_z t} cos(omega_0 t + delta) = e^{-i Omega_z t}((A/2) e^{i delta} e^{i omega_0 t} + (A/2) e^{-i delta} e^{-i omega_0 t}): it needs the term in e^{-i omega_0 t}, which the printed form lacks; and from eta = A e^{-i alpha t} with alpha = Omega_z - omega_0 and Omega_z + omega_0 the exponents are -i Omega_z t + i omega_0 t and -i Omega_z t - i omega_0 t."),
    228: ("holds", "with A_+ = (A/2) e^{i delta}, A_- = (A/2) e^{-i delta} the two modes sum to A e^{-i Omega_z t} cos(omega_0 t + delta), which solves (12.88) up to a term Omega_z^2 eta, of the order the approximation alpha ~ Omega_z +- omega_0 drops (check 228)"),
    236: ("holds", "the vertical component of the Earth's rotation, with cos theta = sin lambda (check 236)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
