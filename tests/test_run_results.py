"""A run's Result and integrals: a prepared run builds its Result from the output rows, each run
has its own integrals (classified from its own numbers, a Goryachev–Chaplygin body per start),
a batch gives each scene its own numbers, a dict is simulated as it is at the call, and the C
drivers refuse bad output times."""
from __future__ import annotations

import copy
import dataclasses
import warnings

import numpy as np
import pytest

import derive
from derive.bench.reference import reference_data
from derive.errors import SceneError
from derive.sim import plan as plans
from derive.sim.scene import load_scene
from derive.symbolic import integrable
from derive.sim.result import Result


def _short() -> dict:
    data = reference_data(10.0)
    data["simulate"].update(t_end=1e-3, samples=2)
    return data


def _euler(scale: float) -> dict:
    """A free asymmetric body (Euler's case: the integral |L|²) with moments of ``scale``."""
    return {"body": {"I1": 1.0 * scale, "I2": 2.0 * scale, "I3": 2.5 * scale},
            "initial": {"alpha": 0.1, "beta": 0.8, "gamma": 0.2, "omega": [1.0, 2.0, 3.0]},
            "simulate": {"t_end": 1e-3, "samples": 2}}


def _fields_equal(a: Result, b: Result) -> None:
    for f in dataclasses.fields(Result):
        x, y = getattr(a, f.name), getattr(b, f.name)
        if isinstance(x, np.ndarray):
            assert np.array_equal(x, y), f.name
        elif f.name == "integrals":
            assert x.keys() == y.keys()
            for k in x:
                assert np.array_equal(x[k], y[k]), k
        else:
            assert x == y, f.name


@pytest.mark.parametrize("data", [_short(), _euler(1.0)], ids=["lagrange", "euler"])
def test_the_short_result_has_every_field_a_batch_result_has(data):
    """The compiled path fills the Result's ``__dict__`` itself, the outputs' views when first
    read: the same fields and values as the dataclass constructor the batch path calls
    (``_result``)."""
    res = derive.prepare(data).run()
    names = {f.name for f in dataclasses.fields(Result)}
    assert not {"alpha", "axis", "L"} & set(vars(res))  # not made yet
    assert all(getattr(res, name) is getattr(res, name) for name in names)  # made once, kept
    assert set(vars(res)) >= names
    assert res.integrals  # both scenes are integrable cases
    _fields_equal(res, derive.simulate_batch([data])[0])
    _fields_equal(derive.simulate(data), res)


def test_an_overflowing_integral_raises_without_a_warning():
    """|L|² beyond the float range (finite outputs, moments of 1e200): the IntegrationError
    names the integral, and no RuntimeWarning is printed before it, prepared or not."""
    data = _euler(1e200)
    prepared = derive.prepare(data)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for call in (prepared.run, lambda: derive.simulate(data)):
            with pytest.raises(derive.IntegrationError, match="non-finite integral_L_squared"):
                call()


def test_new_numbers_change_the_integral():
    """The integral is the run's own, not a number kept from another scene."""
    a, b = _euler(1.0), _euler(1.0)
    b["initial"]["omega"] = [1.0, 2.0, 3.5]
    ra, rb = derive.simulate(a), derive.simulate(b)
    assert not np.array_equal(ra.integral_L_squared, rb.integral_L_squared)
    assert np.allclose(ra.integral_L_squared, np.sum(ra.L ** 2, axis=1))
    assert np.allclose(rb.integral_L_squared, np.sum(rb.L ** 2, axis=1))


def test_prepared_runs_do_not_share_their_integrals():
    prepared = derive.prepare(_short())
    one, two = prepared.run(), prepared.run()
    (name,) = one.integrals
    assert not np.shares_memory(one.integrals[name], two.integrals[name])
    assert np.array_equal(one.integrals[name], two.integrals[name])
    assert not np.array_equal(prepared.run(initial={"gamma_dot": 5.0}).integrals[name], one.integrals[name])


def test_fallback_candidates_weigh_their_method_when_asked():
    """Under method "auto" a fallback's method is the cost model's for its own model, worked out
    when first asked (a fallback rarely runs)."""
    pl = plans.make(load_scene(_short()))
    assert len(pl.candidates) > 1
    assert "method" not in vars(pl.candidates[1])
    assert all(c.method == plans.auto_method(pl.scene, c.desc) for c in pl.candidates)


def _gc(omega3: float) -> dict:
    """A Goryachev–Chaplygin top (I1 = I2 = 4 I3, centre of mass in the equatorial plane):
    on the level L·n = 0 for one ω̃₃ (the example's), off it for others."""
    return {"body": {"I1": 0.4, "I2": 0.4, "I3": 0.1},
            "gravity": {"M": 1.0, "g": 9.81, "com": [0.05, 0.0, 0.0]},
            "initial": {"alpha": 0.0, "beta": 1.0, "gamma": 0.5, "omega": [2.0, -1.0, omega3]},
            "simulate": {"t_end": 1e-3, "samples": 2, "formulation": "euler-poisson"}}


def test_the_goryachev_chaplygin_level_is_decided_per_start():
    """The integrable case of a Goryachev–Chaplygin body depends on its start (on or off
    L·n = 0): alone or in one batch, each start gets its own integrals."""
    on = _gc(13.920675036160134)  # the example's start: on the level
    off = _gc(10.0)
    assert integrable.needs_area_level(0.4, 0.4, 0.1)
    assert not integrable.needs_area_level(1.0, 1.0, 0.5)
    ron, roff = derive.simulate(on), derive.simulate(off)
    assert "goryachev_chaplygin" in ron.integrals and "goryachev_chaplygin" not in roff.integrals
    bon, boff = derive.simulate_batch([on, off])
    _fields_equal(bon, ron)
    _fields_equal(boff, roff)


def test_a_batch_gives_each_scene_its_own_numbers():
    """A scene with other moments between two that share theirs gets its own parameters."""
    base = _short()
    a = dict(base, initial=dict(base["initial"], beta=0.7))
    b = copy.deepcopy(base)
    b["body"]["I1"] = 1.2
    c = dict(base, initial=dict(base["initial"], beta=0.9))
    batch = derive.simulate_batch([a, b, c])
    for scene, res in zip((a, b, c), batch):
        one = derive.simulate(scene)
        assert np.array_equal(res.omega, one.omega) and np.array_equal(res.energy, one.energy)
    assert not np.array_equal(batch[0].energy, batch[1].energy)


@pytest.mark.parametrize("method", ["dop853", "taylor"])
def test_the_c_drivers_refuse_output_times_that_are_not_finite_and_increasing(method):
    """The drivers' own check of the output times (``times_ok``: one branch-free pass,
    increasing from a finite first to a finite last time): every bad kind is BAD_ARGS, the
    good times run. Python checks them first, so these reach C only through the raw call."""
    from derive.methods.status import Status

    data = _short()
    data["simulate"]["method"] = method
    pl = plans.make(load_scene(data))
    c = pl.candidates[0]
    good = np.linspace(0.0, 1e-3, 40)
    bad = {"nan inside": np.where(np.arange(40) == 17, np.nan, good),
           "inf last": np.where(np.arange(40) == 39, np.inf, good),
           "-inf first": np.where(np.arange(40) == 0, -np.inf, good),
           "nan last": np.where(np.arange(40) == 39, np.nan, good),
           "repeated": np.where(np.arange(40) == 21, good[20], good),
           "decreasing": good[::-1].copy(),
           "none": good[:0]}
    assert c.kernel.bind(good, pl.inputs, c.args, c.pole_check)(c.params)[3] == 0
    for name, t in bad.items():
        status = c.kernel.bind(np.ascontiguousarray(t), pl.inputs, c.args, c.pole_check)(c.params)[3]
        assert status == Status.BAD_ARGS, name


def test_a_dict_changed_in_place_is_simulated_as_it_is_now():
    data = _short()
    before = derive.simulate(data)
    data["initial"]["beta"] = 0.9  # the caller's dict changes between the calls
    after = derive.simulate(data)
    assert after.beta[0] == pytest.approx(0.9) and before.beta[0] == pytest.approx(0.8)


def test_an_invalid_dict_fails_every_time_and_a_valid_one_after_it_runs():
    bad = _short()
    bad["body"]["I3"] = -1.0
    for _ in range(2):
        with pytest.raises(SceneError, match="I3"):
            derive.simulate(bad)
    good = _short()
    derive.simulate(good)
    bad2 = copy.deepcopy(good)
    bad2["initial"]["beta"] = float("nan")
    for _ in range(2):
        with pytest.raises(SceneError, match="beta"):
            derive.simulate(bad2)


def test_a_batch_reads_the_model_part_once_and_each_initial_state():
    """Dicts equal but for [initial] share the first's validated model part: the same scenes as
    validated one by one; a model part that differs in a type or a signed zero is validated on
    its own (and fails as it would alone)."""
    from derive.sim import batch
    from derive.sim.validator import same_model_part

    a, b = _short(), _short()
    b["initial"] = dict(b["initial"], beta=0.9)
    assert same_model_part(a, b)
    scenes = batch.batch_plan([a, b]).scenes
    assert scenes == [load_scene(a), load_scene(b)]
    assert scenes[1].body is scenes[0].body  # read once
    bad = copy.deepcopy(b)
    bad["initial"]["beta"] = float("nan")
    with pytest.raises(SceneError, match="initial.beta"):
        batch.batch_plan([a, bad])
    assert not same_model_part(a, dict(b, body={"I1": 1, "I3": 0.5}))
    assert not same_model_part(a, dict(b, body=dict(a["body"], I3=-0.0)))
    with pytest.raises(SceneError, match="body.I3"):
        batch.batch_plan([a, dict(b, body=dict(a["body"], I3=-0.0))])
    with pytest.raises(SceneError, match="body.I1"):
        batch.batch_plan([a, dict(b, body=dict(a["body"], I1=True))])
