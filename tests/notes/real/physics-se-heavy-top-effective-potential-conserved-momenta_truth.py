"""Independent SymPy truth table for physics-se-heavy-top-effective-potential-conserved-momenta.md.

The question's convention: z-x-z Euler angles (phi precession, theta nutation, psi spin), principal
moments I_1 = I_2 and I_3 about the fixed point, l the distance from it to the centre of mass. The
Lagrangian is rebuilt from T = (I_1 (omega_1^2 + omega_2^2) + I_3 omega_3^2) / 2 with the body
components of the z-x-z angular velocity and V = m g l cos(theta); the momenta are its partial
derivatives at fixed angles; the theta equation is Lagrange's, the rates eliminated through the momenta.
Run as a program it compares its verdicts with the table; ``--write`` writes the table.
"""
import sys

import sympy as sp

import truth_table
from truth_table import zero

I1, I3, m, g, l = sp.symbols('I_1 I_3 m g l', positive=True)
th, ph, ps, thd, phd, psd, thdd = sp.symbols('theta phi psi thetadot phidot psidot thetaddot', real=True)
pphi, ppsi = sp.symbols('p_phi p_psi', real=True)

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


# body components of the z-x-z angular velocity
w1 = phd * sp.sin(th) * sp.sin(ps) + thd * sp.cos(ps)
w2 = phd * sp.sin(th) * sp.cos(ps) - thd * sp.sin(ps)
w3 = phd * sp.cos(th) + psd
T = (I1 * (w1**2 + w2**2) + I3 * w3**2) / 2
V = m * g * l * sp.cos(th)
L = T - V

# line 14: the Lagrangian as printed
L14 = I1 / 2 * (thd**2 + phd**2 * sp.sin(th)**2) + I3 / 2 * (psd + phd * sp.cos(th))**2 - m * g * l * sp.cos(th)
check(14, zero(L - L14))

# lines 30, 32: the momenta of the cyclic angles
p_phi = sp.diff(L, phd)
p_psi = sp.diff(L, psd)
check(30, zero(p_phi - (I1 * phd * sp.sin(th)**2 + I3 * (psd + phd * sp.cos(th)) * sp.cos(th))))
check(32, zero(p_psi - I3 * (psd + phd * sp.cos(th))))

# line 36: the precession rate from the two momenta
sol = sp.solve([sp.Eq(pphi, p_phi), sp.Eq(ppsi, p_psi)], [phd, psd], dict=True)[0]
check(36, zero(sol[phd] - (pphi - ppsi * sp.cos(th)) / (I1 * sp.sin(th)**2)))

# Lagrange's equation for theta: d/dt dL/dthetadot = I_1 thetaddot (dL/dthetadot = I_1 thetadot), so
# I_1 thetaddot = dL/dtheta at fixed rates, the rates then written through the momenta
assert zero(sp.diff(L, thd) - I1 * thd)
rhs = sp.diff(L, th).subs(sol)

# line 44: the right-hand side as printed
rhs44 = ((pphi - ppsi * sp.cos(th))**2 / (I1 * sp.sin(th)**3) * sp.cos(th)
         - ppsi * (pphi - ppsi * sp.cos(th)) / (I1 * sp.sin(th)**2) * sp.sin(th)
         - sp.diff(m * g * l * sp.cos(th), th))
check(44, zero(rhs - rhs44))

# lines 20, 48: -dV_eff/dtheta at constant momenta (they are constants of the motion) is that right-hand side
Veff = (pphi - ppsi * sp.cos(th))**2 / (2 * I1 * sp.sin(th)**2) + m * g * l * sp.cos(th)
check(48, zero(-sp.diff(Veff, th) - rhs44))
check(20, zero(-sp.diff(Veff, th) - rhs))

LINES = [14, 20, 24, 30, 32, 36, 40, 44, 48]

ROWS = {
    14: ("holds", "T - V with I_2 = I_1, the body components of the z-x-z angular velocity and V = m g l cos(theta) (check 14)"),
    20: ("holds", "Lagrange's equation for theta is I_1 thetaddot = dL/dtheta at fixed rates; with phidot and psidot written through the constant momenta it is -dV_eff/dtheta for the V_eff of the next display (check 20)"),
    24: ("not a claim", "the definition of the effective potential"),
    30: ("holds", "dL/dphidot of the Lagrangian (check 30)"),
    32: ("holds", "dL/dpsidot of the Lagrangian (check 32)"),
    36: ("holds", "p_phi - p_psi cos(theta) = I_1 phidot sin^2(theta) from the two momenta (check 36)"),
    40: ("not a claim", "Lagrange's equation for theta in its general form"),
    44: ("holds", "I_1 thetaddot = dL/dtheta = I_1 phidot^2 sin cos - I_3 omega_3 phidot sin + m g l sin with phidot and I_3 omega_3 = p_psi from the momenta (check 44)"),
    48: ("holds", "-dV_eff/dtheta with p_phi, p_psi held constant (constants of the motion) equals the right-hand side of the display before (check 48)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
