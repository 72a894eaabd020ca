"""Independent SymPy truth table for verga-polytech-spinning-cone-euler-equations-fr.ipynb.

The notebook's own setting: a solid cone of mass M, height h and base radius d, apex O at the
origin, axis z, cylindrical coordinates (r, phi, z) with r from 0 to d z / h; density rho, volume
element r dr dphi dz. Moments I_1, I_2, I_3 about axes through the apex, I_x, I_y, I_z about the
centre of mass. Euler's equations in body axes with Omega the body angular velocity; the Euler
angles of the notebook's companion (phi about the fixed Z, theta about the line of nodes, psi about
the body z), so that Omega = (phidot sin(theta) sin(psi) + thetadot cos(psi), phidot sin(theta)
cos(psi) - thetadot sin(psi), phidot cos(theta) + psidot). The free symmetric top: I_x = I_y = I.
Every check is built here from these definitions. A display's line is the notebook file's line of
its first row.
"""
import sys
import pathlib
import random
import sympy as sp

import truth_table
from truth_table import Rx, Rz

CHECKS = {}
def check(key, ok):
    CHECKS[key] = bool(ok)

z0 = truth_table.zero


def sampled_zero(expr, samples=4):
    """expr (a matrix in the angles, their rates and second rates) vanishes at sampled values,
    to 1e-12: for an identity too long for simplify."""
    rng = random.Random(11)
    rates2 = sorted((d for d in expr.atoms(sp.Derivative) if d.derivative_count == 2), key=str)
    rates1 = sorted((d for d in expr.atoms(sp.Derivative) if d.derivative_count == 1), key=str)
    funcs = sorted(expr.atoms(sp.core.function.AppliedUndef), key=str)
    for _ in range(samples):
        e = expr
        for group in (rates2, rates1, funcs, sorted(e.free_symbols, key=str)):
            e = e.subs({f: sp.Float(rng.uniform(-2, 2), 30) for f in group})
        if any(abs(complex(sp.N(x, 30))) > 1e-12 for x in e):
            return False
    return True

M, h, d = sp.symbols('M h d', positive=True)
r, ph, z = sp.symbols('r phi z', real=True)

def as_written(f):
    """The triple integral as the display writes it: dz dr dphi, no density, no Jacobian r."""
    return sp.integrate(sp.integrate(sp.integrate(f, (ph, 0, 2 * sp.pi)), (r, 0, d * z / h)), (z, 0, h))

def over_cone(f):
    """The integral of f over the cone's volume: r dr dphi dz."""
    return as_written(r * f)

vol = over_cone(1)
rho = M / vol
# 47: x = r cos(phi), y = r sin(phi), z = z: cylindrical coordinates, a definition (not a claim)
# 49: r = d z / h: the cone's lateral surface, where the radius ends (not a claim)
# 53: the volume as written, without the Jacobian r, is pi d h, not pi d^2 h / 3
check(53, z0(as_written(1) - sp.pi * d**2 * h / 3))
assert z0(vol - sp.pi * d**2 * h / 3)          # the stated value is the cone's volume
# 55: rho = 3 M / (pi d^2 h)
check(55, z0(rho - 3 * M / (sp.pi * d**2 * h)))
# 58: R = int z (as written, no rho/M, no r) = 3h/4
R = rho / M * over_cone(z)
check(58, z0(as_written(z) - 3 * h / 4))
assert z0(R - 3 * h / 4)
# 61: I_1, I_2, I_3 about the apex as the three integrals written, without rho and r
I1 = rho * over_cone(r**2 * sp.sin(ph)**2 + z**2)      # y^2 + z^2
I2 = rho * over_cone(r**2 * sp.cos(ph)**2 + z**2)      # x^2 + z^2
I3 = rho * over_cone(r**2)
check(61, z0(as_written(r**2 * sp.cos(ph)**2 + z**2) - I1) and z0(as_written(r**2 * sp.sin(ph)**2 + z**2) - I2)
      and z0(as_written(r**2) - I3))
# ... the cos^2 <-> sin^2 of I_1 and I_2 is harmless: the two integrals over phi in (0, 2 pi) agree
assert z0(over_cone(r**2 * sp.cos(ph)**2 + z**2) - over_cone(r**2 * sp.sin(ph)**2 + z**2))
assert z0(rho * over_cone(r**2 * sp.cos(ph)**2 + z**2) - I1)     # with rho and r they hold
# 67: I_x = I_1 - M R^2, I_y = I_2 - M R^2, I_z = I_3 (parallel axes, the centre at distance R on z)
Ix_c = rho * over_cone(r**2 * sp.sin(ph)**2 + (z - R)**2)
Iy_c = rho * over_cone(r**2 * sp.cos(ph)**2 + (z - R)**2)
check(67, z0(Ix_c - (I1 - M * R**2)) and z0(Iy_c - (I2 - M * R**2)) and z0(I3 - rho * over_cone(r**2)))
# 80: I_x = I_y = 3M/20 (d^2 + h^2/4), I_z = 3 M d^2 / 10
check(80, z0(Ix_c - sp.Rational(3, 20) * M * (d**2 + h**2 / 4)) and z0(Iy_c - Ix_c)
      and z0(I3 - sp.Rational(3, 10) * M * d**2))
# 82: R = 3h/4
check(82, z0(R - 3 * h / 4))

# --- Euler's equations: a body frame turning with Omega
t = sp.symbols('t', real=True)
q = [sp.Function(n)(t) for n in ('phi', 'theta', 'psi')]
Rot = Rz(q[0]) * Rx(q[1]) * Rz(q[2])                     # body axes in the fixed frame
W = sp.simplify(Rot.T * Rot.diff(t))
Om = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])
Ix, Iy, Iz, I = sp.symbols('I_x I_y I_z I', positive=True)
Ib = sp.diag(Ix, Iy, Iz)
Lb = Ib * Om
# 103: dL/dt|fixed (in body components) = dL/dt|body + Omega x L
Lfix = Rot * Lb
check(103, sampled_zero(Rot.T * Lfix.diff(t) - (Lb.diff(t) + Om.cross(Lb))))
# 107: the three components of Ldot (the fixed-frame rate, in body components) with diagonal I
o = sp.Matrix(sp.symbols('Omega_x Omega_y Omega_z', real=True))
od = sp.Matrix(sp.symbols('Omegadot_x Omegadot_y Omegadot_z', real=True))
Ldot = Ib * od + o.cross(Ib * o)
check(107, z0(Ldot - sp.Matrix([Ix * od[0] + (Iz - Iy) * o[1] * o[2], Iy * od[1] + (Ix - Iz) * o[0] * o[2],
                                Iz * od[2] + (Iy - Ix) * o[0] * o[1]])))
# free symmetric top: Ldot = 0, I_x = I_y = I
free = {Ix: I, Iy: I}
sol = sp.solve(list((Ldot.subs(free))), list(od), dict=True)[0]
# 120: I_z Omegadot_z = 0
check(120, z0(Iz * sol[od[2]]))
# 122: phidot cos(theta) + psidot = Omega_z = const
check(122, z0(Om[2] - (q[0].diff(t) * sp.cos(q[1]) + q[2].diff(t))) and z0(sol[od[2]]))
om = (Iz - I) / I * o[2]
# 125: Omegadot_x = -omega Omega_y, Omegadot_y = omega Omega_x, with 128's omega
check(125, z0(sol[od[0]] - (-om * o[1])) and z0(sol[od[1]] - om * o[0]))
# 128: omega = (I_z - I)/I Omega_z defines omega (not a claim)
w, a = sp.symbols('omega a', positive=True)
Ox, Oy = a * sp.cos(w * t), a * sp.sin(w * t)
# 131: Omega_x = a cos(omega t), Omega_y = a sin(omega t) solve 125
check(131, z0(Ox.diff(t) + w * Oy) and z0(Oy.diff(t) - w * Ox))
# 133: sqrt(Omega_x^2 + Omega_y^2) = a
check(133, z0(sp.sqrt(Ox**2 + Oy**2) - a))
# 137: with psi = 0 (so psidot = 0): Omega_x = thetadot, Omega_y = phidot sin(theta); 125 gives
#      d/dt thetadot = -omega phidot sin(theta), d/dt(phidot sin(theta)) = omega thetadot
th, phd, thd = sp.symbols('theta phidot thetadot', real=True)
Om0 = Om.subs(q[2], 0).doit()
assert z0(Om0[0] - q[1].diff(t)) and z0(Om0[1] - q[0].diff(t) * sp.sin(q[1]))
Oxd_true, Oyd_true = -w * Om0[1], w * Om0[0]          # Euler with omega, at psi = 0
check(137, z0(Oxd_true - w * (q[0].diff(t) * sp.sin(q[1]))) and z0(Oyd_true - (-w * q[1].diff(t))))
assert z0(Oxd_true - (-w * q[0].diff(t) * sp.sin(q[1]))) and z0(Oyd_true - w * q[1].diff(t))
# constant theta: Omega_x = phidot sin(theta) sin(psi), Omega_y = phidot sin(theta) cos(psi)
Omc = Om.subs(q[1], th).doit()
# 158: d/dt(phidot sin(theta) sin(psi)) = -omega phidot sin(theta) cos(psi), i.e. Omegadot_x = -omega Omega_y
check(158, z0(Omc[0] - q[0].diff(t) * sp.sin(th) * sp.sin(q[2])) and z0(Omc[1] - q[0].diff(t) * sp.sin(th) * sp.cos(q[2]))
      and z0(sol[od[0]] + om * o[1]))
# 160: d/dt(phidot sin(theta) cos(psi)) = omega phidot sin(theta) sin(psi), i.e. Omegadot_y = omega Omega_x
check(160, z0(Omc[0] - q[0].diff(t) * sp.sin(th) * sp.sin(q[2])) and z0(sol[od[1]] - om * o[0]))
# the two together: u = phidot sin(theta) e^{i psi}... solved: phidot sin(theta) = const, psidot = -omega
P = sp.Function('P')(t)                                  # P = phidot sin(theta)
ex = sp.Matrix([(P * sp.sin(q[2])).diff(t) + w * P * sp.cos(q[2]), (P * sp.cos(q[2])).diff(t) - w * P * sp.sin(q[2])])
sl = sp.solve(list(ex), [P.diff(t), q[2].diff(t)], dict=True)[0]
# 162: phidot sin(theta) = const
check(162, z0(sl[P.diff(t)]))
# 164: psidot = -omega
check(164, z0(sl[q[2].diff(t)] + w))

KEYS = [47, 49, 53, 55, 58, 61, 67, 80, 82, 103, 107, 120, 122, 125, 128, 131, 133, 137, 158, 160, 162, 164]


if __name__ == "__main__":
    here = pathlib.Path(__file__)
    assert truth_table.notebook_display_lines(here.with_name('verga-polytech-spinning-cone-euler-equations-fr.ipynb')) == KEYS
    sys.exit(truth_table.compare(__file__, CHECKS, KEYS))
