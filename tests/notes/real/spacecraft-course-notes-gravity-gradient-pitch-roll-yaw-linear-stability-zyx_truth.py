"""Independent SymPy truth table for spacecraft-course-notes-gravity-gradient-pitch-roll-yaw-linear-stability-zyx.ipynb.

The notebook's setting (Schaub's notation): a rigid satellite on a circular orbit of radius R_c and
rate Omega (Omega^2 = G M_e / R_c^3); the orbit frame O has o_1 along the track, o_2 across it (the
orbit normal, about which O turns at Omega relative to the inertial frame N) and o_3 along the
radius; the body frame B is principal, [I] = diag(I_11, I_22, I_33). B is placed relative to O by
3-2-1 (z-y-x) Euler angles: yaw psi about o_3, pitch theta about the new 2-axis, roll phi about the
final 1-axis, so that the body axes in orbit components are the columns of Rz(psi) Ry(theta) Rx(phi)
and [BO] (orbit components -> body components) is its transpose. Every quantity below is built
here from these definitions, not from the displays:

* omega_{B/O} in body components from the skew matrix -[BO]' [BO]^T; omega_{B/N} = omega_{B/O} +
  [BO] (0, Omega, 0);
* the gravity-gradient torque from the first-order expansion of the attraction on point masses
  (Sum m r = 0), giving 3 mu / R_c^5 R_c x [I] R_c, with R_c = [BO] (0, 0, R_c) in body components;
* Euler's equation I omega' + omega x I omega = L_G in body components (the transport theorem);
* "first order": the angles and their rates scaled by eps, the Taylor part of order <= 1 in eps.

A display's line is the notebook file's line of its first row. Run as a program it compares its
verdicts with the table; ``--write`` writes the table.
"""
import pathlib
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Ry, Rz, zero

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


t = sp.symbols('t', real=True)
eps = sp.symbols('epsilon', positive=True)
Om, I11, I22, I33, Rc, mu = sp.symbols('Omega I_11 I_22 I_33 R_c mu', positive=True)
phi, th, psi = (sp.Function(n)(t) for n in ('phi', 'theta', 'psi'))
ANG = (phi, th, psi)
d, dd = (lambda f: f.diff(t)), (lambda f: f.diff(t, 2))
s, c = sp.sin, sp.cos
I = sp.diag(I11, I22, I33)


def tilde(v):
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def vee(m):
    return sp.Matrix([m[2, 1], m[0, 2], m[1, 0]])


def scaled(expr):
    """The angles (and so their rates) made small: each angle -> eps * angle."""
    return expr.subs({a: eps * a for a in ANG}).doit()


def first(expr):
    """The part of order 0 and 1 in the small angles and rates."""
    e = scaled(expr)
    return e.subs(eps, 0) + eps * sp.diff(e, eps).subs(eps, 0)


def same_first(a, b):
    """a and b agree to first order in the small angles and rates."""
    return zero(sp.expand(first(a) - first(b)))


# --- kinematics of the 3-2-1 angles, B relative to O --------------------------------------------
BO = (Rz(psi) * Ry(th) * Rx(phi)).T              # orbit components -> body components
w_BO = vee(-BO.diff(t) * BO.T)                    # omega_{B/O}, body components
w_ON = BO * sp.Matrix([0, Om, 0])                 # omega_{O/N} = Omega o_2, body components
w = w_BO + w_ON                                   # omega_{B/N}, body components
wdot = w.diff(t)                                  # its rate: inertial = body rate (omega x omega = 0)
assert truth_table.numeric_zero(w - sp.Matrix([d(phi) - s(th) * d(psi) + Om * c(th) * s(psi),
                                                s(phi) * c(th) * d(psi) + c(phi) * d(th) + Om * (s(phi) * s(th) * s(psi) + c(phi) * c(psi)),
                                                c(phi) * c(th) * d(psi) - s(phi) * d(th) + Om * (c(phi) * s(th) * s(psi) - s(phi) * c(psi))]), t)

# --- the gravity-gradient torque, from point masses -----------------------------------------------
# one mass m at r (from the centre of mass) of a body at R from the Earth's centre: the torque of
# the attraction, r x (-mu m (R + r) / |R + r|^3), expanded in the size eps of the body
X, Y, Z, x, y, z, m = sp.symbols('X Y Z x y z m', real=True)
Rv, rv = sp.Matrix([X, Y, Z]), sp.Matrix([x, y, z])
Rn = sp.sqrt(X**2 + Y**2 + Z**2)
force = -mu * m * (Rv + eps * rv) / ((Rv + eps * rv).dot(Rv + eps * rv)) ** sp.Rational(3, 2)
torque_one = (eps * rv).cross(force)
order1 = sp.diff(torque_one, eps).subs(eps, 0)
order2 = (sp.diff(torque_one, eps, 2) / 2).subs(eps, 0)
I_one = m * (rv.dot(rv) * sp.eye(3) - rv * rv.T)  # the mass's share of [I] about the centre of mass
# order 1 is -mu m r x R / R^3, linear in r: it sums to zero over the body since Sum m r = 0;
# order 2, summed over the masses, is 3 mu / R^5 R x [I] R (each mass's share matches)
GG_OK = (zero(sp.simplify(order1 + mu * m * rv.cross(Rv) / Rn**3))
         and zero(sp.simplify(order2 - 3 * mu / Rn**5 * Rv.cross(I_one * Rv))))
Rc_B = BO * sp.Matrix([0, 0, Rc])                 # R_c in body components
LG = 3 * mu / Rc**5 * Rc_B.cross(I * Rc_B)
LG_orbit = LG.subs(mu, Om**2 * Rc**3)             # circular orbit: mu / R_c^3 = Omega^2

# --- Euler's equation in body components: its residual on the motion -------------------------------
euler = I * wdot + w.cross(I * w) - LG_orbit      # = 0 is the equation of motion
assert zero(first(euler).subs(eps, 0))            # the relative equilibrium is one


def equivalent_first(residual, rows=(0, 1, 2), scale=(1, 1, 1)):
    """The display's equations (residual = 0) are Euler's equations, row by row, to first order:
    each row equal to Euler's row times the given factor."""
    return all(zero(sp.expand(first(residual[k]) - scale[k] * first(euler[r])))
               for k, r in enumerate(rows))


# line 50: sin(theta) psidot ~ 0: the rule of the linearization (a product of small quantities)
# line 56: omega_{B/N} = (phidot + Omega sin psi, thetadot + Omega, psidot - Omega sin phi), to first order
w56 = sp.Matrix([d(phi) + Om * s(psi), d(th) + Om, d(psi) - Om * s(phi)])
check(56, same_first(w, w56))
# line 83: [I] omega' = -[omega~][I] omega + L_c: Euler's equation, dH/dt = L with H = [I] omega in body
# components (transport theorem: the inertial rate is [I] omega' + omega x [I] omega)
a1, a2, a3, b1, b2, b3 = sp.symbols('a1:4 b1:4', real=True)
va, vb = sp.Matrix([a1, a2, a3]), sp.Matrix([b1, b2, b3])
TILDE_OK = zero(tilde(va) * vb - va.cross(vb))
check(83, TILDE_OK)
# line 89: (dr/dt)^N = (dr/dt)^B + omega_{B/N} x r, for a vector with body components r_B(t):
# its inertial components are [BN]^T r_B; here B turns relative to N through the 3-2-1 angles and
# the orbit rate, [BN] = [BO][ON] with [ON] the turn by Omega t about o_2
r1, r2, r3 = (sp.Function(n)(t) for n in ('r1', 'r2', 'r3'))
rB = sp.Matrix([r1, r2, r3])
ON = Ry(Om * t).T
BN = BO * ON
inertial_rate_in_B = BN * (BN.T * rB).diff(t)
check(89, truth_table.numeric_zero(inertial_rate_in_B - (rB.diff(t) + w.cross(rB)), t))
# line 95: the same with the vector omega: omega_dot^N = (d omega/dt)^B + omega x omega
inertial_w_rate = BN * (BN.T * w).diff(t)
check(95, truth_table.numeric_zero(inertial_w_rate - (w.diff(t) + w.cross(w)), t))
# line 101: omega x omega = 0, so the two rates agree
check(101, truth_table.numeric_zero(inertial_w_rate - w.diff(t), t))
# line 111: omega_dot ~ (phi'' + Omega psi', theta'', psi'' - Omega phi'), to first order
wd111 = sp.Matrix([dd(phi) + Om * d(psi), dd(th), dd(psi) - Om * d(phi)])
check(111, same_first(wdot, wd111))
# line 140: ^O R_c = (0, 0, R_c): the radial axis of the orbit frame (given)
# line 151: ^B R_c = [BO] ^O R_c: the frame change, by the definition of [BO] (not a claim)
# line 155: the display's [BO] is the 3-2-1 direction cosine matrix
BO155 = sp.Matrix([[c(th) * c(psi), c(th) * s(psi), -s(th)],
                   [s(phi) * s(th) * c(psi) - c(phi) * s(psi), s(phi) * s(th) * s(psi) + c(phi) * c(psi), s(phi) * c(th)],
                   [c(phi) * s(th) * c(psi) + s(phi) * s(psi), c(phi) * s(th) * s(psi) - s(phi) * c(psi), c(phi) * c(th)]])
check(155, zero(BO - BO155))
# line 169: ^B R_c = (-sin theta, sin phi cos theta, cos phi cos theta) R_c
check(169, zero(Rc_B - sp.Matrix([-s(th), s(phi) * c(th), c(phi) * c(th)]) * Rc))
# line 183: L_G = 3 G M_e / R_c^5 R_c x [I] R_c: the second-order attraction on the masses
check(183, GG_OK)
# line 187: its components with the principal [I]
Rc1, Rc2, Rc3 = sp.symbols('R_c1 R_c2 R_c3', real=True)
Rg = sp.Matrix([Rc1, Rc2, Rc3])
comp187 = 3 * mu / Rc**5 * sp.Matrix([Rc2 * Rc3 * (I33 - I22), Rc1 * Rc3 * (I11 - I33), Rc1 * Rc2 * (I22 - I11)])
check(187, GG_OK and zero(3 * mu / Rc**5 * Rg.cross(I * Rg) - comp187))
# line 204: G M_e / R_c^3 = Omega^2: the rate of the circular orbit (given)
# line 210: L_G = Omega^2 / R_c^2 (R_c2 R_c3 (I_33 - I_22), ...): with mu = Omega^2 R_c^3 the factor is
# 3 Omega^2 / R_c^2, not Omega^2 / R_c^2
disp210 = Om**2 / Rc**2 * sp.Matrix([Rc2 * Rc3 * (I33 - I22), Rc1 * Rc3 * (I11 - I33), Rc1 * Rc2 * (I22 - I11)])
check(210, zero(comp187.subs(mu, Om**2 * Rc**3) - disp210))
assert zero(comp187.subs(mu, Om**2 * Rc**3) - 3 * disp210)        # the intended form
# line 222: ^B L_G = 3/2 Omega^2 ((I_33 - I_22) cos^2 theta sin 2 phi, -(I_11 - I_33) cos phi sin 2 theta, ...)
L222 = sp.Rational(3, 2) * Om**2 * sp.Matrix([(I33 - I22) * c(th)**2 * s(2 * phi),
                                              -(I11 - I33) * c(phi) * s(2 * th),
                                              -(I22 - I11) * s(phi) * s(2 * th)])
check(222, zero(sp.expand_trig(LG_orbit - L222)))
# line 233: ^B L_G ~ 3 Omega^2 ((I_33 - I_22) phi, -(I_11 - I_33) theta, 0), to first order
L233 = 3 * Om**2 * sp.Matrix([(I33 - I22) * phi, -(I11 - I33) * th, 0])
check(233, same_first(LG_orbit, L233))
# line 261: [I] omega' = -[omega~][I] omega + L_G: Euler's equation with the gravity-gradient torque
check(261, TILDE_OK)
# line 267: omega_dot ~ ..., as line 111
check(267, same_first(wdot, wd111))
# line 278: omega_{B/N} ~ (phidot + Omega psi, thetadot + Omega, psidot - Omega phi), to first order
w278 = sp.Matrix([d(phi) + Om * psi, d(th) + Om, d(psi) - Om * phi])
check(278, same_first(w, w278))
# line 289: the skew matrix of the first-order omega_dot of line 267 (as the display writes it)
T289 = sp.Matrix([[0, -(dd(psi) - Om * d(phi)), dd(th)],
                  [dd(psi) - Om * d(phi), 0, -(dd(phi) + Om * d(psi))],
                  [-dd(th), dd(phi) + Om * d(psi), 0]])
check(289, zero(tilde(wd111) - T289))
# line 300: the first-order torque, as line 233
check(300, same_first(LG_orbit, L233))
# line 312: [I] omega_dot_lin = -[omega_lin~][I] omega_lin + L_lin: Euler's equation to first order
res312 = I * wd111 + tilde(w278) * I * w278 - L233
check(312, equivalent_first(res312))
# line 347: the rows multiplied out: the same equation, term by term
lhs347 = sp.Matrix([I11 * (dd(phi) + Om * d(psi)), I22 * dd(th), I33 * (dd(psi) - Om * d(phi))])
rhs347 = sp.Matrix([-(I33 - I22) * (d(th) + Om) * (d(psi) - Om * phi) + 3 * Om**2 * (I33 - I22) * phi,
                    -(I11 - I33) * (d(psi) - Om * phi) * (d(phi) + Om * psi) - 3 * Om**2 * (I11 - I33) * th,
                    -(I22 - I11) * (d(phi) + Om * psi) * (d(th) + Om)])
check(347, zero(sp.expand((lhs347 - rhs347) - res312)))
# line 366 (and 441): the first-order system
rhs366 = sp.Matrix([-(I33 - I22) * Om * d(psi) + 4 * Om**2 * (I33 - I22) * phi,
                    -3 * Om**2 * (I11 - I33) * th,
                    -(I22 - I11) * Om * d(phi) - Om**2 * (I22 - I11) * psi])
res366 = lhs347 - rhs366
check(366, equivalent_first(res366))
check(441, equivalent_first(res366))
# line 395: I_22 theta'' = -3 Omega^2 (I_11 - I_33) theta: the pitch row
check(395, equivalent_first(sp.Matrix([I22 * dd(th) + 3 * Om**2 * (I11 - I33) * th]), rows=(1,)))
# line 401: the same divided by I_22
pitch = sp.Matrix([dd(th) + 3 * Om**2 * ((I11 - I33) / I22) * th])
check(401, equivalent_first(pitch, rows=(1,), scale=(1 / I22,)))
# line 407: x'' + (k/m) x = 0, the mass on a spring (not a claim)
# line 413: k/m > 0 => 3 Omega^2 (I_11 - I_33) / I_22 >= 0: with k = 3 Omega^2 (I_11 - I_33) and
# m = I_22 as the comparison says, k/m is the coefficient of theta in line 401
k_over_m = 3 * Om**2 * (I11 - I33) / I22
check(413, zero(sp.expand(pitch[0] - dd(th) - k_over_m * th)))
# line 419: 3 Omega^2 (I_11 - I_33) / I_22 >= 0 <=> I_11 >= I_33,
# since the factor by which it differs from I_11 - I_33 is positive
check(419, bool((k_over_m / (I11 - I33)).simplify().is_positive))
# line 460: the roll row, I_11(phi'' + Omega psi') = -(I_33 - I_22) Omega psi' + 4 Omega^2 (I_33 - I_22) phi
roll = sp.Matrix([I11 * (dd(phi) + Om * d(psi)) - (-(I33 - I22) * Om * d(psi) + 4 * Om**2 * (I33 - I22) * phi)])
check(460, equivalent_first(roll, rows=(0,)))
# line 466: the right side regrouped with (I_22 - I_33)
check(466, zero(sp.expand((-(I33 - I22) * Om * d(psi) + 4 * Om**2 * (I33 - I22) * phi)
                          - (Om * d(psi) * (I22 - I33) - 4 * Om**2 * (I22 - I33) * phi))))
# line 472: divided by I_11
roll472 = sp.Matrix([dd(phi) + Om * d(psi) * (1 - (I22 - I33) / I11) + 4 * Om**2 * (I22 - I33) / I11 * phi])
check(472, equivalent_first(roll472, rows=(0,), scale=(1 / I11,)))
# line 478: k_Y = (I_22 - I_33)/I_11 (a definition); line 484: the roll equation with k_Y
kY, kR = (I22 - I33) / I11, (I22 - I11) / I33
roll484 = sp.Matrix([dd(phi) + Om * (1 - kY) * d(psi) + 4 * Om**2 * kY * phi])
check(484, equivalent_first(roll484, rows=(0,), scale=(1 / I11,)))
# line 492: the yaw row, I_33(psi'' - Omega phi') = -(I_22 - I_11) Omega phi' - Omega^2 (I_22 - I_11) psi
yaw = sp.Matrix([I33 * (dd(psi) - Om * d(phi)) - (-(I22 - I11) * Om * d(phi) - Om**2 * (I22 - I11) * psi)])
check(492, equivalent_first(yaw, rows=(2,)))
# line 498: the common factor taken out
check(498, zero(sp.expand((-(I22 - I11) * Om * d(phi) - Om**2 * (I22 - I11) * psi)
                          - (-(I22 - I11) * (Om * d(phi) + Om**2 * psi)))))
# line 504: divided by I_33
yaw504 = sp.Matrix([dd(psi) - Om * d(phi) + (I22 - I11) / I33 * (Om * d(phi) + Om**2 * psi)])
check(504, equivalent_first(yaw504, rows=(2,), scale=(1 / I33,)))
# line 510: k_R = (I_22 - I_11)/I_33 (a definition); line 516: with k_R put in
yaw516 = sp.Matrix([dd(psi) - Om * d(phi) - (-Om * kR * d(phi) - Om**2 * kR * psi)])
check(516, equivalent_first(yaw516, rows=(2,), scale=(1 / I33,)))
# line 522: psi'' + Omega (k_R - 1) phi' + Omega^2 k_R psi = 0
yaw522 = sp.Matrix([dd(psi) + Om * (kR - 1) * d(phi) + Om**2 * kR * psi])
check(522, equivalent_first(yaw522, rows=(2,), scale=(1 / I33,)))
# line 530: the coupled system (phi, psi)'' + A (phi, psi)' + B (phi, psi) = 0
A = sp.Matrix([[0, Om * (1 - kY)], [Om * (kR - 1), 0]])
B = sp.Matrix([[4 * Om**2 * kY, 0], [0, Om**2 * kR]])
q = sp.Matrix([phi, psi])
sys530 = q.diff(t, 2) + A * q.diff(t) + B * q
check(530, equivalent_first(sys530, rows=(0, 2), scale=(1 / I11, 1 / I33)))

LINES = [50, 56, 83, 89, 95, 101, 111, 140, 151, 155, 169, 183, 187, 204, 210, 222, 233, 261, 267, 278,
         289, 300, 312, 347, 366, 395, 401, 407, 413, 419, 441, 460, 466, 472, 478, 484, 492, 498, 504,
         510, 516, 522, 530]

ROWS = {
    50: ("not a claim", "the rule of the linearization: a product of two small quantities (sin theta psidot) is dropped"),
    56: ("holds", "to first order in the angles and rates the body components of omega_{B/N} = omega_{B/O} + [BO](0, Omega, 0) of the 3-2-1 angles are (phidot + Omega psi, thetadot + Omega, psidot - Omega phi), and Omega sin psi, -Omega sin phi agree with Omega psi, -Omega phi to that order (check 56)"),
    83: ("holds", "Euler's equation: the inertial rate of H = [I] omega in body components is [I] omega' + omega x [I] omega, and [omega~] v = omega x v (check 83)"),
    89: ("holds", "the transport theorem: for body components r_B, [BN] d/dt([BN]^T r_B) = r_B' + omega_{B/N} x r_B, checked with B turning through the 3-2-1 angles in the orbit frame turning at Omega (check 89)"),
    95: ("holds", "the transport theorem applied to omega itself (check 95)"),
    101: ("holds", "omega x omega = 0, so the inertial rate of omega equals its body rate (check 101)"),
    111: ("holds", "the rate of the first-order angular velocity (Omega constant): to first order omega' = (phi'' + Omega psi', theta'', psi'' - Omega phi') (check 111)"),
    140: ("not a claim", "the centre of mass lies on the radial axis o_3 of the orbit frame: given"),
    151: ("not a claim", "the change to body components by the matrix [BO], by its definition"),
    155: ("holds", "[BO] of the 3-2-1 angles, the transpose of Rz(psi) Ry(theta) Rx(phi), is the matrix written (check 155)"),
    169: ("holds", "[BO](0, 0, R_c) is R_c times the third column of [BO]: (-sin theta, sin phi cos theta, cos phi cos theta) R_c (check 169)"),
    183: ("holds", "the attraction on a mass m at r from the centre of mass, expanded in the size of the body: the first-order torque -mu m r x R/R^3 sums to zero (Sum m r = 0) and the second-order one sums to 3 mu/R^5 R x [I] R (check 183)"),
    187: ("holds", "R x diag(I_11, I_22, I_33) R = (R_2 R_3 (I_33 - I_22), R_1 R_3 (I_11 - I_33), R_1 R_2 (I_22 - I_11)) (check 187)"),
    204: ("not a claim", "the rate of the circular orbit, given"),
    210: ("typo", "with G M_e/R_c^3 = Omega^2 the factor 3 G M_e/R_c^5 of line 187 is 3 Omega^2/R_c^2; the display drops the 3, which the next display (3/2 Omega^2) has again (check 210)",
          "\\mathbf{L}_G =\n\\frac{3\\Omega^2}{R_c^2}\n\\begin{bmatrix}\nR_{c2} R_{c3} (I_{33} - I_{22}) \\\\\nR_{c1} R_{c3} (I_{11} - I_{33}) \\\\\nR_{c1} R_{c2} (I_{22} - I_{11})\n\\end{bmatrix}",
          "By algebra: 3 G M_e/R_c^5 = 3 (G M_e/R_c^3)/R_c^2 = 3 Omega^2/R_c^2. Putting R_c = (-sin theta, sin phi cos theta, cos phi cos theta) R_c into the display as written gives the first component Omega^2 sin phi cos phi cos^2 theta (I_33 - I_22) = (1/2) Omega^2 (I_33 - I_22) cos^2 theta sin 2 phi, while the notebook's own next display has (3/2) Omega^2 for it: only the factor 3 makes the two agree.",
          "By numbers: a dumbbell of two unit masses at r = +-(1, 0, 0) in the body (I_11 = 0, I_22 = I_33 = 2), G M_e = 1, R_c = 100 (Omega^2 = 1e-6), pitched by theta = pi/4 so that ^B R_c = 100 (-1/sqrt 2, 0, 1/sqrt 2): the exact sum of r x (-(R_c + r)/|R_c + r|^3) over the two masses has second component 3.0001e-6; 3 Omega^2/R_c^2 R_c1 R_c3 (I_11 - I_33) = 3e-6/1e4 * (-5000)(-2) = 3.0e-6 agrees, while the display's Omega^2/R_c^2 R_c1 R_c3 (I_11 - I_33) = 1.0e-6 is three times too small."),
    222: ("holds", "with the body components of R_c (line 169) and G M_e/R_c^3 = Omega^2 the torque is 3/2 Omega^2 ((I_33 - I_22) cos^2 theta sin 2phi, -(I_11 - I_33) cos phi sin 2theta, -(I_22 - I_11) sin phi sin 2theta), exactly (check 222)"),
    233: ("holds", "the torque of line 222 to first order in the angles (check 233)"),
    261: ("holds", "Euler's equation with the gravity-gradient torque, as line 83 (check 261)"),
    267: ("holds", "the first-order angular acceleration, as line 111 (check 267)"),
    278: ("holds", "the first-order angular velocity (check 278)"),
    289: ("holds", "the skew (cross-product) matrix of the vector written in line 267, entry by entry; the prose calls it the matrix of the angular velocity, but the display is that of the acceleration and is right as written (check 289)"),
    300: ("holds", "the first-order torque, as line 233 (check 300)"),
    312: ("holds", "[I] omega' + omega x [I] omega - L_G with the first-order omega, omega' and L_G: to first order it is Euler's equation of motion, row by row (check 312)"),
    347: ("holds", "the rows of line 312 multiplied out: -(omega x [I] omega)_1 = -(I_33 - I_22) omega_2 omega_3 and cyclic, term by term (check 347)"),
    366: ("holds", "the first-order part of line 347: the products of two small quantities dropped, the result agrees with Euler's equations to first order (check 366)"),
    395: ("holds", "the second row of the first-order equations: I_22 theta'' + 3 Omega^2 (I_11 - I_33) theta = 0 (check 395)"),
    401: ("holds", "line 395 divided by I_22 (check 401)"),
    407: ("not a claim", "the equation of a mass on a spring, brought in for comparison"),
    413: ("holds", "with k = 3 Omega^2 (I_11 - I_33) and m = I_22, k/m is the coefficient of theta in line 401; k/m > 0 implies it is >= 0 (check 413)"),
    419: ("holds", "3 Omega^2 (I_11 - I_33)/I_22 >= 0 is I_11 >= I_33 since 3 Omega^2/I_22 > 0; the boundary case I_11 = I_33 (no restoring stiffness) is the notebook's non-strict reading of its own k/m > 0 (check 419)"),
    441: ("holds", "the first-order system of line 366 again (check 441)"),
    460: ("holds", "the first row of line 366, Euler's roll equation to first order (check 460)"),
    466: ("holds", "-(I_33 - I_22) = (I_22 - I_33): the right side regrouped (check 466)"),
    472: ("holds", "line 466 brought to one side and divided by I_11 (check 472)"),
    478: ("not a claim", "the definition of k_Y"),
    484: ("holds", "line 472 with k_Y = (I_22 - I_33)/I_11 (check 484)"),
    492: ("holds", "the third row of line 366, Euler's yaw equation to first order (check 492)"),
    498: ("holds", "-(I_22 - I_11) taken out of both terms (check 498)"),
    504: ("holds", "line 498 divided by I_33 (check 504)"),
    510: ("not a claim", "the definition of k_R"),
    516: ("holds", "line 504 with k_R = (I_22 - I_11)/I_33 (check 516)"),
    522: ("holds", "line 516 brought to one side: -Omega phi' + Omega k_R phi' = Omega (k_R - 1) phi' (check 522)"),
    530: ("holds", "the roll and yaw equations of lines 484 and 522 as one matrix system (check 530)"),
}


if __name__ == "__main__":
    here = pathlib.Path(__file__)
    assert truth_table.notebook_display_lines(here.with_name(here.name.removesuffix("_truth.py") + ".ipynb")) == LINES
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
