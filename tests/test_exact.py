"""Exact rigid-body solutions against 30-digit Taylor-series integration with mpmath.

The reference integrator below is independent of the closed forms: it integrates the
equations of motion (Euler's equations with the gravity torque plus R' = R [omega]x, or the
Euler-Lagrange equations in Euler angles) by a Taylor method whose coefficients come from
automatic differentiation in mpmath arithmetic (mp.dps = 30, local error ~1e-25).
"""
import math
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from derive.reference.exact import (euler_angles, euler_matrix, free_asymmetric, free_symmetric, heavy_top,)
from kept_results import kept

EPS = np.finfo(float).eps


# ---------------------------------------------------------------------------------------------
# a small Taylor-mode automatic differentiation and the integrator built on it


class _Tape:
    def __init__(self):
        self.nodes = []


class _Series:
    """A Taylor series whose k-th coefficient is produced on demand by rule(k) (after all
    coefficients < k of everything it depends on, and its own, are known)."""

    __slots__ = ("tape", "c", "rule")

    def __init__(self, tape, rule):
        self.tape, self.c, self.rule = tape, [], rule
        if rule is not None:
            tape.nodes.append(self)

    def _lift(self, o):
        if isinstance(o, _Series):
            return o
        v = mp.mpf(o)
        return _Series(self.tape, lambda k: v if k == 0 else mp.mpf(0))

    def __add__(self, o):
        o = self._lift(o)
        return _Series(self.tape, lambda k: self.c[k] + o.c[k])

    __radd__ = __add__

    def __sub__(self, o):
        o = self._lift(o)
        return _Series(self.tape, lambda k: self.c[k] - o.c[k])

    def __rsub__(self, o):
        return self._lift(o) - self

    def __neg__(self):
        return _Series(self.tape, lambda k: -self.c[k])

    def __mul__(self, o):
        if not isinstance(o, _Series):
            v = mp.mpf(o)
            return _Series(self.tape, lambda k: v * self.c[k])
        return _Series(self.tape, lambda k: mp.fdot(self.c[: k + 1], o.c[k::-1]))

    __rmul__ = __mul__

    def __rtruediv__(self, o):
        return self._lift(o) / self

    def __truediv__(self, o):
        if not isinstance(o, _Series):
            v = 1 / mp.mpf(o)
            return _Series(self.tape, lambda k: v * self.c[k])
        q = _Series(self.tape, None)

        def rule(k):
            if k == 0:
                return self.c[0] / o.c[0]
            return (self.c[k] - mp.fdot(o.c[1 : k + 1], q.c[k - 1 :: -1])) / o.c[0]

        q.rule = rule
        self.tape.nodes.append(q)
        return q


def _sincos(x):
    s, c = _Series(x.tape, None), _Series(x.tape, None)

    def rule_s(k):
        if k == 0:
            return mp.sin(x.c[0])
        return mp.fdot([j * x.c[j] for j in range(1, k + 1)], c.c[k - 1 :: -1]) / k

    def rule_c(k):
        if k == 0:
            return mp.cos(x.c[0])
        return -mp.fdot([j * x.c[j] for j in range(1, k + 1)], s.c[k - 1 :: -1]) / k

    s.rule, c.rule = rule_s, rule_c
    x.tape.nodes += [s, c]
    return s, c


def taylor_solve(rhs, y0, t_out, order=30, tol="1e-25"):
    """Integrate y' = rhs(y) (autonomous) from t = 0 in mpmath arithmetic; return the states
    at the sorted times t_out as a float array. Step h from the last two Taylor coefficients
    (|y_k| h^k <= tol * max(1, |y|)); outputs inside a step from the Taylor polynomial."""
    tol = mp.mpf(tol)
    tape = _Tape()
    Y = [_Series(tape, None) for _ in y0]
    F = rhs(Y)
    y = [mp.mpf(v) for v in y0]
    t = mp.mpf(0)
    times = [mp.mpf(float(x)) for x in t_out]
    out, i = [], 0
    while i < len(times):
        for node in tape.nodes:
            node.c = []
        for Yi, yi in zip(Y, y):
            Yi.c = [yi]
        for k in range(order):
            for node in tape.nodes:
                node.c.append(node.rule(k))
            for Yi, Fi in zip(Y, F):
                Yi.c.append(Fi.c[k] / (k + 1))
        scale = max([mp.mpf(1)] + [abs(v) for v in y])
        h = mp.inf
        for k in (order - 1, order):
            nk = max(abs(Yi.c[k]) for Yi in Y)
            if nk > 0:
                h = min(h, (tol * scale / nk) ** (mp.mpf(1) / k))
        h = h * mp.mpf("0.8")
        while i < len(times) and times[i] <= t + h:
            out.append([mp.polyval(Yi.c[::-1], times[i] - t) for Yi in Y])
            i += 1
        y = [mp.polyval(Yi.c[::-1], h) for Yi in Y]
        t += h
    return np.array([[float(v) for v in row] for row in out])


def rigid_body_rhs(I, mgl=0.0):
    """omega' from I omega' = (I omega) x omega + tau, tau = M g l (R[2,1], -R[2,0], 0) (gravity
    -z on a centre of mass at l e3), and R' = R [omega]x; state (omega, rows of R)."""
    I1, I2, I3 = (mp.mpf(x) for x in I)
    mgl = mp.mpf(mgl)

    def rhs(Y):
        w1, w2, w3 = Y[:3]
        R = [Y[3:6], Y[6:9], Y[9:12]]
        out = [
            ((I2 - I3) * (w2 * w3) + mgl * R[2][1]) / I1,
            ((I3 - I1) * (w3 * w1) - mgl * R[2][0]) / I2,
            ((I1 - I2) / I3) * (w1 * w2),
        ]
        for r in R:
            out += [r[1] * w3 - r[2] * w2, r[2] * w1 - r[0] * w3, r[0] * w2 - r[1] * w1]
        return out

    return rhs


def euler_lagrange_rhs(I1, I3, mgl):
    """The heavy top's Euler-Lagrange equations solved for the accelerations; state
    (a, b, g, a', b', g'): I1 b'' = I1 a'^2 s c - p_g a' s + M g l s, (p_alpha)' = 0 gives
    a'' = b' (p_g - 2 I1 a' c)/(I1 s), (p_gamma)' = 0 gives g'' = a' b' s - a'' c."""
    I1, I3, mgl = mp.mpf(I1), mp.mpf(I3), mp.mpf(mgl)

    def rhs(Y):
        a, b, g, ad, bd, gd = Y
        s, c = _sincos(b)
        pg = I3 * (ad * c + gd)
        bdd = (I1 * (ad * ad) * (s * c) - pg * ad * s + mgl * s) / I1
        add = bd * (pg - 2 * I1 * (ad * c)) / (I1 * s)
        return [ad, bd, gd, add, bdd, ad * bd * s - add * c]

    return rhs


def mp_euler_state(alpha, beta, gamma, ad, bd, gd):
    """omega and R (flattened) at 30 digits from the (double) Euler angles and rates."""
    with mp.workdps(30):
        a, b, g, ad, bd, gd = (mp.mpf(float(x)) for x in (alpha, beta, gamma, ad, bd, gd))
        ca, sa, cb, sb, cg, sg = mp.cos(a), mp.sin(a), mp.cos(b), mp.sin(b), mp.cos(g), mp.sin(g)
        Rz = lambda c, s: mp.matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])
        R = Rz(ca, sa) * mp.matrix([[cb, 0, sb], [0, 1, 0], [-sb, 0, cb]]) * Rz(cg, sg)
        w = [-ad * sb * cg + bd * sg, ad * sb * sg + bd * cg, ad * cb + gd]
        return w + [R[i, j] for i in range(3) for j in range(3)]


def _exactly(v):
    """``v`` (a number, or a list or tuple of them) as a key naming its exact value: an mpf by
    its binary digits (its ``repr`` rounds to the working precision), a double by its float."""
    if isinstance(v, (list, tuple)):
        return tuple(_exactly(x) for x in v)
    return ("mpf", v._mpf_) if isinstance(v, mp.mpf) else float(v)


#: The right-hand sides a reference integrates, by name (the key of a kept reference).
RHS = {"rigid": rigid_body_rhs, "euler-lagrange": euler_lagrange_rhs}


def reference(rhs, args, y0, t):
    """``taylor_solve(RHS[rhs](*args), y0, t)`` at 30 digits, kept between test runs
    (tests/kept_results.py) under its arguments and this file's bytes: the closed forms are held
    to it on every run, the integration runs again when this file or the environment changes.
    The integrator itself is checked against known solutions afresh on every run."""
    def compute():
        with mp.workdps(30):
            return taylor_solve(RHS[rhs](*args), y0, t)
    return kept("exact-reference", (rhs, _exactly(args), _exactly(y0), _exactly(list(t))), compute,
                [Path(__file__)])


def mp_rigid(I, mgl, state0, t):
    ref = reference("rigid", (tuple(I), mgl), list(state0), t)
    return ref[:, :3], ref[:, 3:].reshape(-1, 3, 3)


def hat(w):
    return np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])


def assert_rotation(R, tol=1e-13):
    err = np.abs(np.einsum("nji,njk->nik", R, R) - np.eye(3)).max()
    assert err < tol, err
    assert np.all(np.linalg.det(R) > 0)


# ---------------------------------------------------------------------------------------------
# the reference integrator itself


def test_taylor_reference_reproduces_known_solutions():
    # th' = 1, x' = cos th, y' = 1/(1 + th), z' = z: x = sin t, y = ln(1 + t), z = e^t
    def rhs(Y):
        th, _, _, z = Y
        return [th * 0 + 1, _sincos(th)[1], 1 / (th + 1), z * 1]

    t = np.array([0.5, 1.7, 4.0])
    with mp.workdps(30):
        out = taylor_solve(rhs, [0.0, 0.0, 0.0, 1.0], t)
    assert np.max(np.abs(out[:, 1] - np.sin(t))) < 1e-15
    assert np.max(np.abs(out[:, 2] - np.log1p(t))) < 1e-15
    assert np.max(np.abs(out[:, 3] / np.exp(t) - 1)) < 1e-15


# ---------------------------------------------------------------------------------------------
# torque-free symmetric body


def test_free_symmetric_omega_is_the_lecture_solution():
    I1, I3, w0 = 2.0, 0.7, np.array([0.3, -1.1, 2.5])
    t = np.linspace(0, 40, 101)
    tr = free_symmetric(I1, I3, w0, t)
    Omega = w0[2] * (I3 - I1) / I1
    A, phi = np.hypot(w0[0], w0[1]), np.arctan2(w0[1], w0[0])
    assert np.max(np.abs(tr.omega[:, 0] - A * np.cos(Omega * t + phi))) < 1e-14
    assert np.max(np.abs(tr.omega[:, 1] - A * np.sin(Omega * t + phi))) < 1e-14
    assert np.all(tr.omega[:, 2] == w0[2])
    assert tr.info["Omega"] == Omega


@pytest.mark.parametrize("I1,I3", [(1.0, 3.0), (2.0, 0.5)])  # oblate and prolate
def test_free_symmetric_matches_high_precision_integration(I1, I3):
    angles, rates = (0.3, 0.7, -0.4), (0.2, -0.5, 1.5)
    state = mp_euler_state(*angles, *rates)
    w0 = np.array(state[:3])
    R0 = euler_matrix(*angles)
    t = np.linspace(0, 3, 7)
    tr = free_symmetric(I1, I3, w0, t, R0)
    w_ref, R_ref = mp_rigid((I1, I1, I3), 0.0, state, t)
    assert np.max(np.abs(tr.omega - w_ref)) < 1e-13 * np.linalg.norm(w0)
    assert np.max(np.abs(tr.R - R_ref)) < 1e-13


# ---------------------------------------------------------------------------------------------
# torque-free asymmetric body

# (I, omega0): both polar regimes, all axis orderings, near and exactly on the separatrix.
# I = (3, 4, 6) has L^2 - 2E I2 = 12 (w3^2 - w1^2/4): w1 = 2 w3 is exactly the separatrix.
ASYMMETRIC_CASES = {
    "polar-largest": ((1.0, 2.0, 3.0), (0.3, 1.0, 0.5)),
    "polar-smallest": ((1.0, 2.0, 3.0), (1.0, 0.2, 0.1)),
    "order-312": ((3.0, 1.0, 2.0), (0.2, 0.5, -1.0)),
    "order-231": ((2.0, 3.0, 1.0), (-0.3, 1.0, 0.2)),
    "order-132": ((1.0, 3.0, 2.0), (0.4, -0.3, 0.9)),
    "separatrix": ((3.0, 4.0, 6.0), (2.0, 1.3, 1.0)),
    "near-separatrix-above": ((3.0, 4.0, 6.0), (2.0, 1.3, 1.0 + 2**-40)),
    "near-separatrix-below": ((3.0, 4.0, 6.0), (2.0, 1.3, 1.0 - 2**-40)),
    "near-intermediate-axis": ((1.0, 2.0, 3.0), (1e-6, 1.0, 1e-6)),
}


@pytest.mark.parametrize("name", [n if n in ("polar-largest", "polar-smallest", "separatrix")
                                  else pytest.param(n, marks=pytest.mark.slow) for n in ASYMMETRIC_CASES])
def test_free_asymmetric_matches_high_precision_integration(name):
    I, w0 = ASYMMETRIC_CASES[name]
    angles = (0.3, 0.7, -0.4)
    R0 = euler_matrix(*angles)
    with mp.workdps(30):
        Rmp = mp_euler_state(*angles, 0, 0, 0)[3:]
    t = np.linspace(0, 12, 7)
    tr = free_asymmetric(*I, w0, t, R0)
    w_ref, R_ref = mp_rigid(I, 0.0, list(w0) + Rmp, t)
    wscale = np.linalg.norm(w0)
    assert np.max(np.abs(tr.omega - w_ref)) < 1e-13 * wscale, np.max(np.abs(tr.omega - w_ref))
    assert np.max(np.abs(tr.R - R_ref)) < 1e-12, np.max(np.abs(tr.R - R_ref))


def test_near_separatrix_cases_are_near_the_separatrix():
    I, w0 = ASYMMETRIC_CASES["separatrix"]
    assert free_asymmetric(*I, w0, [0.0]).info["m1"] == 0.0
    for name in ("near-separatrix-above", "near-separatrix-below"):
        I, w0 = ASYMMETRIC_CASES[name]
        info = free_asymmetric(*I, w0, [0.0]).info
        assert 1e-13 < info["m1"] < 1e-11
    regimes = {free_asymmetric(*ASYMMETRIC_CASES[n][0], ASYMMETRIC_CASES[n][1], [0.0]).info["regime"]
               for n in ("near-separatrix-above", "near-separatrix-below")}
    assert regimes == {"polar-largest", "polar-smallest"}
    # m1 = (I3 - I1)(L^2 - 2E I2)/((I3 - I2)(L^2 - 2E I1)) is a small difference of O(1) terms:
    # it must still be correctly rounded for the given omega0 (every flip's timing hangs on it)
    from fractions import Fraction as Fr

    I, w0 = ASYMMETRIC_CASES["near-separatrix-above"]
    I, w = [Fr(x) for x in I], [Fr(x) for x in w0]
    L2 = sum((i * x) ** 2 for i, x in zip(I, w))
    E2 = sum(i * x * x for i, x in zip(I, w))
    exact = (I[2] - I[0]) * (L2 - E2 * I[1]) / ((I[2] - I[1]) * (L2 - E2 * I[0]))
    got = free_asymmetric(*ASYMMETRIC_CASES["near-separatrix-above"][0], w0, [0.0]).info["m1"]
    assert abs(got / float(exact) - 1) < 4 * EPS


def test_separatrix_approaches_the_intermediate_axis():
    # On the separatrix omega tends to the unstable steady rotation about the intermediate axis.
    I, w0 = ASYMMETRIC_CASES["separatrix"]
    tr = free_asymmetric(*I, w0, [0.0, 80.0])
    I, w0 = np.array(I), np.array(w0)
    L2, E2 = np.sum((I * w0) ** 2), np.sum(I * w0**2)
    w_axis = math.sqrt(L2) / I[1]
    assert abs(abs(tr.omega[1, 1]) - w_axis) < 1e-12 and np.max(np.abs(tr.omega[1, [0, 2]])) < 1e-12
    assert L2 == E2 * I[1]


@settings(max_examples=25, deadline=None)
@given(
    moments=st.tuples(*[st.floats(0.5, 3.0)] * 3).filter(
        lambda I: len(set(I)) == 3 and I[0] + I[1] > I[2] and I[1] + I[2] > I[0] and I[0] + I[2] > I[1]),
    w0=st.tuples(*[st.floats(-2.0, 2.0)] * 3).filter(lambda w: np.count_nonzero(w) == 3),
)
def test_free_asymmetric_satisfies_eulers_equations_and_conservation(moments, w0):
    I, w0 = np.array(moments), np.array(w0)
    R0 = euler_matrix(0.1, 2.0, -0.3)
    t = np.linspace(0.0, 30.0, 13)
    tr = free_asymmetric(*I, w0, t, R0)
    wscale = np.max(np.abs(w0))  # (max, not norm: hypothesis tries |w| ~ 1e-200, whose squares underflow)
    assert np.max(np.abs(tr.omega[0] - w0)) <= 1e-14 * wscale
    assert np.max(np.abs(tr.R[0] - R0)) < 1e-14
    assert_rotation(tr.R)
    # angular momentum fixed in space, energy constant (in units of |omega0|)
    L = np.einsum("nij,nj->ni", tr.R, tr.omega / wscale * I)
    assert np.max(np.abs(L - L[0])) < 1e-13 * np.linalg.norm(L[0])
    E = 0.5 * np.sum(I * (tr.omega / wscale) ** 2, axis=1)
    assert np.max(np.abs(E - E[0])) < 1e-13 * E[0]
    # Euler's equations I w' = (I w) x w and R' = R [w]x, derivatives by a sixth-order central
    # difference: truncation ~ h^6 |w^(7)|, rounding ~ eps |w| / h
    h = 1e-3
    offsets = h * np.array([-3, -2, -1, 1, 2, 3.0])
    weights = np.array([-1, 9, -45, 45, -9, 1.0]) / (60 * h)
    for t0 in (0.0, 7.3, 29.0):
        side = free_asymmetric(*I, w0, t0 + offsets, R0)
        mid = free_asymmetric(*I, w0, [t0], R0)
        w = mid.omega[0] / wscale
        wdot = weights @ side.omega / wscale
        resid = I * wdot - wscale * np.cross(I * w, w)
        assert np.max(np.abs(resid)) < np.max(I) * (1e-8 * wscale**2 + 1e-11)
        Rdot = np.einsum("k,kij->ij", weights, side.R)
        assert np.max(np.abs(Rdot - mid.R[0] @ hat(mid.omega[0]))) < 1e-8 * wscale + 1e-11


def test_free_asymmetric_with_two_equal_moments_is_the_symmetric_solution():
    w0, t = np.array([0.3, 1.0, 0.5]), np.linspace(0, 20, 9)
    R0 = euler_matrix(1.0, 0.4, 2.0)
    ref = free_symmetric(1.5, 0.8, w0, t, R0)
    same = free_asymmetric(1.5, 1.5, 0.8, w0, t, R0)
    assert np.array_equal(same.R, ref.R) and np.array_equal(same.omega, ref.omega)
    # symmetry axis 1: relabelled cyclically; compare against a nearly symmetric elliptic solution
    tr = free_asymmetric(0.8, 1.5, 1.5, w0[[2, 0, 1]], t, R0)
    near = free_asymmetric(0.8, 1.5 * (1 + 1e-10), 1.5, w0[[2, 0, 1]], t, R0)
    assert near.info["m1"] < 1 and near.info["m1"] > 1 - 1e-8
    assert np.max(np.abs(tr.R - near.R)) < 1e-8 and np.max(np.abs(tr.omega - near.omega)) < 1e-8


def test_steady_rotation_about_a_principal_axis():
    t = np.linspace(0, 10, 11)
    tr = free_asymmetric(3.0, 4.0, 6.0, [0.0, 1.3, 0.0], t)  # the unstable axis, exactly
    assert np.all(tr.omega == [0.0, 1.3, 0.0])
    assert np.max(np.abs(tr.R - np.array([euler_matrix(0, 1.3 * s, 0) for s in t]))) < 1e-14
    assert free_asymmetric(3.0, 4.0, 6.0, [0.0, 0.0, 0.0], t).info["regime"] == "steady"


def test_free_solutions_reject_bad_input():
    with pytest.raises(ValueError):
        free_asymmetric(1.0, -2.0, 3.0, [1, 2, 3], [0.0])
    with pytest.raises(ValueError):
        free_symmetric(1.0, 2.0, [1, 2], [0.0])
    with pytest.raises(ValueError):
        free_symmetric(1.0, 2.0, [1, 2, 3], [0.0], R0=2 * np.eye(3))
    with pytest.raises(ValueError):
        free_asymmetric(1.0, 2.0, 3.0, [1, np.nan, 3], [0.0])


# ---------------------------------------------------------------------------------------------
# heavy symmetric top

TOP = dict(I1=1.0, I3=0.5, M=1.0, g=9.81, l=0.1)  # M g l = 0.981; sleeping threshold p_g^2 = 3.924


def top_args(top, alpha0, beta0, gamma0, ad0, bd0, gd0):
    return (top["I1"], top["I3"], top["M"], top["g"], top["l"], alpha0, beta0, gamma0, ad0, bd0, gd0)


def mp_top(top, init, t):
    """Heavy top integrated in Cartesian form (no Euler-angle singularities) at 30 digits."""
    mgl = top["M"] * top["g"] * top["l"]
    return mp_rigid((top["I1"], top["I1"], top["I3"]), mgl, mp_euler_state(*init), t)


def steady_precession_rate(top, beta, w3, fast=False):
    """a' of steady precession at beta: I1 a'^2 cos b - p_g a' + M g l = 0 (beta-dot = 0)."""
    I1, mgl = top["I1"], top["M"] * top["g"] * top["l"]
    pg = top["I3"] * w3
    c = math.cos(beta)
    disc = math.sqrt(pg * pg - 4 * I1 * c * mgl)
    return (pg + disc) / (2 * I1 * c) if fast else 2 * mgl / (pg + disc)


# (top overrides, (alpha0, beta0, gamma0, alpha-dot0, beta-dot0, gamma-dot0))
HEAVY_CASES = {
    "fast-top": ({}, (0.0, 0.5, 0.0, 0.3, 0.0, 20.0)),
    "large-nutation": ({}, (0.2, 0.5, 0.1, 0.3, 1.0, 5.0)),
    "looping": ({}, (0.2, 0.8, 0.1, -1.5, 0.3, 6.0)),
    "hanging": ({"l": -0.1}, (0.2, 0.5, 0.1, 0.3, 1.0, 5.0)),
    "below-horizontal": ({}, (0.2, 2.5, 0.1, 0.3, 1.0, 5.0)),
    "negative-beta0": ({}, (0.2, -0.5, 0.1, 0.3, 1.0, 5.0)),
    "no-gravity": ({"g": 0.0}, (0.2, 0.5, 0.1, 0.3, 1.0, 5.0)),
    "over-the-top": ({}, (0.0, 0.5, 0.0, 0.0, 6.0, 0.0)),  # p_alpha = p_gamma = 0: a rotating pendulum
}


@pytest.mark.parametrize("name", list(HEAVY_CASES))
def test_heavy_top_matches_high_precision_integration(name):
    over, init = HEAVY_CASES[name]
    top = {**TOP, **over}
    t = np.linspace(0, 1.5, 7)
    tr = heavy_top(*top_args(top, *init), t)
    w_ref, R_ref = mp_top(top, init, t)
    wscale = np.linalg.norm(w_ref[0])
    assert np.max(np.abs(tr.omega - w_ref)) < 1e-13 * wscale, np.max(np.abs(tr.omega - w_ref))
    assert np.max(np.abs(tr.R - R_ref)) < 1e-12, np.max(np.abs(tr.R - R_ref))
    assert tr.alpha[0] == init[0] and tr.gamma[0] == init[2]
    assert abs(tr.beta[0] - init[1]) <= 2 * EPS * abs(init[1])


def test_heavy_top_over_the_top_has_beta_growing_continuously():
    tr = heavy_top(*top_args(TOP, *HEAVY_CASES["over-the-top"][1]), np.linspace(0, 10, 2001))
    assert np.all(np.diff(tr.beta) > 0) and tr.beta[-1] > 8 * np.pi
    assert tr.info["through_pole"]


@pytest.mark.parametrize("name", ["fast-top", "large-nutation", "looping"])
def test_heavy_top_angles_match_the_euler_lagrange_equations(name):
    over, init = HEAVY_CASES[name]
    top = {**TOP, **over}
    t = np.linspace(0, 1.0, 5)
    tr = heavy_top(*top_args(top, *init), t)
    ref = reference("euler-lagrange", (top["I1"], top["I3"], top["M"] * top["g"] * top["l"]), list(init), t)
    for k, angle in enumerate((tr.alpha, tr.beta, tr.gamma)):
        assert np.max(np.abs(angle - ref[:, k])) < 1e-12, (k, np.max(np.abs(angle - ref[:, k])))


@pytest.mark.parametrize("name", list(HEAVY_CASES))
def test_heavy_top_conserves_energy_and_momenta_over_long_times(name):
    over, init = HEAVY_CASES[name]
    top = {**TOP, **over}
    t = np.linspace(0, 1000, 2001)
    tr = heavy_top(*top_args(top, *init), t)
    assert_rotation(tr.R, 1e-13)
    mgl = top["M"] * top["g"] * top["l"]
    I = np.array([top["I1"], top["I1"], top["I3"]])
    # recompute from omega and R (independently of the Trajectory's own fields)
    E = 0.5 * np.sum(I * tr.omega**2, axis=1) + mgl * tr.R[:, 2, 2]
    L = np.einsum("nij,nj->ni", tr.R, I * tr.omega)
    scale = 0.5 * np.max(np.sum(I * tr.omega**2, axis=1)) + abs(mgl)
    Lscale = np.max(np.linalg.norm(L, axis=1))
    assert np.max(np.abs(E - E[0])) < 1e-13 * scale
    assert np.max(np.abs(L[:, 2] - L[0, 2])) < 1e-13 * Lscale  # p_alpha
    assert np.max(np.abs(tr.omega[:, 2] - tr.omega[0, 2])) == 0.0  # p_gamma / I3
    assert np.allclose(tr.energy, E, rtol=0, atol=1e-14 * scale) and np.allclose(tr.p_alpha, L[:, 2])
    # the Euler angles and R agree, and the angles are continuous
    assert np.max(np.abs(euler_matrix(tr.alpha, tr.beta, tr.gamma) - tr.R)) == 0.0
    assert np.all(np.isfinite(tr.alpha)) and np.all(np.isfinite(tr.gamma))


def test_coalescing_roots_tend_to_steady_precession_at_the_small_oscillation_frequency():
    top, beta0, w3 = TOP, 0.6, 15.0
    ad_s = steady_precession_rate(top, beta0, w3)
    gd_s = w3 - ad_s * math.cos(beta0)
    # exact steady precession (to rounding): beta constant, alpha uniform
    t = np.linspace(0, 200, 41)
    tr = heavy_top(*top_args(top, 0.0, beta0, 0.0, ad_s, 0.0, gd_s), t)
    assert np.max(np.abs(tr.beta - beta0)) < 1e-13
    assert np.max(np.abs(tr.alpha - ad_s * t)) < 1e-13 * ad_s * t[-1]
    # Perturbed: the nutation period tends to the small-oscillation period about the perturbed
    # motion's own steady precession, from linearising b'' = F(b), a' = (p_a - p_g cos b)/(I1 sin^2 b),
    # with a relative error of order (u2 - u1)^2 (a nonlinear-oscillator correction).
    I1, I3, mgl = top["I1"], top["I3"], top["M"] * top["g"] * top["l"]
    for eps in (1e-2, 1e-4, 1e-6, 1e-9):
        ad0 = ad_s * (1 + eps)
        with mp.workdps(30):
            pg = I3 * (mp.mpf(ad0) * mp.cos(beta0) + gd_s)
            pa = I1 * mp.mpf(ad0) * mp.sin(beta0) ** 2 + pg * mp.cos(beta0)

            def F(b):
                ad = (pa - pg * mp.cos(b)) / (I1 * mp.sin(b) ** 2)
                return (I1 * ad**2 * mp.sin(b) * mp.cos(b) - pg * ad * mp.sin(b) + mgl * mp.sin(b)) / I1

            period_lin = float(2 * mp.pi / mp.sqrt(-mp.diff(F, mp.findroot(F, beta0))))
        info = heavy_top(*top_args(top, 0.0, beta0, 0.0, ad0, 0.0, gd_s), [0.0]).info
        u1, u2, _ = info["u_roots"]
        assert 0 < u2 - u1 < 0.02 * eps
        err = abs(info["nutation_period"] / period_lin - 1)
        assert err < (u2 - u1) ** 2 + 4 * EPS, (eps, err)
    assert err < 4 * EPS
    # and the nearly steady motion itself is right
    init = (0.0, beta0, 0.0, ad_s * (1 + 1e-7), 0.0, gd_s)
    t = np.linspace(0, 1.5, 4)
    tr = heavy_top(*top_args(top, *init), t)
    w_ref, R_ref = mp_top(top, init, t)
    assert np.max(np.abs(tr.R - R_ref)) < 1e-12


@pytest.mark.parametrize("w3", [6.0, 1.0])  # p_gamma^2 = 9 > 4 M g l I1 = 3.92 (stable) and 0.25 (unstable)
def test_sleeping_top_stays_vertical(w3):
    t = np.linspace(0, 50, 11)
    tr = heavy_top(*top_args(TOP, 0.3, 0.0, 0.2, 0.5, 0.0, w3 - 0.5), t)
    assert np.all(tr.beta == 0.0) and np.all(tr.axis == [0.0, 0.0, 1.0])
    assert np.max(np.abs(tr.alpha + tr.gamma - (0.5 + w3 * t))) < 1e-13 * w3 * t[-1]
    assert np.all(tr.omega == [0.0, 0.0, w3])


def p_alpha_equal_p_gamma_rate(top, beta0, w3):
    """a' making p_alpha = p_gamma: I1 a' sin^2 b = p_g (1 - cos b), a' = p_g / (I1 (1 + cos b))."""
    return top["I3"] * w3 / (top["I1"] * (1 + math.cos(beta0)))


@pytest.mark.parametrize("w3", [6.0, 1.0])
def test_nearly_sleeping_top_with_p_alpha_equal_p_gamma(w3):
    """beta0 = 1e-8 (u0 = cos beta0 == 1 in double precision), beta-dot0 = 0, p_alpha = p_gamma.
    Stable (w3 = 6): the axis swings through the vertical, beta between +-1e-8. Unstable (w3 = 1):
    the top falls away from the vertical along (nearly) the separatrix."""
    beta0 = 1e-8
    ad0 = p_alpha_equal_p_gamma_rate(TOP, beta0, w3)
    init = (0.4, beta0, -0.2, ad0, 0.0, w3 - ad0 * math.cos(beta0))
    t = np.linspace(0, 1.5, 7)
    tr = heavy_top(*top_args(TOP, *init), t)
    w_ref, R_ref = mp_top(TOP, init, t)
    assert np.max(np.abs(tr.R - R_ref)) < 1e-12
    assert np.max(np.abs(tr.omega - w_ref)) < 1e-13 * w3
    if w3 == 6.0:
        # the tilt is 1e-8: its horizontal components must carry ~13 correct digits
        assert np.max(np.abs(tr.axis[:, :2] - R_ref[:, :2, 2])) < 1e-20
        assert tr.info["through_pole"]
        dense = heavy_top(*top_args(TOP, *init), np.linspace(0, 6, 601))
        assert np.max(np.abs(dense.beta)) <= beta0 * (1 + 1e-13) and np.min(dense.beta) < -0.99 * beta0
    else:
        assert tr.info["m1"] < 1e-14
        # it falls off the separatrix's unstable manifold: check the fall itself, ~16 s later
        t = np.array([16.0, 17.0, 18.0])
        tr = heavy_top(*top_args(TOP, *init), t)
        w_ref, R_ref = mp_top(TOP, init, t)
        assert np.max(np.abs(tr.R - R_ref)) < 1e-12 and tr.beta[-1] > 0.1


def test_motion_through_the_vertical_is_continuous():
    """p_alpha = p_gamma with the axis swinging through beta = 0: beta changes sign smoothly and
    alpha has no jump of pi; R agrees with the Cartesian integration across the passage."""
    beta0, w3 = 0.3, 6.0
    ad0 = p_alpha_equal_p_gamma_rate(TOP, beta0, w3)
    init = (0.4, beta0, -0.2, ad0, -2.0, w3 - ad0 * math.cos(beta0))
    t = np.linspace(0, 1.5, 7)
    tr = heavy_top(*top_args(TOP, *init), t)
    w_ref, R_ref = mp_top(TOP, init, t)
    assert np.max(np.abs(tr.R - R_ref)) < 1e-12
    assert np.max(np.abs(tr.omega - w_ref)) < 1e-13 * np.linalg.norm(w_ref[0])
    dense = heavy_top(*top_args(TOP, *init), np.linspace(0, 3, 3001))
    assert dense.beta.min() < -0.1 and dense.info["through_pole"]
    step = np.max(np.abs(np.diff(np.stack([dense.alpha, dense.beta, dense.gamma]), axis=1)))
    assert step < 0.05  # smooth at this sampling (1 ms): no pi jumps
    # the same motion started exactly at the vertical (beta0 = 0, beta-dot0 != 0)
    k = np.argmin(np.abs(dense.beta[:1500]))
    tr0 = heavy_top(*top_args(TOP, 0.0, 0.0, 0.0, 1.0, 2.0, w3 - 1.0), np.linspace(0, 1.5, 7))
    init0 = (0.0, 0.0, 0.0, 1.0, 2.0, w3 - 1.0)
    w_ref, R_ref = mp_top(TOP, init0, np.linspace(0, 1.5, 7))
    assert np.max(np.abs(tr0.R - R_ref)) < 1e-12 and tr0.info["through_pole"]
    assert k > 0


def test_passage_close_to_the_vertical_with_unequal_momenta():
    """p_alpha - p_gamma small but not zero: the axis passes ~2e-7 rad from the vertical while
    alpha turns by nearly pi in ~1e-7 s; the orientation is still exact."""
    beta0, w3 = 0.3, 6.0
    ad0 = p_alpha_equal_p_gamma_rate(TOP, beta0, w3) * (1 + 1e-6)
    init = (0.4, beta0, -0.2, ad0, -2.0, w3 - ad0 * math.cos(beta0))
    t = np.linspace(0, 1.5, 7)
    tr = heavy_top(*top_args(TOP, *init), t)
    w_ref, R_ref = mp_top(TOP, init, t)
    assert not tr.info["through_pole"]
    assert 0 < tr.info["y_roots"][0] < 1e-12  # closest approach sin^2(b/2)
    assert np.max(np.abs(tr.R - R_ref)) < 1e-12
    assert np.max(np.abs(tr.omega - w_ref)) < 1e-12 * np.linalg.norm(w_ref[0])
    assert np.all(tr.beta >= 0)


def test_passage_close_to_the_lowest_point():
    """Started below the horizontal with p_alpha + p_gamma small: the axis passes ~1e-5 rad from
    straight down (solved as the mirrored problem, the pole term's peak handled by the
    half-period shift)."""
    beta0, w3 = 2.8, 6.0
    b = TOP["I3"] * w3 / TOP["I1"]
    ad0 = -b / (1 - math.cos(beta0)) * (1 + 1e-9)
    init = (0.4, beta0, -0.2, ad0, 2.0, w3 - ad0 * math.cos(beta0))
    t = np.linspace(0, 1.5, 7)
    tr = heavy_top(*top_args(TOP, *init), t)
    assert tr.info["mirrored"] and not tr.info["through_pole"]
    assert 0 < tr.info["y_roots"][0] < 1e-9  # cos^2(b/2) at the lowest point
    w_ref, R_ref = mp_top(TOP, init, t)
    assert np.max(np.abs(tr.R - R_ref)) < 1e-12
    assert np.max(np.abs(tr.omega - w_ref)) < 1e-13 * np.linalg.norm(w_ref[0])
    assert np.all(tr.beta <= np.pi)


def test_heavy_top_without_gravity_is_the_free_symmetric_top():
    init = (0.2, 0.5, 0.1, 0.3, 1.0, 5.0)
    t = np.linspace(0, 100, 51)
    tr = heavy_top(*top_args({**TOP, "g": 0.0}, *init), t)
    free = free_symmetric(TOP["I1"], TOP["I3"], tr.omega[0], t, euler_matrix(*init[:3]))
    assert np.max(np.abs(tr.R - free.R)) < 1e-12 and np.max(np.abs(tr.omega - free.omega)) < 1e-13 * 5


def test_euler_angle_extraction_inverts_the_matrix():
    a, b, g = np.array([0.3, -2.0, 3.0]), np.array([0.2, 1.0, 3.1]), np.array([-1.0, 0.5, 2.9])
    out = euler_angles(euler_matrix(a, b, g), unwrap=False)
    for x, y in zip(out, (a, b, g)):
        assert np.max(np.abs(x - y)) < 1e-13


def test_heavy_top_rejects_bad_input():
    with pytest.raises(ValueError):
        heavy_top(0.0, 0.5, 1, 9.81, 0.1, 0, 0.5, 0, 0, 0, 1, [0.0])
    with pytest.raises(ValueError):
        heavy_top(1.0, 0.5, 1, 9.81, math.inf, 0, 0.5, 0, 0, 0, 1, [0.0])
    with pytest.raises(ValueError):
        heavy_top(1.0, 0.5, 1, 9.81, 0.1, 0, 0.5, 0, 0, 0, 1, [[0.0, 1.0]])


@pytest.mark.slow
@pytest.mark.parametrize("name", ["near-separatrix-above", "near-separatrix-below", "separatrix", "polar-largest"])
def test_free_asymmetric_over_a_full_tumbling_period(name):
    # ~one full period near the separatrix (4K/lam ~ 75 here): the slow passages by the unstable
    # axis and the fast flips between them
    I, w0 = ASYMMETRIC_CASES[name]
    R0 = euler_matrix(0.3, 0.7, -0.4)
    t = np.linspace(0, 80, 9)
    tr = free_asymmetric(*I, w0, t, R0)
    w_ref, R_ref = mp_rigid(I, 0.0, list(w0) + mp_euler_state(0.3, 0.7, -0.4, 0, 0, 0)[3:], t)
    assert np.max(np.abs(tr.omega - w_ref)) < 1e-13 * np.linalg.norm(w0)
    assert np.max(np.abs(tr.R - R_ref)) < 1e-12


@pytest.mark.slow
@pytest.mark.parametrize("name", ["fast-top", "looping", "hanging"])
def test_heavy_top_over_many_nutation_periods(name):
    over, init = HEAVY_CASES[name]
    top = {**TOP, **over}
    t = np.linspace(0, 20, 5)
    tr = heavy_top(*top_args(top, *init), t)
    w_ref, R_ref = mp_top(top, init, t)
    assert np.max(np.abs(tr.omega - w_ref)) < 1e-13 * np.linalg.norm(w_ref[0])
    assert np.max(np.abs(tr.R - R_ref)) < 1e-12
