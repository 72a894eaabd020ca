"""``derive.simulate_batch(dicts)`` (one Result per scene) of a family (dicts that differ only in
their initial numbers) runs as one prepared batch plan (derive.sim.prepared.family_results):
each Result is the scene-by-scene batch's (derive.sim.simulation.simulate_batch), its outputs,
state, statistics, integrals and scene, its ``scene`` validated only when first read; what is
not a family, or fails, goes the scene-by-scene way with its errors."""
from __future__ import annotations

import pickle

import numpy as np
import pytest

import derive
from derive.errors import IntegrationError, SceneError
from derive.sim import prepared, simulation
from derive.sim.scene import load_scene
from derive.symbolic.formulations import OUTPUTS
from tests.test_family_batch import NOT_A_FAMILY, _variant, family, read_one_by_one  # noqa: F401


def same_results(got, want):
    assert len(got) == len(want)
    for a, b in zip(got, want):
        for name, _ in OUTPUTS:
            assert np.array_equal(getattr(a, name), getattr(b, name)), name
        assert np.array_equal(a.t, b.t) and np.array_equal(a.state, b.state)
        assert (a.nfev, a.method, a.formulation, a.model, a.effects) == (b.nfev, b.method, b.formulation, b.model,
                                                                         b.effects)
        assert a.integrals.keys() == b.integrals.keys()
        for k in a.integrals:
            assert np.array_equal(a.integrals[k], b.integrals[k]), k
        assert a.scene == b.scene


@pytest.mark.parametrize("simulate", [{}, {"method": "dop853"}, {"method": "taylor", "rtol": 1e-11},
                                      {"formulation": "euler-angles"}])
def test_a_family_runs_as_one_prepared_plan_with_the_scene_by_scene_results(simulate, read_one_by_one):
    scenes = family(11, **simulate)  # (at least LANES_MIN: the Taylor method's lanes)
    got = derive.simulate_batch(scenes)
    assert read_one_by_one == []
    want = simulation.simulate_batch(scenes)
    assert read_one_by_one == [len(scenes)]
    same_results(got, want)


def test_the_integrals_of_an_integrable_case_are_each_trajectorys_own():
    """The Lagrange top's extra integral (a component of L), made for the batch at once: each
    Result's its own trajectory's, a copy (writing it changes no output)."""
    scenes = family(9, method="taylor")
    got = derive.simulate_batch(scenes)
    want = simulation.simulate_batch(scenes)
    assert got[0].integrals and want[0].integrals
    same_results(got, want)
    name = next(iter(got[3].integrals))
    L = got[3].L.copy()
    got[3].integrals[name][:] = 0.0
    assert np.array_equal(got[3].L, L) and not np.array_equal(got[4].integrals[name], 0.0)


def test_a_results_scene_is_its_dict_as_called_made_when_first_read(read_one_by_one):
    scenes = family(8, method="taylor")
    got = derive.simulate_batch(scenes)
    assert "scene" not in got[5].__dict__
    before = load_scene(scenes[5])
    scenes[5]["initial"]["beta"] += 0.1  # changed after the call: the Result's scene is as called
    scenes[5]["body"]["I1"] = 3.0
    assert got[5].scene == before and got[5].scene.initial.beta == before.initial.beta
    assert "scene" in got[5].__dict__ and got[5].scene is got[5].scene
    copy = pickle.loads(pickle.dumps(got[2]))  # a Result whose scene is not made yet pickles
    assert copy.scene == got[2].scene and np.array_equal(copy.axis, got[2].axis)
    assert read_one_by_one == []


@pytest.mark.parametrize("case", [c for c in NOT_A_FAMILY if c not in ("an int past a double", "a bool")])
def test_what_is_not_a_family_is_read_one_by_one(case, read_one_by_one):
    scenes = _variant(NOT_A_FAMILY[case])
    assert prepared.family_results(scenes) is None
    same_results(derive.simulate_batch(scenes), simulation.simulate_batch(scenes))
    assert read_one_by_one == [len(scenes)] * 2


def test_a_body_whose_case_depends_on_the_state_is_read_one_by_one():
    """A Goryachev-Chaplygin body (I1 = I2 = 4 I3, the centre of mass in the equatorial plane):
    its integrable case holds on L.n = 0 only, so each scene is classified on its own."""
    scenes = family(4)
    for k, d in enumerate(scenes):
        d["body"] = {"I1": 4.0, "I2": 4.0, "I3": 1.0}
        d["gravity"] = {"M": 1.0, "g": 1.0, "com": [1.0, 0.0, 0.0]}
        d["initial"] = {"alpha": 0.0, "beta": 0.5 + 0.1 * k, "gamma": 0.0, "alpha_dot": 0.0,
                        "beta_dot": 0.0, "gamma_dot": 0.0 if k % 2 else 0.3}
    assert prepared.family_results(scenes) is None
    same_results(derive.simulate_batch(scenes), simulation.simulate_batch(scenes))


def test_failures_are_the_scene_by_scene_batchs():
    scenes = family(9, max_steps=5)
    with pytest.raises(IntegrationError) as want:
        simulation.simulate_batch(scenes)
    with pytest.raises(IntegrationError) as got:
        derive.simulate_batch(scenes)
    assert str(got.value) == str(want.value)
    scenes = family(9)
    scenes[6]["initial"]["beta"] = float("nan")
    with pytest.raises(SceneError) as want:
        simulation.simulate_batch(scenes)
    with pytest.raises(SceneError) as got:
        derive.simulate_batch(scenes)
    assert str(got.value) == str(want.value) and "initial.beta" in str(got.value)


def test_overrides_read_one_by_one(read_one_by_one):
    scenes = family(4)
    same_results(derive.simulate_batch(scenes, rtol=1e-9), derive.simulate_batch(scenes))
    assert read_one_by_one == [4]
