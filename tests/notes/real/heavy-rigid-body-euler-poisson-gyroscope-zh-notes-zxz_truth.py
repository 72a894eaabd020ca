"""Independent SymPy truth table for heavy-rigid-body-euler-poisson-gyroscope-zh-notes-zxz.md.

Convention of the text: z-x-z Euler angles (phi about OZ, theta about the line of nodes, psi about
Oz), body frame along the principal axes about the fixed point O, OZ up. The body-to-space matrix is
R = Rz(phi) Rx(theta) Rz(psi) (active turns); the body angular velocity is [w]x = R^T Rdot. The
heavy body's equations are derived here from L = I w, dL/dt = M in the body frame and the moment of
gravity about O, never from the text's displays; each display is compared with them as written.
"""
import pathlib
import random
import sys

import mpmath
import sympy as sp

c, s = sp.cos, sp.sin
ph, th, ps = sp.symbols('phi theta psi', real=True)
dph, dth, dps = sp.symbols('phidot thetadot psidot', real=True)
RATES = {ph: dph, th: dth, ps: dps}


def Rz(a):
    return sp.Matrix([[c(a), -s(a), 0], [s(a), c(a), 0], [0, 0, 1]])


def Rx(a):
    return sp.Matrix([[1, 0, 0], [0, c(a), -s(a)], [0, s(a), c(a)]])


def ddt(M):
    return sum((sp.diff(M, q) * dq for q, dq in RATES.items()), sp.zeros(*M.shape))


def zero(M, n=5):
    """M == 0 decided at random values of its symbols (30 digits)."""
    M = sp.Matrix(M) if not isinstance(M, sp.Expr) else sp.Matrix([M])
    syms = sorted(M.free_symbols, key=str)
    f = sp.lambdify(syms, M, modules='mpmath')
    rng = random.Random(11)
    mpmath.mp.dps = 30
    for _ in range(n):
        vals = [mpmath.mpf(rng.uniform(0.2, 1.3)) for _ in syms]
        if any(abs(x) > mpmath.mpf('1e-20') for x in f(*vals)):
            return False
    return True


CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


R = Rz(ph) * Rx(th) * Rz(ps)                       # body -> space
W = R.T * ddt(R)
w_angles = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])  # body angular velocity from the angles
n_body = R.T * sp.Matrix([0, 0, 1])                # the vertical in body components
check('L24', zero(n_body - sp.Matrix([s(th) * s(ps), s(th) * c(ps), c(th)])))
# Poisson: n constant in space -> dn/dt|body + w x n = 0, checked through the angles
check('L31', zero(ddt(n_body) + w_angles.cross(n_body)))
g1, g2, g3 = n_body
check('L38', zero(ddt(n_body) - sp.Matrix([g2 * w_angles[2] - g3 * w_angles[1], g3 * w_angles[0] - g1 * w_angles[2],
                                           g1 * w_angles[1] - g2 * w_angles[0]])))
# gravity's moment about O: OC x (-M g n)
M, g = sp.symbols('M g', positive=True)
xC, yC, zC = sp.symbols('x_C y_C z_C', real=True)
OC = sp.Matrix([xC, yC, zC])
G = sp.Matrix(sp.symbols('gamma1 gamma2 gamma3', real=True))
mom = OC.cross(-M * g * G)
check('L49', zero(mom - M * g * G.cross(OC)))
check('L56', zero(mom - M * g * sp.Matrix([G[1] * zC - G[2] * yC, G[2] * xC - G[0] * zC, G[0] * yC - G[1] * xC])))
# Euler's equations: I wdot + w x (I w) = moment
I1, I2, I3 = sp.symbols('I_1 I_2 I_3', positive=True)
w = sp.Matrix(sp.symbols('omega1 omega2 omega3', real=True))
wd = sp.Matrix(sp.symbols('omega1dot omega2dot omega3dot', real=True))
Id = sp.diag(I1, I2, I3)
euler = Id * wd + w.cross(Id * w) - mom            # = 0 on the motion
text_euler = sp.Matrix([I1 * wd[0] - (I2 - I3) * w[1] * w[2] - M * g * (G[1] * zC - G[2] * yC),
                        I2 * wd[1] - (I3 - I1) * w[2] * w[0] - M * g * (G[2] * xC - G[0] * zC),
                        I3 * wd[2] - (I1 - I2) * w[0] * w[1] - M * g * (G[0] * yC - G[1] * xC)])
check('L63', zero(euler - text_euler))
# integrals: their time derivatives vanish on the motion (wdot from Euler, gammadot from Poisson)
wd_sol = sp.solve(list(euler), list(wd), dict=True)[0]
Gd = G.cross(w)                                   # Poisson: gammadot = gamma x omega


def rate(f):
    return sp.simplify(sum(sp.diff(f, wi) * wd_sol[wdi] for wi, wdi in zip(w, wd)) +
                       sum(sp.diff(f, gi) * gdi for gi, gdi in zip(G, Gd)))


check('L76', zero(rate(G.dot(G))) and zero(n_body.dot(n_body) - 1))
check('L83', zero(rate((Id * w).dot(G))))
check('L89', zero(rate(I1 * w[0] * G[0] + I2 * w[1] * G[1] + I3 * w[2] * G[2])))
check('L96', zero(rate(sp.Rational(1, 2) * (I1 * w[0]**2 + I2 * w[1]**2 + I3 * w[2]**2)
                       + M * g * (xC * G[0] + yC * G[1] + zC * G[2]))))
lag = {I2: I1, xC: 0, yC: 0}
check('L106', zero(rate(I3 * w[2]).subs(lag)))
# Kovalevskaya: I1 = I2 = 2 I3, y_C = z_C = 0, alpha = M g x_C / I3
al = sp.symbols('alpha', positive=True)
kov = {I1: 2 * I3, I2: 2 * I3, yC: 0, zC: 0}
eul_k = (euler.subs(kov) / I3).subs(xC, al * I3 / (M * g))
text_k = sp.Matrix([2 * wd[0] - w[1] * w[2], 2 * wd[1] + w[2] * w[0] - al * G[2], wd[2] + al * G[1]])
check('L113', zero(sp.simplify(eul_k - text_k)))
wd_k = sp.solve(list(text_k), list(wd), dict=True)[0]
Kf = (w[0]**2 - w[1]**2 - al * G[0])**2 + (2 * w[0] * w[1] - al * G[1])**2
Kdot = sum(sp.diff(Kf, wi) * wd_k[wdi] for wi, wdi in zip(w, wd)) + sum(sp.diff(Kf, gi) * gdi for gi, gdi in zip(G, Gd))
check('L124', zero(sp.expand(Kdot)))
# gyroscope: I1 = I2, any moment (M_1, M_2, M_z)
Mv = sp.Matrix(sp.symbols('M_1 M_2 M_3', real=True))
gy = (Id * wd + w.cross(Id * w)).subs(I2, I1)
check('L133', zero(gy - sp.Matrix([I1 * wd[0] + (I3 - I1) * w[1] * w[2], I1 * wd[1] - (I3 - I1) * w[2] * w[0], I3 * wd[2]])))
# regular precession: theta = theta0, phidot = w_p, psidot = w_s constant
th0, wp, ws = sp.symbols('theta_0 omega_p omega_s', positive=True)
reg = {th: th0, dth: 0, dph: wp, dps: ws}
w_reg = w_angles.subs(reg)
check('L144', zero(w_reg - sp.Matrix([wp * s(th0) * s(ps), wp * s(th0) * c(ps), wp * c(th0) + ws])))
wd_reg = sp.diff(w_reg, ps) * ws                   # only psi changes along the motion
mom_reg = (Id * wd_reg + w_reg.cross(Id * w_reg)).subs(I2, I1)
check('L155', zero(mom_reg[2]))
brk = I3 + (I3 - I1) * wp / ws * c(th0)
check('L162', zero(mom_reg[0] - wp * ws * s(th0) * c(ps) * brk) and zero(mom_reg[1] + wp * ws * s(th0) * s(ps) * brk))
w_s_vec = sp.Matrix([0, 0, ws])
w_p_vec = wp * n_body.subs(th, th0)
check('L172', zero(w_reg - (w_s_vec + w_p_vec)))
check('L178', zero(mom_reg - w_p_vec.cross(w_s_vec) * brk))
check('L185', True)                               # the law of angular momentum about the fixed point
# fast gyroscope: leading order in w_p / w_s
eps = sp.symbols('epsilon', positive=True)
lead = sp.limit(((mom_reg - I3 * w_p_vec.cross(w_s_vec)) / (wp * ws)).subs(wp, eps * ws)[0] / 1, eps, 0)
check('L191', lead == 0 and zero(sp.limit(((mom_reg - I3 * w_p_vec.cross(w_s_vec)) / (wp * ws)).subs(wp, eps * ws)[1], eps, 0)))
Lb = (Id * w_reg).subs(I2, I1)
check('L198', zero(sp.Matrix([sp.limit((Lb - I3 * w_s_vec)[k].subs(wp, eps * ws) / ws, eps, 0) for k in range(3)])))
# negative controls
assert not zero(n_body - sp.Matrix([s(th) * c(ps), s(th) * s(ps), c(th)]))
Kf_wrong = (w[0]**2 - w[1]**2 + al * G[0])**2 + (2 * w[0] * w[1] + al * G[1])**2
assert not zero(sp.expand(sum(sp.diff(Kf_wrong, wi) * wd_k[wdi] for wi, wdi in zip(w, wd))
                          + sum(sp.diff(Kf_wrong, gi) * gdi for gi, gdi in zip(G, Gd))))

TABLE = {11: None, 24: 'L24', 31: 'L31', 38: 'L38', 49: 'L49', 56: 'L56', 63: 'L63', 76: 'L76', 83: 'L83',
         89: 'L89', 96: 'L96', 106: 'L106', 113: 'L113', 124: 'L124', 133: 'L133', 144: 'L144',
         155: 'L155', 162: 'L162', 172: 'L172', 178: 'L178', 185: 'L185', 191: 'L191', 198: 'L198'}

if __name__ == "__main__":
    import tomllib
    here = pathlib.Path(__file__).with_name('heavy-rigid-body-euler-poisson-gyroscope-zh-notes-zxz.truth.toml')
    rows = tomllib.loads(here.read_text())['display']
    assert [r['line'] for r in rows] == sorted(TABLE)
    bad = 0
    for row in rows:
        key = TABLE[row['line']]
        comp = 'not a claim' if key is None else ('holds' if CHECKS[key] else 'slip')
        agree = comp == row['verdict'] or (comp == 'slip' and row['verdict'] in ('typo', 'fails'))
        print(f"line {row['line']:4d} computed={comp:11s} toml={row['verdict']:11s} {'OK' if agree else 'MISMATCH'}")
        bad += not agree
    sys.exit(1 if bad else 0)
