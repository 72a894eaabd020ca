"""The Taylor method's full-grid lanes driver (``<model>_run_taylor`` saving every sample with
``save->lanes``) runs W trajectories at once with every sample, each
lane its own steps, each step's samples made by the scalar solver's own dense output from the
lane's series (kept a few steps and then made together). Each trajectory's states, outputs,
status and statistics are the scalar full batch driver's bit for bit, and
``derive.simulate_batch`` and a prepared ``run_batch`` of outputs at every sample run it for the
Taylor method (``BatchResult.driver`` ``"full-lanes"``)."""
import re

import numpy as np
import pytest

import derive
from derive.methods.status import Status
from derive.runtime import integrate
from derive.runtime.integrate import ModelKernel
from derive.sim import batch
from derive.symbolic.formulations import OUTPUTS
from tests.test_taylor_lanes import RULES, _lanes_library, kernels, same, scenes, spread

# the vector and lanes builds are only what they are at derive's own optimisation level
pytestmark = pytest.mark.optimised

FORMULATIONS = ["reduced-u", "reduced", "euler-angles", "quaternion", "euler-poisson"]


def full(kernel, inputs, ps, t, args, pole, lanes):
    return kernel.simulate_batch(inputs, ps, t, args, pole, lanes=lanes)


# the reduced top (u = cos beta) and the quaternion body in make test; the trigonometric series
# of the full lanes in make test by test_the_reference_tops_outputs_series_in_the_full_lanes
# (Euler angles); the other formulations, each three -O3 builds of its own, in make test-slow
@pytest.mark.parametrize("samples", [21, pytest.param(401, marks=pytest.mark.slow)])
@pytest.mark.parametrize("formulation", [f if f in ("quaternion", "reduced-u") else
                                         pytest.param(f, marks=pytest.mark.slow) for f in FORMULATIONS])
def test_the_full_lanes_are_the_scalar_full_driver_bit_for_bit(formulation, samples):
    """Over 3 s, 21 samples (steps without one) or 401 (a dozen and more in a step), a ragged
    last group (13 trajectories), this CPU's width and the baseline's (with 401 samples, and
    the reduced top's with 21)."""
    sc = scenes(13, formulation=formulation, samples=samples)
    bp, desc, scalar, native, args, pole = kernels(sc, formulation)
    assert native.has_lanes_full and not scalar.has_lanes_full
    ps = bp.params(desc)
    want = full(scalar, bp.inputs, ps, bp.t, args, pole, False)
    assert (want[3]["status"] == 0).all() and len(set(want[3]["nstep"])) > 3
    if samples == 21:
        assert want[3]["nstep"].max() > 20  # more steps than samples: steps without one
    same(want, full(native, bp.inputs, ps, bp.t, args, pole, True))
    # the baseline width (a third -O3 build of the model) for the reduced top in make test, for
    # the others in make test-slow (with 401 samples): test_taylor_lanes.py's
    # test_the_baseline_width_is_the_scalar_driver_bit_for_bit has why
    if formulation == "reduced-u" or samples == 401:
        baseline = _lanes_library(desc, "baseline", ["-DDERIVE_LANES"])
        assert baseline.lanes == 2
        same(want, full(baseline, bp.inputs, ps, bp.t, args, pole, True))


@pytest.mark.slow  # (the rules in the lanes: test_taylor_lanes.py; the full driver: above)
def test_every_rule_and_the_outputs_series_in_the_full_lanes():
    """A user body whose jet has every rule, and whose outputs have series of their own (the
    nodes a lane copies out for the dense output beyond the states)."""
    sc = [{**RULES, "initial": d["initial"], "simulate": {**RULES["simulate"], "samples": 101}}
          for d in scenes(11)]
    bp = batch.batch_plan(sc)
    formulation, pole = bp.candidates[0]
    desc, _, args = bp.kernel(formulation)
    scalar, native = (ModelKernel.load(desc, bp.method, b) for b in ("portable", "lanes"))
    ps = bp.params(desc)
    want = full(scalar, bp.inputs, ps, bp.t, args, pole, False)
    assert (want[3]["status"] == 0).all()
    same(want, full(native, bp.inputs, ps, bp.t, args, pole, True))


def test_the_reference_tops_outputs_series_in_the_full_lanes():
    """The Euler-angle top's outputs read series of sin and cos the right-hand side does not
    have (made in the dense output from the nodes the lane copies out)."""
    sc = scenes(17, formulation="euler-angles", samples=301, t_end=6.0)
    bp, desc, scalar, native, args, pole = kernels(sc, "euler-angles")
    source = desc.c_sources()[f"{desc.name}_taylor.c"]
    dense = re.search(r"#define DERIVE_T_EACH_DENSE\(X\)((?:.*\\\n)*.*)", source).group(1)
    assert dense.count("X(") > len(desc.states)  # more nodes than the states copied
    ps = bp.params(desc)
    same(full(scalar, bp.inputs, ps, bp.t, args, pole, False), full(native, bp.inputs, ps, bp.t, args, pole, True))


@pytest.mark.parametrize("formulation", ["reduced-u", "quaternion"])
def test_full_lanes_refilled_mid_batch_are_the_scalar_driver_bit_for_bit(formulation):
    """Step counts several fold apart, so lanes take new trajectories mid-way and a lane's kept
    steps fill its buffer (fast spins, 1001 samples: the samples of a buffer are made before
    the trajectory ends); the batch the other way round too."""
    sc = spread(37, formulation=formulation, t_end=6.0, samples=1001)
    bp, desc, scalar, native, args, pole = kernels(sc, formulation)
    ps = bp.params(desc)
    want = full(scalar, bp.inputs, ps, bp.t, args, pole, False)
    steps = want[3]["nstep"]
    assert (want[3]["status"] == 0).all() and steps.max() > 4 * steps.min()
    # a lane keeps 2048 doubles of steps, 6 + NY (order + 1) each (order 13 at rtol 1e-10): the
    # longest trajectories fill it
    assert steps.max() * (6 + len(desc.states) * 14) > 2 * 2048
    same(want, full(native, bp.inputs, ps, bp.t, args, pole, True))
    rev = bp.inputs[::-1].copy(), ps[::-1].copy()
    same(full(scalar, *rev, bp.t, args, pole, False), full(native, *rev, bp.t, args, pole, True))


def test_full_lanes_after_failures_and_budgets_are_the_scalar_driver_bit_for_bit():
    """Failing starts, lanes failing in their first step, lanes out of steps with samples kept:
    every status and every statistic the scalar driver's (a kept step's samples are made before
    the lane's failure is said), and the outputs of the trajectories that succeeded."""
    sc = spread(41, formulation="reduced-u", t_end=6.0, samples=401)
    bp, desc, scalar, native, args, pole = kernels(sc, "reduced-u")
    ps = bp.params(desc)
    steps = full(scalar, bp.inputs, ps, bp.t, args, pole, False)[3]["nstep"]
    args = list(args)
    args[-1] = int(np.percentile(steps, 70))
    inputs = bp.inputs.copy()
    inputs[[2, 3, 17], 8] = np.nan
    inputs[[0, 9, 10, 30], 8] = 1e200
    want = full(scalar, inputs, ps, bp.t, args, pole, False)
    st = want[3]
    assert (st["status"] == Status.MAX_STEPS).sum() >= 5 and (st["status"] == 0).sum() >= 15
    assert (st["nfev"][[2, 3, 17]] == 0).all() and (st["nfev"][[0, 9, 10, 30]] == 1).all()
    same(want, full(native, inputs, ps, bp.t, args, pole, True))


def test_a_refused_start_stops_the_full_lanes_batch():
    """A pole check that refuses a start: status RANGE for it and the rest, as the scalar
    driver says, so the batch's next formulation runs."""
    sc = scenes(9, formulation="reduced-u", samples=21)
    bp, desc, scalar, native, args, _ = kernels(sc, "reduced-u")
    inputs = bp.inputs.copy()
    inputs[3, 1] = 0.05
    got = full(native, inputs, bp.params(desc), bp.t, args, 1, True)
    want = full(scalar, inputs, bp.params(desc), bp.t, args, 1, False)
    assert want[3]["status"][3] == Status.RANGE
    assert got[3][3:].tobytes() == want[3][3:].tobytes()


def test_a_single_sample_takes_the_scalar_driver():
    sc = scenes(9, formulation="reduced-u", samples=2)
    bp, desc, scalar, native, args, pole = kernels(sc, "reduced-u")
    t = bp.t[:1].copy()
    ps = bp.params(desc)
    same(full(scalar, bp.inputs, ps, t, args, pole, False), full(native, bp.inputs, ps, t, args, pole, True))


def test_simulate_batch_runs_the_full_lanes_for_the_taylor_method(monkeypatch):
    """``derive.simulate_batch`` of at least LANES_MIN Taylor scenes: each Result the scalar
    batch's bit for bit (the lanes taken away by monkeypatching), the pole check that sends the
    batch to the next formulation included; a smaller batch runs the scalar driver."""
    sc = spread(19, formulation="auto", samples=301)
    sc[5] = {**sc[5], "initial": {**sc[5]["initial"], "beta": 0.02}}  # near the pole: refused by reduced-u
    calls = []
    real = ModelKernel.simulate_batch

    def spy(self, *a, lanes=False, **k):
        calls.append(lanes)
        return real(self, *a, lanes=lanes, **k)

    monkeypatch.setattr(ModelKernel, "simulate_batch", spy)
    got = derive.simulate_batch(sc)
    assert True in calls
    monkeypatch.setattr(ModelKernel, "full_lanes", lambda self, n: None)
    calls.clear()
    want = derive.simulate_batch(sc)
    assert calls and True not in calls
    assert {r.formulation for r in got} == {r.formulation for r in want}
    for a, b in zip(got, want):
        for name, _ in OUTPUTS:
            assert np.array_equal(getattr(a, name), getattr(b, name)), name
        assert np.array_equal(a.state, b.state) and a.nfev == b.nfev
    monkeypatch.undo()
    kernel = batch.batch_plan(sc).kernel("reduced-u")[1]
    assert integrate.LANES_MIN == 8
    assert kernel.full_lanes(7) is None and kernel.full_lanes(8).has_lanes_full


def test_run_batch_of_named_outputs_runs_the_full_lanes_in_whole_lane_sets():
    """A prepared batch of outputs at every sample: driver ``"full-lanes"``, in chunks of whole
    lane sets, the numbers of ``simulate_batch``'s Results."""
    sc = scenes(45, formulation="reduced-u", samples=2001, t_end=6.0)
    runs = derive.simulate_batch(sc)
    prepared = derive.prepare(sc[0])
    initial = {k: np.array([d["initial"][k] for d in sc]) for k in sc[0]["initial"]}
    res = prepared.run_batch(initial=initial, outputs=("axis", "energy", "state"))
    assert res.driver == "full-lanes"
    assert np.array_equal(res.axis, np.array([r.axis for r in runs]))
    assert np.array_equal(res.energy, np.array([r.energy for r in runs]))
    assert np.array_equal(res.state, np.array([r.state for r in runs]))
