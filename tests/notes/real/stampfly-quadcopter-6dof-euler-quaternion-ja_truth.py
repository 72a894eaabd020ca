"""Independent SymPy truth table for stampfly-quadcopter-6dof-euler-quaternion-ja.md.

The document's convention: both frames are north-east-down; R is the rotation matrix from the body
frame to the inertial frame (it says so twice, and uses it as dx/dt = R V_B); the Euler angles are the
Z-Y-X (yaw psi, then pitch theta, then roll phi) sequence, each turn about the axis the previous one
produced; its elementary matrices R_x, R_y, R_z are the active rotations it displays. So the body-to-
inertial matrix is R_z(psi) R_y(theta) R_x(phi), and the body angular velocity (p, q, r) is read off
R^T dR/dt. The quaternion (scalar q0 first) turns a body vector into its inertial components as
q v q*, Hamilton's product; it is built here from its own product, not from the document's matrices.
"""
import random
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Ry, Rz

CHECKS = {}
zero = truth_table.zero


def check(key, ok):
    CHECKS[key] = bool(ok)


t = sp.Symbol('t')
phi, th, psi = (sp.Function(n)(t) for n in ('phi', 'theta', 'psi'))


R = Rz(psi) * Ry(th) * Rx(phi)                        # body -> inertial for the Z-Y-X sequence
W = sp.simplify(R.T * R.diff(t))                      # [omega x] in body components
assert zero(W + W.T)
p_, q_, r_ = W[2, 1], W[0, 2], W[1, 0]
om = sp.Matrix([p_, q_, r_])

# 30: m (dV_B/dt + omega x V_B) = F_B, from m d(R V_B)/dt = R F_B
V = sp.Matrix([sp.Function(n)(t) for n in ('u', 'v', 'w')])
check(30, zero(R.T * (R * V).diff(t) - (V.diff(t) + om.cross(V))))
# 38, 48, 58: the components, the solved form and the matrix form of the same equation
p, q, r, u, v, w, m = sp.symbols('p q r u v w m')
Fx, Fy, Fz, ud, vd, wd = sp.symbols('F_x F_y F_z udot vdot wdot')
Om, Vs = sp.Matrix([p, q, r]), sp.Matrix([u, v, w])
law = m * (sp.Matrix([ud, vd, wd]) + Om.cross(Vs)) - sp.Matrix([Fx, Fy, Fz])
check(38, zero(law - (sp.Matrix([m * (ud + q * w - r * v), m * (vd + r * u - p * w), m * (wd + p * v - q * u)])
                      - sp.Matrix([Fx, Fy, Fz]))))
sol = sp.solve(list(law), [ud, vd, wd])
check(48, zero(sp.Matrix([sol[ud] - (Fx / m - q * w + r * v), sol[vd] - (Fy / m - r * u + p * w),
                          sol[wd] - (Fz / m - p * v + q * u)])))
skew = sp.Matrix([[0, -r, q], [r, 0, -p], [-q, p, 0]])
check(58, zero(sp.Matrix([sol[ud], sol[vd], sol[wd]]) - (sp.Matrix([Fx, Fy, Fz]) / m - skew * Vs)))
# 69: I d omega/dt + omega x (I omega) = tau, from d(R I omega)/dt = R tau (inertial angular momentum)
Ixx, Iyy, Izz, Ixy, Ixz, Iyz = sp.symbols('I_xx I_yy I_zz I_xy I_xz I_yz')
Ifull = sp.Matrix([[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]])
wb = sp.Matrix([sp.Function(n)(t) for n in ('p', 'q', 'r')])
# the body rates as functions of time stand for omega; R' = R [omega x] ties R to them
Rt = sp.Matrix(3, 3, lambda i, j: sp.Function(f'R{i}{j}')(t))
wsk = sp.Matrix([[0, -wb[2], wb[1]], [wb[2], 0, -wb[0]], [-wb[1], wb[0], 0]])
dH = (Rt * Ifull * wb).diff(t).subs({Rt[i, j].diff(t): (Rt * wsk)[i, j] for i in range(3) for j in range(3)})
check(69, zero(dH - Rt * (Ifull * wb.diff(t) + wb.cross(Ifull * wb))))
# 82, 92: the principal-axis components and their solved form
I = sp.diag(Ixx, Iyy, Izz)
pd, qd, rd, L, M, N = sp.symbols('pdot qdot rdot L M N')
eul = I * sp.Matrix([pd, qd, rd]) + Om.cross(I * Om) - sp.Matrix([L, M, N])
check(82, zero(eul - sp.Matrix([Ixx * pd + (Izz - Iyy) * q * r - L, Iyy * qd + (Ixx - Izz) * p * r - M,
                                Izz * rd + (Iyy - Ixx) * p * q - N])))
so = sp.solve(list(eul), [pd, qd, rd])
check(92, zero(sp.Matrix([so[pd] - (L - (Izz - Iyy) * q * r) / Ixx, so[qd] - (M - (Ixx - Izz) * p * r) / Iyy,
                          so[rd] - (N - (Iyy - Ixx) * p * q) / Izz])))
# 132: R = R_x(phi) R_y(theta) R_z(psi) with the displayed elementary matrices, as the body->inertial matrix
a, b, c = sp.symbols('phi theta psi', real=True)
Rs = Rz(c) * Ry(b) * Rx(a)
check(132, zero(Rx(a) * Ry(b) * Rz(c) - Rs))
# 152: the displayed composed matrix, labelled body -> inertial
ca, sa, cb, sb, cc, sc = sp.cos(a), sp.sin(a), sp.cos(b), sp.sin(b), sp.cos(c), sp.sin(c)
Rdisp = sp.Matrix([[cb * cc, cb * sc, -sb],
                   [sa * sb * cc - ca * sc, sa * sb * sc + ca * cc, sa * cb],
                   [ca * sb * cc + sa * sc, ca * sb * sc - sa * cc, ca * cb]])
check(152, zero(Rdisp - Rs))
# 166: the Euler rates from the body rates
T = sp.Matrix([[1, sp.sin(phi) * sp.tan(th), sp.cos(phi) * sp.tan(th)],
               [0, sp.cos(phi), -sp.sin(phi)],
               [0, sp.sin(phi) / sp.cos(th), sp.cos(phi) / sp.cos(th)]])
check(166, zero(T * om - sp.Matrix([phi.diff(t), th.diff(t), psi.diff(t)])))


# the quaternion's own algebra: Hamilton's product, rotation v -> q v q*
def qmul(x, y):
    x0, xv = x[0], sp.Matrix(x[1:])
    y0, yv = y[0], sp.Matrix(y[1:])
    s = x0 * y0 - xv.dot(yv)
    vv = x0 * yv + y0 * xv + xv.cross(yv)
    return [s, vv[0], vv[1], vv[2]]


def qmat(qq):
    conj = [qq[0], -qq[1], -qq[2], -qq[3]]
    cols = []
    for e in sp.eye(3).columns() if hasattr(sp.eye(3), 'columns') else [sp.eye(3)[:, k] for k in range(3)]:
        rot = qmul(qmul(qq, [0, e[0], e[1], e[2]]), conj)
        cols.append(sp.Matrix(rot[1:]))
    return sp.Matrix.hstack(*cols)


q0, q1, q2, q3 = sp.symbols('q_0:4', real=True)
Qs = [q0, q1, q2, q3]
unit = {q0: sp.sqrt(1 - q1**2 - q2**2 - q3**2)}
# 198: q = (cos(theta/2), n sin(theta/2)) turns vectors by theta about n (Rodrigues), for unit n
nx, ny, nz, ang = sp.symbols('n_x n_y n_z vartheta', real=True)
n = sp.Matrix([nx, ny, nz])
qa = [sp.cos(ang / 2), nx * sp.sin(ang / 2), ny * sp.sin(ang / 2), nz * sp.sin(ang / 2)]
K = sp.Matrix([[0, -nz, ny], [nz, 0, -nx], [-ny, nx, 0]])
rod = sp.eye(3) * sp.cos(ang) + sp.sin(ang) * K + (1 - sp.cos(ang)) * n * n.T
check(198, zero((qmat(qa) - rod).subs(nz, sp.sqrt(1 - nx**2 - ny**2))))
# 209: the displayed matrix of the quaternion is the rotation v -> q v q* (for a unit quaternion)
Rq = sp.Matrix([[q0**2 + q1**2 - q2**2 - q3**2, 2 * (q1 * q2 - q0 * q3), 2 * (q1 * q3 + q0 * q2)],
                [2 * (q1 * q2 + q0 * q3), q0**2 - q1**2 + q2**2 - q3**2, 2 * (q2 * q3 - q0 * q1)],
                [2 * (q1 * q3 - q0 * q2), 2 * (q2 * q3 + q0 * q1), q0**2 - q1**2 - q2**2 + q3**2]])
check(209, zero((Rq - qmat(Qs)).subs(unit)))
# 219: the quaternion of the Euler angles turns the body frame into the inertial one (R_z R_y R_x)
h = sp.Rational(1, 2)
qe = [sp.cos(a * h) * sp.cos(b * h) * sp.cos(c * h) + sp.sin(a * h) * sp.sin(b * h) * sp.sin(c * h),
      sp.sin(a * h) * sp.cos(b * h) * sp.cos(c * h) - sp.cos(a * h) * sp.sin(b * h) * sp.sin(c * h),
      sp.cos(a * h) * sp.sin(b * h) * sp.cos(c * h) + sp.sin(a * h) * sp.cos(b * h) * sp.sin(c * h),
      sp.cos(a * h) * sp.cos(b * h) * sp.sin(c * h) - sp.sin(a * h) * sp.sin(b * h) * sp.cos(c * h)]
check(219, zero(sp.expand_trig(sp.simplify(qmat(qe) - Rs))))
# 230: the angles back from the quaternion (principal ranges: |phi|, |psi| < pi, |theta| < pi/2), by numbers
rng = random.Random(7)
ok = True
for _ in range(20):
    va = {a: rng.uniform(-3.1, 3.1), b: rng.uniform(-1.5, 1.5), c: rng.uniform(-3.1, 3.1)}
    Q = [float(x.subs(va)) for x in qe]
    back = (sp.atan2(2 * (Q[0] * Q[1] + Q[2] * Q[3]), Q[0]**2 - Q[1]**2 - Q[2]**2 + Q[3]**2),
            sp.asin(2 * (Q[0] * Q[2] - Q[1] * Q[3])),
            sp.atan2(2 * (Q[0] * Q[3] + Q[1] * Q[2]), Q[0]**2 + Q[1]**2 - Q[2]**2 - Q[3]**2))
    ok &= all(abs(float(x) - va[s]) < 1e-9 for x, s in zip(back, (a, b, c)))
check(230, ok)
# 244: dq/dt = (1/2) Omega(p, q, r) q for the quaternion of time-varying angles, by numbers
qt = [x.subs({a: phi, b: th, c: psi}) for x in qe]
Omega = sp.Matrix([[0, -p_, -q_, -r_], [p_, 0, r_, -q_], [q_, -r_, 0, p_], [r_, q_, -p_, 0]])
res = sp.Matrix(qt).diff(t) - sp.Rational(1, 2) * Omega * sp.Matrix(qt)
ok = True
for _ in range(5):
    vals = {}
    for f in (phi, th, psi):
        vals[f.diff(t)] = rng.uniform(-2, 2)
    sub = {phi: rng.uniform(-3, 3), th: rng.uniform(-1.4, 1.4), psi: rng.uniform(-3, 3)}
    num = res.subs(vals).subs(sub)
    ok &= all(abs(complex(sp.N(x))) < 1e-10 for x in num)
check(244, ok)

LINES = [30, 38, 48, 58, 69, 76, 82, 92, 109, 132, 138, 142, 146, 152, 166, 186, 198, 209, 219, 230, 244, 262]

ROWS = {
    30: ("holds", "Newton's law in body components: R^T d(R V_B)/dt = dV_B/dt + omega x V_B with R body-to-inertial "
         "(check 30)"),
    38: ("holds", "omega x V_B = (qw - rv, ru - pw, pv - qu) (check 38)"),
    48: ("holds", "the component equations solved for u-dot, v-dot, w-dot (check 48)"),
    58: ("holds", "the matrix [[0, -r, q], [r, 0, -p], [-q, p, 0]] is omega's cross-product matrix (check 58)"),
    69: ("holds", "Euler's equation from d(R I omega)/dt = R tau with R' = R [omega x] (check 69)"),
    76: ("not a claim", "the inertia tensor taken diagonal, since the vehicle is symmetric (an assumption)"),
    82: ("holds", "omega x (I omega) for diagonal I has components (I_zz - I_yy) qr, (I_xx - I_zz) pr, "
         "(I_yy - I_xx) pq (check 82)"),
    92: ("holds", "the principal-axis equations solved for p-dot, q-dot, r-dot (check 92)"),
    109: ("not a claim", "defines how the inertial position is integrated: the body velocity turned by R, which the "
          "text defines as the body-to-inertial matrix"),
    132: ("fails", "for the Z-Y-X (yaw, then pitch, then roll about the new axes) sequence the body-to-inertial matrix, "
          "with the elementary matrices the text displays next, is R_z(psi) R_y(theta) R_x(phi); the display writes "
          "the factors in the opposite order (check 132)", "",
          "By hand: turning the body first by roll about its x axis, then by pitch about the once-turned y axis, then "
          "by yaw about the twice-turned z axis composes, for intrinsic turns, as R = R_z(psi) R_y(theta) R_x(phi) "
          "(each later turn about a carried axis multiplies on the right). R_x R_y R_z is that product's reverse, and "
          "it is not its transpose either (that would need R_x(-phi) R_y(-theta) R_z(-psi)), so it is neither the "
          "body-to-inertial nor the inertial-to-body matrix.",
          "Numbers: phi = 0, theta = 90 deg, psi = 90 deg (nose pitched straight up, NED): the body x axis in inertial "
          "components is R e_x; R_z R_y e_x = R_z (0, 0, -1) = (0, 0, -1), straight up, as a 90 deg pitch must give; "
          "the display's R_x R_y R_z e_x = R_y (0, 1, 0) = (0, 1, 0), level and pointing east."),
    138: ("not a claim", "the elementary rotation about x (defined)"),
    142: ("not a claim", "the elementary rotation about y (defined)"),
    146: ("not a claim", "the elementary rotation about z (defined)"),
    152: ("fails", "the matrix displayed is the transpose of the body-to-inertial matrix R_z(psi) R_y(theta) R_x(phi) "
          "that the text labels it as (it is the inertial-to-body direction cosine matrix), and it is not the product "
          "R_x R_y R_z of the displayed elementary matrices either (check 152)", "",
          "By hand: R_z(psi) R_y(theta) R_x(phi) has first row (c_theta c_psi, s_phi s_theta c_psi - c_phi s_psi, "
          "c_phi s_theta c_psi + s_phi s_psi), which is the display's first column; the display's first row "
          "(c_theta c_psi, c_theta s_psi, -s_theta) is that matrix's first column, so the display is its transpose.",
          "Numbers: pure yaw psi = 90 deg (phi = theta = 0): the nose (body x) turns from north to east, so the "
          "body-to-inertial matrix takes (1, 0, 0) to (0, 1, 0); the display is [[0, 1, 0], [-1, 0, 0], [0, 0, 1]] and "
          "takes (1, 0, 0) to (0, -1, 0), west; with it dx/dt = R (1, 0, 0) would fly the vehicle west while it "
          "points east."),
    166: ("holds", "the 3-2-1 Euler rates from the body rates, with (p, q, r) read off R^T dR/dt (check 166)"),
    186: ("not a claim", "the quaternion's components named"),
    198: ("holds", "q = (cos(theta/2), n sin(theta/2)) turns vectors by theta about the unit axis n: v -> q v q* "
          "is Rodrigues's rotation (check 198)"),
    209: ("holds", "the displayed matrix is the rotation v -> q v q* of a unit quaternion (check 209)"),
    219: ("holds", "the quaternion of the Z-Y-X angles, q_z(psi) q_y(theta) q_x(phi), turns vectors by "
          "R_z(psi) R_y(theta) R_x(phi), the body-to-inertial matrix (check 219)"),
    230: ("holds", "the three formulas give the angles back in their principal ranges (check 230, by numbers)"),
    244: ("holds", "dq/dt = (1/2) q (0, omega_body): the displayed 4x4 matrix in p, q, r times q (check 244, "
          "by numbers)"),
    262: ("not a claim", "an assignment: the quaternion renormalised at each integration step"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
