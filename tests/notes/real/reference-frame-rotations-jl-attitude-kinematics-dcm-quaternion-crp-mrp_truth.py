"""Independent SymPy truth table for reference-frame-rotations-jl-attitude-kinematics-dcm-quaternion-crp-mrp.md.

The manual's convention: a rotation by theta about the unit Euler axis w brings frame A into alignment
with frame B, so B's basis vectors are b_i = Rod(w, theta) a_i (Rodrigues's matrix, in A's components);
a vector's components in B are v_b = D v_a with D the direction cosine matrix whose rows are the b_i in
A's components. The angular velocity of B relative to A is the omega with db_i/dt = omega x b_i (seen
from A), and omega_b are its components in B. Quaternions multiply by Hamilton's product; the CRP is
the quaternion's vector part over its real part and the MRP its vector part over one plus its real
part (the manual's own descriptions), which give e tan(phi/2) and e tan(phi/4).
"""
import random
import sys

import sympy as sp

import truth_table

CHECKS = {}
zero = truth_table.zero


def check(key, ok):
    CHECKS[key] = bool(ok)


def qmul(x, y):
    x0, xv = x[0], sp.Matrix(x[1:])
    y0, yv = y[0], sp.Matrix(y[1:])
    vv = x0 * yv + y0 * xv + xv.cross(yv)
    return [x0 * y0 - xv.dot(yv), vv[0], vv[1], vv[2]]


def qinv(x):
    n2 = sum(c**2 for c in x)
    return [x[0] / n2, -x[1] / n2, -x[2] / n2, -x[3] / n2]


def vect(x):
    return sp.Matrix(x[1:])


def skew(v):
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


# 28: v_b = vect(q^-1 v_a q) with q = cos(theta/2) + sin(theta/2) w, for a unit axis w
wx, wy, th = sp.symbols('w_x w_y theta', real=True)
wz = sp.sqrt(1 - wx**2 - wy**2)
w = sp.Matrix([wx, wy, wz])
q = [sp.cos(th / 2), wx * sp.sin(th / 2), wy * sp.sin(th / 2), wz * sp.sin(th / 2)]
rod = sp.eye(3) * sp.cos(th) + sp.sin(th) * skew(w) + (1 - sp.cos(th)) * w * w.T
va = sp.Matrix(sp.symbols('v_1:4', real=True))
vb_true = rod.T * va                       # components along b_i = rod a_i
check(28, zero(vect(qmul(qmul(qinv(q), [0, *va]), q)) - vb_true))

# the kinematics, by numbers: a unit quaternion of time q = q_z(alpha) q_y(beta) q_x(gamma), each angle a
# random value plus a random rate times t, everything evaluated at t = 0
t = sp.Symbol('t')


def qaxis(ang, k):
    e = [0, 0, 0]
    e[k] = sp.sin(ang / 2)
    return [sp.cos(ang / 2), *e]


def small(expr):
    m = expr if hasattr(expr, 'shape') else sp.Matrix([expr])
    return all(abs(complex(sp.N(x.subs(t, 0)))) < 1e-9 for x in m)


rng = random.Random(11)
ok = {75: True, 100: True, 126: True, 151: True}
for _ in range(4):
    al, be, ga = (sp.Float(rng.uniform(-3, 3)) + sp.Float(rng.uniform(-2, 2)) * t for _ in range(3))
    qt = qmul(qmul(qaxis(al, 2), qaxis(be, 1)), qaxis(ga, 0))
    # D: v_b = D v_a, from the frame change checked above; its rows are the b_i in A's components
    D = sp.Matrix.hstack(*[vect(qmul(qmul(qinv(qt), [0, *sp.eye(3)[:, k]]), qt)) for k in range(3)])
    E = D.T                                # columns: b_i in A's components
    Wa = E.diff(t) * E.T                   # [omega_a x] from db_i/dt = omega_a x b_i
    assert small(Wa + Wa.T)
    om_b = D * sp.Matrix([Wa[2, 1], Wa[0, 2], Wa[1, 0]])
    # 75: dD/dt = -[omega_b x] D
    ok[75] &= small(D.diff(t) + skew(om_b) * D)
    # 100: dq/dt = (1/2) Omega(omega_b) q
    ox, oy, oz = om_b
    Om = sp.Matrix([[0, -ox, -oy, -oz], [ox, 0, oz, -oy], [oy, -oz, 0, ox], [oz, oy, -ox, 0]])
    Q = sp.Matrix(qt)
    ok[100] &= small(Q.diff(t) - Om * Q / 2)
    # 126: the CRP c = q_v / q0, dc/dt = (omega + c x omega + (c . omega) c) / 2
    c = vect(qt) / qt[0]
    ok[126] &= small(c.diff(t) - (om_b + c.cross(om_b) + c.dot(om_b) * c) / 2)
    # 151: the MRP m = q_v / (1 + q0), dm/dt = ((1 - |m|^2) omega + 2 m x omega + 2 (m . omega) m) / 4
    m = vect(qt) / (1 + qt[0])
    ok[151] &= small(m.diff(t) - ((1 - m.dot(m)) * om_b + 2 * m.cross(om_b) + 2 * m.dot(om_b) * m) / 4)
for key, good in ok.items():
    check(key, good)
# the quotients used above are the manual's e tan(phi/2) and e tan(phi/4) for q = (cos(phi/2), e sin(phi/2))
for x in (0.3, 1.7, 2.9):
    assert abs(sp.N(sp.sin(x / 2) / sp.cos(x / 2) - sp.tan(x / 2))) < 1e-12
    assert abs(sp.N(sp.sin(x / 2) / (1 + sp.cos(x / 2)) - sp.tan(x / 4))) < 1e-12

LINES = [19, 28, 42, 51, 64, 75, 89, 100, 115, 126, 140, 151]

ROWS = {
    19: ("not a claim", "the quaternion built from the Euler axis and angle (defined)"),
    28: ("holds", "with b_i = Rod(w, theta) a_i, v_b = Rod^T v_a, and vect(q^-1 v_a q) gives the same (check 28)"),
    42: ("not a claim", "defines the CRP as e tan(phi/2)"),
    51: ("not a claim", "defines the MRP as e tan(phi/4)"),
    64: ("not a claim", "names the components of the angular velocity of B relative to A in B"),
    75: ("holds", "the DCM's rows are B's basis vectors in A, each turning as db/dt = omega x b, which gives "
         "dD/dt = -[omega_b x] D (check 75, by numbers)"),
    89: ("not a claim", "names the components of the angular velocity (repeated)"),
    100: ("holds", "dq/dt = (1/2) q (0, omega_b): the displayed 4x4 matrix times q (check 100, by numbers)"),
    115: ("not a claim", "names the components of the angular velocity (repeated)"),
    126: ("holds", "differentiating c = q_v/q0 with the quaternion's rate gives (omega + c x omega + (c . omega) c)/2 "
          "(check 126, by numbers)"),
    140: ("not a claim", "names the components of the angular velocity (repeated)"),
    151: ("holds", "differentiating m = q_v/(1 + q0) gives ((1 - |m|^2) omega + 2 m x omega + 2 (m . omega) m)/4 "
          "(check 151, by numbers)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
