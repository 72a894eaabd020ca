"""`derive analyze`'s numbers against independent physics.

* Steady precession: each rate α̇ carries its own V_eff″ and eigenvalues (one record per root),
  checked against the closed-form nutation frequency and against a simulation.
* Small tilt: V_eff″ against mpmath at 50 digits of the unexpanded V_eff.
* A Goryachev–Chaplygin body off L·n = 0 (L·n computed here with SciPy's rotations) is
  `general`, and G is offered nowhere as conserved.
* One name per integral: analyze's JSON, the npz keys, ``Result.integrals`` and the generated
  outputs.md agree, and a name means what it says (``L_squared`` is |L|², ``L_k`` component k).
* Units and the compact display of V_eff.

``derive analyze`` costs seconds (SymPy): the analyses are module-scoped fixtures, run in-process
through ``derive.lecture.analysis`` (the CLI's own function; one CLI call checks the JSON it prints),
as ``derive.sim.plots._conserved`` is the plots' list of conserved quantities (internal modules).
"""
from __future__ import annotations

import json
import math
import re
import tomllib
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest
from cli_in_process import derive_main
import sympy as sp
from scipy.spatial.transform import Rotation

import derive
from derive.lecture import analysis
from derive.lecture import closed_forms, equilibria
from derive.symbolic import integrable

ROOT = Path(__file__).resolve().parent.parent
SCENES = ROOT / "scenes"
PRECESSING = ("wavy_top", "looping_top", "cuspidal_top", "free_symmetric", "sleeping_top")


def scene_file(name: str) -> dict:
    return tomllib.loads((SCENES / f"{name}.toml").read_text())


def lecture_top(beta: float, gamma_dot: float = 200.0) -> dict:
    """The top of scenes/sleeping_top.toml at the tilt ``beta``, no precession at the start."""
    return {"body": {"I1": 1.8e-4, "I3": 4.0e-5}, "gravity": {"M": 0.1, "g": 9.81, "l": 0.04},
            "initial": {"alpha": 0.0, "beta": beta, "gamma": 0.0, "alpha_dot": 0.0,
                        "beta_dot": 0.0, "gamma_dot": gamma_dot},
            "simulate": {"t_end": 1.0, "samples": 101}}


def precession(a: analysis.Analysis) -> equilibria.Equilibrium:
    (e,) = [e for e in a.equilibria if e.kind == "steady-precession"]
    return e


@pytest.fixture(scope="module")
def analysed() -> dict:
    """{scene name: Analysis} of the example scenes this module reads."""
    names = PRECESSING + ("tennis_racket", "kovalevskaya_top", "goryachev_chaplygin_top",
                          "off_axis_top")
    return {name: analysis.analyze(str(SCENES / f"{name}.toml")) for name in names}


# ---------------------------------------------------------------------------------------------
# item 2: each root with its own curvature and eigenvalues


def closed_form_nutation(I1: float, p_gamma: float, beta0: float, alpha_dot: float) -> float:
    """ω_n of small oscillations about the steady precession α̇ at the tilt β₀, by hand.

    L = ½I₁(β̇² + α̇² sin²β) + ½I₃(γ̇ + α̇ cos β)² − M g l cos β. α and γ are cyclic; with
    p_α = I₁α̇ sin²β + p_γ cos β and p_γ = I₃(γ̇ + α̇ cos β) fixed, Routh's reduction leaves
    I₁β̈ = −V_eff′(β), V_eff = f²/(2I₁) + M g l cos β with f = (p_α − p_γ cos β)/sin β = I₁α̇ sin β.
    Then f′ = p_γ − I₁α̇ cos β and f″ = −p_γ cos β/sin β + I₁α̇(sin²β + 2cos²β)/sin β, so

        I₁V_eff″ = f′² + f f″ − I₁ M g l cos β
                 = (p_γ − I₁α̇c)² − I₁α̇ p_γ c + I₁²α̇²(s² + 2c²) − I₁ M g l c     (c, s of β₀).

    At a steady precession V_eff′ = 0, i.e. α̇ sin β (p_γ − I₁α̇ c) = M g l sin β, so
    I₁ M g l c = I₁α̇ p_γ c − I₁²α̇²c². Substituting, with a = p_γ/I₁:

        ω_n² = V_eff″/I₁ = a² − 4aα̇c + α̇²(4c² + s²) = (a − 2α̇ cos β₀)² + α̇² sin²β₀.

    Gravity enters only through the root α̇ itself (M g l = 0: the free symmetric body)."""
    a = p_gamma / I1
    return math.sqrt((a - 2 * alpha_dot * math.cos(beta0)) ** 2 + (alpha_dot * math.sin(beta0)) ** 2)


@pytest.mark.parametrize("name", PRECESSING)
def test_each_root_carries_its_own_nutation_frequency(analysed, name):
    """For every root α̇ (ascending), V_eff″ = I₁ω_n² and the eigenvalues ±iω_n of the closed
    form at that root, in the records, in the JSON lists and in the eigenvalue list alike."""
    d = scene_file(name)
    i, I1, I3 = d["initial"], d["body"]["I1"], d["body"]["I3"]
    beta0 = i["beta"]
    p_gamma = I3 * (i["gamma_dot"] + i["alpha_dot"] * math.cos(beta0))  # = I3 ω̃3
    e = precession(analysed[name])
    roots = e.values["roots"]
    assert len(roots) == 2
    rates = [r.alpha_dot for r in roots]
    assert rates == sorted(rates) and rates[0] < rates[1]
    js = e.to_json()["values"]
    assert js["alpha_dot_roots"] == rates
    Mgl = d["gravity"]["M"] * d["gravity"]["g"] * d["gravity"]["l"] if "gravity" in d else 0.0
    for k, r in enumerate(roots):
        # the root solves ∂V_eff/∂β = 0: I₁ cos β₀ α̇² − p_γ α̇ + M g l = 0
        assert I1 * math.cos(beta0) * r.alpha_dot ** 2 - p_gamma * r.alpha_dot + Mgl == pytest.approx(
            0.0, abs=1e-13 * (p_gamma * abs(r.alpha_dot) + Mgl))
        w = closed_form_nutation(I1, p_gamma, beta0, r.alpha_dot)
        assert r.nutation_frequency == pytest.approx(w, rel=1e-12)
        assert js["V_eff_second_derivative"][k] == pytest.approx(I1 * w * w, rel=1e-12)
        assert js["roots"][k]["alpha_dot"] == r.alpha_dot
        pair = e.eigenvalues[2 * k: 2 * k + 2]
        np.testing.assert_allclose(sorted(z.imag for z in pair), [-w, w], rtol=1e-12)
        assert all(z.real == 0 for z in pair)
    if beta0 > 0.1:  # tilted: the two roots' frequencies differ, so a swapped pairing fails above
        assert abs(roots[0].nutation_frequency - roots[1].nutation_frequency) > 1e-3 * roots[0].nutation_frequency


def _frequency(t: np.ndarray, x: np.ndarray) -> float:
    """Angular frequency of an oscillation from its upward crossings of the mid-range
    (linear interpolation between samples), over whole periods."""
    mid = 0.5 * (x.max() + x.min())
    j = np.nonzero((x[:-1] < mid) & (x[1:] >= mid))[0]
    tc = t[j] + (mid - x[j]) * (t[j + 1] - t[j]) / (x[j + 1] - x[j])
    assert len(tc) >= 4
    return 2 * math.pi * (len(tc) - 1) / (tc[-1] - tc[0])


def test_wavy_top_simulated_nutation_matches_its_root(analysed):
    """derive's own simulation, started 0.1 % off each steady precession of the wavy top at the
    same p_γ, nods at that root's frequency (20.011 for the slow root 8.14, 24.477 for 30.5)."""
    d = scene_file("wavy_top")
    i = d["initial"]
    w3 = i["gamma_dot"] + i["alpha_dot"] * math.cos(i["beta"])
    for r in precession(analysed["wavy_top"]).values["roots"]:
        ad = 1.001 * r.alpha_dot
        run = {**d, "initial": {**i, "alpha_dot": ad, "gamma_dot": w3 - ad * math.cos(i["beta"])},
               "simulate": {"t_end": 2.0, "samples": 20001, "rtol": 1e-11, "atol": 1e-13}}
        res = derive.simulate(run)
        assert _frequency(res.t, res.beta) == pytest.approx(r.nutation_frequency, rel=1e-3)


# ---------------------------------------------------------------------------------------------
# item 3: V_eff″ at a small tilt


@pytest.fixture(scope="module")
def small_tilts() -> dict:
    return {b: analysis.analyze(lecture_top(b)) for b in (1e-3, 1e-4, 1e-6)}


@pytest.mark.parametrize("beta0", [1e-3, 1e-4, 1e-6])
def test_small_tilt_curvature_against_50_digits(small_tilts, beta0):
    """V_eff″(β₀) of each steady precession against mpmath at 50 digits: the roots of
    I₁ cos β₀ α̇² − p_γ α̇ + M g l = 0, p_α = I₁α̇ sin²β₀ + p_γ cos β₀, and the second
    derivative of the unexpanded V_eff = (p_α − p_γ cos β)²/(2I₁ sin²β) + M g l cos β (whose
    expanded form cancels ~p_γ²/(I₁β⁴) terms in double precision). The motion is stable."""
    e = precession(small_tilts[beta0])
    with mp.workdps(50):
        I1, I3 = mp.mpf(1.8e-4), mp.mpf(4.0e-5)
        Mgl = mp.mpf(0.1) * mp.mpf(9.81) * mp.mpf(0.04)
        pg, b0 = I3 * mp.mpf(200.0), mp.mpf(beta0)
        a, b = I1 * mp.cos(b0), -pg
        disc = b * b - 4 * a * Mgl
        rates = sorted([(-b - mp.sqrt(disc)) / (2 * a), (-b + mp.sqrt(disc)) / (2 * a)])
        truth = []
        for ad in rates:
            pa = I1 * ad * mp.sin(b0) ** 2 + pg * mp.cos(b0)
            truth.append(mp.diff(lambda x: (pa - pg * mp.cos(x)) ** 2 / (2 * I1 * mp.sin(x) ** 2)
                                 + Mgl * mp.cos(x), b0, 2))
    roots = e.values["roots"]
    assert [r.alpha_dot for r in roots] == pytest.approx([float(x) for x in rates], rel=1e-13)
    for r, v in zip(roots, truth):
        assert r.curvature == pytest.approx(float(v), rel=1e-12)
        assert r.stable is True
    assert e.stable is True


# ---------------------------------------------------------------------------------------------
# item 4: Goryachev–Chaplygin only on L·n = 0


def area_level(d: dict) -> tuple[float, float]:
    """(L·n, |L|) from the scene's initial state: R = Rz(α) Ry(β) Rz(γ) (SciPy's intrinsic
    "ZYZ"), n = Rᵀẑ, L = I ω̃ (body axes)."""
    i = d["initial"]
    R = Rotation.from_euler("ZYZ", [i["alpha"], i["beta"], i["gamma"]]).as_matrix()
    n = R.T @ np.array([0.0, 0.0, 1.0])
    L = np.array([d["body"]["I1"], d["body"]["I2"], d["body"]["I3"]]) * np.array(i["omega"])
    return float(L @ n), float(np.linalg.norm(L))


@pytest.fixture(scope="module")
def gc_states() -> dict:
    """The Goryachev–Chaplygin scene on its level, 1e-13 (relative) off it, and far off it."""
    base = scene_file("goryachev_chaplygin_top")
    base["simulate"] = {"t_end": 0.5, "samples": 51, "formulation": "euler-poisson"}
    on = base["initial"]["omega"][2]
    out = {}
    for label, w3 in (("on", on), ("rounding", on * (1 + 1e-13)), ("off", 10.0)):
        d = json.loads(json.dumps(base))
        d["initial"]["omega"][2] = w3
        out[label] = (d, analysis.analyze(d).to_json())
    return out


@pytest.mark.parametrize("label", ["on", "rounding", "off"])
def test_goryachev_chaplygin_only_on_its_level(gc_states, label):
    d, js = gc_states[label]
    ln, size = area_level(d)
    on_level = abs(ln) <= integrable.TOLERANCE * size
    assert on_level is (label != "off")
    names = [i["name"] for i in js["integrals"]]
    res = derive.simulate(d)
    from derive.sim import plots

    conserved = [name for name, _ in plots._conserved(res)]
    if on_level:
        assert js["case"] == "goryachev-chaplygin" and "body_case" not in js
        assert "goryachev_chaplygin" in names and "goryachev_chaplygin" in res.integrals
        assert "goryachev_chaplygin" in conserved
    else:
        assert abs(ln) > 0.1 * size  # far off: L.n = -0.21 kg m^2/s
        assert js["case"] == "general" and js["body_case"] == "goryachev-chaplygin"
        assert "L.n" in js["reason"]
        assert "goryachev_chaplygin" not in names
        assert res.integrals == {} and "integral_goryachev_chaplygin" not in res.arrays()
        assert "goryachev_chaplygin" not in conserved


# ---------------------------------------------------------------------------------------------
# item 8: one name per integral, everywhere


def _outputs_md_names() -> list[str]:
    text = (ROOT / "generated" / "outputs.md").read_text()
    return re.findall(r"^\| `integral_(\w+)` \|", text, flags=re.M)


@pytest.fixture(scope="module")
def named_runs(analysed, tmp_path_factory) -> dict:
    """{scene: (analyze JSON, npz keys, Result)} for a body of every integrable case (a sphere
    and a top symmetric about body axis 1 included); one run through the CLI's -o."""
    sphere = {"body": {"I1": 1.0, "I2": 1.0, "I3": 1.0},
              "gravity": {"M": 1.0, "g": 9.81, "com": [0.03, 0.04, 0.0]},
              "initial": {"alpha": 0.0, "beta": 0.7, "gamma": 0.2, "omega": [0.4, -0.2, 1.0]},
              "simulate": {"t_end": 0.5, "samples": 51, "formulation": "euler-poisson"}}
    axis1 = {"body": {"I1": 4.0e-5, "I2": 1.8e-4, "I3": 1.8e-4},
             "gravity": {"M": 0.1, "g": 9.81, "com": [0.04, 0.0, 0.0]},
             "initial": {"alpha": 0.0, "beta": 1.2, "gamma": 0.4, "omega": [150.0, 1.0, -2.0]},
             "simulate": {"t_end": 0.2, "samples": 51, "formulation": "euler-poisson"}}
    out = {}
    for name in ("tennis_racket", "looping_top", "kovalevskaya_top", "goryachev_chaplygin_top"):
        d = scene_file(name)
        d["simulate"].update(t_end=0.2, samples=21)
        res = derive.simulate(d)
        out[name] = (analysed[name].to_json(), set(res.arrays()), res)
    for name, d in (("sphere", sphere), ("axis1", axis1)):
        res = derive.simulate(d)
        out[name] = (analysis.analyze(d).to_json(), set(res.arrays()), res)
    npz = tmp_path_factory.mktemp("npz") / "kov.npz"
    p = derive_main("simulate", SCENES / "kovalevskaya_top.toml", "-o", npz)
    assert p.returncode == 0, p.stderr
    with np.load(npz) as f:
        js, _, res = out["kovalevskaya_top"]
        out["kovalevskaya_top"] = (js, set(f.files), res)
    return out


def test_integral_names_agree_across_analyze_npz_result_and_outputs_md(analysed, named_runs):
    """The extra integral analyze names (its names minus a general body's) is the npz key
    ``integral_<name>``, the key of Result.integrals, and a row of generated/outputs.md; every
    case's name differs, and outputs.md lists each name once."""
    documented = _outputs_md_names()
    assert len(documented) == len(set(documented))
    common = {i["name"] for i in analysed["off_axis_top"].to_json()["integrals"]}
    seen = {}
    for scene, (js, keys, res) in named_runs.items():
        extra = [i["name"] for i in js["integrals"] if i["name"] not in common]
        assert len(extra) == 1, scene
        (name,) = extra
        assert {k[len("integral_"):] for k in keys if k.startswith("integral_")} == {name}
        assert set(res.integrals) == {name}
        assert name in documented
        seen[name] = scene
    assert len(seen) == len(named_runs)  # one name per quantity: no two cases share one
    assert set(seen) <= set(documented)


def test_an_integral_is_what_its_name_says(named_runs):
    """``L_squared`` is |L|² (not a component) and ``L_k`` the component L_k, on the runs' own L."""
    for js, keys, res in named_runs.values():
        for name, values in res.integrals.items():
            if name == "L_squared":
                np.testing.assert_allclose(values, np.sum(res.L ** 2, axis=1), rtol=1e-14)
            m = re.fullmatch(r"L_(\d)", name)
            if m:
                np.testing.assert_array_equal(values, res.L[:, int(m.group(1)) - 1])
    names = {n for _, _, res in named_runs.values() for n in res.integrals}
    assert "L_squared" in names and "L_3" in names and "L_1" in names


# ---------------------------------------------------------------------------------------------
# item 11: units and the compact display


@pytest.fixture(scope="module")
def wavy_cli_json(analysed) -> dict:
    """What `derive analyze scenes/wavy_top.toml --format json` prints (``analysis.render`` is
    the CLI's function; in-process, so the derivations are not redone)."""
    return json.loads(analysis.render(str(SCENES / "wavy_top.toml"), "json"))


def _numeric_keys(values: dict) -> set:
    keys = set()
    for k, v in values.items():
        if k == "roots":
            for r in v:
                keys |= {f for f, x in r.items() if isinstance(x, (int, float)) and not isinstance(x, bool)}
        elif isinstance(v, (int, float, list)) and not isinstance(v, bool):
            keys.add(k)
    return keys


def test_units_in_json(wavy_cli_json, analysed):
    """Every reported number has a unit: each equilibrium's values and eigenvalues, each
    integral; the momenta in kg m^2 s^-1, the rates in rad s^-1, the eigenvalues in s^-1."""
    docs = [wavy_cli_json] + [a.to_json() for a in analysed.values()]
    for js in docs:
        for i in js["integrals"]:
            assert i["unit"]
        for e in js["equilibria"]:
            assert _numeric_keys(e["values"]) <= set(e["units"])
            assert e["units"]["eigenvalues"] == "s^-1"
    units = {k: v for e in wavy_cli_json["equilibria"] for k, v in e["units"].items()}
    assert units["p_gamma"] == units["threshold"] == units["p_alpha"] == "kg m^2 s^-1"
    assert units["alpha_dot"] == units["nutation_frequency"] == "rad s^-1"
    assert units["k2"] == units["V_eff_second_derivative"] == "J rad^-2"
    assert {i["name"]: i["unit"] for i in wavy_cli_json["integrals"]}["energy"] == "J"


def test_units_in_markdown(analysed):
    md = analysed["wavy_top"].to_markdown()
    assert re.search(r"p_gamma = [0-9.e+-]+ kg m² s⁻¹", md)
    assert re.search(r"threshold = [0-9.e+-]+ kg m² s⁻¹", md)
    assert re.search(r"k2 = [0-9.e+-]+ J rad⁻²", md)
    assert "Eigenvalues [s⁻¹]:" in md
    assert "| α̇ [rad s⁻¹] | p_α [kg m² s⁻¹] | V_eff″(β₀) [J rad⁻²]" in md
    md = analysed["free_symmetric"].to_markdown()
    assert re.search(r"omega0 = [0-9.e+-]+ rad s⁻¹, lambda_squared = [0-9.e+-]+ s⁻²", md)
    assert "Name `L_squared`, in kg² m⁴ s⁻²; the simulation writes it as `integral_L_squared`." in md


def test_v_eff_shown_compact(wavy_cli_json, analysed):
    """V_eff as shown (JSON "V_eff", the Markdown's formula) equals the Routh function by hand,
    (p_α − p_γ cos β)²/(2I₁ sin²β) + M g l cos β up to a constant, in fewer terms than its
    expanded form."""
    names = {s: sp.Symbol(s, real=True) for s in ("I1", "M", "g", "l", "p_alpha", "p_gamma", "beta")}
    shown = sp.sympify(wavy_cli_json["V_eff"], locals=names)
    I1, M, g, l, pa, pg, b = (names[s] for s in ("I1", "M", "g", "l", "p_alpha", "p_gamma", "beta"))
    by_hand = (pa - pg * sp.cos(b)) ** 2 / (2 * I1 * sp.sin(b) ** 2) + M * g * l * sp.cos(b)
    difference = sp.simplify(shown - by_hand)
    assert not difference.has(b) and not difference.has(pa)
    expanded = sp.expand(shown)
    assert len(sp.Add.make_args(shown)) < len(sp.Add.make_args(expanded))
    assert sp.count_ops(shown) < sp.count_ops(expanded)
    md = analysed["wavy_top"].to_markdown()
    assert f"V_\\text{{eff}} = {closed_forms._latex(closed_forms._routh()['Veff_display'])} $$" in md
