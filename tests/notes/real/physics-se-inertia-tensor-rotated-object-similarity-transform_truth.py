"""Independent SymPy truth table for physics-se-inertia-tensor-rotated-object-similarity-transform.md.

The answer's convention: I is the inertia tensor of a body about its centre of mass, L and omega the
angular momentum and angular velocity as columns of components, and `\\times` between matrices is
the matrix product (the answer premultiplies by the rotation matrix R). The inertia tensor is built
here from its particle sum, I = sum m (|r|^2 1 - r r^T), and L = sum m r x (omega x r); a rotation
R is any orthogonal matrix of determinant 1, written through a general quaternion as
R = M(q) / |q|^2 so that every identity is one of rational functions; the new components are
L' = R L, omega' = R omega.
Run as a program it compares its verdicts with the table; ``--write`` writes the table.
"""
import sys

import sympy as sp

import truth_table

m = sp.symbols('m', positive=True)
r = sp.Matrix(sp.symbols('x y z', real=True))
w = sp.Matrix(sp.symbols('omega_1:4', real=True))
q0, q1, q2, q3 = sp.symbols('q_0:4', real=True)
n = q0**2 + q1**2 + q2**2 + q3**2
R = sp.Matrix([
    [q0**2 + q1**2 - q2**2 - q3**2, 2 * (q1 * q2 - q0 * q3), 2 * (q1 * q3 + q0 * q2)],
    [2 * (q1 * q2 + q0 * q3), q0**2 - q1**2 + q2**2 - q3**2, 2 * (q2 * q3 - q0 * q1)],
    [2 * (q1 * q3 - q0 * q2), 2 * (q2 * q3 + q0 * q1), q0**2 - q1**2 - q2**2 + q3**2]]) / n


def zero(m):
    """Every entry of ``m`` cancels to zero as a rational function."""
    m = m if hasattr(m, 'shape') else sp.Matrix([m])
    return all(sp.expand(sp.fraction(sp.together(x))[0]) == 0 for x in m)


# one particle stands for the sum: both sides are linear in the particles
I = m * ((r.T * r)[0] * sp.eye(3) - r * r.T)
L = m * r.cross(w.cross(r))

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


# line 17: L = I omega for the particle sum
check(17, zero(L - I * w))
# line 21: the same relation in components, (1)
check(21, zero(L - I * w))
# line 26: R L = R I omega, (1) premultiplied by R
check(26, zero(R * L - R * I * w))
# line 30: R L = R I (R^T R) omega: R^T R = 1 for a rotation
check(30, zero(R.T * R - sp.eye(3)) and zero(R * L - R * I * (R.T * R) * w))
# line 34: (R L) = R I R^T (R omega), the product regrouped
check(34, zero(R * L - (R * I * R.T) * (R * w)))
# line 38: L' = R I R^T omega', with L' = R L and omega' = R omega; the rotated body's own
# particle sum gives the same tensor, so R I R^T is its inertia tensor in the old axes
Lp, wp, rp = R * L, R * w, R * r
Ip = m * ((rp.T * rp)[0] * sp.eye(3) - rp * rp.T)
check(38, zero(Lp - R * I * R.T * wp) and zero(Ip - R * I * R.T))

LINES = [17, 21, 26, 30, 34, 38]

ROWS = {
    17: ("holds", "L = sum m r x (omega x r) = sum m (|r|^2 1 - r r^T) omega = I omega about the centre of mass (check 17)"),
    21: ("holds", "the same relation in components, L and omega as columns and I as a 3 x 3 matrix (check 21)"),
    26: ("holds", "(1) premultiplied by the rotation matrix R; the answer's \\times between matrices is their product (check 26)"),
    30: ("holds", "R^T R = 1 for a rotation matrix put between I and omega (check 30)"),
    34: ("holds", "the product regrouped: R I R^T R omega = (R I R^T)(R omega) (check 34)"),
    38: ("holds", "with L' = R L and omega' = R omega, L' = R I R^T omega'; the rotated body's own particle sum is R I R^T (check 38)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
