"""Independent SymPy truth table for continuum-lab-dzhanibekov-intermediate-axis-es.md.

The text's own set-up: a free rigid body (no torque), principal moments I_1 < I_2 < I_3 with the
model's values 1.0, 2.4, 4.2 kg m^2, body angular velocity omega = (omega_1, omega_2, omega_3) along
the principal axes; R maps body components to inertial ones, and the body angular velocity is
defined by dR/dt = R [omega]x. Euler's equations are derived here from the constancy of the
inertial angular momentum R I omega, not assumed. The disturbed spin about the intermediate axis
is (d1, Omega_0 + d2, d3) with d small (first order kept). The two conserved values the text states
(172.80 J and 829.44) are those of the state its module integrates, omega(0) = (2e-5,
Omega_0, d3) with Omega_0 = 12 rad/s (the module src/physics/euler_rigid_body.py of the same
folder, get_optimal_perturbation(12.0)); the text itself does not state Omega_0. The quaternion is
q = [q_w, q_x, q_y, q_z], R(q) the usual rotation matrix of a unit quaternion (Hamilton product).
"""
import random
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


z0 = truth_table.zero
I1, I2, I3 = sp.symbols('I_1 I_2 I_3', positive=True)
w = sp.Matrix(sp.symbols('omega_1:4', real=True))
wd = sp.Matrix(sp.symbols('omegadot_1:4', real=True))
I = sp.diag(I1, I2, I3)


def skew(v):
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


# d/dt (R I omega) = R ([omega]x I omega + I omega-dot) (dR/dt = R [omega]x): zero without torque,
# so I omega-dot = -omega x (I omega), solved for the rates
rates = sp.solve(list(skew(w) * I * w + I * wd), list(wd), dict=True)[0]
# 20, 22, 24: I_1 omega_1' = (I_2 - I_3) omega_2 omega_3 and its cyclic companions
check(20, z0(I1 * rates[wd[0]] - (I2 - I3) * w[1] * w[2]))
check(22, z0(I2 * rates[wd[1]] - (I3 - I1) * w[2] * w[0]))
check(24, z0(I3 * rates[wd[2]] - (I1 - I2) * w[0] * w[1]))
# 27: the model's moments, 1.0 < 2.4 < 4.2 (a setting, not a claim)
num = {I1: sp.Rational(1), I2: sp.Rational(24, 10), I3: sp.Rational(42, 10)}
# 32: the disturbed spin about the intermediate axis (a setting, not a claim)
eps, W0 = sp.symbols('epsilon Omega_0', positive=True)
d1, d2, d3 = sp.symbols('delta1 delta2 delta3', real=True)
state = {w[0]: eps * d1, w[1]: W0 + eps * d2, w[2]: eps * d3}


def first_order(expr):
    """The part of expr of first order in the disturbance, divided by epsilon."""
    return sp.expand(expr.subs(state)).coeff(eps, 1)


rate1, rate3 = first_order(rates[wd[0]]), first_order(rates[wd[2]])
# 35: d(delta omega_1)/dt ~ (I_2 - I_3)/I_1 Omega_0 delta omega_3
check(35, z0(rate1 - (I2 - I3) / I1 * W0 * d3))
# 36: d(delta omega_3)/dt ~ (I_1 - I_2)/I_3 Omega_0 delta omega_1
check(36, z0(rate3 - (I1 - I2) / I3 * W0 * d1))
# 39: the second derivative of delta omega_1, putting 36 into the derivative of 35
second = sp.diff(rate1, d3) * rate3              # d/dt of (c d3) with d3' from 36
check(39, z0(second - (I2 - I3) * (I1 - I2) / (I1 * I3) * W0**2 * d1))
# 42, 43, 44: the two factors and their product with the model's moments
check(42, (I2 - I3).subs(num) == sp.Rational(-18, 10) and (I2 - I3).subs(num) < 0)
check(43, (I1 - I2).subs(num) == sp.Rational(-14, 10) and (I1 - I2).subs(num) < 0)
check(44, ((I2 - I3) * (I1 - I2)).subs(num) == sp.Rational(252, 100) and sp.Rational(-18, 10) * sp.Rational(-14, 10) == sp.Rational(252, 100))
# 47: delta omega_1'' = lambda^2 delta omega_1, lambda = Omega_0 sqrt((I_2 - I_1)(I_3 - I_2)/(I_1 I_3))
#     = Omega_0 sqrt(1.4 x 1.8 / (1.0 x 4.2)) = Omega_0 sqrt(0.6) ~ 0.7746 Omega_0
lam = W0 * sp.sqrt((I2 - I1) * (I3 - I2) / (I1 * I3))
check(47, z0(second - lam**2 * d1)
      and z0(lam.subs(num) - W0 * sp.sqrt(sp.Rational(14, 10) * sp.Rational(18, 10) / (1 * sp.Rational(42, 10))))
      and z0(lam.subs(num) - W0 * sp.sqrt(sp.Rational(6, 10)))
      and abs(sp.N(sp.sqrt(sp.Rational(6, 10)), 20) - sp.Float('0.7746', 20)) < 5e-5)
# 50: delta omega_1 = C_1 e^{lambda t} + C_2 e^{-lambda t} solves it
t, C1, C2, L_ = sp.symbols('t C_1 C_2 lambda', positive=True)
sol = C1 * sp.exp(L_ * t) + C2 * sp.exp(-L_ * t)
check(50, z0(sp.diff(sol, t, 2) - L_**2 * sol))

# 62, 66: the conserved 2T and |L|^2, and their values for the module's state
twoT = (I * w).dot(w)
L2 = (I * w).dot(I * w)
assert z0(sp.diff(twoT, w[0]) * rates[wd[0]] + sp.diff(twoT, w[1]) * rates[wd[1]] + sp.diff(twoT, w[2]) * rates[wd[2]])
assert z0(sp.diff(L2, w[0]) * rates[wd[0]] + sp.diff(L2, w[1]) * rates[wd[1]] + sp.diff(L2, w[2]) * rates[wd[2]])
ratio = sp.sqrt(num[I3] * (num[I3] - num[I2]) / (num[I1] * (num[I2] - num[I1])))
delta1 = sp.Rational(2, 10**5)
w0 = {w[0]: delta1, w[1]: 12, w[2]: delta1 / ratio * (1 - sp.Rational(1, 10**12))}
twoT0, L20 = twoT.subs(num).subs(w0), L2.subs(num).subs(w0)
check(62, abs(sp.N(twoT0, 20) - 172.80) < 0.005)
check(66, abs(sp.N(L20, 20) - 829.44) < 0.005)
assert abs(sp.N(twoT0 / 2, 20) - 172.80) < 0.005        # 172.80 J is T, not 2T
assert abs(sp.N(twoT0 * num[I2] - L20, 20)) < 1e-6      # 2T I_2 = |L|^2 near the separatrix

# 82: dq/dt = 1/2 q (x) (0, omega_b) carries dR/dt = R [omega_b]x, sampled at unit quaternions
qs = sp.symbols('q_w q_x q_y q_z', real=True)


def rot(q):
    qw, qx, qy, qz = q
    return sp.Matrix([[1 - 2 * (qy**2 + qz**2), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)],
                      [2 * (qx * qy + qz * qw), 1 - 2 * (qx**2 + qz**2), 2 * (qy * qz - qx * qw)],
                      [2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx**2 + qy**2)]])


def hamilton(p, q):
    pw, px, py, pz = p
    qw, qx, qy, qz = q
    return [pw * qw - px * qx - py * qy - pz * qz, pw * qx + px * qw + py * qz - pz * qy,
            pw * qy - px * qz + py * qw + pz * qx, pw * qz + px * qy - py * qx + pz * qw]


Rq = rot(qs)
rng = random.Random(5)
ok82 = True
for _ in range(5):
    raw = [sp.Rational(rng.randint(-9, 9), 7) for _ in range(4)]
    n = sp.sqrt(sum(c**2 for c in raw))
    qv = [c / n for c in raw]
    wv = sp.Matrix([sp.Rational(rng.randint(-9, 9), 5) for _ in range(3)])
    qdot = [c / 2 for c in hamilton(qv, [0, *wv])]
    Rdot = sum((Rq.diff(qs[k]) * qdot[k] for k in range(4)), sp.zeros(3, 3))
    sub = dict(zip(qs, qv))
    ok82 &= z0(Rdot.subs(sub) - Rq.subs(sub) * skew(wv))
check(82, ok82)
# 86: r_space = R(q) r_body, what R(q) is (not a claim)
# 89: L_s = R I omega is constant: d/dt (R I omega) = R ([omega]x I omega + I omega-dot) = 0
check(89, z0(skew(w) * I * w + I * sp.Matrix([rates[wd[k]] for k in range(3)])))

LINES = [20, 22, 24, 27, 32, 35, 36, 39, 42, 43, 44, 47, 50, 62, 66, 82, 86, 89]

ROWS = {
    20: ("holds", "the constancy of the inertial angular momentum R I omega gives I omega-dot = -omega x (I omega); its first row (check 20)"),
    22: ("holds", "the second row of I omega-dot = -omega x (I omega) (check 22)"),
    24: ("holds", "the third row of I omega-dot = -omega x (I omega) (check 24)"),
    27: ("not a claim", "sets the model's three principal moments, 1.0, 2.4 and 4.2 kg m^2, and says they are ordered"),
    32: ("not a claim", "sets the disturbed spin about the intermediate axis that the linearisation starts from"),
    35: ("holds", "the first Euler equation to first order in the disturbance: (I_2 - I_3)/I_1 Omega_0 delta omega_3 (check 35)"),
    36: ("holds", "the third Euler equation to first order: (I_1 - I_2)/I_3 Omega_0 delta omega_1 (check 36)"),
    39: ("holds", "the derivative of 35 with 36 put in: (I_2 - I_3)(I_1 - I_2)/(I_1 I_3) Omega_0^2 delta omega_1 (check 39)"),
    42: ("holds", "2.4 - 4.2 = -1.8 < 0 (check 42)"),
    43: ("holds", "1.0 - 2.4 = -1.4 < 0 (check 43)"),
    44: ("holds", "(-1.8)(-1.4) = 2.52 > 0 (check 44)"),
    47: ("holds", "(I_2 - I_3)(I_1 - I_2) = (I_2 - I_1)(I_3 - I_2), so lambda^2 is the bracket of 39; 1.4 x 1.8 / 4.2 = 0.6 and sqrt(0.6) = 0.77460 (check 47)"),
    50: ("holds", "C_1 e^{lambda t} + C_2 e^{-lambda t} solves x'' = lambda^2 x (check 50)"),
    62: ("typo", "2T = I_1 omega_1^2 + I_2 omega_2^2 + I_3 omega_3^2 is conserved, but for the state the module integrates (omega_2 = Omega_0 = 12 rad/s, the other two of order 1e-5) it is 2.4 x 144 = 345.60 J: 172.80 J is T itself; the text's own separatrix relation 2 T I_2 = |L|^2 with its |L|^2 = 829.44 also asks for 2T = 345.60 (check 62)",
         "2 T_{\\text{rot}} = I_1 \\omega_1^2 + I_2 \\omega_2^2 + I_3 \\omega_3^2 = \\text{cte} = 345.60\\ \\text{J}",
         "With omega = (2e-5, 12, ~8.6e-6): I_2 omega_2^2 = 2.4 x 144 = 345.6, the other two terms about 1e-9; so 2T = 345.60 J and T = 172.80 J, the number the display gives for 2T.",
         "The text's separatrix condition 2 T I_2 = |L|^2: with its two numbers 172.80 x 2.4 = 414.72, not 829.44; with 2T = 345.60, 345.60 x 2.4 = 829.44 exactly, the |L|^2 of the next display (and |L|^2/(2T) = I_2 holds for any spin about the second axis)."),
    66: ("holds", "|L|^2 = sum of I_k^2 omega_k^2 is conserved; for the module's state 2.4^2 x 144 = 829.44 (check 66)"),
    82: ("holds", "with q-dot = 1/2 q (x) (0, omega_b) the matrix R(q) of a unit quaternion moves by dR/dt = R [omega_b]x, omega_b the body angular velocity (check 82)"),
    86: ("not a claim", "says what the matrix R(q) does: it carries body components to inertial ones"),
    89: ("holds", "L_s = R I_b omega_b is constant: its rate R ([omega]x I omega + I omega-dot) vanishes by Euler's equations (check 89)"),
}


if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
