"""Independent SymPy truth table for jingliangwei-blog-landau-rigid-body-inertia-euler-equations-zxz-zh.md.

The notes' own setting (Landau and Lifshitz's chapter on the rigid body). A body of particles with its
centre of mass at the origin of the body's coordinates (the integrals over rho dV become sums over the
particles), mass mu, translational velocity V and angular velocity Omega, so that a particle at r moves
with V + Omega x r. The tensor A of a point is [r^2 delta_ij - x_i x_j] and I = sum m A. For the
kinematics, the body's axes are a rotation R(t); a vector with body components b has the inertial rate
R(b_dot + Omega x b), Omega the body components of R^T R_dot. The Euler angles turn about z by phi, about
the new x by theta and about the new z by psi (R = Rz(phi) Rx(theta) Rz(psi)). Every check is built from
these definitions, never from the notes' later displays.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero
nzero = truth_table.numeric_zero

# ---------------------------------------------------------------- a body of particles, centre of mass at 0
pts = [(2, sp.Matrix([1, 2, -1])), (3, sp.Matrix([-2, 0, 1])), (1, sp.Matrix([4, -4, -1]))]
mu = sum(mi for mi, _ in pts)
assert sum((mi * p for mi, p in pts), sp.zeros(3, 1)) == sp.zeros(3, 1)
Om = sp.Matrix(sp.symbols("Omega_x Omega_y Omega_z", real=True))
V = sp.Matrix(sp.symbols("V1:4", real=True))


def A_of(p):
    return p.dot(p) * sp.eye(3) - p * p.T


I = sum((mi * A_of(p) for mi, p in pts), sp.zeros(3, 3))
# 19: a point of the body moves with V + Omega x r: r_world = X0 + R s, its rate is X0_dot + w x (R s)
t = sp.Symbol("t")
fa, fb, fc = (sp.Function(n)(t) for n in ("phi", "theta", "psi"))
R = truth_table.Rz(fa) * truth_table.Rx(fb) * truth_table.Rz(fc)
X0 = sp.Matrix([sp.Function(f"X{i}")(t) for i in (1, 2, 3)])
s = sp.Matrix(sp.symbols("s1:4", real=True))
Sw = R.diff(t) * R.T
w = sp.Matrix([Sw[2, 1], Sw[0, 2], Sw[1, 0]])
check(19, nzero((X0 + R * s).diff(t) - (X0.diff(t) + w.cross(R * s)), t))
# 27: M = sum r x m v = sum m r x (Omega x r) = sum m (r^2 Omega - (r.Omega) r) = sum m A Omega = I Omega
vel = [V + Om.cross(p) for _, p in pts]
M = sum((mi * p.cross(v) for (mi, p), v in zip(pts, vel)), sp.zeros(3, 1))
steps = [sum((mi * p.cross(Om.cross(p)) for mi, p in pts), sp.zeros(3, 1)),
         sum((mi * (p.dot(p) * Om - p.dot(Om) * p) for mi, p in pts), sp.zeros(3, 1)),
         sum((mi * A_of(p) * Om for mi, p in pts), sp.zeros(3, 1)), I * Om]
check(27, all(zero(M - st) for st in steps))
# 44: the component form of r^2 Omega - (r.Omega) r equals the matrix [[y^2+z^2, -xy, -xz], ...] Omega
x, y, z = sp.symbols("x y z", real=True)
r = sp.Matrix([x, y, z])
Amat = sp.Matrix([[y**2 + z**2, -x * y, -x * z], [-x * y, x**2 + z**2, -y * z], [-x * z, -y * z, x**2 + y**2]])
lhs45 = r.dot(r) * Om - r.dot(Om) * r
check(44, zero(lhs45 - Amat * Om))
# 62: that matrix is [r^2 delta_ij - x_i x_j]
check(62, zero(Amat - A_of(r)))
# 72: I_ij = sum m (r^2 delta_ij - x_i x_j) gives M = I Omega
check(72, zero(M - sum((mi * A_of(p) for mi, p in pts), sp.zeros(3, 3)) * Om))
# 80: T = mu V^2/2 + Omega.I.Omega/2 = mu V^2/2 + sum_ij I_ij Omega_i Omega_j / 2
T = sum((mi * v.dot(v) / 2 for (mi, _), v in zip(pts, vel)), 0)
quad = sum(I[i, j] * Om[i] * Om[j] for i in range(3) for j in range(3))
check(80, zero(sp.expand(T - (mu * V.dot(V) / 2 + (Om.T * I * Om)[0] / 2)))
      and zero(sp.expand(T - (mu * V.dot(V) / 2 + quad / 2))))
# 89: T = sum m|V + Omega x r|^2/2 = sum m(V^2 + 2 V.(Omega x r) + |Omega x r|^2)/2 = (1) + (2) + (3)
p1 = sum(mi * V.dot(V) / 2 for mi, _ in pts)
p2 = sum(mi * V.dot(Om.cross(p)) for mi, p in pts)
p3 = sum(mi * Om.cross(p).dot(Om.cross(p)) / 2 for mi, p in pts)
mid = sum(mi * (V.dot(V) + 2 * V.dot(Om.cross(p)) + Om.cross(p).dot(Om.cross(p))) / 2 for mi, p in pts)
check(89, zero(sp.expand(T - mid)) and zero(sp.expand(mid - (p1 + p2 + p3))))
# 99: (1) = mu V^2/2
check(99, zero(p1 - mu * V.dot(V) / 2))
# 105: (2) = sum m r.(V x Omega) = (V x Omega).sum m r = 0
check(105, zero(sp.expand(p2 - sum(mi * p.dot(V.cross(Om)) for mi, p in pts))) and zero(sp.expand(p2)))
# 111: |Omega x r|^2 = (Omega r sin)^2 = Omega^2 r^2 (1 - cos^2) = Omega^2 r^2 - (Omega.r)^2, cos = Omega.r/(Omega r)
On, rn = sp.sqrt(Om.dot(Om)), sp.sqrt(r.dot(r))
cos = Om.dot(r) / (On * rn)
ch = [Om.cross(r).dot(Om.cross(r)), (On * rn)**2 * (1 - cos**2), On**2 * rn**2 - Om.dot(r)**2]
check(111, zero(sp.expand(ch[0] - ch[2])) and zero(sp.simplify(ch[1] - ch[2])))
# 121: r^2 Omega - (r.Omega) r = A Omega, A the tensor found above
check(121, zero(lhs45 - A_of(r) * Om))
# 127: |Omega x r|^2 = Omega A Omega
check(127, zero(sp.expand(ch[0] - (Om.T * A_of(r) * Om)[0])))
# 131: (3) = sum m|Omega x r|^2/2 = sum m Omega A Omega/2 = Omega I Omega/2
check(131, zero(sp.expand(p3 - sum(mi * (Om.T * A_of(p) * Om)[0] / 2 for mi, p in pts)))
      and zero(sp.expand(p3 - (Om.T * I * Om)[0] / 2)))
# 141: T = mu V^2/2 + Omega I Omega/2 = mu V^2/2 + sum I_ij Omega_i Omega_j/2
check(141, zero(sp.expand(T - (mu * V.dot(V) / 2 + (Om.T * I * Om)[0] / 2))) and zero(sp.expand(T - mu * V.dot(V) / 2 - quad / 2)))
# 154, 160: the inertia tensor about O' (OO' = a): I' = I + mu (a^2 delta - a a^T), step by step
a = sp.Matrix(sp.symbols("a1:4", real=True))
Ip = sum((mi * A_of(p - a) for mi, p in pts), sp.zeros(3, 3))
check(154, zero(sp.expand(Ip - (I + mu * A_of(a)))))
e = sp.eye(3)
s2 = sum((mi * ((p - a).dot(p - a) * e - (p - a) * (p - a).T) for mi, p in pts), sp.zeros(3, 3))
s34 = (sum((mi * (p.dot(p) * e - p * p.T) for mi, p in pts), sp.zeros(3, 3))
       + sum((mi * ((-2 * a.dot(p) + a.dot(a)) * e + a * p.T + p * a.T - a * a.T) for mi, p in pts), sp.zeros(3, 3)))
s5 = I + sum((mi * (a.dot(a) * e - a * a.T) for mi, _ in pts), sp.zeros(3, 3))
s6 = I + mu * (a.dot(a) * e - a * a.T)
check(160, all(zero(sp.expand(Ip - st)) for st in (s2, s34, s5, s6)))
# 187: dL/dOmega = M: the gradient of Omega.I.Omega/2 with I symmetric is I Omega
Isym = sp.Matrix(3, 3, lambda i, j: sp.Symbol(f"I_{min(i, j) + 1}{max(i, j) + 1}"))
Lrot = (Om.T * Isym * Om)[0] / 2
check(187, zero(sp.Matrix([Lrot.diff(o) for o in Om]) - Isym * Om))
# ---------------------------------------------------------------- body-frame rates
Sb = R.T * R.diff(t)
Ob = sp.Matrix([Sb[2, 1], Sb[0, 2], Sb[1, 0]])
b = sp.Matrix([sp.Function(f"b{i}")(t) for i in (1, 2, 3)])
# 221: a vector fixed in the body, R b0: its rate is w x (R b0), w = R Omega_body
b0 = sp.Matrix(sp.symbols("c1:4", real=True))
check(221, nzero((R * b0).diff(t) - w.cross(R * b0), t) and nzero(w - R * Ob, t))
# 227: dA/dt = d'A/dt + Omega x A (body components: R^T d(R b)/dt = b_dot + Omega x b)
check(227, nzero(R.T * (R * b).diff(t) - (b.diff(t) + Ob.cross(b)), t))
# 233, 236: the laws dp/dt = F, dM/dt = K in body components
check(233, nzero(R.T * (R * b).diff(t) - (b.diff(t) + Ob.cross(b)), t))
check(236, nzero(R.T * (R * b).diff(t) - (b.diff(t) + Ob.cross(b)), t))
# 201: Euler's equations: mu(V_dot + Omega x V) for the translation, I Omega_dot + Omega x (I Omega) for the rotation
I1, I2, I3 = sp.symbols("I1:4", positive=True)
Vb = sp.Matrix([sp.Function(f"V{i}")(t) for i in (1, 2, 3)])
Obs = sp.Matrix([sp.Function(f"W{i}")(t) for i in (1, 2, 3)])
musym = sp.Symbol("mu", positive=True)
trans = musym * (Vb.diff(t) + Obs.cross(Vb))
claim_t = musym * sp.Matrix([Vb[0].diff(t) + Obs[1] * Vb[2] - Obs[2] * Vb[1],
                             Vb[1].diff(t) + Obs[2] * Vb[0] - Obs[0] * Vb[2],
                             Vb[2].diff(t) + Obs[0] * Vb[1] - Obs[1] * Vb[0]])
Id = sp.diag(I1, I2, I3)
rotn = Id * Obs.diff(t) + Obs.cross(Id * Obs)
claim_r = sp.Matrix([I1 * Obs[0].diff(t) + (I3 - I2) * Obs[1] * Obs[2],
                     I2 * Obs[1].diff(t) + (I1 - I3) * Obs[0] * Obs[2],
                     I3 * Obs[2].diff(t) + (I2 - I1) * Obs[0] * Obs[1]])
check(201, zero(trans - claim_t) and zero(rotn - claim_r))
# 260: the body components of Omega in z-x-z angles
claim261 = sp.Matrix([fa.diff(t) * sp.sin(fb) * sp.sin(fc) + fb.diff(t) * sp.cos(fc),
                      fa.diff(t) * sp.sin(fb) * sp.cos(fc) - fb.diff(t) * sp.sin(fc),
                      fa.diff(t) * sp.cos(fb) + fc.diff(t)])
check(260, zero(Ob - claim261))
# 270: T = (I1 O1^2 + I2 O2^2 + I3 O3^2)/2 = I1(phi_dot^2 sin^2 + theta_dot^2)/2 + I3(phi_dot cos + psi_dot)^2/2
# for the symmetric top I1 = I2 the section turns to (for I1 != I2 the second step drops (I2 - I1) O2^2/2)
Tk = (I1 * claim261[0]**2 + I2 * claim261[1]**2 + I3 * claim261[2]**2) / 2
right271 = I1 * (fa.diff(t)**2 * sp.sin(fb)**2 + fb.diff(t)**2) / 2 + I3 * (fa.diff(t) * sp.cos(fb) + fc.diff(t))**2 / 2
check(270, zero(sp.simplify((Tk - right271).subs(I2, I1))))

# negative control: a wrong sign in Euler's equations is caught
assert not zero(rotn - claim_r.subs(I3 - I2, I2 - I3))

LINES = [19, 27, 38, 44, 62, 72, 80, 89, 99, 105, 111, 121, 127, 131, 141, 154, 160, 175, 178, 181, 187, 190, 193, 201, 218, 221, 227, 233, 236, 244, 250, 260, 270]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
