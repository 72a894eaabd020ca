"""Independent SymPy truth table for spacecraft-course-notes-torque-free-momentum-sphere-energy-ellipsoid.ipynb.

The text's convention (Schaub's): angular momentum H, torque L, inertia tensor I, all in principal
body axes, I = diag(I_1, I_2, I_3). The angular velocity follows the torque-free Euler equations
I_1 w_1' = (I_2 - I_3) w_2 w_3 and cyclic, so that the claims "= constant" are checked as rates
that vanish on that motion; the other claims are identities checked with sympy.
"""
import pathlib
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(line, ok):
    CHECKS[line] = bool(ok)


I1, I2, I3 = sp.symbols('I_1 I_2 I_3', positive=True)
w1, w2, w3 = sp.symbols('omega_1 omega_2 omega_3', real=True)
I = sp.diag(I1, I2, I3)
w = sp.Matrix([w1, w2, w3])
H = I * w
# torque-free Euler equations in principal axes: the rates of w
wdot = sp.Matrix([(I2 - I3) * w2 * w3 / I1, (I3 - I1) * w3 * w1 / I2, (I1 - I2) * w1 * w2 / I3])


def rate(expr):
    """The time rate of an expression in w1, w2, w3 along the torque-free motion."""
    return sum(sp.diff(expr, q) * d for q, d in zip(w, wdot))


H1, H2, H3 = H
Hsq = H1**2 + H2**2 + H3**2
T = (w.T * I * w)[0] / 2
Tq = sp.Symbol('T', positive=True)

# 44: H = I w = (I_1 w_1, I_2 w_2, I_3 w_3)
check(44, truth_table.zero(H - sp.Matrix([I1 * w1, I2 * w2, I3 * w3])))
# 65: H^2 = H^T H, the squared length of 60
check(65, truth_table.zero(sp.Matrix([(H.T * H)[0] - Hsq])))
# 73 and 135: H^2 = H_1^2 + H_2^2 + H_3^2 = constant: the sum of squares has zero rate on the motion
check(73, truth_table.zero(sp.Matrix([rate(Hsq)])))
check(135, truth_table.zero(sp.Matrix([rate(Hsq)])))
# 112 and 142: T = 1/2 w^T I w with the diagonal tensor is 1/2 (I_1 w_1^2 + I_2 w_2^2 + I_3 w_3^2)
check(112, truth_table.zero(sp.Matrix([T - (I1 * w1**2 + I2 * w2**2 + I3 * w3**2) / 2])))
check(142, truth_table.zero(sp.Matrix([T - (I1 * w1**2 + I2 * w2**2 + I3 * w3**2) / 2])) and truth_table.zero(sp.Matrix([rate(T)])))
# 127: H_i = I_i w_i, the components of 44
check(127, truth_table.zero(H - sp.Matrix([I1 * w1, I2 * w2, I3 * w3])))
# 146: with H_i = I_i w_i and T the energy, sum H_i^2 / (2 I_i T) = 1
check(146, truth_table.zero(sp.Matrix([(H1**2 / (2 * I1 * Tq) + H2**2 / (2 * I2 * Tq) + H3**2 / (2 * I3 * Tq)).subs(Tq, T) - 1])))
# 156: matching 146 with x^2/a^2 + y^2/b^2 + z^2/c^2 = 1 gives a^2 = 2 I_1 T etc.
a, b, c = sp.sqrt(2 * I1 * Tq), sp.sqrt(2 * I2 * Tq), sp.sqrt(2 * I3 * Tq)
check(156, truth_table.zero(sp.Matrix([H1**2 / a**2 - H1**2 / (2 * I1 * Tq), H2**2 / b**2 - H2**2 / (2 * I2 * Tq),
                                       H3**2 / c**2 - H3**2 / (2 * I3 * Tq)])))

LINES = [35, 44, 55, 60, 65, 73, 88, 94, 103, 112, 127, 135, 142, 146, 152, 156, 168]

ROWS = {
    35: ('not a claim', 'the inertia tensor in principal axes: the definition of the principal frame'),
    44: ('holds', 'the angular momentum I w with the diagonal tensor has components I_i w_i (check 44)'),
    55: ('not a claim', 'the torque-free law: the rate of H equals the torque, zero'),
    60: ('not a claim', 'the length of H named H, written as the root of the sum of squares: a definition'),
    65: ('holds', 'the squared length is the dot product H^T H (check 65)'),
    73: ('holds', 'the sum of the squared components has zero rate on the torque-free Euler motion (check 73)'),
    88: ('not a claim', 'the rotational kinetic energy recalled as the quadratic form of w with I'),
    94: ('not a claim', 'the inertia tensor in a general body frame: a symmetric matrix of named entries'),
    103: ('not a claim', 'the inertia tensor in principal axes: the definition of the principal frame'),
    112: ('holds', 'the quadratic form with the diagonal tensor is half the sum I_i w_i^2 (check 112)'),
    127: ('holds', 'the components of 44 (check 127)'),
    135: ('holds', 'the same sphere as 73: the sum of squares has zero rate on the motion (check 135)'),
    142: ('holds', 'the energy of 112, conserved on the torque-free motion (check 142)'),
    146: ('holds', 'with H_i = I_i w_i, half the sum H_i^2 / I_i is T, divided by T (check 146)'),
    152: ('not a claim', 'the equation of an ellipsoid with semi-axes a, b, c, set out for comparison'),
    156: ('holds', 'matching 146 with 152 term by term gives a^2 = 2 I_1 T, b^2 = 2 I_2 T, c^2 = 2 I_3 T (check 156)'),
    168: ('not a claim', 'the ordering of the principal moments, an assumption'),
}

if __name__ == "__main__":
    here = pathlib.Path(__file__)
    assert truth_table.notebook_display_lines(here.with_name('spacecraft-course-notes-torque-free-momentum-sphere-energy-ellipsoid.ipynb')) == LINES
    if sys.argv[1:] == ['--write']:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
