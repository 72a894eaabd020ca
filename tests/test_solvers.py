"""The generated C solvers, run on hand-written test models (tests/c/, the model ABI).

osc     harmonic oscillator x'' = -w^2 x: exact solution, quadratic energy
free3   torque-free Euler equations: nonlinear, two quadratic invariants
blowup  u' = k u^2: finite-time blow-up at t = 1/(k u0)
tank    level' = -rate, rhs returns 1 for level < 0: leaves its domain at t = level0/rate
"""
from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from derive.runtime import cbuild
from derive.runtime.cbuild import (SANITIZE_FLAGS, STRICT_FLAGS, check_compiles, compile_library)
from derive.errors import CompilerError, IntegrationError
from derive.runtime.kernel import Kernel
from derive.methods.registry import METHODS
from derive.codegen.solvers import render_solvers
from derive.methods.status import Status
from derive.methods.tableaux import DOP853, RK4
from tests.compile_once import once

C_DIR = Path(__file__).parent / "c"
MODELS = {"osc": 2, "free3": 3, "blowup": 1, "tank": 2}
FIXED = {"rk4": 4, "gauss4": 4, "gauss6": 6}
STEP_ARGS = {"dop853": {}, "rk4": {"h": 0.01}, "gauss4": {"h": 0.02}, "gauss6": {"h": 0.05},
             "dop853_fixed": {"h": 0.1}}


def model_sources(name: str) -> dict[str, str]:
    return {f"{name}.h": (C_DIR / f"{name}.h").read_text(),
            f"{name}.c": (C_DIR / f"{name}.c").read_text()}


@pytest.fixture(scope="module")
def kernels() -> dict[str, Kernel]:
    return {name: Kernel.from_sources(name, MODELS[name], model_sources(name)) for name in MODELS}


@pytest.fixture(scope="module")
def osc(kernels):
    return kernels["osc"]


@pytest.fixture(scope="module")
def free3(kernels):
    return kernels["free3"]


def osc_exact(t, w=2.0, x0=1.0, v0=0.0):
    t = np.asarray(t)
    return np.stack([x0 * np.cos(w * t) + v0 / w * np.sin(w * t),
                     -x0 * w * np.sin(w * t) + v0 * np.cos(w * t)], axis=-1)


def all_sources() -> dict[str, str]:
    files = {}
    for name, ny in MODELS.items():
        files.update(model_sources(name))
        files.update(render_solvers(name, ny))
    return files


def _compiles(files, main, flags):
    """check_compiles, kept for these exact sources, flags and compiler (tests/compile_once.py)."""
    once(["check", main, *flags], files, lambda work: check_compiles(files, main, flags))


# --- the C itself ---------------------------------------------------------------------------

def test_kernel_reads_dimensions_and_names_from_the_library(kernels):
    k = kernels["free3"]
    assert (k.ny, k.np) == (3, 3)
    assert k.state_names == ("w1", "w2", "w3")
    assert k.param_names == ("I1", "I2", "I3")
    assert set(k.methods) == set(METHODS)


# Two models in one unit at -O0 in make test; the solvers' -O2 warnings (which -O2 adds) are
# pinned in make test by test_codegen's test_generated_c_compiles_cleanly_with_strict_warnings
# (heavy_top_solvers.c, every method, strict at -O2), this file's at -O2 in make test-slow.
@pytest.mark.parametrize("opt", ["-O0", pytest.param("-O2", marks=pytest.mark.slow)])
def test_generated_solvers_compile_with_all_warnings_as_errors(opt):
    files = all_sources()
    # Two models in one translation unit: the shared derive_stats block must be guarded.
    files["both.c"] = "".join(f'#include "{n}.c"\n#include "{n}_solvers.c"\n' for n in MODELS)
    _compiles(files, "both.c", [*STRICT_FLAGS, opt])


@pytest.mark.parametrize("method", list(METHODS))
def test_each_method_alone_compiles_with_all_warnings_as_errors(method):
    files = model_sources("free3")
    files.update(render_solvers("free3", 3, [method]))
    files["one.c"] = '#include "free3.c"\n#include "free3_solvers.c"\n'
    _compiles(files, "one.c", [*STRICT_FLAGS, "-O1"])


@pytest.mark.parametrize("method", list(METHODS))
def test_each_method_selected_from_the_full_file_compiles_with_all_warnings_as_errors(method):
    """The libraries `derive` builds: every method rendered, one selected at compile time
    (-DDERIVE_SELECT -DDERIVE_WITH_<M>): no helper of the others is left unused."""
    files = model_sources("free3")
    files.update(render_solvers("free3", 3))
    files["one.c"] = '#include "free3.c"\n#include "free3_solvers.c"\n'
    _compiles(files, "one.c", [*STRICT_FLAGS, "-O1", "-DDERIVE_SELECT", f"-DDERIVE_WITH_{method.upper()}"])


def test_rendered_header_declares_one_run_driver_per_method():
    h = render_solvers("osc", 2)["osc_solvers.h"]
    for name, m in METHODS.items():
        assert f"int osc_run_{name}(const derive_saveat *save, long n_batch," in h
    assert "osc_solve_" not in h and "osc_simulate_" not in h
    assert '#include "derive_runtime.h"' in h and "typedef struct" not in h


def test_stage_sums_are_unrolled_literals_without_zero_terms():
    c = render_solvers("osc", 2, ["rk4"])["derive_solvers.inc"]
    assert "yt[i] = y[i] + h * (0.5 * k[0][i]);" in c
    assert "yt[i] = y[i] + h * (0.5 * k[1][i]);" in c
    assert "yt[i] = y[i] + h * (k[2][i]);" in c
    assert "malloc" not in c


def test_sanitizer_run_of_every_solver_exits_cleanly(tmp_path):
    files = all_sources()
    files["solver_main.c"] = (C_DIR / "solver_main.c").read_text()
    try:
        exe = once(["sanitized", *SANITIZE_FLAGS], files,
                   lambda work: check_compiles(files, "solver_main.c", SANITIZE_FLAGS,
                                               executable=work / "run")) / "run"
    except CompilerError as exc:
        if "asan" in str(exc).lower() or "sanitize" in str(exc).lower():
            pytest.skip(f"no sanitizer runtime: {exc}")
        raise
    env = dict(os.environ, ASAN_OPTIONS="detect_leaks=0:abort_on_error=0",
               UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1")
    proc = subprocess.run([str(exe)], capture_output=True, text=True, env=env, timeout=120)
    assert proc.returncode == 0, proc.stderr[-4000:]
    assert "runtime error" not in proc.stderr


# --- the stepper is the tableau ----------------------------------------------------------------

def free3_f(p):
    I1, I2, I3 = p

    def f(t, w):
        return np.array([(I2 - I3) / I1 * w[1] * w[2], (I3 - I1) / I2 * w[2] * w[0],
                         (I1 - I2) / I3 * w[0] * w[1]])
    return f


@pytest.mark.parametrize("method, tab", [("rk4", RK4), ("dop853_fixed", DOP853)])
def test_one_explicit_step_equals_the_tableau_formula(free3, method, tab):
    y0, p, h = np.array([1.0, 2.0, 1.0]), [1.0, 2.0, 3.0], 0.3
    f, arr = free3_f(p), tab.arrays()
    A, b, c = arr["A"], arr["b"], arr["c"]
    k = []
    for i in range(tab.stages):
        k.append(f(c[i] * h, y0 + h * sum((A[i, j] * k[j] for j in range(i)), np.zeros(3))))
    expected = y0 + h * sum(bi * ki for bi, ki in zip(b, k))
    got = free3.solve(method, y0, p, [0.0, h], h=h).y[1]
    np.testing.assert_allclose(got, expected, rtol=1e-14, atol=0)


@pytest.mark.parametrize("method", ["gauss4", "gauss6"])
def test_one_gauss_step_solves_the_collocation_equations(free3, method):
    tab = METHODS[method].tableau
    y0, p, h = np.array([1.0, 2.0, 1.0]), [1.0, 2.0, 3.0], 0.1
    f, arr = free3_f(p), tab.arrays()
    A, b, c = arr["A"], arr["b"], arr["c"]
    Z = np.zeros((tab.stages, 3))
    for _ in range(200):  # fixed point Z = h A F(Z), contracting for this h
        F = np.array([f(c[j] * h, y0 + Z[j]) for j in range(tab.stages)])
        Z = h * A @ F
    F = np.array([f(c[j] * h, y0 + Z[j]) for j in range(tab.stages)])
    expected = y0 + h * b @ F
    got = free3.solve(method, y0, p, [0.0, h], h=h).y[1]
    np.testing.assert_allclose(got, expected, rtol=2e-15, atol=0)


# --- convergence --------------------------------------------------------------------------------

def fitted_order(kernel, method, y0, p, T, hs, reference):
    errs = [np.max(np.abs(kernel.solve(method, y0, p, [0.0, T], h=h).y[-1] - reference))
            for h in hs]
    return np.polyfit(np.log(hs), np.log(errs), 1)[0], errs


@pytest.mark.parametrize("method", list(FIXED))
def test_convergence_order_on_the_oscillator(osc, method):
    order = FIXED[method]
    h0 = {4: 0.1, 6: 0.2}[order]
    hs = h0 / 2.0 ** np.arange(5)
    slope, errs = fitted_order(osc, method, [1.0, 0.0], [2.0], 10.0, hs, osc_exact(10.0))
    assert abs(slope - order) < 0.2, (slope, errs)


def test_dop853_formula_has_order_8_on_fixed_steps(osc):
    hs = 0.3 / 2.0 ** np.arange(0, 2.01, 0.5)
    slope, errs = fitted_order(osc, "dop853_fixed", [1.0, 0.0], [2.0], 100.0, hs,
                               osc_exact(100.0))
    assert abs(slope - 8) < 0.2, (slope, errs)


@pytest.mark.parametrize("method", list(FIXED))
def test_convergence_order_on_the_nonlinear_euler_equations(free3, method):
    y0, p, T = [1.0, 2.0, 1.0], [1.0, 2.0, 3.0], 20.0
    reference = free3.solve("dop853", y0, p, [0.0, T], rtol=1e-14, atol=1e-16).y[-1]
    h0 = {4: 0.05, 6: 0.2}[FIXED[method]]
    slope, errs = fitted_order(free3, method, y0, p, T, h0 / 2.0 ** np.arange(4), reference)
    assert abs(slope - FIXED[method]) < 0.2, (slope, errs)


def test_dop853_error_is_a_small_multiple_of_the_tolerance(osc):
    t = np.linspace(0.0, 10.0, 101)
    tols = 10.0 ** -np.arange(4, 13)
    errs = []
    for rtol in tols:
        sol = osc.solve("dop853", [1.0, 0.0], [2.0], t, rtol=rtol, atol=rtol * 1e-2)
        errs.append(np.max(np.abs(sol.y - osc_exact(t))))
    ratio = np.array(errs) / tols
    assert np.all(ratio < 10), ratio
    slope = np.polyfit(np.log(tols), np.log(errs), 1)[0]
    assert abs(slope - 1) < 0.15, slope  # tolerance proportionality


def test_dense_output_agrees_with_the_exact_solution_between_steps(osc):
    rng = np.random.default_rng(1)
    t_dense = np.unique(np.concatenate([[0.0, 10.0], rng.uniform(0.0, 10.0, 997)]))
    dense = osc.solve("dop853", [1.0, 0.0], [2.0], t_dense, rtol=1e-10, atol=1e-12)
    sparse = osc.solve("dop853", [1.0, 0.0], [2.0], [0.0, 10.0], rtol=1e-10, atol=1e-12)
    assert np.max(np.abs(dense.y - osc_exact(t_dense))) < 1e-9
    # Outputs are interpolated, never stepped onto: the steps are those of the bare run, and
    # the end point is bit-identical.
    assert dense.naccept == sparse.naccept and dense.nreject == sparse.nreject
    assert np.array_equal(dense.y[-1], sparse.y[-1])
    assert dense.naccept < 100 < len(t_dense)


def test_dop853_function_evaluations_are_bounded(osc):
    t = np.linspace(0.0, 10.0, 101)
    sol = osc.solve("dop853", [1.0, 0.0], [2.0], t, rtol=1e-10, atol=1e-12)
    assert sol.nfev < 1000  # SciPy's DOP853 needs 974 here
    assert sol.njev == 0 and sol.nlu == 0
    sol = osc.solve("dop853", [1.0, 0.0], [2.0], [0.0, 10.0], rtol=1e-6, atol=1e-8)
    assert sol.nfev < 350


def test_fixed_steps_land_on_every_output_time(osc):
    t = np.array([0.0, 0.25, 0.3, 1.0, 1.05])
    sol = osc.solve("rk4", [1.0, 0.0], [2.0], t, h=0.1)
    assert sol.naccept == 3 + 1 + 7 + 1
    assert sol.nfev == 4 * sol.naccept
    # round-off in dt/h does not add a step: 0.7/0.1 = 6.999999999999999, 0.3/0.1 > 2.99
    assert osc.solve("rk4", [1.0, 0.0], [2.0], [0.0, 0.3], h=0.1).naccept == 3


# --- geometric integration ------------------------------------------------------------------

def test_gauss_conserves_oscillator_energy_without_drift(osc):
    w, t = 2.0, np.linspace(0.0, 1e4, 1001)
    for method in ("gauss4", "gauss6"):
        y = osc.solve(method, [1.0, 0.0], [w], t, h=0.1).y  # 1e5 steps
        energy = y[:, 1] ** 2 + w ** 2 * y[:, 0] ** 2
        rel = energy / energy[0] - 1
        assert np.max(np.abs(rel)) < 1e-13, (method, np.max(np.abs(rel)))
    # rk4 at the same step drifts (dissipates) visibly: the contrast the test is about
    y = osc.solve("rk4", [1.0, 0.0], [w], t, h=0.1).y
    energy = y[:, 1] ** 2 + w ** 2 * y[:, 0] ** 2
    assert energy[-1] / energy[0] - 1 < -1e-3


@pytest.mark.parametrize("method", ["gauss4", "gauss6"])
def test_gauss_conserves_the_quadratic_invariants_of_euler_equations(free3, method):
    p = np.array([1.0, 2.0, 3.5])
    t = np.linspace(0.0, 1000.0, 201)
    y = free3.solve(method, [1.0, 0.5, -0.3], p, t, h=0.05).y  # 2e4 steps
    L2 = np.sum((p * y) ** 2, axis=1)      # |angular momentum|^2
    T2 = np.sum(p * y ** 2, axis=1)        # twice the kinetic energy
    assert np.max(np.abs(L2 / L2[0] - 1)) < 2e-14
    assert np.max(np.abs(T2 / T2[0] - 1)) < 2e-14


# --- batches ----------------------------------------------------------------------------------

@pytest.mark.parametrize("method", list(METHODS))
def test_batch_equals_single_runs_bit_for_bit(free3, method):
    rng = np.random.default_rng(7)
    y0s = rng.normal(size=(5, 3))
    ps = np.column_stack([np.ones(5), 2.0 + rng.uniform(size=5), 3.5 * np.ones(5)])
    t = np.linspace(0.0, 5.0, 21)
    kw = dict(STEP_ARGS[method], rtol=1e-9, atol=1e-12)
    batch = free3.solve_batch(method, y0s, ps, t, **kw)
    assert batch.y.shape == (5, 21, 3)
    for b in range(5):
        single = free3.solve(method, y0s[b], ps[b], t, **kw)
        assert np.array_equal(batch.y[b], single.y)
        assert batch[b].nfev == single.nfev and batch[b].nstep == single.nstep


def test_batch_shares_parameters_and_reports_each_failure(kernels):
    k = kernels["blowup"]
    y0s = np.array([[0.1], [1.0], [0.2]])
    res = k.solve_batch("rk4", y0s, [1.0], [0.0, 2.0], h=0.01, check=False)
    assert list(res.status) == [0, 2, 0]
    assert "y[0] (u)" in res.messages[1] and res[1].fail_index == 0
    assert np.all(np.isfinite(res.y[0])) and np.isnan(res.y[1, 1, 0])
    with pytest.raises(IntegrationError, match=r"^trajectory 1: t = 1\.0\d*: non-finite"):
        k.solve_batch("rk4", y0s, [1.0], [0.0, 2.0], h=0.01)


# --- failures -------------------------------------------------------------------------------

def test_blow_up_is_reported_near_the_singular_time(kernels):
    k = kernels["blowup"]
    sol = k.solve("dop853", [2.0], [1.0], [0.0, 1.0], check=False)
    assert sol.status in (1, 2)
    assert abs(sol.t_fail - 0.5) < 1e-6
    for method in ("rk4", "gauss4", "gauss6", "dop853_fixed"):
        sol = k.solve(method, [2.0], [1.0], [0.0, 1.0], h=0.005, check=False)
        assert sol.status in (2, 5), (method, sol.message)
        assert abs(sol.t_fail - 0.5) < 0.05, (method, sol.t_fail)


def test_dop853_recovers_from_non_finite_trial_steps(kernels):
    """u' = -u^2 from u0 = 10 with a first step of 10: the trial stages overflow; the step is
    shrunk and retried, and the smooth solution u = 10/(1 + 10 t) is still found."""
    t = np.linspace(0.0, 10.0, 11)
    sol = kernels["blowup"].solve("dop853", [10.0], [-1.0], t, h=10.0)
    assert sol.nreject > 0
    np.testing.assert_allclose(sol.y[:, 0], 10 / (1 + 10 * t), rtol=1e-9)


def test_integration_error_names_the_state(kernels):
    with pytest.raises(IntegrationError, match=r"^t = 1\.0\d*: non-finite value in state "
                                               r"y\[0\] \(u\)$"):
        kernels["blowup"].solve("rk4", [1.0], [1.0], [0.0, 2.0], h=0.01)
    with pytest.raises(IntegrationError, match=r"^t = 1(\.0*)?: step size underflow \(h = "):
        kernels["blowup"].solve("dop853", [1.0], [1.0], [0.0, 2.0])
    with pytest.raises(IntegrationError, match=r"Newton iteration failed to converge"):
        kernels["blowup"].solve("gauss4", [1.0], [1.0], [0.0, 2.0], h=0.01)


@pytest.mark.parametrize("method", list(METHODS))
def test_domain_error_is_status_4(kernels, method):
    sol = kernels["tank"].solve(method, [1.0, 0.0], [1.0], [0.0, 0.5, 2.0],
                                **STEP_ARGS[method], check=False)
    assert sol.status == 4
    assert sol.t_fail >= 1.0 - 1e-12
    assert sol.message.endswith("state outside the model's domain (rhs returned 1)")
    if method != "dop853":  # dop853's first step, error-free here, already overshoots t = 1
        np.testing.assert_allclose(sol.y[1], [0.5, 0.5], rtol=1e-12)  # reached before failing
    with pytest.raises(IntegrationError, match="outside the model's domain"):
        kernels["tank"].solve(method, [1.0, 0.0], [1.0], [0.0, 2.0], **STEP_ARGS[method])


def test_max_steps(osc):
    with pytest.raises(IntegrationError, match=r"^t = .*: step budget spent \(simulate.max_steps = 10\)"):
        osc.solve("dop853", [1.0, 0.0], [2.0], [0.0, 100.0], max_steps=10)


def test_python_validates_arguments(osc):
    with pytest.raises(ValueError, match="strictly increasing"):
        osc.solve("dop853", [1.0, 0.0], [2.0], [0.0, 1.0, 1.0])
    with pytest.raises(ValueError, match="shape"):
        osc.solve("dop853", [1.0, 0.0, 3.0], [2.0], [0.0, 1.0])
    with pytest.raises(ValueError, match="pass the step size h"):
        osc.solve("rk4", [1.0, 0.0], [2.0], [0.0, 1.0])
    with pytest.raises(ValueError, match="unknown method"):
        osc.solve("euler", [1.0, 0.0], [2.0], [0.0, 1.0])
    with pytest.raises(ValueError, match="rtol"):
        osc.solve("dop853", [1.0, 0.0], [2.0], [0.0, 1.0], rtol=-1.0)
    with pytest.raises(ValueError, match="finite"):
        osc.solve("dop853", [np.nan, 0.0], [2.0], [0.0, 1.0])


def test_single_output_time_returns_the_initial_state(osc):
    sol = osc.solve("dop853", [1.0, 0.5], [2.0], [3.0])
    assert sol.y.tolist() == [[1.0, 0.5]] and sol.nfev == 0


def test_rhs_and_jacobian_wrappers(kernels):
    k = kernels["free3"]
    y, p = np.array([1.0, 0.5, -0.3]), np.array([1.0, 2.0, 3.5])
    np.testing.assert_allclose(k.rhs(0.0, y, p), free3_f(p)(0.0, y), rtol=1e-15)
    eps = 1e-7
    fd = np.column_stack([(k.rhs(0, y + eps * e, p) - k.rhs(0, y - eps * e, p)) / (2 * eps)
                          for e in np.eye(3)])
    np.testing.assert_allclose(k.jac(0.0, y, p), fd, atol=1e-8)
    with pytest.raises(IntegrationError, match=r"rhs returned 1"):
        kernels["tank"].rhs(0.0, [-1.0, 0.0], [1.0])


# --- building -----------------------------------------------------------------------------

def test_second_build_is_served_from_the_cache(monkeypatch):
    a = Kernel.from_sources("osc", MODELS["osc"], model_sources("osc"))
    monkeypatch.setattr(cbuild, "_run", lambda *args, **kwargs: pytest.fail("compiled a second time"))
    b = Kernel.from_sources("osc", MODELS["osc"], model_sources("osc"))
    assert a.lib is b.lib


def test_a_state_count_other_than_the_headers_is_refused_at_compile_time(monkeypatch, tmp_path):
    """The caller's ny is checked against <prefix>_NY by the compiler, never parsed from C."""
    monkeypatch.setenv("DERIVE_CACHE", str(tmp_path / "cache"))
    with pytest.raises(CompilerError, match=r"osc_NY differs from the size"):
        Kernel.from_sources("osc", 3, model_sources("osc"), methods=["rk4"])


def test_missing_compiler_is_one_clear_line(monkeypatch, tmp_path):
    monkeypatch.setenv("CC", str(tmp_path / "no-such-cc"))
    monkeypatch.setenv("DERIVE_CACHE", str(tmp_path / "cache"))
    with pytest.raises(CompilerError) as exc:
        compile_library("nocc", {"x.c": "int x(void) { return 1; }\n"}, "x.c")
    msg = str(exc.value)
    assert "no working C compiler" in msg and "\n" not in msg


def test_compiler_errors_show_its_stderr(monkeypatch, tmp_path):
    monkeypatch.setenv("DERIVE_CACHE", str(tmp_path / "cache"))
    with pytest.raises(CompilerError, match=r"(?s)compiling bad failed.*bad\.c:1"):
        compile_library("bad", {"bad.c": "int bad(void) { return }\n"}, "bad.c")


def test_concurrent_builds_share_one_cache_entry(tmp_path):
    """Several processes compiling the same new library at once all load a complete one."""
    src = f"int answer(void) {{ return 42; }} /* {tmp_path} */\n"
    code = ("import sys; from derive.runtime.cbuild import compile_library as c; "
            f"lib = c('race', {{'race.c': {src!r}}}, 'race.c'); "
            "sys.exit(0 if lib.answer() == 42 else 1)")
    env = dict(os.environ, DERIVE_CACHE=str(tmp_path / "cache"))
    procs = [subprocess.Popen([sys.executable, "-c", code], env=env, cwd=Path(__file__).parent.parent)
             for _ in range(4)]
    assert [p.wait(timeout=120) for p in procs] == [0, 0, 0, 0]
    libs = list((tmp_path / "cache").glob("race-*.so"))
    assert len(libs) == 1
    assert not [p for p in (tmp_path / "cache").iterdir() if p.name.startswith(".")]


@pytest.mark.slow
def test_whole_trajectories_are_much_faster_than_scipy(free3):
    from scipy.integrate import solve_ivp

    y0, p = [1.0, 0.5, -0.3], [1.0, 2.0, 3.5]
    t = np.linspace(0.0, 100.0, 1001)
    n = 20
    t0 = time.perf_counter()
    for _ in range(n):
        ours = free3.solve("dop853", y0, p, t, rtol=1e-10, atol=1e-12)
    ours_time = (time.perf_counter() - t0) / n
    t0 = time.perf_counter()
    ref = solve_ivp(free3_f(p), (0.0, 100.0), y0, method="DOP853", t_eval=t, rtol=1e-10,
                    atol=1e-12)
    scipy_time = time.perf_counter() - t0
    assert np.max(np.abs(ours.y - ref.y.T)) < 1e-8
    assert scipy_time / ours_time > 50, (scipy_time, ours_time)


HOOK_MAIN = r"""
#include <stdio.h>
#include "osc.c"
#include "osc_solvers.c"

/* The host's check: interrupted from its n-th question on. */
static int after(void *data)
{
    long *n = data;
    return --*n < 0;
}

int main(void)
{
    const double y0[2] = {1.0, 0.0}, t[2] = {0.0, 100.0};
    double p[1] = {2.0}, y[4];
    const derive_saveat save = {t, 2, 0, 0, 0, 0};
    derive_stats st;
    long n = 5;
    int free_run = osc_run_rk4(&save, 1, y0, p, 0.01, y, NULL, &st), stopped;
    derive_set_interrupt_check(after, &n);
    stopped = osc_run_rk4(&save, 1, y0, p, 0.01, y, NULL, &st);
    printf("%d %d %ld\n", free_run, stopped, st.nstep);
    derive_set_interrupt_check(NULL, NULL);
    printf("%d\n", osc_run_rk4(&save, 1, y0, p, 0.01, y, NULL, &st));
    return 0;
}
"""


def test_the_host_interrupt_hook_stops_a_loop_and_the_runtime_installs_no_signal_handler(tmp_path):
    """An embedding program's check, installed through derive_set_interrupt_check, stops a
    solver at the step it first answers yes (DERIVE_INTERRUPTED); removed, the same call runs
    to the end. The runtime and the solvers hold no signal handler of their own."""
    files = model_sources("osc")
    files.update(render_solvers("osc", 2, ["rk4"]))
    files["main.c"] = HOOK_MAIN
    exe = check_compiles(files, "main.c", [*STRICT_FLAGS, "-O1"], executable=tmp_path / "hook")
    out = subprocess.run([str(exe)], capture_output=True, text=True, check=True).stdout.split()
    assert out == ["0", str(int(Status.INTERRUPTED)), "5", "0"]
    for name, text in files.items():
        if name.startswith(("derive_", "osc_")):
            assert "signal(" not in text and "<signal.h>" not in text, name
