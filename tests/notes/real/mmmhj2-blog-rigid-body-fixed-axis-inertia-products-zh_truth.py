"""Independent SymPy truth table for mmmhj2-blog-rigid-body-fixed-axis-inertia-products-zh.md.

The post's own setting. Plane motion: two points A, B of a rigid body, r_AB = r_B - r_A, the body turning
with angular velocity omega and angular acceleration alpha (vectors along the plane's normal k).
Rotation about a fixed axis z: particles m_i at body coordinates (x_i, y_i, z_i) in a frame Oxyz fixed
in the body, O on the axis, omega = omega k, alpha = alpha k; J_z = sum m_i (x_i^2 + y_i^2), the products
of inertia J_xz = sum m_i x_i z_i, J_yz = sum m_i y_i z_i; the inertial (d'Alembert) force of a particle is
-m_i a_i. Two bearings on the axis, A at z = l_OA and B at z = -l_OB (the post's signs of the moment
equations put them so), l_AB = l_OA + l_OB. Every check is built from these definitions with a
concrete set of particles or generic symbols, never from the post's later displays.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero


t = sp.symbols("t", real=True)
k = sp.Matrix([0, 0, 1])
# ---------------------------------------------------------------- plane motion
phi = sp.Function("phi")(t)
xa, ya = sp.Function("x_A")(t), sp.Function("y_A")(t)
s1, s2 = sp.symbols("s1 s2", real=True)                  # B's body coordinates relative to A
Rz = sp.Matrix([[sp.cos(phi), -sp.sin(phi), 0], [sp.sin(phi), sp.cos(phi), 0], [0, 0, 1]])
rA = sp.Matrix([xa, ya, 0])
rAB = Rz * sp.Matrix([s1, s2, 0])
rB = rA + rAB
om = phi.diff(t) * k
al = phi.diff(t, 2) * k
vA, vB = rA.diff(t), rB.diff(t)
aA, aB = vA.diff(t), vB.diff(t)
# 24: v_B = v_A + v_BA = v_A + omega x r_AB
check(24, zero(vB - vA - om.cross(rAB)))
# 28: projections of v_A and v_B on AB agree (the post's v_a is v_A)
check(28, zero((vB - vA).dot(rAB)))
# 32: with v_A = 0 (A the instantaneous centre), v_B = omega x r_AB
check(32, zero((vB - om.cross(rAB)).subs({xa.diff(t): 0, ya.diff(t): 0})))
# 40, 44: a_B = a_A + alpha x r_AB + omega x (omega x r_AB)
at, an = al.cross(rAB), om.cross(om.cross(rAB))
check(40, zero(aB - aA - at - an))
check(44, zero(aB - aA - at - an))
# 48: |a^t| = alpha |AB| along the tangent k x e_AB; a^n = omega^2 |AB| along the inward normal -e_AB
AB = sp.sqrt(s1**2 + s2**2)
eAB = rAB / AB
check(48, zero(at - phi.diff(t, 2) * AB * k.cross(eAB)) and zero(an - phi.diff(t)**2 * AB * (-eAB)))
# 52: with a_A = 0 (A the centre of acceleration), a_B = a^t + a^n
check(52, zero((aB - at - an).subs({xa.diff(t, 2): 0, ya.diff(t, 2): 0})))

# ---------------------------------------------------------------- fixed axis, particles
w, a = sp.symbols("omega alpha", real=True)
parts = [(2, sp.Matrix([1, 0, 3])), (3, sp.Matrix([0, 2, -1])), (5, sp.Matrix([-1, 1, 2]))]
M = sum(m for m, _ in parts)
Jz = sum(m * (p[0]**2 + p[1]**2) for m, p in parts)
Jxz = sum(m * p[0] * p[2] for m, p in parts)
Jyz = sum(m * p[1] * p[2] for m, p in parts)
xC = sum(m * p[0] for m, p in parts) / M
yC = sum(m * p[1] for m, p in parts) / M
W = w * k
# 62: sum r_i x m_i (omega x r_i) = omega sum m_i r_i^2, r_i the perpendicular from the axis
perp = [(m, sp.Matrix([p[0], p[1], 0])) for m, p in parts]
Lz = sum((m * r.cross(W.cross(r)) for m, r in perp), sp.zeros(3, 1))
mid = sum((m * W * r.dot(r) - m * r * r.dot(W) for m, r in perp), sp.zeros(3, 1))
check(62, zero(Lz - mid) and zero(mid - W * sum(m * r.dot(r) for m, r in perp)))
# 73: L_z = omega sum m r^2 = J_z omega
check(73, zero(Lz[2] - w * Jz))
# 77, 81: for a body turning about z, d(sum (r x m v)_z)/dt equals the z moment of the forces m a
th = sp.Function("theta")(t)
Rt = sp.Matrix([[sp.cos(th), -sp.sin(th), 0], [sp.sin(th), sp.cos(th), 0], [0, 0, 1]])
Lz_t = sum(m * ((Rt * p).cross((Rt * p).diff(t)))[2] for m, p in parts)
Mz_t = sum(m * ((Rt * p).cross((Rt * p).diff(t, 2)))[2] for m, p in parts)
check(77, zero(Lz_t - Jz * th.diff(t)) and zero(Lz_t.diff(t) - Mz_t))
check(81, zero(Jz * th.diff(t, 2) - Mz_t))
# 87: rho_z^2 = sum m r^2 / m (root-mean-square distance) = J_z / m
check(87, zero(sp.sqrt(sum(m * (p[0]**2 + p[1]**2) for m, p in parts) / M) - sp.sqrt(Jz / M)))
# 91: parallel axes: J about an axis through (ex, ey) parallel to z
ex, ey = sp.Rational(3, 2), -2
JC = sum(m * ((p[0] - xC)**2 + (p[1] - yC)**2) for m, p in parts)
Jp = sum(m * ((p[0] - ex)**2 + (p[1] - ey)**2) for m, p in parts)
d2 = (xC - ex)**2 + (yC - ey)**2
check(91, zero(Jp - (JC + M * d2)))
# 97, 101: T = 1/2 m v_c^2 + 1/2 J_C omega^2 for the body turning about the z axis
T = sum(m * (W.cross(sp.Matrix([p[0], p[1], 0]))).dot(W.cross(sp.Matrix([p[0], p[1], 0]))) for m, p in parts) / 2
vc2 = (w**2) * (xC**2 + yC**2)
check(97, zero(T - (M * vc2 / 2 + JC * w**2 / 2)))
Jz0 = Jz                                              # the axis through O, a distance |OC| from C
check(101, zero(T - (M * vc2 / 2 + (Jz0 - M * (xC**2 + yC**2)) * w**2 / 2)))
# 117, 121, 127: accelerations of a particle (x, y, z) of the body
x, y, z = sp.symbols("x y z", real=True)
r = sp.Matrix([x, y, z])
A = a * k
a_t = A.cross(r)
a_n = W.cross(W.cross(r))
check(117, zero(a_t + a_n - (A.cross(r) + W.cross(W.cross(r)))))
check(121, zero(a_t - a * (x * sp.Matrix([0, 1, 0]) - y * sp.Matrix([1, 0, 0]))))
# 127: the chain is the normal acceleration, -omega^2 (x i + y j); its left side names the tangential one
chain_ok = zero(a_n - w**2 * (k.cross(k.cross(r)))) and zero(a_n + w**2 * sp.Matrix([x, y, 0]))
check(127, chain_ok and zero(a_t - a_n))
assert chain_ok and not zero(a_t - a_n)
# 135: the inertial force -m a; the post writes -(a y + w^2 x) i + (a x - w^2 y) j, without m
m_ = sp.symbols("m_i", positive=True)
F_in = -m_ * (a_t + a_n)
written = sp.Matrix([-(a * y + w**2 * x), a * x - w**2 * y, 0])
check(135, zero(F_in - written))
assert zero(F_in - m_ * sp.Matrix([a * y + w**2 * x, -a * x + w**2 * y, 0]))        # the correction
# 139: r x F_in, written as the determinant, expanded
check(139, zero(r.cross(F_in) - m_ * sp.Matrix([a * x * z - w**2 * y * z, a * y * z + w**2 * x * z,
                                                -a * (x**2 + y**2)])))
# 154: summed over the particles: F = m[(a y_C + w^2 x_C) i + m (w^2 y_C - a x_C) j] (a second m)
F_tot = sum((-m * (A.cross(p) + W.cross(W.cross(p))) for m, p in parts), sp.zeros(3, 1))
M_tot = sum(((p).cross(-m * (A.cross(p) + W.cross(W.cross(p)))) for m, p in parts), sp.zeros(3, 1))
written_F = M * sp.Matrix([a * yC + w**2 * xC, M * (w**2 * yC - a * xC), 0])
M_sum = sum((m * sp.Matrix([a * p[0] * p[2] - w**2 * p[1] * p[2], a * p[1] * p[2] + w**2 * p[0] * p[2],
                            -a * (p[0]**2 + p[1]**2)]) for m, p in parts), sp.zeros(3, 1))
check(154, zero(F_tot - written_F) and zero(M_tot - M_sum))
assert zero(F_tot - M * sp.Matrix([a * yC + w**2 * xC, w**2 * yC - a * xC, 0])) and zero(M_tot - M_sum)
# 169: M_O = (J_xz a - J_yz w^2) i + (J_yz a + J_xz w^2) j - J_z a k
check(169, zero(M_tot - sp.Matrix([Jxz * a - Jyz * w**2, Jyz * a + Jxz * w**2, -Jz * a])))
# 185, 200: bearings A at z = l_OA and B at z = -l_OB; d'Alembert: applied + reactions + inertial = 0
lA, lB = sp.symbols("l_OA l_OB", positive=True)
FAx, FAy, FBx, FBy, FBz = sp.symbols("F_Ax F_Ay F_Bx F_By F_Bz")
Fx, Fy, Fz, Mx, My, Mz = sp.symbols("F_x F_y F_z M_x M_y M_z")   # sums of the applied forces and moments
FI, MI = F_tot, M_tot
force = sp.Matrix([Fx, Fy, Fz]) + sp.Matrix([FAx, FAy, 0]) + sp.Matrix([FBx, FBy, FBz]) + FI
moment = (sp.Matrix([Mx, My, Mz]) + sp.Matrix([0, 0, lA]).cross(sp.Matrix([FAx, FAy, 0]))
          + sp.Matrix([0, 0, -lB]).cross(sp.Matrix([FBx, FBy, FBz])) + MI)
rows = sp.Matrix([Fx + FAx + FBx + FI[0], Fy + FAy + FBy + FI[1], Fz + FBz,
                  Mx - FAy * lA + FBy * lB + MI[0], My + FAx * lA - FBx * lB + MI[1], Mz + MI[2]])
check(185, FI[2] == 0 and zero(sp.Matrix([*force, *moment]) - rows))
sol = sp.solve(list(rows), [FAx, FAy, FBx, FBy, FBz], dict=True)[0]
lAB = lA + lB
check(200, zero(sol[FAx] - (-(My + Fx * lB) / lAB - (MI[1] + FI[0] * lB) / lAB)))
# 208: F_Ix = F_Iy = 0 and M_Ix = M_Iy = 0 are the stated conditions (generic body)
xc, yc, jxz, jyz, mm = sp.symbols("x_C y_C J_xz J_yz m", real=True)
FIg = mm * sp.Matrix([a * yc + w**2 * xc, w**2 * yc - a * xc])
MIg = sp.Matrix([jxz * a - jyz * w**2, jyz * a + jxz * w**2])
check(208, zero(FIg / mm - sp.Matrix([xc * w**2 + yc * a, yc * w**2 - xc * a])) and zero(
    MIg - sp.Matrix([jxz * a - jyz * w**2, jyz * a + jxz * w**2])))
# 222: for all omega, alpha the only solution is x_C = y_C = J_xz = J_yz = 0 (determinant w^4 + a^2)
mat = sp.Matrix([[w**2, a], [-a, w**2]])
check(222, sp.factor(mat.det()) == w**4 + a**2 and sp.solve([xc * w**2 + yc * a, yc * w**2 - xc * a], [xc, yc])
      == {xc: 0, yc: 0})

# negative control: the particle set is not balanced, so the checks above can fail
assert not zero(F_tot)

LINES = [24, 28, 32, 40, 44, 48, 52, 62, 73, 77, 81, 87, 91, 97, 101, 107, 111, 117, 121, 127, 135, 139,
         154, 161, 169, 177, 181, 185, 200, 208, 222]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
