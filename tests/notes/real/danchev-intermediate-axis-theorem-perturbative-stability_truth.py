"""Independent SymPy truth table for danchev-intermediate-axis-theorem-perturbative-stability.tex.

The text's own setting: a free rigid body in its principal axes, moments I_1, I_2, I_3, angular
velocity omega = (omega_1, omega_2, omega_3) on the body axes, L_i = I_i omega_i. A steady spin
omega = (0, 0, Omega) is perturbed by (delta omega_1, delta omega_2, 0) and the equations are kept to
first order; kappa^2 = (I_2 - I_3)(I_3 - I_1) Omega^2/(I_1 I_2) as the text defines it, and in the
stable case (kappa^2 < 0) the rate of the oscillation is k = sqrt(-kappa^2), the text's "sin and cos
of kappa t".

Euler's equations are derived here from the rate of change of a body-fixed vector seen from the
inertial frame (d(R v_B)/dt = R (dv_B/dt + omega_B x v_B), omega_B from R^T dR/dt), never from the
text's displays; the perturbation, the oscillator and its solutions are derived from them. The
cylinder's moments come from the integral over its volume. SymPy only.
"""
import sys
import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = CHECKS.get(key, True) and bool(ok)


t = sp.symbols('t', real=True)
I1, I2, I3, Om = sp.symbols('I_1 I_2 I_3 Omega', positive=True)
w1, w2, w3 = [sp.Function(f'omega_{i}')(t) for i in (1, 2, 3)]


def rot(axis, a):
    c, s = sp.cos(a), sp.sin(a)
    if axis == 'x':
        return sp.Matrix([[1, 0, 0], [0, c, -s], [0, s, c]])
    return sp.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def unskew(S):
    return sp.Matrix([S[2, 1], S[0, 2], S[1, 0]])


# ---- 26, 36: the rate of a vector seen from two frames. R(t) takes components on the moving
# frame to components on the other; a vector with moving-frame components v(t) has, seen from the
# other frame, the rate R (v' + w x v) with w the moving frame's rate relative to the other one.
R = rot('z', sp.Rational(3, 5) * t) * rot('x', sp.sin(t) / 2) * rot('z', t ** 2 / 4)
wB = unskew(sp.simplify(R.T * R.diff(t)))
vB = sp.Matrix([sp.Function(f'v_{i}')(t) for i in (1, 2, 3)])
lhs = R.T * (R * vB).diff(t)                       # the inertial rate, on the moving axes
rhs = vB.diff(t) + wB.cross(vB)
check(26, truth_table.numeric_zero(lhs - rhs, t))  # d^N L/dt = d^B L/dt + w_{B/N} x L = tau
# 36: here B is the reference frame and A the moving one (w_{A/B} is A's rate relative to B)
check(36, truth_table.numeric_zero(lhs - rhs, t))
# negative control: the other sign of the cross term fails
assert not truth_table.numeric_zero(lhs - (vB.diff(t) - wB.cross(vB)), t)

# ---- 45, 51: Euler's equations with tau = 0, from d^B L/dt + omega x L = 0, L = I omega
w = sp.Matrix([w1, w2, w3])
Idiag = sp.diag(I1, I2, I3)
L = Idiag * w
euler = L.diff(t) + w.cross(L)                     # = 0 for a free body
wdot = sp.Matrix([sp.solve(euler[i], w[i].diff(t))[0] for i in range(3)])
check(45, truth_table.zero(sp.Matrix([I1 * wdot[0] - (I2 - I3) * w2 * w3,
                                      I2 * wdot[1] - (I3 - I1) * w3 * w1,
                                      I3 * wdot[2] - (I1 - I2) * w1 * w2])))
check(51, truth_table.zero(sp.Matrix([wdot[0] - (I2 - I3) / I1 * w2 * w3,
                                      wdot[1] - (I3 - I1) / I2 * w3 * w1,
                                      wdot[2] - (I1 - I2) / I3 * w1 * w2])))
assert not truth_table.zero(wdot[0] - (I3 - I2) / I1 * w2 * w3)

# ---- 67: first order about (0, 0, Omega)
eps = sp.symbols('epsilon')
d1, d2 = sp.symbols('d_1 d_2')
sub = {w1: eps * d1, w2: eps * d2, w3: Om}
lin = [sp.series(wdot[i].subs(sub), eps, 0, 2).removeO() for i in range(3)]
check(67, sp.simplify(lin[0] - eps * (I2 - I3) / I1 * Om * d2) == 0
      and sp.simplify(lin[1] - eps * (I3 - I1) / I2 * Om * d1) == 0 and sp.simplify(lin[2]) == 0)

# ---- 75: differentiate the first linear equation and use the second
a1 = (I2 - I3) / I1 * Om
a2 = (I3 - I1) / I2 * Om
x1 = sp.Function('x_1')(t)
x2 = sp.Function('x_2')(t)
lin_sys = {x1.diff(t): a1 * x2, x2.diff(t): a2 * x1}
ddx1 = (a1 * x2).diff(t).subs(lin_sys)
check(75, sp.simplify(ddx1 - (I2 - I3) / I1 * (I3 - I1) / I2 * Om ** 2 * x1) == 0)
kappa2 = (I2 - I3) / I1 * (I3 - I1) / I2 * Om ** 2

# ---- 85: stable (kappa^2 < 0) exactly when (I_2 - I_3)(I_3 - I_1) < 0: kappa^2 is that product
# times Omega^2/(I_1 I_2) > 0; I_3 largest or smallest gives a negative product, intermediate a
# positive one
check(85, sp.simplify(kappa2 / ((I2 - I3) * (I3 - I1)) - Om ** 2 / (I1 * I2)) == 0
      and all(((b - c) * (c - a) < 0) == (c in (min(a, b, c), max(a, b, c)))
              for a, b, c in ((1, 2, 3), (2, 1, 3), (3, 1, 2), (1, 3, 2), (2, 3, 1), (3, 2, 1))))

# ---- 105: a homogeneous cylinder (radius r, length l, mass m) about its axis and a transverse
# axis through its centre, from the integral over its volume
rr, ll, m = sp.symbols('r l m', positive=True)
s, ph, z = sp.symbols('s phi z', real=True)
rho = m / (sp.pi * rr ** 2 * ll)
vol = lambda f: sp.integrate(sp.integrate(sp.integrate(f * s, (s, 0, rr)), (ph, 0, 2 * sp.pi)), (z, -ll / 2, ll / 2))  # noqa: E731
Iax = sp.simplify(rho * vol(s ** 2))
Iorth = sp.simplify(rho * vol((s * sp.sin(ph)) ** 2 + z ** 2))
check(105, sp.simplify(Iax - m * rr ** 2 / 2) == 0
      and sp.simplify(Iorth - m * (3 * rr ** 2 + ll ** 2) / 12) == 0)

# ---- 112: moving the origin by R changes the tensor by m (R^2 1 - R R^T), not by m R^2 1: the
# written I' = I + m R^2 fails for a shift along a principal axis (that moment does not change)
Rv = sp.Matrix(sp.symbols('R_1:4', real=True))
shift = m * (Rv.dot(Rv) * sp.eye(3) - Rv * Rv.T)
check(112, truth_table.zero(shift - m * Rv.dot(Rv) * sp.eye(3)))

# ---- 123, 127: solutions of x'' = kappa^2 x. Stable case (kappa^2 < 0): the oscillation rate is
# k = sqrt(-kappa^2), and c_1 cos(k t) + c_2 sin(k t) is the general solution. Unstable case: the
# written c_1 exp(kappa t) + c_2 exp(kappa t) is one exponential, not the general solution.
c1, c2, k = sp.symbols('c_1 c_2 k', positive=True)
stab = c1 * sp.cos(k * t) + c2 * sp.sin(k * t)
check(123, sp.simplify(stab.diff(t, 2) - (-k ** 2) * stab) == 0
      and sp.simplify(sp.Matrix([[sp.cos(k * t), sp.sin(k * t)],
                                 [sp.cos(k * t).diff(t), sp.sin(k * t).diff(t)]]).det()) != 0)
unst = [sp.exp(k * t), sp.exp(k * t)]
check(127, sp.simplify(sp.Matrix([unst, [f.diff(t) for f in unst]]).det()) != 0)
assert sp.simplify(sp.Matrix([[sp.exp(k * t), sp.exp(-k * t)], [k * sp.exp(k * t), -k * sp.exp(-k * t)]]).det()) != 0

# ---- 132, 136, 142: x_2 from x_1 = c_1 cos(k t) + c_2 sin(k t) through x_1' = a_1 x_2, with
# I_3 the largest moment (the text's test, Omega > 0): x_2 = Theta (c_1 sin - c_2 cos) with
# Theta = -I_1 k/((I_2 - I_3) Omega); its square is (I_3 - I_1) I_1/((I_3 - I_2) I_2) > 0, while
# the written radicand (I_3 - I_1) I_1/((I_2 - I_3) I_2) is negative in both stable cases
vals = {I1: 1, I2: 2, I3: 3, Om: sp.Rational(7, 5)}
kv = sp.sqrt(-kappa2.subs(vals))
x1s = stab.subs(k, kv)
x2s = sp.simplify(x1s.diff(t) / a1.subs(vals))
theta_true = -I1 * kv / ((I2 - I3) * Om)
check(132, sp.simplify(x2s - theta_true.subs(vals) * (c1 * sp.sin(kv * t) - c2 * sp.cos(kv * t))) == 0
      and sp.simplify(x2s.diff(t) - a2.subs(vals) * x1s) == 0)
theta_text = sp.sqrt((I3 - I1) * I1 / ((I2 - I3) * I2))
check(136, sp.simplify(theta_text.subs(vals) - theta_true.subs(vals)) == 0)
assert sp.simplify(sp.sqrt((I3 - I1) * I1 / ((I3 - I2) * I2)).subs(vals) - theta_true.subs(vals)) == 0
dw = sp.symbols('delta_omega', positive=True)
om_pert = sp.Matrix([x1s.subs({c1: dw, c2: 0}), x2s.subs({c1: dw, c2: 0}), vals[Om]])
check(142, truth_table.zero(om_pert - sp.Matrix([dw * sp.cos(kv * t), theta_true.subs(vals) * dw * sp.sin(kv * t), vals[Om]])))

LINES = [26, 31, 36, 45, 51, 67, 75, 79, 85, 99, 105, 112, 123, 127, 132, 136, 142]

ROWS = {
    26: ("holds", "Euler's equation with the derivative in the body frame: the inertial rate of L on the body axes is d^B L/dt + omega x L, equal to the torque (check 26)"),
    31: ("not a claim", "the law the handout starts from: the inertial rate of the angular momentum is the external torque"),
    36: ("holds", "the rate of a vector seen from frame B equals its rate seen from A plus omega_{A/B} x v, omega_{A/B} being A's rate relative to B (check 36)"),
    45: ("holds", "Euler's equations in the principal axes with tau = 0, from d^B L/dt + omega x L = 0 with L_i = I_i omega_i (check 45)"),
    51: ("holds", "the same equations divided by the moment on the left (check 51)"),
    67: ("holds", "first order of Euler's equations about (0, 0, Omega) with a transverse perturbation (check 67)"),
    75: ("holds", "differentiating the first linear equation and using the second (check 75)"),
    79: ("not a claim", "defines kappa^2"),
    85: ("holds", "kappa^2 is (I_2 - I_3)(I_3 - I_1) times Omega^2/(I_1 I_2) > 0, so it is negative exactly when that product is; the product is negative when I_3 is the largest or the smallest moment (check 85)"),
    99: ("not a claim", "defines the inertia tensor as the volume integral of rho (delta r^2 - r outer r)"),
    105: ("holds", "a homogeneous cylinder: m r^2/2 about its axis and m(3 r^2 + l^2)/12 about a transverse axis through its centre, by integration over its volume (check 105)"),
    112: ("fails", "moving the origin by R changes the inertia tensor by m(R^2 1 - R R^T): the display adds m R^2 to every moment, which is right only for the moments about axes perpendicular to R and leaves out the products of inertia -m R_i R_j (check 112)", None,
          "Hand: I'_ij = sum m (r'^2 delta_ij - r'_i r'_j) with r' = r + R; the cross terms vanish about the centre of mass, leaving I_ij + m (R^2 delta_ij - R_i R_j). For R along the body's axis 3 the moment I'_33 is unchanged (R^2 - R_3^2 = 0), while the display gives I_33 + m R^2.",
          "Numbers: a point mass m = 1 at the centre of mass (I = 0), shifted by R = (0, 0, 2): its moment about the new point's axis 3 (the line through the mass) is 0 and about axis 1 is 4, so I' = diag(4, 4, 0); the display gives diag(4, 4, 4)."),
    123: ("holds", "with kappa^2 < 0 the rate of the oscillation is sqrt(-kappa^2), the text's 'sin and cos of kappa t'; c_1 cos + c_2 sin of it is the general solution of the oscillator (check 123)"),
    127: ("typo", "the two terms are the same exponential, so the family has one free constant and is not the general solution; the second term should be exp(-kappa t), as the prose before writes exp(+-kappa t) (check 127)",
          "\\delta \\omega_1 = c_1 \\exp( \\kappa t ) + c_2 \\exp( -\\kappa t )",
          "Hand: x'' = kappa^2 x has the two independent solutions exp(kappa t) and exp(-kappa t); the written c_1 exp(kappa t) + c_2 exp(kappa t) = (c_1 + c_2) exp(kappa t), whose Wronskian with itself is 0, so x(0) and x'(0) cannot be set apart (x'(0) = kappa x(0) always).",
          "Numbers: kappa = 1, x(0) = 0, x'(0) = 1 (a start on the equilibrium with a kick): the solution is sinh t = (e^t - e^-t)/2, with c_1 = 1/2, c_2 = -1/2 in the corrected form; the written form gives x(0) = c_1 + c_2 = 0 and then x'(0) = 0, not 1."),
    132: ("holds", "integrating delta omega_2' = (I_3 - I_1) Omega delta omega_1 / I_2 with the stable solution gives Theta (c_1 sin - c_2 cos) with Theta = -I_1 k/((I_2 - I_3) Omega), k the oscillation rate (check 132, I_3 the largest moment)"),
    136: ("typo", "the factor from the integration, -I_1 k/((I_2 - I_3) Omega) with k^2 = -kappa^2, has the square (I_3 - I_1) I_1/((I_3 - I_2) I_2); the written radicand has I_2 - I_3 below, which is negative in both stable cases, so Theta would be imaginary (check 136)",
          "\\Theta = \\sqrt{ \\frac{ (I_3 - I_1) I_1 }{ ( I_3 - I_2 ) I_2 } }.",
          "Hand: from delta omega_1' = (I_2 - I_3) Omega delta omega_2 / I_1, delta omega_2 = I_1 delta omega_1'/((I_2 - I_3) Omega) = -I_1 k (c_1 sin - c_2 cos)/((I_2 - I_3) Omega), so Theta^2 = I_1^2 k^2/((I_2 - I_3)^2 Omega^2) = I_1^2 (I_3 - I_2)(I_3 - I_1)/(I_1 I_2 (I_3 - I_2)^2) = I_1 (I_3 - I_1)/(I_2 (I_3 - I_2)); the root is +Theta for I_3 the largest moment with Omega > 0.",
          "Numbers: I = (1, 2, 3), Omega = 1: k^2 = (3-2)(3-1)/2 = 1; delta omega_1 = cos t gives delta omega_1' = -sin t = (2-3) delta omega_2, so delta omega_2 = sin t and Theta = 1 = sqrt(2 x 1/(1 x 2)); the written radicand is 2 x 1/((2-3) x 2) = -1."),
    142: ("holds", "with delta omega(0) = (delta omega, 0, 0): c_1 = delta omega, c_2 = 0, so omega = (delta omega cos, Theta delta omega sin, Omega), Theta the factor from the integration (check 142)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
