"""``derive.simulate_batch(dicts, outputs=...)`` of a family (dicts that differ only in their
initial numbers) runs as one prepared batch (derive.sim.prepared.family_batch): the numbers,
the driver and the errors of the scene-by-scene batch (derive.sim.batch.simulate_batch), and
anything that is not a family, or fails, goes the scene-by-scene way."""
from __future__ import annotations

import copy

import numpy as np
import pytest

import derive
from derive.errors import IntegrationError, SceneError
from derive.sim import batch, prepared, simulation
from tests.test_prepared_batch import same

BASE = {"title": "a top", "body": {"I1": 1.0, "I3": 0.5}, "gravity": {"M": 1.0, "g": 1.0, "l": 1.0},
        "simulate": {"t_end": 2.0, "samples": 41, "rtol": 1e-9, "atol": 1e-11}}


def family(n=9, seed=4, **simulate) -> list[dict]:
    """Fresh dicts (no table shared between them, as read from files), random starts."""
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n):
        d = copy.deepcopy(BASE)
        d["simulate"].update(simulate)
        d["initial"] = {"alpha": 0.0, "beta": float(rng.uniform(0.4, 1.2)), "gamma": 0.0,
                        "alpha_dot": float(rng.uniform(-0.5, 0.5)), "beta_dot": 0.2,
                        "gamma_dot": float(rng.uniform(4.0, 8.0))}
        out.append(d)
    return out


@pytest.fixture
def read_one_by_one(monkeypatch):
    """Counts the scene-by-scene plans made (each reads every dict of its batch)."""
    calls = []
    real = simulation.batch_plan

    def counted(scenes, **overrides):
        calls.append(len(scenes) if isinstance(scenes, (list, tuple)) else None)
        return real(scenes, **overrides)

    monkeypatch.setattr(simulation, "batch_plan", counted)
    return calls


@pytest.mark.parametrize("simulate", [{}, {"method": "dop853"}, {"method": "taylor", "rtol": 1e-11},
                                      {"formulation": "euler-angles"}])
@pytest.mark.parametrize("outputs", ["final", ("beta", "axis", "state")])
def test_a_family_runs_as_one_prepared_batch_with_the_scene_by_scene_numbers(simulate, outputs, read_one_by_one):
    scenes = family(**simulate)
    got = derive.simulate_batch(scenes, outputs=outputs)
    assert read_one_by_one == []  # no dict read one by one
    want = batch.simulate_batch(scenes, outputs)
    assert read_one_by_one == [len(scenes)]
    same(got, want)


def test_ints_partial_rates_and_a_start_near_the_pole(read_one_by_one):
    """Ints where floats were (as TOML writes 0), rates left out (0), and one start closer to
    the pole than reduced-u takes: the batch's formulation is the one that takes every start,
    as the scene-by-scene plan picks it."""
    scenes = family(5)
    for k, d in enumerate(scenes):
        d["initial"] = {"alpha": 0, "beta": 0.9 - 0.2 * k, "gamma": 0, "gamma_dot": 6}
    scenes[3]["initial"]["beta"] = 0.05
    got = derive.simulate_batch(scenes, outputs="final")
    assert read_one_by_one == []
    want = batch.simulate_batch(scenes, "final")
    assert got.formulation != "reduced-u"
    same(got, want)


def _variant(change):
    scenes = family(6)
    change(scenes)
    return scenes


NOT_A_FAMILY = {
    "another body": lambda s: s[2]["body"].update(I1=1.5),
    "an int for a float in the body": lambda s: s[2]["body"].update(I1=1),
    "-0.0 for 0.0": lambda s: [d.update(gravity={"M": 1.0, "g": 1.0, "com": [0.0, 0.0, 1.0]}) for d in s]
    and s[3]["gravity"].update(com=[-0.0, 0.0, 1.0]),
    "another title": lambda s: s[1].update(title="another top"),
    "another key order": lambda s: s.__setitem__(3, {k: s[3][k] for k in reversed(list(s[3]))}),
    "initial keys in another order": lambda s: s[2].update(initial=dict(reversed(list(s[2]["initial"].items())))),
    "omega given": lambda s: [d.update(initial={"alpha": 0.0, "beta": 0.8, "gamma": 0.0,
                                                "omega": [0.1, 0.2, 6.0 + k]}) for k, d in enumerate(s)],
    "a bool": lambda s: s[5]["initial"].update(alpha=False),
    "a numpy float": lambda s: s[5]["initial"].update(alpha=np.float64(0.1)),
    "an int past a double": lambda s: s[5]["initial"].update(alpha=10 ** 400),
}


@pytest.mark.parametrize("case", list(NOT_A_FAMILY))
def test_what_is_not_a_family_is_read_one_by_one(case, read_one_by_one):
    scenes = _variant(NOT_A_FAMILY[case])
    assert prepared.family_batch(scenes, "final") is None
    if case in ("an int past a double", "a bool"):  # the scene's own error, as one by one
        with pytest.raises(SceneError) as want:
            batch.simulate_batch(scenes, "final")
        with pytest.raises(SceneError) as got:
            derive.simulate_batch(scenes, outputs="final")
        assert str(got.value) == str(want.value) and "initial.alpha" in str(got.value)
        return
    want = batch.simulate_batch(scenes, "final")
    same(derive.simulate_batch(scenes, outputs="final"), want)
    assert read_one_by_one == [len(scenes)] * 2


def test_not_lists_of_dicts_overrides_and_single_scenes_are_read_one_by_one(read_one_by_one):
    scenes = family(4)
    assert prepared.family_batch(iter(scenes), "final") is None  # (consumed once: left alone)
    assert prepared.family_batch(scenes[:1], "final") is None
    assert prepared.family_batch([*scenes[:2], "looping_top"], "final") is None
    got = derive.simulate_batch(iter(scenes), outputs="final")
    # an override (the scenes' own rtol): one by one
    same(got, derive.simulate_batch(scenes, outputs="final", rtol=1e-9))
    derive.simulate_batch(scenes, outputs="final", rtol=None)  # None: not given, a family
    assert read_one_by_one == [None, 4]


@pytest.mark.parametrize("bad, key", [(float("nan"), "beta"), (float("inf"), "gamma_dot")])
def test_a_bad_number_fails_as_the_scene_by_scene_batch_says(bad, key):
    scenes = family(7)
    scenes[4]["initial"][key] = bad
    with pytest.raises(SceneError) as want:
        batch.simulate_batch(scenes, "final")
    with pytest.raises(SceneError) as got:
        derive.simulate_batch(scenes, outputs="final")
    assert str(got.value) == str(want.value) and f"initial.{key}" in str(got.value)


def test_a_failing_trajectory_is_named_as_the_scene_by_scene_batch_names_it():
    scenes = family(7, max_steps=5)
    with pytest.raises(IntegrationError) as want:
        batch.simulate_batch(scenes, "final")
    with pytest.raises(IntegrationError) as got:
        derive.simulate_batch(scenes, outputs="final")
    assert str(got.value) == str(want.value)


def test_an_invalid_first_scene_fails_as_the_scene_by_scene_batch_says():
    scenes = family(3)
    for d in scenes:
        d["body"]["I3"] = -1.0
    with pytest.raises(SceneError) as want:
        batch.simulate_batch(scenes, "final")
    with pytest.raises(SceneError) as got:
        derive.simulate_batch(scenes, outputs="final")
    assert str(got.value) == str(want.value) and "body.I3" in str(got.value)


@pytest.mark.parametrize("n", [1, 2, 999, 1000, 1001, 2001])
def test_same_contents_tells_a_family_across_the_pickles_batches(n):
    """derive.sim.scene.same_contents pickles all the dicts at once: the first's content
    repeated in the list's layout (batches of 1000 items) is a yes, whatever n, and a single
    difference anywhere, the first or the last of a batch included, is a no."""
    from derive.sim.scene import same_contents

    dicts = [copy.deepcopy(BASE) for _ in range(n)]
    assert same_contents(dicts)
    if n == 1:  # (nothing to differ from)
        return
    changes = (lambda d: d["body"].update(I1=1), lambda d: d["gravity"].update(l=-0.0),
               lambda d: d.update(title="another top"),
               lambda d: d.__setitem__("body", {"I3": 0.5, "I1": 1.0}))  # equal by ==, another order
    for at in sorted({0, n // 2, min(999, n - 1), min(1000, n - 1), n - 1}):
        for change in changes:
            other = copy.deepcopy(dicts)
            change(other[at])
            assert not same_contents(other), (n, at)


def test_a_family_past_the_pickles_batch_is_one():
    """1001 dicts: one family read from the pickle's bytes (floats), and one checked dict by
    dict (an int among the initial values: the list's second batch holds one item)."""
    scenes = family(1001)
    got = prepared._family(scenes)
    assert got is not None and got[2] is None and got[3].shape == (6, 1001)
    scenes[1000]["initial"]["beta_dot"] = 1
    got = prepared._family(scenes)
    assert got is not None and got[2] is not None and got[3].shape == (6, 1001)
    assert got[3][4, 1000] == 1.0


def test_what_does_not_pickle_is_not_a_family():
    from derive.sim.scene import same_contents

    a = copy.deepcopy(BASE)
    a["body"]["self"] = a["body"]  # a cycle
    assert not same_contents([a, copy.deepcopy(a)])
    assert not same_contents([{"f": lambda: 0}, {"f": lambda: 0}])


def test_family_columns_are_the_initial_values_bit_for_bit():
    """derive.sim.scene.family_columns reads the values out of one pickle of all the dicts:
    the very doubles (signed zeros, the largest and smallest, a NaN's bits), in the keys' order."""
    from derive.sim.scene import family_columns

    scenes = family(7)
    odd = [-0.0, 1.7976931348623157e308, 5e-324, float("nan"), -1e-300, 2.5]
    scenes[3]["initial"] = dict(zip(scenes[3]["initial"], odd))
    keys = tuple(scenes[0]["initial"])
    got = family_columns(scenes, keys)
    want = np.array([[d["initial"][k] for d in scenes] for k in keys])
    assert got.shape == (6, 7) and got.dtype == np.float64
    assert np.array_equal(got.view(np.uint64), want.view(np.uint64))


@pytest.mark.parametrize("case", [*NOT_A_FAMILY, "an int among the initial values", "three dicts"])
def test_family_columns_say_no_to_all_but_floats_in_the_first_ones_layout(case):
    """Anything but the first dict with other floats in its [initial] table: None (the family
    check then looks dict by dict, and an int among the initial values is still a family)."""
    from derive.sim.scene import family_columns

    if case == "an int among the initial values":
        scenes = family(6)
        scenes[2]["initial"]["beta_dot"] = 1
        assert prepared._family(scenes) is not None
    elif case == "three dicts":
        scenes = family(3)
    else:
        scenes = _variant(NOT_A_FAMILY[case])
    assert family_columns(scenes, tuple(scenes[0]["initial"])) is None
