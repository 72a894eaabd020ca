"""Independent SymPy truth table for siiea-quantum-engineering-rigid-body-kinematics-inertia-tensor.md.

The course's convention: R is the rotation matrix (R^T R = 1, det R = 1) with dR/dt = w~ R, w~ the
antisymmetric matrix of the angular velocity w; in the kinetic energy R is instead the position of
the centre of mass and r'_alpha the particle's position from it (sum m_alpha r'_alpha = 0); the
inertia tensor is I_ij = sum m (|r'|^2 delta_ij - r'_i r'_j), the principal moments its eigenvalues.
Sums over the body are checked on three mass points with the centre-of-mass condition imposed; the
rod and the cube are integrated here with uniform density.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}
zero = truth_table.zero


def check(key, ok):
    CHECKS[key] = bool(ok)


wx, wy, wz = sp.symbols('omega_x omega_y omega_z', real=True)
w = sp.Matrix([wx, wy, wz])
wt = sp.Matrix([[0, -wz, wy], [wz, 0, -wx], [-wy, wx, 0]])     # 47
r = sp.Matrix(sp.symbols('x y z', real=True))
# 51: a point r = R r0 moves with v = dR/dt r0 = w~ R r0 = w~ r, which is w x r
check(51, zero(wt * r - w.cross(r)))

# three mass points about the centre of mass: the third offset is fixed by sum m r' = 0
N = 3
ms = sp.symbols('m0:3', positive=True)
M = sum(ms)
q = [sp.Matrix(sp.symbols(f'x{k} y{k} z{k}', real=True)) for k in range(2)]
q.append(-(ms[0] * q[0] + ms[1] * q[1]) / ms[2])
Vc = sp.Matrix(sp.symbols('V_x V_y V_z', real=True))           # velocity of the centre of mass
vel = [Vc + w.cross(q[k]) for k in range(N)]
T = sum(ms[k] * vel[k].dot(vel[k]) for k in range(N)) / 2
# 62: T = M |R'|^2 / 2 + sum m |w x r'|^2 / 2
check(62, zero(T - (M * Vc.dot(Vc) / 2 + sum(ms[k] * w.cross(q[k]).dot(w.cross(q[k])) for k in range(N)) / 2)))
Iten = sum((ms[k] * (q[k].dot(q[k]) * sp.eye(3) - q[k] * q[k].T) for k in range(N)), sp.zeros(3, 3))   # 72
Trot = sum(ms[k] * w.cross(q[k]).dot(w.cross(q[k])) for k in range(N)) / 2
# 66: T_rot = w^T I w / 2 = sum_ij I_ij w_i w_j / 2
check(66, zero(Trot - (w.T * Iten * w)[0] / 2)
      and zero((w.T * Iten * w)[0] - sum(Iten[a, b] * w[a] * w[b] for a in range(3) for b in range(3))))
# 84: the diagonal elements
check(84, all(zero(Iten[n, n] - sum(ms[k] * (q[k].dot(q[k]) - q[k][n] ** 2) for k in range(N))) for n in range(3))
      and zero(Iten[0, 0] - sum(ms[k] * (q[k][1] ** 2 + q[k][2] ** 2) for k in range(N)))
      and zero(Iten[1, 1] - sum(ms[k] * (q[k][0] ** 2 + q[k][2] ** 2) for k in range(N)))
      and zero(Iten[2, 2] - sum(ms[k] * (q[k][0] ** 2 + q[k][1] ** 2) for k in range(N))))
# 88: I_xy = -sum m x y
check(88, zero(Iten[0, 1] + sum(ms[k] * q[k][0] * q[k][1] for k in range(N))))
# 100: in principal axes (I diagonal) T_rot = (I1 w1^2 + I2 w2^2 + I3 w3^2) / 2
I1, I2, I3 = sp.symbols('I1:4', positive=True)
check(100, zero((w.T * sp.diag(I1, I2, I3) * w)[0] / 2 - (I1 * wx ** 2 + I2 * wy ** 2 + I3 * wz ** 2) / 2))
# 114: the rod
Mr, Lr = sp.symbols('M L', positive=True)
xs = sp.Symbol('x', real=True)
rho = Mr / Lr
members = [sp.integrate(rho * xs ** 2, (xs, -Lr / 2, Lr / 2)),
           (rho * xs ** 3 / 3).subs(xs, Lr / 2) - (rho * xs ** 3 / 3).subs(xs, -Lr / 2),
           Mr / Lr * Lr ** 3 / 12, Mr * Lr ** 2 / 12]
check(114, all(zero(a - members[-1]) for a in members[:-1]))
# 121: the cube of side a about axes through its centre parallel to its edges
a = sp.Symbol('a', positive=True)
ys, zs = sp.symbols('y z', real=True)
dens = Mr / a ** 3
cube = lambda f: sp.integrate(dens * f, (xs, -a / 2, a / 2), (ys, -a / 2, a / 2), (zs, -a / 2, a / 2))  # noqa: E731
check(121, all(zero(cube(f) - Mr * a ** 2 / 6) for f in (ys ** 2 + zs ** 2, xs ** 2 + zs ** 2, xs ** 2 + ys ** 2))
      and all(zero(cube(f)) for f in (xs * ys, xs * zs, ys * zs)))
assert not zero(cube(ys ** 2 + zs ** 2) - Mr * a ** 2 / 12)      # a wrong value is caught

LINES = [23, 33, 43, 47, 51, 62, 66, 72, 76, 80, 84, 88, 95, 100, 107, 114, 121]
NC, H = "not a claim", "holds"
ROWS = {
    23: (NC, "the defining properties of a rotation matrix (orthogonal, determinant one)"),
    33: (NC, "the course's convention for the Euler angles: the product of the three elemental rotations"),
    43: (NC, "ties the angular velocity to the rotation matrix: dR/dt = w~ R, the definition the section uses"),
    47: (NC, "defines the antisymmetric matrix w~ of the angular velocity"),
    51: (H, "a point r = R r0 moves with dR/dt r0 = w~ r, and w~ r = w x r with the matrix of the previous display (check 51)"),
    62: (H, "with r'_alpha measured from the centre of mass, the cross term M V . (w x sum m r'/M) vanishes and T splits "
            "into the translational and the rotational parts (check 62)"),
    66: (H, "sum m |w x r'|^2 / 2 = w^T I w / 2 with the tensor defined next, and w^T I w = sum I_ij w_i w_j (check 66)"),
    72: (NC, "defines the inertia tensor as a sum over the particles"),
    76: (NC, "defines the inertia tensor of a continuous body as an integral"),
    80: (NC, "names the elements of the inertia tensor as a matrix"),
    84: (H, "the diagonal elements of sum m (r^2 delta_ij - r_i r_j): r^2 - x^2 = y^2 + z^2 and so on (check 84)"),
    88: (H, "an off-diagonal element: delta_xy = 0 leaves -sum m x y (check 88)"),
    95: (NC, "the eigenvalue problem whose solutions define the principal axes and moments"),
    100: (H, "w^T I w / 2 with I diagonal, diag(I1, I2, I3), in the principal frame (check 100)"),
    107: (NC, "quotes the rotational energy levels of a quantum rigid rotor, outside the classical derivation"),
    114: (H, "the integral of (M/L) x^2 from -L/2 to L/2: x^3/3 between the limits is L^3/24 + L^3/24 = L^3/12, so I = (M/L) L^3/12 = M L^2/12 (check 114)"),
    121: (H, "the cube about axes through its centre: (M/a^3) times the integral of y^2 + z^2 over the cube is M a^2/6, "
             "and the products vanish by symmetry (check 121)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
