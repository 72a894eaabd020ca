"""Independent SymPy truth table for cline-euler-angles-to-euler-equations.md
(Cline, Variational Principles in Classical Mechanics, ch. 13, sections 13.13-13.18, MyST edition).
Convention of the text: z-x-z Euler angles (phi, theta, psi); {lambda} is the PASSIVE matrix taking
space axes (x,y,z) to body axes (1,2,3): (1,2,3) = lambda.(x,y,z), lambda = lambda_psi lambda_theta lambda_phi.
Everything below is derived from these definitions only."""
import sys, tomllib, pathlib, random
import sympy as sp

t = sp.Symbol('t', real=True)
ph, th, ps = [sp.Function(n)(t) for n in ('phi', 'theta', 'psi')]
phd, thd, psd = [sp.diff(q, t) for q in (ph, th, ps)]
I1, I2, I3, m1, m2, b, w, al = sp.symbols('I_1 I_2 I_3 m_1 m_2 b omega alpha', real=True)
N1, N2, N3 = sp.symbols('N_1 N_2 N_3')

def Rz(a):   # passive rotation about the 3rd axis (new axes in terms of old)
    return sp.Matrix([[sp.cos(a), sp.sin(a), 0], [-sp.sin(a), sp.cos(a), 0], [0, 0, 1]])
def Rx(a):   # passive rotation about the 1st axis
    return sp.Matrix([[1, 0, 0], [0, sp.cos(a), sp.sin(a)], [0, -sp.sin(a), sp.cos(a)]])

lam = Rz(ps) * Rx(th) * Rz(ph)
# body-frame angular velocity: d(lambda)/dt = -[w]x lambda  (rows of lambda are body axes in space coords)
W = -sp.diff(lam, t) * lam.T
wb = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])   # omega_1, omega_2, omega_3
ws = lam.T * wb                              # omega_x, omega_y, omega_z

def zero(e, nsamp=4):
    """decide e == 0 numerically: 30-digit evaluation at nsamp random points (angles, rates,
    second derivatives and parameters all random); exact zero short-circuits"""
    e = sp.sympify(e)
    if isinstance(e, sp.MatrixBase):
        return all(zero(x, nsamp) for x in e)
    if e == 0:
        return True
    rnd = random.Random(1)
    for _ in range(nsamp):
        sub = {d: sp.Float(rnd.uniform(-2, 2), 30) for d in e.atoms(sp.Derivative)}
        e2 = e.xreplace(sub)
        sub = {f: sp.Float(rnd.uniform(0.1, 3), 30) for f in e2.atoms(sp.Function) if isinstance(f, sp.core.function.AppliedUndef)}
        e2 = e2.xreplace(sub)
        sub = {q: sp.Float(rnd.uniform(0.3, 2), 30) for q in e2.free_symbols}
        v = sp.N(e2.xreplace(sub), 30)
        if abs(v) > 1e-20:
            return False
    return True

COMPUTED = {}
def check(line, ok, fix_ok=None, note=''):
    """ok: the display as written holds. fix_ok: for a slip, whether the one-edit correction holds."""
    if ok:
        v = 'holds'
    elif fix_ok is None:
        v = 'fails'
    else:
        v = 'typo' if fix_ok else 'fails'
    COMPUTED[line] = (v, note)
def not_a_claim(line, note=''):
    COMPUTED[line] = ('not a claim', note)

c, s = sp.cos, sp.sin
# ---------------------------------------------------------------- 13.13
not_a_claim(17, 'defines {lambda} as the space->body axis matrix')
check(27, zero(sp.Matrix([[c(ph), s(ph), 0], [-s(ph), c(ph), 0], [0, 0, 1]]) - Rz(ph)), note='passive turn by phi about z')
not_a_claim(33, 'names the intermediate axes (n, y\', z)')
not_a_claim(43, 'symbolic description of the 2nd turn')
# d49: the source writes "\ cos \theta" in the (3,3) slot: a markup glitch for \cos\theta; read as cos(theta)
check(49, zero(sp.Matrix([[1, 0, 0], [0, c(th), s(th)], [0, -s(th), c(th)]]) - Rx(th)), note='passive turn by theta about n; (3,3) read as cos theta')
not_a_claim(59, 'symbolic description of the 3rd turn')
check(65, zero(sp.Matrix([[c(ps), s(ps), 0], [-s(ps), c(ps), 0], [0, 0, 1]]) - Rz(ps)), note='passive turn by psi about 3')
# d73: composition of successive passive turns: new = R3 R2 R1 old
x = sp.Matrix(sp.symbols('x_1:4'))
step = Rz(ps) * (Rx(th) * (Rz(ph) * x))
check(73, zero(step - lam * x), note='successive passive turns compose as lambda_psi lambda_theta lambda_phi')
not_a_claim(79, 'restates the definition of {lambda} with the product')
lam_claim = sp.Matrix([
    [c(ph)*c(ps) - s(ph)*c(th)*s(ps), s(ph)*c(ps) + c(ph)*c(th)*s(ps), s(th)*s(ps)],
    [-c(ph)*s(ps) - s(ph)*c(th)*c(ps), -s(ph)*s(ps) + c(ph)*c(th)*c(ps), s(th)*c(ps)],
    [s(ph)*s(th), -c(ph)*s(th), c(th)]])
check(85, zero(lam_claim - lam), note='full matrix equals Rz(psi)Rx(theta)Rz(phi)')
check(91, zero(lam.T * lam - sp.eye(3)), note='inverse relation follows from d79')
lamT_claim = sp.Matrix([
    [c(ph)*c(ps) - s(ph)*c(th)*s(ps), -c(ph)*s(ps) - s(ph)*c(th)*c(ps), s(ph)*s(th)],
    [s(ph)*c(ps) + c(ph)*c(th)*s(ps), -s(ph)*s(ps) + c(ph)*c(th)*c(ps), -c(ph)*s(th)],
    [s(th)*s(ps), s(th)*c(ps), c(th)]])
check(97, zero(lamT_claim - lam.T) and zero(lam * lam.T - sp.eye(3)), note='inverse = transpose')
r2, r3, r6 = sp.sqrt(2), sp.sqrt(3), sp.sqrt(6)
Lp = sp.Matrix([[r3/2, sp.Rational(1, 2), 0], [-sp.Rational(1, 2), r3/2, 0], [0, 0, 1]])
Lt = sp.Matrix([[1, 0, 0], [0, 1/r2, 1/r2], [0, -1/r2, 1/r2]])
Ls = sp.Matrix([[0, 1, 0], [-1, 0, 0], [0, 0, 1]])
check(108, zero(Lp - Rz(sp.pi/6)), note='phi = 30 deg')
check(114, zero(Lt - Rx(sp.pi/4)), note='theta = 45 deg')
check(120, zero(Ls - Rz(sp.pi/2)), note='psi = 90 deg')
# d126: "lambda = Lp Lt Ls = result". Text's own lambda = Ls Lt Lp (13.81 and the sentence before).
res = sp.Matrix([[-r2/4, r3/2, r2/4], [-r6/4, -sp.Rational(1, 2), r6/4], [r2/2, 0, r2/2]])
lam_num = lam_claim.subs({ph: sp.pi/6, th: sp.pi/4, ps: sp.pi/2})
prod_as_written_ok = zero(Lp * Lt * Ls - res)           # True: the product as written is right
lam_ok = zero(lam_num - res) and zero(Ls * Lt * Lp - res)  # False: it is not lambda
# a single edit cannot repair it: reordering the factors changes the product, so the result matrix must change too
one_edit = zero(Ls * Lt * Lp - res)
check(126, prod_as_written_ok and lam_ok, fix_ok=one_edit,
      note='product written in order phi,theta,psi (equals the result) but lambda = psi,theta,phi gives a different matrix')
# ---------------------------------------------------------------- 13.14
w1c = phd*s(th)*s(ps) + thd*c(ps); w2c = phd*s(th)*c(ps) - thd*s(ps); w3c = phd*c(th) + psd
check(148, zero(w1c - wb[0]), note='omega_1 from d(lambda)/dt')
check(152, zero(w2c - wb[1]), note='omega_2')
check(156, zero(w3c - wb[2]), note='omega_3')
check(162, zero(thd*c(ph) + psd*s(th)*s(ph) - ws[0]), note='omega_x = lambda^T omega_body')
check(166, zero(thd*s(ph) - psd*s(th)*c(ph) - ws[1]), note='omega_y')
check(170, zero(phd + psd*c(th) - ws[2]), note='omega_z')
E = sp.Matrix([phd, thd, psd])
Mb = sp.Matrix([[s(th)*s(ps), c(ps), 0], [s(th)*c(ps), -s(ps), 0], [c(th), 0, 1]])
check(176, zero(Mb*E - wb), note='body matrix form')
Ms = sp.Matrix([[0, c(ph), s(th)*s(ph)], [0, s(ph), s(th)*c(ph)], [1, 0, c(th)]])
Ms_fix = sp.Matrix([[0, c(ph), s(th)*s(ph)], [0, s(ph), -s(th)*c(ph)], [1, 0, c(th)]])
check(182, zero(Ms*E - ws), fix_ok=zero(Ms_fix*E - ws), note='row 2, col 3 must be -sin(theta)cos(phi) (cf. 13.90)')
# ---------------------------------------------------------------- 13.15
# kinetic energy in principal axes: T = 1/2 w.I.w with I diagonal -> sum I_ii w_i^2 / 2
Id = sp.diag(I1, I2, I3)
Tgen = sp.Rational(1, 2) * (wb.T * Id * wb)[0]
check(190, zero(sp.Rational(1, 2)*(I1*wb[0]**2 + I2*wb[1]**2 + I3*wb[2]**2) - Tgen), note='principal axes')
Tc = sp.Rational(1, 2)*(I1*(phd*s(th)*s(ps) + thd*c(ps))**2 + I2*(phd*s(th)*c(ps) - thd*s(ps))**2 + I3*(phd*c(th) + psd)**2)
check(196, zero(Tc - Tgen), note='T in Euler rates')
# ---------------------------------------------------------------- 13.16
not_a_claim(204, 'defines l')
not_a_claim(210, 'defines omega^2')
w2 = phd**2 + thd**2 + psd**2 + 2*phd*psd*c(th)
check(216, zero((wb.T*wb)[0] - w2), note='|omega|^2 from body components')
check(222, zero((ws.T*ws)[0] - w2), note='|omega|^2 from space components')
check(228, zero(w2.xreplace({c(th): 1}) - ((phd + psd)**2 + thd**2)), note='theta = 0')
check(234, zero(w2.xreplace({c(th): -1}) - ((phd - psd)**2 + thd**2)), note='theta = 180 deg')
check(240, zero(w2.xreplace({c(th): 0}) - (phd**2 + psd**2 + thd**2)), note='theta = 90 deg')
# ---------------------------------------------------------------- 13.17
not_a_claim(250, 'Newton law for rotation: starting point')
# d256: transport theorem, check on L = lambda^T L_body with arbitrary body components
Lb = sp.Matrix([sp.Function('L%d' % i)(t) for i in (1, 2, 3)])
Ls_ = lam.T * Lb
lhs = lam * sp.diff(Ls_, t)                     # (dL/dt)_space in body components
rhs = sp.diff(Lb, t) + wb.cross(Lb)
check(256, zero(lhs - rhs), note='(dL/dt)_space = (dL/dt)_body + omega x L, verified with the Euler-angle frame')
check(262, True, note='principal axes: L = diag(I) omega (inertia tensor diagonal by choice of axes)')
wv = sp.Matrix(sp.symbols('w1:4')); wdv = sp.Matrix(sp.symbols('wd1:4'))
Lv = sp.Matrix([I1*wv[0], I2*wv[1], I3*wv[2]])
Nv = sp.Matrix([I1*wdv[0], I2*wdv[1], I3*wdv[2]]) + wv.cross(Lv)
det_row = sp.Matrix([wv[1]*Lv[2] - wv[2]*Lv[1], wv[2]*Lv[0] - wv[0]*Lv[2], wv[0]*Lv[1] - wv[1]*Lv[0]])  # cofactor expansion of the determinant
claim = sp.Matrix([I1*wdv[0] - (I2 - I3)*wv[1]*wv[2], I2*wdv[1] - (I3 - I1)*wv[2]*wv[0], I3*wdv[2] - (I1 - I2)*wv[0]*wv[1]])
check(268, zero(det_row - wv.cross(Lv)) and zero(claim - Nv), note='Euler equations, vector form')
check(274, zero(claim - Nv), note='Euler equations, components')
# ---------------------------------------------------------------- 13.18
check(284, zero(sp.Rational(1, 2)*(I1*wv[0]**2 + I2*wv[1]**2 + I3*wv[2]**2) - sp.Rational(1, 2)*(wv.T*sp.diag(I1, I2, I3)*wv)[0]), note='T principal axes')
not_a_claim(290, 'Lagrange equation with generalized force: starting point')
# d306 / chain rule: T(omega(q, qdot)); verify the psi Lagrange expression = chain-rule form
Tq = Tgen
pdot = sp.Symbol('pdot'); psym = sp.Symbol('p')
def dT(expr, var):   # partial derivative w.r.t. a function or derivative
    return sp.diff(expr.subs(var, psym), psym).subs(psym, var)
lagr = sp.diff(dT(Tq, psd), t) - dT(Tq, ps)
chain = sp.diff(sum(I_*wb[i]*dT(wb[i], psd) for i, I_ in enumerate((I1, I2, I3))), t) - sum(I_*wb[i]*dT(wb[i], ps) for i, I_ in enumerate((I1, I2, I3)))
check(296, zero(lagr - chain), note='chain rule through omega_i')
check(302, True, note='dT/domega_i = I_i omega_i from T = sum I_i omega_i^2 / 2 (trivial derivative)')
# d308: d/dt(I3 w3) - I1 w1 w2 + I2 w2 (-w1) = N3  vs the Lagrange expression (= N_psi = N3)
w1f, w2f, w3f = wb
claim308 = sp.diff(I3*w3f, t) - I1*w1f*w2f + I2*w2f*(-w1f)
fix308 = sp.diff(I3*w3f, t) - I1*w1f*w2f - I2*w2f*(-w1f)
check(308, zero(claim308 - lagr), fix_ok=zero(fix308 - lagr), note='the I_2 term must be subtracted: - I_2 w_2 (-w_1)')
check(314, zero(I3*sp.diff(w3f, t) - (I1 - I2)*w1f*w2f - lagr), note='psi equation = third Euler equation')
check(320, zero(claim - Nv), note='Euler equations (same as d274)')
not_a_claim(331, 'definition of L')
not_a_claim(337, 'choice of the 2 axis along L')
not_a_claim(343, 'defines alpha (components of omega)')
# dumbbell: point masses at +b and -b on the 3 axis
def inertia_point(m, r):
    r = sp.Matrix(r); return m*((r.T*r)[0]*sp.eye(3) - r*r.T)
Idb = inertia_point(m1, [0, 0, b]) + inertia_point(m2, [0, 0, -b])
check(349, zero(Idb - sp.diag((m1 + m2)*b**2, (m1 + m2)*b**2, 0)), note='two point masses on the 3 axis at distance b')
om = sp.Matrix([0, w*s(al), w*c(al)])
Ldb = Idb*om
check(355, zero(Ldb - sp.Matrix([0, (m1 + m2)*b**2*w*s(al), 0])), note='L = I omega')
Ndb = Ldb.diff(t) + om.cross(Ldb)   # omega constant
check(361, zero(Ndb - sp.Matrix([-(m1 + m2)*b**2*w**2*s(al)*c(al), 0, 0])), note='N = omega x L for constant omega')

if __name__ == '__main__':
    here = pathlib.Path(__file__).resolve().parent
    slug = pathlib.Path(__file__).name[:-len('_truth.py')]
    table = tomllib.load(open(here / (slug + '.truth.toml'), 'rb'))['display']
    bad = 0
    seen = set()
    for e in table:
        ln = e['line']; seen.add(ln)
        got = COMPUTED.get(ln, ('MISSING', ''))[0]
        flag = 'ok' if got == e['verdict'] else 'DISAGREE'
        if flag != 'ok': bad += 1
        print(f"{ln:5d}  {got:12s} toml={e['verdict']:12s} {flag}")
    for ln in sorted(set(COMPUTED) - seen):
        print(f"{ln:5d}  computed but not in toml"); bad += 1
    print('ALL AGREE' if not bad else f'{bad} disagreements')
    sys.exit(1 if bad else 0)
