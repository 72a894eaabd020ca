"""The fixed cost of a call: a prepared run builds its Result straight from
the output rows and evaluates the integrals without an ``np.errstate``; ``derive.simulate`` of
a scene equal to a recent one reuses its plan, and never a stale one."""
from __future__ import annotations

import copy
import dataclasses
import warnings

import numpy as np
import pytest

import derive
from derive.bench.reference import reference_data
from derive.sim import simulation
from derive.sim.simulation import Result


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


def test_ignoring_leaves_the_callers_error_state_alone():
    before = np.geterr()
    big = np.array([1e300])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert np.isinf(simulation._ignoring(np.multiply, big, big)).all()
    assert np.geterr() == before
    with pytest.warns(RuntimeWarning):
        np.multiply(big, big)


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


# ---------------------------------------------------------------------------------------------
# the memo of plans (derive.sim.plan.recent)

from derive.runtime import catalogue  # noqa: E402
from derive.sim import plan as plans  # noqa: E402
from derive.sim.scene import load_scene  # noqa: E402
from derive.symbolic import effects  # noqa: E402


def _same_result(a: Result, b: Result) -> None:
    _fields_equal(a, b)


def test_an_equal_scene_reuses_its_plan_and_gives_a_fresh_plan_s_result():
    data = _short()
    kept = plans.recent(load_scene(data))
    assert plans.recent(load_scene(copy.deepcopy(data))) is kept
    res = derive.simulate(data)
    assert res.scene is kept.scene
    _same_result(res, simulation.run(plans.make(load_scene(data))))


@pytest.mark.parametrize("change", [
    lambda d: d["initial"].update(beta=0.81),
    lambda d: d["gravity"].update(M=0.9),
    lambda d: d["body"].update(I3=0.55),
    lambda d: d["simulate"].update(rtol=1e-9),
    lambda d: d["simulate"].update(samples=3),
    lambda d: d.update(title="another top"),
    lambda d: d["initial"].update(alpha=-0.0),  # == 0.0, but its own sign
], ids=["initial", "effect", "body", "rtol", "samples", "title", "signed-zero"])
def test_changed_numbers_make_a_new_plan(change):
    data = _short()
    kept = plans.recent(load_scene(data))
    changed = copy.deepcopy(data)
    change(changed)
    new = plans.recent(load_scene(changed))
    assert new is not kept
    assert load_scene(changed) == new.scene
    _same_result(derive.simulate(changed), simulation.run(plans.make(load_scene(changed))))
    assert plans.recent(load_scene(data)) is kept  # the first one is still kept


def test_a_changed_source_makes_a_new_plan(tmp_path):
    """Scene equality ignores the source; the memo does not (errors name the scene's file)."""
    data = _short()
    data["simulate"].update(max_steps=1, t_end=10.0)
    path = tmp_path / "top.toml"
    path.write_text(f'title = "{data["title"]}"\n' + "".join(
        f"[{table}]\n" + "".join(f"{k} = {v!r}\n" for k, v in data[table].items())
        for table in ("body", "gravity", "initial", "simulate")))
    from_dict, from_file = load_scene(data), load_scene(str(path))
    assert from_dict == from_file
    assert plans.recent(from_file) is not plans.recent(from_dict)
    with pytest.raises(derive.IntegrationError) as from_dict_error:
        derive.simulate(data)
    assert plans.recent(load_scene(str(path))).scene.source == str(path)
    assert plans.recent(load_scene(data)).scene.source == "<dict>"
    with pytest.raises(derive.IntegrationError) as from_file_error:
        derive.simulate(str(path))
    assert str(from_file_error.value) == str(from_dict_error.value)  # the run's own, not a scene's


def test_a_registered_effect_makes_a_new_plan():
    data = _short()
    kept = plans.recent(load_scene(data))
    table = effects.Table("spring", "a toy table", keys=(effects.Key("k", "N m", "stiffness"),))
    effect = effects.Effect("spring", "spring", "a toy effect", params=(effects.Param("k_spring"),),
                            values=lambda v: {"k_spring": v["k"]}, torque=lambda omega, R, sym: None)
    effects.register(effect, table)
    try:
        during = plans.recent(load_scene(data))
        assert during is not kept
    finally:
        effects.unregister("spring")
    after = plans.recent(load_scene(data))
    assert after is not kept and after is not during
    _same_result(derive.simulate(data), simulation.run(plans.make(load_scene(data))))


def test_a_cleared_catalogue_makes_a_new_plan():
    """``catalogue.clear_memory`` forgets the model descriptions (a new cache): a kept plan
    holds the old ones, so it is not used again."""
    data = _short()
    kept = plans.recent(load_scene(data))
    catalogue.clear_memory()
    new = plans.recent(load_scene(data))
    assert new is not kept
    assert new.candidates[0].desc is catalogue.describe(
        (new.candidates[0].desc.formulation, new.scene.symmetric, new.scene.effects))
    _same_result(derive.simulate(data), simulation.run(plans.make(load_scene(data))))


def test_the_memo_stays_small_and_keeps_the_recent_plans():
    data = _short()
    first = plans.recent(load_scene(data))
    for k in range(plans.MEMO_SIZE + 10):
        other = copy.deepcopy(data)
        other["initial"]["beta"] = 0.5 + 1e-3 * k
        plans.recent(load_scene(other))
        plans.recent(load_scene(data))  # used again: stays among the recent ones
        assert len(plans._PLANS) <= plans.MEMO_SIZE
    assert plans.recent(load_scene(data)) is first
    oldest = copy.deepcopy(data)
    oldest["initial"]["beta"] = 0.5
    assert load_scene(oldest) not in [p.scene for p in plans._PLANS.values()]


def test_a_failing_scene_fails_again_from_the_memo():
    data = reference_data(10.0)
    data["simulate"].update(max_steps=5)
    messages = set()
    for _ in range(3):
        with pytest.raises(derive.IntegrationError) as err:
            derive.simulate(data)
        messages.add(str(err.value))
    assert len(messages) == 1


def test_fallback_candidates_weigh_their_method_when_asked():
    """Under method "auto" a fallback's method is the cost model's for its own model, worked out
    when first asked (a fallback rarely runs)."""
    pl = plans.make(load_scene(_short()))
    assert len(pl.candidates) > 1
    assert "method" not in vars(pl.candidates[1])
    assert all(c.method == plans.auto_method(pl.scene, c.desc) for c in pl.candidates)


# ---------------------------------------------------------------------------------------------
# the bench's figures


def test_the_fixed_cost_race_times_a_hit_and_a_miss_and_reports_both():
    from derive.bench import peers, report
    from derive.bench.runner import SMOKE

    plans.forget()
    out = peers.fixed_cost(SMOKE, [])
    assert out["derive_prepared"] > 0 and out["derive_simulate"] > 0 and out["derive_simulate_new"] > 0
    # the misses made plans of their own (the hit one plan): more than two kept, within the bound
    assert 2 < len(plans._PLANS) <= plans.MEMO_SIZE
    fake = dict(out, heyoka=1e-5, prepared_vs_heyoka=1.0, simulate_vs_heyoka=2.0, simulate_new_vs_heyoka=3.0)
    text = "\n".join(report.peers_section({"targets": {"peers": {"peers": ["heyoka"], "fixed_cost": fake}}}))
    assert "new numbers" in text and "**3×**" in text and "**2×**" in text
    older = {k: v for k, v in fake.items() if "new" not in k}  # results of an older bench
    assert "new numbers" not in "\n".join(report.peers_section({"targets": {"peers": {"fixed_cost": older}}}))
