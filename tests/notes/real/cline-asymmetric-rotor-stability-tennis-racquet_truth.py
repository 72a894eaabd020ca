"""Independent SymPy truth table for cline-asymmetric-rotor-stability-tennis-racquet.md.

The text's own setting: a rigid body turning freely about its centre of mass, body-fixed principal
axes e_1, e_2, e_3 with moments I_1, I_2, I_3, angular velocity omega = (omega_1, omega_2, omega_3)
and angular momentum L_i = I_i omega_i in those axes; no external torque, so dL/dt = 0 in space,
i.e. I omega' + omega x (I omega) = 0 in the body. In 13.22 the body spins about one principal axis
and the other two components (lambda, mu) are small: first order in them. The tennis racquet is a
uniform thin disk (head, radius R, mass M) and a uniform solid cylinder (handle, diameter R/10,
length 2R, mass M) on one line, axis 2 along the handle, axis 3 normal to the head. Every check is
built here from these definitions, never from the text's later displays.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero

t = sp.symbols("t", real=True)
I1, I2, I3 = sp.symbols("I_1 I_2 I_3", positive=True)
Ip = sp.diag(I1, I2, I3)
w = sp.Matrix(sp.symbols("omega_1:4", real=True))
L = sp.Matrix(sp.symbols("L_1:4", real=True))

# torque-free Euler's equations from I w' = (I w) x w (the body-frame form of dL/dt = 0)
wdot = Ip.inv() * (Ip * w).cross(w)

# 20: I_1 w1' = (I_2 - I_3) w2 w3 and its cyclic rows
check(20, zero(sp.Matrix([I1 * wdot[0] - (I2 - I3) * w[1] * w[2], I2 * wdot[1] - (I3 - I1) * w[2] * w[0],
                          I3 * wdot[2] - (I1 - I2) * w[0] * w[1]])))
# 26: in L_i = I_i w_i: I_2 I_3 L1' = (I_2 - I_3) L2 L3 and cyclic
Ldot = (Ip * wdot).subs({w[k]: L[k] / Ip[k, k] for k in range(3)})
check(26, zero(sp.Matrix([I2 * I3 * Ldot[0] - (I2 - I3) * L[1] * L[2], I1 * I3 * Ldot[1] - (I3 - I1) * L[2] * L[0],
                          I1 * I2 * Ldot[2] - (I1 - I2) * L[0] * L[1]])))
# 33: I_1 I_2 I_3 (L1 L1' + L2 L2' + L3 L3') = 0 along the motion
check(33, zero(I1 * I2 * I3 * L.dot(Ldot)))
# 40: L1^2 + L2^2 + L3^2 = L^2 with L the (constant) magnitude: the sum's rate vanishes
check(40, zero(L.dot(Ldot)))
# 46: I_2 I_3 L1 L1' + I_1 I_3 L2 L2' + I_1 I_2 L3 L3' = 0
check(46, zero(I2 * I3 * L[0] * Ldot[0] + I1 * I3 * L[1] * Ldot[1] + I1 * I2 * L[2] * Ldot[2]))
# 54: sum L_i^2 / (2 I_i) is the kinetic energy 1/2 sum I_i w_i^2, and it is conserved
T_L = sum(L[k] ** 2 / (2 * Ip[k, k]) for k in range(3))
T_w = sum(Ip[k, k] * w[k] ** 2 for k in range(3)) / 2
check(54, zero(T_L.subs({L[k]: Ip[k, k] * w[k] for k in range(3)}) - T_w)
      and zero(sum(sp.diff(T_L, L[k]) * Ldot[k] for k in range(3))))
# 63: on the sphere |L| = L, L^2/(2 I_3) <= T <= L^2/(2 I_1) when I_3 > I_2 > I_1: T is a weighted mean
# of 1/(2 I_k) with weights L_k^2 / L^2, so it lies between the smallest and the largest weight
a1, a2, a3 = sp.symbols("a_1:4", nonnegative=True)           # a_k = L_k^2 / L^2, a1 + a2 + a3 = 1
Tm = (a1 / I1 + a2 / I2 + (1 - a1 - a2) / I3) / 2
num = {I1: 1, I2: 2, I3: 3}
lo = sp.simplify(Tm - 1 / (2 * I3)).subs(num)                 # = a1 (1/I1 - 1/I3)/2 + a2 (1/I2 - 1/I3)/2
hi = sp.simplify(1 / (2 * I1) - Tm).subs(num)
check(63, sp.expand(lo - (a1 * sp.Rational(1, 3) + a2 * sp.Rational(1, 12))) == 0
      and sp.expand(hi - ((1 - a1 - a2) * sp.Rational(1, 3) + a2 * sp.Rational(1, 4))) == 0)
# 77, 83: the settings (a spin about e_1, then the disturbed angular velocity): not claims

# 89: Euler's equations with w = (w1, lambda, mu), exactly (nothing dropped yet)
w1 = sp.Function("omega_1")(t)
lam, mu = sp.Function("lambda")(t), sp.Function("mu")(t)
wl = sp.Matrix([w1, lam, mu])
resid = Ip * wl.diff(t) - (Ip * wl).cross(wl)                 # = 0 along the motion
rows90 = sp.Matrix([(I2 - I3) * lam * mu - I1 * w1.diff(t), (I3 - I1) * mu * w1 - I2 * lam.diff(t),
                    (I1 - I2) * w1 * lam - I3 * mu.diff(t)])
check(89, zero(rows90 + resid))
# the linear system with w1 constant (lambda mu dropped): lambda' = a mu, mu' = b lambda
W1 = sp.symbols("omega_1", real=True)
a = sp.solve(resid[1].subs(w1, W1), lam.diff(t))[0]
b = sp.solve(resid[2].subs(w1, W1), mu.diff(t))[0]
check(97, zero(a - (I3 - I1) / I2 * W1 * mu))
check(101, zero(b - (I1 - I2) / I3 * W1 * lam))
# 107: lambda'' = (I_3 - I_1)/I_2 w1 mu' (w1 constant)
lam2 = sp.diff(a, t)
check(107, zero(lam2 - (I3 - I1) / I2 * W1 * mu.diff(t)))
# 113: lambda'' + (I_1 - I_3)(I_1 - I_2)/(I_2 I_3) w1^2 lambda = 0
lam2 = lam2.subs(mu.diff(t), b)
k2 = (I1 - I3) * (I1 - I2) / (I2 * I3) * W1**2
check(113, zero(lam2 + k2 * lam))
# 125: the frequency Omega_{1 lambda} = w1 sqrt((I_1 - I_3)(I_1 - I_2)/(I_2 I_3)) squares to the coefficient
Om1 = W1 * sp.sqrt((I1 - I3) * (I1 - I2) / (I2 * I3))
check(125, zero(Om1**2 - k2))
# 119: lambda = A e^{i Om t} + B e^{-i Om t} solves lambda'' + Om^2 lambda = 0
A, B = sp.symbols("A B")
sol = A * sp.exp(sp.I * Om1 * t) + B * sp.exp(-sp.I * Om1 * t)
check(119, zero(sol.diff(t, 2) + k2 * sol))
# 132: the same for mu: mu'' = b a mu, so mu'' + Omega_1^2 mu = 0 with the same frequency
mu2 = sp.diff(b, t).subs(lam.diff(t), a)
check(132, zero(mu2 + Om1**2 * mu))


def spin_frequency_squared(axis):
    """The squared frequency of a small disturbance of a spin about principal axis `axis`, from the
    linearised torque-free Euler's equations: the disturbance obeys u'' = c u, frequency^2 = -c."""
    Ws = sp.symbols("W", real=True)
    e = sp.symbols("epsilon")
    u = [sp.Function(f"u_{k}")(t) for k in range(3)]
    ww = sp.Matrix([Ws if k == axis else e * u[k] for k in range(3)])
    rates = Ip.inv() * (Ip * ww).cross(ww)
    j, k = [m for m in range(3) if m != axis]
    uj = sp.expand(sp.series(rates[j], e, 0, 2).removeO() / e)      # u_j' = p u_k
    uk = sp.expand(sp.series(rates[k], e, 0, 2).removeO() / e)      # u_k' = q u_j
    c = sp.simplify(uj / u[k] * uk / u[j])
    return Ws, -c


# 138, 142: permuting the axes: Omega_2 and Omega_3
W, f2 = spin_frequency_squared(1)
check(138, zero(f2 - ((I2 - I1) * (I2 - I3) / (I1 * I3) * W**2)))
W, f3 = spin_frequency_squared(2)
check(142, zero(f3 - ((I3 - I2) * (I3 - I1) / (I1 * I2) * W**2)))
W, f1 = spin_frequency_squared(0)
assert zero(f1 - Om1.subs(W1, W) ** 2)                          # 13.171 from the same linearisation

# 167: the racquet. Head: thin disk (diametral I = M R^2/4, polar M R^2/2); handle of length 2R taken,
# as the chapter's table does, as a thin rod across (M l^2/12) and with M (R/10)^2/2 along (the stated
# diameter R/10 used as the radius); centres 2R apart on axis 2, the centre of mass halfway, each part's
# centre a distance R from it. The display holds for the moments the chapter states (2.5833 : 0.2550 :
# 2.8333); with the radius R/20 the handle's 1/200 would be 1/800 (a table entry, not a display).
M, R = sp.symbols("M R", positive=True)
l = 2 * R
head = [M * R**2 / 4 + M * R**2, M * R**2 / 4, M * R**2 / 2 + M * R**2]
handle = [M * l**2 / 12 + M * R**2, M * (R / 10)**2 / 2, M * l**2 / 12 + M * R**2]
Iq = [sp.simplify((h + g) / (M * R**2)) for h, g in zip(head, handle)]
table = [sp.Rational(31, 12), sp.Rational(51, 200), sp.Rational(17, 6)]
assert Iq == table, Iq
sq = {I1: table[0], I2: table[1], I3: table[2]}
r1 = complex(sp.sqrt(((I1 - I3) * (I1 - I2) / (I2 * I3)).subs(sq)))
r2 = complex(sp.sqrt(((I2 - I1) * (I2 - I3) / (I1 * I3)).subs(sq)))
r3 = complex(sp.sqrt(((I3 - I2) * (I3 - I1) / (I1 * I2)).subs(sq)))
check(167, abs(r1 - 0.8976j) < 5e-5 and abs(r2 - 0.9056) < 5e-5 and abs(r3 - 0.9892) < 5e-5)

# negative controls: the checks above can fail
assert not zero(sp.Matrix([I1 * wdot[0] - (I3 - I2) * w[1] * w[2]]))
assert abs(r1 - 0.8976) > 0.1

LINES = [20, 26, 33, 40, 46, 54, 63, 77, 83, 89, 97, 101, 107, 113, 119, 125, 132, 138, 142, 167]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
