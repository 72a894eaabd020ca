"""Independent SymPy truth table for principia-celledoni-free-body-elliptic-solution.tex.

The text's own setting: a free rigid body in its principal axes, moments I_1 <= I_2 <= I_3, body
angular momentum m = (m_1, m_2, m_3) with angular velocity omega_i = m_i / I_i, G = ||m|| and the
kinetic energy T with 2T = sum m_i^2 / I_i. The note's names: I_jh = I_j - I_h,
Delta_j = G^2 - 2 T I_j, B_jh = sqrt(+-I_j Delta_h / I_jh) (+ when h = 1 and j >= h or h = 3 and
j < h), k = sqrt(-Delta_1 I_32 / (Delta_3 I_21)), lambda_1 = sqrt(Delta_1 I_32 / (I_1 I_2 I_3)),
lambda_3 = sqrt(Delta_3 I_12 / (I_1 I_2 I_3)), lambda_2 = sqrt(-Delta_1 Delta_3 / (I_1 I_3)) / G.
Jacobi functions sn, cn, dn(u, k) of modulus k (mpmath's parameter m = k^2), am(u, k) the amplitude
and F(phi, k) the incomplete integral of the first kind.

Euler's equation is derived here from dL/dt = 0 in space (dm/dt + omega x m = 0 in the body), never
from the text's displays; each solution is checked against it numerically, at points of each case
(case (i): Delta_2 < 0, case (ii): Delta_2 > 0, case (iii): Delta_2 = 0), with the square roots
taken as complex principal roots so that a radicand of the wrong sign shows. SymPy and its mpmath
only.
"""
import sys
import mpmath as mp
import sympy as sp

import truth_table

mp.mp.dps = 30
CHECKS = {}


def check(key, ok):
    CHECKS[key] = CHECKS.get(key, True) and bool(ok)


def close(a, b, tol=mp.mpf('1e-18')):
    return abs(mp.mpc(a) - mp.mpc(b)) <= tol * (1 + abs(mp.mpc(b)))


# ---- Euler's equation, derived: dm/dt = -omega x m = m x omega, omega_i = m_i / I_i
I1, I2, I3, G, T = sp.symbols('I_1 I_2 I_3 G T', positive=True)
t = sp.symbols('t', real=True)
ms = sp.symbols('m_1:4', real=True)
mvec = sp.Matrix(ms)
Id = sp.diag(I1, I2, I3)
omega = Id.inv() * mvec
mdot = -omega.cross(mvec)

# 35: mdot = m x (m_1/I_1, m_2/I_2, m_3/I_3)
check(35, sp.simplify(mvec.cross(sp.Matrix([ms[0] / I1, ms[1] / I2, ms[2] / I3])) - mdot) == sp.zeros(3, 1))
# 46: the three components as written
rows46 = sp.Matrix([ms[1] * ms[2] * (1 / I3 - 1 / I2), ms[2] * ms[0] * (1 / I1 - 1 / I3),
                    ms[0] * ms[1] * (1 / I2 - 1 / I1)])
check(46, sp.simplify(rows46 - mdot) == sp.zeros(3, 1))
# negative control: the other cyclic order fails
assert sp.simplify(-rows46 - mdot) != sp.zeros(3, 1)

# ---- the note's definitions, as functions of (I, G, T)
def names(i1, i2, i3, g, tt):
    I = {1: i1, 2: i2, 3: i3}
    Ijh = lambda j, h: I[j] - I[h]                                   # noqa: E731
    D = {j: g ** 2 - 2 * tt * I[j] for j in (1, 2, 3)}
    def B(j, h):
        plus = (h == 1 and j >= h) or (h == 3 and j < h)
        return mp.sqrt((1 if plus else -1) * I[j] * D[h] / Ijh(j, h))
    k = mp.sqrt(-D[1] * Ijh(3, 2) / (D[3] * Ijh(2, 1)))
    l1 = mp.sqrt(D[1] * Ijh(3, 2) / (i1 * i2 * i3))
    l3 = mp.sqrt(D[3] * Ijh(1, 2) / (i1 * i2 * i3))
    return I, Ijh, D, B, k, l1, l3


def state(i1, i2, i3, m0):
    g = mp.sqrt(sum(x ** 2 for x in m0))
    tt = (m0[0] ** 2 / i1 + m0[1] ** 2 / i2 + m0[2] ** 2 / i3) / 2
    return g, tt


def euler_rhs(m, i1, i2, i3):
    return [m[1] * m[2] * (1 / i3 - 1 / i2), m[2] * m[0] * (1 / i1 - 1 / i3), m[0] * m[1] * (1 / i2 - 1 / i1)]


def solves(mt, i1, i2, i3, times=(mp.mpf('0.1'), mp.mpf('0.7'), mp.mpf('1.9'))):
    """m_t(t) satisfies Euler's equation (derived above) at the given times."""
    for tv in times:
        m = mt(tv)
        dm = [mp.diff(lambda s, c=c: mt(s)[c], tv) for c in range(3)]
        if not all(close(a, b, mp.mpf('1e-12')) for a, b in zip(dm, euler_rhs(m, i1, i2, i3))):
            return False
    return True


def sn(u, k):
    return mp.ellipfun('sn', u, m=k ** 2)


def cn(u, k):
    return mp.ellipfun('cn', u, m=k ** 2)


def dn(u, k):
    return mp.ellipfun('dn', u, m=k ** 2)


def am(u, k):
    return mp.atan2(sn(u, k), cn(u, k))      # continuous for |am| < pi, enough for the phases used


i1, i2, i3 = mp.mpf(1), mp.mpf(2), mp.mpf(3)

# ---- 64: B_31^2 + B_13^2 = (Delta_1 I_3 - Delta_3 I_1) / I_31 = G^2 (symbolic, the signs of B as defined)
D1s, D3s = G ** 2 - 2 * T * I1, G ** 2 - 2 * T * I3
B31sq, B13sq = I3 * D1s / (I3 - I1), I1 * D3s / (I1 - I3)
check(64, sp.simplify(B31sq + B13sq - (D1s * I3 - D3s * I1) / (I3 - I1)) == 0
      and sp.simplify((D1s * I3 - D3s * I1) / (I3 - I1) - G ** 2) == 0)

# ---- case (i): Delta_2 < 0 (m near the m_1 axis)
for m0 in ([mp.mpf('1.0'), mp.mpf('0.3'), mp.mpf('0.2')], [mp.mpf('-0.9'), mp.mpf('0.4'), mp.mpf('-0.35')]):
    g, tt = state(i1, i2, i3, m0)
    I, Ijh, D, B, k, l1, l3 = names(i1, i2, i3, g, tt)
    assert D[2] < 0 and D[1] >= 0 and D[3] <= 0 and k < 1
    for sg in (1, -1):
        lam = -sg * l3                       # the note's value, derived below from its own equations
        nu = mp.mpf('0.3')
        mt = lambda s: [sg * B(1, 3) * dn(lam * s - nu, k), -B(2, 1) * sn(lam * s - nu, k),   # noqa: E731
                        B(3, 1) * cn(lam * s - nu, k)]
        check(71, solves(mt, i1, i2, i3))
        # negative control: the preprint's sign of lambda does not solve Euler's equation
        wrong = lambda s: [sg * B(1, 3) * dn(-lam * s - nu, k), -B(2, 1) * sn(-lam * s - nu, k),  # noqa: E731
                           B(3, 1) * cn(-lam * s - nu, k)]
        assert not solves(wrong, i1, i2, i3)
        # 80: the three relations, with this lambda
        check(80, close(-sg * lam * k ** 2 * B(1, 3), -B(2, 1) * B(3, 1) * (1 / i3 - 1 / i2))
              and close(-lam * B(2, 1), sg * B(1, 3) * B(3, 1) * (1 / i1 - 1 / i3))
              and close(-lam * B(3, 1), -sg * B(1, 3) * B(2, 1) * (1 / i2 - 1 / i1)))
        # 89: the chain for lambda, link by link, as written
        links = [lam,
                 sg * B(1, 3) * B(2, 1) / B(3, 1) * (i1 - i2) / (i1 * i2),
                 sg * mp.sqrt(i1 * D[3] / Ijh(1, 3) * i2 * D[1] / Ijh(2, 1) * Ijh(3, 1) / (i3 * D[1])) * (i1 - i2) / (i1 * i2),
                 sg * mp.sqrt(D[3] / (Ijh(2, 1) * i1 * i2 * i3)) * (i1 - i2),
                 -sg * mp.sqrt(D[3] * Ijh(2, 1) / (i1 * i2 * i3)),
                 -sg * l3]
        check(89, all(close(a, links[0]) for a in links))
        # the correction (the radicands -Delta_3) makes every link agree
        fixed = links[:3] + [sg * mp.sqrt(-D[3] / (Ijh(2, 1) * i1 * i2 * i3)) * (i1 - i2),
                             -sg * mp.sqrt(-D[3] * Ijh(2, 1) / (i1 * i2 * i3)), -sg * l3]
        assert all(close(a, fixed[0]) for a in fixed)
        # phases, at t = 0 (177, 186, 190, 194)
        m00 = mt(0)
        check(177, all(close(a, b) for a, b in zip(m00, [sg * B(1, 3) * dn(-nu, k), -B(2, 1) * sn(-nu, k),
                                                         B(3, 1) * cn(-nu, k)])))
        check(186, close(m00[1] / m00[2], B(2, 1) / B(3, 1) * mp.tan(am(nu, k))))
        check(190, close(mp.atan(m00[1] / m00[2] * B(3, 1) / B(2, 1)), am(nu, k)))
        check(194, close(nu, mp.ellipf(mp.atan(m00[1] / m00[2] * B(3, 1) / B(2, 1)), k ** 2)))
    # 256, 260: m_c = 1 - k^2 in case (i)
    check(256, close(1 - k ** 2, 1 + D[1] * Ijh(3, 2) / (D[3] * Ijh(2, 1))))
    chain = [1 - k ** 2,
             (D[3] * Ijh(2, 1) + D[1] * Ijh(3, 2)) / (D[3] * Ijh(2, 1)),
             ((g ** 2 - 2 * tt * i3) * (i2 - i1) + (g ** 2 - 2 * tt * i1) * (i3 - i2)) / (D[3] * Ijh(2, 1)),
             (g ** 2 * (i3 - i1) + 2 * tt * i2 * (i1 - i3)) / (D[3] * Ijh(2, 1)),
             D[2] * Ijh(3, 1) / (D[3] * Ijh(2, 1))]
    check(260, all(close(a, chain[0]) for a in chain))

# ---- case (ii): Delta_2 > 0 (m near the m_3 axis); modulus 1/k
for m0 in ([mp.mpf('0.2'), mp.mpf('0.3'), mp.mpf('1.0')], [mp.mpf('-0.3'), mp.mpf('-0.4'), mp.mpf('-0.9')]):
    g, tt = state(i1, i2, i3, m0)
    I, Ijh, D, B, k, l1, l3 = names(i1, i2, i3, g, tt)
    assert D[2] > 0 and k > 1
    for sg in (1, -1):
        lam = -sg * l1
        nu = mp.mpf('-0.4')
        ki = 1 / k
        mt = lambda s: [B(1, 3) * cn(lam * s - nu, ki), -B(2, 3) * sn(lam * s - nu, ki),          # noqa: E731
                        sg * B(3, 1) * dn(lam * s - nu, ki)]
        check(100, solves(mt, i1, i2, i3))
        check(109, close(-lam * B(1, 3), -sg * B(2, 3) * B(3, 1) * (1 / i3 - 1 / i2))
              and close(-lam * B(2, 3), sg * B(1, 3) * B(3, 1) * (1 / i1 - 1 / i3))
              and close(-sg * lam * k ** -2 * B(3, 1), -B(1, 3) * B(2, 3) * (1 / i2 - 1 / i1)))
        links = [lam,
                 sg * B(2, 3) * B(3, 1) / B(1, 3) * (i2 - i3) / (i2 * i3),
                 sg * mp.sqrt(i2 * D[3] / Ijh(2, 3) * i3 * D[1] / Ijh(3, 1) * Ijh(1, 3) / (i1 * D[3])) * (i2 - i3) / (i2 * i3),
                 sg * mp.sqrt(D[1] / (Ijh(2, 3) * i1 * i2 * i3)) * (i2 - i3),
                 -sg * mp.sqrt(D[1] * Ijh(2, 3) / (i1 * i2 * i3)),
                 -sg * l1]
        check(118, all(close(a, links[0]) for a in links))
        fixed = links[:3] + [sg * mp.sqrt(-D[1] / (Ijh(2, 3) * i1 * i2 * i3)) * (i2 - i3),
                             -sg * mp.sqrt(-D[1] * Ijh(2, 3) / (i1 * i2 * i3)), -sg * l1]
        assert all(close(a, fixed[0]) for a in fixed)
        m00 = mt(0)
        check(199, all(close(a, b) for a, b in zip(m00, [B(1, 3) * cn(-nu, ki), -B(2, 3) * sn(-nu, ki),
                                                         sg * B(3, 1) * dn(-nu, ki)])))
        check(208, close(m00[1] / m00[0], B(2, 3) / B(1, 3) * mp.tan(am(nu, ki))))
        check(212, close(nu, mp.ellipf(mp.atan(m00[1] / m00[0] * B(1, 3) / B(2, 3)), ki ** 2)))
    check(267, close(1 - k ** -2, 1 + D[3] * Ijh(2, 1) / (D[1] * Ijh(3, 2)))
          and close(1 - k ** -2, (D[1] * Ijh(3, 2) + D[3] * Ijh(2, 1)) / (D[1] * Ijh(3, 2)))
          and close(1 - k ** -2, D[2] * Ijh(3, 1) / (D[1] * Ijh(3, 2))))

# ---- case (iii): the separatrix, Delta_2 = 0 (2 T I_2 = G^2)
for (a1, a3) in ((mp.mpf('0.7'), mp.mpf('0.5')), (mp.mpf('0.7'), mp.mpf('-0.5'))):
    # choose m_1, m_3, then m_2 so that Delta_2 = m_1^2 I_12/I_1 + m_3^2 I_32/I_3 = 0 holds with any m_2
    m1v = a1
    m3v = a3 * mp.sqrt(-(m1v ** 2 * (i1 - i2) / i1) / ((i3 - i2) / i3)) / abs(a3)
    m0 = [m1v, mp.mpf('0.2'), m3v]
    g, tt = state(i1, i2, i3, m0)
    I, Ijh, D, B, k, l1, l3 = names(i1, i2, i3, g, tt)
    assert abs(D[2]) < mp.mpf('1e-25')
    l2 = mp.sqrt(-D[1] * D[3] / (i1 * i3)) / g
    check(168, close(l1, l2) and close(l3, l2))       # the common value the text names
    for s1 in (1, -1):
        for s2 in (1, -1):
            lam = s1 * s2 * l2
            nu = mp.mpf('0.25')
            mt = lambda s: [s1 * B(1, 3) * mp.sech(lam * s - nu), g * mp.tanh(lam * s - nu),     # noqa: E731
                            s2 * B(3, 1) * mp.sech(lam * s - nu)]
            check(129, solves(mt, i1, i2, i3))
            check(138, close(-s1 * lam * B(1, 3), s2 * g * B(3, 1) * (1 / i3 - 1 / i2))
                  and close(lam * g, s1 * s2 * B(1, 3) * B(3, 1) * (1 / i1 - 1 / i3))
                  and close(-s2 * lam * B(3, 1), s1 * g * B(1, 3) * (1 / i2 - 1 / i1)))
            links = [lam, s1 * s2 * B(1, 3) * B(3, 1) / g * (i3 - i1) / (i1 * i3),
                     s1 * s2 / g * mp.sqrt(i1 * D[3] / Ijh(1, 3) * i3 * D[1] / Ijh(3, 1)) * (i3 - i1) / (i1 * i3),
                     s1 * s2 / g * mp.sqrt(-D[1] * D[3] / (i1 * i3))]
            check(147, all(close(a, links[0]) for a in links))
            links = [lam, -s1 * s2 * g * B(3, 1) / B(1, 3) * (i2 - i3) / (i2 * i3),
                     -s1 * s2 * g * mp.sqrt(i3 * D[1] / Ijh(3, 1) * Ijh(1, 3) / (i1 * D[3])) * (i2 - i3) / (i2 * i3),
                     -s1 * s2 * g * mp.sqrt(-D[1] / (i1 * i3 * D[3])) * (i2 - i3) / i2,
                     s1 * s2 * g * mp.sqrt(-D[1] / (i1 * i3 * D[3])) * (i3 / i2 - 1)]
            check(153, all(close(a, links[0]) for a in links))
            links = [lam, s1 * s2 * g * mp.sqrt(-D[1] / (i1 * i3 * D[3])) * (2 * tt * i3 / g ** 2 - 1),
                     s1 * s2 / g * mp.sqrt(-D[1] * D[3] / (i1 * i3))]
            check(160, all(close(a, links[0]) for a in links))
            check(168, close(lam, s1 * s2 * l2))
            m00 = mt(0)
            check(217, all(close(a, b) for a, b in zip(m00, [s1 * B(1, 3) * mp.sech(-nu), g * mp.tanh(-nu),
                                                             s2 * B(3, 1) * mp.sech(-nu)])))
            check(226, close(nu, -mp.atanh(m00[1] / g)))

# ---- 234, 241, 246: G^2 and 2T in m (the kinetic energy 1/2 omega . I omega), Delta_j in m
Gsq = sum(x ** 2 for x in ms)
twoT = (omega.T * Id * omega)[0]
check(234, sp.simplify(twoT - (ms[0] ** 2 / I1 + ms[1] ** 2 / I2 + ms[2] ** 2 / I3)) == 0
      and sp.simplify(Gsq - (mvec.T * mvec)[0]) == 0)
D = {j: Gsq - twoT * Ij for j, Ij in ((1, I1), (2, I2), (3, I3))}
check(241, sp.simplify(D[2] - (ms[0] ** 2 * (1 - I2 / I1) + ms[2] ** 2 * (1 - I2 / I3))) == 0
      and sp.simplify(D[2] - (ms[0] ** 2 * (I1 - I2) / I1 + ms[2] ** 2 * (I3 - I2) / I3)) == 0)
check(246, sp.simplify(D[1] - (ms[1] ** 2 * (I2 - I1) / I2 + ms[2] ** 2 * (I3 - I1) / I3)) == 0
      and sp.simplify(D[3] - (ms[0] ** 2 * (I1 - I3) / I1 + ms[1] ** 2 * (I2 - I3) / I2)) == 0)

# negative controls: the checks above can fail
assert not sp.simplify(D[2] - (ms[0] ** 2 * (I2 - I1) / I1 + ms[2] ** 2 * (I3 - I2) / I3)) == 0

LINES = [19, 26, 35, 46, 59, 64, 71, 80, 89, 100, 109, 118, 129, 138, 147, 153, 160, 164, 168, 177, 186, 190,
         194, 199, 208, 212, 217, 226, 234, 241, 246, 256, 260, 267]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
