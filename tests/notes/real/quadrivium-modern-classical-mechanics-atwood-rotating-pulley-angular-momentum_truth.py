"""Independent SymPy truth table for
quadrivium-modern-classical-mechanics-atwood-rotating-pulley-angular-momentum.md
(Modern Classical Mechanics, week 13 notes, the Atwood machine with a rotating pulley, MyST edition).

The text's convention: heights y_1 (mass M) and y_2 (mass m) measured upward from the pulley's
centre; the string's fixed length gives y_2 = (l - pi R) - y_1, so U_0 = m g (l - pi R); the
pulley, a uniform disk of mass M_p and radius R, turns through phi with y_1 = R phi + R phi_0 (no
slip). Here M hangs on the string's tangent line x = +R, m on x = -R, phi counted counterclockwise
(z out of the page), so a counterclockwise turn lifts M: that is the text's y_1' = R phi'.
Everything is built from that: the disk's kinetic energy and angular momentum by integration over
the disk, the masses' from r x m v, the Lagrangian from T - V, the equation of motion from the
Euler-Lagrange equation; no formula of the text is assumed.
Run as a program it compares its verdicts with the table; ``--write`` writes the table.
"""
import sys

import sympy as sp

import truth_table
from truth_table import zero

t = sp.Symbol('t', real=True)
M, m, Mp, R, g, l, phi0 = sp.symbols('M m M_p R g l phi_0', positive=True)
ph = sp.Function('phi')(t)
D = lambda e: sp.diff(e, t)  # noqa: E731
w = D(ph)

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


# the uniform disk: surface density, kinetic energy and angular momentum by integration
r, a = sp.symbols('r a', positive=True)
sig = Mp / (sp.pi * R**2)
Idisk = sp.integrate(sp.integrate(sig * r**2 * r, (a, 0, 2 * sp.pi)), (r, 0, R))
Tdisk = sp.integrate(sp.integrate(sp.Rational(1, 2) * sig * (r * w)**2 * r, (a, 0, 2 * sp.pi)), (r, 0, R))
Ldisk = sp.integrate(sp.integrate(sig * r * (r * w) * r, (a, 0, 2 * sp.pi)), (r, 0, R))  # z of r x v dm

# the masses
y1 = R * ph + R * phi0
y2 = (l - sp.pi * R) - y1
U0 = m * g * (l - sp.pi * R)
Tmass = sp.Rational(1, 2) * M * D(y1)**2 + sp.Rational(1, 2) * m * D(y2)**2
V = M * g * y1 + m * g * y2
T = Tmass + Tdisk
Lag = T - V
rM, vM = sp.Matrix([R, y1, 0]), sp.Matrix([0, D(y1), 0])
rm, vm = sp.Matrix([-R, y2, 0]), sp.Matrix([0, D(y2), 0])
LM = (M * rM.cross(vM))[2]
Lm = (m * rm.cross(vm))[2]
Ltot = Ldisk + LM + Lm

yd1 = sp.Symbol('ydot_1')      # y_1' kept as a letter where the text keeps it
half = sp.Rational(1, 2)

# line 24: the disk's kinetic energy is (1/2) I omega^2 with I = int r^2 dm
check(24, zero(Tdisk - half * Idisk * w**2))
# line 29: the uniform disk's moment about its axis
check(29, zero(Idisk - half * Mp * R**2))
# lines 31, 32
check(31, zero(Tdisk - half * (half * Mp * R**2) * w**2))
check(32, zero(Tdisk - sp.Rational(1, 4) * Mp * R**2 * w**2))
# line 36: masses (y_2' = -y_1') plus disk, with y_1' kept
Tmass_y = half * M * yd1**2 + half * m * (-yd1)**2
check(36, zero(Tmass_y + Tdisk - (half * (M + m) * yd1**2 + sp.Rational(1, 4) * Mp * R**2 * w**2)))
# line 40: integrating dy_1 = R dphi gives R phi plus a constant, written R phi_0
check(40, zero(sp.diff(R * ph + R * phi0, t) - R * w) and zero(y1 - (R * ph + R * phi0)))
# line 42
check(42, zero(D(y1) - R * w))
# line 46: the same as line 36
check(46, CHECKS[36])
# line 47
check(47, zero(T - half * (M + m + half * Mp) * R**2 * w**2))
# lines 49-51: V = M g y_1 + m g y_2
check(49, zero(V - ((M - m) * g * y1 + U0)))
check(50, zero(V - ((M - m) * g * (R * ph + R * phi0) + U0)))
U0t = (M - m) * g * R * phi0 + U0
check(51, zero(V - ((M - m) * g * R * ph + U0t)))
# line 56: the definition of the Lagrangian (not a claim)
# line 57: T - V up to the constant U~_0, which the text has just said does not enter the equations
L57 = half * (M + m + half * Mp) * R**2 * w**2 - (M - m) * g * R * ph
diff57 = sp.simplify(Lag - L57)
check(57, zero(diff57 + U0t))
# lines 64, 69: the generalized force and momentum
q, qd = sp.symbols('q qdot')
Lq = Lag.subs(w, qd).subs(ph, q)
check(64, zero(sp.diff(Lq, q) + (M - m) * g * R))
p69 = sp.diff(Lq, qd)
check(69, zero(p69 - (M + m + half * Mp) * R**2 * qd))
# line 75: the total as the sum of its parts (a definition, not a claim)
# line 77: the disk's angular momentum, z component of int r x v dm
check(77, zero(Ldisk - Idisk * w) and zero(Ldisk - half * Mp * R**2 * w))
# lines 79, 81: r x m v of each mass (definitions, not claims)
# lines 85, 89: the sum, out of the page (+z) for phi' > 0
check(85, zero(Ltot - (half * Mp + M + m) * R**2 * w))
check(89, CHECKS[85])
# line 90: p_phi = L_total
check(90, zero(p69.subs(qd, w) - Ltot))
# lines 96, 97: the Euler-Lagrange equation, dL/dphi - d/dt dL/dphi' = 0
EL = sp.diff(Lq, q).subs(q, ph) - D(p69.subs(qd, w))
check(96, zero(EL - (-(M - m) * g * R - D((M + m + half * Mp) * R**2 * w))))
check(97, zero(EL - (-(M - m) * g * R - (M + m + half * Mp) * R**2 * D(w))))
# line 101: solved for phi''
acc = sp.solve(sp.Eq(EL, 0), D(w))[0]
check(101, zero(acc - (-(g / R) * (M - m) / (M + m + half * Mp))))

LINES = [24, 29, 31, 32, 36, 40, 42, 46, 47, 49, 50, 51, 56, 57, 64, 69, 75, 77, 79, 81, 85, 89, 90, 96, 97, 101]

ROWS = {
    24: ("holds", "integrating (1/2) sigma (r phi')^2 over the disk gives (1/2) I phi'^2 with I = int r^2 dm (check 24)"),
    29: ("holds", "a uniform disk: int r^2 dm = (M_p/(pi R^2)) int_0^R 2 pi r^3 dr = M_p R^2/2 (check 29)"),
    31: ("holds", "(1/2) I omega^2 with I = M_p R^2/2 and omega = phi' (check 31)"),
    32: ("holds", "(1/2)(1/2) M_p R^2 phi'^2 = (1/4) M_p R^2 phi'^2 (check 32)"),
    36: ("holds", "the masses' (1/2) M y_1'^2 + (1/2) m y_2'^2 with y_2' = -y_1' is (1/2)(M+m) y_1'^2, plus the pulley's (1/4) M_p R^2 phi'^2 (check 36)"),
    40: ("holds", "integrating dy_1 = R dphi gives y_1 = R phi plus a constant, written R phi_0 (check 40)"),
    42: ("holds", "the time derivative of y_1 = R phi + R phi_0 (check 42)"),
    46: ("holds", "the same kinetic energy as line 36, before y_1' = R phi' is put in (check 46)"),
    47: ("holds", "with y_1' = R phi': (1/2)(M+m) R^2 phi'^2 + (1/4) M_p R^2 phi'^2 = (1/2)(M + m + M_p/2) R^2 phi'^2 (check 47)"),
    49: ("holds", "V = M g y_1 + m g y_2 with y_2 = (l - pi R) - y_1 is (M-m) g y_1 + m g (l - pi R) = (M-m) g y_1 + U_0 (check 49)"),
    50: ("holds", "y_1 = R phi + R phi_0 put in (check 50)"),
    51: ("holds", "expanding, with U~_0 = (M-m) g R phi_0 + U_0 as the text defines it (check 51)"),
    56: ("not a claim", "the definition of the Lagrangian, L = T - V"),
    57: ("holds", "T - V from lines 47 and 51, the constant -U~_0 dropped as the text has just said it may be (it changes no equation of motion); the phi- and phi'-dependence agrees exactly (check 57)"),
    64: ("holds", "dL/dphi = -(M-m) g R, the generalized force (a torque about the axle) (check 64)"),
    69: ("holds", "dL/dphi' = (M + m + M_p/2) R^2 phi' (check 69)"),
    75: ("not a claim", "the total angular momentum named as the sum of the disk's and the two masses'"),
    77: ("holds", "the z component of int r x v dm over the disk is int r^2 phi' dm = I phi' = (1/2) M_p R^2 phi' (check 77)"),
    79: ("not a claim", "the definition r x m v of the angular momentum of mass M, to be computed"),
    81: ("not a claim", "the definition r x m v of the angular momentum of mass m, to be computed"),
    85: ("holds", "M at x = +R with velocity y_1' = R phi' gives z component M R y_1' = M R^2 phi'; m at x = -R with y_2' = -R phi' gives m (-R)(-R phi') = m R^2 phi'; with the disk's, (M_p/2 + M + m) R^2 phi' along +z (check 85)"),
    89: ("holds", "the magnitude of line 85 (check 89)"),
    90: ("holds", "p_phi of line 69 equals L_total of line 89 (check 90)"),
    96: ("holds", "the Euler-Lagrange equation dL/dphi - d/dt(dL/dphi') = 0 with lines 64 and 69 (check 96)"),
    97: ("holds", "the same with the constant coefficient taken out of the time derivative (check 97)"),
    101: ("holds", "solving line 97 for phi'': -(g/R)(M-m)/(M + m + M_p/2) (check 101)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
