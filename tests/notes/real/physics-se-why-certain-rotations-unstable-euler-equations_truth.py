"""Independent SymPy truth table for physics-se-why-certain-rotations-unstable-euler-equations.md.

The thread's convention: principal moments I_1, I_2, I_3 about the body axes x_i, body components
omega_i of the angular velocity, no torque. Euler's equations are derived here from the body-frame
law I omega-dot + omega x (I omega) = 0; the question's perturbation is omega_1 = e h_1,
omega_2 = 1 + e h_2, omega_3 = e h_3 with the terms of first order in e kept. The answer's angular
momentum has body components L_i = I_i omega_i and its kinetic energy is omega . (I omega) / 2.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Rz
from truth_table import zero

t, e = sp.symbols('t epsilon')
I1, I2, I3 = sp.symbols('I_1 I_2 I_3', positive=True)
w = sp.Matrix([sp.Function(f'omega_{i}')(t) for i in (1, 2, 3)])
I = sp.diag(I1, I2, I3)
law = I * w.diff(t) + w.cross(I * w)          # = 0 for the free body (body components)
w1, w2, w3 = w

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


# lines 15-17: each printed equation is the law's row
check(15, zero(I1 * w1.diff(t) + w2 * w3 * (I3 - I2) - law[0]))
check(16, zero(I2 * w2.diff(t) + w1 * w3 * (I1 - I3) - law[1]))
check(17, zero(I3 * w3.diff(t) + w2 * w1 * (I2 - I1) - law[2]))

# lines 26-28: first order about omega = (0, 1, 0)
h = [sp.Function(f'eta_{i}')(t) for i in (1, 2, 3)]
lin = law.subs({w1: e * h[0], w2: 1 + e * h[1], w3: e * h[2]}).doit()
first = lin.applyfunc(lambda x: sp.expand(x).coeff(e, 1))
assert zero(lin.applyfunc(lambda x: sp.expand(x).coeff(e, 0)))   # the unit spin about axis 2 is steady
check(26, zero(first[0] - (I1 * h[0].diff(t) - (I2 - I3) * h[2])))
check(27, zero(first[1] - I2 * h[1].diff(t)))
check(28, zero(first[2] - (I3 * h[2].diff(t) - (I1 - I2) * h[0])))

# line 32: differentiate (1), use (3)
h1dd = ((I2 - I3) * h[2] / I1).diff(t).subs(h[2].diff(t), (I1 - I2) * h[0] / I3)
check(32, zero(h1dd - (I2 - I3) * (I1 - I2) / (I3 * I1) * h[0]))
# the prose after it: positive when I_1 > I_2 > I_3 (I_1 = I_3 + p + q, I_2 = I_3 + p)
p, q = sp.symbols('p q', positive=True)
assert sp.simplify(((I2 - I3) * (I1 - I2)).subs({I1: I3 + p + q, I2: I3 + p})) == p * q

# line 42: the squared magnitude of L equals the sum of squares of its body components
# (body axes are orthonormal: L_space = R L_body with R a z-x-z rotation)
a, b, c = sp.symbols('a b c', real=True)
Lb = sp.Matrix(sp.symbols('L_1:4', real=True))


Ls = Rz(a) * Rx(b) * Rz(c) * Lb
check(42, zero(Ls.dot(Ls) - (Lb[0]**2 + Lb[1]**2 + Lb[2]**2)))

# line 46: T = omega . (I omega) / 2 with omega_i = L_i / I_i
wL = sp.Matrix([Lb[0] / I1, Lb[1] / I2, Lb[2] / I3])
T = wL.dot(I * wL) / 2
check(46, zero(T - sp.Rational(1, 2) * (Lb[0]**2 / I1 + Lb[1]**2 / I2 + Lb[2]**2 / I3)))

LINES = [15, 16, 17, 26, 27, 28, 32, 42, 46]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
