"""The cost of each output sample.

* ``<model>_observables_at``, the output map as one loop over the samples (the parameters'
  temporaries computed once), has the bits of the same map called one sample at a time, for
  every generated model;
* ``<model>_outputs_finite``, the finiteness pass on the bits of the output arrays, reports the
  first non-finite output (earliest sample, then lowest column) as the comparison did;
* a prepared run's buffer is not zeroed (only its stats record is), and what is left in it
  from before never shows in a result or a status.
"""
from __future__ import annotations

import ctypes
import json

import numpy as np
import pytest

import derive
import derive.runtime.integrate as integrate
from derive.bench.reference import reference_data
from derive.codegen.render import GENERATED
from derive.methods.status import Status
from derive.runtime.cbuild import compile_library
from derive.runtime.records import STATS_DTYPE

MODELS = sorted(json.loads(f.read_text())["name"] for f in (GENERATED / "models").glob("*.json"))
DP = ctypes.POINTER(ctypes.c_double)


def _ptr(a: np.ndarray):
    return a.ctypes.data_as(DP)


@pytest.fixture(scope="module")
def models_lib():
    """Every generated model's C file in one library (no solvers)."""
    c = GENERATED / "c"
    sources = {f.name: f.read_text() for f in c.iterdir()
               if f.suffix in (".c", ".h") and f.stem.split("_solvers")[0] in MODELS}
    # <model>_beta is file-local (the measures' own): exported here through a wrapper
    unit = "".join(f'#include "{m}.c"\n' for m in MODELS)
    for m in MODELS:
        if f"{m}_beta(" in sources[f"{m}.c"]:
            unit += (f"double test_{m}_beta(double t, const double *y, const double *p)"
                     f" {{ return {m}_beta(t, y, p); }}\n")
    sources["all_models.c"] = unit
    return compile_library("all_models", sources, "all_models.c")


def _description(name: str) -> dict:
    return json.loads((GENERATED / "models" / f"{name}.json").read_text())


@pytest.mark.parametrize("name", MODELS)
def test_the_output_loop_is_the_output_map_bit_for_bit(models_lib, name):
    """At states and parameters drawn at random (any finite numbers: the map need not be in its
    domain for the two to agree, NaN for NaN), every output of every sample has the bits of
    the map called on that sample alone."""
    d = _description(name)
    ny, nobs, n = len(d["states"]), len(d["outputs"]), 37
    rng = np.random.default_rng(20)
    t = np.sort(rng.uniform(0.0, 10.0, n))
    y = rng.uniform(-1.5, 1.5, (n, ny))
    p = rng.uniform(0.2, 2.0, len(d["params"]))
    loop = getattr(models_lib, f"{name}_observables_at")
    loop.argtypes, loop.restype = (ctypes.c_long, DP, DP, DP, DP), ctypes.c_int
    expected = np.empty((nobs, n))
    o = np.empty(nobs)
    for k in range(n):
        assert loop(1, _ptr(t[k:k + 1]), _ptr(y[k]), _ptr(p), _ptr(o)) == 0
        expected[:, k] = o
    out = np.full((nobs, n), -7.0)
    assert loop(n, _ptr(t), _ptr(y), _ptr(p), _ptr(out)) == 0
    assert np.isfinite(expected).any()
    assert np.array_equal(out.view(np.uint64), expected.view(np.uint64))


@pytest.mark.parametrize("name", [m for m in MODELS if _description(m)["has_angles"]])
def test_beta_alone_is_the_output_map_s_beta_bit_for_bit(models_lib, name):
    """``<model>_beta``, what the sweeps' extremum searches evaluate, has the bits of
    ``_observables_at``' out[1] at random states (NaN for NaN); every model with angles has one."""
    d = _description(name)
    ny, nobs = len(d["states"]), len(d["outputs"])
    rng = np.random.default_rng(21)
    p = rng.uniform(0.2, 2.0, len(d["params"]))
    one = getattr(models_lib, f"{name}_observables_at")
    one.argtypes, one.restype = (ctypes.c_long, DP, DP, DP, DP), ctypes.c_int
    beta = getattr(models_lib, f"test_{name}_beta")
    beta.argtypes, beta.restype = (ctypes.c_double, DP, DP), ctypes.c_double
    o = np.empty(nobs)
    got, want = [], []
    for _ in range(200):
        y = rng.uniform(-1.5, 1.5, ny)
        t = float(rng.uniform(0.0, 10.0))
        one(1, _ptr(np.array([t])), _ptr(y), _ptr(p), _ptr(o))
        want.append(o[1])
        got.append(beta(t, _ptr(y), _ptr(p)))
    want, got = np.array(want), np.array(got)
    assert np.isfinite(want).sum() > 100
    assert np.array_equal(got.view(np.uint64), want.view(np.uint64))


ARRAYS = ("t", "alpha", "beta", "gamma", "omega", "axis", "energy", "p_alpha", "p_gamma", "n", "L")


def _scene(samples: int = 101, **simulate) -> dict:
    data = reference_data(10.0)
    data["simulate"].update(samples=samples, **simulate)
    return data


def _dirty_buffers(monkeypatch):
    """From here on np.empty in the runtime hands out buffers full of NaN (stats record
    included), as memory left over from an earlier run may be."""
    real = np.empty

    def dirty(shape, *args, **kwargs):
        buf = real(shape, *args, **kwargs)
        buf.fill(np.nan)
        return buf

    monkeypatch.setattr(integrate.np, "empty", dirty)


@pytest.mark.parametrize("method", ["dop853", "taylor"])
def test_a_prepared_run_in_a_dirty_buffer_is_simulate_s(monkeypatch, method):
    data = _scene(method=method, formulation="reduced-u")
    direct = derive.simulate(data)
    _dirty_buffers(monkeypatch)
    res = derive.prepare(data).run()
    assert res.nfev == direct.nfev
    for name in ARRAYS:
        assert np.array_equal(getattr(res, name), getattr(direct, name)), name


def test_a_failing_prepared_run_in_a_dirty_buffer_reports_simulate_s_status(monkeypatch):
    data = _scene(max_steps=5)
    with pytest.raises(derive.IntegrationError) as direct:
        derive.simulate(data)
    _dirty_buffers(monkeypatch)
    with pytest.raises(derive.IntegrationError) as prepared:
        derive.prepare(data).run()
    assert str(prepared.value) == str(direct.value)


@pytest.fixture(scope="module")
def finite_check():
    """The runtime's ``derive_outputs_finite`` (the pass the run drivers make over a model's
    outputs) over the reduced-u top's outputs, and their count."""
    data = _scene(method="dop853", formulation="reduced-u")
    c = derive.prepare(data).plan.candidates[0]
    nobs = c.kernel.nout
    raw = c.kernel.lib.derive_outputs_finite
    raw.argtypes, raw.restype = (ctypes.c_long, ctypes.c_int, DP, DP, ctypes.c_void_p), ctypes.c_int
    return (lambda n_out, t, out, st: raw(n_out, nobs, t, out, st)), nobs


def _check(finite_check, out, t):
    fn, _ = finite_check
    st = np.zeros(1, STATS_DTYPE)
    st["fail_index"] = -1
    rc = fn(out.shape[1], _ptr(t), _ptr(out), st.ctypes.data)
    return rc, st[0]


def _first_bad(out):
    """(sample, column) of the first non-finite entry, by sample then column."""
    bad = np.argwhere(~np.isfinite(out.T))
    return tuple(bad[0]) if len(bad) else None


@pytest.mark.parametrize("n", [1, 2, 3, 1001])
def test_the_finiteness_pass_reports_the_first_non_finite_output(finite_check, n):
    """Extreme finite values (the largest and smallest doubles, subnormals, -0) pass; NaN and
    infinities planted anywhere, the very last entry included, are reported at the earliest
    sample and there the lowest column, with that sample's time."""
    _, nobs = finite_check
    rng = np.random.default_rng(n)
    t = np.linspace(0.0, 10.0, n) + 0.25
    out = rng.normal(size=(nobs, n))
    out.flat[rng.integers(0, out.size, min(out.size, 5))] = [np.finfo(float).max, -np.finfo(float).max,
                                                                5e-324, -0.0, np.finfo(float).tiny][:min(out.size, 5)]
    rc, st = _check(finite_check, out, t)
    assert rc == Status.OK and st["status"] == 0 and st["fail_index"] == -1
    planted = [(nobs - 1, n - 1), (nobs // 2, n // 2), (3, 0), (0, n - 1)]
    for bad in (np.nan, np.inf, -np.inf, -np.nan):
        for m in range(1, len(planted) + 1):
            o = out.copy()
            for j, k in planted[:m]:
                o[j, k] = bad
            k, j = _first_bad(o)
            rc, st = _check(finite_check, o, t)
            assert rc == Status.NONFINITE_OUTPUT and st["status"] == Status.NONFINITE_OUTPUT
            assert (st["fail_index"], st["t_fail"]) == (j, t[k])


@pytest.mark.parametrize("method", ["dop853", "taylor"])
def test_reduced_u_beta_is_acos_of_u_within_an_ulp(method):
    """β of the reduced-u outputs, acos(u) of the written states, against mpmath's acos of the
    same doubles: within one ulp at every sample (the former atan2(√((1 − u)(1 + u)), u) was
    off by up to 1.43 ulp within the pole clearance)."""
    mp = pytest.importorskip("mpmath")
    res = derive.simulate(_scene(samples=1001, method=method, formulation="reduced-u"))
    assert res.formulation == "reduced-u"
    u, beta = res.state[:, 1], res.beta
    with mp.workprec(120):
        exact = [mp.acos(mp.mpf(float(x))) for x in u]
        err = [float(abs(mp.mpf(float(b)) - e)) / np.spacing(float(e)) for b, e in zip(beta, exact)]
    assert max(err) <= 1.0, max(err)
