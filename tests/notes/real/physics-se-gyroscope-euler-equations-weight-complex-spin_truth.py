"""Independent SymPy truth table for physics-se-gyroscope-euler-equations-weight-complex-spin.md.

The question's convention: principal moments I_1 = I_2 = I and I_3, body components omega_i of the
angular velocity, the weight's torque taken as mgd about the second body axis (the question's own
model, kept as its premise). Euler's equations come from the body-frame law
I omega-dot + omega x (I omega) = tau; the complex spin u = omega_2 + i omega_1 is solved from
u(0) = 0; the Euler angles are Goldstein's z-x-z ones, the body angular velocity read from
R^T R-dot of R = R_z(phi) R_x(theta) R_z(psi) with the body axes the columns of R.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Rz
from truth_table import zero

t = sp.symbols('t', real=True)
I, I3, m, g, d, w3 = sp.symbols('I I_3 m g d omega_3', positive=True)
w1, w2 = sp.Function('omega_1')(t), sp.Function('omega_2')(t)
w = sp.Matrix([w1, w2, w3])
J = sp.diag(I, I, I3)
tau = sp.Matrix([0, m * g * d, 0])
law = J * w.diff(t) + w.cross(J * w) - tau          # = 0 along the motion

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


# lines 14, 16, 18: the three rows as printed, each the law's row (omega_3 constant in the third)
check(14, zero((w1.diff(t) * I - (I - I3) * w2 * w3) - law[0]))
check(16, zero((w2.diff(t) * I + (I - I3) * w3 * w1 - m * g * d) - law[1]))
# the third row of the law is I_3 omega_3-dot = 0; the printed I omega_3-dot = 0 says the same, I > 0
w3f = sp.Function('omega_3')(t)
row3 = (J * sp.Matrix([w1, w2, w3f]).diff(t) + sp.Matrix([w1, w2, w3f]).cross(
    J * sp.Matrix([w1, w2, w3f])) - tau)[2]
check(18, zero(row3 - I3 * w3f.diff(t)) and sp.solve(w3f.diff(t) * I, w3f.diff(t)) == [0])

# the law solved for the rates
rates = sp.solve([law[0], law[1]], [w1.diff(t), w2.diff(t)])
Om = (I - I3) / I * w3
al = m * g * d / I

# line 23: (omega_2' + i omega_1') - Omega i (omega_2 + i omega_1) = alpha along the motion
lhs23 = (w2.diff(t) + sp.I * w1.diff(t)) - Om * sp.I * (w2 + sp.I * w1)
check(23, zero(lhs23.subs(rates) - al))

# line 27: the same for u = omega_2 + i omega_1
u = sp.Function('u')(t)
check(27, zero((u.diff(t) - Om * sp.I * u).subs(u, w2 + sp.I * w1).doit().subs(rates) - al))

# lines 32, 34: the solution with u(0) = 0 (omega_0 = (0, 0, omega_3))
usol = sp.dsolve(sp.Eq(u.diff(t) - Om * sp.I * u, al), u, ics={u.subs(t, 0): 0}).rhs
w2sol = sp.simplify(sp.re(sp.expand_complex(usol)))
w1sol = sp.simplify(sp.im(sp.expand_complex(usol)))
check(32, zero(w2sol - al / Om * sp.sin(Om * t)))
check(34, zero(w1sol - al / Om * (1 - sp.cos(Om * t))))

# lines 39-43: body components of the angular velocity in z-x-z Euler angles
ph, th, ps = [sp.Function(n)(t) for n in ('phi', 'theta', 'psi')]


R = Rz(ph) * Rx(th) * Rz(ps)
W = sp.simplify(R.T * R.diff(t))
wb = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])
check(39, zero(wb[0] - (ph.diff(t) * sp.sin(th) * sp.sin(ps) + th.diff(t) * sp.cos(ps))))
check(41, zero(wb[1] - (ph.diff(t) * sp.sin(th) * sp.cos(ps) - th.diff(t) * sp.sin(ps))))
check(43, zero(wb[2] - (ph.diff(t) * sp.cos(th) + ps.diff(t))))

# line 48: at theta = pi/2, theta-dot = 0: omega_1^2 + omega_2^2 = phi-dot^2; the printed root has
# omega_2 unsquared.  Its first equality, phidot = sqrt(omega_1^2 + omega_2), fails; with omega_2^2
# both equalities hold for the solution of lines 32 and 34.
flat = {th.diff(t): 0}
b1 = wb[0].subs(flat).subs(th, sp.pi / 2)
b2 = wb[1].subs(flat).subs(th, sp.pi / 2)
pd = sp.symbols('phidot', positive=True)
sq = sp.simplify((b1**2 + b2**2).subs(ph.diff(t), pd))
first_ok = zero(sq - pd**2) and sp.simplify(sp.sqrt(b1**2 + b2).subs(ph.diff(t), pd) - pd) == 0
second = sp.sqrt(w1sol**2 + w2sol**2) - al * sp.sqrt(2) / Om * sp.sqrt(1 - sp.cos(Om * t))
printed_second = sp.sqrt(w1sol**2 + w2sol) - al * sp.sqrt(2) / Om * sp.sqrt(1 - sp.cos(Om * t))
assert zero(sq - pd**2) and zero(second.subs(t, sp.Rational(7, 10)).subs(
    {I: 2, I3: 1, m: 1, g: 10, d: sp.Rational(1, 3), w3: 5}))
assert not zero(printed_second.subs(t, sp.Rational(7, 10)).subs(
    {I: 2, I3: 1, m: 1, g: 10, d: sp.Rational(1, 3), w3: 5}))
check(48, first_ok)

LINES = [14, 16, 18, 23, 27, 32, 34, 39, 41, 43, 48]

H48_1 = ("At theta = pi/2, thetadot = 0 the rows of lines 39 and 41 give omega_1 = phidot sin psi, "
         "omega_2 = phidot cos psi, so omega_1^2 + omega_2^2 = phidot^2 and phidot = sqrt(omega_1^2 + omega_2^2); "
         "the display's sqrt(omega_1^2 + omega_2) is not this (it is not even of the dimension of a rate).")
H48_2 = ("Its right side: (alpha/Omega)^2 [(1 - cos)^2 + sin^2] = (alpha/Omega)^2 (2 - 2 cos), whose root is "
         "alpha sqrt(2)/Omega sqrt(1 - cos(Omega t)), the printed value; it is the root of omega_1^2 + omega_2^2, "
         "so only the square on omega_2 is missing. At I = 2, I_3 = 1, mgd = 10/3, omega_3 = 5, t = 0.7 the "
         "printed middle and right sides differ.")

ROWS = {
    14: ("holds", "Euler's equation along the first principal axis with I_1 = I_2 = I and no torque about it: I omega_1-dot - (I_2 - I_3) omega_2 omega_3 = 0 (check 14)"),
    16: ("holds", "Euler's equation along the second axis with the torque mgd the question takes about it: I omega_2-dot - (I_3 - I_1) omega_3 omega_1 = mgd (check 16)"),
    18: ("holds", "the third equation is I_3 omega_3-dot = (I_1 - I_2) omega_1 omega_2 = 0; written with I for I_3 it says the same, omega_3-dot = 0 (check 18)"),
    23: ("holds", "with the first two equations, omega_1-dot = Omega omega_2 and omega_2-dot = -Omega omega_1 + alpha, so the combination is alpha (check 23)"),
    27: ("holds", "the same equation for u = omega_2 + i omega_1 (check 27)"),
    32: ("holds", "the real part of the solution u = alpha/(i Omega) (e^{i Omega t} - 1) with u(0) = 0 (check 32)"),
    34: ("holds", "the imaginary part of the same solution (check 34)"),
    39: ("holds", "the first body component of the angular velocity in z-x-z Euler angles, from R^T R-dot (check 39)"),
    41: ("holds", "the second body component, from R^T R-dot (check 41)"),
    43: ("holds", "the third body component, from R^T R-dot (check 43)"),
    48: ("typo", "at theta = pi/2 with no nutation phidot = sqrt(omega_1^2 + omega_2^2); the display drops the square on omega_2, its right side being the root of omega_1^2 + omega_2^2 for lines 32 and 34 (check 48)",
         "\\dot{\\phi} = \\sqrt{\\omega_1^2+ \\omega_2^2} = \\frac{\\alpha \\sqrt{2}}{\\Omega} \\sqrt{1-\\cos (\\Omega t)}",
         H48_1, H48_2),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
