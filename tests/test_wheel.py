"""`pip install .` (a wheel, not editable) gives a working package with no checkout around it.

The wheel is built from a copy of the checkout's packaging inputs by the build backend that
pyproject.toml names (as pip builds it), installed into a fresh virtual environment (no pip of
its own: this interpreter's pip installs into it with ``--python``, ``--no-deps --no-index``, so
the test is offline), and its dependencies are borrowed from this environment through a
``.pth`` file. Everything then runs from an empty directory with ``python -I`` (or the
``derive`` console script) and no ``PYTHONPATH``, so the checkout is not on ``sys.path``: the
templates and the committed generated code must come from the wheel itself. The wheel and its environment are kept between runs for the exact inputs
they are built from (the ``installed`` fixture): a change to any of them builds both again.
"""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import sysconfig
import zipfile
from importlib import metadata
from pathlib import Path

import pytest

import compile_once
import derive

CHECKOUT = Path(__file__).resolve().parent.parent
# What the wheel is built from (the rest of the checkout is not part of the package).
PACKAGING_INPUTS = ("pyproject.toml", "README.md", "derive", "templates", "generated", "scenes")
SCENE = """\
title = "wheel test: free symmetric body"
[body]
I1 = 2.5e-5
I3 = 4.0e-5
[initial]
alpha = 0.0
beta = 0.6435011087932844
gamma = 0.0
alpha_dot = 40.0
beta_dot = 0.0
gamma_dot = -12.0
[simulate]
t_end = 0.5
samples = 51
"""


def _data_files(folder: str) -> list[str]:
    """The files of a top-level data folder the wheel must carry (relative paths)."""
    root = CHECKOUT / folder
    return sorted(p.relative_to(root).as_posix() for p in root.rglob("*")
                  if p.is_file() and "__pycache__" not in p.parts and p.suffix != ".pyc")


def _run(cmd, cwd, **kw):
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYTHON")}
    return subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True, timeout=600, **kw)


@pytest.fixture(scope="module")
def installed(tmp_path_factory) -> Path:
    """The folder holding ``wheel/`` (the wheel built from the packaging inputs) and ``venv/`` (a
    virtual environment with it installed; the tests only run its Python).

    Both are a function of the packaging inputs' bytes, this interpreter and its pip and
    setuptools: the folder is kept for exactly these (``compile_once.kept_in_place``), so any
    change to them builds both afresh, and the test processes of a run share it."""
    inputs = compile_once.files_under(*(CHECKOUT / name for name in PACKAGING_INPUTS
                                        if (CHECKOUT / name).is_dir()))
    inputs.update({name: (CHECKOUT / name).read_bytes() for name in PACKAGING_INPUTS
                   if (CHECKOUT / name).is_file()})
    what = ["wheel and venv", sys.version, sys.executable,
            *(f"{dist} {metadata.version(dist)}" for dist in ("pip", "setuptools"))]

    def build(folder: Path) -> None:
        _install(_build_wheel(tmp_path_factory, folder / "wheel"), folder / "venv")

    return compile_once.kept_in_place(what, inputs, build)


@pytest.fixture(scope="module")
def wheel(installed) -> Path:
    (whl,) = (installed / "wheel").glob("derive_rigid_body-*.whl")  # the distribution's name, derive.DISTRIBUTION
    return whl


@pytest.fixture(scope="module")
def venv(installed) -> Path:
    return installed / "venv"


# The wheel as `pip wheel --no-build-isolation` builds it (PEP 517): the backend pyproject.toml names,
# imported in this environment and asked for a wheel, in a process of its own (pip's own start-up,
# which only relays the hook, is left out).
PEP517_BUILD = """\
import importlib, sys, tomllib
with open("pyproject.toml", "rb") as fh:
    module, _, attr = tomllib.load(fh)["build-system"]["build-backend"].partition(":")
backend = importlib.import_module(module)
for name in filter(None, attr.split(".")):
    backend = getattr(backend, name)
backend.build_wheel(sys.argv[1])
"""


def _build_wheel(tmp_path_factory, out: Path) -> Path:
    src = tmp_path_factory.mktemp("src")
    for name in PACKAGING_INPUTS:
        path = CHECKOUT / name
        if path.is_dir():
            shutil.copytree(path, src / name, ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
        else:
            shutil.copy2(path, src / name)
    out.mkdir(parents=True, exist_ok=True)
    r = _run([sys.executable, "-c", PEP517_BUILD, str(out)], cwd=src)
    assert r.returncode == 0, r.stderr
    (whl,) = out.glob("derive_rigid_body-*.whl")
    return whl


def _install(wheel: Path, env_dir: Path) -> Path:
    r = _run([sys.executable, "-m", "venv", "--without-pip", "--clear", str(env_dir)], cwd=env_dir.parent)
    assert r.returncode == 0, r.stderr
    python = env_dir / "bin" / "python"
    purelib = _run([str(python), "-I", "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
                   cwd=env_dir).stdout.strip()
    here = {sysconfig.get_paths()[k] for k in ("purelib", "platlib")}
    # Dependencies (numpy, sympy, ...) from this environment; appended after the venv's own
    # site-packages, so the installed derive is found first.
    Path(purelib, "_derive_test_deps.pth").write_text("".join(f"{p}\n" for p in sorted(here)))
    r = _run([sys.executable, "-m", "pip", "--python", str(python), "install", "-q", "--no-deps", "--no-index",
              "--disable-pip-version-check", str(wheel)], cwd=env_dir)
    assert r.returncode == 0, r.stderr
    return env_dir


@pytest.fixture()
def empty(tmp_path) -> Path:
    d = tmp_path / "empty"
    d.mkdir()
    return d


def test_wheel_carries_the_templates_and_the_generated_code(wheel):
    names = set(zipfile.ZipFile(wheel).namelist())
    for folder in ("templates", "generated", "scenes"):
        files = _data_files(folder)
        assert files, folder
        missing = [f for f in files if f"derive/_{folder}/{f}" not in names]
        assert not missing, f"{folder}/ files missing from the wheel: {missing}"
    # every module of every subpackage, and the bench's baselines (its C and Python rivals)
    package = [f"derive/{f}" for f in _data_files("derive") if f.endswith(".py") or "/baselines/" in f"/{f}"]
    missing = [f for f in package if f not in names]
    assert package and not missing, f"package files missing from the wheel: {missing}"


def test_api_uses_the_packages_own_data_and_simulates_from_an_empty_directory(venv, empty):
    (empty / "scene.toml").write_text(SCENE)
    code = ("import json, derive, derive.codegen.render as r; res = derive.simulate('scene.toml'); "
            "print(json.dumps([derive.__file__, str(r.CHECKOUT), str(r.TEMPLATES), str(r.GENERATED), len(res.t)]))")
    r = _run([str(venv / "bin" / "python"), "-I", "-c", code], cwd=empty)
    assert r.returncode == 0, r.stderr
    module, checkout, templates, generated, samples = json.loads(r.stdout)
    assert Path(module).resolve().is_relative_to(venv.resolve())
    assert checkout == "None"
    assert Path(templates).resolve().is_relative_to(venv.resolve()) and Path(templates, "c").is_dir()
    assert Path(generated).resolve().is_relative_to(venv.resolve()) and Path(generated, "c").is_dir()
    assert samples == 51


def test_console_script_simulates_a_scene_from_an_empty_directory(venv, empty):
    (empty / "scene.toml").write_text(SCENE)
    r = _run([str(venv / "bin" / "derive"), "simulate", "scene.toml", "-o", "out.npz", "--json"], cwd=empty)
    assert r.returncode == 0, r.stderr
    summary = json.loads(r.stdout)
    assert summary["samples"] == 51 and summary["outputs"]["npz"] == "out.npz"
    assert summary["energy_drift"] < 1e-12
    assert (empty / "out.npz").stat().st_size > 0


@pytest.mark.slow  # verify derives with SymPy in the installed wheel: `make test-slow`
def test_version_and_verify_work_installed(venv, empty):
    r = _run([str(venv / "bin" / "derive"), "--version"], cwd=empty)
    assert r.returncode == 0 and r.stdout.strip() == f"derive {derive.__version__}", r.stdout + r.stderr
    r = _run([str(venv / "bin" / "derive"), "verify"], cwd=empty)
    assert r.returncode == 0, r.stderr
    assert "holds" in r.stdout


def test_generate_without_out_is_refused_when_installed(venv, empty):
    r = _run([str(venv / "bin" / "derive"), "generate"], cwd=empty)
    assert r.returncode == 2
    assert r.stderr.startswith("error: ") and r.stderr.count("\n") == 1 and "--out" in r.stderr
    assert list(empty.iterdir()) == []


@pytest.mark.slow  # derives every model again (~5-15 s)
def test_generate_out_writes_what_the_wheel_carries(venv, empty):
    derive_cmd = str(venv / "bin" / "derive")
    r = _run([derive_cmd, "generate", "--out", "gen"], cwd=empty)
    assert r.returncode == 0, r.stderr
    written = sorted(p.relative_to(empty / "gen").as_posix() for p in (empty / "gen").rglob("*") if p.is_file())
    assert written == _data_files("generated")
    # What the installed package generates is the copy it carries (what `generate --check` compares).
    shipped = Path(_run([str(venv / "bin" / "python"), "-I", "-c", "import derive.codegen.render as r; print(r.GENERATED)"],
                        cwd=empty).stdout.strip())
    for rel in written:
        assert (empty / "gen" / rel).read_bytes() == (shipped / rel).read_bytes(), rel


def test_examples_run_by_name_from_an_empty_directory(venv, empty):
    r = _run([str(venv / "bin" / "derive"), "examples"], cwd=empty)
    assert r.returncode == 0 and "looping_top" in r.stdout and "sleeping_threshold" in r.stdout, r.stderr
    r = _run([str(venv / "bin" / "derive"), "simulate", "free_symmetric", "--json"], cwd=empty)
    assert r.returncode == 0, r.stderr
    assert json.loads(r.stdout)["formulation"]


@pytest.mark.slow  # the smoke bench again, from the installed wheel (~7 s): `make test-slow`
def test_bench_runs_from_the_wheel(venv, empty):
    """The bench is a client of the installed package: its baselines and reference scene come
    with the wheel (the smoke settings: a few seconds)."""
    code = ("from derive.bench import suite; r = suite.main(out='bench', smoke=True, peers=False); "
            "print(sorted(r['targets']))")
    r = _run([str(venv / "bin" / "python"), "-I", "-c", code], cwd=empty)
    assert r.returncode == 0, r.stderr[-2000:]
    assert (empty / "bench" / "report.md").is_file()
