"""Independent SymPy truth table for wikipedia-precession-torque-free-and-gyroscopic-encyclopaedia.md.

Names as the article's: a body symmetric about its axis e_s has the moment I_s about that axis and
I_p about the two others; omega_s is the body's angular velocity about the symmetry axis (its
component omega . e_s) and alpha the angle between the constant angular momentum L and the
symmetry axis. For the simulation, R takes body to outside components, I_0 is the body's inertia
tensor, L the outside angular momentum, E the kinetic energy. For the gyroscope, a fast top of
mass m whose centre of mass is r from the pivot, tilted theta from the vertical axis of
precession, spins at omega_s (period T_s) with moment I_s about its axis; its angular momentum is
taken as I_s omega_s along the axis (the gyroscopic approximation the article's formula rests on).
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


def zero(e):
    return truth_table.zero(e)


t = sp.symbols('t', real=True)
Is, Ip = sp.symbols('I_s I_p', positive=True)
A, w3 = sp.symbols('A omega_3', positive=True)

# line 28: torque-free symmetric body. Euler's equations with I_1 = I_2 = I_p give the body
# components omega = (A cos nu t, A sin nu t, omega_3), nu = (I_s - I_p) omega_3 / I_p.
nu = (Is - Ip) * w3 / Ip
wb = sp.Matrix([A * sp.cos(nu * t), A * sp.sin(nu * t), w3])
Ib = sp.diag(Ip, Ip, Is)
euler = Ib * wb.diff(t) + wb.cross(Ib * wb)
assert zero(euler)
Lb = Ib * wb
Lmag = sp.sqrt(Lb.dot(Lb))
# omega splits into a turn about L at |L|/I_p and a turn about the symmetry axis: the axis e_s
# (fixed in the body) therefore moves about L at |L|/I_p, the precession rate
rest = wb - Lb / Ip
assert zero(rest[0]) and zero(rest[1])          # what is left is along e_s
omega_p = Lmag / Ip
cos_alpha = Lb[2] / Lmag                        # L . e_s / |L|
printed28 = Is * w3 / (Ip * cos_alpha)
check(28, zero(omega_p - printed28))

# line 42: L = R I_0 R^T omega (outside components), so omega = R I_0^-1 R^T L
th = sp.symbols('theta_1:4')
Rz = sp.Matrix([[sp.cos(th[0]), -sp.sin(th[0]), 0], [sp.sin(th[0]), sp.cos(th[0]), 0], [0, 0, 1]])
Rx = sp.Matrix([[1, 0, 0], [0, sp.cos(th[1]), -sp.sin(th[1])], [0, sp.sin(th[1]), sp.cos(th[1])]])
Ry = sp.Matrix([[sp.cos(th[2]), 0, sp.sin(th[2])], [0, 1, 0], [-sp.sin(th[2]), 0, sp.cos(th[2])]])
R = Rz * Rx * Ry
I0 = sp.Matrix([[4, 1, 0], [1, 6, -1], [0, -1, 9]])
Lw = sp.Matrix([2, -1, 3])                      # a fixed outside angular momentum
numbers = dict(zip(th, (sp.Rational(1, 3), sp.Rational(-6, 5), sp.Rational(7, 4))))
R = R.subs(numbers).evalf(40)                   # one unremarkable orientation, to 40 digits
w_out = R * I0.inv() * R.T * Lw
check(42, all(abs(x) < 1e-30 for x in R * I0 * R.T * w_out - Lw))

# line 46: the step R_new = exp([omega]_x dt) R_old: the integration step the article chooses
# (a recipe, not a claim); line 51: E = 1/2 omega . L, the kinetic energy 1/2 omega . (I omega)
I_out = R * I0 * R.T
check(51, abs(w_out.dot(I_out * w_out) / 2 - w_out.dot(Lw / 2)) < 1e-30)

# line 56: E(exp([v]_x) R) = E(R) + (omega(R) x L) . v to first order in a small v
eps = sp.symbols('epsilon', positive=True)
n = sp.Matrix([1, -2, sp.Rational(1, 2)])
v = eps * n
K = sp.Matrix([[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]]) / n.norm()
turn = sp.eye(3) + sp.sin(eps * n.norm()) * K + (1 - sp.cos(eps * n.norm())) * K * K   # exp([v]_x), Rodrigues


def energy(Rm):
    return (Rm * I0.inv() * Rm.T * Lw).dot(Lw) / 2


Rn = R
E_new = energy(turn * Rn)
series = sp.series(E_new, eps, 0, 2).removeO()
printed56 = energy(Rn) + (Rn * I0.inv() * Rn.T * Lw).cross(Lw).dot(v)
diff56 = sp.Poly(sp.expand(sp.N(series - printed56, 40)), eps).all_coeffs()
check(56, all(abs(x) < 1e-30 for x in diff56))

# line 77: the law tau = dL/dt the section starts from (no check)

# line 83: gyroscopic precession. L = I_s omega_s along the axis, tilted theta from the vertical,
# turning about the vertical at Omega: dL/dt = Omega x L, and the weight's torque about the pivot
# has the size m g r sin(theta)
m, g, r, theta, ws, Om, Ts = sp.symbols('m g r theta omega_s Omega T_s', positive=True)
axis = sp.Matrix([sp.sin(theta), 0, sp.cos(theta)])
Lg = Is * ws * axis
dL = sp.Matrix([0, 0, Om]).cross(Lg)
weight_torque = (r * axis).cross(sp.Matrix([0, 0, -m * g]))
Om_sol = sp.solve(sp.Eq(dL[1], weight_torque[1]), Om)[0]
assert weight_torque[0] == 0 and weight_torque[2] == 0
tau = weight_torque[1]                          # its size, m g r sin(theta), for 0 < theta < pi
check(83, zero(Om_sol - m * g * r / (Is * ws)) and zero(Om_sol - tau / (Is * ws * sp.sin(theta))))

# line 90: the period T_p = 2 pi / omega_p with omega_s = 2 pi / T_s
Tp = 2 * sp.pi / Om_sol.subs(ws, 2 * sp.pi / Ts)
check(90, zero(Tp - 4 * sp.pi ** 2 * Is / (m * g * r * Ts))
      and zero(Tp - 4 * sp.pi ** 2 * Is * sp.sin(theta) / (tau * Ts)))

LINES = [28, 42, 46, 51, 56, 77, 83, 90]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
