"""Independent SymPy truth table for sicm-workbook-euler-equations-forced.md
(T. Antony's study notes on SICM section 2.9, Euler's equations, free and forced).
Text's conventions (Sussman & Wisdom): D = d/dt; A, B, C principal moments; omega' = (w^a, w^b, w^c)
principal-axis angular velocity; M = Rz(phi) Rx(theta) Rz(psi), ACTIVE right-handed rotations
(carries the body from the reference orientation to the actual one); primes = principal-axis
components; script-A(u) v = u x v; L (space) = M Lbar'.  Derived here from first principles:
body angular velocity as vee(M^T DM), conservation / torque law D(M I' w') = Tbar."""
import sys, tomllib, pathlib, random
import sympy as sp

t = sp.Symbol('t', real=True)
A, B, C = sp.symbols('A B C', positive=True)
c, s = sp.cos, sp.sin

def Rz(a): return sp.Matrix([[c(a), -s(a), 0], [s(a), c(a), 0], [0, 0, 1]])
def Rx(a): return sp.Matrix([[1, 0, 0], [0, c(a), -s(a)], [0, s(a), c(a)]])
def Ry(a): return sp.Matrix([[c(a), 0, s(a)], [0, 1, 0], [-s(a), 0, c(a)]])
def hat(u):  # script-A: hat(u) v = u x v
    return sp.Matrix([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])
def vee(W): return sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])

th, ph, ps = [sp.Function(n)(t) for n in ('theta', 'phi', 'psi')]
M = Rz(ph) * Rx(th) * Rz(ps)
DM = M.diff(t)
# body angular velocity, derived: M^T DM is antisymmetric = hat(omega')
wb = vee(M.T * DM).applyfunc(sp.trigsimp)
Ip = sp.diag(A, B, C)

rnd = random.Random(11)
def subs_point():
    d = {}
    for f in (th, ph, ps):
        d[f.diff(t, 2)] = sp.Float(rnd.uniform(-2, 2), 30)
        d[f.diff(t)] = sp.Float(rnd.uniform(-2, 2), 30)
    for f in (th, ph, ps):
        d[f] = sp.Float(rnd.uniform(0.2, 2.8), 30)
    d[A] = sp.Float(rnd.uniform(0.5, 3), 30); d[B] = sp.Float(rnd.uniform(0.5, 3), 30); d[C] = sp.Float(rnd.uniform(0.5, 3), 30)
    return d

def zero(e, n=6):
    """e: scalar or Matrix; True if it vanishes (symbolically or at n random points)."""
    e = sp.Matrix(e) if isinstance(e, (sp.MatrixBase, list)) else sp.Matrix([e])
    e = e.applyfunc(lambda x: x.doit())
    if all(x == 0 for x in e):
        return True
    for _ in range(n):
        d = subs_point()
        extra = {q: sp.Float(rnd.uniform(-2, 2), 30) for q in e.free_symbols if q not in d}
        v = e.xreplace(d).xreplace(extra).evalf(30)
        # remaining undefined functions of t evaluated at t: replace by random values
        v = v.applyfunc(lambda x: x.xreplace({a: sp.Float(rnd.uniform(-2, 2), 30) for a in x.atoms(sp.Function) if not a.is_number}))
        if any(abs(sp.N(x, 30)) > 1e-18 for x in v):
            return False
    return True

COMPUTED = {}
def check(line, verdict, note=''):
    COMPUTED[line] = (verdict, note)
def hv(ok, slip='fails'):
    return 'holds' if ok else slip

# generic principal-axis vector functions of time
Lp = sp.Matrix([sp.Function(n)(t) for n in ('La', 'Lb', 'Lc')])
L0 = sp.Matrix(sp.symbols('L0x L0y L0z', real=True))

# d15, d21, d27: definitions (Lbar' = I' w', I' diagonal, space components by rotation)
for ln in (15, 21, 27):
    check(ln, 'not a claim')

# d33 (2.65): product rule, then with DL = 0 (free body: Lbar' = M^T L0)
r1 = (M * Lp).diff(t) - (DM * Lp + M * Lp.diff(t))
Lfree = M.T * L0
r2 = M * Lfree.diff(t) + DM * Lfree
r3 = Lfree.diff(t) + M.T * DM * Lfree
check(33, hv(zero(r1) and zero(r2) and zero(r3)), 'product rule; with L = M Lbar\' constant')

# d43 (2.21..2.21c): omega' = M^T vee(DM M^T) etc., against derived wb = vee(M^T DM)
Wsp = DM * M.T
ok = zero(wb - M.T * vee(Wsp)) and zero(M * wb - vee(Wsp)) and zero(hat(M * wb) - Wsp) and zero(hat(M * wb) * M - DM)
check(43, hv(ok), 'all four rows vs derived body angular velocity')

# d54 (2.66): I'Dw' = -M^T DM I'w' = -M^T A(Mw') M I'w'; first '=' is 2.65 with Lbar' = I'w' (checked in d33),
# here: both right-hand sides agree, and on a free motion (w' = I'^-1 M^T L0) the first equality holds
wfree = Ip.inv() * M.T * L0
ok = zero(M.T * DM * Ip * wb - M.T * hat(M * wb) * M * Ip * wb) and zero(Ip * wfree.diff(t) + M.T * DM * Ip * wfree)
check(54, hv(ok))

# d63, d67, d73 (2.67): rotation-covariance of the cross product, R a proper rotation
u = sp.Matrix(sp.symbols('u1:4', real=True)); v = sp.Matrix(sp.symbols('v1:4', real=True))
a1, a2, a3 = sp.symbols('a1:4', real=True)
R = Rz(a1) * Rx(a2) * Rz(a3)
check(63, hv(zero(R * u.cross(v) - R * hat(u) * v)))
check(67, hv(zero((R * u).cross(R * v) - hat(R * u) * R * v)))
ok = zero(R * hat(u) * v - hat(R * u) * R * v) and zero(R * hat(u) - hat(R * u) * R) and zero(hat(u) - R.T * hat(R * u) * R)
check(73, hv(ok))

# d83 (2.68): Euler's equations from conservation of L: D(M I' w') = 0 with DM = M hat(w')
w = sp.Matrix([sp.Function(n)(t) for n in ('wa', 'wb', 'wc')])
Dw_claim = -Ip.inv() * hat(w) * Ip * w
Msym = sp.Matrix(3, 3, lambda i, j: sp.Symbol(f'm{i}{j}'))
# D(M I' w) = DM I' w + M I' Dw, with DM = M hat(w)  ->  M (hat(w) I' w + I' Dw)
resid = hat(w) * Ip * w + Ip * Dw_claim
check(83, hv(zero(resid)))
# component forms
wa, wb_, wc = sp.symbols('w_a w_b w_c', real=True)
wv = sp.Matrix([wa, wb_, wc])
EulerRHS = -(wv.cross(Ip * wv))  # I' Dw
claim91 = sp.Matrix([(B - C) * wb_ * wc, (C - A) * wc * wa, (A - B) * wa * wb_])
check(91, hv(zero(EulerRHS - claim91)))
La_, Lb_, Lc_ = sp.symbols('L_a L_b L_c', real=True)
subsL = {wa: La_ / A, wb_: Lb_ / B, wc: Lc_ / C}
claim101 = sp.Matrix([(1 / C - 1 / B) * Lb_ * Lc_, (1 / A - 1 / C) * Lc_ * La_, (1 / B - 1 / A) * La_ * Lb_])
check(101, hv(zero(EulerRHS.xreplace(subsL) - claim101)), 'DL_a = A Dw^a')

# d111, d119 (2.21c, 2.71): DM = A(Mw')M = M M^T A(Mw') M = M A(w')
ok = zero(DM - hat(M * wb) * M) and zero(hat(M * wb) * M - M * (M.T * hat(M * wb) * M)) and zero(M * (M.T * hat(M * wb) * M) - M * hat(wb))
check(111, hv(ok))
check(119, hv(zero(DM - M * hat(wb))))

# d125: Euler-angle rates from body angular velocity (M = Rz(phi) Rx(theta) Rz(psi))
rates = sp.Matrix([th.diff(t), ph.diff(t), ps.diff(t)])
Mat = sp.Matrix([[c(ps) * s(th), -s(ps) * s(th), 0], [s(ps), c(ps), 0], [-s(ps) * c(th), -c(ps) * c(th), s(th)]]) / s(th)
check(125, hv(zero(rates - Mat * wb)), 'z-x-z, active')

check(139, 'not a claim', 'MathJax \\require{cancel}')

# d143 / d149: Lagrange equation for phi with a potential V(theta, phi, psi)
thd, phd, psd = sp.symbols('thetadot phidot psidot', real=True)
q_th, q_ph, q_ps = sp.symbols('theta_q phi_q psi_q', real=True)
Vf = sp.Function('V')(q_th, q_ph, q_ps)
back = {th.diff(t): thd, ph.diff(t): phd, ps.diff(t): psd}
back2 = {th: q_th, ph: q_ph, ps: q_ps}
wq = wb.xreplace(back).xreplace(back2)
T = sp.Rational(1, 2) * (A * wq[0] ** 2 + B * wq[1] ** 2 + C * wq[2] ** 2)
Lag = T - Vf
pphi = sp.diff(Lag, phd)
# phi is cyclic in T:
assert sp.simplify(sp.diff(T, q_ph)) == 0
# on-shell: D p_phi = dLag/dphi = -dV/dphi ; let X = D p_phi (a number on-shell), dV = dV/dphi = -X
X = sp.Symbol('X', nonzero=True)   # value of D p_phi on a trajectory with nonzero torque
dV = -X
Dd_L = X                           # D (dL/dphidot) = D p_phi identically (p_phi := dL/dphidot)
row1 = Dd_L - (-X)                 # "D d_phidot L = -D p_phi"
row2 = -X - dV                     # "-D p_phi = d_{1,1} V"
fix1 = -Dd_L - (-X)                # correction: "-D d_phidot L = -D p_phi = d_{1,1} V"
check(143, 'holds' if (zero(row1) and zero(row2)) else ('typo' if (zero(fix1) and zero(row2)) else 'fails'),
      'row 1 sign: D p_phi set equal to -D p_phi')
Tz = -dV                            # text's definition: T_z = minus dV/d(angle about z)
r1 = Tz - (-X)                      # "T_z = -D p_phi"
r2 = -X - dV                        # "-D p_phi = d_{1,1} V"
f1 = -Tz - (-X)                     # correction "-T_z = -D p_phi = d_{1,1} V"
check(149, 'holds' if (zero(r1) and zero(r2)) else ('typo' if (zero(f1) and zero(r2)) else 'fails'),
      'T_z = -dV/dphi = D p_phi, not -D p_phi')

check(155, 'not a claim', 'torque law DL = T')

# d161: Tbar = D(M Lbar') = DM Lbar' + M DLbar'
check(161, hv(zero((M * Lp).diff(t) - (DM * Lp + M * Lp.diff(t)))))

# d167 (2.82): with Tbar := D(M I' w), DM = A(Mw')M ; w' here = wb (derived), Dw' generic
Dwp = sp.Matrix([sp.Function(n)(t) for n in ('Dwa', 'Dwb', 'Dwc')])
Tbar = DM * Ip * wb + M * Ip * Dwp
rows = [Tbar - (hat(M * wb) * M * Ip * wb + M * Ip * Dwp),
        M.T * Tbar - ((M.T * hat(M * wb) * M) * Ip * wb + Ip * Dwp),
        M.T * Tbar - (hat(wb) * Ip * wb + Ip * Dwp)]
check(167, hv(all(zero(r) for r in rows)))

# d178 (2.83), d188, d198 (2.80): components of T' = A(w')I'w' + I'Dw'
Da, Db, Dc = sp.symbols('Dw_a Dw_b Dw_c', real=True)
Tp = wv.cross(Ip * wv) + Ip * sp.Matrix([Da, Db, Dc])
claim178 = sp.Matrix([A * Da - (B - C) * wb_ * wc, B * Db - (C - A) * wc * wa, C * Dc - (A - B) * wa * wb_])
check(178, hv(zero(Tp - claim178)))
DLa, DLb, DLc = sp.symbols('DL_a DL_b DL_c', real=True)
subsD = {Da: DLa / A, Db: DLb / B, Dc: DLc / C, **subsL}
Tp_L = Tp.xreplace(subsD)
claim188 = sp.Matrix([A * (DLa / A) - (B - C) * Lb_ * Lc_ / (B * C), B * (DLb / B) - (C - A) * Lc_ * La_ / (C * A), C * (DLc / C) - (A - B) * La_ * Lb_ / (A * B)])
check(188, hv(zero(Tp_L - claim188)))
claim198 = sp.Matrix([DLa - (1 / C - 1 / B) * Lb_ * Lc_, DLb - (1 / A - 1 / C) * Lc_ * La_, DLc - (1 / B - 1 / A) * La_ * Lb_])
check(198, hv(zero(Tp_L - claim198)))

# negative controls: the numeric test must reject wrong identities
assert not zero(DM - hat(wb) * M)
assert not zero(rates - Mat.T * wb)
assert not zero(EulerRHS + claim91)

if __name__ == '__main__':
    here = pathlib.Path(__file__).resolve().parent
    toml = tomllib.load(open(here / 'sicm-workbook-euler-equations-forced.truth.toml', 'rb'))['display']
    bad = 0
    for e in toml:
        got = COMPUTED.get(e['line'], ('MISSING', ''))
        flag = 'ok' if got[0] == e['verdict'] else 'DISAGREE'
        if flag != 'ok':
            bad += 1
        print(f"{e['line']:4d} {got[0]:12s} toml={e['verdict']:12s} {flag} {got[1]}")
    extra = set(COMPUTED) - {e['line'] for e in toml}
    if extra:
        print('computed but not in toml:', sorted(extra)); bad += 1
    sys.exit(1 if bad else 0)
