"""Sweeps on auto's formulations per point (derive.sweeps.plan.sweep_plan): reduced-u where its
compiled pole check takes the start, euler-poisson for the starts it refuses, with measures of
the same meaning whichever ran a point."""
from __future__ import annotations

import math

import numpy as np
import pytest

import derive
from derive.methods.status import Status
from derive.reference.exact import heavy_top
from derive.runtime import catalogue
from derive.sweeps import measures as ms
from derive.sweeps.spec import load
from derive.sweeps.tasks import run_chunk
from derive.sweeps.plan import sweep_plan
from derive.symbolic.formulations import REDUCED_U_CLEARANCE

REF = {"body": {"I1": 1.0, "I3": 0.5}, "gravity": {"M": 1.0, "g": 1.0, "l": 1.0},
       "initial": {"alpha": 0.0, "beta": 0.8, "gamma": 0.0, "alpha_dot": -0.4, "beta_dot": 0.3,
                   "gamma_dot": 6.0},
       "simulate": {"t_end": 10.0, "rtol": 1e-9, "atol": 1e-12}}
#: Starts near the upper pole (the motion dips under |sin beta| = 0.1: 0.04, 0.09, 0.12), clear
#: of both (0.2 .. 2.9) and near the lower pole (3.05).
BETAS = [0.04, 0.09, 0.12, 0.2, 0.5, 1.0, 2.0, 2.9, 3.05]
MEASURES = ["beta_max", "beta_min", "energy_drift", "p_gamma_drift", "flips", "time_to_flip",
            "final_state", "nfev"]


def _turning(b0: float) -> list[float]:
    """The closed-form top's turning points of beta for the start beta0 (REF's rates)."""
    ex = heavy_top(1.0, 0.5, 1.0, 1.0, 1.0, 0.0, b0, 0.0, -0.4, 0.3, 6.0, np.array([0.0, 1.0]))
    turning = sorted(2 * math.asin(math.sqrt(y)) for y in ex.info["y_roots"][:2])
    return sorted(math.pi - b for b in turning) if ex.info["mirrored"] else turning


@pytest.fixture(scope="module")
def swept():
    return derive.sweep({"scene": REF, "vary": {"initial": {"beta": {"values": BETAS}}},
                         "measures": MEASURES}, processes=1)


def test_the_plan_is_reduced_u_then_euler_poisson():
    sp = load({"scene": REF, "vary": {"initial": {"beta": {"values": BETAS}}}})
    assert sweep_plan(True, ("gravity",), sp.method) == (("reduced-u", 1), ("euler-poisson", 0))
    assert sp.key[0] == "reduced-u" and sp.pole_check == 1
    assert [(k[0], c) for k, c, _ in sp.fallback] == [("euler-poisson", 0)]
    # named, a formulation without a singular set runs alone, as before
    # one method per sweep (auto's for the first candidate, derive.sweeps.spec.load): the
    # sweep naming euler-poisson names that method too
    method = load({"scene": REF, "vary": {"initial": {"beta": {"values": BETAS}}}}).method
    named = {**REF, "simulate": {**REF["simulate"], "formulation": "euler-poisson", "method": method}}
    sp = load({"scene": named, "vary": {"initial": {"beta": {"values": BETAS}}}})
    assert sp.key[0] == "euler-poisson" and sp.pole_check == 0 and sp.fallback == ()


def test_each_point_runs_reduced_u_exactly_when_its_motion_keeps_the_clearance(swept):
    """The formulation per point against the closed-form turning points: reduced-u when both
    keep |sin beta| >= 0.1, euler-poisson when one does not (the start itself or later)."""
    assert (swept.status == "ok").all()
    for b0, form in zip(BETAS, swept.formulation):
        clear = min(math.sin(b) for b in _turning(b0)) >= REDUCED_U_CLEARANCE
        assert form == ("reduced-u" if clear else "euler-poisson"), b0
    assert set(swept.formulation) == {"reduced-u", "euler-poisson"}
    assert swept.model == "reduced_u_sym_gravity, euler_poisson_sym_gravity"


def test_measures_agree_with_single_runs_whichever_formulation_ran(swept):
    """Every point against the closed-form turning points and against ``derive.simulate`` of
    the same point (auto: reduced-u or, near a pole, euler-angles), densely sampled: the same
    quantities, to the tolerance."""
    rtol = REF["simulate"]["rtol"]
    for i, b0 in enumerate(BETAS):
        scene = {**REF, "initial": {**REF["initial"], "beta": b0},
                 "simulate": {**REF["simulate"], "samples": 20001}}
        sim = derive.simulate(scene)
        m = {k: v[i] for k, v in swept.measures.items()}
        lo, hi = _turning(b0)
        assert abs(m["beta_max"] - hi) < 1e-6 and abs(m["beta_min"] - lo) < 1e-6, b0
        # the samples' extrema lie inside the located ones, by at most the sampling's (dt^2) error
        assert m["beta_min"] - 1e-9 <= sim.beta.min() <= m["beta_min"] + 1e-5
        assert m["beta_max"] - 1e-5 <= sim.beta.max() <= m["beta_max"] + 1e-9
        # energy from each formulation's own state: a real drift, at the tolerance's level
        e = np.abs(sim.energy - sim.energy[0]) / abs(sim.energy[0])
        assert 0 < m["energy_drift"] < 100 * rtol and e.max() < 100 * rtol
        assert m["p_gamma_drift"] < 1e-6 * abs(sim.p_gamma[0])
        w2 = sim.omega[:, 1]
        assert m["flips"] == np.count_nonzero(np.diff(np.sign(w2[w2 != 0.0])))
        first = np.flatnonzero(np.diff(np.sign(w2)))[0]
        assert sim.t[first] <= m["time_to_flip"] <= sim.t[first + 1]
        for k, name in enumerate(("alpha", "beta", "gamma")):
            d = m[f"final_{name}"] - getattr(sim, name)[-1]
            assert abs(math.remainder(d, 2 * math.pi)) < 1e-5, (b0, name)
        for k in range(3):
            assert abs(m[f"final_omega{k + 1}"] - sim.omega[-1, k]) < 1e-5 * 6.0
        assert m["nfev"] > 0


def test_a_point_refused_by_reduced_u_runs_as_euler_poisson_would_alone(swept):
    """The fallback is per point: a refused point's numbers are those of a sweep that names
    euler-poisson, bit for bit, and the reduced-u points those of one naming reduced-u's
    candidate alone; the refusal itself is the compiled check's status RANGE."""
    # one method per sweep (auto's for the first candidate, derive.sweeps.spec.load): the
    # sweep naming euler-poisson names that method too
    method = load({"scene": REF, "vary": {"initial": {"beta": {"values": BETAS}}}}).method
    named = {**REF, "simulate": {**REF["simulate"], "formulation": "euler-poisson", "method": method}}
    ep = derive.sweep({"scene": named, "vary": {"initial": {"beta": {"values": BETAS}}},
                       "measures": MEASURES}, processes=1)
    fell = swept.formulation == "euler-poisson"
    for k in swept.measures:
        assert np.array_equal(swept.measures[k][fell], ep.measures[k][fell]), k
    # the others are reduced-u's own runs, not euler-poisson's
    assert not np.array_equal(swept.measures["nfev"][~fell], ep.measures["nfev"][~fell])
    sp = load({"scene": REF, "vary": {"initial": {"beta": {"values": BETAS}}}})
    t = np.array([0.0, REF["simulate"]["t_end"]])
    args = ms.driver_args(sp.method, 1e-9, 1e-12, 10**6)
    kernel = ms.MeasureKernel.load(catalogue.describe(sp.key), sp.method)
    res, _, st = kernel.run(sp.inputs, sp.ps, t, args, ms.config_of(MEASURES), None, 1)
    assert np.array_equal(st["status"] == Status.RANGE, fell)
    assert np.isnan(res[fell]).all() and not np.isnan(res[~fell][:, 0]).any()
    assert (st["nfev"][fell] == 0).all()  # refused before a step
    got = run_chunk(sp.key, sp.method, sp.inputs, sp.ps, t, args, ms.config_of(MEASURES))
    assert np.array_equal(got[0][~fell], res[~fell], equal_nan=True)  # no check: reduced-u alone


def test_results_do_not_depend_on_the_chunking():
    sp = load({"scene": REF, "vary": {"initial": {"beta": {"values": BETAS}}}})
    t = np.array([0.0, 3.0])
    args, cfg = ms.driver_args(sp.method, 1e-9, 1e-12, 10**6), ms.config_of(MEASURES)

    def chunk(idx):
        return run_chunk(sp.key, sp.method, sp.inputs[idx], sp.ps[idx], t, args, cfg, None, (),
                         sp.pole_check, tuple((k, c, p[idx]) for k, c, p in sp.fallback), True)

    whole = chunk(np.arange(len(BETAS)))
    assert set(whole[3]) == {0, 1}
    for i in range(len(BETAS)):
        alone = chunk(np.array([i]))
        assert np.array_equal(alone[0][0], whole[0][i], equal_nan=True)
        assert np.array_equal(alone[1][0], whole[1][i]) and alone[3][0] == whole[3][i]
        assert alone[2][0]["nfev"] == whole[2][i]["nfev"]
    odd = chunk(np.arange(1, len(BETAS), 2))
    assert np.array_equal(odd[0], whole[0][1::2], equal_nan=True)


@pytest.mark.slow  # the engines' agreement: tests/test_sweep.py in make test
def test_engines_identical_with_both_formulations():
    """In-process, a local pool and a Dask LocalCluster: the same formulation per point and the
    same numbers, bit for bit, on a sweep that runs both formulations."""
    pytest.importorskip("dask.distributed")
    spec = {"scene": {**REF, "simulate": {**REF["simulate"], "t_end": 1.0}},
            "random": {"n": 240, "seed": 4, "initial": {"beta": {"low": 0.02, "high": 1.2}}},
            "measures": ["beta_max", "beta_min", "energy_drift", "nfev", "flips",
                         "integral_drift"]}
    one = derive.sweep(spec, processes=1)
    assert 10 < (one.formulation == "euler-poisson").sum() < 230
    pool = derive.sweep(spec, processes=2)
    cluster = derive.sweep(spec, workers=2)
    for other in (pool, cluster):
        assert np.array_equal(other.formulation, one.formulation)
        assert np.array_equal(other.status, one.status)
        for k in one.measures:
            assert np.array_equal(other.measures[k], one.measures[k], equal_nan=True), k
