"""Independent truth table for rigid-body-formula-notebook-landau-zxz.md.

Convention of the text (Landau & Lifshitz): z-x-z Euler angles phi, theta, psi;
Omega_i body components of the angular velocity; M angular momentum (but M is also the
mass in the heavy-top section); I_1 = I_2 for symmetric tops; a = pivot-to-centre-of-mass distance.
Only SymPy and the standard library are used.
"""
import sys, re, random, pathlib
import sympy as sp

HERE = pathlib.Path(__file__).resolve().parent
SLUG = "rigid-body-formula-notebook-landau-zxz"

t = sp.symbols('t', real=True)
CHECKS = {}


def check(line, ok, note=""):
    CHECKS.setdefault(line, []).append((bool(ok), note))


def is_zero(expr, syms, n=6, tol=1e-20):
    """Decide expr == 0 by simplify, then by random high-precision evaluation."""
    try:
        if sp.simplify(expr) == 0:
            return True
    except Exception:
        pass
    rnd = random.Random(1)
    for _ in range(n):
        sub = {s: sp.Float(rnd.uniform(0.3, 1.2), 30) for s in syms}
        v = sp.N(expr.subs(sub), 30)
        if abs(complex(v)) > tol:
            return False
    return True


def Rz(a):
    return sp.Matrix([[sp.cos(a), -sp.sin(a), 0], [sp.sin(a), sp.cos(a), 0], [0, 0, 1]])


def Rx(a):
    return sp.Matrix([[1, 0, 0], [0, sp.cos(a), -sp.sin(a)], [0, sp.sin(a), sp.cos(a)]])


def vee(S):
    return sp.Matrix([S[2, 1], S[0, 2], S[1, 0]])


# ---------------------------------------------------------------- kinematics (z-x-z)
ph, th, ps = [sp.Function(n)(t) for n in ('phi', 'theta', 'psi')]
Rot = Rz(ph) * Rx(th) * Rz(ps)            # body -> space (active), Landau's Euler angles
Om_body = vee(sp.simplify(Rot.T * Rot.diff(t)))   # body components Omega_1..3
Om_body = sp.simplify(Om_body)

# d15: moving-frame kinematics (summary). Verify numerically with a concrete motion.
# Frame: origin R0(t), axes Rot(t) with concrete Euler-angle functions; particle with
# moving-frame coordinates rp(t). Vectors expressed in fixed components.
def frame_kinematics_ok():
    subsf = {ph: t**2 / 3 + t, th: sp.sin(t) + 1, ps: sp.cos(2 * t)}
    Rc = Rot.subs(subsf).doit()
    R0 = sp.Matrix([sp.sin(t), t**3, sp.exp(t / 3)])
    q = sp.Matrix([t**2, sp.cos(t), 1 + t])         # coordinates in the moving frame
    r = R0 + Rc * q
    Omega = vee(Rc.diff(t) * Rc.T)                     # space components
    rp = Rc * q
    vp = Rc * q.diff(t)                                # velocity seen in moving frame
    ap = Rc * q.diff(t, 2)
    V = R0.diff(t); A = R0.diff(t, 2)
    v_claim = V + vp + Omega.cross(rp)
    a_claim = A + ap + Omega.diff(t).cross(rp) + Omega.cross(Omega.cross(rp)) + 2 * Omega.cross(vp)
    # d'Q/dt rule: dQ/dt = d'Q/dt + Omega x Q for Q = Rc*w(t)
    w = sp.Matrix([sp.sin(3 * t), t, t**2 - 1])
    Q = Rc * w
    rule = Q.diff(t) - (Rc * w.diff(t) + Omega.cross(Q))
    ok = True
    for tv in (sp.Rational(3, 10), sp.Rational(77, 100), sp.Rational(7, 5)):
        for e in list(r.diff(t) - v_claim) + list(r.diff(t, 2) - a_claim) + list(rule):
            if abs(sp.N(e.subs(t, tv), 30)) > 1e-20:
                ok = False
    return ok

FK = frame_kinematics_ok()
check(15, FK, "v and a in a moving, rotating frame; numeric check on a concrete motion")
# d25: derivation of the same; every row is the rotating-derivative rule or its consequence
check(25, FK, "dQ/dt = d'Q/dt + Omega x Q; a = A + a' + ... (same numeric check)")

# d44: Omega_i in z-x-z angles
phd, thd, psd = ph.diff(t), th.diff(t), ps.diff(t)
claim44 = sp.Matrix([phd * sp.sin(th) * sp.sin(ps) + thd * sp.cos(ps),
                     phd * sp.sin(th) * sp.cos(ps) - thd * sp.sin(ps),
                     phd * sp.cos(th) + psd])
check(44, all(sp.simplify(e) == 0 for e in (Om_body - claim44)), "R^T dR/dt of Rz Rx Rz")

# d56 / d66: inertia tensor, T and M for one generic particle (everything is linear in masses)
m = sp.symbols('m', positive=True)
x1, x2, x3, W1, W2, W3 = sp.symbols('x1 x2 x3 W1 W2 W3', real=True)
rv = sp.Matrix([x1, x2, x3]); W = sp.Matrix([W1, W2, W3])
Iten = m * (rv.dot(rv) * sp.eye(3) - rv * rv.T)
T_direct = sp.Rational(1, 2) * m * (W.cross(rv)).dot(W.cross(rv))
T_tensor = sp.Rational(1, 2) * (W.T * Iten * W)[0]
M_direct = m * rv.cross(W.cross(rv))
M_tensor = Iten * W
ok56 = sp.expand(T_direct - T_tensor) == 0 and all(sp.expand(e) == 0 for e in (M_direct - M_tensor))
check(56, ok56, "T = 1/2 I_ij W_i W_j and M_i = I_ij W_j from the particle sums")
mid_T = sp.Rational(1, 2) * m * (W.dot(W) * rv.dot(rv) - W.dot(rv) ** 2)
mid_M = m * (W * rv.dot(rv) - rv * rv.dot(W))
ok66 = ok56 and sp.expand(T_direct - mid_T) == 0 and all(sp.expand(e) == 0 for e in (M_direct - mid_M))
check(66, ok66, "intermediate rows (BAC-CAB) also hold")

# d83 / d93: Euler's equations from dM/dt = N in principal axes
I1, I2, I3 = sp.symbols('I_1 I_2 I_3', positive=True)
Om = sp.Matrix([sp.Function('Omega_%d' % k)(t) for k in (1, 2, 3)])
Mb = sp.Matrix([I1 * Om[0], I2 * Om[1], I3 * Om[2]])
N_true = Mb.diff(t) + Om.cross(Mb)      # body components of the torque
claim83 = sp.Matrix([I1 * Om[0].diff(t) + (I3 - I2) * Om[1] * Om[2],
                     I2 * Om[1].diff(t) + (I1 - I3) * Om[2] * Om[0],
                     I3 * Om[2].diff(t) + (I2 - I1) * Om[0] * Om[1]])
check(83, all(sp.expand(e) == 0 for e in (claim83 - N_true)), "Euler equations")
check(93, all(sp.expand(e) == 0 for e in (claim83 - N_true)), "column form equals Euler equations")

# ---------------------------------------------------------------- free symmetric top
th0, Mz = sp.symbols('theta_0 M_z', positive=True)
# d124: with theta const, phidot = Mz/I1, psidot = Mz cos(theta)(1/I3 - 1/I1),
# the space-frame angular momentum must be (0, 0, Mz) (z along M) -- vector route.
phid_c = Mz / I1
psid_c = Mz * sp.cos(th0) * (1 / I3 - 1 / I1)
Omb = claim44.subs({thd: 0}).subs({phd: phid_c, psd: psid_c}).subs(th, th0)
Mspace = Rot.subs(th, th0) * sp.diag(I1, I1, I3) * Omb
ok124 = all(sp.simplify(e) == 0 for e in (Mspace - sp.Matrix([0, 0, Mz])))
check(124, ok124, "space components of M equal (0,0,M_z) with the stated rates")

# d134: Lagrangian route for the free top
a_, b_, c_, q = sp.symbols('phidot thetadot psidot theta', real=True)
Lf = sp.Rational(1, 2) * I1 * (a_**2 * sp.sin(q)**2 + b_**2) + sp.Rational(1, 2) * I3 * (a_ * sp.cos(q) + c_)**2
Om3 = a_ * sp.cos(q) + c_
rows = []
rows.append(sp.diff(Lf, c_) - I3 * Om3)
rows.append(sp.diff(Lf, a_) - (I1 * a_ * sp.sin(q)**2 + I3 * Om3 * sp.cos(q)))
# impose M_3 = Mz cos q and p_phi = Mz, solve, compare with the text
sol = sp.solve([I3 * Om3 - Mz * sp.cos(q), I1 * a_ * sp.sin(q)**2 + I3 * Om3 * sp.cos(q) - Mz], [a_, c_], dict=True)[0]
rows.append(sol[a_] - (Mz - Mz * sp.cos(q)**2) / (I1 * sp.sin(q)**2))
rows.append((Mz - Mz * sp.cos(q)**2) / (I1 * sp.sin(q)**2) - Mz / I1)
rows.append(sol[c_] - (Mz * sp.cos(q) / I3 - sol[a_] * sp.cos(q)))
rows.append(sol[c_] - Mz * sp.cos(q) * (1 / I3 - 1 / I1))
dLdq = sp.diff(Lf, q)
rows.append(dLdq - (I1 * a_**2 * sp.sin(q) * sp.cos(q) - I3 * Om3 * a_ * sp.sin(q)))
dLdq_on = dLdq.subs(sol)
rows.append(dLdq_on - (Mz**2 / I1 * sp.sin(q) * sp.cos(q) - Mz**2 / I1 * sp.sin(q) * sp.cos(q)))
rows.append(dLdq_on)   # = 0
rows.append(sp.diff(Lf, b_) - I1 * b_)
E_free = (Lf).subs(sol)   # no potential: E = T
rows.append(E_free - (sp.Rational(1, 2) * I1 * (Mz**2 / I1**2 * sp.sin(q)**2 + b_**2)
                      + sp.Rational(1, 2) * I3 * Mz**2 / I3**2 * sp.cos(q)**2))
check(134, all(is_zero(e, [I1, I3, Mz, q, a_, b_, c_]) for e in rows), "all rows of the free-top derivation")

# ---------------------------------------------------------------- heavy symmetric top
Mm, g, a, M3, E = sp.symbols('M g a M_3 E', positive=True)
Ip = I1 + Mm * a**2
Lh = sp.Rational(1, 2) * Ip * (a_**2 * sp.sin(q)**2 + b_**2) + sp.Rational(1, 2) * I3 * (a_ * sp.cos(q) + c_)**2 - Mm * g * a * sp.cos(q)
# independent route for L: T about the pivot with body rates, potential of the centre of mass
# at height a cos(theta) above the pivot (z up).
OmB = claim44
T_piv = sp.Rational(1, 2) * (Ip * OmB[0]**2 + Ip * OmB[1]**2 + I3 * OmB[2]**2)
zc = (Rot * sp.Matrix([0, 0, a]))[2]
L_ref = (T_piv - Mm * g * zc).subs({phd: a_, thd: b_, psd: c_}).subs(th, q)
okL = sp.simplify(L_ref - Lh) == 0
solh = sp.solve([I3 * (a_ * sp.cos(q) + c_) - M3, sp.diff(Lh, a_) - Mz], [a_, c_], dict=True)[0]
phid_h = (Mz - M3 * sp.cos(q)) / (Ip * sp.sin(q)**2)
psid_h = M3 / I3 - (Mz - M3 * sp.cos(q)) * sp.cos(q) / (Ip * sp.sin(q)**2)
ok_rates = sp.simplify(solh[a_] - phid_h) == 0 and sp.simplify(solh[c_] - psid_h) == 0
check(157, ok_rates, "phidot, psidot from p_phi = M_z, p_psi = M_3")

rows = [L_ref - Lh,
        sp.diff(Lh, c_) - I3 * (a_ * sp.cos(q) + c_),
        sp.diff(Lh, a_) - (Ip * a_ * sp.sin(q)**2 + I3 * (a_ * sp.cos(q) + c_) * sp.cos(q)),
        solh[a_] - phid_h, solh[c_] - psid_h]
# energy: E = T + U with the rates eliminated
E_true = (Lh + 2 * Mm * g * a * sp.cos(q)).subs(solh)
E_claim = (sp.Rational(1, 2) * Ip * b_**2 + sp.Rational(1, 2) * (Mz - M3 * sp.cos(q))**2 / (Ip * sp.sin(q)**2)
           + sp.Rational(1, 2) * M3**2 / I3 + Mm * g * a * sp.cos(q))
rows.append(E_true - E_claim)
# u = cos(theta): thetadot^2 = udot^2/(1-u^2) with udot = -sin(theta) thetadot
ud = -sp.sin(q) * b_
rows.append(b_**2 - ud**2 / (1 - sp.cos(q)**2))
E_u = (sp.Rational(1, 2) * Ip * ud**2 / (1 - sp.cos(q)**2) + sp.Rational(1, 2) * (Mz - M3 * sp.cos(q))**2 / (Ip * (1 - sp.cos(q)**2))
       + sp.Rational(1, 2) * M3**2 / I3 + Mm * g * a * sp.cos(q))
rows.append(E_u - E_claim)
# udot^2 = (1-u^2)(A - B u) - (Mz - M3 u)^2/Ip^2 with A = (2E - M3^2/I3)/Ip, B = 2 M g a/Ip,
# on the energy shell E = E_claim
A_ = (2 * E_claim - M3**2 / I3) / Ip
B_ = 2 * Mm * g * a / Ip
u = sp.cos(q)
rows.append(ud**2 - ((1 - u**2) * (A_ - B_ * u) - (Mz - M3 * u)**2 / Ip**2))
check(167, okL and all(is_zero(e, [I1, I3, Mm, g, a, Mz, M3, q, a_, b_, c_]) for e in rows),
      "L, momenta, rates, E, u-form, udot^2 with A=(2E-M3^2/I3)/I', B=2Mga/I'")

# ---------------------------------------------------------------- asymmetric free top
# d189: bounds sqrt(2 E I1) <= M <= sqrt(2 E I3) for I1<I2<I3 and the stability labels
m1, m2, m3 = sp.symbols('m1 m2 m3', real=True)
i1, d2, d3 = sp.symbols('i1 d2 d3', positive=True)
J1, J2, J3 = i1, i1 + d2, i1 + d2 + d3          # I1 < I2 < I3
E2 = m1**2 / J1 + m2**2 / J2 + m3**2 / J3        # = 2E
Msq = m1**2 + m2**2 + m3**2
up = sp.factor(sp.together(E2 * J3 - Msq))       # 2E I3 - M^2 >= 0
lo = sp.factor(sp.together(Msq - E2 * J1))       # M^2 - 2E I1 >= 0
def nonneg(expr):
    n, d = sp.fraction(sp.together(expr))
    n = sp.expand(n)
    return all(c > 0 for c in sp.Poly(n, m1, m2, m3, i1, d2, d3).coeffs()) and sp.Poly(sp.expand(d), i1, d2, d3).coeffs() and all(c > 0 for c in sp.Poly(sp.expand(d), i1, d2, d3).coeffs())
ok_bounds = nonneg(up) and nonneg(lo)

# linearisation about steady rotation about axis k
W0 = sp.symbols('W0', positive=True)
dW = sp.Matrix(sp.symbols('e1 e2 e3'))
lam2 = {}
for k in range(3):
    base = [0, 0, 0]; base[k] = W0
    Ivec = [I1, I2, I3]
    Wt = sp.Matrix(base) + dW
    f = [((Ivec[(i + 1) % 3] - Ivec[(i + 2) % 3]) * Wt[(i + 1) % 3] * Wt[(i + 2) % 3]) / Ivec[i] for i in range(3)]
    Jac = sp.Matrix(f).jacobian(dW).subs({d: 0 for d in dW})
    ev = [e for e in Jac.eigenvals() if e != 0]
    lam2[k] = sp.simplify(ev[0]**2)
claim_l = [-W0**2 * (I3 - I1) * (I2 - I1) / (I2 * I3),
           W0**2 * (I3 - I2) * (I2 - I1) / (I1 * I3),
           -W0**2 * (I3 - I2) * (I3 - I1) / (I1 * I2)]
ok_l = all(sp.simplify(lam2[k] - claim_l[k]) == 0 for k in range(3))
# signs with I1 < I2 < I3: axis 1 stable (<0), axis 2 unstable (>0), axis 3 stable (<0)
sgn = {I1: J1, I2: J2, I3: J3}
s = [sp.simplify(claim_l[k].subs(sgn)) for k in range(3)]
ok_sign = (sp.simplify(-s[0]).is_positive and s[1].is_positive and sp.simplify(-s[2]).is_positive)
check(189, ok_bounds and ok_sign, "bounds from M^2 and 2E; stability pattern")
# d196: M^2, E definitions, bounds, ansatz, lambda^2 values and their signs
E_def = sp.Rational(1, 2) * (J1 * (m1 / J1)**2 + J2 * (m2 / J2)**2 + J3 * (m3 / J3)**2)
ok_E = sp.simplify(E_def - (m1**2 / (2 * J1) + m2**2 / (2 * J2) + m3**2 / (2 * J3))) == 0
check(196, ok_E and ok_bounds and ok_l and ok_sign, "E in M_i; lambda^2 for each axis; signs")


# ---------------------------------------------------------------- compare with the toml
def load_toml(path):
    try:
        import tomllib
        return tomllib.loads(path.read_text())
    except ImportError:
        ents, cur = [], None
        for ln in path.read_text().splitlines():
            if ln.strip() == '[[display]]':
                cur = {}; ents.append(cur)
            mm = re.match(r'\s*(line|verdict)\s*=\s*"?([^"]*)"?', ln)
            if mm and cur is not None:
                cur[mm.group(1)] = int(mm.group(2)) if mm.group(1) == 'line' else mm.group(2)
        return {'display': ents}


if __name__ == "__main__":
    table = load_toml(HERE / f"{SLUG}.truth.toml")['display']
    bad = 0
    for ent in table:
        ln, want = ent['line'], ent['verdict']
        if ln not in CHECKS:
            got = "not a claim"
        else:
            got = "holds" if all(ok for ok, _ in CHECKS[ln]) else "slip"
        agree = (got == want) or (got == "slip" and want in ("typo", "fails"))
        print(f"{ln:4d}  computed={got:12s} toml={want:12s} {'OK' if agree else 'DISAGREE'}")
        bad += not agree
    missing = set(CHECKS) - {e['line'] for e in table}
    if missing:
        print("checks without toml entry:", sorted(missing)); bad += 1
    sys.exit(1 if bad else 0)
