"""Independent SymPy truth table for white-phy105-heavy-symmetric-top-effective-potential-zxz.ipynb.

The notebook's own setting (Goldstein's): a symmetric top, I_1 = I_2 != I_3 about the fixed point
on its axis, Euler angles phi (azimuth about the vertical Z), theta (tilt from Z), psi (turn about
the body 3-axis), the z-x-z sequence R = R_z(phi) R_x(theta) R_z(psi); the body components of the
angular velocity come from R^T Rdot, the kinetic energy is (I_1 (w_1^2 + w_2^2) + I_3 w_3^2)/2
and the centre of mass sits at l along the body 3-axis. L = T - V; p_q = dL/dqdot. Every check
is built here from these definitions; a display's line is the notebook file's line of its first
row.
"""
import pathlib
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


c, s = sp.cos, sp.sin
t = sp.symbols('t', real=True)
I1, I3, Mm, g, l, a, b = sp.symbols('I_1 I_3 M g ell a b', positive=True)
phi, th, psi = (sp.Function(n)(t) for n in ('phi', 'theta', 'psi'))
phd, thd, psd = phi.diff(t), th.diff(t), psi.diff(t)


def RX(u):
    return sp.Matrix([[1, 0, 0], [0, c(u), -s(u)], [0, s(u), c(u)]])


def RZ(u):
    return sp.Matrix([[c(u), -s(u), 0], [s(u), c(u), 0], [0, 0, 1]])


R = RZ(phi) * RX(th) * RZ(psi)
W = R.T * R.diff(t)
w = [W[2, 1], W[0, 2], W[1, 0]]
T = (I1 * (w[0] ** 2 + w[1] ** 2) + I3 * w[2] ** 2) / 2
cm_height = (R * sp.Matrix([0, 0, l]))[2]
V = Mm * g * cm_height
L = T - V
p_phi = sp.diff(L, phd)
p_psi = sp.diff(L, psd)
p_theta = sp.diff(L, thd)

# 25: T = I_1 (thetadot^2 + sin^2 theta phidot^2)/2 + I_3 (psidot + cos theta phidot)^2/2
text25 = I1 * (thd ** 2 + s(th) ** 2 * phd ** 2) / 2 + I3 * (psd + c(th) * phd) ** 2 / 2
check(25, truth_table.zero(T - text25))
# 30: V = M g l cos theta: the potential of the centre of mass, set out (not a claim)
assert truth_table.zero(V - Mm * g * l * c(th))
# 36: p_theta = (I_1 sin^2 + I_3 cos^2) phidot + I_3 cos psidot and p_psi = I_3 (psidot + phidot cos)
text36_first = (I1 * s(th) ** 2 + I3 * c(th) ** 2) * phd + I3 * c(th) * psd
text36_second = I3 * (psd + phd * c(th))
check(36, truth_table.zero(p_theta - text36_first) and truth_table.zero(p_psi - text36_second))
assert truth_table.zero(p_phi - text36_first) and truth_table.zero(p_theta - I1 * thd)   # the first is p_phi
# 44: p_phi - p_psi cos theta = ... = I_1 sin^2 theta phidot (each step)
step1 = I1 * s(th) ** 2 * phd + I3 * c(th) ** 2 * phd + I3 * c(th) * psd - I3 * c(th) * psd - I3 * c(th) ** 2 * phd
check(44, truth_table.zero(p_phi - p_psi * c(th) - step1) and truth_table.zero(step1 - I1 * s(th) ** 2 * phd))
# 50: phidot = (p_phi - p_psi cos)/(I_1 sin^2) = (b - a cos)/sin^2 with p_psi = I_1 a, p_phi = I_1 b
check(50, truth_table.zero(phd - (p_phi - p_psi * c(th)) / (I1 * s(th) ** 2))
      and truth_table.zero((I1 * b - I1 * a * c(th)) / (I1 * s(th) ** 2) - (b - a * c(th)) / s(th) ** 2))
# 57: V_eff = M g l cos + (I_1/2) ((b - a cos)/sin)^2: the energy with phidot from 50 and
# psidot + phidot cos = p_psi/I_3 is I_1 thetadot^2/2 + V_eff + p_psi^2/(2 I_3), a constant
x = sp.symbols('x', real=True)               # theta
thdot = sp.symbols('thetadot', real=True)
phdot = (b - a * c(x)) / s(x) ** 2
w3 = I1 * a / I3                             # psidot + phidot cos theta = p_psi / I_3
E = I1 * (thdot ** 2 + s(x) ** 2 * phdot ** 2) / 2 + I3 * w3 ** 2 / 2 + Mm * g * l * c(x)
text57 = Mm * g * l * c(x) + I1 / 2 * ((b - a * c(x)) / s(x)) ** 2
check(57, truth_table.zero(E - (I1 * thdot ** 2 / 2 + text57 + (I1 * a) ** 2 / (2 * I3))))

LINES = [25, 30, 36, 44, 50, 57]

ROWS = {
    25: ("holds", "the body components of the angular velocity of the z-x-z angles give (I_1 (w_1^2 + w_2^2) + I_3 w_3^2)/2 = I_1 (thetadot^2 + sin^2 phidot^2)/2 + I_3 (psidot + cos phidot)^2/2 (check 25)"),
    30: ("not a claim", "the potential energy of the centre of mass at height l cos theta, set out"),
    36: ("typo", "the momentum conjugate to phi is dL/dphidot = (I_1 sin^2 + I_3 cos^2) phidot + I_3 cos psidot; the display names it p_theta, which is I_1 thetadot (check 36)",
         "p_\\phi = \\left( I_1\\sin^2\\theta + I_3\\cos^2\\theta\\right)\\,\\dot{\\phi} + I_3\\cos\\theta\\ \\dot{\\psi}\n  \\quad\\mathrm{and}\\quad\n  p_\\psi = I_3\\left( \\dot{\\psi} + \\dot{\\phi}\\cos\\theta \\right)",
         "By algebra: the Lagrangian T - V depends on phidot through I_1 sin^2 phidot^2/2 + I_3 (psidot + cos phidot)^2/2, whose derivative is I_1 sin^2 phidot + I_3 cos (psidot + cos phidot) = (I_1 sin^2 + I_3 cos^2) phidot + I_3 cos psidot; its derivative by thetadot is I_1 thetadot. The sentence before says the two conserved momenta are those of phi and psi, and the next display starts from p_phi.",
         "By numbers: thetadot = 1, phidot = 0, psidot = 0 at theta = pi/3 with I_1 = I_3 = 1: the true p_theta = I_1 thetadot = 1, while the display's expression gives 0; the expression is the phi momentum, 0 here as phidot = psidot = 0."),
    44: ("holds", "p_phi - p_psi cos = (I_1 sin^2 + I_3 cos^2) phidot + I_3 cos psidot - I_3 cos (psidot + cos phidot) = I_1 sin^2 phidot, each step (check 44)"),
    50: ("holds", "the line before solved for phidot, then p_psi = I_1 a, p_phi = I_1 b (check 50)"),
    57: ("holds", "the energy with phidot = (b - a cos)/sin^2 and the constant spin p_psi/I_3 is I_1 thetadot^2/2 + M g l cos + (I_1/2)((b - a cos)/sin)^2 plus the constant p_psi^2/(2 I_3) (check 57)"),
}


if __name__ == "__main__":
    here = pathlib.Path(__file__)
    assert truth_table.notebook_display_lines(here.with_name('white-phy105-heavy-symmetric-top-effective-potential-zxz.ipynb')) == LINES
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
