"""``derive.simulate`` of scene dicts with new numbers: a dict equal to one
validated recently but for its ``[initial]`` table validates only that table
(``scene._rest_key``, ``_Validator.scene_like``), and a scene of a planned family (the same
settings and model, other numbers) is planned from the family's plan (``plan.sibling``),
sharing its kernel and bound C call. Each shortcut must give what the long way gives: the same
Scene, the same errors, the same plan decisions and bit-identical results."""
from __future__ import annotations

import copy
import math

import numpy as np
import pytest

import derive
from derive.bench.reference import reference_data
from derive.errors import SceneError
from derive.sim import plan as plans
from derive.sim import scene as scenes
from derive.sim import simulation
from derive.sim.scene import _Validator, load_scene
from derive.symbolic import integrable
from tests.test_fixed_cost import _fields_equal


def _short() -> dict:
    data = reference_data(10.0)
    data["simulate"].update(t_end=1e-3, samples=2)
    return data


def _full(data: dict):
    """The scene the validator makes of ``data`` in full (no memo)."""
    return _Validator("<dict>").scene(data, {})


def _gc(omega3: float) -> dict:
    """A Goryachev–Chaplygin top (I1 = I2 = 4 I3, centre of mass in the equatorial plane):
    on the level L·n = 0 for one ω̃₃ (the example's), off it for others."""
    return {"body": {"I1": 0.4, "I2": 0.4, "I3": 0.1},
            "gravity": {"M": 1.0, "g": 9.81, "com": [0.05, 0.0, 0.0]},
            "initial": {"alpha": 0.0, "beta": 1.0, "gamma": 0.5, "omega": [2.0, -1.0, omega3]},
            "simulate": {"t_end": 1e-3, "samples": 2, "formulation": "euler-poisson"}}


# ---------------------------------------------------------------------------------------------
# validation: the memo of scenes by everything but [initial]


@pytest.mark.parametrize("initial", [
    {"alpha": 0.1, "beta": 0.7, "gamma": -0.2, "alpha_dot": 0.5, "beta_dot": 0.0, "gamma_dot": 7.0},
    {"alpha": 0, "beta": 1, "gamma": 0, "gamma_dot": 5},          # ints, rates missing
    {"alpha": -0.0, "beta": 0.9, "gamma": 0.0, "omega": [0.1, -0.2, 6.0]},
], ids=["rates", "ints", "omega"])
def test_a_dict_with_a_new_initial_table_validates_as_in_full(initial):
    load_scene(_short())  # the memo's scene of this family
    data = dict(_short(), initial=initial)
    got = load_scene(data)
    assert got == _full(data)
    assert got.initial.__dict__ == _full(data).initial.__dict__
    assert math.copysign(1, got.initial.alpha) == math.copysign(1, _full(data).initial.alpha)
    assert got.source == "<dict>" and got.effects == _full(data).effects


@pytest.mark.parametrize("initial, key", [
    ({"alpha": 0.0, "beta": math.nan, "gamma": 0.0, "gamma_dot": 5.0}, "initial.beta"),
    ({"alpha": 0.0, "beta": 0.5, "gamma": 0.0, "gamma_dot": True}, "initial.gamma_dot"),
    ({"alpha": 0.0, "beta": 0.5, "gamma": 0.0, "spin": 5.0}, "initial.spin"),
    ({"alpha": 0.0, "beta": 0.5, "gamma": 0.0}, "initial"),
    ([1, 2, 3], "initial"),
], ids=["nan", "bool", "unknown-key", "no-rates", "not-a-table"])
def test_a_bad_initial_table_fails_as_in_full(initial, key):
    load_scene(_short())
    data = dict(_short(), initial=initial)
    with pytest.raises(SceneError) as memo:
        load_scene(data)
    with pytest.raises(SceneError) as full:
        _full(data)
    assert str(memo.value) == str(full.value)
    assert f": {key}" in str(memo.value)


@pytest.mark.parametrize("change, key", [
    (lambda d: d["body"].update(I1=True), "body.I1"),          # True == 1: a bool is refused
    (lambda d: d["body"].update(I1=-1.0), "body.I1"),
    (lambda d: d["simulate"].update(samples=2.0), "simulate.samples"),  # 2.0 == 2
    (lambda d: d["gravity"].update(com=[0.0, 0.0, "1"]), "gravity.com"),
], ids=["bool", "negative", "float-samples", "string-in-vector"])
def test_an_equal_but_invalid_rest_is_not_taken_from_the_memo(change, key):
    """Values equal to a validated dict's by ``==`` but of another type are validated anew."""
    good = _short()
    if key == "gravity.com":
        good["gravity"] = {"M": 1.0, "g": 1.0, "com": [0.0, 0.0, 1]}
    elif key == "body.I1":
        good["body"]["I1"] = 1
    load_scene(good)
    bad = copy.deepcopy(good)
    change(bad)
    with pytest.raises(SceneError, match=key.replace(".", r"\.")):
        load_scene(bad)


def test_signed_zeros_outside_initial_are_told_apart():
    """-0.0 == 0.0: the memo's key holds the text of a table with a zero, so a scene with
    g = -0.0 is not the one with g = 0.0 (the sign can reach the outputs)."""
    a = _short()
    a["gravity"]["g"] = 0.0
    b = copy.deepcopy(a)
    b["gravity"]["g"] = -0.0
    sa, sb = load_scene(a), load_scene(b)
    assert math.copysign(1, sa.gravity.g) == 1 and math.copysign(1, sb.gravity.g) == -1
    assert math.copysign(1, load_scene(copy.deepcopy(b)).gravity.g) == -1


def test_a_memo_scene_does_not_follow_a_changed_dict():
    data = _short()
    first = load_scene(data)
    data["body"]["I3"] = 0.6  # the caller's dict changes after the call
    assert load_scene(data).body.I3 == 0.6
    assert first.body.I3 == 0.5


def test_user_terms_are_memoised_by_their_text_and_numbers():
    """A scene with user terms: a new initial table validates as in full (the terms the
    memo's); other expressions or params are validated anew (a bad one fails)."""
    data = _short()
    del data["gravity"]
    data["potential"] = [{"name": "g1", "V": "M*g*l*R33", "params": {"M": 1.0, "g": 1.0, "l": 1.0}}]
    data["torque"] = [{"name": "drive", "tau": ["0", "0", "A*cos(w*t)"], "params": {"A": 0.01, "w": 3}}]
    load_scene(data)
    other = dict(data, initial=dict(data["initial"], beta=0.6))
    assert scenes._rest_key(other) == scenes._rest_key(data)
    got = load_scene(other)
    assert got == _full(other) and got.terms == _full(other).terms
    for change, key in ((lambda d: d["potential"][0].update(V="M*g*l*R33 + import_"), r"potential\.g1\.V"),
                        (lambda d: d["torque"][0]["params"].update(w=True), r"torque\.drive\.params\.w"),
                        (lambda d: d["torque"][0].update(tau=["0", "0", "os.system(1)"]), r"torque\.drive\.tau\.2")):
        bad = copy.deepcopy(data)
        change(bad)
        assert scenes._rest_key(bad) != scenes._rest_key(data)
        with pytest.raises(SceneError, match=key):
            load_scene(bad)


def test_unmemoised_shapes_still_validate():
    """Values of types TOML does not give and nested lists are left to the validator."""
    data = _short()
    assert scenes._rest_key(dict(data, potential=({"name": "k", "V": "0"},))) is None
    for com in ([[0.0], 0.0, 1.0], np.array([0.0, 0.0, 1.0]), [0.0, 0.0, None]):
        data["gravity"] = {"M": 1.0, "g": 1.0, "com": com}
        assert scenes._rest_key(data) is None
    with pytest.raises(SceneError, match=r"gravity\.com"):
        load_scene(data)


# ---------------------------------------------------------------------------------------------
# planning: a scene of a planned family


def _fresh_run(data: dict):
    return simulation.run(plans.make(load_scene(data)))


def test_a_family_scene_is_planned_from_the_family_and_runs_as_a_fresh_plan():
    plans.forget()
    data = _short()
    first = derive.simulate(data)
    near = plans._FAMILIES[plans._family(load_scene(data))]
    other = dict(data, initial=dict(data["initial"], beta=0.9, gamma_dot=5.5))
    pl = plans.recent(load_scene(other))
    assert pl.near is near and pl is not near
    assert pl.candidates[0].kernel is near.candidates[0].kernel
    assert pl.candidates[0].bound(pl.t, pl.inputs) is near.candidates[0].bound(near.t, near.inputs)
    res = derive.simulate(other)
    _fields_equal(res, _fresh_run(other))
    assert res.scene == load_scene(other)
    # the shared bound call runs each plan with its own inputs: no cross-talk
    _fields_equal(derive.simulate(data), first)
    _fields_equal(simulation.run(pl), res)


@pytest.mark.parametrize("change", [
    lambda d: d["body"].update(I3=0.55),
    lambda d: d["gravity"].update(M=0.9),
], ids=["body", "effect"])
def test_a_family_scene_with_new_model_numbers_runs_as_a_fresh_plan(change):
    plans.forget()
    data = _short()
    derive.simulate(data)
    other = copy.deepcopy(data)
    change(other)
    pl = plans.recent(load_scene(other))
    assert pl.near is not None and pl.candidates[0].params is not pl.near.candidates[0].params
    _fields_equal(derive.simulate(other), _fresh_run(other))


def test_a_start_that_changes_auto_s_formulations_gets_its_own_plan():
    """Near the pole reduced-u refuses the start: the family's plan is not this scene's."""
    plans.forget()
    data = _short()
    derive.simulate(data)
    near = plans._FAMILIES[plans._family(load_scene(data))]
    polar = dict(data, initial=dict(data["initial"], beta=1e-9))
    pl = plans.recent(load_scene(polar))
    assert [c.desc.formulation for c in pl.candidates] != [c.desc.formulation for c in near.candidates]
    assert pl.near is None
    _fields_equal(derive.simulate(polar), _fresh_run(polar))


def test_a_start_that_changes_auto_s_method_gets_its_own_plan():
    """A spin a hundred times faster makes the run a hundred times longer in radians: the cost
    model picks DOP853 for it where the family's plan runs the Taylor method (many samples,
    rtol 1e-6); the scene is planned anew, with make()'s method."""
    plans.forget()
    data = reference_data(10.0)
    data["simulate"].update(samples=10001, rtol=1e-6, atol=1e-8)
    derive.simulate(data)
    assert plans._FAMILIES[plans._family(load_scene(data))].method == "taylor"
    fast = dict(data, initial=dict(data["initial"], gamma_dot=600.0))
    pl = plans.recent(load_scene(fast))
    assert pl.near is None and pl.method == plans.make(load_scene(fast)).method == "dop853"
    _fields_equal(derive.simulate(fast), _fresh_run(fast))


def test_the_goryachev_chaplygin_level_is_decided_per_start():
    """The integrable case of a Goryachev–Chaplygin body depends on its start (on or off
    L·n = 0): a family scene with the same body does not take the family's integrals."""
    plans.forget()
    on = _gc(13.920675036160134)  # the example's start: on the level
    off = _gc(10.0)
    assert integrable.needs_area_level(0.4, 0.4, 0.1)
    assert not integrable.needs_area_level(1.0, 1.0, 0.5)
    ron = derive.simulate(on)
    roff = derive.simulate(off)
    assert plans.recent(load_scene(off)).near is not None
    assert "goryachev_chaplygin" in ron.integrals and "goryachev_chaplygin" not in roff.integrals
    _fields_equal(roff, _fresh_run(off))
    _fields_equal(derive.simulate(on), _fresh_run(on))


def test_a_cleared_catalogue_is_not_planned_from_an_old_family():
    from derive.runtime import catalogue

    plans.forget()
    data = _short()
    derive.simulate(data)
    catalogue.clear_memory()
    other = dict(data, initial=dict(data["initial"], gamma_dot=5.0))
    pl = plans.recent(load_scene(other))
    assert pl.near is None
    assert pl.candidates[0].desc is catalogue.describe(
        (pl.candidates[0].desc.formulation, pl.scene.symmetric, pl.scene.effects))
    _fields_equal(derive.simulate(other), _fresh_run(other))


def test_many_families_keep_the_memos_small():
    plans.forget()
    base = _short()
    for k in range(plans.MEMO_SIZE + 5):
        d = copy.deepcopy(base)
        d["body"]["I3"] = 0.5 + 1e-3 * k
        d["title"] = f"top {k}"
        plans.recent(load_scene(d))
        assert len(plans._FAMILIES) <= plans.MEMO_SIZE and len(plans._PLANS) <= plans.MEMO_SIZE
    assert len(scenes._RESTS) <= scenes._RESTS_SIZE
    assert np.isfinite(derive.simulate(base).energy).all()


def test_a_batch_of_family_scenes_gives_each_its_own_numbers():
    """A batch whose scenes share their body and effect values (load_scene's memo) works out
    the parameters once per run of equal ones: a scene with other moments between two of the
    family still gets its own."""
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


# ---------------------------------------------------------------------------------------------
# a dict simulated recently (plan.for_dict): its plan, not validated again


def _counting(monkeypatch):
    """Count the scenes ``derive.simulate`` validates (its calls of load_scene)."""
    calls = []
    real = simulation.load_scene
    monkeypatch.setattr(simulation, "load_scene", lambda *a, **k: calls.append(1) or real(*a, **k))
    return calls


def test_an_equal_dict_runs_the_kept_plan_without_validation(monkeypatch):
    plans.forget()
    calls = _counting(monkeypatch)
    data = _short()
    first = derive.simulate(data)
    again = derive.simulate(copy.deepcopy(data))  # another dict, the same content
    assert len(calls) == 1
    _fields_equal(again, first)
    assert again.energy.tobytes() == first.energy.tobytes()


@pytest.mark.parametrize("change", [
    lambda d: d["initial"].update(gamma=-0.0),     # -0.0 == 0.0, but the sign is the scene's
    lambda d: d["initial"].update(beta_dot=0),     # an int where a float was: validated as given
    lambda d: d["gravity"].update(l=1),
    lambda d: d["simulate"].update(samples=3),
    lambda d: d.update(title="another"),
])
def test_a_dict_that_differs_in_any_way_is_validated_again(monkeypatch, change):
    plans.forget()
    calls = _counting(monkeypatch)
    data = _short()
    derive.simulate(data)
    other = copy.deepcopy(data)
    change(other)
    res = derive.simulate(other)
    assert len(calls) == 2
    _fields_equal(res, _fresh_run(other))
    if other["initial"]["gamma"] == 0.0 and math.copysign(1, other["initial"]["gamma"]) < 0:
        assert math.copysign(1, res.scene.initial.gamma) == -1


def test_a_dict_changed_in_place_is_simulated_as_it_is_now(monkeypatch):
    plans.forget()
    data = _short()
    before = derive.simulate(data)
    data["initial"]["beta"] = 0.9  # the caller's dict changes between the calls
    after = derive.simulate(data)
    assert after.beta[0] == pytest.approx(0.9) and before.beta[0] == pytest.approx(0.8)


def test_an_invalid_dict_fails_every_time_and_a_valid_one_after_it_runs(monkeypatch):
    plans.forget()
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


def test_a_dict_that_does_not_pickle_is_left_to_the_validator():
    data = _short()
    data["title"] = lambda: None  # pickle refuses a lambda; the validator names the key
    assert scenes.dict_key(data) is None
    with pytest.raises(SceneError, match="title"):
        derive.simulate(data)


def test_a_new_effects_registry_is_not_served_from_the_dict_memo(monkeypatch):
    """The key holds the effects registry's version: a registered effect changes what a dict
    validates to."""
    plans.forget()
    calls = _counting(monkeypatch)
    data = _short()
    derive.simulate(data)
    version = scenes.effects.VERSION
    version[0] += 1  # (a list bumped in place, as registering an effect does)
    try:
        derive.simulate(data)
    finally:
        version[0] -= 1
    assert len(calls) == 2
