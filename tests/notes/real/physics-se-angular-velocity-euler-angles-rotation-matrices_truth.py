"""Independent SymPy truth table for physics-se-angular-velocity-euler-angles-rotation-matrices.md.

The first answer's convention: rotations about Z, X, Z by phi, theta, psi, T_1 = R_z(phi) and
T_2 = R_x(theta) active rotation matrices, T = T_1 T_2 T_3 with T_3 = R_z(psi); the angular velocity
in space components is the vector of the antisymmetric matrix T-dot T^t, and "a x T" is the cross
product with each column of T, the matrix [a]_x T. The second answer's: x(t) = R(t) x(0) for a
rotation R(t), Omega = R-dot R^t with the entries it prints. Each claim is checked with the angles
as functions of time.
Run as a program it compares its verdicts with the table; ``--write`` writes the table.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Rz
from truth_table import zero

t = sp.symbols('t', real=True)
ph, th, ps = (sp.Function(n)(t) for n in ('phi', 'theta', 'psi'))
psid_free = sp.symbols('psidot', real=True)      # the letter psi-dot of the two-rotation update

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


def skew(v):
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def vee(M):
    return sp.Matrix([M[2, 1], M[0, 2], M[1, 0]])


zh, xh = sp.Matrix([0, 0, 1]), sp.Matrix([1, 0, 0])
T1, T2, T3 = Rz(ph), Rx(th), Rz(ps)

# line 17: omega = phidot z + T_1 (thetadot x + T_2 (psidot z)) is the vector of T-dot T^t, T = T_1 T_2 T_3
T = T1 * T2 * T3
W = sp.simplify(T.diff(t) * T.T)
assert zero(W + W.T)
check(17, zero(vee(W) - (ph.diff(t) * zh + T1 * (th.diff(t) * xh + T2 * (ps.diff(t) * zh)))))

# line 26: the two-rotation update, T = T_1 T_2; its second row writes T_1-dot = (psidot z) x T_1
T12 = T1 * T2
row2 = skew(psid_free * zh) * T1 * T2 + T1 * (skew(th.diff(t) * xh) * T2)
rows_after = [skew(psid_free * zh) * T12 + skew(T1 * (th.diff(t) * xh)) * T12,
              skew(psid_free * zh + T1 * (th.diff(t) * xh)) * T12]
chain_ok = zero(T12.diff(t) - (T1.diff(t) * T2 + T1 * T2.diff(t))) and zero(T12.diff(t) - row2)
steps_ok = all(zero(row2 - r) for r in rows_after)          # the later rows follow from the second
assert steps_ok and not zero(T12.diff(t) - row2)
assert zero(T12.diff(t) - row2.subs(psid_free, ph.diff(t)))   # with phidot for psidot it holds
check(26, chain_ok)

# line 38: omega = psidot z + T_1 (thetadot x) for T = T_1 T_2; the vector of T-dot T^t is phidot z + T_1 thetadot x
W12 = sp.simplify(T12.diff(t) * T12.T)
om12 = vee(W12)
check(38, zero(om12 - (psid_free * zh + T1 * (th.diff(t) * xh))))
assert zero(om12 - (ph.diff(t) * zh + T1 * (th.diff(t) * xh)))

# the second answer: a rotation R(t) (any z-x-z one stands for it) and a body point x(t) = R x(0)
R = T
x0 = sp.Matrix(sp.symbols('a b c', real=True))
x = R * x0
# line 54: xdot = R-dot x(0) = R-dot R^t x(t)
check(54, zero(x.diff(t) - R.diff(t) * x0) and zero(R.diff(t) * x0 - R.diff(t) * R.T * x))
# line 58: R R^t = I
check(58, zero(R * R.T - sp.eye(3)))
# line 62: R-dot R^t = -R R-dot^t = -(R-dot R^t)^t
A = R.diff(t) * R.T
check(62, zero(A + R * R.diff(t).T) and zero(A + A.T))
# line 76: Omega x = omega x x with Omega of the printed form
wx, wy, wz = sp.symbols('omega_x omega_y omega_z', real=True)
Om = sp.Matrix([[0, -wz, wy], [wz, 0, -wx], [-wy, wx, 0]])
xv = sp.Matrix(sp.symbols('x_1:4', real=True))
check(76, zero(Om * xv - sp.Matrix([wx, wy, wz]).cross(xv)))
# line 80: xdot = omega x x, omega the vector of R-dot R^t
check(80, zero(x.diff(t) - vee(sp.simplify(A)).cross(x)))

LINES = [17, 26, 38, 49, 54, 58, 62, 67, 72, 76, 80]

H26_1 = ("T_1 = R_z(phi) = [[cos phi, -sin phi, 0], [sin phi, cos phi, 0], [0, 0, 1]] differentiates to "
         "phidot [[-sin phi, -cos phi, 0], [cos phi, -sin phi, 0], [0, 0, 0]] = [phidot z]_x T_1: the rate that "
         "turns T_1 is phidot; psi is not an angle of T = T_1 T_2 at all, so (psidot z) x T_1 is not T_1-dot.")
H26_2 = ("Take thetadot = 0 and theta = 0: T = R_z(phi) turns at phidot about z, so dT/dt = (phidot z) x T, "
         "while the chain's second row gives (psidot z) x T, with psidot a rate that does not enter T. The rows "
         "after it follow from the second by T (a x b) = (T a) x (T b), so only the letter is wrong.")
H38_1 = ("The first display with the third rotation dropped (T = T_1 T_2, psidot = 0) gives "
         "omega = phidot z + T_1 (thetadot x): the z term carries phidot, the rate of T_1.")
H38_2 = ("With theta fixed the body turns about z at phidot, so omega = phidot z; the display gives psidot z, "
         "a rate of an angle that T_1 T_2 does not contain; it is the chain's last row with the same letter.")

ROWS = {
    17: ("holds", "the vector of the antisymmetric T-dot T^t for T = R_z(phi) R_x(theta) R_z(psi), the angular velocity in space components (check 17)"),
    26: ("typo", "for T = T_1 T_2 with T_1 = R_z(phi), T_1-dot = (phidot z) x T_1; the chain writes psidot, a rate that does not enter T; with phidot in its place every row holds, the rows after the second following from it by T (a x b) = (T a) x (T b) (check 26)",
         "\\frac{{\\rm d} T}{{\\rm d} t} = \\dot{T}_1 T_2 + T_1 \\dot{T}_2 = \\left( (\\dot{\\phi} \\hat{z}) \\times T_1 \\right) T_2 + T_1 \\left( (\\dot{\\theta} \\hat{x}) \\times T_2 \\right) = \\dots = \\left(\\dot{\\phi} \\hat{z} + T_1 (\\dot{\\theta} \\hat{x}) \\right) \\times T",
         H26_1, H26_2),
    38: ("typo", "the vector of T-dot T^t for T = T_1 T_2 is phidot z + T_1 (thetadot x), the first display without its third rotation; the display writes psidot (check 38)",
         "\\vec{\\omega} = \\dot{\\phi} \\hat{z} + T_1 (\\dot{\\theta} \\hat{x})", H38_1, H38_2),
    49: ("not a claim", "the motion of a body point generated by a rotation R(t), the answer's starting model"),
    54: ("holds", "x-dot = R-dot x(0), and x(0) = R^t x(t) for a rotation (check 54)"),
    58: ("holds", "a rotation matrix is orthogonal (check 58)"),
    62: ("holds", "the derivative of R R^t = I: R-dot R^t + R R-dot^t = 0, and (R-dot R^t)^t = R R-dot^t (check 62)"),
    67: ("not a claim", "names the three independent entries of the antisymmetric Omega"),
    72: ("not a claim", "the definition of the angular velocity vector from Omega's entries"),
    76: ("holds", "the printed Omega times x is (omega_x, omega_y, omega_z) x x (check 76)"),
    80: ("holds", "x-dot = Omega x(t) = omega x x(t) with Omega = R-dot R^t (check 80)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
