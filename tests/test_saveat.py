"""One "what to keep" argument, ``derive.SaveAt``, on every entry point: the same numbers as the
full run, only what was asked for, bad values refused with one line naming the key."""
from __future__ import annotations

import numpy as np
import pytest

import derive
from derive import SaveAt

BASE = {"body": {"I1": 1.0, "I3": 0.5}, "gravity": {"M": 1.0, "g": 1.0, "l": 1.0},
        "simulate": {"t_end": 0.5, "samples": 11}}


def start(beta: float) -> dict:
    return {**BASE, "initial": {"alpha": 0.0, "beta": beta, "gamma": 0.0,
                                "alpha_dot": 0.0, "beta_dot": 0.0, "gamma_dot": 6.0}}


SCENES = [start(b) for b in (0.3, 0.45, 0.6)]


@pytest.mark.parametrize("bad, key", [(dict(t="events"), "t"), (dict(t="sometimes"), "t"),
                                      (dict(outputs=()), "outputs"), (dict(outputs=3), "outputs"),
                                      (dict(outputs=("beta", 4)), "outputs")])
def test_a_bad_saveat_is_one_line_naming_the_key(bad, key):
    with pytest.raises(derive.SceneError, match=f"saveat>: {key}:") as exc:
        SaveAt(**bad)
    assert "\n" not in str(exc.value)


def test_the_short_spellings_are_saveats():
    assert SaveAt.of(None) == SaveAt() and SaveAt().everything
    assert SaveAt.of("final") == SaveAt(t="final") and SaveAt.of("grid") == SaveAt()
    assert SaveAt.of(["beta", "axis", "beta"]).outputs == ("beta", "axis")
    assert SaveAt.of("beta").outputs == ("beta",)


def test_simulate_keeps_t_end_alone_bit_for_bit():
    full = derive.simulate(SCENES[0])
    end = derive.simulate(SCENES[0], saveat=SaveAt(t="final"))
    assert end.t.tolist() == [full.t[-1]]
    for name in ("alpha", "beta", "energy", "omega", "axis", "L", "state"):
        assert np.array_equal(getattr(end, name), getattr(full, name)[-1:]), name
    for name, values in full.integrals.items():
        assert np.array_equal(end.integrals[name], values[-1:])


def test_simulate_keeps_only_the_outputs_named():
    full = derive.simulate(SCENES[1])
    some = derive.simulate(SCENES[1], saveat=SaveAt(outputs=("beta", "axis")))
    assert np.array_equal(some.beta, full.beta) and np.array_equal(some.axis, full.axis)
    assert some.omega is None and some.energy is None and some.state is None
    assert {"beta", "axis", "t"} <= set(some.arrays()) and "omega" not in some.arrays()
    with pytest.raises(derive.SceneError, match="unknown output 'spin'"):
        derive.simulate(SCENES[1], saveat=SaveAt(outputs=("spin",)))


def test_a_prepared_run_keeps_what_simulate_keeps():
    top = derive.prepare(SCENES[0])
    for saveat in (SaveAt(t="final"), SaveAt(outputs=("gamma",)), SaveAt(t="final", outputs=("state",))):
        a, b = top.run(saveat=saveat), derive.simulate(SCENES[0], saveat=saveat)
        assert np.array_equal(a.t, b.t)
        for name in ("gamma", "beta", "state"):
            x, y = getattr(a, name), getattr(b, name)
            assert (x is None and y is None) or np.array_equal(x, y), name


def test_a_batch_with_saveat_is_the_batch_with_outputs():
    full = derive.simulate_batch(SCENES)
    assert isinstance(full, list) and len(full) == 3
    assert isinstance(derive.simulate_batch(SCENES, saveat=SaveAt()), list)
    end = derive.simulate_batch(SCENES, saveat=SaveAt(t="final"))
    old = derive.simulate_batch(SCENES, outputs="final")
    assert end.outputs.keys() == old.outputs.keys()
    for k in end.outputs:
        assert np.array_equal(end.outputs[k], old.outputs[k]), k
    assert np.array_equal(end.beta, [r.beta[-1] for r in full])
    some = derive.simulate_batch(SCENES, saveat=SaveAt(t="final", outputs=("omega",)))
    assert list(some.outputs) == ["omega"] and some.omega.shape == (3, 3)
    assert np.array_equal(some.omega, [r.omega[-1] for r in full])
    grid = derive.simulate_batch(SCENES, saveat=SaveAt(outputs=("beta",)))
    assert np.array_equal(grid.beta, [r.beta for r in full])
    with pytest.raises(derive.SceneError, match="saveat or outputs, not both"):
        derive.simulate_batch(SCENES, outputs="final", saveat=SaveAt(t="final"))


def test_a_prepared_batch_keeps_the_final_state_unless_told():
    top = derive.prepare(SCENES[0])
    betas = np.array([0.3, 0.45, 0.6])
    end = top.run_batch(initial={"beta": betas})
    assert end.final and np.array_equal(end.beta, derive.simulate_batch(SCENES, saveat=SaveAt(t="final")).beta)
    grid = top.run_batch(initial={"beta": betas}, saveat=SaveAt(outputs=("beta",)))
    assert not grid.final and np.array_equal(grid.beta, derive.simulate_batch(SCENES, outputs=("beta",)).beta)


def test_a_sweep_keeps_the_final_state_it_is_asked_for():
    spec = {"scene": SCENES[0], "vary": {"initial": {"beta": {"values": [0.3, 0.6]}}}, "measures": ["nfev"]}
    res = derive.sweep(spec, processes=1, saveat=SaveAt(t="final", outputs=("beta",)))
    ends = derive.simulate_batch([start(0.3), start(0.6)], saveat=SaveAt(t="final"))
    assert np.allclose(res.measures["final_beta"], ends.beta, rtol=1e-8)
    with pytest.raises(derive.SceneError, match="saveat: a sweep keeps t_end only"):
        derive.sweep(spec, processes=1, saveat=SaveAt())
    with pytest.raises(derive.SceneError, match="not 'energy'"):
        derive.sweep(spec, processes=1, saveat=SaveAt(t="final", outputs=("energy",)))
