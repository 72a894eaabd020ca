"""derive.prepare: a scene planned once (the one-way walk of derive.sim.plan) and run many times,
with the same numbers as derive.simulate, and no validation or look-up per run."""
from __future__ import annotations

import copy
import tomllib

import numpy as np
import pytest

import derive
from derive.sim import examples

ARRAYS = ("t", "alpha", "beta", "gamma", "omega", "axis", "energy", "p_alpha", "p_gamma", "n", "L")


def _scene(name: str) -> dict:
    with open(examples.path(name), "rb") as fh:
        data = tomllib.load(fh)
    data["simulate"] = {**data.get("simulate", {}), "t_end": 0.3, "samples": 31}
    return data


def _same(a, b):
    assert (a.method, a.formulation, a.nfev) == (b.method, b.formulation, b.nfev)
    for name in ARRAYS:
        assert np.array_equal(getattr(a, name), getattr(b, name)), name
    assert a.integrals.keys() == b.integrals.keys()


@pytest.mark.parametrize("name", ["looping_top", "free_symmetric", "tennis_racket", "kovalevskaya_top"])
def test_a_prepared_run_is_simulate_bit_for_bit(name):
    data = _scene(name)
    prepared = derive.prepare(data)
    _same(prepared.run(), derive.simulate(data))
    _same(prepared.run(), derive.simulate(data))  # and again: nothing of the first run kept


def test_new_initial_values_give_the_simulation_of_the_changed_scene():
    data = _scene("looping_top")
    prepared = derive.prepare(data)
    changed = copy.deepcopy(data)
    changed["initial"].update(beta=0.7, gamma_dot=140.0)
    _same(prepared.run(initial={"beta": 0.7, "gamma_dot": 140.0}), derive.simulate(changed))


def test_new_parameters_give_the_simulation_of_the_changed_scene():
    data = _scene("looping_top")
    prepared = derive.prepare(data)
    changed = copy.deepcopy(data)
    changed["gravity"]["M"] = 0.12
    changed["body"]["I1"] = 2.0e-4
    _same(prepared.run(params={"M": 0.12, "I1": 2.0e-4}), derive.simulate(changed))


def test_a_scene_given_omega_takes_omega():
    data = _scene("tennis_racket")
    assert "omega" in data["initial"]
    prepared = derive.prepare(data)
    changed = copy.deepcopy(data)
    changed["initial"]["omega"] = [0.02, 3.0, 0.01]
    # (the prepared plan keeps the method auto chose for the scene's own numbers; a simulate
    # of the changed scene may choose another: compared with the prepared one's)
    _same(prepared.run(initial={"omega": [0.02, 3.0, 0.01]}),
          derive.simulate(changed, method=prepared.plan.method))
    with pytest.raises(derive.SceneError, match="initial.gamma_dot: not a key"):
        prepared.run(initial={"gamma_dot": 1.0})


@pytest.mark.parametrize("initial, params, match", [
    ({"beta": float("nan")}, None, "initial.beta: must be a finite number"),
    ({"betta": 0.5}, None, "initial.betta: not a key"),
    ({"omega": [1.0, 2.0, 3.0]}, None, "initial.omega: not a key"),
    (None, {"mass": 1.0}, "params: unknown parameter 'mass'"),
    (None, {"M": "heavy"}, "params.M: must be a finite number"),
])
def test_bad_values_are_scene_errors_naming_the_key(initial, params, match):
    prepared = derive.prepare(_scene("looping_top"))
    with pytest.raises(derive.SceneError, match=match):
        prepared.run(initial=initial, params=params)


def test_a_run_asks_no_stage_again(monkeypatch):
    """The one-way walk: after prepare, a run neither validates the scene, nor plans, nor looks
    up a model or a kernel; it only calls C."""
    from derive.runtime import catalogue
    from derive.runtime.integrate import ModelKernel
    from derive.sim import auto, plan, scene

    prepared = derive.prepare(_scene("looping_top"))
    prepared.run()  # the first run loads the first candidate's kernel

    def asked(*args, **kwargs):
        raise AssertionError("a stage was asked again")

    for module, name in ((scene, "load_scene"), (plan, "make"), (auto, "plan"),
                         (catalogue, "describe"), (ModelKernel, "load")):
        monkeypatch.setattr(module, name, asked)
    _same(prepared.run(), prepared.run())


def test_a_start_the_planned_formulation_cannot_take_falls_back_like_simulate():
    """The plan keeps every candidate: a start at the pole, which the cheapest formulation's
    pole check (reduced-u's) refuses in C, runs the next one, as simulate of that scene does."""
    data = _scene("looping_top")
    prepared = derive.prepare(data)
    first = prepared.run()
    assert first.formulation == "reduced-u"
    changed = copy.deepcopy(data)
    changed["initial"]["beta"] = 0.0
    again = prepared.run(initial={"beta": 0.0})
    direct = derive.simulate(changed)
    assert again.formulation == direct.formulation != "reduced-u"
    _same(again, direct)
