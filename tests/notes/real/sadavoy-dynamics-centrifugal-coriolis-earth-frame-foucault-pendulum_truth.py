"""Independent SymPy truth table for sadavoy-dynamics-centrifugal-coriolis-earth-frame-foucault-pendulum.md
(Sadavoy, Second-Year Dynamics, ch. 5, sections 5.1 to 5.5, MyST edition by Quadrivium Press).

The text's convention: an inertial frame (unprimed) and a frame S' (primed) whose unit vectors i', j', k'
turn with angular velocity omega (alpha its rate) and whose origin moves with velocity u and acceleration
A. Here the primed unit vectors are the columns of a rotation matrix Q(t) (Q = Rz(a) Ry(b) Rz(c), three
arbitrary functions of t), the origin is at an arbitrary point R0(t), and a point has primed coordinates
x', y', z' (arbitrary functions of t): r = R0 + r', r' = Q (x', y', z'), v' = Q (x', y', z')' and
a' = Q (x', y', z')'' (the rates seen in S'), omega the vector of the skew matrix Q' Q^T, u = R0', A = R0''.
Cross products written in primed components are ordinary cross products (Q is a proper rotation).
On the Earth (5.4, 5.5): latitude theta from the equator, colatitude varphi = 90 deg - theta, East i',
North j', up k' at the observer, the Earth turning at the constant rate omega about the inertial z axis;
the observer's frame is built here from its latitude and a longitude advancing as omega t.
The cats (Sample Problems 5-1, 5-2): a table turning at constant omega about k = k', a cat at rest at
radius R, or walking outward along i' at constant v'. Foucault's pendulum: pivot at height l above the
origin, bob at (x', y', z'), the text's model m a' = T + m g + F_Cor with the centrifugal term dropped and
the velocity taken horizontal. Nothing of the text's displays is assumed; each is derived here.
Run as a program it compares its verdicts with the table; ``--write`` writes the table.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Ry, Rz, numeric_zero, zero

t = sp.Symbol('t', real=True)
a_, b_, c_ = [sp.Function(n)(t) for n in ('a', 'b', 'c')]
xp, yp, zp = [sp.Function(n)(t) for n in ('xp', 'yp', 'zp')]
R1, R2, R3 = [sp.Function(n)(t) for n in ('R1', 'R2', 'R3')]
m, g, mu, R, w, l, T = sp.symbols('m g mu R omega ell T', positive=True)
D = lambda e: sp.diff(e, t)  # noqa: E731

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


def vee(S):
    return sp.Matrix([S[2, 1], S[0, 2], S[1, 0]])


def det3(row2, row3):
    """The determinant |i j k; row2; row3| expanded along its first row, as components."""
    return sp.Matrix([row2[1] * row3[2] - row2[2] * row3[1],
                      -(row2[0] * row3[2] - row2[2] * row3[0]),
                      row2[0] * row3[1] - row2[1] * row3[0]])


def norm(v):
    return sp.sqrt(sum(x**2 for x in v))


# ---- 5.1: the general moving, turning frame
Q = Rz(a_) * Ry(b_) * Rz(c_)
Xp = sp.Matrix([xp, yp, zp])
R0 = sp.Matrix([R1, R2, R3])
rp = Q * Xp
r = R0 + rp
v, acc = D(r), D(D(r))
vp, ap = Q * D(Xp), Q * D(D(Xp))
W = vee(sp.simplify(D(Q) * Q.T))
alpha, u, A = D(W), D(R0), D(D(R0))
assert numeric_zero(D(Q) - sp.Matrix.hstack(*[W.cross(Q[:, i]) for i in range(3)]), t)

# line 23: (5.1)
check(23, numeric_zero(ap - (acc - alpha.cross(rp) - 2 * W.cross(vp) - W.cross(W.cross(rp)) - A), t))
# line 31: (5.2), a frame that does not turn: Q constant
a0, b0, c0 = sp.symbols('a_0 b_0 c_0', real=True)
Q0 = Rz(a0) * Ry(b0) * Rz(c0)
check(31, zero(Q0 * D(D(Xp)) - (D(D(R0 + Q0 * Xp)) - A)))
# line 39: (5.3)
check(39, numeric_zero(vp - (v - W.cross(rp) - u), t))
# line 49: (5.4), m times (5.1); the underbraces name its four terms
check(49, numeric_zero(m * ap - (m * acc - m * alpha.cross(rp) - 2 * m * W.cross(vp)
                                 - m * W.cross(W.cross(rp)) - m * A), t))

# ---- 5.2: omega = omega k', r' = r i' (primed components)
rr, vv = sp.symbols('r vprime', positive=True)
Wk = sp.Matrix([0, 0, w])
inner = det3(Wk, sp.Matrix([rr, 0, 0]))
check(80, zero(inner - Wk.cross(sp.Matrix([rr, 0, 0])))
      and zero(inner - sp.Matrix([0 - 0, rr * w - 0, 0 - 0])) and zero(inner - sp.Matrix([0, rr * w, 0])))
outer = det3(Wk, inner)
check(96, zero(outer - Wk.cross(Wk.cross(sp.Matrix([rr, 0, 0]))))
      and zero(outer - sp.Matrix([0 - rr * w**2, 0, 0])) and zero(outer - sp.Matrix([-rr * w**2, 0, 0])))

# Sample Problem 5-1: the cat at rest at radius R on a table turning at constant omega about k
Qc = Rz(w * t)
cat = Qc * sp.Matrix([R, 0, 0])               # inertial position; r' = cat (common origin)
acc_cat = D(D(cat))
rhat = cat / R
check(121, zero(acc_cat - (-w**2 * R * rhat)))
# line 128: friction at its limit mu N, inward; N = m g from the vertical balance N - m g = m * 0
N = sp.solve(sp.Symbol('N') - m * g, sp.Symbol('N'))[0]
f_lim = -mu * N * rhat
check(128, zero(f_lim - (-mu * m * g * rhat)))
# line 140: friction the only horizontal force: f = m a
check(140, zero(m * acc_cat - (-m * w**2 * R * rhat)))
# line 146: at the limit the friction f_lim is the m a of line 140: the display is f_lim = m a
check(146, zero((f_lim - m * acc_cat) - ((-mu * m * g * rhat) - (-m * w**2 * R * rhat))))
# lines 152, 174: the rate that solves it (and the cat-frame balance -mu m g + m R omega^2 = 0)
sol = sp.solve(sp.Eq(mu * m * g, m * w**2 * R), w)
check(152, sol == [sp.sqrt(mu * g / R)])
Wc = vee(sp.simplify(D(Qc) * Qc.T))
rp_c = cat
vp_c = Qc * D(sp.Matrix([R, 0, 0]))
ap_c = Qc * D(D(sp.Matrix([R, 0, 0])))
F_I = m * acc_cat
F_cent = -m * Wc.cross(Wc.cross(rp_c))
check(160, zero(m * ap_c - (F_I + F_cent)) and zero(Wc.cross(vp_c)) and zero(D(Wc)))
check(167, zero(ap_c) and zero(F_I + F_cent))
sol2 = sp.solve(sp.Eq(-mu * m * g + m * R * w**2, 0), w)
check(174, sol2 == [sp.sqrt(mu * g / R)])

# ---- 5.3: omega = omega k', v' = v' i'
cor = det3(Wk, sp.Matrix([vv, 0, 0]))
check(194, zero(cor - Wk.cross(sp.Matrix([vv, 0, 0])))
      and zero(cor - sp.Matrix([0 - 0, vv * w - 0, 0 - 0])) and zero(cor - sp.Matrix([0, vv * w, 0])))

# Sample Problem 5-2: the cat walks outward along i' at constant v'
x0 = sp.Symbol('x_0', positive=True)
Xc = sp.Matrix([x0 + vv * t, 0, 0])
xc = Xc[0]
cat2 = Qc * Xc
acc2 = D(D(cat2))
vp2, ap2 = Qc * D(Xc), Qc * D(D(Xc))
F_I2 = m * acc2
F_cor2 = -2 * m * Wc.cross(vp2)
F_cent2 = -m * Wc.cross(Wc.cross(cat2))
ip, jp = Qc[:, 0], Qc[:, 1]
check(224, zero(ap2) and zero(F_I2 + F_cent2 + F_cor2) and zero(D(Wc)))
check(245, zero(ap2) and zero(F_I2 + F_cent2 + F_cor2))
kp_ = sp.Matrix([0, 0, 1])
check(232, zero(Qc.T * F_cor2 - sp.Matrix([0, -2 * m * vv * w, 0]))
      and zero(-2 * m * (w * kp_).cross(vv * sp.Matrix([1, 0, 0])) - sp.Matrix([0, -2 * m * vv * w, 0])))
check(239, zero(Qc.T * F_cent2 - sp.Matrix([m * w**2 * xc, 0, 0]))
      and zero(-m * (w * kp_).cross((w * kp_).cross(xc * sp.Matrix([1, 0, 0]))) - sp.Matrix([m * w**2 * xc, 0, 0])))
check(249, zero(F_I2 + m * w**2 * xc * ip - 2 * m * vv * w * jp))
check(253, zero(F_I2 - (2 * m * vv * w * jp - m * w**2 * xc * ip)))
# line 266: |F_I| written out with line 253 (mu m g = |F_I| is the slipping condition)
check(266, zero(sp.simplify(norm(F_I2) - norm(2 * m * vv * w * jp - m * w**2 * xc * ip))))
check(270, zero(sp.simplify(norm(2 * m * vv * w * jp - m * w**2 * xc * ip)
                            - sp.sqrt((2 * m * vv * w)**2 + (m * w**2 * xc)**2))))
X = sp.Symbol('x', positive=True)
check(274, zero(sp.expand((mu * m * g)**2 - ((2 * m * vv * w)**2 + (m * w**2 * X)**2))
                - m**2 * (mu**2 * g**2 - (4 * vv**2 * w**2 + w**4 * X**2))))
solx = sp.solve(sp.Eq(mu**2 * g**2, 4 * vv**2 * w**2 + w**4 * X**2), X)
check(278, len(solx) == 1 and zero(solx[0]**2 - (mu**2 * g**2 - 4 * vv**2 * w**2) / w**4)
      and zero(solx[0] - sp.sqrt(mu**2 * g**2 - 4 * vv**2 * w**2) / w**2))

# ---- 5.4: the observer's frame on the turning Earth, latitude th, longitude lam0 + omega t
th, lam0 = sp.symbols('theta lambda_0', real=True)
lam = lam0 + w * t
east = sp.Matrix([-sp.sin(lam), sp.cos(lam), 0])
north = sp.Matrix([-sp.sin(th) * sp.cos(lam), -sp.sin(th) * sp.sin(lam), sp.cos(th)])
up = sp.Matrix([sp.cos(th) * sp.cos(lam), sp.cos(th) * sp.sin(lam), sp.sin(th)])
QE = sp.Matrix.hstack(east, north, up)
assert zero(QE.T * QE - sp.eye(3)) and zero(east.cross(north) - up)
WE = vee(sp.simplify(D(QE) * QE.T))
assert zero(WE - sp.Matrix([0, 0, w]))
check(299, zero(WE - (w * sp.cos(th) * north + w * sp.sin(th) * up)))
check(306, CHECKS[23])
# line 315: constant omega (alpha = 0), a non-accelerating origin (A = 0), a' = 0: a point moving
# uniformly in the turning frame
Qw = Rz(w * t) * Ry(b0) * Rz(c0)
Ww = vee(sp.simplify(D(Qw) * Qw.T))
X0 = sp.Matrix(sp.symbols('X_1:4', real=True))
V0 = sp.Matrix(sp.symbols('V_1:4', real=True))
Xu = X0 + V0 * t
ru = Qw * Xu
check(315, zero(D(Ww)) and zero(Qw * D(D(Xu)))
      and zero(D(D(ru)) - 2 * Ww.cross(Qw * D(Xu)) - Ww.cross(Ww.cross(ru))))
# primed components at the observer: omega' = (0, w cos th, w sin th), r' = R k'
Wp = sp.Matrix([0, w * sp.cos(th), w * sp.sin(th)])
assert zero(QE.T * WE - Wp)
rk = sp.Matrix([0, 0, R])
Fcen = -m * Wp.cross(Wp.cross(rk))
# line 323: |F_cen| = m w^2 R sin(varphi) = m w^2 R cos(theta), varphi the angle from omega to r';
# for latitudes strictly between the poles, sampled (50 digits)
cosphi = Wp.dot(rk) / (norm(Wp) * norm(rk))
ok323 = True
for thv in (sp.Rational(-7, 5), sp.Rational(-1, 3), 0, sp.Rational(1, 2), sp.Rational(6, 5)):
    s = {th: thv, m: 2, w: 3, R: 5}
    sinphi = sp.sqrt(1 - cosphi.subs(s)**2)
    lhs = norm(Fcen.subs(s))
    ok323 &= (abs(sp.N(lhs - (m * w**2 * R).subs(s) * sinphi, 50)) < 1e-40
              and abs(sp.N(lhs - (m * w**2 * R * sp.cos(th)).subs(s), 50)) < 1e-40)
check(323, ok323)
inner_E = det3(Wp, rk)
check(337, zero(inner_E - Wp.cross(rk)) and zero(inner_E - sp.Matrix([R * w * sp.cos(th), 0, 0])))
outer_E = det3(Wp, inner_E)
check(347, zero(outer_E - Wp.cross(Wp.cross(rk)))
      and zero(outer_E - sp.Matrix([0, w**2 * R * sp.cos(th) * sp.sin(th), -w**2 * R * sp.cos(th)**2])))
check(362, zero(Fcen - sp.Matrix([0, -m * w**2 * R * sp.cos(th) * sp.sin(th), m * w**2 * R * sp.cos(th)**2])))
# line 369: the chain holds (cos(theta) >= 0 between the poles), but the brace marks cos^2(theta) alone as 1
c_ = sp.Symbol('c', positive=True)            # cos(theta) between the poles
s_ = sp.Symbol('s', real=True)
pyth = {s_**2: 1 - c_**2}
line1 = sp.sqrt((-m * w**2 * R * c_ * s_)**2 + (m * w**2 * R * c_**2)**2)
line2 = m * w**2 * R * c_ * sp.sqrt(s_**2 + c_**2)
line3 = m * w**2 * R * c_
chain = zero(sp.simplify((line1**2 - line2**2))) and zero(sp.simplify(line2.subs(s_, sp.sqrt(1 - c_**2)) - line3))
brace = zero(sp.cos(th)**2 - 1)
check(369, chain and brace)
FIX_369 = chain and zero(sp.sin(th)**2 + sp.cos(th)**2 - 1)

# ---- 5.5: Foucault's pendulum
dl, be = sp.symbols('delta beta', real=True)
bob = sp.Matrix([l * sp.sin(dl) * sp.cos(be), l * sp.sin(dl) * sp.sin(be), l - l * sp.cos(dl)])
pivot = sp.Matrix([0, 0, l])
Tvec = T * (pivot - bob) / l                  # tension T along the string, toward the pivot
xb, yb, zb = bob
disp409 = sp.Matrix([-T * xb / l, -T * yb / l, T * (l - zb) / l])
check(409, zero(disp409 - Tvec) and zero(sp.simplify(norm(Tvec) - T)))
xd, yd, xdd, ydd = sp.symbols('xdot ydot xddot yddot', real=True)
vh = sp.Matrix([xd, yd, 0])
cor_E = det3(Wp, vh)
check(421, zero(cor_E - Wp.cross(vh))
      and zero(cor_E - sp.Matrix([-yd * w * sp.sin(th), xd * w * sp.sin(th), -xd * w * sp.cos(th)])))
FcorE = -2 * m * Wp.cross(vh)
check(437, zero(FcorE[0] - 2 * m * yd * w * sp.sin(th)))
check(441, zero(FcorE[1] - (-2 * m * xd * w * sp.sin(th))))
# the model m a' = T + m g (down) + F_Cor, horizontal components, bob at (x', y', z')
xs, ys, zs = sp.symbols('x y z', real=True)
Tgen = sp.Matrix([-T * xs / l, -T * ys / l, T * (l - zs) / l])
force = Tgen + sp.Matrix([0, 0, -m * g]) + FcorE
check(450, zero(force[0] - (-T * xs / l + 2 * m * w * sp.sin(th) * yd))
      and zero(force[1] - (-T * ys / l - 2 * m * w * sp.sin(th) * xd)))
forceg = force.subs(T, m * g) / m
check(459, zero(forceg[0] - (-g / l * xs + 2 * w * sp.sin(th) * yd))
      and zero(forceg[1] - (-g / l * ys - 2 * w * sp.sin(th) * xd)))
# line 471: with eta = x' + i y', the equations are eta'' = -(g/l) eta - 2 i Omega eta', Omega = w sin(theta);
# eta = e^{-i Omega t} xi with xi'' = -(g/l + Omega^2) xi solves them: a straight swing (xi real) whose
# line turns at the rate Omega, once round in 2 pi / Omega; and 2 pi / omega is the day, 24 h
Om = w * sp.sin(th)
w0 = sp.sqrt(g / l + Om**2)
A1, B1 = sp.symbols('A_1 B_1', real=True)
xi = A1 * sp.cos(w0 * t) + B1 * sp.sin(w0 * t)
eta = sp.exp(-sp.I * Om * t) * xi
ode = D(D(eta)) + g / l * eta + 2 * sp.I * Om * D(eta)
xe, ye = sp.re(sp.expand_complex(eta)), sp.im(sp.expand_complex(eta))
ode_xy = sp.Matrix([D(D(xe)) - (-g / l * xe + 2 * Om * D(ye)), D(D(ye)) - (-g / l * ye - 2 * Om * D(xe))])
hours = sp.Symbol('h', positive=True)
day = {w: 2 * sp.pi / (24 * hours)}
check(471, zero(sp.simplify(ode)) and numeric_zero(ode_xy.subs({th: sp.Rational(7, 10)}), t)
      and zero((2 * sp.pi / (w * sp.sin(th)) - 24 * hours / sp.sin(th)).subs(day)))

# negative controls: a corrected brace holds, and a wrong sign is caught
assert FIX_369
assert not zero(FcorE[0] - (-2 * m * yd * w * sp.sin(th)))
assert not numeric_zero(vp - (v + W.cross(rp) - u), t)

LINES = [23, 31, 39, 49, 66, 80, 96, 121, 128, 134, 140, 146, 152, 160, 167, 174, 186, 194, 218, 224, 232,
         239, 245, 249, 253, 262, 266, 270, 274, 278, 299, 306, 315, 323, 330, 337, 347, 362, 369, 383, 397,
         409, 421, 437, 441, 450, 459, 471]

ROWS = {
    23: ("holds", "r = R0 + Q x' differentiated twice: a = A + a' + alpha x r' + 2 omega x v' + omega x (omega x r'), so a' = a - alpha x r' - 2 omega x v' - omega x (omega x r') - A (check 23)"),
    31: ("holds", "with Q constant (no turning) r = R0 + Q x' gives a = A + a', so a' = a - A (check 31)"),
    39: ("holds", "r = R0 + Q x' differentiated once: v = u + v' + omega x r', so v' = v - omega x r' - u (check 39)"),
    49: ("holds", "m times (5.1); the four underbraces name its terms F_az, F_Cor, F_cent, F_trans (check 49)"),
    66: ("not a claim", "the centrifugal force, named in (5.4), stated as the definition the section works with"),
    80: ("holds", "omega = omega k', r' = r i': the determinant expanded along its first row is i'(0 - 0) + j'(r omega - 0) + k'(0 - 0) = r omega j' (check 80)"),
    96: ("holds", "omega k' x (r omega j') = -r omega^2 i', the determinant expanded as printed (check 96)"),
    121: ("holds", "the cat at radius R on a table turning at constant omega: position R(cos omega t, sin omega t, 0), acceleration -omega^2 R r-hat (check 121)"),
    128: ("holds", "friction at its limit mu N, pointing inward, with N = m g from the vertical balance (no vertical motion) (check 128)"),
    134: ("not a claim", "Newton's second law, the law the solution starts from"),
    140: ("holds", "friction the only horizontal force: f = m a = -m omega^2 R r-hat (check 140)"),
    146: ("holds", "at the limit the friction -mu m g r-hat is the m a of the previous display: the display is f_lim = m a (check 146)"),
    152: ("holds", "solving mu m g = m omega^2 R for omega > 0 gives sqrt(mu g / R) (check 152)"),
    160: ("holds", "in the cat's frame (a point at rest in a frame turning steadily about k) the azimuthal, Coriolis and translational terms vanish: m a' = m a + F_cent, m a the real force F_I (check 160)"),
    167: ("holds", "the cat at rest in its frame: a' = 0, and F_I = -m omega^2 R r-hat balances F_cent = m omega^2 R r-hat (check 167)"),
    174: ("holds", "-mu m g + m R omega^2 = 0 solved for omega > 0: sqrt(mu g / R) (check 174)"),
    186: ("not a claim", "the Coriolis force, named in (5.4), stated as the definition the section works with"),
    194: ("holds", "omega k' x v' i' = v' omega j', the determinant expanded as printed (check 194)"),
    218: ("not a claim", "introduces F_fic as the sum of the apparent forces in (5.4)"),
    224: ("holds", "the cat walking outward at constant v' on a table turning steadily: a' = 0, alpha = 0, A = 0, so 0 = m a - 2 m omega x v' - m omega x (omega x r') with m a = F_I (check 224)"),
    232: ("holds", "-2 m omega k' x v' i' = -2 m v' omega j', also in the cat's actual turning frame (check 232)"),
    239: ("holds", "-m omega k' x (omega k' x x' i') = m omega^2 x' i' (check 239)"),
    245: ("holds", "the balance of line 224 restated (check 245)"),
    249: ("holds", "F_I + m omega^2 x' i' - 2 m v' omega j' = 0 with F_I = m a of the walking cat (check 249)"),
    253: ("holds", "F_I = m a = 2 m v' omega j' - m omega^2 x' i' for the walking cat (check 253)"),
    262: ("not a claim", "the slipping condition: the needed force reaches the limit of static friction"),
    266: ("holds", "the condition with F_I written out from the previous display: |F_I| = |2 m v' omega j' - m omega^2 x' i'| (check 266)"),
    270: ("holds", "i' and j' orthonormal: the magnitude is sqrt((2 m v' omega)^2 + (m omega^2 x')^2) (check 270)"),
    274: ("holds", "squaring and dividing by m^2: mu^2 g^2 = 4 v'^2 omega^2 + omega^4 x'^2 (check 274)"),
    278: ("holds", "solved for x' > 0: x'^2 = (mu^2 g^2 - 4 v'^2 omega^2)/omega^4 and x' its positive root (check 278)"),
    299: ("holds", "with East i', North j', up k' at latitude theta, the Earth's omega along the axis is omega cos(theta) j' + omega sin(theta) k'; derived here as the vector of the observer's turning frame (check 299)"),
    306: ("holds", "(5.1) restated (check 306)"),
    315: ("holds", "(5.1) with alpha = 0, A = 0 (the text's assumptions) and a' = 0: a point moving uniformly in a steadily turning frame with a fixed origin satisfies 0 = a - 2 omega x v' - omega x (omega x r') (check 315)"),
    323: ("holds", "with r' = R k' and omega of (5.9), |m omega x (omega x r')| = m omega^2 R sin(varphi), varphi the angle from omega to r' (the colatitude), and sin(varphi) = cos(theta); sampled at five latitudes between the poles (check 323)"),
    330: ("not a claim", "a bare expression: the first cross product the text points to"),
    337: ("holds", "(0, omega cos theta, omega sin theta) x (0, 0, R) = R omega cos(theta) i', the determinant as printed (check 337)"),
    347: ("holds", "omega x (R omega cos(theta) i') = omega^2 R cos(theta) sin(theta) j' - omega^2 R cos^2(theta) k' (check 347)"),
    362: ("holds", "F_cen = -m times the previous display: -m omega^2 R cos sin j' + m omega^2 R cos^2 k' (check 362)"),
    369: ("typo", "the chain of values holds (sqrt(c^2 s^2 + c^4) = c sqrt(s^2 + c^2) = c for cos(theta) >= 0), but the underbrace labels cos^2(theta) alone as equal to 1; it is the sum sin^2(theta) + cos^2(theta) that is 1 (check 369)",
          "|\\vec{F}_{cen}| =\\sqrt{(-m\\omega^2R\\cos\\theta\\sin\\theta)^2+(m\\omega^2R\\cos^2\\theta)^2} =m\\omega^2R\\cos\\theta\\sqrt{\\underbrace{\\sin^2\\theta+\\cos^2\\theta}_{=1}} = m\\omega ^{2}R\\cos \\theta",
          "theta = 60 deg: cos^2(theta) = 1/4, not 1, while sin^2(theta) + cos^2(theta) = 3/4 + 1/4 = 1; at the pole, theta = 90 deg, cos^2(theta) = 0. The brace's statement fails everywhere except on the equator.",
          "The chain itself at theta = 60 deg with m omega^2 R = 1: the first line is sqrt((sqrt(3)/4)^2 + (1/4)^2) = 1/2 and the last is cos 60 deg = 1/2, equal only because the whole root sqrt(3/4 + 1/4) is 1; taking cos^2(theta) = 1 as the brace says would make the root sqrt(3/4 + 1) = sqrt(7)/2 and the line (1/2)(sqrt(7)/2), not 1/2."),
    383: ("not a claim", "the model kept on the Earth's surface: the centrifugal term dropped as under one percent of g, an approximation, not an identity"),
    397: ("not a claim", "the same approximation taken for the pendulum: azimuthal and centrifugal terms dropped"),
    409: ("holds", "the bob at (x', y', z') = (l sin(delta) cos(beta), l sin(delta) sin(beta), l - l cos(delta)) below the pivot at height l: T along the string toward the pivot is T (pivot - bob)/l = (-T x'/l, -T y'/l, T(l - z')/l), of size T (check 409)"),
    421: ("holds", "(0, omega cos theta, omega sin theta) x (x'dot, y'dot, 0) = (-y'dot omega sin theta, x'dot omega sin theta, -x'dot omega cos theta) (check 421)"),
    437: ("holds", "the x' component of -2 m omega x v' is 2 m y'dot omega sin(theta) (check 437)"),
    441: ("holds", "the y' component of -2 m omega x v' is -2 m x'dot omega sin(theta) (check 441)"),
    450: ("holds", "the horizontal components of m a' = T + m g + F_Cor with the tension of line 409 and the Coriolis force of lines 437, 441 (the text's model: centrifugal dropped, velocity horizontal) (check 450)"),
    459: ("holds", "the previous pair with T = m g, divided by m (the small-swing approximation stated) (check 459)"),
    471: ("holds", "with eta = x' + i y' the pair is eta'' = -(g/l) eta - 2 i Omega eta', Omega = omega sin(theta); eta = e^{-i Omega t} xi with xi'' = -(g/l + Omega^2) xi solves it exactly, a swing whose line turns at Omega, once round in 2 pi/(omega sin theta); and 2 pi/omega = 24 h for the day (check 471)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
