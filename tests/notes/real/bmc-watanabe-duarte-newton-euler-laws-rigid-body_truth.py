"""Independent SymPy truth table for bmc-watanabe-duarte-newton-euler-laws-rigid-body.ipynb.

The notebook's convention: a vector r_{A/B} runs from the point B to the point A (it says so of
r_{i/O}, from O to the point where F_i acts); the moment about O is M_O = sum r_{i/O} x F_i plus the
free moments; H_O is the angular momentum about O, L the linear momentum, m_B = sum m_i the mass of
the body. Sums over the body are checked on three mass points with symbolic positions, velocities
and accelerations given as functions of time, so the steps that differentiate are done by SymPy;
the planar second law is checked on a body turning in the xy plane (positions about the centre of
mass at a common angle phi(t)), with the point O fixed.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}
zero = truth_table.zero


def check(key, ok):
    CHECKS[key] = bool(ok)


t = sp.Symbol('t')
i_, j_, k_ = sp.eye(3)[:, 0], sp.eye(3)[:, 1], sp.eye(3)[:, 2]
m = sp.Symbol('m', positive=True)
r = sp.Matrix([sp.Function(f'r{c}')(t) for c in 'xyz'])     # a particle's position from the fixed point O
F = sp.Matrix(sp.symbols('F_x F_y F_z', real=True))
v = r.diff(t)
L = m * v                                                     # 31: L = m v
H = r.cross(L)                                                # 37: H_O = r_O x L
newton = {sp.Derivative(r[n], (t, 2)): F[n] / m for n in range(3)}   # the particle's second law, F = m a

# 57: M = dH/dt = dr/dt x L + r x dL/dt = dr/dt x (m v) + r x d(m v)/dt = v x (m v) + r x d(m v)/dt = 0 + r x F
members = [H.diff(t), v.cross(L) + r.cross(L.diff(t)), v.cross(m * v) + r.cross((m * v).diff(t)),
           v.cross(m * v) + r.cross((m * v).diff(t)), r.cross(F)]
check(57, all(zero((a - members[-1]).subs(newton)) for a in members[:-1]) and zero(v.cross(m * v)))
# 60: M = r x F
check(60, zero((H.diff(t) - r.cross(F)).subs(newton)))
# 62: (r_x i + r_y j + r_z k) x (F_x i + F_y j + F_z k)
check(62, zero((r[0] * i_ + r[1] * j_ + r[2] * k_).cross(F[0] * i_ + F[1] * j_ + F[2] * k_) - r.cross(F)))
# 68: the determinant with the unit vectors in the first row, expanded along that row
det = i_ * (r[1] * F[2] - r[2] * F[1]) - j_ * (r[0] * F[2] - r[2] * F[0]) + k_ * (r[0] * F[1] - r[1] * F[0])
check(68, zero(det - r.cross(F)))
# 78: components
check(78, zero((r[1] * F[2] - r[2] * F[1]) * i_ + (r[2] * F[0] - r[0] * F[2]) * j_
               + (r[0] * F[1] - r[1] * F[0]) * k_ - r.cross(F)))
# 90: |r x F| = |r||F| sin(theta), theta the angle between them (r and F in the xy plane at angles a, b)
ra, fa, a, b = sp.symbols('r_a f_a a b', positive=True)
rv = ra * sp.Matrix([sp.cos(a), sp.sin(a), 0])
fv = fa * sp.Matrix([sp.cos(b), sp.sin(b), 0])
check(90, zero(rv.cross(fv).norm() ** 2 - (ra * fa * sp.sin(b - a)) ** 2))
# 110, 116: a force at right angles to r: M = r F = r m a, and with a = r alpha, M = r m r alpha = m r^2 alpha
rO, Fm, am, al = sp.symbols('r_O F a alpha', positive=True)
check(110, zero((rO * Fm - rO * m * am).subs(Fm, m * am)))
check(116, zero((rO * m * am).subs(am, rO * al) - rO * m * rO * al) and zero(rO * m * rO * al - m * rO ** 2 * al))

# 154: the moment about O' of a set of forces F_k at points P_k (and free moments C)
P = [sp.Matrix(sp.symbols(f'p{k}x p{k}y p{k}z', real=True)) for k in range(3)]
Fk = [sp.Matrix(sp.symbols(f'f{k}x f{k}y f{k}z', real=True)) for k in range(3)]
O = sp.Matrix(sp.symbols('o_x o_y o_z', real=True))
Op = sp.Matrix(sp.symbols('q_x q_y q_z', real=True))
C = sp.Matrix(sp.symbols('c_x c_y c_z', real=True))
Ftot = Fk[0] + Fk[1] + Fk[2]
M_about = lambda Q: sum(((P[k] - Q).cross(Fk[k]) for k in range(3)), sp.zeros(3, 1)) + C   # noqa: E731
r_Op_O = Op - O                                               # r_{O'/O}: from O to O'
check(154, zero(M_about(Op) - (M_about(O) + r_Op_O.cross(Ftot))))
assert zero(M_about(Op) - (M_about(O) - r_Op_O.cross(Ftot)))  # the sign that holds

# ---- the first law: three mass points
N = 3
ms = sp.symbols(f'm0:{N}', positive=True)
mB = sum(ms)
R = [sp.Matrix([sp.Function(f'x{k}{c}')(t) for c in 'xyz']) for k in range(N)]
V = [x.diff(t) for x in R]
A = [x.diff(t, 2) for x in R]
Lb = sum((ms[k] * V[k] for k in range(N)), sp.zeros(3, 1))   # 210
rcm = sum((ms[k] * R[k] for k in range(N)), sp.zeros(3, 1)) / mB   # 216
vcm = sum((ms[k] * V[k] for k in range(N)), sp.zeros(3, 1)) / mB
acm = sum((ms[k] * A[k] for k in range(N)), sp.zeros(3, 1)) / mB
check(222, zero(rcm.diff(t) - vcm))
check(228, zero(Lb - mB * vcm))
# 246: the particles' second laws with external forces E_k and internal forces f_kl = -f_lk cancel in the sum
E = [sp.Matrix(sp.symbols(f'e{k}x e{k}y e{k}z', real=True)) for k in range(N)]
f = {(k, l): sp.Matrix(sp.symbols(f'g{k}{l}x g{k}{l}y g{k}{l}z', real=True)) for k in range(N) for l in range(k + 1, N)}
fint = lambda k, l: f[(k, l)] if k < l else -f[(l, k)]         # noqa: E731
total = [E[k] + sum((fint(k, l) for l in range(N) if l != k), sp.zeros(3, 1)) for k in range(N)]
check(246, zero(sum(total, sp.zeros(3, 1)) - sum(E, sp.zeros(3, 1))))
check(252, zero(rcm.diff(t, 2) - acm))
Fext = sum(E, sp.zeros(3, 1))
laws = {A[k][n]: total[k][n] / ms[k] for k in range(N) for n in range(3)}
check(258, zero((sum((ms[k] * A[k] for k in range(N)), sp.zeros(3, 1)) - mB * acm))
      and zero((mB * acm).subs(laws) - Fext))

# ---- the second law: 280 with the points about the centre of mass
Q = [x - rcm for x in R]
HO = sum((R[k].cross(ms[k] * V[k]) for k in range(N)), sp.zeros(3, 1))
split = rcm.cross(mB * vcm) + sum((Q[k].cross(ms[k] * Q[k].diff(t)) for k in range(N)), sp.zeros(3, 1))
check(280, zero(HO - split))
check(286, zero(HO.diff(t) - split.diff(t)))
# 292, 298, 304: a body turning in the xy plane: positions about the centre of mass at a common angle phi
phi = sp.Function('phi')(t)
X, Y = sp.Function('X')(t), sp.Function('Y')(t)
rho = sp.symbols('rho0:3', positive=True)
c0 = sp.symbols('c0:3', real=True)
Qp = [rho[k] * sp.Matrix([sp.cos(phi + c0[k]), sp.sin(phi + c0[k]), 0]) for k in range(N)]
# the centre of mass at (X, Y): the offsets must average to zero, so the third point is fixed by the others
mu = [ms[k] for k in range(N)]
q2 = -(mu[0] * Qp[0] + mu[1] * Qp[1]) / mu[2]
Qp[2] = q2
Rc = sp.Matrix([X, Y, 0])
Rp = [Rc + q for q in Qp]
Hp = sum((Rp[k].cross(ms[k] * Rp[k].diff(t)) for k in range(N)), sp.zeros(3, 1))
Icm = sum(ms[k] * (Qp[k][0] ** 2 + Qp[k][1] ** 2) for k in range(N))
alpha = sp.Matrix([0, 0, phi.diff(t, 2)])
M292 = Rc.cross(mB * Rc.diff(t, 2)) + Icm * alpha
check(292, zero(sp.simplify(Hp.diff(t) - M292)))
# 298: |r_cm/O x m a_cm| = m |a_cm| d, d the distance from O to the line through the centre of mass along a_cm
ax_, ay_ = sp.symbols('a_x a_y', real=True)
Xs, Ys = sp.symbols('X_s Y_s', real=True)
acm_v = sp.Matrix([ax_, ay_, 0])
dist = (Xs * ay_ - Ys * ax_) / sp.sqrt(ax_ ** 2 + ay_ ** 2)   # signed distance from O to that line
check(298, zero(sp.Matrix([Xs, Ys, 0]).cross(mB * acm_v)[2] - mB * sp.sqrt(ax_ ** 2 + ay_ ** 2) * dist))
check(304, zero(M292.subs({X: 0, Y: 0}).doit() - Icm * alpha))
# 316, 318, 320: Euler's equations from M = dH/dt in axes turning with the body (principal axes)
I1, I2, I3 = sp.symbols('I1:4', positive=True)
w = sp.Matrix([sp.Function(f'w{n}')(t) for n in (1, 2, 3)])
Ib = sp.diag(I1, I2, I3)
Mbody = Ib * w.diff(t) + w.cross(Ib * w)                       # body components of dH/dt
printed = [I1 * w[0].diff(t) + (I3 - I2) * w[1] * w[2], I2 * w[1].diff(t) + (I1 - I3) * w[2] * w[0],
           I3 * w[2].diff(t) + (I2 - I1) * w[0] * w[1]]
for n, line in enumerate((316, 318, 320)):
    check(line, zero(Mbody[n] - printed[n]))

LINES = [31, 37, 57, 60, 62, 68, 78, 90, 110, 116, 138, 146, 154, 178, 184, 190, 210, 216, 222, 228,
         240, 246, 252, 258, 280, 286, 292, 298, 304, 316, 318, 320]
NC, H_ = "not a claim", "holds"
ROWS = {
    31: (NC, "defines the linear momentum of a particle, L = m v"),
    37: (NC, "defines the angular momentum about O, H_O = r_O x L"),
    57: (H_, "the product rule on r x L; v x (m v) = 0 and d(m v)/dt = F (check 57)"),
    60: (H_, "the moment of a force about O is r_O x F, the chain's result (check 60)"),
    62: (H_, "the two vectors written on the unit vectors (check 62)"),
    68: (H_, "the cross product as the determinant with the unit vectors in the first row (check 68)"),
    78: (H_, "the determinant expanded: (r_y F_z - r_z F_y, r_z F_x - r_x F_z, r_x F_y - r_y F_x) (check 78)"),
    90: (H_, "|r x F| = |r||F| sin theta (check 90)"),
    110: (H_, "for a force at right angles to r_O the size of the moment is r_O F, and F = m a (check 110)"),
    116: (H_, "with the tangential acceleration a = r_O alpha, r_O m r_O alpha = m r_O^2 alpha (check 116)"),
    138: (NC, "defines the resultant force as the sum of the forces"),
    146: (NC, "defines the total moment about O: the moments r_{i/O} x F_i plus the free moments"),
    154: ("typo",
          "r_{i/O} runs from O to the point where F_i acts, so r_{O'/O} runs from O to O'; moving the reference point "
          "from O to O' gives M_O' = sum (r_{i/O} - r_{O'/O}) x F_i + free = M_O - r_{O'/O} x F; the display adds "
          "r_{O'/O} x F instead (check 154)",
          "\\vec{\\bf{M_{O'}}} = \\vec{\\bf{M_O}} + \\vec{\\bf{r_{O/O'}}} \\times \\vec{\\bf{F}}",
          "By hand: the vector from O' to the point of F_i is r_{i/O'} = r_{i/O} - r_{O'/O}, so M_O' = sum r_{i/O'} x F_i + "
          "sum M_{F_i} = sum r_{i/O} x F_i - r_{O'/O} x sum F_i + sum M_{F_i} = M_O - r_{O'/O} x F = M_O + r_{O/O'} x F.",
          "Example: one force F = (0, 1, 0) acting at (1, 0, 0), O at the origin, O' = (1, 0, 0). M_O = (1, 0, 0) x (0, 1, 0) "
          "= (0, 0, 1); about O', the point where the force acts, the moment is 0. The display gives M_O + r_{O'/O} x F = "
          "(0, 0, 1) + (1, 0, 0) x (0, 1, 0) = (0, 0, 2), not 0; with the minus sign it is (0, 0, 1) - (0, 0, 1) = 0."),
    178: (NC, "Euler's first law as the notebook states it (the linear momentum is the mass times the velocity of the "
              "centre of mass); it is derived at line 228"),
    184: (NC, "the first law differentiated, F = m a_cm, stated as a law; derived at line 258"),
    190: (NC, "Euler's second law, M_O = dH_O/dt about a point fixed in an inertial frame: the law the section starts from"),
    210: (NC, "the linear momentum of the body as the sum over its particles (the definition)"),
    216: (NC, "defines the centre of mass and the mass m_B of the body"),
    222: (H_, "the time derivative of the centre of mass (check 222)"),
    228: (H_, "sum m_i v_i = m_B v_cm by the previous display; the second member repeats the first (check 228)"),
    240: (NC, "Newton's second law for every particle, summed: the premise of the derivation"),
    246: (H_, "the internal forces cancel in pairs (third law), leaving the external forces (check 246)"),
    252: (H_, "the second time derivative of the centre of mass (check 252)"),
    258: (H_, "the resultant external force is sum m_i a_i = m_B a_cm (check 258)"),
    280: (H_, "the angular momentum about O splits into that of the centre of mass and that about the centre of mass, "
               "since the particles' moments sum m_i r_{i/cm} vanish (check 280)"),
    286: (H_, "the second law with the split angular momentum put in (check 286)"),
    292: (H_, "in the plane, with O fixed: d/dt (r_cm x m v_cm) = r_cm x m a_cm and the spin part is I_cm alpha (check 292)"),
    298: (H_, "the size of r_{cm/O} x m a_cm is m a_cm times the distance d from O to the line of a_cm (check 298)"),
    304: (H_, "the same law about the centre of mass, where r_{cm} = 0 (check 304)"),
    316: (H_, "the first Euler equation: I1 w1' + (I3 - I2) w2 w3 is the body component of I w' + w x I w (check 316)"),
    318: (H_, "the second Euler equation (check 318)"),
    320: (H_, "the third Euler equation (check 320)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
