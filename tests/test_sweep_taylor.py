"""Sweeps on the Taylor method: the measures search the step's series (the dense output the
solver has anyway) with the searches and accumulators DOP853's dense polynomial goes through
(templates/c/measures.c.j2, the window's "series" flavour)."""
from __future__ import annotations

import copy
import math
import shutil

import numpy as np
import pytest

import compile_once
from cli_in_process import derive_main

import derive
from derive.bench.reference import reference_data
from derive.errors import SceneError
from derive.methods import registry
from derive.reference.exact import heavy_top
from derive.runtime import catalogue
from derive.sim.plan import auto_method
from derive.sweeps import measures as ms
from derive.sweeps.spec import load
from derive.sweeps.plan import measuring_methods

TIGHT = {"rtol": 1e-12, "atol": 1e-14}
#: The tennis racket (intermediate axis 2, spun about it with a small perturbation omega1): it
#: flips; beta swings between its extrema. Not so close to the separatrix (omega1 = 1e-6) that
#: the two methods' round-off alone moves the extrema by more than the test's 1e-9.
RACKET = {"body": {"I1": 1e-3, "I2": 2e-3, "I3": 2.5e-3},
          "initial": {"alpha": 0.0, "beta": 1.5707963267948966, "gamma": 1.5707963267948966,
                      "omega": [1e-3, 10.0, 0.0]},
          "simulate": {"t_end": 15.0}}
RACKET_MEASURES = ["beta_max", "beta_min", "flips", "time_to_flip", "time_to_tilt",
                   "energy_drift", "integral_drift", "nfev"]


def _with(scene: dict, **simulate) -> dict:
    scene = copy.deepcopy(scene)
    scene["simulate"] = {**scene["simulate"], **simulate}
    return scene


def _top_spec(method: str, names=None, **simulate) -> dict:
    """Random starts of the reference heavy top (beta0, beta_dot0), t_end 10: several turning
    points, tilts past 1 rad and flips of omega2; the measures ``names`` (None: the lot)."""
    scene = _with(reference_data(10.0), method=method, **simulate)
    return {"scene": scene, "random": {"n": 6, "seed": 3, "initial": {
        "beta": {"low": 0.3, "high": 1.4}, "beta_dot": {"low": -0.5, "high": 0.5}}},
        "measure": {"names": names or ["beta_max", "beta_min", "nutation", "time_to_tilt",
                                       "flips", "time_to_flip", "energy_drift", "nfev"],
                    "time_to_tilt": {"angle": 1.0}}}


def _racket_spec(method: str, **simulate) -> dict:
    return {"scene": _with(RACKET, method=method, **simulate),
            "vary": {"initial": {"omega": {"0": {"values": [1e-3, 0.03, 0.3]}}}},
            "measure": {"names": RACKET_MEASURES, "time_to_tilt": {"angle": 2.0}}}


@pytest.fixture(scope="module")
def top():
    return {m: derive.sweep(_top_spec(m, **TIGHT), processes=1) for m in ("dop853", "taylor")}


@pytest.fixture(scope="module")
def racket():
    return {m: derive.sweep(_racket_spec(m, **TIGHT), processes=1) for m in ("dop853", "taylor")}


def test_the_registry_gives_each_family_its_window():
    """The method's family says what the measures search on; the engine asks nothing else."""
    assert registry.measure_window("dop853") == "stages"
    assert registry.measure_window("taylor") == "series"
    for name in ("rk4", "gauss4", "gauss6", "dop853_fixed", "splitting2", "splitting4"):
        assert registry.measure_window(name) is None
    assert measuring_methods() == ("dop853", "taylor")
    assert load(_top_spec("taylor")).method == "taylor"


def test_heavy_top_extrema_agree_with_dop853_and_the_closed_form(top):
    """beta_max, beta_min on the series agree with DOP853's dense polynomial's and with the
    closed-form top's turning points (the roots of the cubic in sin^2(beta/2)) to 1e-9 at
    rtol 1e-12."""
    tay, dop = top["taylor"], top["dop853"]
    assert (tay.status == "ok").all() and (dop.status == "ok").all()
    ref = reference_data(10.0)["initial"]
    for i in range(6):
        b0, bd0 = tay.params["initial.beta"][i], tay.params["initial.beta_dot"][i]
        ex = heavy_top(1.0, 0.5, 1.0, 1.0, 1.0, ref["alpha"], b0, ref["gamma"], ref["alpha_dot"],
                       bd0, ref["gamma_dot"], np.array([0.0, 1.0]))
        assert not ex.info["mirrored"]
        turning = [2 * math.asin(math.sqrt(y)) for y in ex.info["y_roots"][:2]]
        assert abs(tay.measures["beta_max"][i] - max(turning)) < 1e-9
        assert abs(tay.measures["beta_min"][i] - min(turning)) < 1e-9
    for name in ("beta_max", "beta_min", "nutation"):
        assert np.abs(tay.measures[name] - dop.measures[name]).max() < 1e-9, name


def test_heavy_top_tilt_and_flip_times_agree_with_dop853(top):
    tay, dop = top["taylor"], top["dop853"]
    assert np.array_equal(tay.measures["flips"], dop.measures["flips"])
    for name in ("time_to_tilt", "time_to_flip"):
        a, b = tay.measures[name], dop.measures[name]
        assert np.array_equal(np.isnan(a), np.isnan(b)), name
        assert np.isfinite(a).any(), name  # the scene tilts and flips
        assert np.nanmax(np.abs(a - b)) < 1e-9, name


def test_racket_flips_tilts_and_extrema_agree_with_dop853(racket):
    tay, dop = racket["taylor"], racket["dop853"]
    assert (tay.status == "ok").all() and (dop.status == "ok").all()
    assert np.array_equal(tay.measures["flips"], dop.measures["flips"])
    assert (tay.measures["flips"] >= 2).all()
    for name in ("beta_max", "beta_min", "time_to_flip", "time_to_tilt"):
        a, b = tay.measures[name], dop.measures[name]
        assert np.isfinite(a).all(), name
        assert np.abs(a - b).max() < 1e-9, name
    # Euler's free body: |L|^2 and the energy conserved to the tolerance's scale
    assert (tay.measures["integral_drift"] < 1e-11).all()
    assert (tay.measures["energy_drift"] < 1e-11).all()


@pytest.mark.parametrize("rtol", [1e-8, 1e-10, 1e-12])
def test_energy_drift_stays_at_the_tolerance_scale(rtol):
    res = derive.sweep(_top_spec("taylor", ["energy_drift", "nfev"], rtol=rtol, atol=rtol * 1e-2),
                       processes=1)
    assert (res.status == "ok").all()
    assert (res.measures["energy_drift"] < 10 * rtol).all()


def test_measured_values_at_output_samples_equal_simulate_bit_for_bit():
    """Measuring does not move a Taylor step (the hook only reads the series; the steps do not
    depend on the output times), so where a measure's value is taken at a time that is also an
    output sample it is the sample's value: beta rising all along [0, t_end], beta_min is the
    start's beta and beta_max t_end's; final_state is the last sample; nfev is the step count
    simulate reports."""
    for form in ("auto", "euler-poisson"):
        for t_end in (0.5, 1.0):  # beta's first maximum is at t = 1.046
            scene = _with(reference_data(t_end), method="taylor", rtol=1e-10, atol=1e-12,
                          samples=11, formulation=form)
            sim = derive.simulate(scene)
            res = derive.sweep({"scene": scene, "vary": {"initial": {"beta": {"values": [0.8]}}},
                                "measures": ["beta_max", "beta_min", "final_state", "nfev"]},
                               processes=1)
            assert res.formulation[0] == sim.formulation
            assert np.all(np.diff(sim.beta) > 0)
            assert res.measures["beta_min"][0] == sim.beta[0]
            assert res.measures["beta_max"][0] == sim.beta[-1]
            assert res.measures["final_beta"][0] == sim.beta[-1]
            for k in range(3):
                assert res.measures[f"final_omega{k + 1}"][0] == sim.omega[-1, k]
            assert res.measures["nfev"][0] == sim.nfev
            assert sim.nfev < 20  # a step is one jet: no stage, no rhs evaluation added


def test_nfev_is_the_step_count_and_the_searches_add_none():
    """nfev is the number of Taylor steps whatever the measures ask: the series is there
    already (DOP853's searches cost dense stages)."""
    def nfev(method, names):
        return derive.sweep(_top_spec(method, names), processes=1).measures["nfev"]

    plain = nfev("taylor", ["nfev"])
    assert np.array_equal(nfev("taylor", ["beta_max", "time_to_flip", "nfev"]), plain)
    assert (nfev("dop853", ["beta_max", "nfev"]) > nfev("dop853", ["nfev"])).all()


def test_auto_takes_the_cost_models_method_for_the_sweep():
    """method = "auto": the cost model's choice for the sweep's first model at its tolerance
    and span (two outputs kept); at rtol 1e-12 on the reference top that is taylor, and the
    sweep's numbers are those of the method named."""
    spec = _top_spec("auto", **TIGHT)
    sp = load(spec)
    desc = catalogue.describe(sp.key)
    assert sp.method == auto_method(sp.scene, desc, samples=2) == "taylor"
    named = derive.sweep(_top_spec("taylor", **TIGHT), processes=1)
    auto = derive.sweep(spec, processes=1)
    for k in named.measures:
        assert np.array_equal(auto.measures[k], named.measures[k], equal_nan=True), k


def test_fallback_formulation_runs_taylor_too():
    """Formulation auto with taylor: reduced-u where its pole check takes the start,
    euler-poisson for the starts it refuses; each point's numbers are those of a sweep naming
    the formulation that ran it."""
    betas = [0.04, 0.5, 1.0, 3.05]
    scene = _with(reference_data(5.0), method="taylor", rtol=1e-10, atol=1e-12)
    names = ["beta_max", "beta_min", "energy_drift", "final_state", "nfev"]
    res = derive.sweep({"scene": scene, "vary": {"initial": {"beta": {"values": betas}}},
                        "measures": names}, processes=1)
    assert (res.status == "ok").all()
    assert list(res.formulation) == ["euler-poisson", "reduced-u", "reduced-u", "euler-poisson"]
    ep = derive.sweep({"scene": _with(scene, formulation="euler-poisson"),
                       "vary": {"initial": {"beta": {"values": [betas[0], betas[3]]}}},
                       "measures": names}, processes=1)
    for k in ep.measures:
        assert np.array_equal(res.measures[k][[0, 3]], ep.measures[k], equal_nan=True), k


@pytest.mark.slow  # the engines' agreement: tests/test_sweep.py in make test
def test_engines_give_identical_results():
    """In-process, a local process pool and a dask LocalCluster give the same numbers bit for
    bit with the Taylor method too."""
    pytest.importorskip("dask.distributed")
    spec = {"scene": _with(reference_data(1.0), method="taylor", rtol=1e-9, atol=1e-12),
            "random": {"n": 240, "seed": 11, "initial": {"beta": {"low": 0.3, "high": 1.2}}},
            "measures": ["beta_max", "beta_min", "energy_drift", "nfev", "flips", "time_to_flip",
                         "integral_drift"]}
    one = derive.sweep(spec, processes=1)
    assert (one.status == "ok").all()
    for other in (derive.sweep(spec, processes=2), derive.sweep(spec, workers=2)):
        assert np.array_equal(other.status, one.status)
        for k in one.measures:
            assert np.array_equal(other.measures[k], one.measures[k], equal_nan=True), k


@pytest.mark.parametrize("method,extra", [("rk4", {"h": 0.01}), ("gauss4", {"h": 0.01}),
                                          ("splitting2", {"h": 0.01})])
def test_methods_without_a_measure_window_are_refused_naming_the_key(method, extra):
    scene = _with(reference_data(1.0), method=method, **extra)
    spec = {"scene": scene, "vary": {"initial": {"beta": {"values": [0.5]}}}}
    with pytest.raises(SceneError) as info:
        load(spec)
    msg = str(info.value)
    assert msg.startswith("<sweep>: scene.simulate.method: ") and method in msg, msg
    assert "dop853, taylor" in msg


def test_cli_refuses_a_fixed_step_method_with_exit_2(tmp_path):
    scene = tmp_path / "top.toml"
    scene.write_text('[body]\nI1 = 1.0\nI3 = 0.5\n[gravity]\nM = 1.0\ng = 1.0\nl = 1.0\n'
                     '[initial]\nalpha = 0.0\nbeta = 0.8\ngamma = 0.0\nalpha_dot = 0.0\n'
                     'beta_dot = 0.0\ngamma_dot = 6.0\n[simulate]\nt_end = 1.0\nmethod = "rk4"\n'
                     'h = 0.01\n')
    sweep = tmp_path / "s.toml"
    sweep.write_text('scene = "top.toml"\n[vary]\ninitial.beta = { values = [0.5] }\n')
    out = tmp_path / "r.csv"
    p = derive_main("sweep", sweep, "-o", out)
    assert p.returncode == 2 and not out.exists()
    assert p.stderr.strip().splitlines() == [p.stderr.strip()]
    assert p.stderr.startswith(f"error: {sweep}: scene.simulate.method: ")


def test_the_series_window_compiles_under_the_strict_flags():
    """The measures unit of the Taylor method (model, solvers, Taylor solver, measures) compiles
    cleanly under the project's strict flags, and runs from the cache's library."""
    gcc = shutil.which("gcc")
    if gcc is None:
        pytest.skip("no gcc")
    desc = catalogue.describe(("euler-poisson", True, ("gravity",)))
    files = dict(ms.c_sources(desc, "taylor"))
    files["unit.c"] = "".join(f'#include "{n}"\n' for n in (
        f"{desc.name}.c", f"{desc.name}_solvers.c", f"{desc.name}_taylor.c", f"{desc.name}_measures.c"))
    # as derive.sweeps.measures builds it: one method per library
    flags = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O0", "-DDERIVE_MEASURES",
             "-DDERIVE_SELECT", "-DDERIVE_WITH_TAYLOR"]
    compile_once.compiles_once(files, "unit.c", flags)  # kept for these exact sources and flags
    assert "_measure_series" in files[f"{desc.name}_measures.c"]
    assert ms.MeasureKernel.load(desc, "taylor") is ms.MeasureKernel.load(desc, "taylor")
