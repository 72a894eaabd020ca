"""Independent SymPy truth table for murundb-euler-angles-321-rates.md.
Convention of the text: 3-2-1 (z-y-x) intrinsic sequence, yaw psi, pitch theta, roll phi;
R^alpha_beta converts beta-frame coordinates to alpha (body) coordinates (passive / frame rotation):
R^alpha_beta = R1(phi) R2(theta) R3(psi).  Body angular velocity omega^alpha_{beta alpha}.
"""
import sys, random, pathlib
import sympy as sp

t = sp.symbols('t', real=True)
psi, th, ph = sp.symbols('psi theta phi', real=True)
dpsi, dth, dph = sp.symbols('psidot thetadot phidot', real=True)
_RATES = {psi: dpsi, th: dth, ph: dph}
def ddt(M):
    """time derivative by the chain rule (angles depend on t through their rates)"""
    return sum((sp.diff(M, q) * dq for q, dq in _RATES.items()), sp.zeros(*M.shape) if hasattr(M, 'shape') else 0)
c, s = sp.cos, sp.sin

def R1(a):  # frame rotation about x
    return sp.Matrix([[1, 0, 0], [0, c(a), s(a)], [0, -s(a), c(a)]])
def R2(a):  # frame rotation about y
    return sp.Matrix([[c(a), 0, -s(a)], [0, 1, 0], [s(a), 0, c(a)]])
def R3(a):  # frame rotation about z
    return sp.Matrix([[c(a), s(a), 0], [-s(a), c(a), 0], [0, 0, 1]])
def skew(v):
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
def unskew(M):
    return sp.Matrix([M[2, 1], M[0, 2], M[1, 0]])
E = sp.eye(3)
I1, I2, I3 = E[:, 0], E[:, 1], E[:, 2]

def zero(M, n=4):
    """Decide M == 0 by evaluation at random points (angles, rates, free symbols), 30 digits."""
    M = sp.Matrix(M) if not isinstance(M, sp.Expr) else sp.Matrix([M])
    rng = random.Random(12345)
    syms = sorted(M.free_symbols, key=str)
    f = sp.lambdify(syms, M, modules='mpmath')
    import mpmath
    mpmath.mp.dps = 30
    for _ in range(n):
        vals = [mpmath.mpf(rng.uniform(-1.4, 1.4)) for _ in syms]
        if any(abs(x) > mpmath.mpf('1e-20') for x in f(*vals)):
            return False
    return True

# ---- independent derivation -------------------------------------------------
Rab = R1(ph) * R2(th) * R3(psi)            # R^alpha_beta
Rba = Rab.T                                # R^beta_alpha
# Angular velocity of body alpha relative to beta, in alpha: sum of the three
# elementary rates, each carried into the body frame (built by geometry, not from the text)
w_geom = I1 * dph + R1(ph) * I2 * dth + R1(ph) * R2(th) * I3 * dpsi

CHECKS = {}
def check(line, ok, note=""):
    CHECKS[line] = (bool(ok), note)

# d1 Poisson relations (alignat): Omega^a_{ab} = Rdot^a_b R^b_a, Omega^a_{ba} = -..., Omega^b_{ab} = R^b_a Rdot^a_b ...
Om_a_ab = ddt(Rab) * Rba
Om_a_ba = -ddt(Rab) * Rba
Om_b_ab = Rba * ddt(Rab)
Om_b_ba = -Rba * ddt(Rab)
ok = zero(Om_a_ab + Om_a_ab.T)                          # skew
ok &= zero(Om_a_ab + Om_a_ba)                           # index swap reverses sense
ok &= zero(Om_b_ab - Rba * Om_a_ab * Rab)               # frame change of a skew matrix
ok &= zero(Om_b_ba + Om_b_ab)
ok &= zero(unskew(Om_a_ba) - w_geom)                    # Omega^a_{ba} is [w^a_{ba}]x
check('d1', ok)
# d2 [w]x = -Rdot R^{-1} = -Rdot R^T
check('d2', zero(skew(w_geom) + ddt(Rab) * Rab.inv()) and zero(Rab.inv() - Rab.T))
# d3 elementary relations
ok = zero(-ddt(R3(psi)) * R3(psi).T - skew(I3) * dpsi)
ok &= zero(-ddt(R2(th)) * R2(th).T - skew(I2) * dth)
ok &= zero(-ddt(R1(ph)) * R1(ph).T - skew(I1) * dph)
check('d3', ok)
# d4 R3 as written (the "1." entry is the number 1)
check('d4', zero(sp.Matrix([[c(psi), s(psi), 0], [-s(psi), c(psi), 0], [0, 0, 1]]) - R3(psi)))
# d5 Rdot_3 as written
pd = dpsi
R3dot_claim = sp.Matrix([[-pd * s(psi), pd * c(psi), 0], [-pd * c(psi), -pd * s(psi), 0], [0, 0, 0]])
check('d5', zero(R3dot_claim - ddt(R3(psi))))
# d6 -R3dot R3^T = [I3]x psidot
check('d6', zero(-R3dot_claim * R3(psi).T - skew(I3) * pd))
# d7 R^a_b = R^a_th R^th_psi R^psi_b = R1 R2 R3 (composition; same as the proofs' matrices)
check('d7', zero(Rab - R1(ph) * R2(th) * R3(psi)))
# d8 product-rule chain: compare every row with -Rdot R^T
A, B, C = R1(ph), R2(th), R3(psi)
lhs = -ddt(Rab) * Rab.T
row2 = -(ddt(A) * B * C + A * ddt(B) * C + A * B * ddt(C)) * C.T * B.T * A.T
row3 = -A * B * ddt(C) * C.T * B.T * A.T - A * ddt(B) * B.T * A.T - ddt(A) * A.T
row4 = row3
row5 = A * B * skew(I3) * pd * B.T * A.T + A * skew(I2) * dth * A.T + skew(I1) * dph
check('d8', zero(lhs - row2) and zero(lhs - row3) and zero(lhs - row5) and zero(skew(w_geom) - lhs))
# d9 [R r]x = R [r]x R^T for a rotation R (random rotations, symbolic r)
rv = sp.Matrix(sp.symbols('r1 r2 r3'))
ok = True
for _ in range(3):
    a, b, g = [sp.Rational(random.randint(-300, 300), 100) for _ in range(3)]
    Rn = R1(a) * R2(b) * R3(g)
    ok &= zero(skew(Rn * rv) - Rn * skew(rv) * Rn.T)
check('d9', ok)
# d10 [w]x = [R1R2 I3 psidot]x + [R1 I2 thdot]x + [I1 phdot]x
check('d10', zero(skew(w_geom) - (skew(A * B * I3 * pd) + skew(A * I2 * dth) + skew(I1 * dph))))
# d11 w = [I1, R1 I2, R1 R2 I3] Psidot
S_cols = sp.Matrix.hstack(I1, A * I2, A * B * I3)
Psidot = sp.Matrix([dph, dth, dpsi])
check('d11', zero(S_cols * Psidot - w_geom) and zero(lhs - skew(S_cols * Psidot)))
# d12 S as written
S_claim = sp.Matrix([[1, 0, -s(th)], [0, c(ph), s(ph) * c(th)], [0, -s(ph), c(ph) * c(th)]])
check('d12', zero(S_claim - S_cols))
# d13 inverse as written
Sinv_claim = sp.Matrix([[1, s(ph) * sp.tan(th), c(ph) * sp.tan(th)], [0, c(ph), -s(ph)],
                        [0, s(ph) / c(th), c(ph) / c(th)]])
check('d13', zero(Sinv_claim * S_claim - E))
# d14..d19: single-axis coordinate transformations (frame rotations) and their matrices
xb, yb, zb = sp.symbols('x_b y_b z_b')
v = sp.Matrix([xb, yb, zb])
# d14: x^psi = x c + y s, y^psi = -x s + y c, z^psi = z  -> axes rotated by +psi about z
ex, ey = sp.Matrix([c(psi), s(psi), 0]), sp.Matrix([-s(psi), c(psi), 0])   # new axes in old frame
check('d14', zero(sp.Matrix([xb * c(psi) + yb * s(psi), -xb * s(psi) + yb * c(psi), zb]) -
                  sp.Matrix([ex.dot(v), ey.dot(v), zb])))
check('d15', zero(sp.Matrix([[c(psi), s(psi), 0], [-s(psi), c(psi), 0], [0, 0, 1]]) * v -
                  sp.Matrix([xb * c(psi) + yb * s(psi), -xb * s(psi) + yb * c(psi), zb])))
# d16: pitch, new axes: x' = (c, 0, -s), z' = (s, 0, c) in old frame (rotation +theta about y)
exp_, ezp = sp.Matrix([c(th), 0, -s(th)]), sp.Matrix([s(th), 0, c(th)])
check('d16', zero(sp.Matrix([xb * c(th) - zb * s(th), yb, xb * s(th) + zb * c(th)]) -
                  sp.Matrix([exp_.dot(v), yb, ezp.dot(v)])))
check('d17', zero(sp.Matrix([[c(th), 0, -s(th)], [0, 1, 0], [s(th), 0, c(th)]]) - R2(th)))
# d18: roll, new axes y' = (0, c, s), z' = (0, -s, c)
eyp, ezp2 = sp.Matrix([0, c(ph), s(ph)]), sp.Matrix([0, -s(ph), c(ph)])
check('d18', zero(sp.Matrix([xb, yb * c(ph) + zb * s(ph), -yb * s(ph) + zb * c(ph)]) -
                  sp.Matrix([xb, eyp.dot(v), ezp2.dot(v)])))
check('d19', zero(sp.Matrix([[1, 0, 0], [0, c(ph), s(ph)], [0, -s(ph), c(ph)]]) - R1(ph)))
# extra (not a display): the table's DCM R^beta_alpha for 321
cf, sf, ct, st, cp, sps = c(ph), s(ph), c(th), s(th), c(psi), s(psi)
DCM_tab = sp.Matrix([[ct * cp, -cf * sps + sf * st * cp, sf * sps + cf * st * cp],
                     [ct * sps, cf * cp + sf * st * sps, -sf * cp + cf * st * sps],
                     [-st, sf * ct, cf * ct]])
assert zero(DCM_tab - Rba)

# negative controls: the numeric zero test must reject wrong variants
assert not zero(S_claim.T - S_cols)
assert not zero(-ddt(R3(psi)) * R3(psi).T + skew(I3) * dpsi)

ORDER = ['d%d' % k for k in range(1, 20)]

def verdict_from_check(ok):
    return 'holds' if ok else 'slip'

if __name__ == "__main__":
    here = pathlib.Path(__file__).with_name('murundb-euler-angles-321-rates.truth.toml')
    import tomllib
    table = tomllib.loads(here.read_text())['display']
    assert len(table) == len(ORDER), (len(table), len(ORDER))
    bad = 0
    for key, row in zip(ORDER, table):
        if key not in CHECKS:
            comp = 'not a claim'
        else:
            comp = 'holds' if CHECKS[key][0] else 'slip'
        want = row['verdict']
        agree = (comp == want) or (comp == 'slip' and want in ('typo', 'fails'))
        print(f"line {row['line']:4d} {key:4s} computed={comp:11s} toml={want:11s} {'OK' if agree else 'MISMATCH'}")
        bad += not agree
    sys.exit(1 if bad else 0)
