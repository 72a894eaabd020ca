"""Independent SymPy truth table for uniform-ball-sliding-rolling-on-rough-plane-zh-notes.tex.

The text's own setting: a uniform ball of mass m and radius a on a fixed rough horizontal plane,
OZ vertical, the translating frame Cxyz at the centre C with axes parallel to OXYZ; gravity
m g = (0, 0, -m g) acts at C, the plane's reaction R = N + F = (F_X, F_Y, N) at the contact point D,
CD = (0, 0, -a). Built here from first principles: the velocity of a body point from a rotation
matrix Q(t) (omega from Qdot Q^T), the inertia tensor of the ball by integration over it, Newton's
law for the centre and the theorem of angular momentum about it, then the sliding phase solved
with u = (cos beta, sin beta, 0) and Coulomb's F = -k N u. Never reads the text's later displays
to get an earlier one, and never imports the reader.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Rz

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero
t = sp.symbols("t", real=True)
m, a, g, k = sp.symbols("m a g k", positive=True)

# 42: the velocity of a body point D: r_D = r_C + Q b, so v_D = v_C + Qdot b = v_C + omega x (Q b)
phi, th, psi = (sp.Function(n)(t) for n in ("phi", "theta", "psi"))
Q = Rz(phi) * Rx(th) * Rz(psi)
W = sp.simplify(Q.diff(t) * Q.T)
omega = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])
b = sp.Matrix(sp.symbols("b1:4", real=True))
rC = sp.Matrix([sp.Function(n)(t) for n in ("X_C", "Y_C", "Z_C")])
rD = rC + Q * b
CD = Q * b
check(42, zero(W + W.T) and zero(rD.diff(t) - (rC.diff(t) + omega.cross(CD))))

# 59: inertia tensor of the uniform ball about its centre, by integration: 2/5 m a^2 times the unit matrix
r_, th_, ph_ = sp.symbols("r theta_s phi_s", positive=True)
rho = m / (sp.Rational(4, 3) * sp.pi * a**3)
pt = sp.Matrix([r_ * sp.sin(th_) * sp.cos(ph_), r_ * sp.sin(th_) * sp.sin(ph_), r_ * sp.cos(th_)])
jac = r_**2 * sp.sin(th_)


def integrate_ball(f):
    return sp.integrate(sp.integrate(sp.integrate(f * jac, (ph_, 0, 2 * sp.pi)), (th_, 0, sp.pi)), (r_, 0, a))


Iball = sp.Matrix(3, 3, lambda i, j: integrate_ball(rho * ((1 if i == j else 0) * pt.dot(pt) - pt[i] * pt[j])))
assert sp.simplify(integrate_ball(rho) - m) == 0
w = sp.Matrix([sp.Function(n)(t) for n in ("omega_x", "omega_y", "omega_z")])
L_C = Iball * w
check(59, zero(L_C - sp.Rational(2, 5) * m * a**2 * w))

# forces and torques: gravity at C, R = (F_X, F_Y, N) at D, CD = (0, 0, -a) in the translating frame
FX, FY, N = sp.symbols("F_X F_Y N", real=True)
R = sp.Matrix([FX, FY, N])
gvec = sp.Matrix([0, 0, -g])
cd = sp.Matrix([0, 0, -a])
forces = [(m * gvec, sp.zeros(3, 1)), (R, cd)]              # (force, point of application from C)
total_force = sum((f for f, _ in forces), sp.zeros(3, 1))
total_torque = sum((p.cross(f) for f, p in forces), sp.zeros(3, 1))
vC = rC.diff(t)
# 54: m dv_C/dt = sum of external forces = m g + R
check(54, zero(total_force - (m * gvec + R)))
# 63: dL_C/dt = torque about C: (2/5) m a^2 domega/dt = CD x R
check(63, zero(L_C.diff(t) - sp.Rational(2, 5) * m * a**2 * w.diff(t))
      and zero(total_torque - cd.cross(R)))
acc = total_force / m                       # the centre's acceleration
wdot = Iball.inv() * total_torque           # the angular acceleration
# 69: components of the centre's equation
check(69, zero(acc - sp.Matrix([FX / m, FY / m, -g + N / m])))
# 77: components of the angular momentum equation
check(77, zero(wdot - sp.Matrix([5 / (2 * m * a) * FY, -5 / (2 * m * a) * FX, 0])))
# N = mg from Z_C = a constant
Nval = sp.solve(sp.Eq(acc[2], 0), N)[0]
assert Nval == m * g
# 85: dv_D/dt = dv_C/dt + domega/dt x CD (CD constant in the translating frame) = 7 F / (2 m), F = (F_X, F_Y, 0)
vDdot = (acc + wdot.cross(cd)).subs(N, Nval)
Fvec = sp.Matrix([FX, FY, 0])
check(85, zero(vDdot - sp.Rational(7, 2) / m * Fvec))

# sliding phase: v_D = v_D(t) u(t), u = (cos beta, sin beta, 0) (v_D is horizontal), F = -k N u
vD = sp.Function("v_D")(t)
beta = sp.Function("beta")(t)
u = sp.Matrix([sp.cos(beta), sp.sin(beta), 0])
Fsl = -k * Nval * u
rhs = vDdot.subs({FX: Fsl[0], FY: Fsl[1]})
# 90: d(v_D u)/dt = -7/2 k g u, i.e. the text's right side equals 7 F/(2m) with F = -k N u, N = mg
lhs90 = vD.diff(t) * u + vD * u.diff(t)
check(90, zero((vD * u).diff(t) - lhs90) and zero(rhs - (-sp.Rational(7, 2) * k * g * u)))
# solve d(v_D u)/dt = rhs for v_D' and beta'
sol = sp.solve(list(lhs90 - rhs)[:2], [vD.diff(t), beta.diff(t)], dict=True)[0]
sol = {kk: sp.simplify(vv) for kk, vv in sol.items()}
# 95: dv_D/dt = -7/2 k g
check(95, zero(sol[vD.diff(t)] + sp.Rational(7, 2) * k * g))
# 100: du/dt = 0 (beta' = 0 while v_D != 0)
check(100, zero(u.diff(t).subs(beta.diff(t), sol[beta.diff(t)])))
# 104: F = -k m g u
check(104, zero(Fsl - (-k * m * g * u)))
# 108: v_D(t) from v_D' = -7/2 k g: v_D(0) - 7/2 k g t; the text drops the t
vD0 = sp.Symbol("v_D0")
vDsol = sp.dsolve(sp.Eq(vD.diff(t), sol[vD.diff(t)]), vD, ics={vD.subs(t, 0): vD0}).rhs
text108 = vD0 - sp.Rational(7, 2) * k * g
check(108, zero(vDsol - text108))
assert zero(vDsol - (vD0 - sp.Rational(7, 2) * k * g * t))
# 112, 119: integrate the centre's equations with u = (cos alpha, sin alpha, 0) fixed
al = sp.Symbol("alpha", real=True)
Xd0, Yd0, X0, Y0, wx0, wy0 = sp.symbols("Xdot_0 Ydot_0 X_0 Y_0 omega_x0 omega_y0", real=True)
Fc = (-k * m * g * sp.Matrix([sp.cos(al), sp.sin(al), 0]))
ax_, ay_ = acc[0].subs({FX: Fc[0], FY: Fc[1]}), acc[1].subs({FX: Fc[0], FY: Fc[1]})
s = sp.Symbol("s")
Xdot = Xd0 + sp.integrate(ax_, (s, 0, t))
Ydot = Yd0 + sp.integrate(ay_, (s, 0, t))
Xc = X0 + sp.integrate(Xdot.subs(t, s), (s, 0, t))
Yc = Y0 + sp.integrate(Ydot.subs(t, s), (s, 0, t))
check(112, zero(sp.Matrix([Xdot - (-(k * g * sp.cos(al)) * t + Xd0), Ydot - (-(k * g * sp.sin(al)) * t + Yd0)])))
check(119, zero(sp.Matrix([Xc - (-sp.Rational(1, 2) * (k * g * sp.cos(al)) * t**2 + Xd0 * t + X0),
                           Yc - (-sp.Rational(1, 2) * (k * g * sp.sin(al)) * t**2 + Yd0 * t + Y0)]))
      and zero(sp.Matrix([Xc.diff(t, 2) - ax_, Yc.diff(t, 2) - ay_])))
# 127: integrate the angular momentum equations
wxdot = wdot[0].subs({FX: Fc[0], FY: Fc[1]})
wydot = wdot[1].subs({FX: Fc[0], FY: Fc[1]})
wx_t = wx0 + sp.integrate(wxdot, (s, 0, t))
wy_t = wy0 + sp.integrate(wydot, (s, 0, t))
check(127, zero(sp.Matrix([wx_t - (wx0 - 5 * k * g * sp.sin(al) / (2 * a) * t),
                           wy_t - (wy0 + 5 * k * g * sp.cos(al) / (2 * a) * t)])))
# 135: v_D(t_*) = 0
tstar = sp.solve(sp.Eq(vDsol, 0), t)
check(135, len(tstar) == 1 and zero(tstar[0] - 2 * vD0 / (7 * k * g)))

LINES = [42, 47, 54, 59, 63, 69, 77, 85, 90, 95, 100, 104, 108, 112, 119, 127, 135]

ROWS = {
    42: ("holds", "a body point at r_C + Q b moves with v_C + Qdot b = v_C + omega x CD, omega read off the skew matrix Qdot Q^T (check 42)"),
    47: ("not a claim", "Coulomb's law of sliding friction posited: size kN, direction against the sliding velocity v_D"),
    54: ("holds", "Newton's law for the centre: the external forces are the weight m g and the plane's reaction R (check 54)"),
    59: ("holds", "the inertia tensor of a uniform ball about its centre, integrated over the ball, is 2/5 m a^2 times the unit matrix (check 59)"),
    63: ("holds", "the weight acts at C and has no moment about it; R acts at D, moment CD x R; dL_C/dt = 2/5 m a^2 domega/dt (check 63)"),
    69: ("holds", "components of m dv_C/dt = m g + R with g = (0, 0, -g), R = (F_X, F_Y, N) (check 69)"),
    77: ("holds", "CD x R = (0, 0, -a) x (F_X, F_Y, N) = (a F_Y, -a F_X, 0), divided by 2/5 m a^2 (check 77)"),
    85: ("holds", "dv_D/dt = dv_C/dt + domega/dt x CD = F/m + (5/(2 m a^2)) (CD x F) x CD = F/m + 5F/(2m) with N = mg (check 85)"),
    90: ("holds", "d(v_D u)/dt = v_D' u + v_D u'; 7F/(2m) with F = -k m g u is -7/2 k g u (check 90)"),
    95: ("holds", "with u = (cos beta, sin beta, 0) the two components of the previous equation give v_D' = -7/2 k g (check 95)"),
    100: ("holds", "the same components give v_D beta' = 0, so u' = 0 while v_D != 0 (check 100)"),
    104: ("holds", "F = -k N u with N = mg (check 104)"),
    108: ("typo", "integrating dv_D/dt = -7/2 k g from v_D(0) gives v_D(0) - 7/2 k g t; the display drops the factor t (check 108)",
          "v_D = v_D(0)-\\frac72kg t",
          "Differentiate the display: d/dt [v_D(0) - 7/2 k g] = 0, but the display at line 95 says dv_D/dt = -7/2 k g; and at t = 0 it gives v_D(0) - 7/2 k g, not v_D(0). Units too: with k = 0.2, g = 10 m/s^2, 7/2 k g = 7 m/s^2 is an acceleration, which cannot be subtracted from a speed v_D(0) in m/s.",
          "Numbers: k = 0.2, g = 10, v_D(0) = 14 m/s. From dv_D/dt = -7 m/s^2, v_D(1 s) = 7 m/s and v_D(2 s) = 0, which matches t_* = 2 v_D(0)/(7 k g) = 28/14 = 2 s at line 135; the display as written gives 14 - 7 = 7 m/s at every time and never reaches zero."),
    112: ("holds", "F = -k m g (cos alpha, sin alpha) in X_C'' = F_X/m, Y_C'' = F_Y/m, integrated once (check 112)"),
    119: ("holds", "integrated twice from X_C(0), Y_C(0) (check 119)"),
    127: ("holds", "omega_x' = 5 F_Y/(2 m a) = -5 k g sin alpha/(2a), omega_y' = -5 F_X/(2 m a) = +5 k g cos alpha/(2a), integrated (check 127)"),
    135: ("holds", "v_D(0) - 7/2 k g t = 0 at t = 2 v_D(0)/(7 k g) (check 135)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
