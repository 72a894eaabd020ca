"""Independent SymPy truth table for c4dynamics-6dof-kinematics-321-rates.md.

The text's own setting: an earth-fixed inertial frame; body axes x_b, y_b, z_b, taken as principal
(only the moments I_xx, I_yy, I_zz enter); the attitude by 3-2-1 Euler angles, yaw psi about z, then
pitch theta about the new y, then roll phi (written varphi, once phi) about the new x; the body rates
p, q, r are the angular velocity's components on the body axes; "d" before a quantity is its rate of
change. The Euler-angle rates are derived here from the angular velocity built by geometry (each
elementary rate carried to the body axes), and Euler's equations from the rate of change of the
angular momentum in the inertial frame, h = R I omega, never from the text's displays.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero
c, s, tan = sp.cos, sp.sin, sp.tan
t = sp.symbols("t", real=True)
ph, th, ps = [sp.Function(n, real=True)(t) for n in ("phi", "theta", "psi")]


def R1(a):  # frame rotation about x (components in the old frame -> in the new)
    return sp.Matrix([[1, 0, 0], [0, c(a), s(a)], [0, -s(a), c(a)]])


def R2(a):
    return sp.Matrix([[c(a), 0, -s(a)], [0, 1, 0], [s(a), 0, c(a)]])


def R3(a):
    return sp.Matrix([[c(a), s(a), 0], [-s(a), c(a), 0], [0, 0, 1]])


E = sp.eye(3)
# body rates from the three elementary rates, each carried into the body frame
w = E[:, 0] * ph.diff(t) + R1(ph) * E[:, 1] * th.diff(t) + R1(ph) * R2(th) * E[:, 2] * ps.diff(t)
p, q, r = sp.symbols("p q r", real=True)
rates = sp.solve(list(w - sp.Matrix([p, q, r])), [ph.diff(t), th.diff(t), ps.diff(t)], dict=True)[0]
dph, dth, dps = rates[ph.diff(t)], rates[th.diff(t)], rates[ps.diff(t)]
P, T, S = sp.symbols("varphi theta psi", real=True)
sub = {ph: P, th: T, ps: S}
dph, dth, dps = (sp.simplify(e.subs(sub)) for e in (dph, dth, dps))

# Newton: F = d(m v)/dt is the law posed (line 38, not a claim); with m constant it is m v'
m = sp.symbols("m", positive=True)
v = sp.Function("v")(t)
check(46, zero(sp.diff(m * v, t) - m * v.diff(t)))
# M = dh/dt: the rotational law posed (line 53, not a claim)
# M = [I] omega': h = R^T I omega (inertial components), so dh/dt = R^T (I omega' + omega x I omega);
# it equals R^T I omega' only when omega x I omega = 0; for Ixx != Iyy != Izz and a general omega it does not
Ixx, Iyy, Izz = sp.symbols("I_xx I_yy I_zz", positive=True)
Ib = sp.diag(Ixx, Iyy, Izz)
om = sp.Matrix([p, q, r])
gyro = om.cross(Ib * om)
check(59, zero(gyro))
# translational: dx = v_x ... define the velocity (lines 72, 76, 80 not claims); dv = F/m from F = m v'
Fx = sp.symbols("F0", real=True)
vx = sp.Function("v_x")(t)
law = sp.Eq(Fx, m * vx.diff(t))
sol = sp.solve(law, vx.diff(t))[0]
for line in (84, 88, 92):
    check(line, zero(sol - Fx / m))
# Euler-angle rates (the text's cos(phi) in d psi is its roll angle varphi)
check(106, zero(dph - (p + (q * s(P) + r * c(P)) * tan(T))))
check(110, zero(dth - (q * c(P) - r * s(P))))
check(114, zero(dps - (q * s(P) + r * c(P)) / c(T)))
# Euler's equations: body components of M = I omega' + omega x I omega
M0, M1, M2 = sp.symbols("M0 M1 M2", real=True)
dp_, dq_, dr_ = sp.symbols("dp dq dr", real=True)
euler = Ib * sp.Matrix([dp_, dq_, dr_]) + gyro - sp.Matrix([M0, M1, M2])
sol = sp.solve(list(euler), [dp_, dq_, dr_], dict=True)[0]
check(118, zero(sol[dp_] - (M0 - q * r * (Izz - Iyy)) / Ixx))
check(122, zero(sol[dq_] - (M1 - p * r * (Ixx - Izz)) / Iyy))
check(126, zero(sol[dr_] - (M2 - p * q * (Iyy - Ixx)) / Izz))

# the inertial rate of the angular momentum is R^T (I omega' + omega x I omega) (built by geometry)
Rt = (R1(ph) * R2(th) * R3(ps)).T
wb = w
pt, qt, rt = sp.Function("p")(t), sp.Function("q")(t), sp.Function("r")(t)
h_in = Rt * Ib * sp.Matrix([pt, qt, rt])
Rdot_body = Rt.T * Rt.diff(t)        # = [w]x in body components
skew_w = sp.Matrix([[0, -wb[2], wb[1]], [wb[2], 0, -wb[0]], [-wb[1], wb[0], 0]])
assert zero(Rdot_body - skew_w)

# negative controls: the checks can fail
assert not zero(dps - (q * s(P) + r * c(P)) * tan(T))
assert not zero(sol[dp_] - (M0 + q * r * (Izz - Iyy)) / Ixx)

LINES = [38, 46, 53, 59, 72, 76, 80, 84, 88, 92, 106, 110, 114, 118, 122, 126]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
