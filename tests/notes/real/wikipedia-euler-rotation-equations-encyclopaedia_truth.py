"""Independent SymPy truth table for wikipedia-euler-rotation-equations-encyclopaedia.md.

The article's convention: a body turns with the rotation R(t) taking body to inertial components;
the angular velocity in body components is the vector of the skew matrix R^T dR/dt; I is the
inertia matrix in the body (constant), I_in = R I R^T the one in the inertial frame; L_in = I_in
omega_in is the inertial angular momentum, L = I omega its body components, M the torque in body
components (M_in = R M). R is a z-x-z product of three angles; the inertial law dL_in/dt = M_in is
evaluated from R, dR/dt and d2R/dt2 at several unremarkable states of the angles, their rates and
accelerations, to 40 digits, so no formula of the text is assumed. The angular momentum of a
rigid body is also built from particles.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Rz

q = sp.symbols('a b c')                     # the three angles
qd = sp.symbols('ad bd cd')                 # their rates
qdd = sp.symbols('add bdd cdd')             # their accelerations
I11, I22, I33, I12, I13, I23 = 5, 7, sp.Rational(19, 2), -1, sp.Rational(1, 2), sp.Rational(2, 3)
Ib = sp.Matrix([[I11, I12, I13], [I12, I22, I23], [I13, I23, I33]])   # a general body inertia matrix
I1, I2, I3 = 3, sp.Rational(11, 2), 8
Ip = sp.diag(I1, I2, I3)                    # a principal-axes inertia matrix

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


def vee(S):
    return sp.Matrix([S[2, 1], S[0, 2], S[1, 0]])


R_sym = Rz(q[0]) * Rx(q[1]) * Rz(q[2])
Rd_sym = sum((R_sym.diff(x) * v for x, v in zip(q, qd)), sp.zeros(3, 3))
Rdd_sym = (sum((Rd_sym.diff(x) * v for x, v in zip(q, qd)), sp.zeros(3, 3))
           + sum((R_sym.diff(x) * v for x, v in zip(q, qdd)), sp.zeros(3, 3)))
STATES = [[sp.Rational(p, r) for p, r in row] for row in (
    [(1, 2), (2, 3), (-1, 1), (3, 7), (-5, 4), (2, 1), (1, 9), (7, 3), (-2, 5)],
    [(-4, 3), (13, 11), (5, 2), (-1, 6), (3, 2), (-7, 8), (4, 1), (-3, 10), (1, 4)],
    [(9, 4), (1, 5), (-3, 8), (2, 9), (-1, 3), (5, 6), (-6, 7), (3, 4), (8, 5)])]


def at(state):
    """R, dR/dt and d2R/dt2 at one state (angles, rates, accelerations), to 40 digits."""
    sub = dict(zip(q + qd + qdd, state))
    return [m.subs(sub).evalf(40) for m in (R_sym, Rd_sym, Rdd_sym)]


def small(m):
    return all(abs(x) < 1e-30 for x in m)


def every_state(claim):
    """``claim(R, Rd, Rdd)`` (a residual) vanishes at every state."""
    return all(small(claim(*at(s))) for s in STATES)


def kin(R, Rd, Rdd):
    """The body angular velocity and its rate, from R alone."""
    w = vee(R.T * Rd)
    wd = vee(Rd.T * Rd + R.T * Rdd)
    return w, wd


def torque(I, R, Rd, Rdd):
    """Body components of the torque from the inertial law: R^T d/dt (R I omega)."""
    w, wd = kin(R, Rd, Rdd)
    return R.T * (Rd * I * w + R * I * wd)


# lines 23 and 60: I omega-dot + omega x (I omega) = M, in body components
vector_form = every_state(lambda R, Rd, Rdd: Ib * kin(R, Rd, Rdd)[1]
                          + kin(R, Rd, Rdd)[0].cross(Ib * kin(R, Rd, Rdd)[0]) - torque(Ib, R, Rd, Rdd))
check(23, vector_form)
check(60, vector_form)


# line 30: the three equations along principal axes (I diagonal)
def printed30(R, Rd, Rdd):
    w, wd = kin(R, Rd, Rdd)
    rows = sp.Matrix([I1 * wd[0] + (I3 - I2) * w[1] * w[2],
                      I2 * wd[1] + (I1 - I3) * w[2] * w[0],
                      I3 * wd[2] + (I2 - I1) * w[0] * w[1]])
    return rows - torque(Ip, R, Rd, Rdd)


check(30, every_state(printed30))

# line 40: Euler's second law in the inertial frame, the law the derivation starts from (no check)

# line 45: L_in = I_in omega for a rigid set of particles, I_in = sum m (r.r 1 - r r^T)
Q = sp.Rational
masses = [Q(1), Q(2), Q(3, 2), Q(5, 2)]
rs = [sp.Matrix(v) for v in ([1, 0, 2], [-1, 3, 0], [2, -1, 1], [0, 1, -3])]
wn = sp.Matrix([Q(1, 3), -2, Q(5, 4)])
L_particles = sum((m * r.cross(wn.cross(r)) for m, r in zip(masses, rs)), sp.zeros(3, 1))
I_in = sum((m * (r.dot(r) * sp.eye(3) - r * r.T) for m, r in zip(masses, rs)), sp.zeros(3, 3))
check(45, L_particles == I_in * wn)


# line 52: (dL/dt)_rot + omega x L = M with L = I omega in body components
def printed52(R, Rd, Rdd):
    w, wd = kin(R, Rd, Rdd)
    return Ib * wd + w.cross(Ib * w) - torque(Ib, R, Rd, Rdd)   # dL/dt in the body is I omega-dot


check(52, every_state(printed52))

# line 71: along principal axes L = sum L_i e_i = sum I_i omega_i e_i (body components)
w_s = sp.Matrix(sp.symbols('w1:4'))
check(71, Ip * w_s == sp.Matrix([I1 * w_s[0], I2 * w_s[1], I3 * w_s[2]]))

# the inline relation omega x u = Qdot Q^-1 u (inertial omega) the derivation uses
u = sp.Matrix([2, -3, Q(1, 2)])
assert every_state(lambda R, Rd, Rdd: (R * kin(R, Rd, Rdd)[0]).cross(u) - Rd * R.T * u)

LINES = [23, 30, 40, 45, 52, 60, 71]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
