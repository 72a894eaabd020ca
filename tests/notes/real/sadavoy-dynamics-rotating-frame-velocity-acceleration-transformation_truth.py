"""Independent SymPy truth table for sadavoy-dynamics-rotating-frame-velocity-acceleration-transformation.md
(Sadavoy, Second-Year Dynamics, ch. 4, section 4.4, MyST edition by Quadrivium Press).

The text's convention: an inertial frame S with fixed unit vectors i, j, k and a frame S' with the same
origin turning with angular velocity omega, its unit vectors i', j', k' the columns of a rotation
matrix Q(t) (here Q = Rz(a) Ry(b) Rz(c), three arbitrary functions of t, so omega and its rate are
general). A point has primed coordinates x', y', z' (arbitrary functions of t) and r = r' = Q (x', y', z').
omega is the vector of the skew matrix Q' Q^T; a rate taken in the rotating frame, (d/dt)_R q, is
Q d/dt(Q^T q) (the primed components differentiated); (d/dt)_I is the plain derivative of the
components in S. Section 4.4.1 is a body turning at constant omega about the fixed k axis.
Everything is built from that; no formula of the text is assumed.
Run as a program it compares its verdicts with the table; ``--write`` writes the table.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Ry, Rz, numeric_zero, zero

t = sp.Symbol('t', real=True)
a_, b_, c_ = [sp.Function(n)(t) for n in ('a', 'b', 'c')]
xp, yp, zp = [sp.Function(n)(t) for n in ('xp', 'yp', 'zp')]
D = lambda e: sp.diff(e, t)  # noqa: E731

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


def vee(S):
    return sp.Matrix([S[2, 1], S[0, 2], S[1, 0]])


# ---- 4.4.1: a body turning at constant omega about the fixed k axis
w, x0, y0, z0 = sp.symbols('omega x_0 y_0 z_0', positive=True)
r1 = Rz(w * t) * sp.Matrix([x0, y0, z0])
W1 = sp.Matrix([0, 0, w])
v1, acc1 = D(r1), D(D(r1))
check(22, zero(v1 - W1.cross(r1)))
check(28, zero(acc1 - W1.cross(W1.cross(r1))))
# line 37: theta the angle from omega to r, so r sin(theta) = rho = |(x, y)|; theta-hat the azimuthal unit vector
rmag = sp.sqrt(r1.dot(r1))
rho = sp.sqrt(r1[0]**2 + r1[1]**2)
sin_th = rho / rmag
azim = sp.Matrix([-r1[1], r1[0], 0]) / rho
check(37, zero(W1.cross(r1) - w * rmag * sin_th * azim) and zero(w * rmag * sin_th * azim - w * rho * azim))
# line 44: a = -omega^2 rho-vector, rho-vector the part of r normal to omega
rhovec = sp.Matrix([r1[0], r1[1], 0])
check(44, zero(acc1 + w**2 * rhovec))

# ---- 4.4.2 and 4.4.3: the general turning frame
Q = Rz(a_) * Ry(b_) * Rz(c_)
e = [Q[:, i] for i in range(3)]                 # i', j', k' in S components
Xp = sp.Matrix([xp, yp, zp])
r = Q * Xp                                      # r = r'
W = vee(sp.simplify(D(Q) * Q.T))               # omega
assert numeric_zero(D(Q) - sp.Matrix.hstack(*[W.cross(ei) for ei in e]), t)


def rate_R(q):                                  # (d/dt)_R q: the primed components differentiated
    return Q * D(Q.T * q)


v = D(r)                                        # (dr/dt)_I
vp = Q * D(Xp)                                  # v' = (dr'/dt)_R
ap = Q * D(D(Xp))                               # a' = (dv'/dt)_R
acc = D(v)                                      # a = (dv/dt)_I
alpha = D(W)
# line 62: d/dt of r and of r' written in their components: the same vector, differentiated
check(62, numeric_zero(D(r) - D(xp * e[0] + yp * e[1] + zp * e[2]), t))
# line 69: the product rule on the primed side
prod = D(xp) * e[0] + xp * D(e[0]) + D(yp) * e[1] + yp * D(e[1]) + D(zp) * e[2] + zp * D(e[2])
check(69, numeric_zero(D(r) - prod, t))
# line 86: the grouping: v = v' + x' di'/dt + y' dj'/dt + z' dk'/dt
rot_part = xp * D(e[0]) + yp * D(e[1]) + zp * D(e[2])
check(86, numeric_zero(v - (vp + rot_part), t))
check(98, numeric_zero(v - (vp + rot_part), t))
# line 106: omega = omega n-hat defines n-hat: not a claim
# lines 118, 122, 128, 132: the change of i' as a vector along i' itself. Take omega along z and i'
# at the angle phi from it; a turn by Delta theta moves i' to Rz(Delta theta) i'.
ph, dth, dt_ = sp.symbols('varphi Delta_theta Delta_t', positive=True)
i0 = sp.Matrix([sp.sin(ph), 0, sp.cos(ph)])
di = Rz(dth) * i0 - i0
check(118, zero(di - i0 * sp.sin(ph) * dth))
check(122, zero(di / dt_ - i0 * sp.sin(ph) * dth / dt_))
# the derivatives: |omega| = d theta/dt, sin(phi) = |omega x i'|/|omega|
Wmag = sp.sqrt(W.dot(W))
sinph = sp.sqrt(W.cross(e[0]).dot(W.cross(e[0]))) / Wmag
check(128, numeric_zero(D(e[0]) - e[0] * sinph * Wmag, t))
check(132, numeric_zero(D(e[0]) - e[0] * sinph * Wmag, t))
assert numeric_zero(sp.Matrix([sp.sqrt(D(e[0]).dot(D(e[0]))) - sinph * Wmag]), t)   # the magnitudes agree
# lines 139, 145, 149: the rates of the primed unit vectors
check(139, numeric_zero(D(e[0]) - W.cross(e[0]), t))
check(145, numeric_zero(D(e[1]) - W.cross(e[1]), t))
check(149, numeric_zero(D(e[2]) - W.cross(e[2]), t))
# lines 157, 164: x' di'/dt + ... = x'(omega x i') + ... = omega x (x' i' + ...) = omega x r'
line157 = [rot_part - (xp * W.cross(e[0]) + yp * W.cross(e[1]) + zp * W.cross(e[2])),
           xp * W.cross(e[0]) + yp * W.cross(e[1]) + zp * W.cross(e[2]) - W.cross(xp * e[0] + yp * e[1] + zp * e[2])]
check(157, numeric_zero(sp.Matrix.hstack(*line157), t))
check(164, numeric_zero(rot_part - W.cross(r), t))
# line 170: (4.3)
check(170, numeric_zero(v - (vp + W.cross(r)), t))
# line 185: definitions of v and v' as rates in their own frames: not a claim
# line 194: (4.3) and the same with the rates written out
check(194, numeric_zero(v - (vp + W.cross(r)), t) and numeric_zero(D(r) - (rate_R(r) + W.cross(r)), t))
# lines 201, 208: the operator form, on r' and on r = r'
check(201, numeric_zero(D(r) - (rate_R(r) + W.cross(r)), t))
check(208, numeric_zero(D(r) - (rate_R(r) + W.cross(r)), t))
# lines 217, 224: the operator on v
check(217, numeric_zero(D(v) - (rate_R(v) + W.cross(v)), t))
check(224, numeric_zero(D(v) - (rate_R(v) + W.cross(v)), t))
# line 228: the two rows continuing (dv/dt)_I
row1 = rate_R(vp + W.cross(r)) + W.cross(vp + W.cross(r))
row2 = rate_R(vp) + rate_R(W).cross(r) + W.cross(rate_R(r)) + W.cross(vp) + W.cross(W.cross(r))
check(228, numeric_zero(sp.Matrix.hstack(D(v) - row1, row1 - row2), t))
# lines 237, 247: definitions of a, a' and v': not a claim
# line 253: a = a' + (d omega/dt)_R x r' + 2 omega x v' + omega x (omega x r')
check(253, numeric_zero(acc - (ap + rate_R(W).cross(r) + 2 * W.cross(vp) + W.cross(W.cross(r))), t))
# lines 260, 274: the rate of omega is the same in both frames
check(260, numeric_zero(rate_R(W) - D(W), t))
check(274, numeric_zero(rate_R(W) - D(W), t))
# line 266: (4.5) with alpha = d omega/dt
check(266, numeric_zero(acc - (ap + alpha.cross(r) + 2 * W.cross(vp) + W.cross(W.cross(r))), t))

LINES = [22, 28, 37, 44, 62, 69, 86, 98, 106, 118, 122, 128, 132, 139, 145, 149, 157, 164, 170,
         185, 194, 201, 208, 217, 224, 228, 237, 247, 253, 260, 266, 274]

SLIP_WHY = ("turning by Delta theta about omega, the tip of the unit vector i' (at the angle phi from omega) moves on a circle of "
            "radius sin phi, so the SIZE of the change is sin phi Delta theta; but the change is a vector at right angles to i' "
            "(i' stays of unit length), and the display writes it as i' sin phi Delta theta, a vector along i' itself: the size is "
            "written with the unit vector where |i'| = 1 belongs")
HC1 = ("omega along z, i' = x (phi = 90 deg), a turn by Delta theta: i' becomes (cos Dtheta, sin Dtheta, 0), so Delta i' = "
       "(cos Dtheta - 1, sin Dtheta, 0), about (0, Dtheta, 0), along y; the display gives (Dtheta, 0, 0), along x. The sizes "
       "agree (Dtheta), the directions are at right angles.")
HC2 = ("i' is a unit vector, so i'.i' = 1 and, differentiating, i'.di'/dt = 0: the rate is perpendicular to i'. The display's "
       "right side dotted with i' gives sin phi omega (or sin phi Delta theta), nonzero unless phi = 0; and the text's own "
       "conclusion di'/dt = omega x i' is perpendicular to i', not along it.")
ROWS = {
    22: ("holds", "a point of a body turning at constant omega about a fixed axis through the origin: r = Rz(omega t) r_0, so dr/dt = omega x r (check 22)"),
    28: ("holds", "differentiating again at constant omega: d2r/dt2 = omega x (omega x r) (check 28)"),
    37: ("holds", "omega along k: omega x r = omega(-y, x, 0); its size is omega r sin theta = omega rho (theta the angle from omega to r, rho = sqrt(x^2 + y^2)) and its direction (-y, x, 0)/rho the azimuthal unit vector the text calls theta-hat (check 37)"),
    44: ("holds", "omega x (omega x r) = -omega^2 (x, y, 0) = -omega^2 rho-vector, rho-vector the part of r normal to omega (check 44)"),
    62: ("holds", "r = r' = x' i' + y' j' + z' k' with a common origin: the same vector differentiated on both sides (check 62)"),
    69: ("holds", "the product rule on x' i' + y' j' + z' k'; the unit vectors of S are constant (check 69)"),
    86: ("holds", "the same terms grouped: the primed components' rates make v', the rest comes from the turning axes (check 86)"),
    98: ("holds", "the grouping of the previous display written with v and v' (check 98)"),
    106: ("not a claim", "defines n-hat as the unit vector along omega"),
    118: ("typo", SLIP_WHY + " (check 118)", "|\\Delta \\hat{\\imath}^{\\prime }| = \\sin \\varphi \\, \\Delta \\theta", HC1, HC2),
    122: ("typo", "the previous display divided by Delta t, the same slip: the rate of the unit vector i' is written as a vector along i', where only its size sin phi Delta theta/Delta t is meant (check 122)", "\\frac{|\\Delta \\hat{\\imath}^{\\prime}|}{\\Delta t} = \\sin \\varphi \\frac{\\Delta \\theta}{\\Delta t}",
          "omega along z, i' = x, phi = 90 deg, Delta theta = 0.01, Delta t = 0.01: Delta i'/Delta t = (cos 0.01 - 1, sin 0.01, 0)/0.01 = (-0.005, 0.99998, 0), along y; the display gives (1, 0, 0), along x.",
          "phi = 0 (i' along the axis): i' does not move, both sides vanish; phi = 90 deg: the size of both sides is Delta theta/Delta t, but i' stays a unit vector, so its change is perpendicular to it, not along it as printed."),
    128: ("typo", "the limit of the previous display: di'/dt is perpendicular to i' (i' is a unit vector) and equals omega x i', of size omega sin phi; the display sets it along i' itself: the size is written with the unit vector (check 128)", "\\left|\\frac{\\mathrm{d}\\hat{\\imath}^{\\prime}}{\\mathrm{d}t}\\right| = \\sin \\varphi \\frac{\\mathrm{d}\\theta}{\\mathrm{d}t}",
          "omega = (0, 0, 1) rad/s, i' = (1, 0, 0) at t = 0 (phi = 90 deg): i'(t) = (cos t, sin t, 0), di'/dt = (0, 1, 0) at t = 0; the display gives i' sin phi d theta/dt = (1, 0, 0).",
          "d/dt (i'.i') = 2 i'.di'/dt = 0, so i'.di'/dt = 0; the display's right side dotted with i' is sin phi d theta/dt, which vanishes only for phi = 0 or a frame at rest."),
    132: ("typo", "the same rate with d theta/dt = omega: di'/dt = omega x i' is perpendicular to i', of size omega sin phi; the display writes it along i' (check 132)", "\\left|\\frac{\\mathrm{d}\\hat{\\imath}^{\\prime}}{\\mathrm{d}t}\\right| = \\omega \\sin \\varphi",
          "omega = 2 rad/s along z, i' = (sin 30 deg, 0, cos 30 deg) (phi = 30 deg): di'/dt = omega x i' = (0, 2 sin 30 deg, 0) = (0, 1, 0); the display gives i' sin 30 deg * 2 = (0.5, 0, 0.866). Both have size 1, in directions at right angles.",
          "The next display, di'/dt = omega x i', which the text draws from this one, is perpendicular to i'; a vector along i' cannot equal it unless both vanish (phi = 0 or omega = 0)."),
    139: ("holds", "a unit vector turning with the frame: di'/dt = omega x i' (omega from Q' Q^T) (check 139)"),
    145: ("holds", "dj'/dt = omega x j' (check 145)"),
    149: ("holds", "dk'/dt = omega x k' (check 149)"),
    157: ("holds", "the three rates put in, and the cross product distributes over the sum: omega x (x' i' + y' j' + z' k') (check 157)"),
    164: ("holds", "x' i' + y' j' + z' k' = r', so the sum is omega x r' (check 164)"),
    170: ("holds", "(4.3): v = v' + omega x r', v' the rates of the primed components on the primed axes (check 170)"),
    185: ("not a claim", "defines v and v' as the rates of r and r' each taken in its own frame"),
    194: ("holds", "(4.3) again and the same with v = (dr/dt)_I and v' = (dr'/dt)_R, (d/dt)_R q = Q d/dt(Q^T q) (check 194)"),
    201: ("holds", "the same factored as an operator acting on r' (check 201)"),
    208: ("holds", "(4.4): r = r' with a common origin, so the operator acts on r (check 208)"),
    217: ("holds", "the transport theorem applied to v: (dv/dt)_I = (dv/dt)_R + omega x v (check 217)"),
    224: ("holds", "the previous display written again (check 224)"),
    228: ("holds", "with v = v' + omega x r': the first row is (dv/dt)_R + omega x v, the second expands (d/dt)_R(omega x r') by the product rule; both hold for a general Q(t) (check 228)"),
    237: ("not a claim", "defines a and a' as the rates of v and v' each in its own frame"),
    247: ("not a claim", "recalls the definition of v' as the rate of r' in the rotating frame"),
    253: ("holds", "omega x (dr'/dt)_R = omega x v' joins omega x v' to give 2 omega x v'; the inertial acceleration of r = Q X' is a' + (d omega/dt)_R x r' + 2 omega x v' + omega x (omega x r') (check 253)"),
    260: ("holds", "(d omega/dt)_I = (d omega/dt)_R + omega x omega and omega x omega = 0 (check 260)"),
    266: ("holds", "(4.5) with alpha = d omega/dt, the same in both frames (check 266)"),
    274: ("holds", "the quick question's claim, the same as the display at line 260 (check 274)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
