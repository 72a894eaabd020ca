"""Independent SymPy truth table for cline-torque-free-symmetric-rotor-lagrange.md
(Cline, ch. 13, section 13.20, Lagrange subsection; MyST edition).
Text's convention: z-x-z Euler angles (phi, theta, psi), passive matrix lambda = Rz(psi) Rx(theta) Rz(phi);
symmetric rotor I_1 = I_2, no torque, U = 0."""
import sys, tomllib, pathlib, random
import sympy as sp

ph, th, ps = sp.symbols('phi theta psi', real=True)
phd, thd, psd, phdd = sp.symbols('phidot thetadot psidot phiddot', real=True)
I1, I3, E = sp.symbols('I_1 I_3 E', positive=True)
c, s = sp.cos, sp.sin

# body angular velocity from the passive z-x-z matrix, derived (not typed):
t = sp.Symbol('t')
def Rz(a): return sp.Matrix([[c(a), s(a), 0], [-s(a), c(a), 0], [0, 0, 1]])
def Rx(a): return sp.Matrix([[1, 0, 0], [0, c(a), s(a)], [0, -s(a), c(a)]])
f = {q: sp.Function(q.name)(t) for q in (ph, th, ps)}
lam = Rz(f[ps]) * Rx(f[th]) * Rz(f[ph])
W = -sp.diff(lam, t) * lam.T
back = {sp.diff(f[ph], t): phd, sp.diff(f[th], t): thd, sp.diff(f[ps], t): psd}
back2 = {f[ph]: ph, f[th]: th, f[ps]: ps}
wb = [sp.simplify(W[i, j].xreplace(back).xreplace(back2)) for i, j in ((2, 1), (0, 2), (1, 0))]
w1, w2, w3 = wb

def zero(e, nsamp=5):
    e = sp.sympify(e)
    if e == 0 or sp.simplify(e) == 0:
        return True
    rnd = random.Random(7)
    for _ in range(nsamp):
        sub = {q: sp.Float(rnd.uniform(0.2, 2.5), 30) for q in e.free_symbols}
        if abs(sp.N(e.xreplace(sub), 30)) > 1e-20:
            return False
    return True

COMPUTED = {}
def check(line, ok, fix_ok=None, note=''):
    v = 'holds' if ok else ('typo' if fix_ok else 'fails')
    COMPUTED[line] = (v, note)

# Lagrangian derived from first principles (I_2 = I_1, U = 0)
Tgen = sp.Rational(1, 2) * (I1*w1**2 + I1*w2**2 + I3*w3**2)
Lag = Tgen
pphi = sp.diff(Lag, phd); ppsi = sp.diff(Lag, psd)

check(17, zero(sp.Rational(1, 2)*I1*(w1**2 + w2**2) + sp.Rational(1, 2)*I3*w3**2 - Tgen), note='I_2 = I_1')
claim = phd**2*s(th)**2*s(ps)**2 + 2*ph*thd*s(th)*s(ps)*c(ps) + thd**2*c(ps)**2
fix = phd**2*s(th)**2*s(ps)**2 + 2*phd*thd*s(th)*s(ps)*c(ps) + thd**2*c(ps)**2
check(23, zero((phd*s(th)*s(ps) + thd*c(ps))**2 - w1**2) and zero(claim - w1**2), zero(fix - w1**2), 'cross term needs phidot, not phi')
claim = phd**2*s(th)**2*c(ps)**2 - 2*ph*thd*s(th)*s(ps)*c(ps) + thd**2*s(ps)**2
fix = phd**2*s(th)**2*c(ps)**2 - 2*phd*thd*s(th)*s(ps)*c(ps) + thd**2*s(ps)**2
check(27, zero((phd*s(th)*c(ps) - thd*s(ps))**2 - w2**2) and zero(claim - w2**2), zero(fix - w2**2), 'cross term needs phidot, not phi')
check(33, zero(w1**2 + w2**2 - (phd**2*s(th)**2 + thd**2)))
check(39, zero(w3**2 - (phd*c(th) + psd)**2))
Tc = sp.Rational(1, 2)*I1*(phd**2*s(th)**2 + thd**2) + sp.Rational(1, 2)*I3*(phd*c(th) + psd)**2
check(45, zero(Tc - Tgen))
check(51, zero(Tc - Lag), note='U = 0')
check(57, zero(sp.diff(Lag, ph)), note='phi cyclic')
check(63, zero(pphi - ((I1*s(th)**2 + I3*c(th)**2)*phd + I3*psd*c(th))))
check(69, zero(sp.diff(Lag, ps)), note='psi cyclic')
claim = I3*(phdd*c(th) + psd); fix = I3*(phd*c(th) + psd)
check(75, zero(claim - ppsi) and zero(fix - I3*w3), zero(fix - ppsi) and zero(fix - I3*w3), 'double dot on phi')
Pf, Ps = sp.symbols('p_phi p_psi')
sol = sp.solve([sp.Eq(pphi, Pf), sp.Eq(ppsi, Ps)], [phd, psd], dict=True)[0]
check(81, zero(sol[phd] - (Pf - Ps*c(th))/(I1*s(th)**2)))
check(87, zero(sol[psd] - (Ps/I3 - (Pf - Ps*c(th))*c(th)/(I1*s(th)**2))))
H = sum(q*sp.diff(Lag, q) for q in (phd, thd, psd)) - Lag
check(93, zero(H - Tc), note='energy function = T for U = 0')
half3 = sp.Rational(1, 2)*I3*(phd*c(th) + psd)**2
ppsi_val = I3*(phd*c(th) + psd)
check(99, zero(half3 - ppsi_val**2/I3), zero(half3 - ppsi_val**2/(2*I3)), 'p_psi^2/(2 I_3)')
Eval = Tc
lhs = sp.Rational(1, 2)*I1*(phd**2*s(th)**2 + thd**2)
check(105, zero(lhs - (Eval - ppsi_val**2/I3)), zero(lhs - (Eval - ppsi_val**2/(2*I3))), 'E - p_psi^2/(2 I_3)')

if __name__ == '__main__':
    here = pathlib.Path(__file__).resolve().parent
    slug = pathlib.Path(__file__).name[:-len('_truth.py')]
    table = tomllib.load(open(here / (slug + '.truth.toml'), 'rb'))['display']
    bad = 0; seen = set()
    for e in table:
        ln = e['line']; seen.add(ln)
        exp = e['verdict']
        got = COMPUTED.get(ln, ('not a claim' if exp == 'not a claim' else 'MISSING', ''))[0]
        flag = 'ok' if got == exp else 'DISAGREE'
        bad += flag != 'ok'
        print(f"{ln:5d}  {got:12s} toml={exp:12s} {flag}")
    for ln in sorted(set(COMPUTED) - seen):
        print(f"{ln:5d}  computed but not in toml"); bad += 1
    print('ALL AGREE' if not bad else f'{bad} disagreements')
    sys.exit(1 if bad else 0)
