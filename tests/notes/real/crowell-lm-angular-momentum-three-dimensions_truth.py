"""Independent SymPy truth table for crowell-lm-angular-momentum-three-dimensions.tex.

The text's own setting: vectors in a right-handed Cartesian frame (x, y, z); a system of
particles i with masses m_i at r_i; a rigid rotation with angular velocity omega about the origin,
so v_i = omega x r_i; L = sum r_i x p_i, torque = sum r_i x F_i with dp_i/dt = F_i; the moment of
inertia matrix I_jk of L_j = sum_k I_jk omega_k; K = sum m_i v_i^2 / 2. The shoe in flight is
torque-free. Small rotations compose to first order as vectors (the text's 10-degree example).
Every check is built here from these definitions, never from the text's later displays.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero


def rot(axis, a):
    c, s = sp.cos(a), sp.sin(a)
    if axis == "x":
        return sp.Matrix([[1, 0, 0], [0, c, -s], [0, s, c]])
    return sp.Matrix([[c, 0, s], [0, 1, 0], [-s, 0, c]])


# 45: two small turns eps about x then about y equal, to first order in eps, one turn by eps x + eps y
eps = sp.symbols("epsilon", positive=True)
Rxy = rot("y", eps) * rot("x", eps)
n = sp.Matrix([1, 1, 0])
K = sp.Matrix([[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]])
first = (sp.eye(3) + eps * K)                              # the turn by the vector eps (x + y) to first order
diff1 = (Rxy - first).applyfunc(lambda e: sp.series(e, eps, 0, 2).removeO())
tendeg = 10 * sp.pi / 180
check(45, zero(diff1) and abs(float(sp.sqrt(2) * 10) - 14) < 0.5)   # |(10 deg, 10 deg)| = 14 deg as printed

A = sp.Matrix(sp.symbols("A_x A_y A_z", real=True))
B = sp.Matrix(sp.symbols("B_x B_y B_z", real=True))
# 57: A x B = -B x A
check(57, zero(A.cross(B) + B.cross(A)))
# 61: the components
AB = A.cross(B)
check(61, zero(AB - sp.Matrix([A[1] * B[2] - B[1] * A[2], A[2] * B[0] - B[2] * A[0], A[0] * B[1] - B[0] * A[1]])))

# 70: v = omega x r for a rigid rotation R(t) about the origin; L = r x p and tau = r x F define L and tau
t = sp.symbols("t", real=True)
th = sp.Function("theta")(t)
Rz = sp.Matrix([[sp.cos(th), -sp.sin(th), 0], [sp.sin(th), sp.cos(th), 0], [0, 0, 1]])
r0 = sp.Matrix(sp.symbols("a b c", real=True))
r = Rz * r0
check(70, zero(r.diff(t) - sp.Matrix([0, 0, th.diff(t)]).cross(r)))

# 82: r = (4, 5, 0) m, F = (1, 2, 3) N: tau = (15, -12, 3) N m, each row's middle form as written
rv, Fv = sp.Matrix([4, 5, 0]), sp.Matrix([1, 2, 3])
tau = rv.cross(Fv)
rows = [rv[1] * Fv[2] - Fv[1] * rv[2], rv[2] * Fv[0] - Fv[2] * rv[0], rv[0] * Fv[1] - Fv[0] * rv[1]]
check(82, list(tau) == [15, -12, 3] and rows == [15, -12, 3])

# particles: r_i(t), p_i = m_i dr_i/dt, dp_i/dt = F_i
N = 2
m = sp.symbols(f"m_1:{N + 1}", positive=True)
ri = [sp.Matrix([sp.Function(f"{c}_{i}")(t) for c in "xyz"]) for i in range(1, N + 1)]
pi = [m[i] * ri[i].diff(t) for i in range(N)]
L = sum((ri[i].cross(pi[i]) for i in range(N)), sp.zeros(3, 1))
Fi = [pi[i].diff(t) for i in range(N)]
# 93: tau = dL/dt = d/dt sum r x p = sum d/dt (r x p)
check(93, zero(L.diff(t) - sum((ri[i].cross(pi[i]).diff(t) for i in range(N)), sp.zeros(3, 1))))
# 99: the product rule
check(99, zero(L.diff(t) - sum((ri[i].diff(t).cross(pi[i]) + ri[i].cross(pi[i].diff(t)) for i in range(N)),
                               sp.zeros(3, 1))))
# 107: tau = sum r_i x F_i
check(107, zero(L.diff(t) - sum((ri[i].cross(Fi[i]) for i in range(N)), sp.zeros(3, 1))))

# rigid rotation: v_i = omega x r_i
w = sp.Matrix(sp.symbols("omega_x omega_y omega_z", real=True))
rs = [sp.Matrix(sp.symbols(f"x_{i} y_{i} z_{i}", real=True)) for i in range(1, N + 1)]
vs = [w.cross(rs[i]) for i in range(N)]
Lr = sum((rs[i].cross(m[i] * vs[i]) for i in range(N)), sp.zeros(3, 1))
# 115: L = sum r x p = sum m r x v = sum m r x (omega x r)
check(115, zero(Lr - sum((m[i] * rs[i].cross(w.cross(rs[i])) for i in range(N)), sp.zeros(3, 1))))
# 121: L_j = sum_k I_jk omega_k with I_jk = sum m (r^2 delta_jk - x_j x_k), independent of omega
I = sum((m[i] * ((rs[i].T * rs[i])[0] * sp.eye(3) - rs[i] * rs[i].T) for i in range(N)), sp.zeros(3, 3))
check(121, zero(Lr - I * w) and all(sp.diff(I[j, k], s) == 0 for j in range(3) for k in range(3) for s in w))
# 128: in principal axes I is diagonal, L_j = I_jj omega_j: a symmetric real matrix has an orthonormal eigenbasis
I_num = I.subs({s: v for s, v in zip(list(m) + list(rs[0]) + list(rs[1]), [1, 2, 1, 2, 3, -1, 0, 2])})
P, Dg = I_num.diagonalize(normalize=True)
check(128, zero(P.T * I_num * P - Dg) and zero(P.T * P - sp.eye(3)))
# 137: K = sum m v^2 / 2 = 1/2 sum m (omega x r).(omega x r)
Kin = sum((m[i] * vs[i].dot(vs[i]) for i in range(N))) / 2
check(137, sp.simplify(Kin - sum((m[i] * w.cross(rs[i]).dot(w.cross(rs[i])) for i in range(N))) / 2) == 0)
# 143: = 1/2 sum m [r x (omega x r)] . omega = 1/2 omega . sum m r x (omega x r) = 1/2 L . omega
k1 = sum((m[i] * rs[i].cross(w.cross(rs[i])).dot(w) for i in range(N))) / 2
check(143, sp.simplify(Kin - k1) == 0 and sp.simplify(Kin - Lr.dot(w) / 2) == 0)
# 154, 158: torque-free in principal axes: |L|^2 and 2K = sum L_j^2 / I_jj are constant along Euler's equations
I1, I2, I3 = sp.symbols("I_xx I_yy I_zz", positive=True)
W = sp.Matrix([sp.Function(f"w{j}")(t) for j in range(3)])
Id = sp.diag(I1, I2, I3)
wdot = Id.inv() * (-(W.cross(Id * W)))
Lb = Id * W
sub = {W[j].diff(t): wdot[j] for j in range(3)}
check(154, sp.simplify((Lb.dot(Lb)).diff(t).subs(sub)) == 0)
check(158, sp.simplify((Lb[0] ** 2 / I1 + Lb[1] ** 2 / I2 + Lb[2] ** 2 / I3).diff(t).subs(sub)) == 0
      and sp.simplify(Lb[0] ** 2 / I1 + Lb[1] ** 2 / I2 + Lb[2] ** 2 / I3 - Lb.dot(W)) == 0)

# negative controls: the checks above can fail
assert not zero(A.cross(B) - B.cross(A))
assert sp.simplify(Kin - Lr.dot(w)) != 0
assert sp.simplify((Lb[0] ** 2 * I1 + Lb[1] ** 2 * I2 + Lb[2] ** 2 * I3).diff(t).subs(sub)) != 0

LINES = [45, 57, 61, 70, 82, 93, 99, 107, 115, 121, 128, 137, 143, 154, 158]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
