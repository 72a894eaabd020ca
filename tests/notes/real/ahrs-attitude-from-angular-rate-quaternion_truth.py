"""Independent SymPy truth table for ahrs-attitude-from-angular-rate-quaternion.md.

The text's own setting: quaternions scalar first, q = (q_w, q_x, q_y, q_z), multiplied by Hamilton's
product; a vector is the pure quaternion (0, v). The angular velocity omega = (w_x, w_y, w_z) is the
body's, in body (sensor) components, as a gyroscope gives it; a unit attitude quaternion q turns body
components into reference ones, R(q) v_body = v_ref, so the body rate obeys dR/dt = R [omega]x and
q' = 1/2 q (0, omega). The text's own notation floor(x)_x is the matrix it defines (rows (0, x_2, -x_1),
(-x_2, 0, x_0), (x_1, -x_0, 0)). Every check is built here from these definitions, never from the text's
later displays.
"""
import random
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero


def qmul(a, b):
    """Hamilton's product of two quaternions (scalar first), as 4-vectors."""
    a0, av = a[0], sp.Matrix(a[1:])
    b0, bv = b[0], sp.Matrix(b[1:])
    v = a0 * bv + b0 * av + av.cross(bv)
    return sp.Matrix([a0 * b0 - av.dot(bv), *v])


def pure(v):
    return sp.Matrix([0, *v])


def rot(q):
    """The rotation matrix of a unit quaternion: R v = vect(q (0, v) q*)."""
    w, x, y, z = q
    return sp.Matrix([[w**2 + x**2 - y**2 - z**2, 2 * (x * y - w * z), 2 * (x * z + w * y)],
                      [2 * (x * y + w * z), w**2 - x**2 + y**2 - z**2, 2 * (y * z - w * x)],
                      [2 * (x * z - w * y), 2 * (y * z + w * x), w**2 - x**2 - y**2 + z**2]])


def skew(v):
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


th, dt, t = sp.symbols("theta Delta_t t", positive=True)
wx, wy, wz = sp.symbols("omega_x omega_y omega_z", real=True)
qw, qx, qy, qz = sp.symbols("q_w q_x q_y q_z", real=True)
om = sp.Matrix([wx, wy, wz])
nw = sp.sqrt(wx**2 + wy**2 + wz**2)
q = sp.Matrix([qw, qx, qy, qz])
ux, uy = sp.symbols("u_x u_y", real=True)
u = sp.Matrix([0, ux, uy, sp.sqrt(1 - ux**2 - uy**2)])          # a pure unit quaternion
one = sp.Matrix([1, 0, 0, 0])

# 24: the definition of the exponential as a power series: not a claim

# 32: e^{u theta} = (1 - theta^2/2! + theta^4/4! ...) + (u theta - u theta^3/3! + u theta^5/5! ...):
# the partial sums of the series in powers of the pure unit quaternion u theta, to order 7
partial, power = sp.zeros(4, 1), one
for k in range(8):
    partial += power / sp.factorial(k)
    power = qmul(power, u * th)
text_series = one * (1 - th**2 / 2 + th**4 / 24 - th**6 / 720) + u * (th - th**3 / 6 + th**5 / 120 - th**7 / 5040)
check(32, zero(partial - text_series))
# 40: q = e^v = (cos theta/2, u sin theta/2): e^v sums to cos theta + u sin theta (u^2 = -1), the
# half angle is e^{v/2}
ev = one * sp.cos(th) + u * sp.sin(th)
assert zero(sp.Matrix([sp.series(ev[k] - partial[k], th, 0, 8).removeO() for k in range(4)]))
half = one * sp.cos(th / 2) + u * sp.sin(th / 2)
check(40, zero(ev - half))
assert zero(one * sp.cos(th / 2) + u * sp.sin(th / 2) - half)               # the correction: e^{v/2}

# 59: Delta q with u = omega/|omega| and theta = |omega| dt
dq = one * sp.cos(nw * dt / 2) + pure(om / nw) * sp.sin(nw * dt / 2)
check(59, zero(dq - (one * sp.cos(th / 2) + pure(om / nw) * sp.sin(th / 2)).subs(th, nw * dt)))
# 69: with q(t + dt) = Delta q q(t): (Delta q - 1) q, and cos x - 1 = -2 sin^2(x/2)
diff_q = qmul(dq, q) - q
row2 = qmul(one * (-2 * sp.sin(nw * dt / 4) ** 2) + pure(om / nw) * sp.sin(nw * dt / 2), q)
check(69, zero(diff_q - row2))
# 79: the limit of (q(t+dt) - q(t))/dt is 1/2 omega q; the last row's column is 1/2 q omega instead
qdot_left = sp.Matrix([sp.limit(diff_q[k] / dt, dt, 0) for k in range(4)])
left, right = qmul(pure(om), q) / 2, qmul(q, pure(om)) / 2
col = sp.Matrix([-wx * qx - wy * qy - wz * qz, wx * qw + wz * qy - wy * qz,
                 wy * qw - wz * qx + wx * qz, wz * qw + wy * qx - wx * qy]) / 2
assert zero(qdot_left - left)                       # rows 1-5: 1/2 omega q
assert zero(col - right)                            # row 6: 1/2 q omega
check(79, zero(left - col))
# 101: Omega(omega) = [[0, -omega^T], [omega, floor(omega)_x]] with the text's floor(x)_x, written out
flo = sp.Matrix([[0, wz, -wy], [-wz, 0, wx], [wy, -wx, 0]])   # rows (0, x2, -x1), (-x2, 0, x0), (x1, -x0, 0)
Om = sp.zeros(4, 4)
Om[0, 1:] = -om.T
Om[1:, 0] = om
Om[1:, 1:] = flo
Om_text = sp.Matrix([[0, -wx, -wy, -wz], [wx, 0, wz, -wy], [wy, -wz, 0, wx], [wz, wy, -wx, 0]])
check(101, zero(Om - Om_text))
# 114: the text's definition of floor(x)_x: not a claim
# 122: q' = 1/2 Omega(omega) q is the body-rate kinematics: Omega q = q (0, omega), and then
# dR(q)/dt = R(q) [omega]x on unit quaternions
qd = Om_text * q / 2
Rdot = sp.Matrix(3, 3, lambda i, j: sum(sp.diff(rot(q)[i, j], s) * qd[k] for k, s in enumerate(q)))
unit = {qw: sp.sqrt(1 - qx**2 - qy**2 - qz**2)}
check(122, zero(qd - right) and zero((Rdot - rot(q) * skew(om)).subs(unit)))
# 130: the Taylor series of q(t + dt) about t, to third order, for a smooth q(t)
rng = random.Random(7)
W = sp.Matrix([sp.Rational(rng.randint(-9, 9), 7) for _ in range(3)])
Wn = sp.Matrix([[0, -W[0], -W[1], -W[2]], [W[0], 0, W[2], -W[1]], [W[1], -W[2], 0, W[0]], [W[2], W[1], -W[0], 0]])
q0 = sp.Matrix([sp.Rational(rng.randint(1, 9), 5) for _ in range(4)])
f = sp.Matrix([sp.sin(t), sp.exp(2 * t), sp.cos(3 * t), t**3])          # any smooth q(t)
taylor = sum((f.diff(t, k) * dt**k / sp.factorial(k) for k in range(4)), sp.zeros(4, 1))
exact = sp.Matrix([sp.series(f.subs(t, t + dt)[k], dt, 0, 4).removeO() for k in range(4)])
check(130, zero(sp.expand(sp.expand_trig(exact - taylor))))


def third_order(O0, O1, O2, q0):
    """Terms to dt^3 of the solution of q' = 1/2 Omega(t) q with Omega(t) = O0 + O1 t + O2 t^2/2."""
    d1 = O0 * q0 / 2
    d2 = O1 * q0 / 2 + O0 * d1 / 2
    d3 = O2 * q0 / 2 + O1 * d1 + O0 * d2 / 2
    return q0 + d1 * dt + d2 * dt**2 / 2 + d3 * dt**3 / 6


def rmat():
    return sp.Matrix(4, 4, lambda i, j: sp.Rational(rng.randint(-9, 9), 4))


O0, O1, O2 = rmat(), rmat(), rmat()
half_O = O0 * dt / 2
text138 = ((sp.eye(4) + half_O + half_O**2 / 2 + half_O**3 / 6) * q0 + O1 * dt**2 * q0 / 4
           + (O1 * O0 / 12 + O0 * O1 / 24 + O2 / 12) * dt**3 * q0)
check(138, zero(sp.expand(third_order(O0, O1, O2, q0) - text138)))
# 154: the same with Omega constant (O1 = O2 = 0)
text154 = (sp.eye(4) + half_O + half_O**2 / 2 + half_O**3 / 6) * q0
check(154, zero(sp.expand(third_order(O0, sp.zeros(4, 4), sp.zeros(4, 4), q0) - text154)))
# 163: the bracket is the exponential's series: sum_k (dt/2 Omega)^k / k! against the exponential
ser = sum(((Wn / 2) ** k / sp.factorial(k) for k in range(30)), sp.zeros(4, 4))
check(163, max(abs(float(e)) for e in (ser - (Wn / 2).exp()).evalf(30)) < 1e-20)
# 170, 177: the first-order update the package keeps and its normalisation: not claims
# 184, 190: for constant omega, q(t + dt) = exp(1/2 Omega dt) q(t) = [cos(|w| dt/2) I + sin(|w| dt/2)/|w| Omega] q(t):
# the bracket is I at dt = 0 and obeys X' = 1/2 Omega X (Omega^2 = -|w|^2 I)
X = sp.cos(nw * dt / 2) * sp.eye(4) + sp.sin(nw * dt / 2) / nw * Om_text
assert zero(Om_text**2 + nw**2 * sp.eye(4))
ode = zero(X.diff(dt) - Om_text * X / 2) and zero(X.subs(dt, 0) - sp.eye(4))
check(184, ode)
check(190, ode)
# 207: q' = 1/2 q w, q'' = 1/4 q w^2 + 1/2 q w', q''' = 1/8 q w^3 + 1/4 q w' w + 1/2 q w w' (w'' = 0);
# the text's 1/6 for 1/8
w0 = pure(sp.Matrix([sp.Rational(rng.randint(-9, 9), 3) for _ in range(3)]))
w1 = pure(sp.Matrix([sp.Rational(rng.randint(-9, 9), 3) for _ in range(3)]))
p = sp.Matrix([sp.Rational(rng.randint(1, 9), 3) for _ in range(4)])
d1 = qmul(p, w0) / 2
d2 = qmul(d1, w0) / 2 + qmul(p, w1) / 2
d3 = qmul(d2, w0) / 2 + qmul(d1, w1)                     # w'' = 0
ww = qmul(w0, w0)
row2_ok = zero(d2 - (qmul(p, ww) / 4 + qmul(p, w1) / 2))
row3 = lambda c: qmul(p, qmul(ww, w0)) * c + qmul(p, qmul(w1, w0)) / 4 + qmul(p, qmul(w0, w1)) / 2  # noqa: E731
assert row2_ok and zero(d3 - row3(sp.Rational(1, 8)))
check(207, row2_ok and zero(d3 - row3(sp.Rational(1, 6))))

# negative controls: the checks above can fail
assert not zero(qdot_left - right)
assert not zero(sp.expand(third_order(O0, O1, O2, q0) - text154))

LINES = [24, 32, 40, 59, 69, 79, 101, 114, 122, 130, 138, 154, 163, 170, 177, 184, 190, 207]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
