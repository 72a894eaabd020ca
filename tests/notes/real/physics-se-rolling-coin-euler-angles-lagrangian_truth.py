"""Independent SymPy truth table for physics-se-rolling-coin-euler-angles-lagrangian.md.

The question's convention: a coin of mass m and radius R, its orientation
R_z(varphi) R_y(theta) R_z(psi) with psi about the normal to its face (the body z axis), its centre
of mass at R_0. The coin is a thin disc: moments I_1 = I_2 = I_d across the normal and I_3 about it.
Its height is the lowest rim point's depth below the centre; its kinetic energy is
(1/2) m |R_0-dot|^2 + (1/2) omega_b . diag(I_d, I_d, I_3) omega_b with omega_b the vector of
Q^T Q-dot for the orientation Q. The question's Lagrangian is compared with it for every choice of
constant moments I_psi, I_theta, I_varphi.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Ry, Rz
from truth_table import zero

t = sp.symbols('t', real=True)
m, g, R, Id, I3 = sp.symbols('m g R I_d I_3', positive=True)
x, y, ph, th, ps = [sp.Function(n)(t) for n in ('x', 'y', 'varphi', 'theta', 'psi')]


Q = Rz(ph) * Ry(th) * Rz(ps)
CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


# line 23: the centre's height is the depth of the lowest rim point: for a rim point at angle a in
# the face, R_0 + Q (R cos a, R sin a, 0) touches the floor (z = 0) at its lowest
a = sp.symbols('alpha', real=True)
rim_z = (Q * sp.Matrix([R * sp.cos(a), R * sp.sin(a), 0]))[2]
# the lowest point: rim_z = -R sqrt(Q20^2 + Q21^2) = -R sqrt(1 - Q22^2) = -R sin(theta), 0 < theta < pi
amp2 = sp.simplify(Q[2, 0]**2 + Q[2, 1]**2)
lowest = sp.atan2(Q[2, 1], Q[2, 0]) + sp.pi          # the minimum of R (Q20 cos a + Q21 sin a)
sample = {ph: sp.Rational(3, 10), th: sp.Rational(9, 10), ps: sp.Rational(-4, 5)}
check(23, zero(amp2 - sp.sin(th)**2)
      and zero(sp.simplify(sp.diff(rim_z, a).subs(a, lowest).subs(sample)))
      and zero(sp.simplify(rim_z.subs(a, lowest).subs(sample)) + R * sp.sin(sp.Rational(9, 10))))

# line 28: the Lagrangian
R0 = sp.Matrix([x, y, R * sp.sin(th)])
W = sp.simplify(Q.T * Q.diff(t))
wb = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])
T = sp.Rational(1, 2) * m * (R0.diff(t).T * R0.diff(t))[0] + sp.Rational(1, 2) * (wb.T * sp.diag(Id, Id, I3) * wb)[0]
L = sp.simplify(T - m * g * R * sp.sin(th))
Ips, Ith, Iph = sp.symbols('I_psi I_theta I_varphi', real=True)
printed = (sp.Rational(1, 2) * m * (x.diff(t)**2 + y.diff(t)**2 + R**2 * th.diff(t)**2 * sp.cos(th)**2)
           + sp.Rational(1, 2) * Ips * ps.diff(t)**2 + sp.Rational(1, 2) * Ith * th.diff(t)**2
           + sp.Rational(1, 2) * Iph * ph.diff(t)**2 - m * g * R * sp.sin(th))
P, Th, S = sp.symbols('P Th S', real=True)
diff = sp.expand(sp.simplify((L - printed).subs({ph.diff(t): P, th.diff(t): Th, ps.diff(t): S})))
# the translational part and the potential agree; the rotational part keeps a cross term
# I_3 cos(theta) varphi-dot psi-dot that no constant moments remove
cross = sp.simplify(diff.coeff(P, 1).coeff(S, 1))
assert zero(cross - I3 * sp.cos(th))
# constant moments that make the printed squares equal the energy: the cross term must vanish and
# the squares' coefficients must be free of theta
sols = sp.solve([diff.coeff(P, 2), diff.coeff(Th, 2), diff.coeff(S, 2)], [Ips, Ith, Iph], dict=True)
constant = [s for s in sols if not any(v.has(th) for v in s.values())]
check(28, zero(cross) and bool(constant))

LINES = [18, 23, 28]

H28_1 = ("The coin's body angular velocity in these angles is varphidot z + thetadot y' + psidot n, n the normal; "
         "with moments I_d across n and I_3 about it, the rotational energy is "
         "(1/2) I_d (thetadot^2 + varphidot^2 sin^2 theta) + (1/2) I_3 (psidot + varphidot cos theta)^2; "
         "its term I_3 cos theta varphidot psidot has no counterpart in a sum of the three squared rates.")
H28_2 = ("Take the coin spinning about its normal with the normal vertical (theta = 0, a coin lying flat) turning "
         "both varphi and psi: the angles then add, and its energy is (1/2) I_3 (varphidot + psidot)^2, not "
         "(1/2) I_psi psidot^2 + (1/2) I_varphi varphidot^2 for any constants; and the coefficient of varphidot^2 "
         "must change with theta (I_d sin^2 theta + I_3 cos^2 theta), not stay a constant I_varphi.")

ROWS = {
    18: ("not a claim", "the coin's points placed by its centre and its orientation, the question's definition of its coordinates"),
    23: ("holds", "with psi about the normal the face is tilted by theta from the floor, and the lowest rim point lies R sin theta below the centre, so the centre's height is R sin theta (check 23)"),
    28: ("fails", "the translational energy (1/2) m (xdot^2 + ydot^2 + R^2 thetadot^2 cos^2 theta) and the potential hold, but the rotational energy of a coin in these angles is (1/2) I_d (thetadot^2 + varphidot^2 sin^2 theta) + (1/2) I_3 (psidot + varphidot cos theta)^2, with a cross term I_3 cos theta varphidot psidot and a theta-dependent coefficient of varphidot^2; no constant moments I_psi, I_theta, I_varphi make the three squares equal it (check 28)",
         "", H28_1, H28_2),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
