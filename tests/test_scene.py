"""Scene files: the validation rules of the contract, the omega <-> rates conversion, and the
physics each example scene is named for."""
import copy
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from derive.methods import registry as solvers
from derive.symbolic.formulations import POLE_CLEARANCE
from derive.errors import SceneError
from derive.sim.scene import (FIXED_STEP_METHODS, FORMULATIONS, METHODS, SIMULATE_DEFAULTS, Scene, body_omega, load_scene,)

SCENES = Path(__file__).resolve().parent.parent / "scenes"
EXAMPLES = sorted(p.stem for p in SCENES.glob("*.toml"))

# Every table and a rate-based initial state: each rule test changes one thing in a copy.
BASE = {
    "title": "test top",
    "body": {"I1": 1.0, "I2": 1.0, "I3": 0.5},
    "gravity": {"M": 1.0, "g": 9.81, "l": 0.1},
    "damping": {"c": 0.0},
    "initial": {"alpha": 0.0, "beta": 0.5, "gamma": 0.0,
                "alpha_dot": 0.3, "beta_dot": 0.0, "gamma_dot": 20.0},
    "simulate": {"t_end": 10.0, "samples": 1001, "method": "auto", "rtol": 1e-10,
                 "atol": 1e-12, "formulation": "auto"},
}


def changed(*edits):
    """A copy of BASE with edits ("table.key", value) applied; value DELETE removes the key."""
    data = copy.deepcopy(BASE)
    for dotted, value in edits:
        *tables, key = dotted.split(".")
        target = data
        for t in tables:
            target = target[t]
        if value is DELETE:
            del target[key]
        else:
            target[key] = value
    return data


DELETE = object()


def error(scene, **overrides) -> str:
    """The SceneError message, checked to be a single line."""
    with pytest.raises(SceneError) as info:
        load_scene(scene, **overrides)
    message = str(info.value)
    assert "\n" not in message and "\r" not in message
    return message


def assert_names(message: str, key: str, source: str = "<dict>"):
    assert message.startswith(f"{source}: {key}: "), message


# ---------------------------------------------------------------------------------------------
# Loading and defaults


def test_base_scene_loads_with_every_field():
    scene = load_scene(BASE)
    assert scene.title == "test top"
    assert scene.named_effects == ("gravity", "damping")
    assert scene.effects == ("gravity",)  # BASE's c = 0: the damping term vanishes
    assert scene.symmetric
    assert scene.source == "<dict>"
    assert scene.simulate.h is None


def test_defaults_fill_optional_keys():
    scene = load_scene(changed(("title", DELETE), ("body.I2", DELETE), ("gravity", DELETE),
                               ("damping", DELETE), ("simulate", {"t_end": 3})))
    assert scene.title is None
    assert scene.body.I2 == scene.body.I1 == 1.0
    assert scene.effects == ()
    sim = scene.simulate
    assert (sim.samples, sim.method, sim.rtol, sim.atol, sim.formulation, sim.h) == (
        1001, "auto", 1e-10, 1e-12, "auto", None)
    assert sim.t_end == 3.0 and isinstance(sim.t_end, float)  # ints are accepted as floats


def test_t_out_spans_zero_to_t_end_inclusive():
    t = load_scene(changed(("simulate.t_end", 2.0), ("simulate.samples", 5))).t_out
    np.testing.assert_array_equal(t, [0.0, 0.5, 1.0, 1.5, 2.0])


def test_damping_with_zero_coefficient_is_named_but_does_not_act():
    """A zero term costs nothing (tests/test_same_body.py runs it)."""
    scene = load_scene(changed(("damping.c", 0)))
    assert "damping" in scene.named_effects and "damping" not in scene.effects
    assert scene.damping.c == 0.0  # the table stays readable
    assert "damping" in load_scene(changed(("damping.c", 1e-9))).effects


def test_negative_l_is_a_centre_of_mass_below_the_pivot():
    assert load_scene(changed(("gravity.l", -0.2))).gravity.l == -0.2


def test_every_method_and_formulation_has_a_one_line_description():
    for table in (METHODS, FORMULATIONS):
        assert "auto" in table
        for name, text in table.items():
            assert text and "\n" not in text, name
    assert set(FIXED_STEP_METHODS) <= set(METHODS)
    assert set(SIMULATE_DEFAULTS) == set(BASE["simulate"]) - {"t_end"} | {"h", "max_steps"}


def test_h_is_accepted_with_a_fixed_step_method():
    scene = load_scene(changed(("simulate.method", "gauss6"), ("simulate.h", 1e-3)))
    assert scene.simulate.h == 1e-3


# ---------------------------------------------------------------------------------------------
# One test per rule: the message is one line and names the key


RULES = [
    # (name, edits, key the message must name, fragment of the message)
    ("unknown table", [("wind", {"v": 1})], "wind",
     "unknown table (expected one of body, gravity, damping, initial, simulate)"),
    ("table typo", [("bdy", {})], "bdy", "did you mean body?"),
    ("unknown top-level key", [("t_end", 1.0)], "t_end", "belongs in [simulate]"),
    ("table given as a value", [("body", 3)], "body", "must be a table"),
    ("title not a string", [("title", 3)], "title", "must be a string"),
    ("unknown key", [("body.I4", 1.0)], "body.I4", "unknown key (expected one of I1, I2, I3)"),
    ("key typo", [("initial.alpha_do", 1.0)], "initial.alpha_do", "did you mean alpha_dot?"),
    ("key case typo", [("gravity.m", 1.0)], "gravity.m", "did you mean M?"),
    ("key in the wrong table", [("body.M", 1.0)], "body.M", "belongs in [gravity]"),
    ("missing body", [("body", DELETE)], "body", "missing required table"),
    ("missing initial", [("initial", DELETE)], "initial", "missing required table"),
    ("missing simulate", [("simulate", DELETE)], "simulate", "missing required table"),
    ("missing I1", [("body.I1", DELETE)], "body.I1", "missing required key"),
    ("missing I3", [("body.I3", DELETE)], "body.I3", "missing required key"),
    ("missing M", [("gravity.M", DELETE)], "gravity.M", "missing required key"),
    ("missing g", [("gravity.g", DELETE)], "gravity.g", "missing required key"),
    ("missing l", [("gravity.l", DELETE)], "gravity.l", "missing required key"),
    ("missing c", [("damping.c", DELETE)], "damping.c", "missing required key"),
    ("missing beta", [("initial.beta", DELETE)], "initial.beta", "missing required key"),
    ("missing t_end", [("simulate.t_end", DELETE)], "simulate.t_end", "missing required key"),
    ("negative moment", [("body.I3", -0.5)], "body.I3",
     "must be a positive finite number, got -0.5"),
    ("zero moment", [("body.I2", 0)], "body.I2", "must be a positive finite number, got 0"),
    ("bool is not a number", [("body.I1", True)], "body.I1", "got true (a boolean)"),
    ("string is not a number", [("gravity.g", "9.81")], "gravity.g", "got '9.81' (a string)"),
    ("nan", [("gravity.l", math.nan)], "gravity.l", "got nan"),
    ("inf", [("initial.gamma_dot", math.inf)], "initial.gamma_dot", "got inf"),
    ("integer too big for a float", [("body.I1", 10**400)], "body.I1", "401 digits"),
    ("triangle I1 + I2 >= I3", [("body.I3", 2.5)], "body",
     "moments violate the triangle inequality I1 + I2 >= I3 (I1 = 1, I2 = 1, I3 = 2.5)"),
    ("triangle I2 + I3 >= I1", [("body.I1", 1.6)], "body", "I2 + I3 >= I1"),
    ("triangle I1 + I3 >= I2", [("body.I2", 1.6)], "body", "I1 + I3 >= I2"),
    ("mass not positive", [("gravity.M", 0.0)], "gravity.M", "positive"),
    ("negative g", [("gravity.g", -9.81)], "gravity.g", "non-negative"),
    ("negative damping", [("damping.c", -1e-3)], "damping.c", "non-negative"),
    ("both rates and omega", [("initial.omega", [0.0, 0.0, 1.0])], "initial",
     "give either the Euler-angle rates (alpha_dot, beta_dot, gamma_dot) or omega, not both"),
    ("neither rates nor omega", [("initial.alpha_dot", DELETE), ("initial.beta_dot", DELETE),
                                 ("initial.gamma_dot", DELETE)], "initial", "got neither"),
    ("omega too short", [("initial", {"alpha": 0, "beta": 1, "gamma": 0, "omega": [1, 2]})],
     "initial.omega", "must be a list of 3 finite numbers"),
    ("omega with nan", [("initial", {"alpha": 0, "beta": 1, "gamma": 0,
                                     "omega": [1, math.nan, 2]})], "initial.omega", "got [1, nan, 2]"),
    ("omega not a list", [("initial", {"alpha": 0, "beta": 1, "gamma": 0, "omega": 3.0})],
     "initial.omega", "must be a list"),
    ("t_end zero", [("simulate.t_end", 0.0)], "simulate.t_end", "positive"),
    ("samples float", [("simulate.samples", 1001.0)], "simulate.samples", "must be an integer"),
    ("samples too few", [("simulate.samples", 1)], "simulate.samples", "from 2"),
    ("samples bool", [("simulate.samples", True)], "simulate.samples", "must be an integer"),
    ("unknown method", [("simulate.method", "dopri853")], "simulate.method",
     "did you mean dop853?"),
    ("method not a string", [("simulate.method", 4)], "simulate.method", "must be a string"),
    ("rtol not below 1", [("simulate.rtol", 1.0)], "simulate.rtol", "in (0, 1)"),
    ("rtol negative", [("simulate.rtol", -1e-8)], "simulate.rtol", "in (0, 1)"),
    ("rtol absurdly small", [("simulate.rtol", 1e-16)], "simulate.rtol",
     "at least 100 machine epsilons"),
    ("atol zero", [("simulate.atol", 0.0)], "simulate.atol", "positive"),
    ("unknown formulation", [("simulate.formulation", "lagrangian")], "simulate.formulation",
     "expected one of auto, reduced-u, euler-angles, reduced, quaternion, euler-poisson"),
    ("h not positive", [("simulate.method", "rk4"), ("simulate.h", -0.1)], "simulate.h",
     "positive"),
    ("h with an adaptive method", [("simulate.method", "dop853"), ("simulate.h", 0.1)],
     "simulate.h", "fixed-step method"),
    ("reduced with an asymmetric body", [("body.I2", 1.2), ("simulate.formulation", "reduced")],
     "simulate.formulation", "'reduced' needs a symmetric body"),
    ("reduced with damping", [("damping.c", 0.1), ("simulate.formulation", "reduced")],
     "simulate.formulation", "effect 'damping' does not conserve them"),
    ("euler-angles at the pole", [("initial.beta", 0.0),
                                  ("simulate.formulation", "euler-angles")],
     "simulate.formulation", "singular at sin(beta) = 0"),
    ("reduced at the lower pole", [("initial.beta", math.pi), ("damping", DELETE),
                                   ("simulate.formulation", "reduced")],
     "simulate.formulation", "singular at sin(beta) = 0"),
]


@pytest.mark.parametrize("edits, key, fragment",
                         [r[1:] for r in RULES], ids=[r[0] for r in RULES])
def test_rule_names_the_key(edits, key, fragment):
    message = error(changed(*edits))
    assert_names(message, key)
    assert fragment in message


def test_triangle_equality_is_allowed_within_rounding():
    # A flat plate: I3 = I1 + I2 exactly, and computed with rounding error either way.
    assert load_scene(changed(("body.I1", 0.1), ("body.I2", 0.2), ("body.I3", 0.3)))
    assert load_scene(changed(("body.I1", 0.1), ("body.I2", 0.2), ("body.I3", 0.1 + 0.2)))
    message = error(changed(("body.I1", 0.1), ("body.I2", 0.2), ("body.I3", 0.3 * (1 + 1e-9))))
    assert_names(message, "body")


def test_partial_rates_default_to_zero():
    scene = load_scene(changed(("initial.alpha_dot", DELETE), ("initial.beta_dot", DELETE)))
    assert (scene.initial.alpha_dot, scene.initial.beta_dot, scene.initial.gamma_dot) == (
        0.0, 0.0, 20.0)
    assert scene.initial.omega == (0.0, 0.0, 20.0)


def test_pole_start_is_accepted_by_the_quaternion_and_auto_formulations():
    for formulation in ("auto", "quaternion"):
        scene = load_scene(changed(("initial.beta", 0.0), ("simulate.formulation", formulation)))
        assert scene.initial.at_pole


# ---------------------------------------------------------------------------------------------
# Files


def test_file_errors_name_the_file(tmp_path):
    missing = tmp_path / "missing.toml"
    assert_names(error(missing), "file", str(missing))
    assert "not found" in error(missing)
    assert_names(error(tmp_path), "file", str(tmp_path))
    binary = tmp_path / "binary.toml"
    binary.write_bytes(b"\xff\xfe[body]")
    assert_names(error(binary), "file", str(binary))


def test_toml_syntax_error_gives_line_and_column(tmp_path):
    path = tmp_path / "spin.toml"
    path.write_text("[body]\nI1 = 1.0\nI3 = \n")
    message = error(path)
    assert message.startswith(f"{path}: line 3, column 6: invalid TOML: ")


def test_duplicate_key_is_a_toml_error(tmp_path):
    path = tmp_path / "spin.toml"
    path.write_text("[body]\nI1 = 1.0\nI1 = 2.0\n")
    assert error(path).startswith(f"{path}: line 3")


def test_file_errors_use_the_path_as_given(tmp_path):
    path = tmp_path / "spin.toml"
    path.write_text("[body]\nI1 = 1.0\nI3 = -0.5\n")
    assert error(str(path)) == f"{path}: body.I3: must be a positive finite number, got -0.5"


def test_nan_and_inf_written_in_toml_are_rejected(tmp_path):
    for literal, key in (("nan", "body.I1"), ("-inf", "body.I1")):
        path = tmp_path / "scene.toml"
        path.write_text(f"[body]\nI1 = {literal}\nI3 = 1.0\n")
        assert_names(error(path), key, str(path))


@pytest.mark.parametrize("name", EXAMPLES)
def test_dict_input_equals_file_input(name):
    path = SCENES / f"{name}.toml"
    from_file = load_scene(path)
    from_dict = load_scene(tomllib.loads(path.read_text()))
    assert from_file == from_dict
    assert (from_file.source, from_dict.source) == (str(path), "<dict>")


@pytest.mark.parametrize("value", [42, None, [1, 2], b"scene.toml", 1.5])
def test_load_scene_rejects_other_types(value):
    with pytest.raises(SceneError, match="scene: must be a path"):
        load_scene(value)


# ---------------------------------------------------------------------------------------------
# Overrides


def test_overrides_take_precedence_over_the_file(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text(tomllib_dump(changed(("simulate.rtol", 1e-8), ("simulate.method", "dop853"))))
    scene = load_scene(path, rtol=1e-6, method="scipy-radau", samples=11)
    assert (scene.simulate.rtol, scene.simulate.method, scene.simulate.samples) == (
        1e-6, "scipy-radau", 11)


def test_none_override_means_not_given():
    scene = load_scene(changed(("simulate.rtol", 1e-8)), rtol=None, atol=None, method=None)
    assert scene.simulate.rtol == 1e-8


def test_override_may_supply_a_missing_required_key():
    scene = load_scene(changed(("simulate", DELETE)), t_end=4.0)
    assert scene.simulate.t_end == 4.0 and scene.simulate.samples == 1001


def test_bad_override_is_named_as_an_override():
    message = error(BASE, rtol=2.0)
    assert_names(message, "simulate.rtol")
    assert message.endswith("(given as an override)")
    assert_names(error(BASE, rtl=1e-8), "simulate.rtl")
    assert_names(error(BASE, method="rk5"), "simulate.method")


def test_override_cannot_break_cross_checks():
    assert_names(error(changed(("body.I2", 1.5)), formulation="reduced"), "simulate.formulation")
    assert_names(error(BASE, h=0.1), "simulate.h")  # method stays "auto": adaptive


def test_overrides_apply_to_a_loaded_scene():
    scene = load_scene(SCENES / "cuspidal_top.toml")
    again = load_scene(scene, method="rk4", h=1e-4)
    assert again.simulate.h == 1e-4 and again.source == scene.source
    assert again.initial == scene.initial
    assert load_scene(scene) == scene


def tomllib_dump(data: dict) -> str:
    """Just enough TOML writing for the flat tables of a scene."""
    def value(v):
        if isinstance(v, str):
            return f'"{v}"'
        if isinstance(v, list):
            return "[" + ", ".join(value(x) for x in v) + "]"
        return repr(v)

    lines = [f"{k} = {value(v)}" for k, v in data.items() if not isinstance(v, dict)]
    for table, body in data.items():
        if isinstance(body, dict):
            lines += [f"[{table}]"] + [f"{k} = {value(v)}" for k, v in body.items()]
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------------------------------------
# omega <-> Euler-angle rates


def rotation(alpha, beta, gamma):
    """R = Rz(alpha) Ry(beta) Rz(gamma): body components -> inertial components."""
    def rz(t):
        c, s = math.cos(t), math.sin(t)
        return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1.0]])

    def ry(t):
        c, s = math.cos(t), math.sin(t)
        return np.array([[c, 0, s], [0, 1.0, 0], [-s, 0, c]])

    return rz(alpha) @ ry(beta) @ rz(gamma)


def test_body_omega_at_hand_computed_points():
    # beta = pi/2, gamma = 0: alpha turns about -e1, beta about e2, gamma about e3.
    np.testing.assert_allclose(body_omega(math.pi / 2, 0.0, 1.0, 2.0, 3.0), (-1, 2, 3), atol=1e-15)
    # beta = 0: alpha and gamma both turn about e3; beta about e2' = (sin g, cos g, 0).
    np.testing.assert_allclose(body_omega(0.0, math.pi / 2, 1.0, 2.0, 3.0), (2, 0, 4), atol=1e-15)


angles = st.floats(-4.0, 4.0, allow_nan=False)
rates = st.floats(-50.0, 50.0, allow_nan=False)


@settings(max_examples=60, deadline=None)
@given(angles, angles, angles, rates, rates, rates)
def test_body_omega_is_the_angular_velocity_of_the_rotation(a, b, g, ad, bd, gd):
    # skew(omega_body) = R^T dR/dt, with dR/dt by central differences along the rates.
    h = 1e-6
    dR = (rotation(a + ad * h, b + bd * h, g + gd * h)
          - rotation(a - ad * h, b - bd * h, g - gd * h)) / (2 * h)
    W = rotation(a, b, g).T @ dR
    expected = (W[2, 1], W[0, 2], W[1, 0])
    scale = 1 + abs(ad) + abs(bd) + abs(gd)
    np.testing.assert_allclose(body_omega(b, g, ad, bd, gd), expected, atol=1e-7 * scale)


def test_scene_with_rates_stores_both_representations():
    ini = load_scene(BASE).initial
    assert ini.has_rates
    assert ini.omega == tuple(body_omega(0.5, 0.0, 0.3, 0.0, 20.0))


def test_scene_with_omega_keeps_rates_unknown():
    scene = load_scene(changed(("initial", {"alpha": 0.1, "beta": 0.0, "gamma": 0.2,
                                            "omega": [1, -2, 3.5]})))
    ini = scene.initial
    assert not ini.has_rates
    assert (ini.alpha_dot, ini.beta_dot, ini.gamma_dot) == (None, None, None)
    assert ini.omega == (1.0, -2.0, 3.5) and all(type(w) is float for w in ini.omega)


def test_p_alpha_matches_the_notes_for_a_symmetric_body():
    # p_alpha = L . z (inertial), computed from omega, equals the notes' formula in the rates.
    ini, body = (s := load_scene(BASE)).initial, s.body
    p_alpha, p_gamma = momenta(s)
    sb, cb = math.sin(ini.beta), math.cos(ini.beta)
    assert p_gamma == pytest.approx(body.I3 * (ini.alpha_dot * cb + ini.gamma_dot), rel=1e-14)
    assert p_alpha == pytest.approx(body.I1 * ini.alpha_dot * sb**2 + p_gamma * cb, rel=1e-14)


# ---------------------------------------------------------------------------------------------
# The example scenes and the motions they are named for


def momenta(scene):
    """(p_alpha, p_gamma) = (L . z, L . e3): conjugate to the cyclic angles, from omega."""
    ini = scene.initial
    L_body = np.array(scene.body.moments) * np.array(ini.omega)
    return (rotation(ini.alpha, ini.beta, ini.gamma) @ L_body)[2], L_body[2]


def turning_points(scene):
    """u = cos(beta) at the two turning points of a heavy symmetric top's nutation.

    With a = p_alpha/I1, b = p_gamma/I1, A = 2 E'/I1, B = 2 M g l/I1 (E' as in the notes),
    u'^2 = f(u) = (1 - u^2)(A - B u) - (a - b u)^2. The scenes start with beta_dot = 0, so
    u0 = cos(beta0) is a root; dividing it out leaves a quadratic whose root in [-1, 1] is
    the other turning point (no cancellation between two close roots of the cubic).
    """
    ini, I1, grav = scene.initial, scene.body.I1, scene.gravity
    assert ini.beta_dot == 0.0 and scene.symmetric
    p_alpha, p_gamma = momenta(scene)
    a, b, B = p_alpha / I1, p_gamma / I1, 2 * grav.M * grav.g * grav.l / I1
    u0 = math.cos(ini.beta)
    A = (a - b * u0) ** 2 / (1 - u0**2) + B * u0  # 2E'/I1 at a turning point
    cubic = [B, -(A + b * b), 2 * a * b - B, A - a * a]
    quadratic, remainder = np.polydiv(cubic, [1.0, -u0])
    assert abs(remainder[-1]) < 1e-9 * max(abs(c) for c in cubic)
    others = [r.real for r in np.roots(quadratic) if abs(r.imag) < 1e-12 and -1 <= r.real <= 1]
    assert len(others) == 1
    return sorted((u0, others[0]))


def example(name):
    return load_scene(SCENES / f"{name}.toml")


def with_spin(scene, gamma_dot):
    return load_scene(changed_scene(scene, initial={"gamma_dot": gamma_dot}))


def changed_scene(scene, **tables):
    data = scene.to_dict()
    for table, values in tables.items():
        data[table].update(values)
    return data


def sleeping_parameter(scene):
    """a = p_gamma^2 / (4 M g l I1): the notes' upright top is stable for a >= 1."""
    grav = scene.gravity
    return momenta(scene)[1] ** 2 / (4 * grav.M * grav.g * grav.l * scene.body.I1)


def test_required_examples_exist():
    assert {"sleeping_top", "looping_top", "cuspidal_top", "free_symmetric", "tennis_racket",
            "damped_top"} <= set(EXAMPLES)


@pytest.mark.parametrize("name", EXAMPLES)
def test_example_loads_with_title_and_moderate_sampling(name):
    scene = example(name)
    assert scene.title
    assert 1001 <= scene.simulate.samples <= 2001
    assert 0 < scene.simulate.t_end <= 20
    assert not scene.initial.at_pole  # every formulation can start from it
    assert load_scene(scene.to_dict()) == scene


def test_sleeping_top_spins_above_threshold_and_stays_upright():
    scene = example("sleeping_top")
    beta0 = scene.initial.beta
    assert 0 < beta0 <= 1e-2  # a tiny tilt, not exactly 0
    a = sleeping_parameter(scene)
    assert a > 1.5  # p_gamma >= sqrt(4 M g l I1), with margin
    beta_max = math.acos(turning_points(scene)[0])
    assert beta_max < 2 * beta0
    # Small-angle theory: beta_max = beta0 / sqrt(1 - 1/a).
    assert beta_max == pytest.approx(beta0 / math.sqrt(1 - 1 / a), rel=1e-3)


def test_sleeping_top_below_threshold_falls():
    # The same tilt with half the spin: the turning-point test must see the top fall.
    slow = with_spin(example("sleeping_top"), 100.0)
    assert sleeping_parameter(slow) < 1
    assert math.acos(turning_points(slow)[0]) > 0.5


def test_cuspidal_top_starts_with_its_axis_at_rest_at_the_upper_turning_point():
    scene = example("cuspidal_top")
    ini = scene.initial
    assert ini.alpha_dot == 0.0 and ini.beta_dot == 0.0
    p_alpha, p_gamma = momenta(scene)
    assert p_alpha == pytest.approx(p_gamma * math.cos(ini.beta), rel=1e-12)
    u1, u2 = turning_points(scene)
    assert u2 == math.cos(ini.beta) and u1 < u2 - 0.1  # it falls first, visibly
    # alpha_dot ~ p_alpha - p_gamma u >= 0 on [u1, u2], zero only at the cusp u2.
    assert p_alpha - p_gamma * u1 > 0


def test_looping_top_reverses_precession_between_turning_points():
    scene = example("looping_top")
    p_alpha, p_gamma = momenta(scene)
    u1, u2 = turning_points(scene)
    assert (p_alpha - p_gamma * u1) * (p_alpha - p_gamma * u2) < 0


def test_wavy_top_precesses_one_way():
    scene = example("wavy_top")
    p_alpha, p_gamma = momenta(scene)
    u1, u2 = turning_points(scene)
    assert (p_alpha - p_gamma * u1) * (p_alpha - p_gamma * u2) > 0  # linear in u: no zero


def test_free_symmetric_body_has_angular_momentum_along_z():
    scene = example("free_symmetric")
    assert scene.effects == () and scene.symmetric
    ini, body = scene.initial, scene.body
    L = rotation(ini.alpha, ini.beta, ini.gamma) @ (np.array(body.moments) * ini.omega)
    assert np.hypot(L[0], L[1]) < 1e-12 * np.linalg.norm(L)  # so beta stays constant
    assert ini.alpha_dot == pytest.approx(np.linalg.norm(L) / body.I1, rel=1e-12)
    omega_body = ini.omega[2] * (body.I3 - body.I1) / body.I1  # the notes' Omega
    assert ini.gamma_dot == pytest.approx(-omega_body, rel=1e-12)


def test_tennis_racket_spins_about_the_unstable_intermediate_axis():
    scene = example("tennis_racket")
    I1, I2, I3 = scene.body.moments
    assert scene.effects == () and I1 < I2 < I3
    w1, w2, w3 = scene.initial.omega
    assert 0 < max(abs(w1), abs(w3)) < 1e-3 * abs(w2)  # a small, non-zero perturbation
    growth_rate = abs(w2) * math.sqrt((I2 - I1) * (I3 - I2) / (I1 * I3))
    assert growth_rate * scene.simulate.t_end > 2 * math.log(abs(w2) / abs(w1))  # time to flip
    ini = scene.initial
    L = rotation(ini.alpha, ini.beta, ini.gamma) @ (np.array(scene.body.moments) * ini.omega)
    assert L[2] > 0.9999 * np.linalg.norm(L)  # L along z keeps beta off the poles


def test_damped_top_spin_decays_below_the_sleeping_threshold():
    scene = example("damped_top")
    assert scene.effects == ("gravity", "damping") and scene.damping.c > 0
    assert sleeping_parameter(scene) > 1
    # Symmetric body: I3 dw3/dt = -c w3 exactly, so a(t) = a(0) exp(-2 c t / I3).
    t_cross = scene.body.I3 / (2 * scene.damping.c) * math.log(sleeping_parameter(scene))
    assert 0.2 * scene.simulate.t_end < t_cross < 0.8 * scene.simulate.t_end


# ---------------------------------------------------------------------------------------------
# Random valid scenes load; random corruptions are reported under the right key

finite = st.floats(-10.0, 10.0, allow_nan=False)
positive = st.one_of(st.floats(0.01, 10.0), st.integers(1, 10))


@st.composite
def valid_scenes(draw):
    I1 = draw(positive)
    I2 = draw(st.one_of(st.none(), positive))
    other = I1 if I2 is None else I2
    lo, hi = abs(I1 - other), I1 + other
    I3 = lo + (hi - lo) * draw(st.floats(0.01, 0.99))  # strictly inside the triangle
    data = {"body": {"I1": I1, "I3": I3} | ({} if I2 is None else {"I2": I2})}
    if draw(st.booleans()):
        data["title"] = draw(st.text(max_size=20))
    if draw(st.booleans()):
        data["gravity"] = {"M": draw(positive), "g": draw(st.floats(0.0, 20.0)),
                           "l": draw(finite)}
    if draw(st.booleans()):
        data["damping"] = {"c": draw(st.one_of(st.just(0.0), st.floats(0.0, 1.0)))}
    initial = {k: draw(finite) for k in ("alpha", "beta", "gamma")}
    if draw(st.booleans()):
        keys = draw(st.lists(st.sampled_from(["alpha_dot", "beta_dot", "gamma_dot"]),
                             min_size=1, unique=True))
        initial |= {k: draw(finite) for k in keys}
    else:
        initial["omega"] = draw(st.lists(finite, min_size=3, max_size=3))
    data["initial"] = initial
    simulate = {"t_end": draw(st.one_of(st.floats(0.01, 100.0), st.integers(1, 100)))}
    if draw(st.booleans()):
        simulate["samples"] = draw(st.integers(2, 5000))
    if draw(st.booleans()):
        # A splitting needs a Hamiltonian to split: no damping table.
        simulate["method"] = draw(st.sampled_from([m for m in METHODS if "damping" not in data
                                                   or solvers.method_reason(m, "auto", ("damping",)) is None]))
        if simulate["method"] in FIXED_STEP_METHODS and draw(st.booleans()):
            simulate["h"] = draw(st.floats(1e-6, 1.0))
    if draw(st.booleans()):
        simulate["rtol"] = draw(st.floats(1e-13, 0.5))
    if draw(st.booleans()):
        simulate["atol"] = draw(st.floats(1e-16, 1.0))
    formulations = ["auto", "quaternion", "euler-poisson"]
    # The Euler-angle charts refuse to start within POLE_CLEARANCE of a pole when omega is given.
    if abs(math.sin(initial["beta"])) > (POLE_CLEARANCE if "omega" in initial else 1e-6):
        formulations.append("euler-angles")
        # A damping table, even with c = 0, names the effect: the reduced chart cannot take it.
        if (I2 is None or I2 == I1) and "damping" not in data:
            formulations.append("reduced")
    if solvers.method_reason(simulate.get("method", "auto"), "quaternion", ()):
        formulations = ["auto", "euler-poisson"]  # the method's own rule (a splitting)
    simulate["formulation"] = draw(st.sampled_from(formulations))
    data["simulate"] = simulate
    return data


QUICK = settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@QUICK
@given(valid_scenes())
def test_random_valid_scenes_load_and_round_trip(data):
    scene = load_scene(data)
    assert isinstance(scene, Scene)
    assert load_scene(scene.to_dict()) == scene
    assert len(scene.initial.omega) == 3


REQUIRED = {"body": ["I1", "I3"], "gravity": ["M", "g", "l"], "damping": ["c"],
            "initial": ["alpha", "beta", "gamma"], "simulate": ["t_end"]}


@QUICK
@given(valid_scenes(), st.data())
def test_deleting_a_required_key_names_it(data, draw):
    table = draw.draw(st.sampled_from([t for t in REQUIRED if t in data]))
    key = draw.draw(st.sampled_from(REQUIRED[table]))
    del data[table][key]
    assert_names(error(data), f"{table}.{key}")


@QUICK
@given(valid_scenes(), st.data(), st.sampled_from(["x", "_", "2", "s"]))
def test_renaming_a_key_names_the_new_key(data, draw, suffix):
    table = draw.draw(st.sampled_from([t for t in data if isinstance(data[t], dict)]))
    key = draw.draw(st.sampled_from(sorted(data[table])))
    data[table][key + suffix] = data[table].pop(key)
    message = error(data)
    assert_names(message, f"{table}.{key + suffix}")
    assert "unknown key" in message


@QUICK
@given(valid_scenes(), st.data(), st.sampled_from([math.nan, math.inf, -math.inf, True]))
def test_a_non_finite_or_boolean_number_names_its_key(data, draw, bad):
    numeric = [(t, k) for t in data if isinstance(data[t], dict)
               for k, v in data[t].items() if not isinstance(v, str)]
    table, key = draw.draw(st.sampled_from(numeric))
    if key == "omega":
        data[table][key][draw.draw(st.integers(0, 2))] = bad
    else:
        data[table][key] = bad
    assert_names(error(data), f"{table}.{key}")
