"""derive.prepare(scene).run_batch: N variations of a prepared scene in one batch call, the same
numbers as derive.simulate_batch of the N scenes, bit for bit, and its arrays checked as arrays."""
from __future__ import annotations

import numpy as np
import pytest

import derive
from derive.errors import IntegrationError, SceneError
from derive.symbolic.formulations import REGISTRY, starts_accepted
from derive.sim.scene import load_scene


def base(**simulate) -> dict:
    return {"body": {"I1": 1.0, "I3": 0.5}, "gravity": {"M": 1.0, "g": 1.0, "l": 1.0},
            "initial": {"alpha": 0.0, "beta": 0.8, "gamma": 0.0, "alpha_dot": -0.4, "beta_dot": 0.3,
                        "gamma_dot": 6.0},
            "simulate": {"t_end": 2.0, "samples": 41, "rtol": 1e-9, "atol": 1e-11, **simulate}}


def variants(data: dict, betas, masses=None) -> list[dict]:
    out = []
    for k, b in enumerate(betas):
        d = dict(data, initial=dict(data["initial"], beta=float(b)))
        if masses is not None:
            d["gravity"] = dict(data["gravity"], M=float(masses[k]))
        out.append(d)
    return out


def by_scene(scenes, outputs):
    """The scene-by-scene batch (each dict read and checked): the reference the prepared batch
    is held to."""
    return derive.simulate_batch(scenes, outputs=outputs)


def same(a, b) -> None:
    assert a.outputs.keys() == b.outputs.keys()
    for k in a.outputs:
        np.testing.assert_array_equal(a.outputs[k], b.outputs[k], err_msg=k)
    np.testing.assert_array_equal(a.nfev, b.nfev)
    assert (a.method, a.formulation, a.model, a.driver) == (b.method, b.formulation, b.model, b.driver)


BETAS = np.linspace(0.3, 1.2, 11)


@pytest.mark.parametrize("simulate", [{}, {"method": "taylor"}, {"method": "dop853"},
                                      {"method": "rk4", "h": 1e-3}, {"formulation": "euler-poisson"}])
@pytest.mark.parametrize("outputs", ["final", ("beta", "axis", "state")])
def test_equals_simulate_batch_of_the_scenes(simulate, outputs):
    data = base(**simulate)
    got = derive.prepare(data).run_batch(initial={"beta": BETAS}, outputs=outputs)
    want = by_scene(variants(data, BETAS), outputs)
    same(got, want)
    assert len(got) == len(BETAS)


def test_parameters_and_omega_as_arrays():
    """Parameters by the model's names and ω̃ as an (N, 3) array, beside numbers the same for
    every trajectory."""
    data = base()
    data["initial"] = {"alpha": 0.0, "beta": 0.8, "gamma": 0.0, "omega": [0.3, -0.2, 6.0]}
    masses = np.linspace(0.5, 2.0, len(BETAS))
    omegas = np.column_stack([np.linspace(0.1, 0.5, len(BETAS)), -0.2 * np.ones(len(BETAS)),
                              np.linspace(4.0, 8.0, len(BETAS))])
    got = derive.prepare(data).run_batch(initial={"beta": BETAS, "omega": omegas, "gamma": 0.25},
                                         params={"M": masses})
    scenes = []
    for k, d in enumerate(variants(data, BETAS, masses)):
        d["initial"] = dict(d["initial"], omega=omegas[k].tolist(), gamma=0.25)
        scenes.append(d)
    same(got, by_scene(scenes, "final"))


def test_starts_near_a_pole_send_the_batch_to_a_formulation_that_takes_them():
    """reduced-u needs |sin β₀| ≥ 0.1: a start closer to the pole keeps it out of the batch,
    as simulate_batch's plan keeps it out."""
    data = base()
    betas = np.array([0.8, 0.05, 1.0])
    got = derive.prepare(data).run_batch(initial={"beta": betas})
    want = by_scene(variants(data, betas), "final")
    assert got.formulation != "reduced-u"
    same(got, want)


@pytest.mark.parametrize("name", list(REGISTRY))
@pytest.mark.parametrize("beta", [0.8, 0.2, 0.05, 1e-4, 1e-10, 0.0])
@pytest.mark.parametrize("rates", [True, False])
def test_starts_accepted_is_applicable_on_the_start(name, beta, rates):
    """The start clearance a prepared batch checks as an array agrees with the formulation's
    own applicable() on a scene with that start (a symmetric top under gravity)."""
    data = base()
    if not rates:
        data["initial"] = {"alpha": 0.0, "beta": beta, "gamma": 0.0, "omega": [0.3, -0.2, 6.0]}
    else:
        data["initial"] = dict(data["initial"], beta=beta)
    sc = load_scene(data)
    assert bool(starts_accepted(name, np.array([abs(np.sin(beta))]), rates)[0]) == \
        (REGISTRY[name].applicable(sc) is None)


@pytest.mark.parametrize("initial, params, match", [
    ({"bogus": [1.0]}, None, r"initial\.bogus: not a key"),
    ({"omega": [1.0, 2.0, 3.0]}, None, r"initial\.omega: not a key"),
    ({"beta": [0.3, np.nan]}, None, r"initial\.beta\[1\]: must be finite"),
    ({"beta": "0.3"}, None, r"initial\.beta: must be a number or an array"),
    ({"beta": [[0.3]]}, None, r"initial\.beta: must be a number or an array"),
    ({"beta": [True, False]}, None, r"initial\.beta: must be a number or an array"),
    ({"beta": [0.3, 0.4]}, {"M": [1.0, 2.0, 3.0]}, r"params\.M: 3 values, but initial\.beta has 2"),
    (None, {"Q": [1.0]}, r"params: unknown parameter 'Q'"),
    (None, {"M": np.inf}, r"params\.M: must be finite"),
])
def test_bad_arrays_are_scene_errors_naming_the_key(initial, params, match):
    with pytest.raises(SceneError, match=match):
        derive.prepare(base()).run_batch(initial=initial, params=params)


def test_a_scipy_method_is_refused_as_simulate_batch_refuses_it():
    with pytest.raises(SceneError, match=r"simulate\.method: batches run in the C kernels"):
        derive.prepare(base(method="scipy-rk45")).run_batch(initial={"beta": BETAS})


def test_a_fixed_step_method_needs_its_step():
    with pytest.raises(SceneError, match=r"simulate\.h: a prepared batch of the fixed-step method rk4"):
        derive.prepare(base(method="rk4")).run_batch(initial={"beta": BETAS})


def test_a_named_formulation_refusing_a_start_names_the_trajectory():
    with pytest.raises(SceneError, match=r"initial\.beta\[1\]: the formulation 'reduced-u' cannot start"):
        derive.prepare(base(formulation="reduced-u")).run_batch(initial={"beta": [0.8, 0.01]})


def test_a_failure_names_the_trajectory():
    with pytest.raises(IntegrationError, match=r"trajectory 0: .*step"):
        derive.prepare(base(max_steps=3)).run_batch(initial={"beta": BETAS})


def test_numbers_alone_make_one_trajectory():
    got = derive.prepare(base()).run_batch(initial={"beta": 0.9}, params={"M": 1.5})
    want = by_scene(variants(base(), [0.9], [1.5]), "final")
    same(got, want)
    assert len(got) == 1
