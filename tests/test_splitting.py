"""The Lie–Poisson splitting integrators (derive/methods/splitting.py, templates/c/splitting.c.j2).

Each step composes exact flows, so the checks are: the free flow *is* the exact torque-free
solution (derive.reference.exact) for any step size, the compositions converge at their declared orders
(slopes of log error vs log h, against the exact Lagrange top and a tight DOP853 run), and the
geometric invariants |n| = |e| = 1, n·e = 0, L·n stay at round-off for steps far too large to
be accurate.
"""
from __future__ import annotations

from fractions import Fraction as F
from pathlib import Path

import numpy as np
import pytest

from derive.reference import exact
from derive.symbolic import models
from derive.bench import splitting as bsplit
from derive.codegen import splitting as csplit
from derive.methods import splitting
from derive.runtime import splitter
from derive.runtime.cbuild import STRICT_FLAGS
from compile_once import compiles_once
from kept_results import kept

VARIANTS = [(True, ("gravity",)), (False, ("gravity_general",)), (True, ("gravity_general",)),
            (False, ()), (True, ())]
R0 = exact.euler_matrix(0.3, 1.1, -0.4)


@pytest.fixture(scope="module")
def splitters():
    cache = {}

    def get(symmetric, effects):
        key = (symmetric, tuple(effects))
        if key not in cache:
            cache[key] = splitter.Splitter(models.build("euler-poisson", symmetric, effects))
        return cache[key]
    return get


def _exact_state(sp, p, traj):
    """The model's state along an exact trajectory."""
    return np.stack([splitter.initial_state(sp.model, p, w, R) for w, R in zip(traj.omega, traj.R)])


# --------------------------------------------------------------------------------------------
# data and rendering


def test_composition_weights_satisfy_their_order_conditions():
    # Symmetric compositions of a symmetric order-2 method: sum = 1; order 4 needs sum g^3 = 0;
    # order 6 also sum g^5 = 0 (plus a condition on brackets, checked by the slopes below).
    for c in splitting.COMPOSITIONS.values():
        g = c.gammas
        assert abs(float(sum(g)) - 1) < 1e-24
        if c.order >= 4:
            assert abs(float(sum(x**3 for x in g))) < 1e-24
        if c.order >= 6:
            assert abs(float(sum(x**5 for x in g))) < 1e-24
    for m in splitting.METHODS.values():  # (consistency and symmetry: Splitting's constructor)
        assert int(m.name[-1]) == m.order
    # A composition is the BAB splitting with the adjacent half kicks merged.
    ops = splitting.COMPOSITIONS["triple-jump"].ops()
    g = splitting.COMPOSITIONS["triple-jump"].gammas
    assert [k for k, _ in ops] == ["kick", "free"] * 3 + ["kick"]
    assert [c for _, c in ops] == [g[0] / 2, g[0], (g[0] + g[1]) / 2, g[1], (g[1] + g[2]) / 2, g[2], g[2] / 2]
    with pytest.raises(ValueError, match="symmetric"):
        splitting.Splitting("x", 2, (F(1, 3), F(2, 3)), (F(1),))
    with pytest.raises(ValueError, match="sum to 1"):
        splitting.Splitting("x", 2, (F(1, 2), F(1, 2)), (F(1, 2),))


def _rkn_pair(mp):
    """q' = p, p' = −(K₀ + εK₁) q as A + εB: A = [[0, I], [−K₀, 0]], B = [[0, 0], [−K₁, 0]].
    B² = 0 and [B, [B, [B, A]]] = 0, the structure of the rigid body's split (H_V depends on n
    alone, {n_i, n_j} = 0, H_T is quadratic in L)."""
    K0, K1 = ((2.0, 0.3), (0.3, 1.1)), ((0.7, -0.4), (-0.4, 1.3))
    A, B = mp.zeros(4), mp.zeros(4)
    for i in range(2):
        A[i, i + 2] = 1
        for j in range(2):
            A[i + 2, j], B[i + 2, j] = -K0[i][j], -K1[i][j]
    return A, B


def _local_errors_by_power_of_eps(mp, scheme, A, B, h, powers=3, K=6, r=0.05):
    """‖E_j‖ for j = 1..powers, where Φ_h − exp(h(A + εB)) = Σ ε^j E_j(h) (Φ_h the scheme's step
    with exp(c h A) for "free" and exp(c h ε B) for "kick"), each E_j from K values of ε on a
    circle of radius r (discrete Fourier transform; aliasing from E_{j+K} is r^K smaller)."""
    ops = scheme.ops()
    exp_a = {c: mp.expm(A * (c * h)) for k, c in ops if k == "free"}
    errs = []
    for k in range(K):
        eps = r * mp.expjpi(mp.mpf(2 * k) / K)
        step = mp.eye(A.rows)
        for kind, c in ops:
            step = (exp_a[c] if kind == "free" else mp.expm(B * (eps * c * h))) * step
        errs.append(step - mp.expm((A + eps * B) * h))
    return [mp.mnorm(sum((errs[k] * mp.expjpi(-mp.mpf(2 * j * k) / K) for k in range(K)),
                         mp.zeros(A.rows)) / (K * mp.mpf(r) ** j), 1)
            for j in range(1, powers + 1)]


@pytest.mark.parametrize("name", list(splitting.SCHEMES))
def test_schemes_meet_their_order_conditions_on_a_linear_system(name):
    # Local error of one step, split by powers of the perturbation: O(ε^j h^(p_j + 1)) with
    # p_j = the scheme's ε-orders (classical order p for the terms beyond them). Measured as the
    # slope between h = 0.2 and 0.1, at 40 digits.
    import mpmath

    # (the slopes depend on the step's sub-flows alone: kept between test runs under them and this
    # file's bytes, tests/kept_results.py)
    scheme = splitting.SCHEMES[name]

    def slopes_at_40_digits():
        with mpmath.workdps(40):
            A, B = _rkn_pair(mpmath)
            e1, e2 = (_local_errors_by_power_of_eps(mpmath, scheme, A, B, mpmath.mpf(h)) for h in ("0.2", "0.1"))
            return [float(mpmath.log(a / b, 2)) for a, b in zip(e1, e2)]

    slopes = kept("splitting-order-slopes", tuple(scheme.ops()), slopes_at_40_digits, [Path(__file__)])
    claimed = list(scheme.eps_orders) + [scheme.order] * (3 - len(scheme.eps_orders))
    for j, (s, p) in enumerate(zip(slopes, claimed), start=1):
        assert s > p + 1 - 0.3, (name, j, slopes)
        if scheme.eps_orders:  # a method designed for ε-orders has exactly those
            assert s < p + 1 + 0.3, (name, j, slopes)
    if name == "mclachlan-s5":  # a plain composition: its ε-linear error is O(h⁵), the control
        assert slopes[0] < 5.5


@pytest.mark.parametrize("name", [n for n, s in splitting.SCHEMES.items() if s.eps_orders])
def test_near_integrable_schemes_are_quadratures_of_their_eps_order(name):
    # The ε-linear error of an ABA method vanishes to O(h^p₁) iff its kicks (times cᵢ inside the
    # step, weights bᵢ) integrate polynomials of degree < p₁ exactly: Σ bᵢ cᵢᵏ = 1/(k + 1). Exact
    # arithmetic on the published 40-digit coefficients.
    scheme = splitting.SCHEMES[name]
    t, nodes = F(0), []
    for kind, c in scheme.ops():
        if kind == "free":
            t += c
        else:
            nodes.append((t, c))
    p1 = scheme.eps_orders[0]
    for k in range(p1):
        assert abs(sum(w * x**k for x, w in nodes) - F(1, k + 1)) < F(1, 10**38), k
    assert abs(sum(w * x**p1 for x, w in nodes) - F(1, p1 + 1)) > F(1, 10**9)


@pytest.mark.parametrize("symmetric,effects", [v if i < 2 else pytest.param(*v, marks=pytest.mark.slow)
                                              for i, v in enumerate(VARIANTS)])  # a symmetric and a general body
def test_generated_c_is_strict_c99(symmetric, effects):
    model = models.build("euler-poisson", symmetric, effects)
    files, unity = splitter.sources(model)
    # The splitting file stands alone; once, the whole translation unit (no name clashes with
    # the model's own solvers).
    mains = [f"{model.name}_splitting.c"] + ([unity] if effects == ("gravity_general",) and not symmetric else [])
    compiles_once(files, mains, STRICT_FLAGS)  # kept for these exact sources (tests/compile_once.py)


def test_applicable_only_to_conservative_euler_poisson_models():
    assert splitting.applicable(models.build("euler-poisson", False, ("gravity_general",))) is None
    why = splitting.applicable(models.build("quaternion", False, ("gravity_general",)))
    assert "euler-poisson" in why
    damped = models.build("euler-poisson", False, ("gravity_general", "damping"))
    assert "damping" in splitting.applicable(damped)
    with pytest.raises(ValueError, match="damping"):
        csplit.render_splitting(damped)
    with pytest.raises(ValueError, match="unknown splitting method"):
        csplit.render_splitting(models.build("euler-poisson", True, ()), ["splitting3"])


# --------------------------------------------------------------------------------------------
# the free flow is exact


@pytest.mark.parametrize("I,w0", [
    ((1.0, 2.0, 3.0), (0.5, 1.2, -0.7)),    # circulating about the largest axis
    ((1.0, 2.0, 3.0), (2.0, 0.3, 0.2)),     # ... about the smallest
    ((3.0, 1.0, 2.0), (-0.4, 2.5, 0.9)),    # moments in another order
    ((1.0, 1.0, 3.0), (0.5, 1.2, -0.7)),    # two equal moments, in the asymmetric model
    ((2.0, 1.0, 1.0), (0.5, 1.2, -0.7)),
    ((1.0, 2.0, 3.0), (0.0, 0.0, 2.0)),     # steady rotation about a principal axis
])
@pytest.mark.parametrize("h", [0.05, 0.7, 9.0])
def test_asymmetric_free_flow_is_the_exact_solution(splitters, I, w0, h):
    sp = splitters(False, ())
    t = np.linspace(0.0, 27.0, 28)
    ref = _exact_state(sp, I, exact.free_asymmetric(*I, np.array(w0), t, R0))
    y, st = sp.solve("splitting2", ref[0], I, t, h)
    assert st["status"] == 0
    # Round-off: each step perturbs |L| (and so the precession rate) by ~eps, a random walk.
    tol = 2e-13 * max(1.0, np.sqrt(st["nstep"] / 100)) * max(1.0, np.abs(ref[:, :3]).max())
    assert np.abs(y - ref).max() < tol


@pytest.mark.parametrize("eps", [1e-8, 1e-12])
def test_near_the_separatrix_the_free_flow_is_as_good_as_the_problem_allows(splitters, eps):
    # m1 ~ 2 eps: a perturbation of the state by one ulp moves the flips by ~ulp/m1, so every
    # integrator restarted from rounded states drifts; the splitting stays within a few times
    # DOP853 at rtol 1e-13 (each free flow restarts the elliptic solution from the state).
    sp = splitters(False, ())
    I = (1.0, 2.0, 3.0)
    w0 = np.array([np.sqrt(3) * 0.5 * (1 + eps), 0.1, 0.5])  # L^2 = 2E I2 at eps = 0
    t = np.linspace(0.0, 40.0, 81)
    tr = exact.free_asymmetric(*I, w0, t, R0)
    assert tr.info["m1"] < 3 * eps
    ref = _exact_state(sp, I, tr)
    dop = np.abs(sp.kernel.solve("dop853", ref[0], I, t, rtol=1e-13, atol=1e-15).y - ref).max()
    for h in (0.05, 1.0):
        y, st = sp.solve("splitting2", ref[0], I, t, h)
        assert st["status"] == 0 and np.abs(y - ref).max() < 10 * dop


@pytest.mark.parametrize("h", [0.03, 1.3])
def test_symmetric_free_flow_is_the_exact_solution(splitters, h):
    sp = splitters(True, ())
    I1, I3, w0 = 1.5, 0.6, np.array([0.8, -1.1, 7.0])
    t = np.linspace(0.0, 30.0, 31)
    ref = _exact_state(sp, (I1, I3), exact.free_symmetric(I1, I3, w0, t, R0))
    y, st = sp.solve("splitting4", ref[0], (I1, I3), t, h)
    assert st["status"] == 0
    assert np.abs(y - ref).max() < 1e-13 * np.abs(ref[:, :3]).max()


# --------------------------------------------------------------------------------------------
# orders


def _slope(hs, errs):
    return float(np.polyfit(np.log(hs), np.log(errs), 1)[0])


def test_orders_on_the_lagrange_top_against_the_exact_solution(splitters):
    sp = splitters(True, ("gravity",))
    I1, I3, M, g, l = 1.0, 0.5, 1.0, 9.81, 0.2
    a0, b0, c0, ad0, bd0, gd0 = 0.2, 0.7, 0.1, 1.0, 0.4, 9.0
    T = 1.5
    tr = exact.heavy_top(I1, I3, M, g, l, a0, b0, c0, ad0, bd0, gd0, np.array([0.0, T]))
    p = (I1, I3, M, g, l)
    ref = _exact_state(sp, p, tr)
    for method, hs in (("splitting2", [0.02, 0.01, 0.005]), ("splitting4", [0.1, 0.05, 0.025]),
                       ("splitting6", [0.15, 0.1, 0.075])):
        errs = []
        for h in hs:
            y, st = sp.solve(method, ref[0], p, [0.0, T], h)
            errs.append(np.abs(y[-1] - ref[-1]).max())
        order = splitting.METHODS[method].order
        assert abs(_slope(hs, errs) - order) < 0.3, (method, errs)
        assert errs[-1] > 1e-12  # still in the asymptotic range, not at round-off


def test_orders_on_an_off_axis_asymmetric_top_against_dop853(splitters):
    sp = splitters(False, ("gravity_general",))
    p = np.array([1.0, 1.5, 2.0, 1.0, 9.81, 0.05, 0.02, 0.1])
    y0 = splitter.initial_state(sp.model, p, (0.3, -0.2, 5.0), exact.euler_matrix(0.1, 0.6, 0.2))
    t = np.array([0.0, 2.0])
    ref = sp.kernel.solve("dop853", y0, p, t, rtol=1e-14, atol=1e-16).y[-1]
    for method, hs in (("splitting2", [0.1, 0.05, 0.025]), ("splitting4", [0.1, 0.05, 0.025]),
                       ("splitting6", [0.1, 0.05, 0.025])):
        errs = [np.abs(sp.solve(method, y0, p, t, h)[0][-1] - ref).max() for h in hs]
        order = splitting.METHODS[method].order
        assert abs(_slope(hs, errs) - order) < 0.3, (method, errs)
        assert errs[-1] > 1e-12


@pytest.mark.parametrize("method", list(splitting.METHODS))
def test_merged_steps_and_the_lagrange_top_shortcut_change_round_off_only(splitters, method):
    # Within an output interval the last sub-flow of a step is merged with the first of the next,
    # and for the Lagrange top (axial gravity) the free flows' turns about body axis 3 are applied
    # once per interval. One interval of 10 steps against 10 one-step intervals (nothing merged),
    # and against the same top as a general centre of mass (0, 0, l) (no shortcut).
    axial, general = splitters(True, ("gravity",)), splitters(True, ("gravity_general",))
    I1, I3, M, g, l = 1.0, 0.5, 1.0, 9.81, 0.2
    p_ax, p_gen = (I1, I3, M, g, l), (I1, I3, M, g, 0.0, 0.0, l)
    y0 = splitter.initial_state(axial.model, p_ax, (0.7, -0.3, 9.0), R0)
    T, n = 2.0, 10
    one, st1 = axial.solve(method, y0, p_ax, [0.0, T], T / n)
    many, stn = axial.solve(method, y0, p_ax, np.linspace(0.0, T, n + 1), T / n)
    gen, _ = general.solve(method, y0, p_gen, [0.0, T], T / n)
    assert st1["nstep"] == stn["nstep"] == n
    scale = np.abs(y0).max()
    assert np.abs(one[-1] - many[-1]).max() < 1e-12 * scale
    assert np.abs(one[-1] - gen[-1]).max() < 1e-12 * scale
    # ... while the step is far from converged: the comparison is not between exact solutions
    fine, _ = axial.solve(method, y0, p_ax, [0.0, T], T / (8 * n))
    assert np.abs(fine[-1] - one[-1]).max() > 1e-9 * scale


# --------------------------------------------------------------------------------------------
# invariants for any h


@pytest.mark.parametrize("symmetric,effects,p", [
    (False, ("gravity_general",), (1.0, 1.5, 2.0, 1.0, 9.81, 0.05, 0.02, 0.1)),
    (True, ("gravity",), (1.0, 0.5, 1.0, 9.81, 0.2)),
])
@pytest.mark.parametrize("method", list(splitting.METHODS))
def test_geometric_invariants_at_round_off_for_large_steps(splitters, symmetric, effects, p, method):
    sp = splitters(symmetric, effects)
    y0 = splitter.initial_state(sp.model, p, (1.3, -0.8, 6.0), R0)
    t = np.linspace(0.0, 100.0, 11)
    y, st = sp.solve(method, y0, p, t, 0.5)   # 200 steps, each far too long to be accurate
    assert st["status"] == 0 and st["nstep"] == 200
    L, n, e = splitter.angular_momentum(sp.model, p, y), y[:, 3:6], y[:, 6:]
    # Round-off only: up to 1800 rotations (200 steps x 9 stages) at a fraction of an ulp each.
    tol = 2e-14
    assert np.abs(np.linalg.norm(n, axis=1) - 1).max() < tol
    assert np.abs(np.linalg.norm(e, axis=1) - 1).max() < tol
    assert np.abs(np.sum(n * e, axis=1)).max() < tol
    Ln = np.sum(L * n, axis=1)
    assert np.abs(Ln - Ln[0]).max() < tol * np.abs(L).max()
    # ... while the trajectory itself is far from converged (the step is not small)
    fine, _ = sp.solve(method, y0, p, t, 0.01)
    assert np.abs(fine[-1] - y[-1]).max() > 1e-6


def test_energy_error_stays_bounded_over_long_runs(splitters):
    # Poisson integrator: energy oscillates at O(h^4), no secular drift.
    sp = splitters(False, ("gravity_general",))
    p = np.array([1.0, 1.5, 2.0, 1.0, 9.81, 0.05, 0.02, 0.1])
    y0 = splitter.initial_state(sp.model, p, (0.3, -0.2, 5.0), exact.euler_matrix(0.1, 0.6, 0.2))
    t = np.linspace(0.0, 2000.0, 4001)
    y, st = sp.solve("splitting4", y0, p, t, 0.05)
    de = np.abs(splitter.energy(sp.model, p, y) - splitter.energy(sp.model, p, y0))
    first, last = de[: len(de) // 10].max(), de[-len(de) // 10:].max()
    assert last < 2.0 * first and first > 0


# --------------------------------------------------------------------------------------------
# the C API


def test_batch_is_bitwise_the_single_runs_and_bad_input_is_reported(splitters):
    sp = splitters(False, ("gravity_general",))
    p = np.array([1.0, 1.5, 2.0, 1.0, 9.81, 0.05, 0.02, 0.1])
    y0s = np.stack([splitter.initial_state(sp.model, p, (0.3, -0.2, w3), R0) for w3 in (2.0, 5.0, 9.0)])
    t = np.linspace(0.0, 3.0, 7)
    yb, stb = sp.solve_batch("splitting4", y0s, p, t, 0.01)
    for b in range(3):
        y, st = sp.solve("splitting4", y0s[b], p, t, 0.01)
        assert np.array_equal(y, yb[b]) and st["nstep"] == stb[b]["nstep"] == 300
    assert stb[0]["nfev"] == 300 * 8  # ABA(10,6,4): 8 kicks per step (and 8 merged free flows)
    bad = p.copy()
    bad[1] = -1.0
    assert sp.solve("splitting4", y0s[0], bad, t, 0.01)[1]["status"] == 6      # moment <= 0
    assert sp.solve("splitting4", y0s[0], p, t, 0.0)[1]["status"] == 6         # h = 0
    assert sp.solve("splitting4", y0s[0], p, t[::-1], 0.01)[1]["status"] == 6  # t decreasing
    y0n = y0s[0].copy()
    y0n[4] = np.nan
    y, st = sp.solve("splitting4", y0n, p, t, 0.01)
    assert st["status"] == 2 and st["fail_index"] == 4


def test_bench_finds_settings_that_meet_the_target():
    # Only that the scan finds, within its time budget, a setting of each method whose run meets
    # the target (the row reports that run); timings are reported, never asserted.
    r = bsplit.bench_energy("lagrange", periods=20, target=1e-6, methods=("splitting4", "dop853"),
                               repeat=1, samples=97, measure="axis")
    for m in ("splitting4", "dop853"):
        assert r[m] is not None and r[m]["error"] <= 1e-6
    with pytest.raises(ValueError, match="unknown benchmark case"):
        bsplit.bench_case("spinning-plate")


def test_simulate_drivers_and_interrupt_in_the_kernel_translation_unit(splitters):
    # Compiled after <prefix>_solvers.c, the splitting methods get the whole-simulation drivers
    # (init map, solve, outputs) and poll the kernel's interrupt flag.
    import ctypes

    from derive.methods.status import Status
    from derive.runtime.records import SaveAt, saveat

    sp = splitters(False, ("gravity_general",))
    lib, P = sp.lib, sp.model.name
    dims = (ctypes.c_int * 4).in_dll(lib, f"{P}_dims")
    nobs, nin = dims[2], dims[3]
    p = np.array([1.0, 1.5, 2.0, 1.0, 9.81, 0.05, 0.02, 0.1])
    inp = np.array([0.3, 1.1, -0.4, 1.3, -0.8, 6.0, 0.0, 0.0, 0.0, 0.0])[:nin]
    t = np.linspace(0.0, 2.0, 5)
    f64 = np.ctypeslib.ndpointer(dtype=np.float64, flags="C_CONTIGUOUS")
    outs = {}
    for m, extra, cty in (("splitting4", (0.001,), [ctypes.c_double]), ("rk4", (0.001,), [ctypes.c_double])):
        fn = lib[f"{P}_run_{m}"]  # (a fresh function object: the splitter keeps its own)
        fn.argtypes = [ctypes.POINTER(SaveAt), ctypes.c_long, f64, f64, *cty, f64, f64, ctypes.c_void_p]
        y_work, out = np.zeros(len(t) * 9), np.zeros(nobs * len(t))
        assert fn(saveat(t), 1, inp, p.copy(), *extra, y_work, out, None) == 0
        outs[m] = out
        if m == "splitting4":
            y, _ = sp.solve(m, y_work[:9], p, t, 0.001)
            assert np.array_equal(y.ravel(), y_work)
    assert np.abs(outs["splitting4"] - outs["rk4"]).max() < 1e-6 * np.abs(outs["rk4"]).max()
    lib_req = lib.derive_sigint_request
    guard = lib.derive_sigint_guard
    guard.argtypes = [ctypes.c_int]
    lib_req()
    try:
        y, st = sp.solve("splitting4", y_work[:9], p, t, 0.001)
        assert st["status"] == Status.INTERRUPTED and st["nstep"] == 0
    finally:
        guard(0)  # clears the flag
    assert sp.solve("splitting4", y_work[:9], p, t, 0.001)[1]["status"] == 0


def test_carlson_integrals_in_c_against_mpmath():
    """The C R_J (duplication with cancellation-free R_C(1, 1 + e) terms), R_C and R_F of
    derive_elliptic.h against mpmath at 50 digits: small and large p, a zero argument, and the
    R_C series / arctan / logarithm branches up to e -> -1."""
    import ctypes

    import mpmath

    from derive.runtime.cbuild import DEFAULT_FLAGS, compile_library
    from derive.codegen.render import GENERATED

    harness = ('#include <math.h>\n#include "derive_elliptic.h"\n'
               "double t_rj(double x, double y, double z, double p) { return derive_carlson_rj(x, y, z, p); }\n"
               "double t_rf(double x, double y, double z) { return derive_carlson_rf(x, y, z); }\n"
               "double t_rc1(double e, double ope) { return derive_carlson_rc1(e, ope); }\n")
    lib = compile_library("derive_test_carlson", {
        "derive_elliptic.h": (GENERATED / "c" / "derive_elliptic.h").read_text(),
        "harness.c": harness}, "harness.c", list(DEFAULT_FLAGS))
    for name, n in (("t_rj", 4), ("t_rf", 3), ("t_rc1", 2)):
        getattr(lib, name).restype = ctypes.c_double
        getattr(lib, name).argtypes = [ctypes.c_double] * n
    with mpmath.workdps(50):  # not mp.dps: other tests share the process
        _carlson_cases(lib, mpmath)


def _carlson_cases(lib, mpmath):
    for x, y, z, p in [(1.0, 2.0, 3.0, 0.5), (0.0, 1.0, 2.0, 1e-9), (0.3, 0.7, 1.1, 1.0 - 1e-12),
                       (2.0, 3.0, 4.0, 1e3), (1e-6, 1.0, 1.0, 0.2), (0.5, 0.5, 4.0, 0.5)]:
        want = float(mpmath.elliprj(x, y, z, p))
        assert lib.t_rj(x, y, z, p) == pytest.approx(want, rel=4e-15), (x, y, z, p)
        assert lib.t_rf(x, y, z) == pytest.approx(float(mpmath.elliprf(x, y, z)), rel=4e-15)
    for e in (1e-4, -1e-4, 1e-3, -1e-3, 0.5, -0.5, 40.0, -1.0 + 1e-12):
        ope = float(mpmath.mpf(1) + mpmath.mpf(e))
        want = float(mpmath.elliprc(1, mpmath.mpf(1) + mpmath.mpf(e)))
        assert lib.t_rc1(e, ope) == pytest.approx(want, rel=4e-15), e
