"""Independent SymPy truth table for moore-learn-multibody-dynamics-mass-distribution.md.

The text's own setting (Kane's notation): particles P_i of masses m_i at positions r^{P_i/O}
relative to a point O, written in the components of one frame; unit vectors n_a, n_b; the unit
dyadic U is the identity and a dyadic is a 3x3 matrix acting on a vector from the left
(n . D = D^T n) or the right (D . n = D n); u (x) v is u v^T. The inertia vector is
I_a = sum m r x (n_a x r), the inertia scalar I_ab = I_a . n_b, the inertia dyadic
I^{S/O} = sum m (|r|^2 U - r (x) r), the angular momentum H = I . omega. A solid body is the
same with the sums read as integrals of rho dV (the checks use particles: a sum of generic
particles stands for the integral's integrand). Every check is built here from these definitions,
never from the text's later displays.
"""
import sys

import numpy as np
import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


def zero(expr):
    m = expr if hasattr(expr, "shape") else sp.Matrix([expr])
    return sp.simplify(m.applyfunc(lambda e: sp.expand(sp.together(e)))) == sp.zeros(*m.shape)


N = 3
m = sp.symbols(f"m_1:{N + 1}", positive=True)
r = [sp.Matrix(sp.symbols(f"x_{i} y_{i} z_{i}", real=True)) for i in range(1, N + 1)]
a = sp.Matrix(sp.symbols("a_x a_y a_z", real=True))
na = a          # n_a: the identities below are linear in it (85 and 92 put |n_a| = 1 in by hand)
b = sp.Matrix(sp.symbols("b_x b_y b_z", real=True))
nb = b
U = sp.eye(3)


def outer(u, v):
    return u * v.T


def inertia_vector(n, pts=None):
    pts = pts if pts is not None else list(zip(m, r))
    return sum((mi * ri.cross(n.cross(ri)) for mi, ri in pts), sp.zeros(3, 1))


def dyadic(pts=None):
    pts = pts if pts is not None else list(zip(m, r))
    return sum((mi * (ri.dot(ri) * U - outer(ri, ri)) for mi, ri in pts), sp.zeros(3, 3))


# 54, 60: the mass centre: with s = r^{S_o/O}, sum m (r_i - s) = 0 gives s = sum m r_i / sum m
s = sp.Matrix(sp.symbols("s_x s_y s_z", real=True))
sol = sp.solve(list(sum((mi * (ri - s) for mi, ri in zip(m, r)), sp.zeros(3, 1))), list(s), dict=True)[0]
centre = sum((mi * ri for mi, ri in zip(m, r)), sp.zeros(3, 1)) / sum(m)
check(54, zero(s.subs(sol) - centre))
check(60, CHECKS[54])                     # the integral form: the same linear solve with sums as integrals

# 85, 92: one particle: |I_a| = m |r|^2 |sin theta|, and m |r|^2 when n_a is perpendicular to r
M = sp.symbols("m", positive=True)
rp = r[0]
Ia1 = M * rp.cross(na.cross(rp))
sin2 = 1 - rp.dot(na)**2 / (rp.dot(rp) * na.dot(na))       # sin^2 of the angle between r and n_a
check(85, zero(Ia1.dot(Ia1) - (M * rp.dot(rp))**2 * na.dot(na) * sin2))   # |n_a|^2 = 1 for a unit vector
perp = {a[0]: -rp[1], a[1]: rp[0], a[2]: 0}                # n_a perpendicular to r
check(92, zero((Ia1.dot(Ia1) - (M * rp.dot(rp))**2 * na.dot(na)).subs(perp)))

# 104, 114, 121: I_ab = I_a . n_b = sum m (r x n_a).(r x n_b), symmetric; I_aa with n_b = n_a
Iab = inertia_vector(na).dot(nb)
form = sum(mi * ri.cross(na).dot(ri.cross(nb)) for mi, ri in zip(m, r))
check(104, zero(Iab - form))
check(114, zero(Iab - inertia_vector(nb).dot(na)))
check(121, zero(inertia_vector(na).dot(na) - sum(mi * ri.cross(na).dot(ri.cross(na)) for mi, ri in zip(m, r))))

# 172: the outer product of two columns
v = sp.Matrix(sp.symbols("v_1:4"))
w = sp.Matrix(sp.symbols("w_1:4"))
check(172, zero(outer(v, w) - sp.Matrix(3, 3, lambda i, j: v[i] * w[j])))

# 206, 213, 221, 231, 252: the inertia vector, its triple-product form, with U, n_a out of the sum, I_a = n_a . I
Ia = inertia_vector(na)
check(206, zero(Ia - inertia_vector(na)))
check(213, zero(Ia - sum((mi * (na * ri.dot(ri) - ri * ri.dot(na)) for mi, ri in zip(m, r)), sp.zeros(3, 1))))
left = lambda n, D: D.T * n                                # noqa: E731  (n . D)
check(221, zero(Ia - sum((mi * (ri.dot(ri) * left(na, U) - left(na, outer(ri, ri))) for mi, ri in zip(m, r)),
                         sp.zeros(3, 1))))
check(231, zero(Ia - left(na, dyadic())))
check(252, zero(Ia - left(na, dyadic())))

# 281, 288: the parallel axis theorem, with the particles placed about their mass centre
d = sp.Matrix(sp.symbols("d_x d_y d_z", real=True))
rel = [r[0], r[1], -(m[0] * r[0] + m[1] * r[1]) / m[2]]    # sum m r^{P_i/B_o} = 0
about_O = dyadic(list(zip(m, [d + q for q in rel])))
central = dyadic(list(zip(m, rel)))
Mtot = sum(m)
check(281, zero(about_O - central - dyadic([(Mtot, d)])))
check(288, zero(dyadic([(Mtot, d)]) - Mtot * (d.dot(d) * U - outer(d, d))))

# 302: in principal axes the dyadic is sum I_kk b_k (x) b_k: a sample body, its eigenvectors (numerically)
pts = [(1, sp.Matrix([1, 2, 0])), (2, sp.Matrix([0, 1, 1])), (3, sp.Matrix([1, 0, 2]))]
D = np.array(dyadic([(sp.Integer(mm), q) for mm, q in pts]).tolist(), dtype=float)
vals, vecs = np.linalg.eigh(D)
recon = sum(vals[k] * np.outer(vecs[:, k], vecs[:, k]) for k in range(3))
check(302, np.allclose(recon, D) and abs(D[0, 1]) > 0.1 and np.allclose(vecs.T @ vecs, np.eye(3)))

# 324: H about B_o = I^{B/B_o} . omega equals sum m r x (omega x r) about B_o
om = sp.Matrix(sp.symbols("omega_1:4", real=True))
H = sum((mi * q.cross(om.cross(q)) for mi, q in zip(m, rel)), sp.zeros(3, 1))
check(324, zero(central * om - H))

# negative controls: the checks above can fail
assert not zero(Iab + form)
assert not zero(about_O - central)
assert not zero(Ia - sum((mi * (ri * ri.dot(ri) - na * ri.dot(na)) for mi, ri in zip(m, r)), sp.zeros(3, 1)))

LINES = [21, 27, 34, 42, 48, 54, 60, 69, 76, 85, 92, 98, 104, 114, 121, 131, 144, 154, 164, 172, 191, 206, 213,
         221, 231, 242, 252, 258, 269, 281, 288, 302, 317, 324]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
