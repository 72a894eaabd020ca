"""Independent SymPy truth table for wikipedia-poinsot-ellipsoid-construction-encyclopaedia.md.

The article's convention: a rigid body turns with angular velocity omega about its centre of mass;
I is its inertia tensor about that point, T its rotational kinetic energy and L its angular
momentum, all in one frame; along the principal axes I = diag(I_1, I_2, I_3). T and L are built
here from particles (T = sum m |omega x r|^2 / 2, L = sum m r x (omega x r)) with the particles'
positions and omega as symbols, so no formula of the text is assumed; the principal-axes form takes
a diagonal tensor with symbolic moments.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


w = sp.Matrix(sp.symbols('w1:4'))                       # the angular velocity
masses = sp.symbols('m1:3', positive=True)              # two particles, enough for a general tensor
pos = [sp.Matrix(sp.symbols(f'x{k} y{k} z{k}')) for k in (1, 2)]

T_particles = sum(m * (w.cross(r)).dot(w.cross(r)) for m, r in zip(masses, pos)) / 2
L_particles = sum((m * r.cross(w.cross(r)) for m, r in zip(masses, pos)), sp.zeros(3, 1))
I_tensor = sum((m * (r.dot(r) * sp.eye(3) - r * r.T) for m, r in zip(masses, pos)), sp.zeros(3, 3))

# line 26: T = 1/2 omega . I . omega = 1/2 sum I_k omega_k^2 (the second along principal axes)
I1, I2, I3 = sp.symbols('I1:4', positive=True)
Ip = sp.diag(I1, I2, I3)
first = truth_table.zero(T_particles - (w.T * I_tensor * w)[0] / 2)
second = truth_table.zero((w.T * Ip * w)[0] / 2 - (I1 * w[0] ** 2 + I2 * w[1] ** 2 + I3 * w[2] ** 2) / 2)
check(26, first and second)

# line 41: L = I . omega
check(41, truth_table.zero(L_particles - I_tensor * w))

# line 47: T = 1/2 omega . L
check(47, truth_table.zero(T_particles - w.dot(L_particles) / 2))

# line 61: dT/d omega = I . omega = L (the gradient of T with respect to omega)
grad = sp.Matrix([sp.diff(T_particles, x) for x in w])
check(61, truth_table.zero(grad - I_tensor * w) and truth_table.zero(I_tensor * w - L_particles))

LINES = [26, 41, 47, 61]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
