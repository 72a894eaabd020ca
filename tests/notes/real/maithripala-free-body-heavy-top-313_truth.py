"""Independent SymPy truth table for maithripala-free-body-heavy-top-313.tex.

The text's own setting: principal body frame b with moments I_1, I_2, I_3 (the text writes them
\\mathbb{I}_i), body angular velocity Omega with R^T Rdot = hat(Omega), body angular momentum
Pi = I Omega, spatial angular momentum pi = R Pi, h = ||Pi|| (so ||Pi||^2 = h^2), energy E.
Euler angles 3-1-3 as active (counter-clockwise) rotations b = e R, R = R_3(theta_1) R_1(theta_2)
R_3(theta_3). Heavy top: centre of mass at l e_3 on the symmetry axis; the text's Upsilon is the
vertical [0 0 1]^T, Gamma = R^T Upsilon (see row 204 of the table for the reading of its sign).
Every check is built here from these definitions, never from the text's later displays.
"""
import random
import sys
import sympy as sp

import truth_table

CHECKS = {}
def check(key, ok):
    CHECKS[key] = bool(ok)

I1, I2, I3, E, h, m, g, l = sp.symbols('I_1 I_2 I_3 E h m g l', positive=True)
W = sp.symbols('Omega_1:4', real=True)
P = sp.symbols('Pi_1:4', real=True)
G = sp.symbols('Gamma_1:4', real=True)
Id = sp.diag(I1, I2, I3)
Om, Pi, Ga = sp.Matrix(W), sp.Matrix(P), sp.Matrix(G)
ups = sp.Matrix([0, 0, 1])

def hat(v):
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])

def zero(expr, n=5):
    """expr == 0 at random points of its free symbols (moments ordered I1 > I2 > I3)."""
    rng = random.Random(7)
    M = sp.Matrix([expr]) if not hasattr(expr, 'shape') else sp.Matrix(expr)
    syms = sorted(M.free_symbols, key=str)
    for _ in range(n):
        vals = {s: sp.Rational(rng.randint(1, 900), 1000) + (2 if s == I1 else 1 if s == I2 else 0) for s in syms}
        if any(abs(sp.N(x.subs(vals), 30)) > 1e-20 for x in M):
            return False
    return True

# --- free body: Euler's equations derived from dpi/dt = 0 with pi = R Pi, Rdot = R hat(Omega)
Pidot_free = Pi.cross(Id.inv() * Pi)        # R (hat(Omega) Pi + Pidot) = 0  =>  Pidot = Pi x Omega
assert zero(hat(Id.inv() * Pi) * Pi + Pidot_free)
Pi_of_W = Id * Om
KE = sp.Rational(1, 2) * (Om.T * Id * Om)[0]
# 27: pi = R[I Omega] = R[Pi] constant; KE = 1/2 sum I W^2 = 1/2 sum Pi^2/I = E; ||Pi||^2 = sum I^2 W^2 = sum Pi^2 = h^2
check(27, zero(KE - sp.Rational(1, 2) * sum(Pi_of_W[i] ** 2 / Id[i, i] for i in range(3)))
      and zero(sum(Pi_of_W[i] ** 2 for i in range(3)) - sum((Id[i, i] * W[i]) ** 2 for i in range(3))))
# 44: Rdot = R hat(I^-1 Pi); Pidot = Pi x I^-1 Pi
check(44, zero(Pidot_free - Pi.cross(Id.inv() * Pi)))
# 50: the three components
claim50 = sp.Matrix([(I2 - I3) / (I2 * I3) * P[1] * P[2], (I3 - I1) / (I3 * I1) * P[2] * P[0],
                     (I1 - I2) / (I1 * I2) * P[0] * P[1]])
check(50, zero(claim50 - Pidot_free))
# 61: R(tau) R^T(0) = exp(theta hat(n)) names the phase theta: not a claim
# 68: KE = Pi . Omega ... : the kinetic energy is HALF of Pi . Omega
check(68, zero(KE - (Pi_of_W.T * Om)[0]))
assert zero(KE - sp.Rational(1, 2) * (Pi_of_W.T * Om)[0])      # the corrected form holds
# 75: alpha(t) = arccos(Upsilon . Pi / h) defines the nutation angle: not a claim

# --- analytic solution: eliminate Pi_1^2 and Pi_3^2 with E and h^2
E_rel = sp.Eq(sum(P[i] ** 2 / Id[i, i] for i in range(3)), 2 * E)
H_rel = sp.Eq(sum(P[i] ** 2 for i in range(3)), h ** 2)
s1, s3 = sp.symbols('s1 s3')
sol = sp.solve([E_rel.subs({P[0] ** 2: s1, P[2] ** 2: s3}), H_rel.subs({P[0] ** 2: s1, P[2] ** 2: s3})], [s1, s3], dict=True)[0]
a21 = sp.simplify(sol[s1].subs(P[1], 0)); b21 = sp.simplify(-sp.diff(sol[s1], P[1], 2) / 2)
a23 = sp.simplify(sol[s3].subs(P[1], 0)); b23 = sp.simplify(-sp.diff(sol[s3], P[1], 2) / 2)
assert zero(sol[s1] - (a21 - b21 * P[1] ** 2)) and zero(sol[s3] - (a23 - b23 * P[1] ** 2))
# 86: Pi_1^2 = alpha21 - beta21 Pi_2^2, Pi_3^2 = alpha23 - beta23 Pi_2^2 (with the constants derived here)
check(86, True)
# 92: alpha21, alpha23 as written (h where the derivation has h^2)
a21_t = I1 * (h - 2 * E * I3) / (I1 - I3); a23_t = I3 * (h - 2 * E * I1) / (I3 - I1)
check(92, zero(a21_t - a21) and zero(a23_t - a23))
assert zero(a21_t.subs(h, h ** 2) - a21) and zero(a23_t.subs(h, h ** 2) - a23)   # h -> h^2 repairs it
# 97: beta21, beta23
check(97, zero(I1 * (I2 - I3) / (I2 * (I1 - I3)) - b21) and zero(I3 * (I2 - I1) / (I2 * (I3 - I1)) - b23))
# 102: Pidot_2 = (I1-I3)/(I1 I3) sqrt((a21 - b21 Pi2^2)(a23 - b23 Pi2^2)): Euler gives
# Pidot_2 = (I3-I1)/(I3 I1) Pi_3 Pi_1, and Pi_1 Pi_3 = -sqrt(...) on the branch the text takes
Pi13 = {P[0]: sp.sqrt(sol[s1]), P[2]: -sp.sqrt(sol[s3])}     # the branch Pi_1 Pi_3 < 0
check(102, zero((((I1 - I3) / (I1 * I3)) * sp.sqrt(sol[s1] * sol[s3]) - Pidot_free[1].subs(Pi13))
                .subs(P[1], sp.Rational(1, 5))))
# 107: u := sqrt(beta21/alpha21) Pi_2 (a definition)
u, kk, w, c, tt = sp.symbols('u k omega c t', positive=True)
omega_def = sp.sqrt(b21 * a23) * (I1 - I3) / (I1 * I3)
k2_def = a21 * b23 / (a23 * b21)
# 112: omega := sqrt(b21 a23)(I1-I3)/(I1 I3) = sqrt((I2-I3)(2E I1 - h)/(I1 I2 I3))
check(112, zero(omega_def ** 2 - (I2 - I3) * (2 * E * I1 - h) / (I1 * I2 * I3)))
assert zero(omega_def ** 2 - (I2 - I3) * (2 * E * I1 - h ** 2) / (I1 * I2 * I3))
# 117: k^2 := a21 b23/(a23 b21) = (I1-I2)(h-2E I3)/((I2-I3)(2E I1 - h))
check(117, zero(k2_def - (I1 - I2) * (h - 2 * E * I3) / ((I2 - I3) * (2 * E * I1 - h))))
assert zero(k2_def - (I1 - I2) * (h ** 2 - 2 * E * I3) / ((I2 - I3) * (2 * E * I1 - h ** 2)))
# 122: udot = omega sqrt((1-u^2)(1-k^2 u^2)), from 102 with Pi_2 = sqrt(a21/b21) u
Pi2_u = sp.sqrt(a21 / b21) * u
lhs = sp.sqrt(b21 / a21) * (I1 - I3) / (I1 * I3) * sp.sqrt((a21 - b21 * Pi2_u ** 2) * (a23 - b23 * Pi2_u ** 2))
check(122, zero((lhs ** 2 - omega_def ** 2 * (1 - u ** 2) * (1 - k2_def * u ** 2)).subs(u, sp.Rational(1, 3))))
# 127: separation of variables: d/du of the left integral is the integrand, of the right omega t + c gives omega
check(127, True)
# 132: sn^{-1}(u) = int_0^u ... defines the inverse of sn: not a claim
# 137: u(t) = sn(omega t + c): sn' = cn dn = sqrt((1-sn^2)(1-k^2 sn^2)) (checked numerically with mpmath)
import mpmath
mpmath.mp.dps = 30
m_ = mpmath.mpf('0.3') ** 2
x0 = mpmath.mpf('0.7')
dsn = mpmath.diff(lambda x: mpmath.ellipfun('sn', x, m=m_), x0)
sn0 = mpmath.ellipfun('sn', x0, m=m_)
check(137, abs(dsn - mpmath.sqrt((1 - sn0 ** 2) * (1 - m_ * sn0 ** 2))) < 1e-20)
# 142: Pi_2(t) = sqrt(I2(h - 2E I3)/(I2 - I3)) sn: Pi_2 = sqrt(a21/b21) u
check(142, zero(a21 / b21 - I2 * (h - 2 * E * I3) / (I2 - I3)))
assert zero(a21 / b21 - I2 * (h ** 2 - 2 * E * I3) / (I2 - I3))
# 148: Pi_1^2 = a21(1-u^2) = a21 cn^2, Pi_3^2 = a23(1 - k^2 u^2) = a23 dn^2
check(148, zero(sol[s1].subs(P[1], Pi2_u) - a21 * (1 - u ** 2))
      and zero(sol[s3].subs(P[1], Pi2_u) - a23 * (1 - k2_def * u ** 2)))
# 154: Pi_1(t) = sqrt(I1(h-2E I3)/(I1-I3)) cn, Pi_3(t) = sqrt(I3(2E I1 - h)/(I1-I3)) dn
check(154, zero(a21 - I1 * (h - 2 * E * I3) / (I1 - I3)) and zero(a23 - I3 * (2 * E * I1 - h) / (I1 - I3)))
assert zero(a21 - I1 * (h ** 2 - 2 * E * I3) / (I1 - I3)) and zero(a23 - I3 * (2 * E * I1 - h ** 2) / (I1 - I3))
# 160: K(k) = sn^{-1}(1) = int_0^1 = int_0^{pi/2} dpsi / sqrt(1 - k^2 sin^2) ~ (1 + k^2/4) pi/2
K1 = mpmath.quad(lambda v: 1 / mpmath.sqrt((1 - v ** 2) * (1 - m_ * v ** 2)), [0, 1])
K2 = mpmath.quad(lambda p: 1 / mpmath.sqrt(1 - m_ * mpmath.sin(p) ** 2), [0, mpmath.pi / 2])
kk_ = sp.symbols('kk')
series = sp.series(sp.elliptic_k(kk_ ** 2), kk_, 0, 4).removeO()
check(160, abs(K1 - mpmath.ellipk(m_)) < 1e-15 and abs(K2 - mpmath.ellipk(m_)) < 1e-20
      and sp.simplify(series - (1 + kk_ ** 2 / 4) * sp.pi / 2) == 0)
# 166: T = 4K/omega = 2pi/omega (1 + k^2/4 + ...) ~ 2pi sqrt(I1I2I3/((2EI1-h)(I2-I3))) (1 + (I1-I2)(h-2EI3)/(4(I2-I3)(2EI1-h)))
T_claim = 2 * sp.pi * sp.sqrt(I1 * I2 * I3 / ((2 * E * I1 - h) * (I2 - I3)))
T_true = 2 * sp.pi / omega_def
check(166, zero(T_claim ** 2 - T_true ** 2) and zero(k2_def - (I1 - I2) * (h - 2 * E * I3) / ((I2 - I3) * (2 * E * I1 - h))))
assert zero(T_claim.subs(h, h ** 2) ** 2 - T_true ** 2)
# 171: alpha(t) = arccos(Pi_3/h) = arccos(sqrt(I3(2E I1 - h)/(h^2 (I1-I3))) dn)
check(171, zero(a23 / h ** 2 - I3 * (2 * E * I1 - h) / (h ** 2 * (I1 - I3))))
# --- axi-symmetric body I1 = I2
ax = {I2: I1}
# 178: omega = sqrt((2E I1 - h)(I2 - I3)/(I1 I2 I3)), and Euler's equations give |omega| = (I1-I3)|Pi_3|/(I1 I3)
w_axi = (I1 - I3) / (I1 * I3) * sp.sqrt(a23.subs(ax))
check(178, zero(w_axi ** 2 - ((2 * E * I1 - h) * (I2 - I3) / (I1 * I2 * I3)).subs(ax)))
assert zero(w_axi ** 2 - ((2 * E * I1 - h ** 2) * (I2 - I3) / (I1 * I2 * I3)).subs(ax))
# 183: Pi_1, Pi_2 amplitudes sqrt(a21), Pi_3 = sqrt(a23) constant (amplitude = sqrt(a21) when I1 = I2)
check(183, zero((a21 - I1 * (h - 2 * E * I3) / (I1 - I3)).subs(ax)) and zero((a23 - I3 * (2 * E * I1 - h) / (I1 - I3)).subs(ax)))
# 190: T = 2 pi sqrt(I1 I2 I3 / ((2E I1 - h)(I2 - I3))) = 2 pi / omega
check(190, zero((T_claim ** 2 - (2 * sp.pi / w_axi) ** 2).subs(ax)))
# 195: alpha = arccos(Pi_3 / h) = arccos(sqrt(I3(2E I1 - h)/(h^2(I1-I3))))
check(195, zero((a23 / h ** 2 - I3 * (2 * E * I1 - h) / (h ** 2 * (I1 - I3))).subs(ax)))
# --- heavy top: torque of gravity about the pivot, in the body frame, centre of mass at l e3,
# weight -m g z (z the upward vertical = Upsilon, e3 the symmetry axis = [0 0 1])
R = sp.Matrix(3, 3, sp.symbols('r0:9', real=True))
Gam = R.T * ups
torque = (l * ups).cross(-m * g * Gam)
# 204: I Omegadot = I Omega x Omega + m g l (R^T Upsilon) x Upsilon
check(204, zero(torque - m * g * l * Gam.cross(ups)))
# 211: the frames a', f, b (definitions): not a claim
# 216: R = R3(phi) R1(theta) R3(psi): b = a R3 R1 R3 by composing the three frame relations
check(216, True)
# 223: Gammadot = Gamma x Omega (Gamma = R^T Upsilon, Rdot = R hat(Omega)); I Omegadot = I Omega x Omega + m g l Gamma x Upsilon
Gdot = -hat(Om) * Ga          # d/dt (R^T U) = Rdot^T U = -hat(Omega) R^T U
check(223, zero(Gdot - Ga.cross(Om)) and zero(m * g * l * Ga.cross(ups) - torque.subs(dict(zip(Gam, Ga)))))
# 230: conserved: energy 1/2 Omega.I Omega + m g l Gamma_3, Pi.Gamma, |Gamma|^2 (time derivatives vanish)
Omdot = Id.inv() * ((Id * Om).cross(Om) + m * g * l * Ga.cross(ups))
dE = (Om.T * Id * Omdot)[0] + m * g * l * (Gdot.T * ups)[0]
dPG = ((Id * Omdot).T * Ga)[0] + ((Id * Om).T * Gdot)[0]
dGG = 2 * (Ga.T * Gdot)[0]
check(230, zero(dE) and zero(dPG) and zero(dGG) and zero((Ga.T * ups)[0] - G[2]))

# --- 3-1-3 Euler angles (active rotations, b = e R)
t = sp.symbols('t')
q = [sp.Function(f'theta_{i}')(t) for i in (1, 2, 3)]
def R1(a):
    return sp.Matrix([[1, 0, 0], [0, sp.cos(a), -sp.sin(a)], [0, sp.sin(a), sp.cos(a)]])
def R3(a):
    return sp.Matrix([[sp.cos(a), -sp.sin(a), 0], [sp.sin(a), sp.cos(a), 0], [0, 0, 1]])
Rq = R3(q[0]) * R1(q[1]) * R3(q[2])
c1, c2, c3 = [sp.cos(x) for x in q]; sn1, sn2, sn3 = [sp.sin(x) for x in q]
# 242: R = R_i R_j R_k defines the i-j-k angles: not a claim
# 247: the 3-1-3 matrix as written
R_text = sp.Matrix([[c1 * c3 - c2 * sn1 * sn3, c2 * c3 * sn1 + c1 * sn3, sn1 * sn2],
                    [-c3 * sn1 - c1 * c2 * sn3, c1 * c2 * c3 - sn1 * sn3, c1 * sn2],
                    [sn2 * sn3, -c3 * sn2, c2]])
def zq(M):
    return sp.simplify(M) == sp.zeros(*M.shape)
check(247, zq(R_text - Rq))
# what the written matrix is: the transpose of R_3(theta_3) R_1(theta_2) R_3(theta_1) (the angles in reverse order)
R_rev = R3(q[2]) * R1(q[1]) * R3(q[0])
assert not zq(R_text - Rq.T) and zq(R_text - R_rev.T)
Omhat = sp.simplify(Rq.T * Rq.diff(t))
Om_q = sp.Matrix([Omhat[2, 1], Omhat[0, 2], Omhat[1, 0]])
d = [x.diff(t) for x in q]; dd = [x.diff(t, 2) for x in q]
# 257: body angular velocity
Om_text = sp.Matrix([d[0] * sn2 * sn3 + d[1] * c3, d[0] * sn2 * c3 - d[1] * sn3, d[0] * c2 + d[2]])
check(257, zq(Om_text - Om_q))
# 265: spatial angular velocity omega = R Omega
om_text = sp.Matrix([d[2] * sn2 * sn1 + d[1] * c1, -d[2] * sn2 * c1 + d[1] * sn1, d[2] * c2 + d[0]])
check(265, zq(om_text - Rq * Om_q))
# 274: body angular acceleration
Omd_text = sp.Matrix([
    dd[0] * sn2 * sn3 + d[0] * d[1] * c2 * sn3 + d[0] * d[2] * sn2 * c3 + dd[1] * c3 - d[1] * d[2] * sn3,
    dd[0] * sn2 * c3 + d[0] * d[1] * c2 * c3 - d[0] * d[2] * sn2 * sn3 - dd[1] * sn3 - d[1] * d[2] * c3,
    dd[0] * c2 - d[0] * d[1] * sn2 + dd[2]])
check(274, zq(Omd_text - Om_q.diff(t)))
# 284: Pi = I Omega componentwise
check(284, zq(Id * Om_text - Id * Om_q))
# 294: I Omegadot componentwise
check(294, zq(Id * Omd_text - Id * Om_q.diff(t)))
# 305: Euler's equations I Omegadot = I Omega x Omega + T^e in the angles, moved as written
T1, T2, T3 = sp.symbols('T_1^e T_2^e T_3^e')
Te = sp.Matrix([T1, T2, T3])
euler = Id * Om_q.diff(t) - ((Id * Om_q).cross(Om_q) + Te)
rows_text = sp.Matrix([
    I1 * sn2 * sn3 * dd[0] + I1 * c3 * dd[1] - (-I1 * (d[0] * d[1] * c2 * sn3 + d[0] * d[2] * sn2 * c3 - d[1] * d[2] * sn3)
        + (I2 - I3) * (d[0] * sn2 * c3 - d[1] * sn3) * (d[0] * c2 + d[2]) + T1),
    I2 * sn2 * c3 * dd[0] - I2 * sn3 * dd[1] - (-I2 * (d[0] * d[1] * c2 * c3 - d[0] * d[2] * sn2 * sn3 - d[1] * d[2] * c3)
        + (I3 - I1) * (d[0] * c2 + d[2]) * (d[0] * sn2 * sn3 + d[1] * c3) + T2),
    I3 * c2 * dd[0] + I3 * dd[2] - (I3 * d[0] * d[1] * sn2 + (I1 - I2) * (d[0] * sn2 * sn3 + d[1] * c3)
        * (d[0] * sn2 * c3 - d[1] * sn3) + T3)])
check(305, zq(rows_text - euler))

# negative controls: the tests above must be able to fail
assert not zero(KE - (Pi_of_W.T * Om)[0])
assert not zq(Om_text - R_rev.T * Om_q)

LINES = [27, 44, 50, 61, 68, 75, 86, 92, 97, 102, 107, 112, 117, 122, 127, 132, 137, 142, 148, 154, 160,
         166, 171, 178, 183, 190, 195, 204, 211, 216, 223, 230, 242, 247, 257, 265, 274, 284, 294, 305]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
