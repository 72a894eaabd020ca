"""Independent SymPy truth table for physics-se-euler-equations-inertial-body-frame-rotation-matrix.md.

The answer's convention: R(t) is the rotation matrix that carries body components into inertial
ones (v = R v_B), I_B the constant inertia tensor in body components about the centre of mass, omega
the angular velocity in inertial components (R-dot = [omega]_x R), omega_B = R^T omega, tau the
torque in inertial components and tau_B = R^T tau. The law is d(L)/dt = tau with L = R L_B =
R I_B omega_B, so the inertia tensor in inertial components is R I_B R^T. R is written here through
a quaternion q, R = M(q) / |q|^2, so every identity is one of rational functions of q; q turns by q-dot = (0, omega) q / 2 with omega and its rate as symbols, so a rate is
taken by the chain rule through q and omega and R-dot R^T = [omega]_x is checked, not assumed; I_B is
a general symmetric matrix.
Run as a program it compares its verdicts with the table; ``--write`` writes the table.
"""
import sys

import sympy as sp

import truth_table

q = sp.symbols('q_0:4', real=True)
q0, q1, q2, q3 = q
n = q0**2 + q1**2 + q2**2 + q3**2
w = sp.Matrix(sp.symbols('omega_x omega_y omega_z', real=True))
wdot = sp.symbols('omegadot_x omegadot_y omegadot_z', real=True)
# the quaternion turns at q-dot = (0, omega) * q / 2 (omega in inertial components)
qdot = (-(w[0] * q1 + w[1] * q2 + w[2] * q3) / 2,
        (w[0] * q0 + w[1] * q3 - w[2] * q2) / 2,
        (w[1] * q0 + w[2] * q1 - w[0] * q3) / 2,
        (w[2] * q0 + w[0] * q2 - w[1] * q1) / 2)


def rate(m):
    """The time derivative of ``m``, a function of q and omega (the chain rule through their rates)."""
    m = m if hasattr(m, 'shape') else sp.Matrix([m])
    return m.applyfunc(lambda x: sum(sp.diff(x, v) * vd for v, vd in zip(q + tuple(w), qdot + wdot)))


R = sp.Matrix([
    [q0**2 + q1**2 - q2**2 - q3**2, 2 * (q1 * q2 - q0 * q3), 2 * (q1 * q3 + q0 * q2)],
    [2 * (q1 * q2 + q0 * q3), q0**2 - q1**2 + q2**2 - q3**2, 2 * (q2 * q3 - q0 * q1)],
    [2 * (q1 * q3 - q0 * q2), 2 * (q2 * q3 + q0 * q1), q0**2 - q1**2 - q2**2 + q3**2]]) / n
a, b, c, d, e, f = sp.symbols('A B C D E F', real=True)
IB = sp.Matrix([[a, d, e], [d, b, f], [e, f, c]])


def vanishes(m):
    """Every entry of ``m`` cancels to zero as a rational function of q, omega and its rate."""
    m = m if hasattr(m, 'shape') else sp.Matrix([m])
    return all(sp.expand(sp.fraction(sp.together(x))[0]) == 0 for x in m)


def skew(v):
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


assert vanishes(R * R.T - sp.eye(3)) and vanishes(rate(R) * R.T - skew(w))   # R-dot R^T = [omega]_x
I = R * IB * R.T                                     # the inertia tensor in inertial components
tau = rate(I * w)                                    # the torque the law asks for
wB = R.T * w
tauB = R.T * tau

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


# line 20: d(I omega)/dt = tau => I omega-dot + I-dot omega = tau, "with I = R I_B", I-dot = R-dot I_B
# = [omega]_x R I_B, => I omega-dot + omega x I omega = tau (Eq. 1)
rows20 = [
    vanishes(rate(I * w) - tau),
    vanishes(I * rate(w) + rate(I) * w - tau),
    vanishes(R * IB - I),                            # the answer's I = R I_B
    vanishes(rate(R) - skew(w) * R),                 # R-dot = [omega]_x R
    vanishes(I * rate(w) + w.cross(I * w) - tau),    # the boxed Eq. (1)
]
check(20, all(rows20))
assert rows20[0] and rows20[1] and rows20[3] and rows20[4] and not rows20[2]

# line 41: I = R I_B R^T; R I_B (R^T omega-dot) + omega x R I_B (R^T omega) = tau with R^T omega-dot
# = omega_B-dot and R^T omega = omega_B; times R^T from the left; the boxed Eq. (2)
rows41 = [
    vanishes(R * IB * R.T - I),
    vanishes(rate(wB) - R.T * rate(w)),              # the underbrace R^T omega-dot = omega_B-dot
    vanishes(R * IB * (R.T * rate(w)) + w.cross(R * IB * (R.T * w)) - tau),
    vanishes(IB * (R.T * rate(w)) + R.T * w.cross(R * IB * (R.T * w)) - R.T * tau),
    vanishes(IB * rate(wB) + wB.cross(IB * wB) - tauB),
]
check(41, all(rows41))

LINES = [20, 41]

H20_1 = ("Take R = R_z(phi) and I_B = diag(A, B, C) with A != B: R I_B has (1,2) entry -B sin(phi) and "
         "(2,1) entry A sin(phi), so it is not symmetric, while an inertia tensor is symmetric in any "
         "components; R I_B R^T is, with (1,2) entry (A - B) sin(phi) cos(phi).")
H20_2 = ("Components go as v = R v_B, so L = R L_B = R I_B omega_B = R I_B R^T omega. With R = R_z(phi), "
         "I_B = diag(A, B, C) and omega = (1, 0, 0): L = (A cos^2 phi + B sin^2 phi, (A - B) sin phi cos phi, 0), "
         "while R I_B omega = A (cos phi, sin phi, 0); the two differ whenever A != B and sin phi != 0.")

ROWS = {
    20: ("fails", "its step 'with I = R I_B' is wrong: the inertia tensor in inertial components is R I_B R^T "
                  "(L = R L_B = R I_B R^T omega); R I_B is not even symmetric. The first two rows, R-dot = "
                  "[omega]_x R and the boxed Eq. (1) hold: with I = R I_B R^T, I-dot omega = omega x I omega "
                  "- I (omega x omega) = omega x I omega (check 20)",
         "", H20_1, H20_2),
    41: ("holds", "with I = R I_B R^T: R^T omega-dot is omega_B-dot (R-dot^T omega = -R^T (omega x omega) = 0), "
                  "the equation premultiplied by R^T, and R^T (omega x v) = omega_B x R^T v give the boxed "
                  "I_B omega_B-dot + omega_B x I_B omega_B = tau_B (check 41)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
