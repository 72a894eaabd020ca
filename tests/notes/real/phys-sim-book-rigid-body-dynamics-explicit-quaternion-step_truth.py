"""Independent SymPy truth table for phys-sim-book-rigid-body-dynamics-explicit-quaternion-step.md.

The text's convention: x is a point of the body in world space, c its centre of mass, R(t) the body's
rotation from time 0 to t, omega the angular velocity in world components (dR/dt = [omega]x R), f the
force per unit mass at a point (the integrals read rho f), I^c the inertia tensor about c in world
axes. The integral over the body is modelled by a sum over two particles of masses m1, m2 (every
identity used is linear in the masses, so the sum stands for the integral). Quaternions are written
scalar first here; the text's w = (omega_x, omega_y, omega_z, 0) is the pure quaternion of omega.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Rz

CHECKS = {}
zero = truth_table.zero


def check(key, ok):
    CHECKS[key] = bool(ok)


def nzero(expr):
    return truth_table.numeric_zero(expr, t)


t = sp.Symbol('t')


def vec(name):
    return sp.Matrix([sp.Function(f'{name}{k}')(t) for k in 'xyz'])


# 18: Newton's second law for one particle, stated: not a claim
# 27: d(m x cross v)/dt = m x' cross v + m x cross v' = m v cross v + x cross f = x cross f
m = sp.Symbol('m', positive=True)
x = vec('x')
v = x.diff(t)
f = m * v.diff(t)
lhs = (m * x.cross(v)).diff(t)
check(27, nzero(lhs - (m * x.diff(t).cross(v) + m * x.cross(v.diff(t))))
      and nzero(m * v.cross(v) + x.cross(f) - x.cross(f)) and nzero(lhs - x.cross(f)))

# 40: the particle law summed over the body, stated: not a claim
# 47, 57, 64: two particles, f_i = dv_i/dt per unit mass; c the centre of mass
m1, m2 = sp.symbols('m1 m2', positive=True)
ms = (m1, m2)
xs = (vec('p'), vec('q'))
vs = [xi.diff(t) for xi in xs]
fs = [vi.diff(t) for vi in vs]
M = m1 + m2
c = (m1 * xs[0] + m2 * xs[1]) / M
vc = c.diff(t)


def total(terms):
    return terms[0] + terms[1]


L_c = total([mi * c.cross(vi) for mi, vi in zip(ms, vs)])
check(47, nzero(L_c.diff(t) - total([mi * c.cross(vi.diff(t)) for mi, vi in zip(ms, vs)]))
      and nzero(L_c.diff(t) - total([mi * c.cross(fi) for mi, fi in zip(ms, fs)])))
tau_c = total([mi * (xi - c).cross(fi) for mi, xi, fi in zip(ms, xs, fs)])
check(57, nzero(total([mi * (xi - c).cross(vi) for mi, xi, vi in zip(ms, xs, vs)]).diff(t) - tau_c))
assert nzero(total([mi * (xi - c) for mi, xi in zip(ms, xs)]))
check(64, nzero(total([mi * (xi - c).cross(vi - vc) for mi, xi, vi in zip(ms, xs, vs)]).diff(t) - tau_c))

# 72, 82, 89, 95, 102: a rigid body, x_i = c(t) + R(t) s_i with R from three angles; the angles, the
# centre's path, the masses and the body-frame points are given concrete values (the identities hold for
# any, and numbers keep the derivatives small)
phi, th, psi = sp.sin(t) + t / 3, 1 + t ** 2 / 5, 2 * t - sp.cos(t)
R = Rz(phi) * Rx(th) * Rz(psi)
W = R.diff(t) * R.T
om = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])
mr = {m1: 1, m2: 2}
s = [sp.Matrix([1, 2, 3]), sp.Matrix([-sp.Rational(1, 2), -1, -sp.Rational(3, 2)])]
# the body's points about c: their first moment m1 s1 + m2 s2 vanishes
assert zero(s[0] * mr[m1] + s[1] * mr[m2])
cb = sp.Matrix([sp.cos(t), t ** 3 / 4, sp.sin(2 * t)])
rel = [R * si for si in s]
xb = [cb + ri for ri in rel]
E = sp.eye(3)
msr = [mr[m1], mr[m2]]
Ic = total([mi * ((ri.T * ri)[0] * E - ri * ri.T) for mi, ri in zip(msr, rel)])
# 72: v - v_c = omega x (x - c); the triple product; then the text's last member I^c omega drops d/dt
first = [xi.diff(t) - cb.diff(t) - om.cross(ri) for xi, ri in zip(xb, rel)]
assert all(nzero(e) for e in first)
trip = total([mi * ((ri.T * ri)[0] * om - (ri.T * om)[0] * ri) for mi, ri in zip(msr, rel)])
assert nzero(total([mi * ri.cross(om.cross(ri)) for mi, ri in zip(msr, rel)]) - trip)
assert nzero(trip - Ic * om)
# the display's last member: I^c omega, where the chain holds d/dt (I^c omega)
check(72, nzero(trip.diff(t) - Ic * om))
# 82: the definition of the inertia tensor: not a claim
# 89: I^c(t) = R(t) I^c(0) R(t)^T, with I^c(0) built from the body-frame s_i
I0 = total([mi * ((si.T * si)[0] * E - si * si.T) for mi, si in zip(msr, s)])
check(89, nzero(Ic - R * I0 * R.T))
# 95: tau_c = d/dt (I^c omega) = omega x (I^c omega) + I^c d omega/dt
J = sp.Matrix([[3, 1, -1], [1, 2, sp.Rational(1, 2)], [-1, sp.Rational(1, 2), 4]])   # a general I^c(0)
Iw = R * J * R.T
check(95, nzero((Iw * om).diff(t) - (om.cross(Iw * om) + Iw * om.diff(t))))
# 102: d/dt (m v_c) = f (the total force, sum of m_i f_i), and the torque balance of 95
check(102, nzero((M * vc).diff(t) - total([mi * fi for mi, fi in zip(ms, fs)])) and CHECKS[95])
# 113: the explicit step, a scheme: not a claim

# quaternions, scalar first
Q = sp.Quaternion
dt = sp.Symbol('Delta_t', positive=True)
wx, wy, wz = sp.symbols('omega_x omega_y omega_z', positive=True)
nw = sp.sqrt(wx ** 2 + wy ** 2 + wz ** 2)
q = Q(*sp.symbols('q0:4', real=True))


def qv(a):
    return sp.Matrix([a.a, a.b, a.c, a.d])


wq = Q(0, wx, wy, wz)
expo = Q(0, dt / 2 * wx, dt / 2 * wy, dt / 2 * wz).exp()
bracket = Q(sp.cos(nw * dt / 2) - 1, wx / nw * sp.sin(nw * dt / 2), wy / nw * sp.sin(nw * dt / 2),
            wz / nw * sp.sin(nw * dt / 2))
# 127: e^{dt/2 omega} q - q = (cos - 1 + omega/|omega| sin) q, and the bracket is Theta(dt^2) + dt/2 omega
diff2 = qv(bracket) - qv(Q(0, dt / 2 * wx, dt / 2 * wy, dt / 2 * wz))
ser = sp.Matrix([sp.series(e, dt, 0, 3).removeO() for e in diff2])
check(127, zero(qv(expo * q - q) - qv(bracket * q))
      and zero(ser.subs(dt, 0)) and zero(ser.diff(dt).subs(dt, 0)) and not zero(ser.diff(dt, 2)))
# 137: (q~ - q)/dt tends to 1/2 w q, w the pure quaternion of omega
lim = sp.Matrix([sp.series(e / dt, dt, 0, 1).removeO() for e in qv(expo * q - q)])
check(137, zero(lim - qv(wq * q) / 2))
# 147: e^{theta/2 u} = cos(theta/2) + u sin(theta/2) for a unit u
al, be, thq = sp.symbols('alpha beta theta', positive=True)
u = (sp.sin(al) * sp.cos(be), sp.sin(al) * sp.sin(be), sp.cos(al))
eu = Q(0, *(thq / 2 * ui for ui in u)).exp()
check(147, zero(qv(eu) - sp.Matrix([sp.cos(thq / 2)] + [ui * sp.sin(thq / 2) for ui in u])))

LINES = [18, 27, 40, 47, 57, 64, 72, 82, 89, 95, 102, 113, 127, 137, 147]
NC, H_ = "not a claim", "holds"
ROWS = {
    18: (NC, "Newton's second law for one particle, stated"),
    27: (H_, "the product rule, v x v = 0 and f = m dv/dt (check 27)"),
    40: (NC, "the particle law summed over the body, stated"),
    47: (H_, "d/dt of c x (total momentum) = (dc/dt) x M v_c + c x (total force) and v_c x M v_c = 0 (check 47)"),
    57: (H_, "the difference of the two statements before it (check 57)"),
    64: (H_, "the term with v_c drops since the first moment of the mass about c vanishes (check 64)"),
    72: ("typo",
         "the first two steps hold (v - v_c = omega x (x - c), the triple product) and the integral is I^c omega, but "
         "the last member writes I^c omega where the chain holds d/dt of it: the d/dt of the members before is "
         "dropped (the next display differentiates I^c omega to get the torque) (check 72)",
         "\\frac{d}{dt}\\left(\\mathbf{I}_{\\mathcal{B}}^{\\bm{c}} \\bm{\\omega}\\right)",
         "By hand: the middle member is d/dt of the integral of rho (|r|^2 omega - (r . omega) r), r = x - c, and that "
         "integral is I^c omega by the definition of I^c given next; so the member is d/dt (I^c omega), which is "
         "omega x (I^c omega) + I^c d omega/dt, not I^c omega.",
         "Numbers: a body momentarily at rest (omega = 0 at time t) but starting to turn, d omega/dt = (0, 0, 1), with "
         "I^c = diag(1, 1, 1): the members before the last give d/dt (I^c omega) = (0, 0, 1), the last gives I^c omega "
         "= 0."),
    82: (NC, "defines the inertia tensor about the centre of mass"),
    89: (H_, "x - c = R (x0 - c0), so the integrand is R (|r0|^2 1 - r0 r0^T) R^T (check 89)"),
    95: (H_, "d/dt (R I0 R^T omega) with dR/dt = [omega]x R gives omega x (I omega) + I d omega/dt (check 95)"),
    102: (H_, "the total force changes the total momentum M v_c, and the torque balance of the display before (check 102)"),
    113: (NC, "the explicit integrator, a scheme (its angular step uses d omega/dt = I^-1 (tau - omega x I omega))"),
    127: (H_, "the exponential of the pure quaternion dt/2 omega is cos(|omega| dt/2) + omega/|omega| sin(|omega| dt/2), "
               "and cos - 1 is of order dt^2 while the sine term is dt/2 omega to first order (check 127)"),
    137: (H_, "dividing by dt and letting dt go to 0 leaves 1/2 omega q, omega taken as a pure quaternion (check 137)"),
    147: (H_, "the exponential of a pure quaternion theta/2 u with |u| = 1 (check 147)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
