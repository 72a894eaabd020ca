"""Independent SymPy truth table for physics-se-dzhanibekov-earth-linearized-euler-eigenvalues.md.

The answer's convention: principal moments I_1, I_2, I_3, body components omega_i of the angular
velocity, no torque. Euler's equations are derived here from the body-frame law
I omega-dot + omega x (I omega) = 0; the linearization puts omega_1 = e u_1, omega_2 = e u_2,
omega_3 = Omega + e u_3 and keeps the terms of first order in e; the growth rates are the
eigenvalues of the linear system's matrix.
"""
import sys

import sympy as sp

import truth_table
from truth_table import zero

t, e = sp.symbols('t epsilon')
I1, I2, I3, Om = sp.symbols('I_1 I_2 I_3 Omega', positive=True)
lam = sp.symbols('lambda')
w = sp.Matrix([sp.Function(f'omega_{i}')(t) for i in (1, 2, 3)])
I = sp.diag(I1, I2, I3)
law = I * w.diff(t) + w.cross(I * w)          # = 0 for the free body (body components)

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


# line 14: the three rows as printed, each the law's row
w1, w2, w3 = w
printed14 = sp.Matrix([I1 * w1.diff(t) - (I2 - I3) * w2 * w3,
                       I2 * w2.diff(t) - (I3 - I1) * w3 * w1,
                       I3 * w3.diff(t) - (I1 - I2) * w1 * w2])
check(14, zero(printed14 - law))

# linearization about a spin Omega about axis 3
u = [sp.Function(f'u_{i}')(t) for i in (1, 2, 3)]
sub = {w1: e * u[0], w2: e * u[1], w3: Om + e * u[2]}
lin = (law.subs(sub).doit())
first = lin.applyfunc(lambda x: sp.expand(x).coeff(e, 1))
zeroth = lin.applyfunc(lambda x: sp.expand(x).coeff(e, 0))
assert zero(zeroth)                            # steady spin about axis 3 solves the equations

# line 26: I_3 omega_3-dot = 0 to first order, so omega_3 stays Omega
check(26, zero(first[2] - I3 * u[2].diff(t)))

# line 32: I_1 w1' = (I_2 - I_3) Omega w2, I_2 w2' = (I_3 - I_1) Omega w1 at first order
check(32, zero(first[0] - (I1 * u[0].diff(t) - (I2 - I3) * Om * u[1]))
      and zero(first[1] - (I2 * u[1].diff(t) - (I3 - I1) * Om * u[0])))

# line 39: the pair as diag(I_1, I_2) d/dt (w1, w2) = M (w1, w2)
ud = sp.Matrix([u[0].diff(t), u[1].diff(t)])
uv = sp.Matrix([u[0], u[1]])
M39 = sp.Matrix([[0, (I2 - I3) * Om], [(I3 - I1) * Om, 0]])
lin2 = sp.Matrix([first[0], first[1]])
check(39, zero(lin2 - (sp.diag(I1, I2) * ud - M39 * uv)))

# line 49: divided by the moments
A = sp.Matrix([[0, (I2 - I3) / I1 * Om], [(I3 - I1) / I2 * Om, 0]])
check(49, zero(A - sp.diag(I1, I2).inv() * M39))

# line 59: the characteristic matrix A - lambda 1 of that system, as printed
printed59 = sp.Matrix([[-lam, (I2 - I3) / I1 * Om], [(I3 - I1) / I2 * Om, -lam]])
check(59, zero(printed59 - (A - lam * sp.eye(2))))

# line 65: the expanded determinant
charpoly = (A - lam * sp.eye(2)).det()
check(65, zero(charpoly - (lam**2 - ((I2 - I3) * (I3 - I1) / (I1 * I2)) * Om**2)))

# line 71: its two roots
roots = sp.solve(charpoly, lam)
printed71 = [s * Om * sp.sqrt((I2 - I3) * (I3 - I1) / (I1 * I2)) for s in (1, -1)]
check(71, all(zero(charpoly.subs(lam, r)) for r in printed71) and len(roots) == 2
      and zero(printed71[0] + printed71[1]))

LINES = [14, 26, 32, 39, 49, 59, 65, 71]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
