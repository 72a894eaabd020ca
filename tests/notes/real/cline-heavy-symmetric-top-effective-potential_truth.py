"""Independent SymPy truth table for cline-heavy-symmetric-top-effective-potential.md.

The text's own setting: a symmetric top (I_1 = I_2 != I_3 about the fixed tip), z-x-z Euler angles
(phi, theta, psi) with the body rates omega_1 = phidot sin(theta) sin(psi) + thetadot cos(psi),
omega_2 = phidot sin(theta) cos(psi) - thetadot sin(psi), omega_3 = phidot cos(theta) + psidot (derived
here from the passive z-x-z matrix), potential U = M g h cos(theta). S_z and B_3 are the text's names
for p_phi and p_psi. Every check is built from the Lagrangian derived here, never from the text's
later displays.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero

t = sp.Symbol('t')
ph, th, ps = sp.symbols('phi theta psi', real=True)
phd, thd, psd, phdd, thdd = sp.symbols('phidot thetadot psidot phiddot thetaddot', real=True)
I1, I3, M, g, h = sp.symbols('I_1 I_3 M g h', positive=True)
Pf, Ps = sp.symbols('p_phi p_psi', real=True)
c, s = sp.cos, sp.sin


def Rz(a):
    return sp.Matrix([[c(a), s(a), 0], [-s(a), c(a), 0], [0, 0, 1]])


def Rx(a):
    return sp.Matrix([[1, 0, 0], [0, c(a), s(a)], [0, -s(a), c(a)]])


f = {q: sp.Function(q.name)(t) for q in (ph, th, ps)}
lam = Rz(f[ps]) * Rx(f[th]) * Rz(f[ph])
W = -sp.diff(lam, t) * lam.T
back = {sp.diff(f[ph], t): phd, sp.diff(f[th], t): thd, sp.diff(f[ps], t): psd}
back2 = {f[ph]: ph, f[th]: th, f[ps]: ps}
w1, w2, w3 = [sp.simplify(W[i, j].xreplace(back).xreplace(back2)) for i, j in ((2, 1), (0, 2), (1, 0))]

T = sp.Rational(1, 2) * (I1 * w1**2 + I1 * w2**2 + I3 * w3**2)
U = M * g * h * c(th)
Lag = T - U
pphi, ppsi = sp.diff(Lag, phd), sp.diff(Lag, psd)

Tc = sp.Rational(1, 2) * I1 * (phd**2 * s(th)**2 + thd**2) + sp.Rational(1, 2) * I3 * (phd * c(th) + psd)**2
check(17, zero(T - (sp.Rational(1, 2) * I1 * (w1**2 + w2**2) + sp.Rational(1, 2) * I3 * w3**2)) and zero(T - Tc))
check(23, zero(Lag - (Tc - M * g * h * c(th))))
check(29, zero(sp.diff(Lag, ph)))
check(35, zero(pphi - ((I1 * s(th)**2 + I3 * c(th)**2) * phd + I3 * psd * c(th))))
check(41, zero(sp.diff(Lag, ps)))
claim47 = I3 * (phdd * c(th) + psd)
check(47, zero(ppsi - claim47))
FIX_47 = zero(ppsi - I3 * (phd * c(th) + psd))
sol = sp.solve([sp.Eq(pphi, Pf), sp.Eq(ppsi, Ps)], [phd, psd], dict=True)[0]
check(53, zero(sol[phd] - (Pf - Ps * c(th)) / (I1 * s(th)**2)))
check(59, zero(sol[psd] - (Ps / I3 - (Pf - Ps * c(th)) * c(th) / (I1 * s(th)**2))))
Hen = sum(q * sp.diff(Lag, q) for q in (phd, thd, psd)) - Lag
check(67, zero(Hen - (Tc + M * g * h * c(th))))
half3 = sp.Rational(1, 2) * I3 * (phd * c(th) + psd)**2
check(73, zero(half3 - ppsi**2 / I3))
FIX_73 = zero(half3 - ppsi**2 / (2 * I3))
rest = sp.Rational(1, 2) * I1 * (phd**2 * s(th)**2 + thd**2) + M * g * h * c(th)
check(79, zero(Hen - ppsi**2 / I3 - rest))
FIX_79 = zero(Hen - ppsi**2 / (2 * I3) - rest)
# reduced energy in theta alone: E' (the right side of line 80) with phidot from the momenta
V = (Pf - Ps * c(th))**2 / (2 * I1 * s(th)**2) + M * g * h * c(th)
Ered = rest.subs(phd, sol[phd])
check(85, zero(Ered - (sp.Rational(1, 2) * I1 * thd**2 + V)))
check(97, zero(V - ((Pf - Ps * c(th))**2 / (2 * I1 * s(th)**2) + M * g * h * c(th))))
# Routhian: phidot p_phi + psidot p_psi - L with the rates eliminated in favour of the momenta
Rou = (phd * pphi + psd * ppsi - Lag).subs({phd: sol[phd], psd: sol[psd]})
Rtext = -sp.Rational(1, 2) * I1 * thd**2 + V + Ps**2 / (2 * I3)
check(103, zero(Rou - Rtext))
Veff_R = Rou + sp.Rational(1, 2) * I1 * thd**2          # the Routhian's non-kinetic part
check(109, zero(Veff_R - (V + Ps**2 / I3)))
FIX_109 = zero(Veff_R - (V + Ps**2 / (2 * I3)))
# Routh's equation for theta is Lagrange's theta equation with the cyclic rates eliminated
dLdth = sp.diff(Lag, th).subs({phd: sol[phd], psd: sol[psd]})
routh = -I1 * thdd - sp.diff(Rou, th)                    # d/dt(dR/dthetadot) - dR/dtheta
lagr = I1 * thdd - dLdth                                 # d/dt(dL/dthetadot) - dL/dtheta
check(115, zero(routh + lagr))
# steady precession: the roots for p_phi - p_psi cos(theta_0) make dV/dtheta vanish at theta_0
th0 = sp.Symbol('theta_0', real=True)
root = lambda sg: Ps * s(th0)**2 / (2 * c(th0)) * (1 + sg * sp.sqrt(1 - 4 * M * g * h * I1 * c(th0) / Ps**2))
dV = sp.diff(V, th).subs(th, th0)
check(123, all(zero(sp.expand(dV.subs(Pf, root(sg) + Ps * c(th0)) * I1 * s(th0)**3)) for sg in (1, -1)))

# negative controls: the corrected forms hold, and a wrong root is caught
assert FIX_47 and FIX_73 and FIX_79 and FIX_109
assert not zero(sp.expand(dV.subs(Pf, 2 * root(1) + Ps * c(th0)) * I1 * s(th0)**3))

LINES = [17, 23, 29, 35, 41, 47, 53, 59, 67, 73, 79, 85, 91, 97, 103, 109, 115, 123]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
