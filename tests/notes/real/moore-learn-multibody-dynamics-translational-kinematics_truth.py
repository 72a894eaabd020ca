"""Independent SymPy truth table for moore-learn-multibody-dynamics-translational-kinematics.md.

The text's own setting (Kane's notation): every vector is written by its components in the ground
frame N; a frame X is given by the matrix R_X(t) whose columns are X's unit vectors in N. The
derivative of a vector u taken in X is R_X d/dt (R_X^T u) (the rate of its X-components, turned
back to N); the angular velocity of X in N is the vector of the skew matrix R_X' R_X^T, and the
angular velocity of B in A is omega^{NB} - omega^{NA}. A point's velocity in a frame is the rate, taken
in that frame, of its position from a point fixed in that frame; its acceleration the rate, taken
in that frame, of that velocity. A point T "fixed in B at R at this instant" is the point of B whose
B-coordinates are R's, held constant. Motions are sample functions of time (generic: no special
values); every identity is evaluated at t = 3/10 to 40 digits after differentiating. The sculpture
is built as the text's prose and code build it: A turned from N through alpha about n_z, B from A
through beta about a_x, O on the ground on the axis, P = O + h n_z, S = P - d a_x,
Q = S - w b_x - (c + l/2) b_z, R = Q + l b_z + s b_x, B_c = S - c b_z - (w/2) a_x.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Rz

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


t = sp.symbols("t", real=True)


def vee(S):
    return sp.Matrix([S[2, 1], S[0, 2], S[1, 0]])


def omega(R):
    """The angular velocity in N of the frame whose unit vectors are R's columns (N components)."""
    return vee(R.diff(t) * R.T)


def d_in(R, u):
    """The derivative of u (N components) taken in the frame R."""
    return R * (R.T * u).diff(t)


def at(expr):
    return sp.Matrix(expr).xreplace({t: sp.Float("0.3", 40)}).evalf(40)


def near(m):
    return all(abs(x) < 1e-20 for x in sp.Matrix(m))


def same(a, b):
    return near(at(sp.Matrix(a) - sp.Matrix(b)))


def vec(*c):
    return sp.Matrix(c)


# generic frames and motions (sample functions of time)
R_A = Rz(sp.Rational(1, 3) + t) * Rx(sp.Rational(2, 3) + t**2 / 5) * Rz(-sp.Rational(1, 2) + 2 * t)
R_B = Rz(sp.Rational(1, 7) - t / 2) * Rx(sp.Rational(5, 4) + sp.sin(t)) * Rz(sp.Rational(3, 5) + t**3 / 4)
w_A, w_B = omega(R_A), omega(R_B)
p_path = vec(sp.cos(t) + 2, t**3 - t, sp.exp(t / 2))                    # a moving point's path in N
rho = vec(1 + t**2, sp.sin(2 * t) - sp.Rational(1, 3), 2 - t / 3)      # a point's coordinates in B, moving
sigma = vec(sp.Rational(3, 2), -sp.Rational(2, 5), sp.Rational(7, 4))   # a point's coordinates fixed in A or B

# line 39: O fixed in A and B (their shared origin), P moving: d^A r = d^B r + omega^{AB} x r = ^B v^P + omega^{AB} x r
w_AB = w_B - w_A
r_PO = p_path
vA_P = d_in(R_A, r_PO)
vB_P = d_in(R_B, r_PO)
check(39, same(vA_P, d_in(R_A, r_PO)) and same(vA_P, d_in(R_B, r_PO) + w_AB.cross(r_PO))
      and same(vA_P, vB_P + w_AB.cross(r_PO)))

# the sculpture
al, be = sp.Rational(2, 5) + sp.sin(t) + t**2, -sp.Rational(1, 3) + 2 * t - t**3 / 3
h, d, w, c, l = sp.Rational(3), sp.Rational(1, 2), sp.Rational(7, 5), sp.Rational(1, 5), sp.Rational(9, 4)
s = sp.Rational(1, 3) + t / 2 + t**2
SA = Rz(al)
SB = SA * Rx(be)
n_z = vec(0, 0, 1)
a_x = SA[:, 0]
b_x, b_z = SB[:, 0], SB[:, 2]
r_P = h * n_z                                    # positions from O
r_S = r_P - d * a_x
r_Q = r_S - w * b_x - (c + l / 2) * b_z
r_R = r_Q + l * b_z + s * b_x
r_Bc = r_S - c * b_z - w / 2 * a_x
wS_A, wS_B = omega(SA), omega(SB)
# the frames are what the prose says: A turns at alpha' about n_z, B turns in A at beta' about a_x
assert same(wS_A, al.diff(t) * n_z) and same(wS_B - wS_A, be.diff(t) * a_x)

# line 59: ^N v^S = ^A v^S + omega^{NA} x r^{S/O}, O fixed in N and (on the axis) in A
check(59, same(r_S.diff(t), d_in(SA, r_S) + wS_A.cross(r_S)))

# line 73: ^A v^{B_c} = ^B v^{B_c} + omega^{AB} x r^{B_c/S}, S fixed in A and (on the hinge) in B
r_BcS = r_Bc - r_S
check(73, same(d_in(SA, r_BcS), d_in(SB, r_BcS) + (wS_B - wS_A).cross(r_BcS)))
assert same(d_in(SB, r_BcS), sp.zeros(3, 1))     # B_c does not move in B

# lines 84, 137: P moving with A (its path p), S fixed in A at sigma from P; O fixed in N
r_SP = R_A * sigma
vN_S = (p_path + r_SP).diff(t)
vN_P = p_path.diff(t)
check(84, same(vN_S, (p_path + r_SP).diff(t)) and same(vN_S, vN_P + r_SP.diff(t))
      and same(vN_S, vN_P + w_A.cross(r_SP)))
check(137, same(vN_S, vN_P + w_A.cross(r_SP)))

# line 95: ^N v^Q = ^N v^S + omega^{NB} x r^{Q/S} in the sculpture
check(95, same(r_Q.diff(t), r_S.diff(t) + wS_B.cross(r_Q - r_S)))

# lines 107, 114, 177: B moving (origin path p, orientation R_B), R at coordinates rho(t) in B,
# S fixed in B at sigma, T the point of B at R's coordinates held constant
r_R_gen = p_path + R_B * rho
vN_R = r_R_gen.diff(t)
vB_R = R_B * rho.diff(t)                          # = d^B of R's position from a point fixed in B
assert same(vB_R, d_in(R_B, r_R_gen - (p_path + R_B * sigma)))
vN_T = p_path.diff(t) + R_B.diff(t) * rho
vN_Sb = p_path.diff(t) + R_B.diff(t) * sigma
r_RS = R_B * (rho - sigma)
check(107, same(vN_R, vB_R + vN_T))
check(114, same(vN_R, vB_R + vN_Sb + w_B.cross(r_RS)))
check(177, same(vN_R, vB_R + vN_Sb + w_B.cross(r_RS)))

# line 143: the acceleration two point theorem, each row against ^N a^S = d^2/dt^2 r^{S/O}
aN_S = (p_path + r_SP).diff(t, 2)
aN_P = p_path.diff(t, 2)
alpha_A = w_A.diff(t)                             # the angular acceleration: the rate of omega in N
rows143 = [vN_P.diff(t) + w_A.cross(r_SP).diff(t),
           aN_P + w_A.diff(t).cross(r_SP) + w_A.cross(r_SP.diff(t)),
           aN_P + alpha_A.cross(r_SP) + w_A.cross(w_A.cross(r_SP))]
check(143, all(same(aN_S, r) for r in rows143))

# line 183: the acceleration one point theorem (the five term beast), each row against ^N a^R
aN_R = r_R_gen.diff(t, 2)
aB_R = d_in(R_B, vB_R)                            # = R_B rho''
aN_Sb = p_path.diff(t, 2) + R_B.diff(t, 2) * sigma
alpha_B = w_B.diff(t)
vB_T = sp.zeros(3, 1)                             # T is fixed in B
rows183 = [vB_R.diff(t) + vN_Sb.diff(t) + w_B.cross(r_RS).diff(t),
           vN_R.diff(t) + w_B.cross(vN_R) + aN_Sb + w_B.diff(t).cross(r_RS) + w_B.cross(r_RS.diff(t)),
           aB_R + w_B.cross(vB_R) + aN_Sb + alpha_B.cross(r_RS) + w_B.cross(vB_T + w_B.cross(r_RS)),
           aB_R + 2 * w_B.cross(vB_R) + aN_Sb + alpha_B.cross(r_RS) + w_B.cross(w_B.cross(r_RS))]
ok183 = [same(aN_R, r) for r in rows183]
assert ok183 == [True, False, False, True], ok183
check(183, all(ok183))
# the corrected rows hold: d^N(^B v^R) = d^B(^B v^R) + omega x ^B v^R, and d^N r^{R/S} = ^B v^R + omega x r^{R/S}
row2_fixed = d_in(R_B, vB_R) + w_B.cross(vB_R) + aN_Sb + w_B.diff(t).cross(r_RS) + w_B.cross(r_RS.diff(t))
row3_fixed = aB_R + w_B.cross(vB_R) + aN_Sb + alpha_B.cross(r_RS) + w_B.cross(vB_R + w_B.cross(r_RS))
assert same(aN_R, row2_fixed) and same(aN_R, row3_fixed)

# line 214: ^N a^R = ^B a^R + ^N a^T + 2 omega x ^B v^R, T fixed in B at R's coordinates
aN_T = p_path.diff(t, 2) + R_B.diff(t, 2) * rho
check(214, same(aN_R, aB_R + aN_T + 2 * w_B.cross(vB_R)))
# ^N a^T is the two point theorem's acceleration of T from S (the text's "embedded" remark)
assert same(aN_T, aN_Sb + alpha_B.cross(r_RS) + w_B.cross(w_B.cross(r_RS)))

# negative controls: the checks can fail
assert not same(aN_R, aB_R + aN_T + w_B.cross(vB_R))
assert not same(vN_R, vN_T)
assert not same(aN_S, aN_P + alpha_A.cross(r_SP))
assert not same(r_S.diff(t), d_in(SA, r_S) - wS_A.cross(r_S))

LINES = [31, 39, 59, 73, 84, 95, 107, 114, 127, 137, 143, 158, 165, 177, 183, 214]

ROWS = {
    31: ("not a claim", "defines the velocity of P in A as the rate, taken in A, of its position from O fixed in A"),
    39: ("holds", "the definition, then the derivative in A through the derivative in B plus omega^{AB} x r, then ^B v^P for the rate in B: "
         "the last row takes O fixed in B as well (as O on the sculpture's axis is), which the text leaves tacit (check 39)"),
    59: ("holds", "the sculpture's hinge S: O on the vertical axis is fixed in N and A, so the rate in N of r^{S/O} is its rate in A plus alpha' n_z x r^{S/O} (check 59)"),
    73: ("holds", "B_c fixed in B and S on the hinge fixed in A and B: the rate in A of r^{B_c/S} is its rate in B (zero) plus omega^{AB} x r^{B_c/S} (check 73)"),
    84: ("holds", "the velocity two point theorem, all rows: r^{S/O} = r^{P/O} + r^{S/P}, the sum rule, and the rate of a vector fixed in A (check 84)"),
    95: ("holds", "S and Q both fixed in B: the two point theorem in the sculpture (check 95)"),
    107: ("holds", "the velocity one point theorem: R's velocity in N is its velocity in B plus that of the point T of B at R (check 107)"),
    114: ("holds", "the one point theorem with the two point theorem for T from S fixed in B (check 114)"),
    127: ("not a claim", "defines the acceleration of P in A as the rate, taken in A, of its velocity in A"),
    137: ("holds", "the velocity two point theorem repeated (check 137)"),
    143: ("holds", "the acceleration two point theorem, all rows: the rate in N of the velocity theorem, the product rule, alpha = the rate of omega, "
          "and the rate of r^{S/P} fixed in A (check 143)"),
    158: ("not a claim", "names the tangential part of the acceleration, an expression (no relation)"),
    165: ("not a claim", "names the centripetal part of the acceleration, an expression (no relation)"),
    177: ("holds", "the expanded velocity one point theorem repeated (check 177)"),
    183: ("typo", "rows 1 and 4 hold, but row 2 writes the rate in N of ^B v^R as d^N(^N v^R)/dt + omega x ^N v^R (N for B twice), "
          "and row 3 writes ^B v^T, zero since T is fixed in B, for ^B v^R inside the last cross product, so one of the two Coriolis terms "
          "that row 4 collects is missing there (check 183)",
          "\\frac{{}^Bd {}^B\\bar{v}^R }{dt} + {}^N\\bar{\\omega}^B \\times {}^B\\bar{v}^R + \\ldots \\text{ (row 2)}, \\quad "
          "{}^N\\bar{\\omega}^B \\times \\left( {}^B\\bar{v}^R + {}^N\\bar{\\omega}^B \\times \\bar{r}^{R/S} \\right) \\text{ (row 3)}",
          "a limiting case: let R be fixed in B (^B v^R = 0, ^B a^R = 0) on a disk B spinning at a constant rate omega about its axis through S "
          "fixed in N, at distance r from the axis: the true acceleration is the centripetal omega^2 r toward the axis; row 2's first two terms "
          "d^N(^N v^R)/dt + omega x ^N v^R are then omega x (omega x r) twice, and with the last term omega x (omega x r) row 2 gives three times "
          "the centripetal acceleration, 3 omega^2 r, not omega^2 r",
          "a second case for row 3: B not turning in N would hide it, so take B spinning at constant omega k about k through S fixed in N, and R "
          "sliding along b_x at constant speed u from S (r^{R/S} = x b_x, x' = u): the exact acceleration in N is -omega^2 x b_x + 2 omega u b_y "
          "(polar coordinates: r'' - r theta'^2 radially, 2 r' theta' across); row 3 with ^B v^T = 0 gives omega u b_y + (-omega^2 x b_x), "
          "half the Coriolis term, while row 4 gives 2 omega u b_y, so rows 3 and 4 differ by omega x ^B v^R"),
    214: ("holds", "the acceleration one point theorem: ^B a^R + ^N a^T + 2 omega x ^B v^R, with ^N a^T the two point theorem's acceleration of T (check 214)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
