"""The one-way pipeline: registries, state maps, one C call, no SymPy on the warm path."""
import ast
import os
import subprocess
import sys

import numpy as np
import pytest

import compile_once
import derive
from kept_results import kept
from compiled_models import compiled_model
from derive.runtime import catalogue
from derive.symbolic import effects
from derive.symbolic import formulations
from derive.symbolic.models import CATALOGUE_KEYS
from derive.methods import registry as solvers
from derive.runtime.integrate import ModelKernel
from derive.codegen.render import ROOT
from derive.sim.scene import load_scene

RNG = np.random.default_rng(8)
SCENES = ROOT / "scenes"


def _top(**over):
    sc = {"body": {"I1": 1.0, "I3": 0.5}, "gravity": {"M": 1.0, "g": 1.0, "l": 1.0},
          "initial": {"alpha": 0.0, "beta": 0.8, "gamma": 0.0, "alpha_dot": -0.4,
                      "beta_dot": 0.3, "gamma_dot": 6.0},
          "simulate": {"t_end": 2.0, "samples": 51}}
    sc.update(over)
    return sc


# ---------------------------------------------------------------------------------------------
# state maps


@pytest.mark.parametrize("name, symmetric", [
    pytest.param(n, s, marks=pytest.mark.slow) if (n, s) == ("euler-angles", False) else (n, s)
    for s in (True, False) for n in formulations.REGISTRY])  # the asymmetric Euler-angle model: slow
def test_state_maps_round_trip(name, symmetric):
    """angles + ω̃ → y (the compiled init map) → angles + ω̃ (the compiled output map), at random
    states away from the singular set, for every formulation that takes the body."""
    if name in ("reduced", "reduced-u") and not symmetric:
        pytest.skip(f"the {name} formulation needs a symmetric body")
    key = (name, symmetric, ("gravity",) if symmetric else ("gravity_general",))
    desc = catalogue.describe(key)
    kernel = ModelKernel.load(desc, solvers.DEFAULT_METHOD)
    for _ in range(20):
        a, g = RNG.uniform(-np.pi, np.pi, 2)
        b = RNG.uniform(0.2, np.pi - 0.2)
        w = RNG.normal(size=3)
        inputs = np.array([a, b, g, *w, 0.0, 0.0, 0.0, 0.0])
        p = np.array([{"I1": 1.3, "I2": 1.3 if symmetric else 1.7, "I3": 0.9, "M": 1.0, "g": 9.81,
                       "l": 0.2, "cx": 0.1, "cy": -0.05, "cz": 0.2}.get(n, 0.0) for n in desc.params])
        y, p, rc = kernel.init(inputs, p)
        assert rc == 0
        out = kernel.outputs_at(np.array([0.0]), y[None, :], p)[:, 0]
        named = dict(zip(desc.outputs, out))
        np.testing.assert_allclose([named["alpha"], named["beta"], named["gamma"]], [a, b, g],
                                   atol=1e-12)
        np.testing.assert_allclose([named["omega1"], named["omega2"], named["omega3"]], w,
                                   atol=1e-12)
        # and the vertical: n = Rᵀẑ = (−sinβ cosγ, sinβ sinγ, cosβ)
        np.testing.assert_allclose([named["n1"], named["n2"], named["n3"]],
                                   [-np.sin(b) * np.cos(g), np.sin(b) * np.sin(g), np.cos(b)],
                                   atol=1e-12)


def test_canonical_angles_through_a_pole_passage():
    """The reduced chart's β changes sign at a pole passage; the output's β stays in [0, π]
    and α + γ (the combination defined at β = 0) stays continuous."""
    desc = catalogue.describe(("reduced", True, ("gravity",)))
    kernel = ModelKernel.load(desc, solvers.DEFAULT_METHOD)
    t = np.linspace(0.0, 1.0, 5)
    beta = np.array([0.2, 0.1, -0.05, -0.1, 0.3])
    y = np.column_stack([np.full(5, 0.3), beta, np.full(5, 1.0), np.zeros(5)])
    p = np.array([1.0, 0.5, 1.0, 1.0, 1.0, 2.0, 2.0])
    out = kernel.outputs_at(t, y, p)
    a, b, g = out[0], out[1], out[2]
    np.testing.assert_allclose(b, np.abs(beta))
    np.testing.assert_allclose(a + g, 1.3, atol=1e-15)  # continuous through the passage
    jumps = np.abs(np.diff(a))
    np.testing.assert_allclose(jumps, [0.0, np.pi, 0.0, np.pi], atol=1e-15)  # α turns by π


def _canonical_reference(a, b, c):
    """The canonical-angle rule of the C output map, step by step with the library calls
    always made (fmod, nearbyint = NumPy's round half to even): the reference its fast path
    must equal bit for bit."""
    import math

    pi, twopi = math.pi, 2.0 * math.pi
    a, b, c = (np.array(v, dtype=float) for v in (a, b, c))
    for k in range(len(b)):
        bb = math.fmod(b[k], twopi)
        if bb < 0.0:
            bb += twopi
        if bb > pi:
            bb = twopi - bb
            a[k] += pi
            c[k] += pi
        b[k] = bb
        if k == 0:
            continue
        a[k] += twopi * np.round((a[k - 1] - a[k]) / twopi)
        if abs(a[k] - a[k - 1]) > 0.5 * pi:
            target = a[k - 1] + c[k - 1] - a[k] if bb < 0.5 * pi else a[k] - (a[k - 1] - c[k - 1])
        else:
            target = c[k - 1]
        c[k] += twopi * np.round((target - c[k]) / twopi)
    return a, b, c


def test_canonical_angles_equal_the_rule_bit_for_bit():
    """The output map's canonical angles (with its fast path for the usual case) against the
    rule computed with every library call: random walks with whole-turn jumps, β outside
    [0, 2π), signed zeros."""
    desc = catalogue.describe(("euler-angles", True, ("gravity",)))
    kernel = ModelKernel.load(desc, solvers.DEFAULT_METHOD)
    rng = np.random.default_rng(5)
    n = 400
    for scale in (0.3, 2.0, 40.0):
        ang = np.cumsum(rng.normal(0.0, scale, size=(n, 3)), axis=0)
        ang[rng.integers(0, n, 20), rng.integers(0, 3, 20)] = 0.0
        ang[rng.integers(0, n, 20), rng.integers(0, 3, 20)] = -0.0
        ang[rng.integers(0, n, 10), 1] += 2 * np.pi * rng.integers(-3, 4, 10)
        y = np.column_stack([ang, rng.normal(size=(n, 3))])
        out = kernel.outputs_at(np.arange(n, dtype=float), y, np.array([1.0, 0.5, 1.0, 1.0, 1.0]))
        want = _canonical_reference(ang[:, 0], ang[:, 1], ang[:, 2])
        for got, ref in zip(out[:3], want):
            assert np.array_equal(got.view(np.int64), ref.view(np.int64))


# ---------------------------------------------------------------------------------------------
# registries


def _names():
    return (set(formulations.REGISTRY) | set(effects.REGISTRY) | set(effects.TABLES)
            | set(solvers.METHODS) | set(solvers.REFERENCE_METHODS))


#: The registries themselves, and modules that are data about them.
REGISTRIES = {"symbolic/effects.py", "symbolic/formulations.py", "methods/registry.py",
              "methods/tableaux.py", "methods/splitting.py", "symbolic/models.py",
              "runtime/catalogue.py", "codegen/sources.py", "methods/status.py", "sweeps/measures.py",
              # the renderers of the method registries (split from them: same data, same names)
              "codegen/solvers.py", "codegen/splitting.py"}
#: Modules outside the one-way pipeline: the benchmarks compare named contenders, the lecture
#: and its report quote the notes, tests-only references.
OUTSIDE = {"lecture/claims.py", "lecture/verify.py", "lecture/report.py", "reference/exact.py"}


def _registry_names_by_string(paths, names) -> list[str]:
    """``file:line: 'name'`` for each string constant (not a docstring) of ``paths`` that is one of
    ``names``, outside the registries and the modules outside the pipeline."""
    offenders = []
    for path in paths:
        rel = path.relative_to(ROOT / "derive").as_posix()
        if rel in REGISTRIES | OUTSIDE or rel.startswith("bench/"):
            continue
        docstrings = set()
        # one walk: a docstring's owner (a module, function or class) comes before the string
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.Constant):
                if isinstance(node.value, str) and node.value in names and id(node) not in docstrings:
                    offenders.append(f"{rel}:{node.lineno}: {node.value!r}")
            elif (isinstance(node, (ast.Module, ast.FunctionDef, ast.ClassDef, ast.AsyncFunctionDef))
                    and node.body and isinstance(node.body[0], ast.Expr)
                    and isinstance(node.body[0].value, ast.Constant)):
                docstrings.add(id(node.body[0].value))
    return offenders


def test_no_pipeline_module_names_a_registry_entry_by_string():
    """(The offenders are kept between test runs, tests/kept_results.py, under the names and the
    bytes of every module and of this file: the package is parsed again whenever any changes.)"""
    names = _names()
    paths = sorted((ROOT / "derive").rglob("*.py"))
    assert len(paths) > 40  # the whole package, every stage
    offenders = kept("registry-names-by-string", sorted(names),
                     lambda: _registry_names_by_string(paths, names), [*paths, __file__])
    assert not offenders, offenders


# ---------------------------------------------------------------------------------------------
# a toy effect, one entry, end to end


def test_a_toy_effect_registered_in_a_test_runs_end_to_end(tmp_path, monkeypatch):
    """A torsional spring about the vertical through the pivot? No: a uniform magnetic field
    B along z acting on a body dipole m along axis 3, V = −m B ẑ·(R ê₃) — one registry entry
    with its table; scene validation, derivation, code generation, compilation and simulation
    take it with no other edit. It is axisymmetric and conservative, so it behaves like
    gravity with M g l = −m B: the energy is conserved and matches the same top under gravity."""
    monkeypatch.setenv("DERIVE_CACHE", str(tmp_path / "cache"))
    catalogue.clear_memory()

    def V(R, sym):
        return -sym("m_dip") * sym("B") * R[2, 2]

    table = effects.Table("magnet", "uniform field B along z on a dipole m along body axis 3",
                          keys=(effects.Key("m", "A m^2", "dipole moment"),
                                effects.Key("B", "T", "field")))
    effect = effects.Effect("magnet", "magnet", "dipole m ê₃ in a field B ẑ",
                            params=(effects.Param("m_dip", (("real", True),)),
                                    effects.Param("B", (("real", True),))),
                            values=lambda v: {"m_dip": v["m"], "B": v["B"]},
                            potential=V, axisymmetric=True)
    effects.register(effect, table)
    try:
        sc = _top()
        del sc["gravity"]
        sc["magnet"] = {"m": -2.0, "B": 0.5}  # −m B = 1 = M g l of the gravity top
        with pytest.raises(derive.SceneError, match="magnet.q: unknown key"):
            load_scene({**sc, "magnet": {"m": 1.0, "B": 1.0, "q": 0.0}})
        res = derive.simulate(sc, formulation="euler-poisson")
        assert res.model == "euler_poisson_sym_magnet"
        assert np.ptp(res.energy) < 1e-10 * abs(res.energy[0])
        ref = derive.simulate(_top(), formulation="euler-poisson")
        np.testing.assert_allclose(res.axis, ref.axis, atol=1e-9)
        np.testing.assert_allclose(res.energy, ref.energy, atol=1e-9)
    finally:
        effects.unregister("magnet")
        catalogue.clear_memory()


# ---------------------------------------------------------------------------------------------
# one C call: batch = single runs, bit for bit


def test_every_output_of_a_batch_equals_the_single_run_bit_for_bit():
    scenes = []
    for b0, gd in [(0.3, 6.0), (0.6, 7.0), (1.1, 5.0)]:
        sc = _top()
        sc["initial"] = dict(sc["initial"], beta=b0, gamma_dot=gd)
        scenes.append(sc)
    batch = derive.simulate_batch(scenes)
    for sc, res in zip(scenes, batch):
        single = derive.simulate(sc, formulation=res.formulation)
        a, b = res.arrays(), single.arrays()
        assert a.keys() == b.keys()
        for k in a:
            np.testing.assert_array_equal(a[k], b[k], err_msg=k)


def _kovalevskaya(k: int) -> dict:
    sc = _scene_dict(ROOT / "scenes" / "kovalevskaya_top.toml")
    sc["simulate"] = {**sc.get("simulate", {}), "t_end": 2.0, "samples": 41}
    sc["initial"] = {**sc["initial"], "beta": 0.8 + 0.05 * k}
    return sc


def _tennis(k: int) -> dict:
    sc = _scene_dict(ROOT / "scenes" / "tennis_racket.toml")
    sc["simulate"] = {**sc.get("simulate", {}), "t_end": 2.0, "samples": 41}
    sc["initial"] = {**sc["initial"], "beta": 0.8 + 0.05 * k}
    return sc


def _scene_dict(path) -> dict:
    import tomllib

    with open(path, "rb") as f:
        return tomllib.load(f)


@pytest.mark.parametrize("make", [
    lambda k: {**_top(), "initial": {**_top()["initial"], "beta": 0.4 + 0.1 * k}},  # L3: an integral from L
    _kovalevskaya,  # K: an integral from its formula
    _tennis,  # none
], ids=["lagrange", "kovalevskaya", "asymmetric"])
def test_every_field_of_a_batch_result_is_the_single_runs(make):
    """Each Result of ``simulate_batch`` (9 scenes: a Taylor batch runs in lanes) has the single
    run's every field: outputs, state, integrals, statistics, model, effects and scene, whichever
    way the batch makes its Results (every integral a component of L, or one from a formula)."""
    scenes = [make(k) for k in range(9)]
    batch = derive.simulate_batch(scenes)
    assert len(batch) == 9
    for sc, res in zip(scenes, batch):
        single = derive.simulate(sc, formulation=res.formulation, method=res.method)
        a, b = res.arrays(), single.arrays()
        assert a.keys() == b.keys()
        for k in a:
            np.testing.assert_array_equal(a[k], b[k], err_msg=k)
        assert (res.model, res.effects, res.nfev) == (single.model, single.effects, single.nfev)
        assert res.integrals.keys() == single.integrals.keys()
        assert res.scene == load_scene(sc)  # (the single run's names its formulation and method)
        for k in res.integrals:  # each Result's own arrays
            assert not np.shares_memory(res.integrals[k], batch[0].integrals[k]) or res is batch[0]


# ---------------------------------------------------------------------------------------------
# warm path: no SymPy, no matplotlib


def _run(code: str, **env) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          cwd=ROOT, env={**os.environ, **env}, timeout=120)


def test_every_shipped_model_is_described_by_its_key_from_generated():
    for name, key in CATALOGUE_KEYS.items():
        assert formulations.model_name(*key) == name
        assert catalogue.describe(key).name == name


def test_import_derive_imports_neither_sympy_nor_matplotlib():
    r = _run("import sys, derive; print(sorted(m for m in ('sympy', 'matplotlib', 'scipy', 'jinja2',"
             " 'dask', 'distributed', 'pandas') if m in sys.modules))")
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "[]"


def test_a_warm_simulation_of_a_shipped_model_does_not_import_sympy():
    code = ("import sys, derive; derive.simulate('scenes/looping_top.toml'); "
            "derive.simulate('scenes/tennis_racket.toml'); "
            "print(sorted(m for m in ('sympy', 'matplotlib', 'jinja2') if m in sys.modules))")
    for name in ("looping_top", "tennis_racket"):  # compiled here if the cache is cold
        derive.simulate(str(ROOT / "scenes" / f"{name}.toml"))
    r = _run(code)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "[]"


# Ctrl-C inside a compiled loop: tests/test_cli_robust.py (rk4 and dop853, signal to exit < 0.5 s).


def test_fixed_step_budget_is_refused_up_front_naming_h():
    sc = _top(simulate={"t_end": 1e6, "samples": 11, "method": "rk4", "h": 1e-9})
    with pytest.raises(derive.SceneError, match=r"simulate\.h: rk4 with h = 1e-09 s .* takes "
                                                r"\d{15} steps, more than simulate\.max_steps"):
        derive.simulate(sc)


def test_adaptive_budget_is_a_numerical_failure():
    with pytest.raises(derive.IntegrationError, match=r"step budget spent \(simulate\.max_steps = 5\)"):
        derive.simulate(_top(), max_steps=5)


def test_the_c_abi_example_compiles_cleanly_and_runs():
    """docs/c-abi.md's example: strict C99 against the committed generated/c, and it agrees
    with the compiled kernel."""
    example = ROOT / "docs" / "examples" / "call_heavy_top.c"
    flags = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"]

    def build(work):
        r = subprocess.run(["cc", *flags, "-I", str(ROOT / "generated" / "c"), str(example),
                            str(ROOT / "generated" / "c" / "heavy_top.c"), "-lm", "-o", str(work / "example")],
                           capture_output=True, text=True)
        assert r.returncode == 0, r.stderr

    # kept for the exact example, generated/c and compiler (tests/compile_once.py); run every time
    inputs = {**compile_once.files_in(ROOT / "generated" / "c"), str(example): example.read_bytes()}
    exe = compile_once.once(["c-abi example", *flags], inputs, build, cc="cc") / "example"
    out = subprocess.run([str(exe)], capture_output=True, text=True, check=True).stdout
    values = [float(line.split("=")[1]) for line in out.splitlines()]
    desc = catalogue.describe(("euler-angles", True, ("gravity",)))
    assert desc.name == "heavy_top" and len(values) == 6
    y = np.array([0.0, 0.8, 0.0, -0.4, 0.3, 6.0])
    ref = compiled_model("euler-angles", True, ("gravity",)).rhs(0.0, y, [1.0, 0.5, 1.0, 1.0, 1.0])
    np.testing.assert_array_equal(values, ref)
    assert desc.params == ("I1", "I3", "M", "g", "l")


def test_docs_name_nothing_outside_the_repository():
    import re

    for path in [ROOT / "README.md", *(ROOT / "docs").rglob("*.md"), *(ROOT / "generated").glob("*.md")]:
        text = path.read_text()
        assert not re.search(r"\.\./shared|shared/(notes|INTERFACE|STYLE)|/work/", text), path


@pytest.mark.parametrize("method", ["splitting2", "splitting4", "splitting6"])
def test_splitting_methods_run_from_a_scene_and_keep_the_casimirs(method):
    """method = "splittingN" takes the Euler–Poisson formulation under auto; |n| = 1 and L·n
    stay at round-off whatever h, because every sub-flow is an exact rotation or kick."""
    res = derive.simulate(SCENES / "kovalevskaya_top.toml", method=method, h=0.05, t_end=20.0,
                          samples=201)
    assert res.formulation == formulations.UNIVERSAL and res.method == method
    assert np.max(np.abs(np.linalg.norm(res.n, axis=1) - 1.0)) < 1e-14
    Ln = np.sum(res.L * res.n, axis=1)
    assert np.max(np.abs(Ln - Ln[0])) < 1e-14 * np.max(np.abs(res.L))


def test_splitting_is_refused_where_there_is_no_hamiltonian_to_split():
    with pytest.raises(derive.SceneError, match=r"simulate\.method: .*'damping'"):
        derive.simulate(SCENES / "damped_top.toml", method="splitting4")
    with pytest.raises(derive.SceneError, match=r"simulate\.method: .*'euler-poisson' formulation"):
        derive.simulate(SCENES / "looping_top.toml", method="splitting4", formulation="quaternion")
