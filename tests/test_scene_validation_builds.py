"""What scene validation builds: the Scene, field by field and type by type, for every shape of
valid input; the first problem in document order; the key sets following the effects registry."""
import copy
import math
import types

import numpy as np
import pytest

from derive.symbolic import effects
from derive.errors import SceneError
from derive.sim.scene import (SIMULATE_DEFAULTS, Body, Initial, Scene, Simulate, TableValues, body_omega, load_scene,)

TOP = {
    "title": "top",
    "body": {"I1": 1.0, "I3": 0.5},
    "gravity": {"M": 1.0, "g": 1.0, "l": 1.0},
    "initial": {"alpha": 0.0, "beta": 0.8, "gamma": 0.0,
                "alpha_dot": -0.4, "beta_dot": 0.3, "gamma_dot": 6.0},
    "simulate": {"t_end": 10.0, "samples": 1001, "rtol": 1e-10, "atol": 1e-12},
}


def edited(base=TOP, **tables):
    """A deep copy of ``base`` with whole tables replaced (None deletes one)."""
    data = copy.deepcopy(base)
    for name, table in tables.items():
        if table is None:
            del data[name]
        else:
            data[name] = table
    return data


def table_values(name, values, effect, given):
    """A TableValues as validation builds it (the keys the scene gave recorded for ``given()``)."""
    out = TableValues(name, values, effect)
    out.__dict__["_given"] = set(given)
    return out


def sim(**changes):
    """The Simulate of TOP's [simulate] with ``changes``."""
    fields = dict(SIMULATE_DEFAULTS, t_end=10.0, samples=1001, rtol=1e-10, atol=1e-12)
    fields.update(changes)
    return Simulate(**fields)


AXIAL = table_values("gravity", {"M": 1.0, "g": 1.0, "l": 1.0, "com": (0.0, 0.0, 1.0)},
                     "gravity", ("M", "g", "l"))
RATES = Initial(0.0, 0.8, 0.0, -0.4, 0.3, 6.0, body_omega(0.8, 0.0, -0.4, 0.3, 6.0))


def scene(title="top", body=Body(1.0, 1.0, 0.5), tables=None, initial=RATES, simulate=None):
    return Scene(title, body, {"gravity": AXIAL} if tables is None else tables, initial,
                 simulate or sim())


# name, scene dict, overrides, the Scene built by hand with the plain constructors
VALID = [
    ("reference", TOP, {}, scene()),
    ("ints where floats are expected, I2 given",
     edited(body={"I1": 1, "I2": 1, "I3": 1}, gravity={"M": 2, "g": 0, "l": -1},
            initial={"alpha": 0, "beta": 1, "gamma": 0, "alpha_dot": 0, "beta_dot": 0,
                     "gamma_dot": 3},
            simulate={"t_end": 2, "samples": 3, "atol": 1, "rtol": 0.5}),
     {},
     scene(body=Body(1.0, 1.0, 1.0),
           tables={"gravity": table_values("gravity", {"M": 2.0, "g": 0.0, "l": -1.0,
                                                       "com": (0.0, 0.0, -1.0)},
                                           "gravity", ("M", "g", "l"))},
           initial=Initial(0.0, 1.0, 0.0, 0.0, 0.0, 3.0, body_omega(1.0, 0.0, 0.0, 0.0, 3.0)),
           simulate=sim(t_end=2.0, samples=3, atol=1.0, rtol=0.5))),
    ("omega instead of rates, asymmetric body, no gravity, no title",
     edited(title=None, gravity=None, body={"I1": 1.0, "I2": 2.0, "I3": 2.5},
            initial={"alpha": 0.1, "beta": 1.0, "gamma": 0.2, "omega": [0.1, 3, -0.0]}),
     {},
     scene(title=None, body=Body(1.0, 2.0, 2.5), tables={},
           initial=Initial(0.1, 1.0, 0.2, None, None, None, (0.1, 3.0, -0.0)))),
    ("one rate given: the others are 0.0",
     edited(initial={"alpha": 0.0, "beta": 0.8, "gamma": 0.0, "gamma_dot": 6.0}), {},
     scene(initial=Initial(0.0, 0.8, 0.0, 0.0, 0.0, 6.0, body_omega(0.8, 0.0, 0.0, 0.0, 6.0)))),
    ("general centre of mass and damping, NumPy scalars and a tuple",
     edited(gravity={"M": np.float64(0.5), "g": 9.81, "com": (0.01, np.int64(0), 0.03)},
            damping={"c": np.float32(0.25)}),
     {},
     scene(tables={"gravity": table_values("gravity", {"M": 0.5, "g": 9.81, "l": None,
                                                       "com": (0.01, 0.0, 0.03)},
                                           "gravity_general", ("M", "g", "com")),
                   "damping": table_values("damping", {"c": 0.25}, "damping", ("c",))})),
    # ... and is l, written back as l
    ("com on axis 3 selects axial gravity, l derived",
     edited(gravity={"M": 1.0, "g": 1.0, "com": [0, 0, 2]}), {},
     scene(tables={"gravity": table_values("gravity", {"M": 1.0, "g": 1.0, "l": 2.0,
                                                       "com": (0.0, 0.0, 2.0)},
                                           "gravity", ("M", "g", "l"))})),
    ("every [simulate] key, a fixed-step method with h",
     edited(simulate={"t_end": 1.0, "samples": 11, "method": "rk4", "rtol": 1e-8, "atol": 1e-9,
                      "formulation": "quaternion", "h": 0.01, "max_steps": np.int64(500)}),
     {},
     scene(simulate=Simulate(1.0, 11, "rk4", 1e-8, 1e-9, "quaternion", 0.01, 500))),
    ("overrides replace and supply keys; None is not given",
     edited(simulate={"samples": 5}), {"t_end": 3, "method": "dop853", "rtol": None},
     scene(simulate=sim(t_end=3.0, samples=5, method="dop853", rtol=1e-10,
                        atol=SIMULATE_DEFAULTS["atol"]))),
    ("tables as read-only mappings, not dicts",
     {k: (types.MappingProxyType(v) if isinstance(v, dict) else v) for k, v in TOP.items()}, {},
     scene()),
]


def exact(x):
    """A value with its type and every bit (repr tells -0.0 from 0.0 and 1 from 1.0)."""
    if isinstance(x, tuple):
        return tuple(exact(v) for v in x)
    return type(x).__name__, repr(x)


@pytest.mark.parametrize("name, data, overrides, expected", VALID, ids=[v[0] for v in VALID])
def test_valid_variants_give_the_scene_built_by_hand(name, data, overrides, expected):
    got = load_scene(data, **overrides)
    assert got == expected
    for part in ("body", "initial", "simulate"):
        g, e = getattr(got, part), getattr(expected, part)
        assert type(g) is type(e)
        assert {k: exact(v) for k, v in vars(g).items()} == {k: exact(v) for k, v in vars(e).items()}
    assert exact(got.title) == exact(expected.title)
    assert list(got.tables) == list(expected.tables)
    for t, values in got.tables.items():
        want = expected.tables[t]
        assert values.effect == want.effect
        assert {k: exact(v) for k, v in values.items()} == {k: exact(v) for k, v in want.items()}
        assert values.given() == want.given()
    assert got.effects == expected.effects
    # What a Scene round-trips to stays put, and the scene reloads to itself.
    assert load_scene(got.to_dict()) == got
    assert load_scene(got) == got


def error(data, **overrides) -> str:
    with pytest.raises(SceneError) as info:
        load_scene(data, **overrides)
    return str(info.value)


# The first problem in document order.
FIRST_PROBLEM = [
    ("unknown key before a bad value in the same table",
     edited(body={"I1": 1.0, "i3": 2.0, "I3": -1.0}), {},
     "<dict>: body.i3: unknown key (did you mean I3? expected one of I1, I2, I3)"),
    ("the first of two unknown keys",
     edited(gravity={"M": 1.0, "q": 1, "g": 1.0, "l": 1.0, "c": 0.1}), {},
     "<dict>: gravity.q: unknown key (expected one of M, g, l, com)"),
    ("an unknown key in a read-only mapping",
     edited(damping=types.MappingProxyType({"c": 0.1, "k": 1.0})), {},
     "<dict>: damping.k: unknown key (expected one of c)"),
    ("a bad body before a bad gravity table",
     edited(body={"I1": 1.0, "I3": 3.0}, gravity={"M": -1.0, "g": 1.0, "l": 1.0}), {},
     "<dict>: body: moments violate the triangle inequality I1 + I2 >= I3 (I1 = 1, I2 = 1, "
     "I3 = 3); no rigid body has these principal moments"),
    ("I1 before I3 before the triangle",
     edited(body={"I3": math.nan, "I1": True}), {},
     "<dict>: body.I1: must be a positive finite number, got true (a boolean)"),
    ("the triangle with I1 the largest",
     edited(body={"I1": 3.0, "I2": 1.0, "I3": 1.0}), {},
     "<dict>: body: moments violate the triangle inequality I2 + I3 >= I1 (I1 = 3, I2 = 1, "
     "I3 = 1); no rigid body has these principal moments"),
    ("l and com both given before a bad M",
     edited(gravity={"M": "heavy", "g": 1.0, "l": 1.0, "com": [0, 0, 1]}), {},
     "<dict>: gravity.com: give l or com, not both (l, com given)"),
    ("a bad angle before rates and omega both given",
     edited(initial={"alpha": 0.0, "beta": math.inf, "gamma": 0.0, "gamma_dot": 1.0,
                     "omega": [0, 0, 1]}), {},
     "<dict>: initial.beta: must be a finite number (rad), got inf"),
    ("a bad rate after the good ones before it",
     edited(initial={"alpha": 0.0, "beta": 0.5, "gamma": 0.0, "alpha_dot": 1.0,
                     "gamma_dot": [1.0]}), {},
     "<dict>: initial.gamma_dot: must be a finite number (rad/s), got [1.0]"),
    ("t_end before samples before method",
     edited(simulate={"method": 3, "samples": 1, "t_end": -1.0}), {},
     "<dict>: simulate.t_end: must be a positive finite number (s), got -1.0"),
    ("method: a string of the wrong spelling",
     edited(simulate={"t_end": 1.0, "method": "Dop853"}), {},
     "<dict>: simulate.method: unknown method 'Dop853' (did you mean dop853? expected one of "),
    ("method: not a string",
     edited(simulate={"t_end": 1.0, "method": ["rk4"]}), {},
     "<dict>: simulate.method: must be a string, one of auto, "),
    ("rtol's range before its floor, before atol",
     edited(simulate={"t_end": 1.0, "rtol": 1e-15, "atol": -1.0}), {},
     "<dict>: simulate.rtol: must be at least 100 machine epsilons (2.2e-14): no "
     "double-precision integrator can meet 1e-15"),
    ("formulation after atol",
     edited(simulate={"t_end": 1.0, "formulation": "euler", "atol": 0.0}), {},
     "<dict>: simulate.atol: must be a positive finite number, got 0.0"),
    ("an unknown override before the [simulate] table is read",
     edited(simulate={"t_end": 1.0, "bogus": 1}), {"rtoll": 1e-6},
     "<dict>: simulate.rtoll: unknown key (did you mean rtol? expected one of t_end, samples, "
     "method, rtol, atol, formulation, h, max_steps) (given as an override)"),
    ("a bad override named as one",
     edited(simulate={"t_end": 1.0, "samples": 0}), {"samples": 11, "atol": -1},
     "<dict>: simulate.atol: must be a positive finite number, got -1 (given as an override)"),
    ("h with an adaptive method",
     edited(simulate={"t_end": 1.0, "h": 0.1}), {},
     "<dict>: simulate.h: is the step of a fixed-step method ("),
    ("an unknown table before a missing one",
     {"bodyy": {"I1": 1.0}, "initial": TOP["initial"]}, {},
     "<dict>: bodyy: unknown table (did you mean body? expected one of body, gravity, damping, "
     "initial, simulate)"),
    ("a table that is not one",
     edited(damping=0.1), {}, "<dict>: damping: must be a table [damping], got 0.1"),
]


@pytest.mark.parametrize("name, data, overrides, message", FIRST_PROBLEM,
                         ids=[p[0] for p in FIRST_PROBLEM])
def test_the_first_problem_in_document_order_is_reported(name, data, overrides, message):
    got = error(data, **overrides)
    assert got.startswith(message), got
    assert "\n" not in got


def test_the_key_sets_follow_the_effects_registry():
    """A table registered after a scene was validated is known to the next validation, and
    unknown again once removed (the key sets are cached per registry version)."""
    load_scene(TOP)
    table = effects.Table("spring", "a toy table", keys=(effects.Key("k", "N m", "stiffness"),))
    effect = effects.Effect("spring", "spring", "a toy effect",
                            params=(effects.Param("k_spring"),), values=lambda v: {"k_spring": v["k"]},
                            torque=lambda omega, R, sym: None)
    effects.register(effect, table)
    try:
        got = load_scene(edited(spring={"k": 2}))
        assert dict(got.spring) == {"k": 2.0} and got.spring.effect == "spring"
        assert got.effects == ("gravity", "spring")
        assert error(edited(spring={"k": 2, "kk": 1})).startswith(
            "<dict>: spring.kk: unknown key (did you mean k? expected one of k)")
    finally:
        effects.unregister("spring")
    assert error(edited(spring={"k": 2})).startswith("<dict>: spring: unknown table (")
    assert load_scene(TOP).effects == ("gravity",)
