"""Independent SymPy truth table for physics-se-tennis-racket-degenerate-moments-stability.md.

The answer's convention: principal moments I_1, I_2, I_3, body components Omega_i of the angular
velocity, L_i = I_i Omega_i, indices modulo three. Euler's equations of the free body are written
out component by component (I_1 Omega_1' = (I_2 - I_3) Omega_2 Omega_3 and its cyclic shifts); the
second derivatives come from differentiating them along the motion; the linearised cases keep the
terms of first order in the small components.
Run as a program it compares its verdicts with the table; ``--write`` writes the table.
"""
import sys

import sympy as sp

import truth_table
from truth_table import zero

I = sp.symbols('I_1:4', positive=True)
W = sp.symbols('Omega_1:4', real=True)
eps = sp.symbols('epsilon', positive=True)

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


# Euler's equations of the free body, written out: I_1 Omega_1' = (I_2 - I_3) Omega_2 Omega_3, cyclic
rate = [(I[1] - I[2]) * W[1] * W[2] / I[0],
        (I[2] - I[0]) * W[2] * W[0] / I[1],
        (I[0] - I[1]) * W[0] * W[1] / I[2]]


def ddot(i):
    """Omega_i'' along the motion: the chain rule through Euler's equations."""
    return sum(sp.diff(rate[i], W[j]) * rate[j] for j in range(3))


# line 23: (1) with i+1, i-1 taken modulo three
check(23, all(zero(rate[i] - W[(i + 1) % 3] * (I[(i + 1) % 3] - I[(i - 1) % 3]) * W[(i - 1) % 3] / I[i])
              for i in range(3)))

# line 28: (2) the second derivative of each component
ok28 = True
for i in range(3):
    p, q = (i + 1) % 3, (i - 1) % 3
    rhs = (I[p] - I[q]) * W[i] * ((I[i] - I[p]) * I[p] * W[p]**2 - (I[i] - I[q]) * I[q] * W[q]**2)
    ok28 &= zero(I[0] * I[1] * I[2] * ddot(i) - rhs)
check(28, ok28)

# line 33: (3) I_{i+1} = I_{i-1} makes Omega_i' = 0, so Omega_i and L_i = I_i Omega_i are constant
check(33, all(zero(rate[i].subs(I[(i + 1) % 3], I[(i - 1) % 3])) for i in range(3)))

# lines 46, 50: (5) near (0, Omega_2, 0), to first order in Omega_1, Omega_3, Omega_i'' = +omega_2^2 Omega_i
w2sq = W[1]**2 * (I[0] - I[1]) * (I[1] - I[2]) / (I[0] * I[2])
ok46 = True
for i in (0, 2):
    small = ddot(i).subs({W[0]: eps * W[0], W[2]: eps * W[2]})
    first = sp.diff(small, eps).subs(eps, 0)
    ok46 &= zero(first - w2sq * W[i])
check(46, ok46)

# lines 55, 59: (7) with I_1 = I_2 exactly, Omega_i'' = -omega_3^2 Omega_i for i = 1, 2, with (8)
w3sq = W[2]**2 * (I[0] - I[2]) * (I[1] - I[2]) / (I[0] * I[1])
check(55, all(zero((ddot(i) + w3sq * W[i]).subs(I[1], I[0])) for i in (0, 1)))
# (8): omega_3 is built from Omega_3 and the moments only, and Omega_3 is constant when I_1 = I_2 (3)
check(59, zero(rate[2].subs(I[1], I[0])))

LINES = [15, 23, 28, 33, 37, 46, 50, 55, 59]

ROWS = {
    15: ("not a claim", "the two cases of equal moments the question asks about"),
    23: ("holds", "I_i Omega_i' = Omega_{i+1} (I_{i+1} - I_{i-1}) Omega_{i-1} is I_1 Omega_1' = (I_2 - I_3) Omega_2 Omega_3 and its cyclic shifts, Euler's equations of the free body (check 23)"),
    28: ("holds", "differentiating (1) and putting (1) back in: I_1 I_2 I_3 Omega_i'' = (I_{i+1} - I_{i-1}) Omega_i {(I_i - I_{i+1}) I_{i+1} Omega_{i+1}^2 - (I_i - I_{i-1}) I_{i-1} Omega_{i-1}^2} for each i (check 28)"),
    33: ("holds", "with I_{i+1} = I_{i-1} the right side of (1) vanishes, so Omega_i and L_i = I_i Omega_i are constant (check 33)"),
    37: ("not a claim", "the ordering of the moments assumed for the cases"),
    46: ("holds", "(2) to first order in Omega_1, Omega_3 near (0, Omega_2, 0): Omega_i'' = Omega_2^2 (I_1 - I_2)(I_2 - I_3)/(I_1 I_3) Omega_i for i = 1, 3, that is +omega_2^2 Omega_i with the omega_2 of (6) (check 46)"),
    50: ("not a claim", "the definition of omega_2"),
    55: ("holds", "(2) with I_1 = I_2: Omega_i'' = -Omega_3^2 (I_1 - I_3)(I_2 - I_3)/(I_1 I_2) Omega_i for i = 1, 2, exactly, that is -omega_3^2 Omega_i with the omega_3 of (8) (check 55)"),
    59: ("holds", "a definition of omega_3 whose claim is that it is constant: it is made of the moments and Omega_3, and Omega_3' = (I_1 - I_2) Omega_1 Omega_2 / I_3 = 0 when I_1 = I_2 (check 59)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
