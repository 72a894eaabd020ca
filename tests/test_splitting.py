"""The Lie–Poisson splitting integrators (derive/splitting.py, templates/c/splitting.c.j2).

Each step composes exact flows, so the checks are: the free flow *is* the exact torque-free
solution (derive.exact) for any step size, the compositions converge at their declared orders
(slopes of log error vs log h, against the exact Lagrange top and a tight DOP853 run), and the
geometric invariants |n| = |e| = 1, n·e = 0, L·n stay at round-off for steps far too large to
be accurate.
"""
from __future__ import annotations

import numpy as np
import pytest

from derive import exact, models, splitting
from derive.cbuild import STRICT_FLAGS, check_compiles

VARIANTS = [(True, ("gravity",)), (False, ("gravity_general",)), (True, ("gravity_general",)),
            (False, ()), (True, ())]
R0 = exact.euler_matrix(0.3, 1.1, -0.4)


@pytest.fixture(scope="module")
def splitters():
    cache = {}

    def get(symmetric, effects):
        key = (symmetric, tuple(effects))
        if key not in cache:
            cache[key] = splitting.Splitter(models.build("euler-poisson", symmetric, effects))
        return cache[key]
    return get


def _exact_state(sp, p, traj):
    """The model's state along an exact trajectory."""
    return np.stack([splitting.initial_state(sp.model, p, w, R) for w, R in zip(traj.omega, traj.R)])


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
    for m in splitting.METHODS.values():
        ops = m.composition.ops()
        for kind in ("free", "kick"):
            assert abs(sum(c for k, c in ops if k == kind) - 1) < 1e-24
        assert int(m.name[-1]) == m.order


@pytest.mark.parametrize("symmetric,effects", VARIANTS)
def test_generated_c_is_strict_c99(symmetric, effects):
    model = models.build("euler-poisson", symmetric, effects)
    files, unity = splitting.sources(model)
    # The splitting file stands alone; once, the whole translation unit (no name clashes with
    # the model's own solvers).
    mains = [f"{model.name}_splitting.c"] + ([unity] if effects == ("gravity_general",) and not symmetric else [])
    check_compiles(files, mains, STRICT_FLAGS)


def test_applicable_only_to_conservative_euler_poisson_models():
    assert splitting.applicable(models.build("euler-poisson", False, ("gravity_general",))) is None
    why = splitting.applicable(models.build("quaternion", False, ("gravity_general",)))
    assert "euler-poisson" in why
    damped = models.build("euler-poisson", False, ("gravity_general", "damping"))
    assert "damping" in splitting.applicable(damped)
    with pytest.raises(ValueError, match="damping"):
        splitting.render_splitting(damped)
    with pytest.raises(ValueError, match="unknown splitting method"):
        splitting.render_splitting(models.build("euler-poisson", True, ()), ["splitting3"])


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
    y0 = splitting.initial_state(sp.model, p, (0.3, -0.2, 5.0), exact.euler_matrix(0.1, 0.6, 0.2))
    t = np.array([0.0, 2.0])
    ref = sp.kernel.solve("dop853", y0, p, t, rtol=1e-14, atol=1e-16).y[-1]
    for method, hs in (("splitting2", [0.1, 0.05, 0.025]), ("splitting4", [0.1, 0.05, 0.025]),
                       ("splitting6", [0.1, 0.05, 0.025])):
        errs = [np.abs(sp.solve(method, y0, p, t, h)[0][-1] - ref).max() for h in hs]
        order = splitting.METHODS[method].order
        assert abs(_slope(hs, errs) - order) < 0.3, (method, errs)
        assert errs[-1] > 1e-12


# --------------------------------------------------------------------------------------------
# invariants for any h


@pytest.mark.parametrize("symmetric,effects,p", [
    (False, ("gravity_general",), (1.0, 1.5, 2.0, 1.0, 9.81, 0.05, 0.02, 0.1)),
    (True, ("gravity",), (1.0, 0.5, 1.0, 9.81, 0.2)),
])
@pytest.mark.parametrize("method", list(splitting.METHODS))
def test_geometric_invariants_at_round_off_for_large_steps(splitters, symmetric, effects, p, method):
    sp = splitters(symmetric, effects)
    y0 = splitting.initial_state(sp.model, p, (1.3, -0.8, 6.0), R0)
    t = np.linspace(0.0, 100.0, 11)
    y, st = sp.solve(method, y0, p, t, 0.5)   # 200 steps, each far too long to be accurate
    assert st["status"] == 0 and st["nstep"] == 200
    L, n, e = splitting.angular_momentum(sp.model, p, y), y[:, 3:6], y[:, 6:]
    # Round-off only: up to 1800 rotations (200 steps x 9 stages) at a fraction of an ulp each.
    tol = 4e-14
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
    y0 = splitting.initial_state(sp.model, p, (0.3, -0.2, 5.0), exact.euler_matrix(0.1, 0.6, 0.2))
    t = np.linspace(0.0, 2000.0, 4001)
    y, st = sp.solve("splitting4", y0, p, t, 0.05)
    de = np.abs(splitting.energy(sp.model, p, y) - splitting.energy(sp.model, p, y0))
    first, last = de[: len(de) // 10].max(), de[-len(de) // 10:].max()
    assert last < 2.0 * first and first > 0


# --------------------------------------------------------------------------------------------
# the C API


def test_batch_is_bitwise_the_single_runs_and_bad_input_is_reported(splitters):
    sp = splitters(False, ("gravity_general",))
    p = np.array([1.0, 1.5, 2.0, 1.0, 9.81, 0.05, 0.02, 0.1])
    y0s = np.stack([splitting.initial_state(sp.model, p, (0.3, -0.2, w3), R0) for w3 in (2.0, 5.0, 9.0)])
    t = np.linspace(0.0, 3.0, 7)
    yb, stb = sp.solve_batch("splitting4", y0s, p, t, 0.01)
    for b in range(3):
        y, st = sp.solve("splitting4", y0s[b], p, t, 0.01)
        assert np.array_equal(y, yb[b]) and st["nstep"] == stb[b]["nstep"] == 300
    assert stb[0]["nfev"] == 300 * 6  # 5 Strang stages: 6 merged kicks per step
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
    # The measurement the bench reports (timings are reported, never asserted).
    r = splitting.bench_energy("lagrange", periods=20, target=1e-6, methods=("splitting4", "dop853"),
                               repeat=1, samples=97, measure="axis")
    for m in ("splitting4", "dop853"):
        assert r[m] is not None and r[m]["error"] <= 1e-6 and r[m]["seconds"] > 0
    assert r["ratio_dop853"] > 0
    with pytest.raises(ValueError, match="unknown benchmark case"):
        splitting.bench_case("spinning-plate")


def test_simulate_drivers_and_interrupt_in_the_kernel_translation_unit(splitters):
    # Compiled after <prefix>_solvers.c, the splitting methods get the whole-simulation drivers
    # (init map, solve, outputs) and poll the kernel's interrupt flag.
    import ctypes

    from derive.status import Status

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
        fn = getattr(lib, f"{P}_simulate_{m}")
        fn.argtypes = [f64, f64, f64, ctypes.c_long, *cty, f64, f64, ctypes.c_void_p]
        y_work, out = np.zeros(len(t) * 9), np.zeros(nobs * len(t))
        assert fn(inp, p.copy(), t, len(t), *extra, y_work, out, None) == 0
        outs[m] = out
        if m == "splitting4":
            y, _ = sp.solve(m, y_work[:9], p, t, 0.001)
            assert np.array_equal(y.ravel(), y_work)
    assert np.abs(outs["splitting4"] - outs["rk4"]).max() < 1e-6 * np.abs(outs["rk4"]).max()
    lib_req = getattr(lib, f"{P}_interrupt_request")
    guard = getattr(lib, f"{P}_interrupt_guard")
    guard.argtypes = [ctypes.c_int]
    lib_req()
    try:
        y, st = sp.solve("splitting4", y_work[:9], p, t, 0.001)
        assert st["status"] == Status.INTERRUPTED and st["nstep"] == 0
    finally:
        guard(0)  # clears the flag
    assert sp.solve("splitting4", y_work[:9], p, t, 0.001)[1]["status"] == 0
