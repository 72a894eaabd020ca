"""Independent SymPy truth table for jingliangwei-blog-landau-non-inertial-frames-coriolis-foucault-zh.md.

The notes' own setting (Landau and Lifshitz's section on non-inertial frames). A particle of mass m in a
potential U with gradient G (taken in the components of whichever frame is in use). The moving frame's
axes are R(t) (a rotation built from two turns about the z and x axes by angles a(t), b(t)); its origin is
at X0(t). A primed vector is given by its components in the moving frame: r' (the particle's position
from the moving origin), v' = dr'/dt componentwise, a' = dv'/dt. The frame's angular velocity Omega has
the moving-frame components of R^T dR/dt, and V, dV/dt are the origin's velocity and acceleration in the
moving frame's components. The inertial law is m d^2(X0 + R r')/dt^2 = -R G. Each equation of motion
holds when its residual (left minus right) is the inertial law's residual taken in the moving frame.
Energies and momenta at one instant use the inertial velocity v = v' + Omega x r' (no translation).
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero
nzero = truth_table.numeric_zero

t, m = sp.symbols("t m", positive=True)
fa, fb = sp.Function("a")(t), sp.Function("b")(t)
R = truth_table.Rz(fa) * truth_table.Rx(fb)
rp = sp.Matrix([sp.Function(f"x{i}")(t) for i in (1, 2, 3)])
X0 = sp.Matrix([sp.Function(f"X{i}")(t) for i in (1, 2, 3)])
G = sp.Matrix(sp.symbols("G1:4", real=True))
vp, ap = rp.diff(t), rp.diff(t, 2)
S = R.T * R.diff(t)
Om = sp.Matrix([S[2, 1], S[0, 2], S[1, 0]])
Omd = Om.diff(t)
W = R.T * X0.diff(t, 2)                       # the origin's acceleration, moving-frame components


def law(Rm, X):
    """The inertial law's residual m r_ddot + grad U, in the moving frame's components."""
    return Rm.T * (m * (X + Rm * rp).diff(t, 2)) + G


def cross(u, w):
    return u.cross(w)


# 22, 56: translating frame: m a' = -m dV/dt - dU/dr'
res = m * ap - (-m * X0.diff(t, 2) - G)
eye = sp.eye(3)
check(22, zero(res - law(eye, X0)))
check(56, zero(res - law(eye, X0)))
# 28: L' = m|v|^2/2 - U with v = v' + V, expanded
V = sp.Matrix(sp.symbols("V1:4", real=True))
v1 = sp.Matrix(sp.symbols("w1:4", real=True))
Usym = sp.Symbol("U")
Lfull = m * (v1 + V).dot(v1 + V) / 2 - Usym
check(28, zero(Lfull - (m * v1.dot(v1) / 2 + m * V.dot(V) / 2 + m * v1.dot(V) - Usym)))
# 38: m v'.V = d(m r'.V)/dt - m r'.dV/dt
Vt = X0.diff(t)
check(38, zero(m * vp.dot(Vt) - ((m * rp.dot(Vt)).diff(t) - m * rp.dot(Vt.diff(t)))))
# 64, 106: rotating frame: m a' = m r' x Omega_dot + 2 m v' x Omega + m (Omega x r') x Omega - G
rot = m * ap - (m * cross(rp, Omd) + 2 * m * cross(vp, Om) + m * cross(cross(Om, rp), Om) - G)
zero0 = sp.zeros(3, 1)
check(64, nzero(rot - law(R, zero0), t))
check(106, nzero(rot - law(R, zero0), t))
# 103: m a' + m(Omega_dot x r' + Omega x v') = m(Omega x r') x Omega + m v' x Omega - G
lag = m * ap + m * (cross(Omd, rp) + cross(Om, vp)) - (m * cross(cross(Om, rp), Om) + m * cross(vp, Om) - G)
check(103, nzero(lag - law(R, zero0), t))
# 112: translation and rotation together
both = m * ap - (-m * W + m * cross(rp, Omd) + 2 * m * cross(vp, Om) + m * cross(cross(Om, rp), Om) - G)
check(112, nzero(both - law(R, X0), t))
# 118: no translation, uniform rotation (a turn about z at a constant rate)
w0 = sp.Symbol("w0", positive=True)
Ru = truth_table.Rz(w0 * t)
Su = Ru.T * Ru.diff(t)
Omu = sp.Matrix([Su[2, 1], Su[0, 2], Su[1, 0]])
uni = m * ap - (2 * m * cross(vp, Omu) + m * cross(cross(Omu, rp), Omu) - G)
check(118, zero(sp.simplify(uni - law(Ru, zero0))))
# The Lagrangian in the turning frame (constant Omega at the instant), its momenta and energies
O = sp.Matrix(sp.symbols("O1:4", real=True))
r1 = sp.Matrix(sp.symbols("r1:4", real=True))
u1 = sp.Matrix(sp.symbols("u1:4", real=True))       # v' at the instant
Ufun = sp.Function("U")(*r1)
Gr = sp.Matrix([Ufun.diff(x) for x in r1])
Lrot = m * (u1 + cross(O, r1)).dot(u1 + cross(O, r1)) / 2 - Ufun
# 72: L' = m|v'+Omega x r'|^2/2 - U = m(v'^2 + |Omega x r'|^2 + 2 v'.(Omega x r'))/2 - U
check(72, zero(Lrot - (m * (u1.dot(u1) + cross(O, r1).dot(cross(O, r1)) + 2 * u1.dot(cross(O, r1))) / 2 - Ufun)))
# 81: dL' = m v'.dv' + m(Omega x r').(Omega x dr') + m dv'.(Omega x r') + m v'.(Omega x dr') - grad U.dr'
dv, dr = sp.Matrix(sp.symbols("dv1:4", real=True)), sp.Matrix(sp.symbols("dr1:4", real=True))
eps = sp.Symbol("eps")
dL = Lrot.subs({**dict(zip(u1, u1 + eps * dv)), **dict(zip(r1, r1 + eps * dr))}, simultaneous=True).diff(eps).subs(eps, 0)
claim82 = (m * u1.dot(dv) + m * cross(O, r1).dot(cross(O, dr)) + m * dv.dot(cross(O, r1))
           + m * u1.dot(cross(O, dr)) - Gr.dot(dr))
check(81, zero(sp.expand(dL.doit() - claim82)))
# 91, 133: dL'/dv' = m v' + m Omega x r'
pL = sp.Matrix([Lrot.diff(x) for x in u1])
check(91, zero(pL - (m * u1 + m * cross(O, r1))))
check(133, zero(pL - (m * u1 + m * cross(O, r1))))
# 94: dL'/dr' = m(Omega x r') x Omega + m v' x Omega - grad U
qL = sp.Matrix([Lrot.diff(x) for x in r1])
check(94, zero(qL - (m * cross(cross(O, r1), O) + m * cross(u1, O) - Gr)))
# 124: p = p', M = M', E - E' = M.Omega (p, M, E with the inertial velocity v = v' + Omega x r')
vin = u1 + cross(O, r1)
Ein = m * vin.dot(vin) / 2 + Ufun
Erot = pL.dot(u1) - Lrot                         # E' = v'.p' - L'
Min = cross(r1, m * vin)
check(124, zero(m * vin - pL) and zero(Min - cross(r1, pL)) and zero(sp.expand(Ein - Erot - Min.dot(O))))
# 130: L' with m v.(Omega x r'), v the inertial velocity (the v' of the line before is meant)
claim131 = m * u1.dot(u1) / 2 + m * cross(O, r1).dot(cross(O, r1)) / 2 + m * vin.dot(cross(O, r1)) - Ufun
check(130, zero(sp.expand(claim131 - Lrot)))
# 139: E' = v.p' - L' = m v'^2/2 + U - m|Omega x r'|^2/2 (the chain with v, the inertial velocity)
right140 = m * u1.dot(u1) / 2 + Ufun - m * cross(O, r1).dot(cross(O, r1)) / 2
check(139, zero(sp.expand(vin.dot(pL) - Lrot - right140)) and zero(sp.expand(Erot - right140)))
# 151: E - E' = m|Omega x r|^2 + m v'.(Omega x r) = m(Omega x r).v = (r x m v).Omega = M.Omega
steps = [Ein - Erot, m * cross(O, r1).dot(cross(O, r1)) + m * u1.dot(cross(O, r1)),
         m * cross(O, r1).dot(vin), cross(r1, m * vin).dot(O), Min.dot(O)]
check(151, all(zero(sp.expand(steps[0] - s)) for s in steps[1:]))
# 169: Foucault: m a = 2 m v x (Omega_z z) - grad U, U = m g (x^2 + y^2)/(2 l), horizontal components
g, l, Oz = sp.symbols("g l Omega_z", positive=True)
x, y = sp.Function("x")(t), sp.Function("y")(t)
Uf = m * g * (x**2 + y**2) / (2 * l)
vel = sp.Matrix([x.diff(t), y.diff(t), 0])
force = 2 * m * vel.cross(sp.Matrix([0, 0, Oz])) - sp.Matrix([Uf.diff(x), Uf.diff(y), 0])
om2 = g / l
eqx = x.diff(t, 2) + om2 * x - 2 * Oz * y.diff(t)
eqy = y.diff(t, 2) + om2 * y + 2 * Oz * x.diff(t)
check(169, zero(m * x.diff(t, 2) - force[0] - m * eqx) and zero(m * y.diff(t, 2) - force[1] - m * eqy))

# negative control: a wrong sign of the Coriolis term is caught
assert not nzero(m * ap - (m * cross(rp, Omd) - 2 * m * cross(vp, Om) + m * cross(cross(Om, rp), Om) - G)
                 - law(R, zero0), t)

LINES = [22, 28, 38, 44, 50, 56, 64, 72, 81, 91, 94, 100, 103, 106, 112, 118, 124, 130, 133, 139, 145, 151, 163, 169, 178]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
