"""Independent SymPy truth table for continuum-lab-gyroscope-precession-nutation-es.md.

Model (the text's own set-up): a solid uniform disc (mass m, radius R) on a massless axle, its centre
of mass a distance r_cm from a fixed frictionless pivot; theta is the axle's tilt from the upward
vertical, phi its azimuth (precession angle), the spin about the axle is omega_s and L = I_z omega_s.
I_z = m R^2 / 2 is the polar moment, I_x = I_y the transverse moment about the pivot.
The nutation displays are checked against the heavy top's exact Lagrangian
L = I_x/2 (thd^2 + phd^2 sin^2 th) + I_z/2 (psd + phd cos th)^2 - m g r_cm cos th, linearised about the
horizontal axle theta_0 = 90 deg (the text's case) with theta'(0) = phi'(0) = 0.
Only SymPy and the standard library are used.
"""
import pathlib
import sys
import tomllib

import sympy as sp

m, R, r, g, t = sp.symbols('m R r_cm g t', positive=True)
Iz, Ix, ws, Lm = sp.symbols('I_z I_x omega_s L', positive=True)
CHECKS = {}


def check(line, ok):
    CHECKS[line] = bool(ok)


def close(a, b, rel):
    """|a - b| <= rel |b|: a number the text rounds, compared with the exact one."""
    return abs(sp.N(a - b, 30)) <= rel * abs(sp.N(b, 30))


# -- the disc's moments, from the integrals (not from a table) ---------------------------------
rho, s, phi_, z = sp.symbols('rho s varphi z', positive=True)
sigma = m / (sp.pi * R**2)                                   # areal density of the thin disc
Iz_int = sp.integrate(sp.integrate(sigma * s**2 * s, (s, 0, R)), (phi_, 0, 2 * sp.pi))
Idiam_int = sp.integrate(sp.integrate(sigma * (s * sp.sin(phi_))**2 * s, (s, 0, R)), (phi_, 0, 2 * sp.pi))
assert sp.simplify(Iz_int - m * R**2 / 2) == 0
assert sp.simplify(Idiam_int - m * R**2 / 4) == 0
Ix_pivot = Idiam_int + m * r**2                              # parallel-axis theorem about the pivot

num = {m: sp.Rational(250, 100), R: sp.Rational(18, 100), r: sp.Rational(25, 100), g: sp.Rational(981, 100)}

# line 29: I_z = 1/2 m R^2 = 1/2 (2.50)(0.18)^2 = 0.04050
check(29, sp.simplify(Iz_int - m * R**2 / 2) == 0 and Iz_int.subs(num) == sp.Rational(405, 10000))
# line 34: I_x = I_y = I_diam + m r^2 = 1/4 m R^2 + m r^2
check(34, sp.simplify(Ix_pivot - (m * R**2 / 4 + m * r**2)) == 0)
# line 36: 1/4 (2.50)(0.18)^2 + (2.50)(0.25)^2 = 0.02025 + 0.15625 = 0.17650
check(36, Idiam_int.subs(num) == sp.Rational(2025, 100000) and (m * r**2).subs(num) == sp.Rational(15625, 100000)
      and Ix_pivot.subs(num) == sp.Rational(17650, 100000))
# line 42: N = 10,000 RPM is the given spin rate: not a claim
# line 44: omega_s = 10000 * 2 pi / 60 ~ 1047.19755 rad/s (rounded to 5 decimals)
ws_num = sp.Rational(10000) * 2 * sp.pi / 60
check(44, abs(sp.N(ws_num, 20) - sp.Float('1047.19755', 20)) < 5e-6)
# line 48: L = I_z omega_s = 0.04050 * 1047.19755 ~ 42.4115 N m s (rounded to 4 decimals)
L_num = Iz_int.subs(num) * ws_num
check(48, abs(sp.N(L_num, 20) - sp.Float('42.4115', 20)) < 5e-5)
# line 54: the definition of the weight's torque about the pivot: not a claim
# line 58: tau_g = r m g sin(theta) = (0.25)(2.50)(9.81) sin 90deg = 6.13125 ~ 6.13 N m
th_ = sp.symbols('theta', positive=True)
rvec = r * sp.Matrix([sp.sin(th_), 0, sp.cos(th_)])          # axle at tilt theta from the vertical
tau_vec = rvec.cross(m * sp.Matrix([0, 0, -g]))
tau_sq = sp.simplify(tau_vec.dot(tau_vec))                   # |tau|^2, sin(theta) >= 0 on [0, pi]
tau90 = (r * m * g).subs(num)
check(58, sp.simplify(tau_sq - (r * m * g * sp.sin(th_))**2) == 0 and tau90 == sp.Rational(613125, 100000)
      and close(sp.Rational(613, 100), tau90, 1e-3))
# line 62: dL/dt = tau about the fixed pivot (Newton's second law summed over the particles, the
# internal forces central): a law of the text's model; checked for one particle r x (m rdd) = r x F
x = sp.Matrix([sp.Function(n)(t) for n in ('x', 'y', 'z')])
Lp = x.cross(m * x.diff(t))
check(62, sp.simplify(Lp.diff(t) - x.cross(m * x.diff(t, 2))) == sp.zeros(3, 1))
# line 68: dL/dt = Omega_p x L = tau for L = L u(t), u turning about k at Omega_p (steady precession)
Op = sp.symbols('Omega_p', positive=True)
u = sp.Matrix([sp.cos(Op * t), sp.sin(Op * t), 0])            # horizontal axle precessing about z
Lvec = Lm * u
Ovec = sp.Matrix([0, 0, Op])
tau_h = (r * u).cross(m * sp.Matrix([0, 0, -g]))             # gravity torque on the horizontal axle
steady = sp.solve(sp.Eq((Lvec.diff(t) - tau_h)[1].subs(t, 0), 0), Op)  # precession rate that balances
check(68, sp.simplify(Lvec.diff(t) - Ovec.cross(Lvec)) == sp.zeros(3, 1)
      and steady == [m * g * r / Lm]
      and sp.simplify((Ovec.cross(Lvec) - tau_h).subs(Op, m * g * r / Lm)) == sp.zeros(3, 1))
# line 72: Omega_p L sin 90 = tau_g => Omega_p = tau_g / L = r m g / (I_z omega_s)
check(72, steady == [m * g * r / Lm] and sp.simplify((m * g * r / Lm).subs(Lm, Iz * ws) - r * m * g / (Iz * ws)) == 0)
# line 88: d|L|^2/dt = 2 L . dL/dt = 2 L . tau = 0 when tau is perpendicular to L
Lf = sp.Matrix([sp.Function(n)(t) for n in ('L_x', 'L_y', 'L_z')])
ident = sp.simplify(Lf.dot(Lf).diff(t) - 2 * Lf.dot(Lf.diff(t))) == 0
check(88, ident and sp.simplify(Lvec.dot(tau_h)) == 0)

# -- nutation: the heavy top's Lagrangian about the pivot, linearised at theta_0 = 90 deg --------
th, ph, ps = [sp.Function(n)(t) for n in ('theta', 'phi', 'psi')]
Lag = (Ix / 2 * (th.diff(t)**2 + ph.diff(t)**2 * sp.sin(th)**2)
       + Iz / 2 * (ps.diff(t) + ph.diff(t) * sp.cos(th))**2 - m * g * r * sp.cos(th))
p_psi = sp.diff(Lag, ps.diff(t))                             # = I_z omega_3 = L (conserved)
p_phi = sp.diff(Lag, ph.diff(t))                             # conserved; 0 when phi'(0) = 0 at theta = 90 deg
d = sp.Function('delta')(t)                                  # theta = pi/2 + delta
PHD = sp.symbols('PHD')
phidot_exact = sp.solve(sp.Eq(p_phi.subs(ps.diff(t), Lm / Iz - ph.diff(t) * sp.cos(th)), 0).subs(ph.diff(t), PHD), PHD)[0]
eps = sp.symbols('epsilon')
phidot_lin = sp.series(phidot_exact.subs(th, sp.pi / 2 + eps * d), eps, 0, 2).removeO().subs(eps, 1)
EL_theta = sp.diff(sp.diff(Lag, th.diff(t)), t) - sp.diff(Lag, th)
EL = EL_theta.subs(ps.diff(t, 2), 0)                         # p_psi conserved
EL = EL.subs(ps.diff(t), Lm / Iz - ph.diff(t) * sp.cos(th))
EL = EL.subs(th, sp.pi / 2 + eps * d).doit()
PH = sp.symbols('PH')
EL = EL.subs(ph.diff(t), PH)
EL = EL.subs(PH, phidot_exact.subs(th, sp.pi / 2 + eps * d))
EL_lin = sp.series(EL, eps, 0, 2).removeO().subs(eps, 1)
wn = Lm / Ix
# line 99: omega_n = L / I_x: the linearised theta equation is delta'' + omega_n^2 delta = m g r / I_x
dsol = sp.dsolve(sp.Eq(EL_lin, 0), d, ics={d.subs(t, 0): 0, d.diff(t).subs(t, 0): 0})
OpL = m * g * r / Lm                                         # Omega_p of line 72
theta_claim = OpL / wn * (1 - sp.cos(wn * t))
check(99, sp.simplify(dsol.rhs - theta_claim) == 0
      and close(sp.Rational(101, 100) / sp.Rational(17650, 100000), sp.Float('5.72'), 1e-3))
# line 103: theta(t) = theta_0 + Omega_p/omega_n [1 - cos(omega_n t)]
check(103, sp.simplify(dsol.rhs - theta_claim) == 0)
# line 107: phi'(t) = Omega_p [1 - cos(omega_n t)]
phidot_t = sp.simplify(phidot_lin.subs(d, dsol.rhs))
check(107, sp.simplify(phidot_t - OpL * (1 - sp.cos(wn * t))) == 0)
# line 105: phi(t) = Omega_p t - Omega_p/omega_n sin(omega_n t), with phi(0) = 0
phi_t = sp.integrate(phidot_t.subs(t, sp.Symbol('s')), (sp.Symbol('s'), 0, t))
check(105, sp.simplify(phi_t - (OpL * t - OpL / wn * sp.sin(wn * t))) == 0)

# negative controls: the checks can fail
assert not sp.simplify(dsol.rhs - 2 * theta_claim) == 0
assert not close(sp.Rational(101, 100) / sp.Rational(17650, 100000), sp.Float('5.27'), 1e-3)

ORDER = [29, 34, 36, 42, 44, 48, 54, 58, 62, 68, 72, 88, 99, 103, 105, 107]
if __name__ == "__main__":
    table = tomllib.loads(pathlib.Path(__file__).with_name(
        'continuum-lab-gyroscope-precession-nutation-es.truth.toml').read_text())['display']
    assert [r['line'] for r in table] == ORDER, [r['line'] for r in table]
    bad = 0
    for row in table:
        comp = 'not a claim' if row['line'] not in CHECKS else ('holds' if CHECKS[row['line']] else 'slip')
        want = row['verdict']
        agree = comp == want or (comp == 'slip' and want in ('typo', 'fails'))
        print(f"line {row['line']:4d} computed={comp:11s} toml={want:11s} {'OK' if agree else 'MISMATCH'}")
        bad += not agree
    sys.exit(1 if bad else 0)
