"""Jacobi elliptic functions and the elliptic integrals the exact rigid-body solutions need,
accurate for every parameter 0 <= m <= 1, including m = 1 and m within 1e-17 of it.

Notation (DLMF chapters 19 and 22): parameter m = k^2, complementary parameter m1 = 1 - m = k'^2,
quarter period K = K(m) = int_0^{pi/2} dtheta / sqrt(1 - m sin^2 theta), amplitude am(u) with
sn u = sin am u, cn u = cos am u, dn u = sqrt(1 - m sn^2 u); periods 4K (sn, cn) and 2K (dn),
am(u + 2K) = am(u) + pi. At m = 1 (K infinite): sn = tanh, cn = dn = sech, am = gd.

Every function takes the complementary parameter m1 as the primary input, because near the
separatrix of a spinning body the physics lives in m1 (m = 1 - 1e-17 is not a double, m1 is).

How ``ellipj_accurate`` stays accurate where ``scipy.special.ellipj`` does not:

1. Reduction by quarter periods, u = j K + v with |v| <= K/2, where K is known to ~100 bits
   (mpmath's AGM, once per m1) and stored as a three-term Cody-Waite split, so that v is exact to a few
   ulps of v even for u ~ 1e7 K.
2. On |v| <= K/2 the descending Landen (AGM) recurrence, with each backward step written as
   phi_{n-1} = (phi_n + atan2(c_n sin phi_n, sqrt(b_n^2 + c_n^2 cos^2 phi_n))) / 2
   instead of arcsin(c_n/a_n sin phi_n); the arcsin form amplifies rounding by
   1/sqrt(1 - x^2), which is what ruins the textbook algorithm as m -> 1.
   dn is taken as sqrt(cn^2 + m1 sn^2) (a sum of positives) instead of cos phi_0 / cos(phi_1 - phi_0).
3. The quarter-period shift formulas (DLMF 22.4.3): sn(v + K) = cn v / dn v,
   cn(v + K) = -k' sn v / dn v, dn(v + K) = k' / dn v; with v small these give cn and dn near
   their small extremes with relative, not merely absolute, accuracy.

The integrals are Carlson forms (scipy.special.elliprf, elliprj) fed with cn^2, dn^2 and
cn^2 + (1 - n) sn^2 instead of 1 - m sn^2 and 1 - n sn^2, for the same reason: F(am u) inverts
the Jacobi functions, and ``sn2_rational_integral`` integrates (A + B sn^2)/(C + D sn^2), the
form every angle rate of the exact solutions takes (an elliptic integral of the third kind).
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import mpmath
import numpy as np
from scipy import special

__all__ = [
    "ellipj_accurate",
    "ellipk_m1",
    "elliptic_f_from_jacobi",
    "JacobiArgument",
    "reduce_argument",
    "sn2_rational_integral",
]

_EPS = float(np.finfo(float).eps)


@dataclass(frozen=True)
class QuarterPeriod:
    """K(m) for one m1, with what the reduction and the Landen recurrence need.

    ``parts`` is a Cody-Waite split K = parts[0] + parts[1] + parts[2]: the first two carry
    26 significant bits each, so j * parts[0] and j * parts[1] are exact for |j| < 2^26.
    ``a``, ``b``, ``c`` are the AGM sequences a_0 = 1, b_0 = k', c_0 = k.
    """

    m1: float
    K: float
    parts: tuple[float, float, float]
    kp: float
    a: tuple[float, ...]
    b: tuple[float, ...]
    c: tuple[float, ...]


def _check_m1(m, m1) -> float:
    """The complementary parameter to use, from (m, m1); m1 wins when given."""
    if m1 is None:
        m = float(m)
        if not 0.0 <= m <= 1.0:
            raise ValueError(f"parameter m = {m!r} outside [0, 1]")
        return 1.0 - m  # exact for m >= 1/2 (Sterbenz)
    m1 = float(m1)
    if not 0.0 <= m1 <= 1.0:
        raise ValueError(f"complementary parameter m1 = {m1!r} outside [0, 1]")
    if m is not None and abs(float(m) - (1.0 - m1)) > 4 * _EPS:
        raise ValueError(f"m = {m!r} and m1 = {m1!r} disagree (m + m1 must be 1)")
    return m1


def _split26(x: mpmath.mpf) -> float:
    """x truncated to 26 significant bits, as an exact double."""
    if x == 0:
        return 0.0
    e = int(mpmath.floor(mpmath.log(abs(x), 2)))
    scale = mpmath.mpf(2) ** (25 - e)
    return float(mpmath.floor(x * scale) / scale)


@functools.lru_cache(maxsize=512)
def _quarter_period(m1: float) -> QuarterPeriod:
    if m1 == 0.0:
        return QuarterPeriod(0.0, math.inf, (math.inf, 0.0, 0.0), 0.0, (1.0,), (0.0,), (1.0,))
    with mpmath.workdps(45):
        # K = pi / (2 AGM(1, k')): no 1 - m1 to round away when m1 < 1e-45.
        K = mpmath.pi / (2 * mpmath.agm(1, mpmath.sqrt(mpmath.mpf(m1))))
        k1 = _split26(K)
        k2 = _split26(K - k1)
        k3 = float(K - k1 - k2)
        Kf = float(K)
    a, b, c = [1.0], [math.sqrt(m1)], [math.sqrt(1.0 - m1)]
    # c_{n+1} = c_n^2 / (4 a_{n+1}) is the cancellation-free form of (a_n - b_n) / 2.
    while c[-1] > 0.25 * _EPS * a[-1]:
        an, bn = a[-1], b[-1]
        a.append(0.5 * (an + bn))
        b.append(math.sqrt(an * bn))
        c.append(c[-1] * c[-1] / (4.0 * a[-1]))
    return QuarterPeriod(m1, Kf, (k1, k2, k3), math.sqrt(m1), tuple(a), tuple(b), tuple(c))


def ellipk_m1(m1: float) -> float:
    """Complete elliptic integral of the first kind K(m) as a function of m1 = 1 - m
    (correctly rounded; inf at m1 = 0)."""
    return _quarter_period(_check_m1(None, m1)).K


def _landen(v: np.ndarray, qp: QuarterPeriod):
    """sn, cn, dn, am at |v| <= K/2 (m1 > 0) by the descending Landen / AGM recurrence."""
    n = len(qp.a) - 1
    phi = (2.0**n * qp.a[n]) * v
    for i in range(n, 0, -1):
        s, c = np.sin(phi), np.cos(phi)
        ci = qp.c[i]
        phi = 0.5 * (phi + np.arctan2(ci * s, np.sqrt(qp.b[i] ** 2 + (ci * c) ** 2)))
    sn, cn = np.sin(phi), np.cos(phi)
    dn = np.sqrt(cn * cn + qp.m1 * sn * sn)
    return sn, cn, dn, phi


@dataclass(frozen=True)
class JacobiArgument:
    """An argument u = j K + v reduced by quarter periods, with sn, cn, dn, am at v.

    For m1 = 0 there is no period: j = 0 and v = u (any size).
    """

    qp: QuarterPeriod
    j: np.ndarray  # integer-valued float array
    v: np.ndarray
    sv: np.ndarray
    cv: np.ndarray
    dv: np.ndarray
    av: np.ndarray

    def shifted(self, dj: int) -> "JacobiArgument":
        """The same point written as (u - dj K) + dj K, i.e. the argument u - dj K."""
        return JacobiArgument(self.qp, self.j - dj, self.v, self.sv, self.cv, self.dv, self.av)

    def values(self):
        """(sn, cn, dn, am) at u = j K + v."""
        j, s, c, d = self.j, self.sv, self.cv, self.dv
        kp = self.qp.kp
        if self.qp.m1 == 0.0:
            return s.copy(), c.copy(), d.copy(), self.av.copy()
        r = np.mod(j, 4.0)
        with np.errstate(divide="ignore", invalid="ignore"):
            cd, sd = c / d, s / d
        sn = np.select([r == 0, r == 1, r == 2], [s, cd, -s], -cd)
        cn = np.select([r == 0, r == 1, r == 2], [c, -kp * sd, -c], kp * sd)
        dn = np.where(np.mod(j, 2.0) == 0, d, kp / d)
        odd = np.mod(j, 2.0) == 1
        half = np.floor(j / 2.0)
        am = np.where(odd, half * np.pi + 0.5 * np.pi + np.arctan2(kp * s, c), half * np.pi + self.av)
        return sn, cn, dn, am


def reduce_argument(u, m1: float) -> JacobiArgument:
    """Reduce u (array) by quarter periods of the parameter m = 1 - m1 and evaluate at the
    remainder. The building block of ``ellipj_accurate`` and of the integrals below."""
    m1 = _check_m1(None, m1)
    qp = _quarter_period(m1)
    u = np.asarray(u, dtype=float)
    if m1 == 0.0:
        # m = 1: sn = tanh, cn = dn = sech, am = gd; sech written without overflowing cosh.
        e = np.exp(-np.abs(u))
        sech = 2.0 * e / (1.0 + e * e)
        th = np.tanh(u)
        return JacobiArgument(qp, np.zeros_like(u), u, th, sech, sech, np.arctan2(th, sech))
    k1, k2, k3 = qp.parts
    j = np.rint(u / qp.K)
    v = ((u - j * k1) - j * k2) - j * k3
    s, c, d, a = _landen(v, qp)
    return JacobiArgument(qp, j, v, s, c, d, a)


def ellipj_accurate(u, m, m1=None):
    """Jacobi elliptic functions sn, cn, dn and the amplitude am of (u | m), vectorised over u.

    Parameters: u, any real array (large values are reduced modulo the quarter period K using a
    ~100-bit K); m, the parameter in [0, 1]; m1, optionally the complementary parameter 1 - m
    given directly, which then takes precedence (so m1 = 1e-17 is usable although
    1 - 1e-17 == 1.0 in double precision; pass m=None or a consistent m).

    Returns (sn, cn, dn, am) like ``scipy.special.ellipj``; am is continuous and unbounded
    (am(u + 2K) = am(u) + pi). Absolute error ~1e-15 for |u| <~ 1e3 K; the arguments themselves
    carry the rounding of u (|u| * 1.1e-16), which no algorithm can undo.
    """
    m1 = _check_m1(m, m1)
    return reduce_argument(u, m1).values()


def elliptic_f_from_jacobi(sn, cn, dn, m1: float):
    """The incomplete integral F(phi | m) at the amplitude with sin phi = sn, cos phi = cn,
    i.e. the argument u in (-2K, 2K] with (sn u, cn u, dn u) = (sn, cn, dn).

    F = sn R_F(cn^2, dn^2, 1) for cn >= 0 (DLMF 19.25.5), and 2K sign(sn) - sn R_F(cn^2, dn^2, 1)
    for cn < 0. Taking dn^2 = cn^2 + m1 sn^2 instead of 1 - m sn^2 keeps F accurate near K.
    """
    sn, cn, dn = (np.asarray(x, dtype=float) for x in (sn, cn, dn))
    qp = _quarter_period(_check_m1(None, m1))
    # R_F is homogeneous of degree -1/2: R_F(c^2, d^2, 1) = S R_F((S c)^2, (S d)^2, S^2). Scaling
    # by a power of two S ~ 1/max(|c|, d) keeps c^2 and d^2 out of the subnormal range when the
    # point lies within ~1e-150 of K (an orbit that close to an unstable axis).
    big = np.maximum(np.abs(cn), np.abs(dn))
    S = np.where(big < 1e-100, np.exp2(np.minimum(-np.floor(np.log2(np.maximum(big, 1e-300))), 500.0)), 1.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        f = sn * S * special.elliprf((S * cn) ** 2, (S * dn) ** 2, S * S)
    f = np.where(sn == 0.0, 0.0, f)
    if np.any(cn < 0):
        if qp.m1 == 0.0:
            raise ValueError("cn < 0 is impossible at m = 1 (cn = sech > 0)")
        sgn = np.where(sn < 0, -1.0, 1.0)
        f = np.where(cn < 0, 2.0 * qp.K * sgn - f, f)
    return f


def _rj_part(arg: JacobiArgument, rho: float, pref: float) -> np.ndarray:
    """pref * H(u) with H(u) = int_0^u [(1 - nu sn^2)^-1 - 1] dv / nu for nu = 1 - rho,
    continued quasi-periodically.

    On |u| <= K, H = sn^3 R_J(cn^2, dn^2, 1, cn^2 + rho sn^2) / 3 (DLMF 19.25.14 divided by nu);
    H(u + 2K) = H(u) + 2 H(K). Near u = K the principal formula is used at K - |v|, where the
    quarter-shift formulas give cn and dn with relative accuracy.
    """
    qp = arg.qp
    s, c, d = arg.sv, arg.cv, arg.dv
    pref = pref / 3.0

    def h(sn, cn, dn):
        return pref * sn**3 * special.elliprj(cn * cn, dn * dn, 1.0, cn * cn + rho * sn * sn)

    h0 = h(s, c, d)
    if qp.m1 == 0.0:
        return h0
    kp = qp.kp
    hK = pref * special.elliprj(0.0, qp.m1, 1.0, rho)
    h1 = h(c / d, kp * np.abs(s) / d, kp / d)
    j = arg.j
    odd = np.mod(j, 2.0) == 1
    k = np.floor(j / 2.0)
    # odd j: (2k+1) H(K) + sign(v) (H(K) - H(K - |v|)), with the multiples of the (possibly
    # large) H(K) summed as integers first, so a small result does not cancel out of two large
    sv = np.sign(arg.v)
    return np.where(odd, (2 * k + 1 + sv) * hK - sv * h1, 2 * k * hK + h0)


def sn2_rational_integral(arg_t: JacobiArgument, arg_0: JacobiArgument, lam: float, t,
                          A: float, B: float, C: float, D: float, CD: float) -> np.ndarray:
    """int_0^t (A + B sn^2 w) / (C + D sn^2 w) dt' with w = lam t' + w0, for the reduced
    arguments arg_t (w at the times t) and arg_0 (w0).

    The denominator must keep one sign on 0 <= sn^2 <= 1; CD is its value C + D at sn^2 = 1,
    passed separately because it is the small, physically meaningful number when the
    denominator nearly vanishes (it is computed upstream without cancellation).

    Formula: with nu = -D/C, the integrand is A/C + (B C - A D)/C^2 sn^2/(1 - nu sn^2), so
    int_0^w = (A/C) w + ((B C - A D)/C^2) H(w) with H from ``_rj_part`` (an elliptic integral
    of the third kind in Carlson form). When D/C > 0 the integrand peaks at sn = 0 and that
    form cancels badly; the half-period shift sn^2(w) = cn^2(w')/dn^2(w'), w' = w - K, turns it
    into a trough with nu' = (C m + D)/(C + D) in [m, 1]: A' = A + B, B' = -(A m + B),
    C' = C + D, D' = -(C m + D), C' + D' = C m1, B'C' - A'D' = -m1 (B C - A D).
    """
    t = np.asarray(t, dtype=float)
    if C < 0 or (C == 0 and CD < 0):
        A, B, C, D, CD = -A, -B, -C, -D, -CD
    if not (C > 0 and CD >= 0):
        raise ValueError("denominator C + D sn^2 changes sign or vanishes identically")
    m1 = arg_t.qp.m1
    m = 1.0 - m1
    num = B * C - A * D
    if m1 == 0.0 and D > 0:
        return _tanh2_rational_integral(arg_t, arg_0, lam, t, A, B, C, D, CD, num)
    if D > 0 and m1 > 0:
        A, B, C, D, CD, num = A + B, -(A * m + B), CD, -(C * m + D), C * m1, -m1 * num
        arg_t, arg_0 = arg_t.shifted(1), arg_0.shifted(1)
    out = (A / C) * t
    if num != 0.0:
        rho = CD / C
        pref = num / (C * C)
        out = out + (_rj_part(arg_t, rho, pref) - _rj_part(arg_0, rho, pref)) / lam
    return out


def _tanh2_rational_integral(arg_t, arg_0, lam, t, A, B, C, D, CD, num):
    """The m = 1 case with D > 0 in elementary form, x = tanh w, dw = dx / (1 - x^2):
    (A + B x^2) / ((C + D x^2)(1 - x^2)) = ((A + B)/CD) / (1 - x^2) - (num / CD) / (C + D x^2),
    so the secular rate is the integrand's value at sn^2 = 1, with no cancellation against a
    large A/C (the R_J form cannot be rescued by the half-period shift here: K is infinite).
    int dx / (C + D x^2) = atan(r x) / sqrt(C D), r = sqrt(D/C); the difference of two arctangents
    is taken as atan2(r (x - x0), 1 + r^2 x x0), and x - x0 = sinh(w - w0) sech w sech w0."""
    x_t, x_0 = arg_t.sv, arg_0.sv
    r = math.sqrt(D / C)
    lt = lam * t
    with np.errstate(over="ignore"):
        dx = np.where(np.abs(lt) < 1, np.sinh(np.minimum(np.abs(lt), 1.0)) * np.sign(lt) * arg_t.cv * arg_0.cv,
                      x_t - x_0)
    datan = np.arctan2(r * dx, 1.0 + r * r * x_t * x_0)
    out = ((A + B) / CD) * t
    if num != 0.0:
        out = out - (num / CD / lam / math.sqrt(C * D)) * datan
    return out
