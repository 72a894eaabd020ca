"""Independent SymPy truth table for pycav-gyroscope-heavy-top-zxz.md.
Heavy symmetric top, z-x-z Euler angles (phi precession, theta tilt from vertical, chi spin),
support fixed, I_1 transverse moment about the support, I_3 axial, centre of mass at height h cos(theta).
Body angular velocity (1-axis along the line of nodes): (thetadot, phidot sin th, chidot + phidot cos th).
"""
import sys, pathlib
import sympy as sp

t = sp.symbols('t')
I1, I3, m, g, h, E, Jz, J3 = sp.symbols('I_1 I_3 m g h E J_z J_3', positive=True)
th, ph, ch = [sp.Function(n)(t) for n in ('theta', 'phi', 'chi')]
thd, phd, chd = th.diff(t), ph.diff(t), ch.diff(t)

# kinetic energy from the body angular velocity
w = sp.Matrix([thd, phd * sp.sin(th), chd + phd * sp.cos(th)])
T = sp.Rational(1, 2) * (I1 * w[0]**2 + I1 * w[1]**2 + I3 * w[2]**2)
V = m * g * h * sp.cos(th)
L = T - V
p_phi = sp.diff(L, phd)            # = J_z
p_chi = sp.diff(L, chd)            # = J_3
Energy = T + V
EL_theta = sp.diff(sp.diff(L, thd), t) - sp.diff(L, th)

# solve the momenta for phidot, chidot in terms of J_z, J_3
Phd, Chd, Thd = sp.symbols('Phd Chd Thd')
rep = {phd: Phd, chd: Chd, thd: Thd}
sol = sp.solve([sp.Eq(p_phi.subs(rep), Jz), sp.Eq(p_chi.subs(rep), J3)], [Phd, Chd], dict=True)[0]
Th = sp.symbols('Th')
phidot_d = sol[Phd].subs(th, Th)
chidot_d = sol[Chd].subs(th, Th)

CHECKS = {}
def check(key, ok):
    CHECKS[key] = bool(ok)
def z(expr):
    return sp.simplify(sp.trigsimp(sp.together(expr))) == 0

s, c = sp.sin(Th), sp.cos(Th)
def to_sym(e):
    return e.subs({thd: Thd}).subs({th: Th})

# energy reduced to theta: E = 1/2 I1 thetadot^2 + U_eff
E_red = to_sym(Energy.subs(rep)).subs({Phd: phidot_d, Chd: chidot_d})
# d1 energy equation as written: 1/2 I1 thd^2 = E - (Jz - J3 c)^2/(2 I1 s^2) - mgh c - J3^2/(2 I3)
claim1 = sp.Rational(1, 2) * I1 * Thd**2 - (E - (Jz - J3 * c)**2 / (2 * I1 * s**2) - m * g * h * c - J3**2 / (2 * I3))
check('d1', z(claim1.subs(E, E_red)))
# d2 theta equation as written; compare with Euler-Lagrange for theta after eliminating phidot, chidot
Thdd = sp.symbols('Thdd')
EL = EL_theta.subs(th.diff(t, 2), Thdd).subs(rep).subs(th, Th)
EL = EL.subs({Phd: phidot_d, Chd: chidot_d})
thdd_true = sp.solve(sp.Eq(EL, 0), Thdd)[0]
rhs2 = m * g * h * s - J3 * (Jz - J3 * c) / (I1 * s) + (Jz - J3 * c)**2 * c / (I1 * s**3)
check('d2', z(I1 * thdd_true - rhs2))
# also: d2 is the time derivative of d1 (dU/dtheta)
Ueff = (Jz - J3 * c)**2 / (2 * I1 * s**2) + m * g * h * c + J3**2 / (2 * I3)
assert z(-sp.diff(Ueff, Th) - rhs2)
# d3 phidot
check('d3', z(phidot_d - (Jz - J3 * c) / (I1 * s**2)))
# d4 chidot
check('d4', z(chidot_d - (J3 / I3 + (J3 * c**2 - Jz * c) / (I1 * s**2))))
# d5 energy with U_eff (first equality as d1; U_eff defined by the second)
check('d5', CHECKS['d1'])
# d6 omegadot = (1/I1)(...)
check('d6', z(thdd_true - rhs2 / I1))
# d7 thetadot = omega: definition of omega -> not a claim
# d8, d9 repeat d3, d4
check('d8', CHECKS['d3'])
check('d9', CHECKS['d4'])
# negative control
assert not z(I1 * thdd_true - (rhs2 - 2 * m * g * h * s))

ORDER = ['d1', 'd2', 'd3', 'd4', 'd5', 'd6', 'd7', 'd8', 'd9']
if __name__ == "__main__":
    import tomllib
    table = tomllib.loads(pathlib.Path(__file__).with_name('pycav-gyroscope-heavy-top-zxz.truth.toml').read_text())['display']
    assert len(table) == len(ORDER)
    bad = 0
    for key, row in zip(ORDER, table):
        comp = 'not a claim' if key not in CHECKS else ('holds' if CHECKS[key] else 'slip')
        want = row['verdict']
        agree = comp == want or (comp == 'slip' and want in ('typo', 'fails'))
        print(f"line {row['line']:4d} {key:3s} computed={comp:11s} toml={want:11s} {'OK' if agree else 'MISMATCH'}")
        bad += not agree
    sys.exit(1 if bad else 0)
