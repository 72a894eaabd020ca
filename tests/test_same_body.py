"""The same body gets the same model, and every init map takes the input it is given.

* Item 13: every shipped model's compiled ``<name>_init`` (the C ABI, called through ctypes on a
  library built from ``generated/c`` alone) starts from the Euler rates when rates_given = 1:
  ω̃ and the energy are compared with an independent conversion (ω̃ from Rᵀ Ṙ, R built here
  from the three elementary rotations), with the Python-side conversion of the scene validator
  and with the Euler-angle model's outputs.
* Item 12: spellings of one body (``com = [0, 0, l]`` for ``l``; an effect whose parameters
  make it vanish, ``[damping] c = 0``, ``g = 0``) give the same formulation, model, nfev and
  numbers as the plain scene.

Internal imports: ``derive.sim.scene.body_omega`` (the Python-side conversion the C one is checked
against), ``derive.symbolic.models`` (the derivation's guard against an init map that ignores the rates)
and, in a slow test, ``derive.runtime.catalogue`` (to derive models that are not shipped).
"""
from __future__ import annotations

import ctypes
import json
import os
import shlex
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import compile_once
from cli_in_process import derive_main

import derive

ROOT = Path(__file__).resolve().parents[1]
GENERATED = ROOT / "generated"
EPS = np.finfo(float).eps

#: Every shipped model: the descriptions in generated/models (what `derive generate` writes).
SHIPPED = sorted(p.stem for p in (GENERATED / "models").glob("*.json"))

ANGLES = (0.3, 0.7, -0.4)     # alpha, beta, gamma (rad): no symmetry, away from the poles
RATES = (-1.3, 0.8, 5.0)      # alpha_dot, beta_dot, gamma_dot (rad/s)
#: Parameter values by name; a model reads the ones it has (its derived ones are written by init).
ASYM = {"I1": 0.8, "I2": 0.6, "I3": 0.3, "M": 1.2, "g": 9.81, "l": 0.15,
        "cx": 0.05, "cy": -0.02, "cz": 0.15, "c": 0.05}
#: A symmetric body with its centre of mass on axis 3: every shipped model describes it.
SYM = {**ASYM, "I2": ASYM["I1"], "cx": 0.0, "cy": 0.0}


# ---------------------------------------------------------------------------------------------
# the C init and output maps, from generated/c alone


def _compiler() -> list[str]:
    """$CC (may carry arguments), default cc: what derive's own builds run."""
    return shlex.split(os.environ.get("CC", "cc")) or ["cc"]


def _compile(c_files: list[Path], include: Path, out: Path) -> ctypes.CDLL:
    """A shared library of model files, compiled as strictly as the ABI promises (kept for the
    exact files of ``include``, flags and compiler: ``compile_once.once``)."""
    flags = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O1", "-fPIC", "-shared"]

    def build(work: Path) -> None:
        cmd = _compiler() + flags + ["-I", str(include), *map(str, c_files), "-o", str(work / out.name), "-lm"]
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
        assert proc.returncode == 0, proc.stderr[-2000:]

    done = compile_once.once(["same-body", *flags, *(f.name for f in c_files), out.name],
                             compile_once.files_in(include), build)
    return ctypes.CDLL(str(done / out.name))


class CModel:
    """One model's ``_init`` and ``_observables_at`` from a compiled library and its description."""

    def __init__(self, lib: ctypes.CDLL, desc: dict):
        self.desc = desc
        self.name = desc["name"]
        dp = ctypes.POINTER(ctypes.c_double)
        self._init = getattr(lib, f"{self.name}_init")
        self._init.argtypes = (dp, dp, dp)
        self._init.restype = ctypes.c_int
        self._obs = getattr(lib, f"{self.name}_observables_at")
        self._obs.argtypes = (ctypes.c_long, dp, dp, dp, dp)
        self._obs.restype = ctypes.c_int

    def params(self, values: dict) -> np.ndarray:
        derived = set(self.desc["derived_params"])
        return np.array([0.0 if k in derived else values[n]
                         for k, n in enumerate(self.desc["params"])])

    def init(self, inputs, values: dict):
        """(y, p, status) of ``<name>_init``."""
        inputs = np.ascontiguousarray(inputs, dtype=float)
        assert inputs.shape == (self.desc["nin"],)
        p = self.params(values)
        y = np.full(len(self.desc["states"]), np.nan)
        rc = self._init(_ptr(inputs), _ptr(p), _ptr(y))
        return y, p, rc

    def outputs(self, y, p) -> dict:
        """The output map at (y, p) as {name: value or 3-vector}."""
        out = np.full(len(self.desc["outputs"]), np.nan)
        assert self._obs(1, _ptr(np.zeros(1)), _ptr(y), _ptr(p), _ptr(out)) == 0
        flat = dict(zip(self.desc["outputs"], out))
        # The output file's vectors, flattened with suffixes; a name that is not a complete
        # vector stays a scalar (euler_free's "L2" is |L|², not L₂).
        for base, parts in _VECTORS.items():
            if all(p in flat for p in parts):
                flat[base] = np.array([flat.pop(p) for p in parts])
        return flat


_VECTORS = {"omega": ("omega1", "omega2", "omega3"), "axis": ("axis_x", "axis_y", "axis_z"),
            "n": ("n1", "n2", "n3"), "L": ("L1", "L2", "L3")}


def _ptr(a: np.ndarray):
    return a.ctypes.data_as(ctypes.POINTER(ctypes.c_double))


@pytest.fixture(scope="module")
def shipped(tmp_path_factory) -> dict[str, CModel]:
    """Every shipped model's C init and output maps, one library from generated/c."""
    c = GENERATED / "c"
    files = [c / f"{name}.c" for name in SHIPPED]
    lib = _compile(files, c, tmp_path_factory.mktemp("abi") / "models.so")
    return {name: CModel(lib, json.loads((GENERATED / "models" / f"{name}.json").read_text()))
            for name in SHIPPED}


# ---------------------------------------------------------------------------------------------
# an independent conversion: R = Rz(α) Ry(β) Rz(γ) and ω̃ from Rᵀ Ṙ


def _rz(t):
    c, s = np.cos(t), np.sin(t)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def _ry(t):
    c, s = np.cos(t), np.sin(t)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


_KZ = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]])  # d/dt Rz(t) = Rz(t) [ẑ]ₓ
_KY = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, 0.0], [-1.0, 0.0, 0.0]])  # d/dt Ry(t) = Ry(t) [ŷ]ₓ


def rotation(a, b, c) -> np.ndarray:
    """Body → inertial components, z-y-z."""
    return _rz(a) @ _ry(b) @ _rz(c)


def omega_from_rates(angles, rates) -> np.ndarray:
    """ω̃ with [ω̃]ₓ = Rᵀ Ṙ, Ṙ by the product rule (no Euler-angle formula typed in)."""
    (a, b, c), (ad, bd, gd) = angles, rates
    A, B, C = _rz(a), _ry(b), _rz(c)
    Rdot = ad * A @ _KZ @ B @ C + bd * A @ B @ _KY @ C + gd * A @ B @ C @ _KZ
    W = rotation(a, b, c).T @ Rdot
    return np.array([W[2, 1] - W[1, 2], W[0, 2] - W[2, 0], W[1, 0] - W[0, 1]]) / 2


def energy(desc: dict, values: dict, angles, w) -> float:
    """½ ω̃ᵀ I ω̃ + M g ẑ·(R r_c) with the model's own parameters (I2 = I1 for a symmetric
    body; the centre of mass (0, 0, l) for axial gravity)."""
    params = desc["params"]
    I = np.array([values["I1"], values["I2" if "I2" in params else "I1"], values["I3"]])
    E = 0.5 * float(np.sum(I * w * w))
    if "M" in params:
        com = (np.array([values["cx"], values["cy"], values["cz"]]) if "cx" in params
               else np.array([0.0, 0.0, values["l"]]))
        E += values["M"] * values["g"] * float((rotation(*angles) @ com)[2])
    return E


def given_rates(angles=ANGLES, rates=RATES, omega=(np.nan,) * 3) -> np.ndarray:
    """Init inputs with rates_given = 1; omega NaN by default, so any read of it shows."""
    return np.array([*angles, *omega, *rates, 1.0])


def close(actual, expected, scale: float):
    """Equal to rounding: a few tens of ulps of the quantity's scale (nothing here is
    ill-conditioned: the maps are a handful of products of sines and cosines)."""
    np.testing.assert_allclose(actual, expected, rtol=0, atol=32 * EPS * scale)


# ---------------------------------------------------------------------------------------------
# item 13: the C init map uses the rates


def test_every_shipped_model_is_covered():
    """The list the tests below iterate is what generated/ ships: the contract's models and
    every formulation the registry has."""
    descs = [json.loads((GENERATED / "models" / f"{n}.json").read_text()) for n in SHIPPED]
    assert {"euler_free", "heavy_top"} <= set(SHIPPED)
    from_registry = {d["formulation"] for d in descs}
    assert {"euler-angles", "reduced", "quaternion", "euler-poisson"} <= from_registry


@pytest.mark.parametrize("name", SHIPPED)
def test_c_init_map_starts_from_the_given_euler_rates(shipped, name):
    """rates_given = 1 with omega NaN: the state is finite, its ω̃ is the rates' ω̃ (from Rᵀ Ṙ)
    and its energy ½ ω̃ᵀ I ω̃ + V (a user's own main() once got ω̃ = 0 from every model but the
    Euler-angle one)."""
    check_starts_from_rates(shipped[name], ASYM)


def check_starts_from_rates(m: CModel, values: dict):
    """``m``'s init map with rates_given = 1 (omega NaN) against the independent conversion."""
    y, p, rc = m.init(given_rates(), values)
    assert rc == 0 and np.isfinite(y).all() and np.isfinite(p).all()
    out = m.outputs(y, p)
    w = omega_from_rates(ANGLES, RATES)
    scale = float(np.max(np.abs(RATES)))
    close(out["omega"], w, scale)
    E = energy(m.desc, values, ANGLES, w)
    close(out["energy"], E, abs(E))
    if "n" in out:  # the orientation too: n = Rᵀẑ, axis = R ê₃
        R = rotation(*ANGLES)
        close(out["n"], R[2, :], 1.0)
        close(out["axis"], R[:, 2], 1.0)


#: Models derived on demand (not shipped), one per formulation with effects no shipped one has.
DERIVED = [("quaternion", True, ("gravity",)), ("quaternion", False, ()),
           ("euler-angles", False, ("gravity_general",)), ("euler-angles", True, ("damping",)),
           ("euler-poisson", False, ("gravity_general", "damping"))]


@pytest.mark.slow
@pytest.mark.parametrize("key", DERIVED, ids=lambda k: "-".join([k[0], str(k[1]), *k[2]]))
def test_c_init_map_of_a_derived_model_starts_from_the_given_euler_rates(key, tmp_path):
    """The same for models a scene derives into the cache (SymPy, 4-7 s each: slow)."""
    from derive.runtime import catalogue

    desc = catalogue.describe(key)
    c = Path(desc.folder) / "c"
    lib = _compile([c / f"{desc.name}.c"], c, tmp_path / "model.so")
    d = json.loads((Path(desc.folder) / "models" / f"{desc.name}.json").read_text())
    check_starts_from_rates(CModel(lib, d), ASYM)


@pytest.mark.parametrize("name", SHIPPED)
def test_c_init_map_from_rates_equals_the_python_side_conversion(shipped, name):
    """The state from the rates equals the state from ω̃ = body_omega(rates), the conversion the
    scene validator makes: the two forms of one initial condition give one state."""
    from derive.sim.scene import body_omega

    m = shipped[name]
    w = body_omega(ANGLES[1], ANGLES[2], *RATES)
    y1, p1, rc1 = m.init(given_rates(), ASYM)
    y0, p0, rc0 = m.init(np.array([*ANGLES, *w, np.nan, np.nan, np.nan, 0.0]), ASYM)
    assert rc1 == 0 and rc0 == 0
    scale = max(1.0, float(np.max(np.abs(RATES))), float(np.max(np.abs(p1))))
    close(y1, y0, scale)
    close(p1, p0, scale)


def _euler_angle_reference(desc: dict) -> str:
    """The shipped Euler-angle model of the same symmetric body: with gravity (any centre of mass
    on axis 3 is the heavy top; damping adds no energy) or without."""
    gravity = any(e.startswith("gravity") for e in desc["effects"])
    return "heavy_top" if gravity else "euler_angles_sym"


@pytest.mark.parametrize("name", SHIPPED)
def test_c_init_map_agrees_with_the_euler_angle_model(shipped, name):
    """For a symmetric body with its centre of mass on axis 3 (which every shipped model can
    describe), the outputs at t = 0 from the given rates equal those of the Euler-angle model,
    whose state is the angles and the rates themselves."""
    m, ref = shipped[name], shipped[_euler_angle_reference(shipped[name].desc)]
    y, p, rc = m.init(given_rates(), SYM)
    yr, pr, rcr = ref.init(given_rates(), SYM)
    assert rc == 0 and rcr == 0
    np.testing.assert_array_equal(yr, [*ANGLES, *RATES])  # the reference holds what it is given
    out, expected = m.outputs(y, p), ref.outputs(yr, pr)
    shared = set(out) & set(expected) - {"alpha", "beta", "gamma"}
    assert {"omega", "energy"} <= shared
    for key in sorted(shared):
        scale = max(1.0, float(np.max(np.abs(expected[key]))))
        close(out[key], expected[key], scale)


def test_a_model_whose_init_map_ignores_the_rates_is_not_built(monkeypatch):
    """The guarantee is structural: the derivation refuses an init map that does not read the
    Euler rates (so a new formulation cannot reintroduce the dropped input)."""
    from derive.symbolic import models

    monkeypatch.setattr(models, "_omega_in", lambda: models.INPUTS[3:6])  # ω̃ only: drops rates
    with pytest.raises(ValueError, match="ignores the Euler rates"):
        models.build("euler", False)
    monkeypatch.undo()
    assert models.build("euler", False).name == "euler_free"


# ---------------------------------------------------------------------------------------------
# item 12: one body, one formulation; a zero effect costs nothing

#: The README's heavy top (its scene template: [damping] c = 0.0 included, here left out).
TOP = {"body": {"I1": 1.8e-4, "I3": 4.0e-5},
       "gravity": {"M": 0.1, "g": 9.81, "l": 0.04},
       "initial": {"alpha": 0.0, "beta": 0.5, "gamma": 0.0, "alpha_dot": -3.0, "gamma_dot": 150.0},
       "simulate": {"t_end": 0.5, "samples": 101}}


def spelt(**tables) -> dict:
    """TOP with tables replaced (None removes one)."""
    out = {k: v for k, v in TOP.items() if tables.get(k, v) is not None}
    out.update({k: v for k, v in tables.items() if v is not None})
    return out


def assert_same_run(a, b):
    """One body, one run: the same formulation, model and nfev, and every output array equal
    bit for bit (the same kernel from the same numbers)."""
    assert (a.formulation, a.model, a.effects, a.nfev) == (b.formulation, b.model, b.effects, b.nfev)
    arrays_a, arrays_b = a.arrays(), b.arrays()
    assert arrays_a.keys() == arrays_b.keys()
    for key in arrays_a:
        np.testing.assert_array_equal(arrays_a[key], arrays_b[key], err_msg=key)


@pytest.mark.parametrize("com", [[0, 0, 0.04], [0.0, -0.0, 0.04]])
def test_a_centre_of_mass_on_axis_3_is_the_same_body_as_l(com):
    """com = [0, 0, l] is l: the same formulation (reduced-u, the cheapest here), model,
    nfev and numbers; the scene is stored and written back as l."""
    plain = derive.simulate(TOP)
    other = derive.simulate(spelt(gravity={"M": 0.1, "g": 9.81, "com": com}))
    assert plain.formulation == "reduced-u" and plain.model == "reduced_u_sym_gravity"
    assert_same_run(other, plain)
    assert other.scene == plain.scene
    assert other.scene.to_dict() == plain.scene.to_dict()
    assert other.scene.to_dict()["gravity"] == {"M": 0.1, "g": 9.81, "l": 0.04}


def test_zero_damping_runs_the_undamped_kernel_and_says_so():
    """The README's template has [damping] c = 0.0: it used to switch the heavy top to
    Euler–Poisson with its damped kernel (3.2x the rhs evaluations). Now the term is dropped:
    the undamped heavy top runs, the result names it, and every number is the same."""
    plain = derive.simulate(TOP)
    damped0 = derive.simulate(spelt(damping={"c": 0.0}))
    assert_same_run(damped0, plain)
    assert damped0.model == "reduced_u_sym_gravity" and damped0.effects == ("gravity",)
    assert damped0.scene.damping.c == 0.0  # what the scene said is still there
    # ... while any c > 0 keeps its term (and is not the conservative run)
    damped = derive.simulate(spelt(damping={"c": 1e-7}))
    assert "damping" in damped.effects and "damping" in damped.model
    assert damped.energy[-1] < damped.energy[0]


def test_zero_damping_lets_the_reduced_top_and_the_splittings_run():
    """What a zero term used to forbid (a formulation or a method that needs a conservative
    body) runs, with the numbers of the scene without it."""
    for overrides in ({"formulation": "reduced"},
                      {"method": "splitting4", "h": 1e-3, "formulation": "euler-poisson"}):
        plain = derive.simulate(TOP, **overrides)
        assert_same_run(derive.simulate(spelt(damping={"c": 0.0}), **overrides), plain)


@pytest.mark.parametrize("gravity", [{"M": 0.1, "g": 0.0, "l": 0.04},
                                     {"M": 0.1, "g": 9.81, "l": 0.0},
                                     {"M": 0.1, "g": 0.0, "com": [0.01, 0.0, 0.02]}])
def test_gravity_that_vanishes_is_the_free_body(gravity):
    """No field, or the centre of mass at the pivot: the same run as a scene without [gravity]."""
    assert_same_run(derive.simulate(spelt(gravity=gravity)), derive.simulate(spelt(gravity=None)))


def test_cli_json_names_the_model_that_ran(tmp_path):
    """`derive simulate --json` of the README template (c = 0.0) and of the same scene without
    the table: one formulation, one model, one nfev, and the summary says which kernel ran."""
    def toml(scene):
        lines = []
        for table, values in scene.items():
            lines.append(f"[{table}]")
            lines += [f"{k} = {v!r}" for k, v in values.items()]
        return "\n".join(lines) + "\n"

    summaries = []
    for name, scene in (("plain", TOP), ("template", spelt(damping={"c": 0.0}))):
        path = tmp_path / f"{name}.toml"
        path.write_text(toml(scene))
        proc = derive_main("simulate", path, "--json", cwd=tmp_path)
        assert proc.returncode == 0, proc.stderr
        summaries.append(json.loads(proc.stdout))
    plain, template = summaries
    for key in ("formulation", "model", "effects", "nfev", "energy_drift"):
        assert template[key] == plain[key], key
    assert plain["model"] == "reduced_u_sym_gravity" and plain["effects"] == ["gravity"]


def test_a_batch_mixing_zero_and_nonzero_damping_runs_one_damped_model():
    """A batch is one C call, so one model: the effects any scene needs. The damped scene's
    trajectory is the one it has alone; a batch of zero terms only runs the undamped kernel."""
    c0, c1 = spelt(damping={"c": 0.0}), spelt(damping={"c": 1e-7})
    mixed = derive.simulate_batch([c0, c1])
    assert all(r.effects == ("gravity", "damping") for r in mixed)
    assert_same_run(mixed[1], derive.simulate(c1))
    alone = derive.simulate_batch([c0, spelt(damping={"c": 0.0}, initial={**TOP["initial"], "beta": 0.6})])
    assert_same_run(alone[0], derive.simulate(TOP))


def test_a_sweep_of_the_damping_from_zero_keeps_the_term_at_every_point():
    """A sweep runs one model: with c = 0 at some points and c > 0 at others the damped one (a
    point that made the term vanish must not drop it for the whole sweep); with c = 0 at every
    point the undamped one."""
    spec = {"scene": spelt(damping={"c": 0.0}),
            "vary": {"damping": {"c": {"values": [0.0, 2e-6]}}},
            "measures": ["energy_drift"]}
    sw = derive.sweep(spec, progress=False)
    assert "damping" in sw.model
    drift = np.asarray(sw.measures["energy_drift"])
    assert drift[1] > 1e3 * drift[0]  # the damped point loses energy, the undamped one keeps it
    none = derive.sweep({**spec, "vary": {"initial": {"beta": {"values": [0.4, 0.5]}}}},
                        progress=False)
    assert "damping" not in none.model


@pytest.mark.slow
def test_analyze_of_zero_damping_is_the_analysis_of_the_conservative_top(tmp_path):
    """`derive analyze` (3-5 s a run: slow) of the template with c = 0 is the plain heavy top's:
    the same JSON, word for word, and the same document but for the line that reports c = 0
    (no "the damping torque breaks these conservation laws")."""
    gravity = "[gravity]\nM = 0.1\ng = 9.81\nl = 0.04\n"
    rest = ("[initial]\nalpha = 0.0\nbeta = 0.5\ngamma = 0.0\nalpha_dot = -3.0\n"
            "gamma_dot = 150.0\n[simulate]\nt_end = 2.0\n")
    outs = {}
    for name, tables in (("plain", gravity), ("template", gravity + "[damping]\nc = 0.0\n")):
        folder = tmp_path / name
        folder.mkdir()
        (folder / "scene.toml").write_text("[body]\nI1 = 1.8e-4\nI3 = 4.0e-5\n" + tables + rest)
        for fmt in ("json", "markdown"):
            proc = subprocess.run([sys.executable, "-m", "derive", "analyze", "scene.toml",
                                   "--format", fmt], capture_output=True, text=True, timeout=120,
                                  cwd=folder, env={**os.environ, "PYTHONPATH": str(ROOT)})
            assert proc.returncode == 0, proc.stderr
            outs[name, fmt] = proc.stdout
    assert json.loads(outs["template", "json"]) == json.loads(outs["plain", "json"])
    assert json.loads(outs["plain", "json"])["case"] == "lagrange"
    template = outs["template", "markdown"].splitlines()
    said = [line for line in template if line.startswith("Damping:")]
    assert said == ["Damping: torque −c ω̃ with c = 0 N m s (zero: no term, the body is conservative)."]
    assert [line for line in template if line not in said] == outs["plain", "markdown"].splitlines()


def test_a_batch_refuses_a_scene_that_cannot_give_an_acting_effect_its_numbers():
    """Zero damping and no [damping] table are the same body (one batch, undamped); c > 0 beside
    a scene without the table is refused (nothing gives that scene's c), naming the scene."""
    runs = derive.simulate_batch([spelt(damping={"c": 0.0}), TOP])
    assert [r.model for r in runs] == ["reduced_u_sym_gravity", "reduced_u_sym_gravity"]
    with pytest.raises(derive.SceneError, match="a batch needs the same effects"):
        derive.simulate_batch([TOP, spelt(damping={"c": 1e-7})])
    with pytest.raises(derive.SceneError, match="a batch needs the same effects"):
        derive.simulate_batch([spelt(damping={"c": 1e-7}), TOP])
