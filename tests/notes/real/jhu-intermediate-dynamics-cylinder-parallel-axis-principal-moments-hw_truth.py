"""Independent SymPy truth table for jhu-intermediate-dynamics-cylinder-parallel-axis-principal-moments-hw.tex.

Problem 1: a homogeneous cylinder of mass m, radius R and length h = 2R (the length the figure draws, which
the solution's 7/12 uses); body axes x'y'z' at the centroid with x' along the cylinder's axis, so the
centroidal inertia matrix is diag(m R^2/2, m(3R^2+h^2)/12, m(3R^2+h^2)/12). The parallel axis term for an
offset d = (x, y, z) is m(|d|^2 1 - d d^T); the turn to xyz is R_z(pi/4); I_xyz = R^T (I' + I_pat) R. The
solution carries four decimals, so a numeric display holds when it agrees to half a unit in its last place
(a check product of rounded entries to the accumulated rounding).
Problem 2: the given matrix I; its characteristic polynomial det(I - lambda 1); the principal moments are
its roots; R = R_y(theta) with I = R I_D R^T, theta = -1.2234.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Ry, Rz

CHECKS = {}
zero = truth_table.zero


def check(key, ok):
    CHECKS[key] = bool(ok)


def close(A, B, tol):
    """Every entry of A - B below tol in size (numbers shown to four decimals)."""
    D = sp.Matrix(A) - sp.Matrix(B)
    return all(abs(sp.N(e)) < tol for e in D)


m, R_, h = sp.symbols('m R h', positive=True)
# Problem 1
h_fig = 2 * R_
Iyy = m * (3 * R_**2 + h**2) / 12
check(34, zero(Iyy.subs(h, h_fig) - sp.Rational(7, 12) * m * R_**2))
Ip = sp.diag(m * R_**2 / 2, Iyy.subs(h, h_fig), Iyy.subs(h, h_fig))
x, y, z = sp.symbols('x y z')
d = sp.Matrix([x, y, z])
Ipat_gen = m * (d.dot(d) * sp.eye(3) - d * d.T)
Ipat_shown = m * sp.Matrix([[y**2 + z**2, -x * y, -x * z], [-x * y, x**2 + z**2, -y * z],
                            [-x * z, -y * z, x**2 + y**2]])
Ipat = Ipat_gen.subs({x: R_, y: R_, z: 0})
check(54, zero(Ipat_gen - Ipat_shown)
      and zero(Ipat - m * sp.Matrix([[R_**2, -R_**2, 0], [-R_**2, R_**2, 0], [0, 0, 2 * R_**2]])))
Rot = Rz(sp.pi / 4)
check(62, close(Rot, [[0.7071, -0.7071, 0], [0.7071, 0.7071, 0], [0, 0, 1]], 5e-5))
Ixyz = (Rot.T * (Ip + Ipat) * Rot / (m * R_**2)).applyfunc(sp.simplify)
check(68, close(Ixyz, [[0.5417, 0.0417, 0], [0.0417, 2.5417, 0], [0, 0, 2.5833]], 5e-5))
# Problem 2
lam, th = sp.symbols('lambda theta')
I2 = sp.Matrix([[400, 0, -125], [0, 350, 0], [-125, 0, 100]])
charpoly = (I2 - lam * sp.eye(3)).det()
check(95, zero(charpoly - (-lam**3 + 850 * lam**2 - 199375 * lam + 8531250)))
roots = sorted(sp.N(r) for r in sp.solve(charpoly, lam))
check(100, close(sp.diag(*roots), sp.diag(54.7438, 350, 445.2562), 5e-5))
ID = sp.diag(*roots)
Ry_th = Ry(th)
assert zero(Ry_th - sp.Matrix([[sp.cos(th), 0, sp.sin(th)], [0, 1, 0], [-sp.sin(th), 0, sp.cos(th)]]))
# the root of the first entry of I = R I_D R^T near the theta = -1.2234 the solution reports
theta = sp.nsolve((Ry_th * ID * Ry_th.T)[0, 0] - 400, th, -1.2234)
assert abs(theta + 1.2234) < 5e-5
R2 = Ry_th.subs(th, theta)
check(124, close(R2, [[0.3404, 0, -0.9403], [0, 1, 0], [0.9403, 0, 0.3404]], 5e-5))
R2s = sp.Matrix([[0.3404, 0, -0.9403], [0, 1, 0], [0.9403, 0, 0.3404]])
# the product of the rounded entries: each entry of R off by at most 5e-5 moves R I_D R^T by < 0.1
check(129, close(R2s * sp.diag(54.7438, 350, 445.2562) * R2s.T, I2, 0.1))
check(134, close(R2s.T * R2s, sp.eye(3), 2e-4) and close(R2s * R2s.T, sp.eye(3), 2e-4))
check(138, abs(sp.N(R2s.det()) - 1) < 2e-4)
check(142, all(abs(sp.N(R2s[:, k].norm()) - 1) < 2e-4 for k in range(3)))

LINES = [34, 44, 49, 54, 62, 68, 86, 95, 100, 106, 110, 114, 119, 124, 129, 134, 138, 142]
NC, H_ = "not a claim", "holds"
ROWS = {
    34: (H_, "the appendix's centroidal moments of a cylinder, with h = 2R (the figure's length): "
              "m(3R^2 + 4R^2)/12 = 7 m R^2/12 (check 34)"),
    44: (NC, "the moments of line 34 set as a diagonal matrix, naming it I_{x'y'z'}"),
    49: (NC, "the centroid's offset in the body frame, read from the figure"),
    54: (H_, "m(|d|^2 1 - d d^T) written out, then at (x, y, z) = (R, R, 0): m[[R^2, -R^2, 0], [-R^2, R^2, 0], "
              "[0, 0, 2R^2]] (check 54)"),
    62: (H_, "R_z(theta) at theta = pi/4: cos = sin = 0.7071 to four decimals (check 62)"),
    68: (H_, "R^T (I' + I_pat) R with R = R_z(pi/4): (3/2 + 19/12 - 2)/2 = 0.5417, (19/12 - 3/2)/2 = 0.0417, "
              "(3/2 + 19/12 + 2)/2 = 2.5417, 31/12 = 2.5833, times m R^2 (check 68)"),
    86: (NC, "the given inertia matrix of Problem 2's statement"),
    95: (H_, "det(I - lambda 1) = (350 - lambda)((400 - lambda)(100 - lambda) - 125^2) = -lambda^3 + 850 lambda^2 "
              "- 199375 lambda + 8531250 (check 95)"),
    100: (H_, "the roots 250 -+ sqrt(38125) = 54.7438, 445.2562 and 350, to four decimals (check 100)"),
    106: (NC, "the form sought for the transformation, a turn about y by an unknown theta"),
    110: (NC, "the relation that defines the transformation sought"),
    114: (NC, "an equation for the unknown theta, which the solution solves next (its right side is R_y(theta) "
               "I_D R_y(theta)^T written out)"),
    119: (NC, "the first entry of line 114, an equation for theta"),
    124: (H_, "R_y(theta) at the root theta = -1.22343 of the first entry of I = R I_D R^T: cos = 0.3404, sin = -0.9403 to four decimals (check 124)"),
    129: (H_, "the rounded R times diag(54.7438, 350, 445.2562) times its transpose gives back the given matrix "
               "to the rounding of four decimals (check 129)"),
    134: (H_, "the rounded R is orthogonal to the rounding of four decimals (check 134)"),
    138: (H_, "det R = cos^2 + sin^2 = 1 to the rounding (check 138)"),
    142: (H_, "each column of the rounded R has unit length to the rounding (check 142)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
