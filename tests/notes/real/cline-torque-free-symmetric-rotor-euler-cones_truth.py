"""Independent SymPy truth table for cline-torque-free-symmetric-rotor-euler-cones.md.

The text's own setting: a torque-free rigid body with principal moments I_1 = I_2 != I_3 about its
center of mass; omega = (omega_1, omega_2, omega_3) and L = I omega in body principal components;
e_3 = (0, 0, 1) is the symmetry axis. Euler's equations are derived here from dL/dt + omega x L = 0
(the time derivative taken in the body), Omega is the text's name (I_3 - I_1) omega_3 / I_1. For the
cones, L is taken along the space z axis and the instant is the one at which e_2 lies in the plane of
L and e_3, so L = (0, L sin(theta), L cos(theta)) in body components; alpha is the angle between
omega and e_3. Every check is built from these definitions, never from the text's later displays.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero

t = sp.Symbol('t', real=True)
I1, I2, I3, A, Lm = sp.symbols('I_1 I_2 I_3 A L', positive=True)
w1, w2, w3, th = sp.symbols('omega_1 omega_2 omega_3 theta', real=True)
Ib = sp.diag(I1, I1, I3)
w = sp.Matrix([w1, w2, w3])
e3 = sp.Matrix([0, 0, 1])

# Euler's equations without torque, body frame: I wdot = -(omega x I omega)
wdot = -Ib.inv() * w.cross(Ib * w)
Om = (I3 - I1) / I1 * w3

# 13.111-13.113 with I_2 = I_1: each left side vanishes on the derived rates
lhs = [(I2 - I3) * w2 * w3 - I1 * wdot[0], (I3 - I1) * w3 * w1 - I2 * wdot[1], I3 * wdot[2]]
check(17, all(zero(e.subs(I2, I1)) for e in lhs))
check(23, zero(wdot[0] + Om * w2))
check(27, zero(wdot[1] - Om * w1))
# second derivatives: omega_3 is constant (wdot_3 = 0), so Omega is too
grad = lambda f: sum(sp.diff(f, x) * d for x, d in zip((w1, w2, w3), wdot))
check(39, zero(grad(wdot[0]) + Om**2 * w1) and zero(wdot[2]))
check(43, zero(grad(wdot[1]) + Om**2 * w2))
# the harmonic solution satisfies the first-order pair
Os = sp.Symbol('Omega', real=True)
s1, s2 = A * sp.cos(Os * t), A * sp.sin(Os * t)
check(49, zero(sp.diff(s1, t) + Os * s2))
check(53, zero(sp.diff(s2, t) - Os * s1))
check(59, zero(s1**2 + s2**2 - A**2))
check(65, zero(grad(w1**2 + w2**2 + w3**2)))
check(73, zero(I3 * w3 - I1 * I3 / (I3 - I1) * Om))
check(79, zero(grad(sp.Rational(1, 2) * w.dot(Ib * w))))
check(85, zero(w.cross(e3) - (w2 * sp.Matrix([1, 0, 0]) - w1 * sp.Matrix([0, 1, 0]))))
check(91, zero((sp.diag(I1, I2, I3) * w).dot(w.cross(e3)) - (I1 * w1 * w2 - I2 * w1 * w2)) and
      zero((I1 * w1 * w2 - I2 * w1 * w2).subs(I2, I1)))

# the instant of the cones: L along z, e_2 in the plane of L and e_3
Lb = sp.Matrix([0, Lm * sp.sin(th), Lm * sp.cos(th)])
wc = Ib.inv() * Lb
wmag = sp.sqrt(wc.dot(wc))
sa, ca = wc[1] / wmag, wc[2] / wmag           # sin(alpha), cos(alpha)
check(111, zero(Ib * wc - sp.Matrix([0, I1 * wmag * sa, I3 * wmag * ca])))
check(117, zero(Lb[1] / Lb[2] - sp.tan(th)) and zero(sp.tan(th) - I1 / I3 * sa / ca))

# transport of the body-fixed axis: R' = [omega_s]x R, e_3 space = R e_3 body
ws = sp.Matrix(sp.symbols('a_1 a_2 a_3', real=True))
R = sp.Matrix(3, 3, sp.symbols('r0:9', real=True))
skew = lambda v: sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
check(125, zero(skew(ws) * R * e3 - ws.cross(R * e3)))
e3dot = w.cross(e3)                           # (d e_3/dt)_space, in body components
check(131, zero(e3.cross(e3dot) - (e3.dot(e3) * w - e3.dot(w) * e3)) and
      zero(e3.cross(e3dot) - (w - w3 * e3)))
check(137, zero(w - (e3.cross(e3dot) + w3 * e3)))
check(143, zero(Ib * w - (I1 * e3.cross(e3dot) + I3 * w3 * e3)))
check(149, zero(e3.dot(Ib * w) - (I1 * e3.dot(e3.cross(e3dot)) + I3 * w3 * e3.dot(e3))))
check(155, zero((Ib * wc)[2] - I3 * wc[2]) and zero(I3 * wc[2] - Lm * sp.cos(th)))
d = sp.Matrix(sp.symbols('d_1 d_2 d_3', real=True))
check(161, zero(e3.cross(Ib * w) - (I1 * e3.cross(e3.cross(e3dot)) + I3 * w3 * e3.cross(e3))) and
      zero(e3.cross(e3.cross(d)) - (e3.dot(d) * e3 - e3.dot(e3) * d)))
check(167, zero(e3dot - (Ib * w / I1).cross(e3)))

# the angular velocity rebuilt from the axis' precession, at the instant of the cones
zb = Lb / Lm                                   # space z in body components
e3dot_c = wc.cross(e3)
row1 = e3.cross(e3dot_c) + wc[2] * e3
row2 = Lm / I1 * e3.cross(zb.cross(e3)) + Lm * ca / I3 * e3
row3 = Lm / I1 * zb + Lm * ca * (I1 - I3) / (I1 * I3) * e3
fix2 = Lm / I1 * e3.cross(zb.cross(e3)) + Lm * sp.cos(th) / I3 * e3
fix3 = Lm / I1 * zb + Lm * sp.cos(th) * (I1 - I3) / (I1 * I3) * e3
check(173, zero(row1 - wc) and zero(row2 - wc) and zero(row3 - wc))
SLIP_173_FIXED = zero(row1 - wc) and zero(fix2 - wc) and zero(fix3 - wc)

# precession of the axis about L: rate L / I_1 (13.136); omega's part across e_3 is omega sin(alpha)
phidot = Lm / I1
check(179, zero(phidot * sp.sin(th) - wmag * sa))
check(185, zero(phidot - wmag * sp.sqrt(1 + ((I3 / I1)**2 - 1) * ca**2)))

# negative controls: the checks can fail
assert SLIP_173_FIXED
assert not zero(row2 - wc)
assert not zero(wdot[0] - Om * w2)

LINES = [17, 23, 27, 33, 39, 43, 49, 53, 59, 65, 73, 79, 85, 91, 99, 105, 111, 117, 125, 131, 137, 143, 149, 155, 161, 167, 173, 179, 185]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
