"""The sweep's per-step work cut to what the measures read, without moving a value: the step
ends compute only the outputs the sweep's measures read (each alone, the output map inlined
and cut down by the compiler: templates/c/measures.c.j2), and the explicit steps take the
right-hand side inline (templates/c/solvers.c.j2). Every measure alone gives the bits it gives
beside all the others, and those are the bits of the full output pass at the same step ends."""
from __future__ import annotations

import copy
import platform

import numpy as np
import pytest

from derive.bench.reference import reference_data
from derive.runtime import catalogue
from derive.sweeps import measures as ms
from derive.sweeps.spec import load
from derive.sweeps.tasks import run_chunk

ALL = ["beta_max", "beta_min", "nutation", "energy_drift", "p_alpha_drift", "p_gamma_drift",
       "flips", "time_to_flip", "time_to_tilt", "integral_drift", "final_state", "nfev"]
RACKET = {"body": {"I1": 1e-3, "I2": 2e-3, "I3": 2.5e-3},
          "initial": {"alpha": 0.0, "beta": 1.5707963267948966, "gamma": 1.5707963267948966,
                      "omega": [1e-3, 10.0, 0.0]},
          "simulate": {"t_end": 15.0, "rtol": 1e-10}}


def _top(method, formulation="auto"):
    scene = reference_data(6.0)
    scene["simulate"] = {"t_end": 6.0, "rtol": 1e-9, "atol": 1e-12, "method": method,
                         "formulation": formulation}
    # starts clear of the poles and one near beta = 0 (reduced-u refuses it: the fallback runs)
    return {"scene": scene, "vary": {"initial": {"beta": {"values": [0.02, 0.4, 0.9, 1.3]}}}}


def _racket(method):
    scene = copy.deepcopy(RACKET)
    scene["simulate"]["method"] = method
    return {"scene": scene, "vary": {"initial": {"omega": {"0": {"values": [1e-3, 0.03, 0.3]}}}}}


CASES = {f"{name}-{method}": (make, method) for method in ("dop853", "taylor")
         for name, make in (("top", _top), ("racket", _racket))}
CASES["top-euler-poisson-dop853"] = (lambda m: _top(m, "euler-poisson"), "dop853")


def _measured(spec, names, options=None):
    spec = {**spec, "measure": {"names": list(names), "time_to_tilt": {"angle": 1.0},
                                **(options or {})}}
    sp = load(spec)
    s = sp.scene.simulate
    rows = ms.integral_rows(sp.general, sp.damping) if "integral_drift" in names else None
    res, final, st, ran = run_chunk(sp.key, sp.method, sp.inputs, sp.ps,
                                    np.array([0.0, s.t_end]),
                                    ms.driver_args(sp.method, s.rtol, s.atol, s.max_steps),
                                    ms.config_of(sp.measures, sp.options), rows, sp.terms,
                                    sp.pole_check, sp.fallback, True)
    assert (st["status"] == 0).all()
    return ms.read(sp.measures, catalogue.describe(sp.key), res, st, final), res, ran


@pytest.mark.parametrize("case", CASES)
def test_each_measure_alone_gives_its_bits_beside_all_the_others(case):
    make, method = CASES[case]
    spec = make(method)
    together, _, ran = _measured(spec, ALL)
    if case.startswith("top") and "euler-poisson" not in case:
        assert set(ran) == {0, 1}  # both candidates ran
    for name in ALL:
        alone, _, _ = _measured(spec, [name])
        for col, values in alone.items():
            if name in ("nfev",):  # the searches form dense outputs: their count depends on them
                continue
            assert np.array_equal(values, together[col], equal_nan=True), (case, col)


def test_accumulators_of_outputs_not_read_are_nan():
    """The compiled call's accumulators that no asked-for measure reads are not computed: NaN,
    and never read (derive.sweeps.measures.read picks the asked-for columns)."""
    spec = _top("dop853")
    _, res, _ = _measured(spec, ["energy_drift"])
    for k, slot in enumerate(ms.SLOTS):
        assert np.isnan(res[:, k]).all() == (slot != "energy_drift"), slot
    _, res, _ = _measured(spec, ["beta_max", "nfev"])
    for k, slot in enumerate(ms.SLOTS):
        assert np.isnan(res[:, k]).all() == (slot not in ("beta_max", "beta_min")), slot


@pytest.mark.skipif(platform.system() != "Linux" or platform.machine() != "x86_64",
                    reason="values recorded with glibc's libm on x86-64")
def test_values_recorded_before_the_step_ends_read_each_output_alone():
    """The reference top's points (one refused by reduced-u near beta = 0, run by euler-poisson)
    as the code that computed the whole output map at every step end, called the rhs and formed
    both steps' dense outputs around a turning point gave them (recorded at commit e98b5a7,
    float.hex): the outputs computed alone, the rhs inline and the dense outputs formed where a
    search reads give the same bits."""
    import derive

    spec = _top("dop853")
    spec["measure"] = {"names": ALL, "time_to_tilt": {"angle": 1.0}}
    res = derive.sweep(spec, processes=1)
    assert list(res.formulation) == ["euler-poisson", "reduced-u", "reduced-u", "reduced-u"]
    recorded = {
        "beta_max": ["0x1.366aea3d7e93ep-2", "0x1.84200681da52dp-1", "0x1.62d7db8ee2833p+0",
                     "0x1.cbfeea0ce47abp+0"],
        "beta_min": ["0x1.37ac4b0853199p-9", "0x1.70a006effd4e2p-2", "0x1.c094c933e2f06p-1",
                     "0x1.47a6abbb81dadp+0"],
        "energy_drift": ["0x1.961339bc95213p-43", "0x1.8e46569f77227p-38", "0x1.74e5a2ea1283bp-36",
                         "0x1.4383ef107afc1p-35"],
        "p_alpha_drift": ["0x1.9bb0000000000p-38", "0x0.0p+0", "0x0.0p+0", "0x0.0p+0"],
        "p_gamma_drift": ["0x0.0p+0", "0x0.0p+0", "0x0.0p+0", "0x0.0p+0"],
        "flips": ["0x1.8000000000000p+2"] * 4,
        "time_to_flip": ["0x1.0cedf1a00abc8p-1", "0x1.824af633c17cap-2", "0x1.3ad4ff8124a13p-2",
                         "0x1.20cb12ee1c509p-2"],
        "time_to_tilt": ["nan", "nan", "0x1.bb28226fd0258p-3", "0x0.0p+0"],
        "final_omega2": ["0x1.0e354f3b9b8b7p-2", "0x1.c4fba5861c35cp-2", "0x1.a1a3132d541bap-1",
                         "0x1.d239ac0955cbbp-2"],
    }
    for name, values in recorded.items():
        expected = [float.fromhex(v) for v in values]
        assert np.array_equal(res.measures[name], expected, equal_nan=True), name
    # the rhs evaluations then: the searches now form only the dense outputs they read (three
    # DOP853 stages fewer for each step a turning point's search does not enter)
    before, now = np.array([1014, 641, 652, 664]), res.measures["nfev"]
    assert (now < before).all() and ((before - now) % 3 == 0).all()
    assert now.tolist() == [1008, 632, 640, 652]


def test_loading_a_sweep_changes_neither_the_given_scene_nor_the_base():
    """The points' scenes (each varied value checked against the contract, the representative
    point) are shallow copies of the base scene with the changed tables copied
    (derive.sweeps.points._set): neither the caller's dict nor the base scene is touched, a
    vector key and a user term's parameter included."""
    from derive.sweeps.points import _set

    base = reference_data(2.0)
    base["simulate"] = {"t_end": 2.0}
    base["potential"] = [{"name": "magnet", "V": "-mu*B*R13", "params": {"mu": 0.2, "B": 1.5}}]
    spec = {"scene": base, "vary": {"initial": {"beta": {"values": [0.4, 0.9]},
                                                "gamma_dot": {"values": [3.0, 5.0]}},
                                    "potential.magnet.mu": {"values": [0.1, 0.3]}},
            "measures": ["beta_max"]}
    given = copy.deepcopy(spec)
    sp = load(spec)
    assert spec == given and sp.raw == given["scene"]
    data = dict(sp.raw)
    _set(data, "potential.magnet.mu", 0.7)
    _set(data, "initial.beta", 0.5)
    assert sp.raw == given["scene"]
    assert data["potential"][0]["params"] == {"mu": 0.7, "B": 1.5} and data["initial"]["beta"] == 0.5
    omega = {"body": {"I1": 1.0, "I3": 0.5}, "initial": {"alpha": 0.0, "beta": 0.5, "gamma": 0.0,
                                                          "omega": [0.1, 0.2, 3.0]},
             "simulate": {"t_end": 1.0}}
    kept = copy.deepcopy(omega)
    data = dict(omega)
    _set(data, "initial.omega.1", -0.2)
    assert omega == kept and data["initial"]["omega"] == [0.1, -0.2, 3.0]


def test_a_config_of_another_length_is_refused_before_the_c_call():
    """The compiled loop reads every flag of config (derive.sweeps.measures.CONFIG): an array of
    the old length (before the output flags) is refused, not read past its end."""
    sp = load({**_top("dop853"), "measures": ["beta_max"]})
    kernel = ms.MeasureKernel.load(catalogue.describe(sp.key), sp.method)
    s = sp.scene.simulate
    args = ms.driver_args(sp.method, s.rtol, s.atol, s.max_steps)
    with pytest.raises(ValueError, match="config must hold"):
        kernel.run(sp.inputs, sp.ps, np.array([0.0, 1.0]), args, np.zeros(6))
