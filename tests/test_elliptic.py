"""Jacobi elliptic functions and integrals against mpmath at 50 digits, up to and at m = 1."""
import math
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest
import scipy.special as sc
from hypothesis import given, settings
from hypothesis import strategies as st

from derive.reference.elliptic import (ellipj_accurate, ellipk_m1, elliptic_f_from_jacobi, reduce_argument, sn2_rational_integral,)
from kept_results import kept

EPS = np.finfo(float).eps
# Complementary parameters m1 = 1 - m: the brief's list plus one beyond double precision of m.
M1_VALUES = [1.0, 0.5, 0.1, 1e-6, 1e-10, 1e-14, 1e-17, 0.0]


def mp_jacobi(u, m1, dps=50):
    """sn, cn, dn, am at the double u, computed with mpmath after an exact reduction by 4K.
    (50 digits: at m1 = 1e-17 mpmath's theta-function series lose ~15 digits near u = 2K.)"""
    with mp.workdps(dps):
        x = mp.mpf(u)
        if m1 == 0:
            return mp.tanh(x), mp.sech(x), mp.sech(x), 2 * mp.atan(mp.tanh(x / 2))
        m = 1 - mp.mpf(m1)
        K = mp.ellipk(m)
        n = mp.floor(x / (4 * K) + mp.mpf(1) / 2)
        r = x - 4 * K * n
        sn, cn, dn = (mp.ellipfun(k, r, m=m) for k in ("sn", "cn", "dn"))
        return sn, cn, dn, mp.atan2(sn, cn) + 2 * mp.pi * n


def reference(name, args, compute):
    """``compute()``, an mpmath reference as doubles, kept between test runs (tests/kept_results.py)
    under ``name``, its arguments (doubles) and this file's bytes: the functions under test are
    held to it on every run, mpmath computes it again when this file or the environment changes."""
    return kept("elliptic-reference", (name, args), compute, [Path(__file__)])


def mp_jacobi_table(u, m1, columns=4):
    """The first ``columns`` of :func:`mp_jacobi` (sn, cn, dn, am) at each double of ``u``, as
    doubles (kept: :func:`reference`)."""
    u = [float(x) for x in u]
    return reference("jacobi", (tuple(u), float(m1), columns),
                     lambda: np.array([[float(v) for v in mp_jacobi(x, m1)[:columns]] for x in u]))


def sample_points(K, rng):
    if math.isinf(K):
        K = 20.0
    special = np.array([0.0, K / 2, K, 1.5 * K, 2 * K, 3 * K, 4 * K, K * (1 - 1e-9), 2 * K * (1 + 1e-12),
                        999 * K, 1000 * K, -1000.5 * K, 1e3 * K + 0.37])
    return np.concatenate([special, rng.uniform(-1e3 * K, 1e3 * K, 25), rng.uniform(-3 * K, 3 * K, 25)])


@pytest.mark.parametrize("m1", M1_VALUES)
def test_ellipj_matches_mpmath_up_to_a_thousand_periods(m1):
    rng = np.random.default_rng(int(1e6 * m1) + 7)
    K = ellipk_m1(m1)
    u = sample_points(K, rng)
    sn, cn, dn, am = ellipj_accurate(u, None, m1=m1)
    ref = mp_jacobi_table(u, m1)
    # sn, cn, dn are O(1): absolute error. am grows like u: error relative to its size.
    assert np.max(np.abs(sn - ref[:, 0])) < 1e-14
    assert np.max(np.abs(cn - ref[:, 1])) < 1e-14
    assert np.max(np.abs(dn - ref[:, 2])) < 1e-14
    assert np.all(np.abs(am - ref[:, 3]) <= 8 * EPS * np.maximum(1.0, np.abs(ref[:, 3])))


def test_ellipj_accepts_m_and_agrees_with_scipy_where_scipy_is_accurate():
    u = np.linspace(-7.0, 7.0, 41)
    for m in (0.0, 0.3, 0.5, 0.9):
        mine = ellipj_accurate(u, m)
        theirs = sc.ellipj(u, m)
        for a, b in zip(mine, theirs):
            assert np.max(np.abs(a - b)) < 1e-14


def test_ellipj_where_scipy_fails_near_m_equal_one():
    # scipy returns values far outside [-1, 1] here; the accurate version stays on the circle.
    m1 = 1e-12
    u = np.array([50.0, 1234.5])
    assert not np.all(np.abs(sc.ellipj(u, 1 - m1)[1]) <= 1)
    sn, cn, dn, _ = ellipj_accurate(u, None, m1=m1)
    ref = mp_jacobi_table(u, m1, 3)
    assert np.max(np.abs(np.stack([sn, cn, dn], 1) - ref)) < 1e-14


@pytest.mark.parametrize("m1", [1e-6, 1e-14, 1e-17])
def test_small_values_near_the_quarter_period_have_relative_accuracy(m1):
    # cn(u) ~ k' (K - u) and dn(K) = k' are tiny here; the quarter-period shift keeps their digits.
    K = ellipk_m1(m1)
    u = K * (1 - np.array([1e-3, 1e-6, 1e-9, 1e-12, 0.0]))
    _, cn, dn, _ = ellipj_accurate(u, None, m1=m1)
    ref = mp_jacobi_table(u, m1, 3)
    nz = ref[:, 1] != 0
    assert np.max(np.abs(cn[nz] / ref[nz, 1] - 1)) < 1e-10
    assert np.max(np.abs(dn / ref[:, 2] - 1)) < 1e-13


def test_m_equal_zero_and_one_are_trigonometric_and_hyperbolic():
    u = np.linspace(-30, 30, 121)
    sn, cn, dn, am = ellipj_accurate(u, 0.0)
    assert np.max(np.abs(sn - np.sin(u))) < 4 * EPS * 30 and np.max(np.abs(cn - np.cos(u))) < 4 * EPS * 30
    assert np.max(np.abs(dn - 1)) <= 2 * EPS and np.max(np.abs(am - u)) < 4 * EPS * 30
    sn, cn, dn, am = ellipj_accurate(u, 1.0)
    assert np.max(np.abs(sn - np.tanh(u))) < 2 * EPS
    assert np.max(np.abs(cn - 1 / np.cosh(u))) < 2 * EPS and np.array_equal(cn, dn)
    assert np.max(np.abs(am - (2 * np.arctan(np.tanh(u / 2))))) < 4 * EPS


def test_m1_beyond_double_m_is_periodic_yet_close_to_the_hyperbolic_limit():
    m1 = 1e-17  # 1 - m1 == 1.0 in double precision, yet K = 20.96 is finite
    K = ellipk_m1(m1)
    assert 20.9 < K < 21.0
    u = np.linspace(-5, 5, 21)
    sn, cn, dn, _ = ellipj_accurate(u, None, m1=m1)
    assert np.max(np.abs(sn - np.tanh(u))) < 1e-13
    shifted = ellipj_accurate(u + 4 * K * 37, None, m1=m1)
    assert np.max(np.abs(shifted[0] - sn)) < 1e-12


@settings(max_examples=60, deadline=None)
@given(u=st.floats(-500, 500), m1=st.floats(0, 1) | st.sampled_from([1e-16, 1e-12, 1e-8, 0.0]))
def test_identities_and_derivatives(u, m1):
    sn, cn, dn, am = ellipj_accurate(np.array([u]), None, m1=m1)
    m = 1 - m1
    assert abs(sn[0] ** 2 + cn[0] ** 2 - 1) < 4 * EPS
    assert abs(dn[0] ** 2 + m * sn[0] ** 2 - 1) < 4 * EPS
    assert abs(math.sin(am[0]) - sn[0]) < 1e-13 * max(1, abs(am[0]))
    # d sn/du = cn dn, d am/du = dn (sixth-order central difference)
    h = 1e-3
    x = u + h * np.array([-3, -2, -1, 1, 2, 3.0])
    s, _, _, a = ellipj_accurate(x, None, m1=m1)
    w = np.array([-1, 9, -45, 45, -9, 1.0]) / (60 * h)
    assert abs(w @ s - cn[0] * dn[0]) < 1e-9
    assert abs(w @ a - dn[0]) < 1e-9


@pytest.mark.parametrize("m1", [0.7, 1e-9, 1e-15, 0.0])
def test_incomplete_integral_inverts_the_jacobi_functions(m1):
    K = ellipk_m1(m1)
    top = 2 * K if math.isfinite(K) else 30.0
    u = np.linspace(-top, top, 33)[1:]
    if m1 == 0:
        u = u[np.abs(u) < 19]  # tanh(u) = 1 beyond: the argument is no longer recoverable
    sn, cn, dn, _ = ellipj_accurate(u, None, m1=m1)
    diff = elliptic_f_from_jacobi(sn, cn, dn, m1) - u
    if math.isfinite(K):  # the result lies in (-2K, 2K]; at u = 2K rounding may give -2K
        diff = np.remainder(diff + 2 * K, 4 * K) - 2 * K
    assert np.max(np.abs(diff)) < 64 * EPS * max(1, top)


@pytest.mark.parametrize("m1", [1.0, 0.25, 1e-9, 1e-17])
def test_complete_integral_matches_mpmath(m1):
    with mp.workdps(40):
        ref = mp.ellipk(1 - mp.mpf(m1))
    assert abs(ellipk_m1(m1) - float(ref)) <= EPS * float(ref)


RATIONALS = [
    (1.0, 0.0, 2.0, -1.999),  # trough of the denominator at sn^2 = 1 (integrand up to 1000)
    (1.0, 0.0, 1e-3, 1.0),  # peak at sn = 0: needs the half-period shift
    (1.0, 0.0, 1e-7, 1.0),  # ... a sharp one (a top passing 3e-4 rad from a pole)
    (1.0, 0.5, 0.3, 0.7),
    (2.0, -1.0, 1.0, 5.0),
    (-3.0, 1.0, -1.0, -0.5),  # negative denominator
]


def mp_rational_integral(A, B, C, D, m1, w0, lam, t):
    """int_0^t (A + B sn^2)/(C + D sn^2) dt' at 30 digits via mpmath's own incomplete integral
    of the third kind: (A + B x)/(C + D x) = B/D + ((A D - B C)/(C D)) / (1 + (D/C) x), and
    int_0^w dv / (1 - n sn^2 v) = Pi(n; am w | m) with the continuous amplitude am."""
    # At m = 1 the amplitude approaches pi/2 like 2 exp(-w): 60 digits keep cos(am) significant.
    with mp.workdps(60 if m1 == 0 else 30):
        m = 1 - mp.mpf(m1)
        w0, lam, t = mp.mpf(w0), mp.mpf(lam), mp.mpf(t)

        def am(w):
            if m1 == 0:
                return mp.atan(mp.sinh(w))
            K = mp.ellipk(m)
            q = mp.nint(w / (2 * K))
            return q * mp.pi + mp.asin(mp.ellipfun("sn", w - 2 * K * q, m=m))

        def prim(w):
            return (mp.mpf(B) / D) * w + ((mp.mpf(A) * D - mp.mpf(B) * C) / (mp.mpf(C) * D)) * mp.ellippi(
                -mp.mpf(D) / C, am(w), m)

        return (prim(lam * t + w0) - prim(w0)) / lam


def mp_rational_quadrature(A, B, C, D, m1, w0, lam, t):
    """The same integral by brute-force quadrature (slow; short t only)."""
    with mp.workdps(20):
        m = 1 - mp.mpf(m1)
        sn2 = lambda s: mp.ellipfun("sn", lam * s + w0, m=m) ** 2
        return mp.quad(lambda s: (A + B * sn2(s)) / (C + D * sn2(s)), mp.linspace(0, t, 8))


@pytest.mark.parametrize("coef, m1", [
    (coef, m1) if m1 == 0.0 or coef is RATIONALS[0] else pytest.param(coef, m1, marks=pytest.mark.slow)
    for coef in RATIONALS for m1 in (0.5, 1e-6, 1e-12, 0.0)])  # every set at m1 = 0, every m1 for the first
def test_rational_integral_of_sn_squared_matches_quadrature(m1, coef):
    A, B, C, D = coef
    lam, w0 = 1.3, 0.7
    t = np.array([0.5, 3.0, 25.0])
    got = sn2_rational_integral(reduce_argument(lam * t + w0, m1), reduce_argument(np.array([w0]), m1),
                                lam, t, A, B, C, D, C + D)
    # The integrands are of one sign, so |integral| = integral of |integrand|: relative error.
    for x, g in zip(t, got):
        ref = reference("rational-integral", (coef, m1, w0, lam, float(x)), lambda: float(
            mp_rational_integral(A, B, C, D, m1, mp.mpf(w0), mp.mpf(lam), mp.mpf(x))))
        assert abs(g - ref) < 2e-14 * abs(ref), (x, g, ref)
    # and, independently of any elliptic-integral code, by quadrature over a short span
    if C > 1e-5:  # (the sharp peak defeats a plain quadrature)
        ref = reference("rational-quadrature", (coef, m1, w0, lam, float(t[1])), lambda: float(
            mp_rational_quadrature(A, B, C, D, m1, w0, lam, t[1])))
        assert abs(got[1] - ref) < 1e-13 * abs(ref)


def test_parameter_validation():
    with pytest.raises(ValueError):
        ellipj_accurate(1.0, 1.5)
    with pytest.raises(ValueError):
        ellipj_accurate(1.0, -0.1)
    with pytest.raises(ValueError):
        ellipj_accurate(1.0, 0.5, m1=0.3)
    with pytest.raises(ValueError):
        ellipk_m1(-1e-3)
