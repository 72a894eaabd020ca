"""Independent SymPy truth table for cooperrc-advanced-dynamics-spinning-top.md.

A top of mass m spins on a fixed point O; its centre of mass G lies on the symmetry axis at a
distance d from O. Euler angles z-x-z: precession phi about the vertical, nutation theta about the
line of nodes, spin psi about the top's axis; the active rotation is R = R_z(phi) R_x(theta) R_z(psi).
The moments about G are I_x = I_y (transverse) and I_z (axial). Kinetic energies are checked on a
set of particles with exact rational positions, masses and velocities, so that no formula of the
text is assumed.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Rz

t = sp.symbols('t')
ph, th, ps = [sp.Function(n)(t) for n in ('phi', 'theta', 'psi')]
phd, thd, psd = ph.diff(t), th.diff(t), ps.diff(t)
m, g, d, Ix, Iz, IO = sp.symbols('m g d I_x I_z I_O', positive=True)

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


def zero(e):
    return sp.simplify(sp.expand_trig(sp.expand(e))) == 0


# --- kinetic energy of a rigid body, from particles (lines 18, 19, 20) ----------------------------
R = sp.Rational
masses = [R(1), R(2), R(3), R(5, 2)]
rho_raw = [sp.Matrix(v) for v in ([1, 0, 2], [-1, 3, 0], [2, -1, 1], [0, 1, -3])]
M = sum(masses)
rG = sum((mi * r for mi, r in zip(masses, rho_raw)), sp.zeros(3, 1)) / M
om = sp.Matrix([R(1, 2), -2, R(3, 2)])              # angular velocity
vB = sp.Matrix([1, R(-1, 3), 2])                    # velocity of the reference point B (at the origin)
vel = [vB + om.cross(r) for r in rho_raw]           # rigid-body velocity field, B at the origin
T_true = sum(mi * v.dot(v) for mi, v in zip(masses, vel)) / 2
vG = vB + om.cross(rG)
# about G: H_G = sum m (r - rG) x v
H_G = sum((mi * (r - rG).cross(v) for mi, r, v in zip(masses, rho_raw, vel)), sp.zeros(3, 1))
check(18, T_true == M * vG.dot(vG) / 2 + om.dot(H_G) / 2)
# line 19 is the form for a point B at rest: with v_B = 0 the same body has T = 1/2 omega . H_B
vel0 = [om.cross(r) for r in rho_raw]
T0 = sum(mi * v.dot(v) for mi, v in zip(masses, vel0)) / 2
H_B0 = sum((mi * r.cross(v) for mi, r, v in zip(masses, rho_raw, vel0)), sp.zeros(3, 1))
check(19, T0 == om.dot(H_B0) / 2)
# line 20 with B moving: H_B about B from absolute velocities, or from velocities relative to B;
# the printed form holds for neither
H_abs = sum((mi * r.cross(v) for mi, r, v in zip(masses, rho_raw, vel)), sp.zeros(3, 1))
H_rel = sum((mi * r.cross(om.cross(r)) for mi, r in zip(masses, rho_raw)), sp.zeros(3, 1))
printed = [M * vB.dot(vB) / 2 + M * vB.dot(vG) / 2 + om.dot(H) / 2 for H in (H_abs, H_rel)]
check(20, any(p == T_true for p in printed))
# the corrections named in the table: v_G/B = omega x r_G/B with H_B from absolute velocities, or
# m v_B . v_G/B with H_B = I_B omega
vGB = om.cross(rG)
assert T_true == M * vB.dot(vB) / 2 + M * vB.dot(vGB) / 2 + om.dot(H_abs) / 2
assert T_true == M * vB.dot(vB) / 2 + M * vB.dot(vGB) + om.dot(H_rel) / 2


# --- the top in Euler angles -------------------------------------------------------------------------
Rot = Rz(ph) * Rx(th) * Rz(ps)
W = sp.simplify(Rot.diff(t) * Rot.T)                 # space angular velocity as a skew matrix
w_space = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])
nodes = Rz(ph) * Rx(th)                             # the axes i', j', k' (k' the top's axis)
w_nodes = sp.simplify(nodes.T * w_space)
w_body = sp.simplify(Rot.T * w_space)
# line 60: omega = thetadot i' + phidot sin(theta) j' + (phidot cos(theta) + psidot) k'
check(60, zero((w_nodes - sp.Matrix([thd, phd * sp.sin(th), phd * sp.cos(th) + psd])).norm() ** 2))
# line 61: inertia about O from the moments about G, O on the axis at distance d from G
I_G = sp.diag(Ix, Ix, Iz)
rOG = sp.Matrix([0, 0, d])
I_Omat = I_G + m * (rOG.dot(rOG) * sp.eye(3) - rOG * rOG.T)
check(61, I_Omat == sp.diag(Ix + m * d ** 2, Ix + m * d ** 2, Iz))
# the Lagrangian from the body components (independent of the i', j', k' form), with I_O = I_x + m d^2
T_body = (IO * (w_body[0] ** 2 + w_body[1] ** 2) + Iz * w_body[2] ** 2) / 2
zG = (Rot * sp.Matrix([0, 0, d]))[2]                # height of G above O
Lag = T_body - m * g * zG
# line 53: L = 1/2 omega I_O omega - m g z with the text's omega (in i', j', k') and z = d cos(theta)
IOn = sp.diag(IO, IO, Iz)
wn = sp.Matrix([thd, phd * sp.sin(th), phd * sp.cos(th) + psd])
check(53, zero((wn.T * IOn * wn)[0] / 2 - m * g * d * sp.cos(th) - Lag))
# lines 74 and 75: the momenta of phi and psi
check(74, zero(Lag.diff(phd) - (phd * (IO * sp.sin(th) ** 2 + Iz * sp.cos(th) ** 2) + Iz * psd * sp.cos(th))))
check(75, zero(Lag.diff(psd) - Iz * (psd + phd * sp.cos(th))))
# line 76: Lagrange's equation for theta
EL = Lag.diff(thd).diff(t) - Lag.diff(th)
printed76 = (IO * th.diff(t, 2) - phd ** 2 * sp.sin(th) * sp.cos(th) * (IO - Iz)
             + phd * psd * Iz * sp.sin(th) - m * g * d * sp.sin(th))
check(76, zero(EL - printed76))
# lines 34 and 90: steady precession (theta constant) from the theta equation; the slow root
# for a fast spin, to leading order in 1/psidot, is m g d / (I_z psidot)
P, S, c = sp.symbols('P S c')                       # phidot, psidot, cos(theta)
quad = sp.expand(-P ** 2 * c * (IO - Iz) + P * S * Iz - m * g * d)     # printed76 / sin(theta), theta fixed
slow = [r for r in sp.solve(quad, P) if sp.limit(r, S, sp.oo) == 0][0]
lead = sp.limit(slow * S, S, sp.oo)
fast_top = sp.simplify(lead - m * g * d / Iz) == 0
for key in (34, 90):
    check(key, fast_top)
# line 82: d = 2r = 0.2 m with r = 0.1 m
check(82, 2 * R(1, 10) == R(2, 10))

LINES = [18, 19, 20, 34, 43, 47, 48, 49, 53, 60, 61, 74, 75, 76, 80, 81, 82, 90]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
