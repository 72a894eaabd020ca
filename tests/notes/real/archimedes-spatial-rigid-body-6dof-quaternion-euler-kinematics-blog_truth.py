"""Independent SymPy truth table for archimedes-spatial-rigid-body-6dof-quaternion-euler-kinematics-blog.md.

The post's convention: rotations are passive, R_BE changes earth-frame coordinates into body-frame
coordinates (the transpose of the active turn that carries the earth axes onto the body axes);
quaternions are Hamilton's, scalar first, q the attitude whose active matrix R(q) = R_EB carries
body coordinates into earth coordinates; omega^B the body angular velocity in body coordinates; the
rigid body's state velocity v^B is the inertial velocity of its centre of mass in body coordinates.
Here the body's attitude is a product of three elementary active turns whose angles are functions
of time, R_NB = Rz(a) Ry(b) Rx(c); omega^B is read off R^T R-dot, and vectors in N are functions of
time, so every law the post states is rebuilt from the inertial one by the transport theorem.
Run as a program it compares its verdicts with the table; ``--write`` writes the table.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Ry, Rz
from truth_table import numeric_zero, zero

t = sp.symbols('t', real=True)
phi, theta, psi, m, g0 = sp.symbols('phi theta psi m g_0', real=True)

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


def skew(v):
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def unskew(M):
    return sp.Matrix([M[2, 1], M[0, 2], M[1, 0]])


def fvec(name):
    return sp.Matrix([sp.Function(f'{name}{k}')(t) for k in (1, 2, 3)])


def qmul(a, b):
    """Hamilton product, scalar first."""
    a0, av = a[0], sp.Matrix(a[1:])
    b0, bv = b[0], sp.Matrix(b[1:])
    return sp.Matrix([a0 * b0 - av.dot(bv), *(a0 * bv + b0 * av + av.cross(bv))])


def qmat(q):
    """The active rotation matrix of the unit quaternion q (scalar first)."""
    w, x, y, z = q
    return sp.Matrix([[w**2 + x**2 - y**2 - z**2, 2 * (x * y - w * z), 2 * (x * z + w * y)],
                      [2 * (x * y + w * z), w**2 - x**2 + y**2 - z**2, 2 * (y * z - w * x)],
                      [2 * (x * z - w * y), 2 * (y * z + w * x), w**2 - x**2 - y**2 + z**2]])


a, b, c = (sp.Function(n)(t) for n in ('a', 'b', 'c'))
R_NB = Rz(a) * Ry(b) * Rx(c)                 # body to inertial coordinates (active)
R_BN = R_NB.T                                # the post's passive matrix, inertial to body
w_B = unskew(R_NB.T * R_NB.diff(t))          # body angular velocity in body coordinates

# line 31: the weight in the earth frame, a definition
# line 38: F_g^B = R_BE(phi) F_g^E; a roll alone, passive: the transpose of the active turn about x
F_E = sp.Matrix([0, 0, m * g0])
check(38, zero(Rx(phi).T * F_E - m * g0 * sp.Matrix([0, sp.sin(phi), sp.cos(phi)])))

# line 47: q-dot = 1/2 q (x) omega^B: along this rate the active matrix R(q) moves as R [omega]x
qs = sp.Matrix(sp.symbols('q_0:4', real=True))
wq = sp.Matrix(sp.symbols('w_1:4', real=True))
qdot = qmul(qs, sp.Matrix([0, *wq])) / 2
Rq = qmat(qs)
Rdot = sum((Rq.diff(qs[k]) * qdot[k] for k in range(4)), sp.zeros(3, 3))
unit = {qs[0]: sp.sqrt(1 - qs[1]**2 - qs[2]**2 - qs[3]**2)}
check(47, zero((Rdot - Rq * skew(wq)).subs(unit)))

# line 54: the implemented model with its Baumgarte term, a definition; on the unit sphere it is line 47
assert zero((qdot - sp.Symbol('lambda') * (qs.dot(qs) - 1) * qs - qdot).subs(unit))

# line 69: R_BE(phi, theta, psi) = R_z(psi) R_y(theta) R_x(psi); whatever the elementary matrices
# (active or passive), the product as written holds no phi, while a roll changes the attitude
written = Rz(psi) * Ry(theta) * Rx(psi)
roll_free = phi not in written.free_symbols
true_forms = [Rz(psi) * Ry(theta) * Rx(phi), (Rz(psi) * Ry(theta) * Rx(phi)).T,
              Rx(phi).T * Ry(theta).T * Rz(psi).T]
check(69, not roll_free and all(phi in f.free_symbols for f in true_forms))

# line 85: the 6dof equations; p-dot^N = R_BN^T v^B, v-dot^B = F^B/m - omega x v^B, Euler's equation
vN = fvec('v')                                   # inertial velocity in N
vB = R_BN * vN
FN = m * vN.diff(t)                              # Newton in N
FB = R_BN * FN
J = sp.Matrix(3, 3, lambda i, j: sp.Symbol(f'J_{min(i, j) + 1}{max(i, j) + 1}'))
wdot = w_B.diff(t)
LN = R_NB * J * w_B                              # angular momentum in N
MN = LN.diff(t)
MB = R_BN * MN
ok = zero(R_BN.T * vB - vN)
ok &= numeric_zero(vB.diff(t) - (FB / m - w_B.cross(vB)), t)
ok &= numeric_zero(J * wdot - (MB - w_B.cross(J * w_B)), t)
check(85, ok)

# line 106: d(m v)/dt = F implies m v-dot + m-dot v = F (product rule, m a function of time)
mt = sp.Function('m')(t)
vb = fvec('u')
check(106, zero((mt * vb).diff(t) - (mt * vb.diff(t) + mt.diff(t) * vb)))

# line 117: d(J omega)/dt = M implies J omega-dot + J-dot omega = M
Jt = sp.Matrix(3, 3, lambda i, j: sp.Function(f'J{min(i, j) + 1}{max(i, j) + 1}')(t))
wv = fvec('w')
check(117, zero((Jt * wv).diff(t) - (Jt * wv.diff(t) + Jt.diff(t) * wv)))

# line 131: v^B = v_ref^B + r-dot_CM^B + omega x r_CM^B: the centre of mass sits at r_CM (body
# coordinates) from the reference point; differentiate its inertial position and express in B
pref = fvec('p')                                  # reference point in N
rcm = fvec('r')                                   # centre of mass from it, body coordinates
pcm = pref + R_NB * rcm
v_cm_B = R_BN * pcm.diff(t)
v_ref_B = R_BN * pref.diff(t)
check(131, numeric_zero(v_cm_B - (v_ref_B + rcm.diff(t) + w_B.cross(rcm)), t))

# line 140: M^B = M_ref^B - r_CM x F_ref: a force F at the reference point, moment about the centre
# of mass; the reference point is at -r_CM from the centre of mass
F = sp.Matrix(sp.symbols('F_1:4', real=True))
Mref = sp.Matrix(sp.symbols('M_1:4', real=True))
r = sp.Matrix(sp.symbols('r_1:4', real=True))
check(140, zero((Mref + (-r).cross(F)) - (Mref - r.cross(F))))

# line 148: M^B = dh^B/dt + omega x h^B: the inertial rate of R_NB h^B, in body coordinates
hB = fvec('h')
check(148, numeric_zero(R_BN * (R_NB * hB).diff(t) - (hB.diff(t) + w_B.cross(hB)), t))

# line 158: h = J omega + h_int substituted in line 148 (J may vary, d/dt kept whole)
hint = fvec('k')
h = J * w_B + hint
lhs = R_BN * (R_NB * h).diff(t)
rhs = (J * w_B).diff(t) + hint.diff(t) + w_B.cross(J * w_B) + w_B.cross(hint)
check(158, numeric_zero(lhs - rhs, t))

# line 167: M_eff = M - dh_int/dt - omega x h_int, the moment that makes the rigid model exact
Meff = lhs - hint.diff(t) - w_B.cross(hint)
check(167, numeric_zero(Meff - ((J * w_B).diff(t) + w_B.cross(J * w_B)), t))

# line 184: planet frame E turning at constant Omega about N's z axis; N -> E coordinates
Om = sp.Symbol('Omega', positive=True)
R_NE = Rz(Om * t)
R_EB = R_NE.T * R_NB                              # attitude relative to E
pE = fvec('x')                                    # position in E coordinates
vE = pE.diff(t)                                   # velocity relative to E, in E
OmE = sp.Matrix([0, 0, Om])                       # Omega in E coordinates (and in N: the z axis)
OmB = R_EB.T * OmE
# attitude rate: the body rate relative to E is omega^B - Omega^B (quaternion kinematics of line 47)
wBE = unskew(R_EB.T * R_EB.diff(t))
ok = numeric_zero(wBE - (w_B - OmB), t)
# Newton in N, written in E: F^E = m a^N in E coordinates
aN_E = R_NE.T * (R_NE * pE).diff(t, 2)
FE = m * aN_E
ok &= numeric_zero(vE.diff(t) - (FE / m - 2 * OmE.cross(vE) - OmE.cross(OmE.cross(pE))), t)
# Euler's equation keeps omega^B relative to N
ok &= numeric_zero(J * wdot - (MB - w_B.cross(J * w_B)), t)
check(184, ok)

# negative controls: the checks reject a wrong sign or a wrong roll
assert not zero(Rx(phi) * F_E - m * g0 * sp.Matrix([0, sp.sin(phi), sp.cos(phi)]))
assert not zero((Rdot + Rq * skew(wq)).subs(unit))
assert not numeric_zero(vB.diff(t) - (FB / m + w_B.cross(vB)), t)

LINES = [31, 38, 47, 54, 69, 85, 106, 117, 131, 140, 148, 158, 167, 184]

ROWS = {
    31: ("not a claim", "the weight in North-East-Down earth coordinates, a definition"),
    38: ("holds", "the passive roll matrix takes (0, 0, m g0) to m g0 (0, sin phi, cos phi) (check 38)"),
    47: ("holds", "along q-dot = q (x) (0, omega)/2 the active matrix R(q) = R_EB moves as R [omega]x, the body-rate kinematics (check 47)"),
    54: ("not a claim", "the model the library integrates: line 47 plus a Baumgarte term that vanishes on unit quaternions"),
    69: ("typo", "the last factor's angle is the yaw psi again; the roll phi appears nowhere on the right although R_BE depends on it (check 69)",
         "R_BE(\\phi, \\theta, \\psi) = R_z(\\psi) R_y(\\theta) R_x(\\phi)",
         "algebra: the right side is a product of turns by psi, theta, psi; no factor holds phi, so it cannot be a roll-pitch-yaw matrix, whose last (or first) factor is the turn by the roll about x",
         "numbers: phi = 0.3, theta = psi = 0 makes the written product the identity, but a roll of 0.3 rad about x sends (0, 0, 1) to (0, sin 0.3, cos 0.3) = (0, 0.296, 0.955) in body axes (line 38's matrix), not to (0, 0, 1)"),
    85: ("holds", "p-dot^N = R_BN^T v^B, v-dot^B = F^B/m - omega x v^B and Euler's equation rebuilt from Newton's laws in N by the transport theorem; the quaternion line is line 54's model (check 85)"),
    106: ("holds", "the product rule on m(t) v(t) (check 106)"),
    117: ("holds", "the product rule on J(t) omega(t) (check 117)"),
    131: ("holds", "the inertial velocity of the point r_CM (body coordinates, moving) from the reference point, expressed in body axes (check 131)"),
    140: ("holds", "a force at the reference point, which lies at -r_CM from the centre of mass, has the moment -r_CM x F about it (check 140)"),
    148: ("holds", "the transport theorem: the inertial rate of h in body coordinates is h-dot + omega x h (check 148)"),
    158: ("holds", "h = J omega + h_int substituted in line 148 (check 158)"),
    167: ("holds", "moving the h_int terms to the left leaves d(J omega)/dt + omega x J omega, the rigid model (check 167)"),
    184: ("holds", "for E turning at constant Omega: the body rate relative to E is omega^B - Omega^B, the Coriolis and centrifugal terms of Newton's law in E, and Euler's equation with omega relative to N (check 184)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
