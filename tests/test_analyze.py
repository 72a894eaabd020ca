"""`derive analyze`: verdicts on every example scene, the lecture's sleeping-top condition, the
free body's permanent rotations, the JSON contract, and the verdicts against simulations (a
state called stable stays near its equilibrium, one called unstable leaves it)."""
from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

import derive
from derive.lecture import analysis
from derive.lecture import closed_forms
from derive.symbolic import integrable
from derive.cli import main

SCENES = Path(__file__).resolve().parent.parent / "scenes"

#: scene -> (case, [(kind, axis, stable), ...]) as `derive analyze` must report them.
EXPECTED = {
    "sleeping_top": ("lagrange", [("sleeping", 3, True), ("hanging", 3, True),
                                  ("steady-precession", 3, True)]),
    "cuspidal_top": ("lagrange", [("sleeping", 3, True), ("hanging", 3, True),
                                  ("steady-precession", 3, True)]),
    "looping_top": ("lagrange", [("sleeping", 3, True), ("hanging", 3, True),
                                 ("steady-precession", 3, True)]),
    "wavy_top": ("lagrange", [("sleeping", 3, True), ("hanging", 3, True),
                              ("steady-precession", 3, True)]),
    "damped_top": ("general", [("sleeping", 3, False), ("hanging", 3, True)]),
    "free_symmetric": ("euler", [("permanent-rotation", 1, None), ("permanent-rotation", 2, None),
                                 ("permanent-rotation", 3, True), ("steady-precession", 3, True)]),
    "tennis_racket": ("euler", [("permanent-rotation", 1, True), ("permanent-rotation", 2, False),
                                ("permanent-rotation", 3, True)]),
    "kovalevskaya_top": ("kovalevskaya", [("sleeping", 1, False), ("hanging", 1, True)]),
    "goryachev_chaplygin_top": ("goryachev-chaplygin", [("sleeping", 1, False), ("hanging", 1, True)]),
    "off_axis_top": ("general", [("sleeping", None, False), ("hanging", None, True)]),
}
KINDS = {"sleeping", "hanging", "steady-precession", "permanent-rotation"}
#: Lagrange tops that take sleeping_top's path through the analysis with other numbers: their
#: every-scene checks run in ``make test-slow``, sleeping_top's in ``make test``.
SAME_PATH_AS_SLEEPING_TOP = {"cuspidal_top", "looping_top", "wavy_top", "reference_top"}
EXAMPLES = [pytest.param(p, marks=pytest.mark.slow) if p.stem in SAME_PATH_AS_SLEEPING_TOP else p
            for p in sorted(SCENES.glob("*.toml"))]


def lecture_top(gamma_dot=200.0, beta=1e-3, alpha_dot=0.0, **sim):
    """The toy top of scenes/sleeping_top.toml with rates given."""
    return {"body": {"I1": 1.8e-4, "I3": 4.0e-5}, "gravity": {"M": 0.1, "g": 9.81, "l": 0.04},
            "initial": {"alpha": 0.0, "beta": beta, "gamma": 0.0, "alpha_dot": alpha_dot,
                        "beta_dot": 0.0, "gamma_dot": gamma_dot},
            "simulate": {"t_end": 2.0, "samples": 401, **sim}}


def body(I, omega, com=None, M=1.0, beta=1.0, gamma=0.0, t_end=2.0, **sim):
    d = {"body": dict(zip(("I1", "I2", "I3"), I)),
         "initial": {"alpha": 0.0, "beta": beta, "gamma": gamma, "omega": list(omega)},
         "simulate": {"t_end": t_end, "samples": 401, **sim}}
    if com is not None:
        d["gravity"] = {"M": M, "g": 9.81, "com": list(com)}
    return d


def verdicts(scene):
    a = analysis.analyze(scene).to_json()
    return a["case"], [(e["kind"], e["axis"], e["stable"]) for e in a["equilibria"]]


def find(scene, kind, axis):
    eqs = analysis.analyze(scene).equilibria
    (e,) = [e for e in eqs if e.kind == kind and e.axis == axis]
    return e


# ---------------------------------------------------------------------------------------------
# every example scene


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_example_scene_json(path, capsys):
    """Every scene: exit 0, the JSON contract; the known scenes give the expected verdicts."""
    assert main(["analyze", str(path), "--format", "json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["case"] in integrable.CASES
    assert out["integrals"] and all(isinstance(i["name"], str) and isinstance(i["expression"], str)
                                    for i in out["integrals"])
    for e in out["equilibria"]:
        assert e["kind"] in KINDS
        assert e["axis"] in (1, 2, 3, None)
        assert isinstance(e["condition"], str) and e["condition"]
        assert e["stable"] in (True, False, None)
    if path.stem in EXPECTED:
        case, eqs = EXPECTED[path.stem]
        assert out["case"] == case
        assert [(e["kind"], e["axis"], e["stable"]) for e in out["equilibria"]] == eqs
        assert all(i["proved"] for i in out["integrals"])


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_example_scene_markdown(path):
    """Every scene renders: sections in order, one verdict per equilibrium, the case named."""
    a = analysis.analyze(str(path))
    md = a.to_markdown()
    heads = [line for line in md.splitlines() if line.startswith("## ")]
    assert heads == ["## Body, effects and integrable case", "## Kinetic and potential energy, Lagrangian",
                     "## Equations of motion", "## Cyclic coordinates, momenta, Routh reduction",
                     "## Integrals of the motion", "## Relative equilibria and their stability"]
    assert f"**Case: {a.classification.case}**" in md
    assert md.count("At the scene's numbers: **") == len(a.equilibria)
    assert md.count("$$") % 2 == 0


def test_new_scenes_are_covered():
    """The added example scenes are in the table (so their verdicts are checked)."""
    for name in ("kovalevskaya_top", "goryachev_chaplygin_top", "off_axis_top"):
        assert (SCENES / f"{name}.toml").exists()


def test_markdown(capsys):
    assert main(["analyze", str(SCENES / "sleeping_top.toml")]) == 0
    md = capsys.readouterr().out
    for needle in ("## Equations of motion", r"\mathbb{M}", "V_\\text{eff}", "Case: lagrange",
                   r"p_\gamma \ge \sqrt{4 I_{1} M g l}", "### sleeping, axis 3", "**stable**"):
        assert needle in md


def test_bad_input_exit_2(tmp_path, capsys):
    assert main(["analyze", str(tmp_path / "missing.toml")]) == 2
    err = capsys.readouterr().err
    assert err.startswith("error: ") and "missing.toml" in err and err.count("\n") == 1
    bad = tmp_path / "bad.toml"
    bad.write_text('[body]\nI1 = -1.0\nI3 = 1.0\n[initial]\nalpha = 0\nbeta = 0\ngamma = 0\n'
                   'omega = [0, 0, 1]\n[simulate]\nt_end = 1\n')
    assert main(["analyze", str(bad), "--format", "json"]) == 2
    err = capsys.readouterr().err
    assert "body.I1" in err and err.count("\n") == 1


# ---------------------------------------------------------------------------------------------
# the lecture's top


def test_sleeping_condition_is_the_lectures():
    from derive.symbolic.lagrangian import I1, Mass, g, l

    R = closed_forms._routh()
    assert sp.simplify(R["threshold"] ** 2 - 4 * Mass * g * l * I1) == 0
    e = find(lecture_top(), "sleeping", 3)
    assert e.condition == "p_gamma >= sqrt(4*I1*M*g*l)"
    assert e.values["p_gamma"] == pytest.approx(8.0e-3)
    assert e.values["threshold"] == pytest.approx(math.sqrt(4 * 0.1 * 9.81 * 0.04 * 1.8e-4))
    assert e.stable is True
    assert find(lecture_top(gamma_dot=100.0), "sleeping", 3).stable is False
    # exactly at the threshold (p_gamma = I3 w3): marginal
    w3 = math.sqrt(4 * 0.1 * 9.81 * 0.04 * 1.8e-4) / 4.0e-5
    assert find(lecture_top(gamma_dot=w3), "sleeping", 3).stable is None


def test_hanging_series_by_symmetry():
    """V_eff(pi - b; -p_alpha, -l) = V_eff(b; p_alpha, l), which the series about pi relies on."""
    from derive.symbolic.lagrangian import l, p_alpha
    from derive.symbolic.rotations import beta

    V = closed_forms._routh()["Veff"]
    flipped = V.subs({beta: sp.pi - beta, p_alpha: -p_alpha, l: -l}, simultaneous=True)
    assert sp.simplify(flipped - V) == 0


def test_hanging_lagrange_top_below_the_pivot():
    """l < 0: the centre of mass hangs at beta = 0; the sleeping (upright) state is at pi."""
    d = lecture_top(gamma_dot=50.0)
    d["gravity"]["l"] = -0.04
    case, eqs = verdicts(d)
    assert case == "lagrange"
    assert ("hanging", 3, True) in eqs
    assert ("sleeping", 3, False) in eqs  # p_gamma = 2e-3 < 5.3e-3


def test_steady_precession_roots():
    """The two alpha_dot roots solve I1 cos b0 a^2 - p_gamma a + M g l = 0 and exist iff
    p_gamma^2 >= 4 M g l I1 cos b0."""
    e = find(lecture_top(beta=0.5, gamma_dot=150.0), "steady-precession", 3)
    pg, b0 = 150.0 * 4.0e-5, 0.5
    roots = e.values["alpha_dot_roots"]
    assert len(roots) == 2
    for a in roots:
        assert 1.8e-4 * math.cos(b0) * a * a - pg * a + 0.1 * 9.81 * 0.04 == pytest.approx(0, abs=1e-12)
    slow = find(lecture_top(beta=0.5, gamma_dot=100.0), "steady-precession", 3)
    assert slow.values["alpha_dot_roots"] == [] and slow.stable is None  # 4e-3^2 < 4 M g l I1 cos b0


# ---------------------------------------------------------------------------------------------
# free asymmetric body


def test_free_asymmetric_body_permanent_rotations():
    I = (1.0e-3, 2.0e-3, 2.5e-3)
    d = body(I, (0.0, 10.0, 0.0))
    case, eqs = verdicts(d)
    assert case == "euler"
    assert eqs == [("permanent-rotation", 1, True), ("permanent-rotation", 2, False),
                   ("permanent-rotation", 3, True)]
    e2 = find(d, "permanent-rotation", 2)
    rate = 10.0 * math.sqrt((I[1] - I[0]) * (I[2] - I[1]) / (I[0] * I[2]))
    assert max(z.real for z in e2.eigenvalues) == pytest.approx(rate, rel=1e-12)
    assert e2.values["lambda_squared"] == pytest.approx(rate**2, rel=1e-12)
    for k in (1, 3):  # oscillation, no growth
        assert max(abs(z.real) for z in find(d, "permanent-rotation", k).eigenvalues) < 1e-9


# ---------------------------------------------------------------------------------------------
# verdicts against simulations


def _tilt_range(d):
    res = derive.simulate(d)
    return float(np.min(res.beta)), float(np.max(res.beta))


def test_sleeping_top_simulated():
    """Called stable: the 1e-3 rad tilt stays below 2e-3; called unstable: it exceeds 0.1."""
    assert find(lecture_top(), "sleeping", 3).stable is True
    assert _tilt_range(lecture_top())[1] < 2e-3
    assert find(lecture_top(gamma_dot=100.0), "sleeping", 3).stable is False
    assert _tilt_range(lecture_top(gamma_dot=100.0))[1] > 0.1


def test_steady_precession_simulated():
    """Started on a root the tilt stays put; nudged 1 % off it stays near (stable)."""
    b0, w3 = 0.5, 150.0
    e = find(lecture_top(beta=b0, gamma_dot=w3), "steady-precession", 3)
    assert e.stable is True
    for a in e.values["alpha_dot_roots"]:
        # same p_gamma = I3 (alpha_dot cos b0 + gamma_dot)
        lo, hi = _tilt_range(lecture_top(beta=b0, alpha_dot=a, gamma_dot=w3 - a * math.cos(b0),
                                         rtol=1e-11))
        assert hi - lo < 1e-6
        lo, hi = _tilt_range(lecture_top(beta=b0, alpha_dot=1.01 * a,
                                         gamma_dot=w3 - 1.01 * a * math.cos(b0)))
        assert hi - lo < 0.05


def _spin_component_range(d, k):
    res = derive.simulate(d)
    return float(np.min(res.omega[:, k])), float(np.max(res.omega[:, k]))


def test_free_rotations_simulated():
    I = (1.0e-3, 2.0e-3, 2.5e-3)
    eps = 1e-3
    lo, hi = _spin_component_range(body(I, (10.0, eps, eps), t_end=5.0), 0)
    assert lo > 9.9  # axis 1 (smallest moment): stays
    lo, hi = _spin_component_range(body(I, (eps, eps, 10.0), t_end=5.0), 2)
    assert lo > 9.9  # axis 3 (largest): stays
    lo, hi = _spin_component_range(body(I, (eps, 10.0, eps), t_end=5.0), 1)
    assert lo < 0.0  # axis 2 (intermediate): flips


def _orientation_of(u):
    """(beta, gamma) with n = R^T z = u (z-y-z, alpha = 0): n = (-sb cg, sb sg, cb)."""
    return math.acos(max(-1.0, min(1.0, u[2]))), math.atan2(u[1], -u[0])


def _max_angle_from(d, u):
    res = derive.simulate(d)
    u = np.asarray(u) / np.linalg.norm(u)
    return float(np.max(np.arccos(np.clip(res.n @ u, -1, 1))))


@pytest.mark.parametrize("hanging", [True, False])
def test_off_axis_rest_equilibria_simulated(hanging):
    path = SCENES / "off_axis_top.toml"
    e = find(str(path), "hanging" if hanging else "sleeping", None)
    assert e.stable is (True if hanging else False)
    com = np.array([0.01, 0.005, 0.03])
    u = -com if hanging else com  # n, the upward vertical, along r_c when upright
    b, g = _orientation_of(u / np.linalg.norm(u))
    d = body((3.0e-4, 4.0e-4, 2.0e-4), (1e-3, -1e-3, 1e-3), com=list(com), M=0.2, beta=b, gamma=g,
             t_end=2.0, formulation="euler-poisson")
    angle = _max_angle_from(d, u)
    if hanging:
        assert angle < 0.01
    else:
        assert angle > 0.5


@pytest.mark.parametrize("hanging", [True, False])
def test_kovalevskaya_vertical_spin_simulated(hanging):
    """Spin 0.5 rad/s about body axis 1 held vertical: hanging stable, upright unstable
    (real eigenvalue 0.855 /s)."""
    com = [0.1, 0.0, 0.0]
    u = [-1.0, 0.0, 0.0] if hanging else [1.0, 0.0, 0.0]
    b, g = _orientation_of(u)
    d = body((2.0, 2.0, 1.0), (0.5, 1e-4, 1e-4), com=com, beta=b, gamma=g, t_end=20.0,
             formulation="euler-poisson")
    e = find(d, "hanging" if hanging else "sleeping", 1)
    assert e.stable is (True if hanging else False)
    angle = _max_angle_from(d, u)
    if hanging:
        assert angle < 0.01
    else:
        assert angle > 0.5


def test_equatorial_com_at_any_azimuth_same_verdicts():
    """I1 = I2: r_c anywhere in the equatorial plane is a principal direction; turning the body
    about axis 3 changes neither the verdicts nor the eigenvalues."""
    def eqs(phi):
        u = (math.cos(phi), math.sin(phi), 0.0)
        d = body((2.0, 2.0, 1.0), [0.5 * x for x in u], com=[0.1 * x for x in u])
        return analysis.analyze(d).equilibria

    a, b = eqs(0.0), eqs(0.7)
    assert [(e.kind, e.stable) for e in a] == [(e.kind, e.stable) for e in b] == [
        ("sleeping", False), ("hanging", True)]
    assert [e.axis for e in b] == [None, None]
    for x, y in zip(a, b):
        np.testing.assert_allclose(sorted(np.round(x.eigenvalues, 9), key=lambda z: (z.real, z.imag)),
                                   sorted(np.round(y.eigenvalues, 9), key=lambda z: (z.real, z.imag)),
                                   atol=1e-8)


@pytest.mark.parametrize("w, stable", [(200.0, True), (100.0, False)])
def test_lecture_top_about_body_axis_1(w, stable):
    """The lecture's top with its axes relabelled (symmetry axis = body axis 1): the same k2,
    threshold and verdict as the original, and the simulation agrees."""
    d = body((4.0e-5, 1.8e-4, 1.8e-4), (w, 0.0, 0.0), com=[0.04, 0.0, 0.0], M=0.1,
             t_end=2.0, formulation="euler-poisson")
    u = (math.cos(1e-3), math.sin(1e-3), 0.0)  # body axis 1 tilted 1e-3 rad from the vertical
    d["initial"]["beta"], d["initial"]["gamma"] = _orientation_of(u)
    e = find(d, "sleeping", 1)
    ref = find(lecture_top(gamma_dot=w), "sleeping", 3)
    assert e.stable is ref.stable is stable
    assert e.values["k2"] == pytest.approx(ref.values["k2"], rel=1e-12)
    assert e.values["threshold"] == pytest.approx(ref.values["threshold"], rel=1e-12)
    angle = _max_angle_from(d, (1.0, 0.0, 0.0))
    assert (angle < 2e-3) if stable else (angle > 0.1)
