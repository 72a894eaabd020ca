"""`derive export`: the scene's model as a self-contained C99 folder and as an FMI 2.0 FMU.

The folder's ``./example`` is built with the C compiler under the strictest warnings
(``-std=c99 -Wall -Wextra -Werror -pedantic``) and must print what ``derive simulate --json``
and its output file say: the same nfev, the outputs at the last sample to 1e-12. The FMU is
validated by FMPy and its co-simulation compared with derive.simulate.
"""
from __future__ import annotations

import json
import os
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from derive.cli import main

ROOT = Path(__file__).resolve().parent.parent
SCENES = ROOT / "scenes"
STRICT = "CFLAGS=-std=c99 -O2 -Wall -Wextra -Werror -pedantic"

pytestmark = pytest.mark.skipif(shutil.which("make") is None, reason="needs make")


def _cli(capsys, *argv) -> tuple[int, str, str]:
    rc = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return rc, out, err


def _scene(tmp_path: Path, name: str) -> Path:
    """A scene file: an example by name, or ``reduced`` (the reference top in the reduced
    formulation, whose init map derives p_alpha and p_gamma)."""
    if name == "reduced":
        path = tmp_path / "reduced_top.toml"
        text = (SCENES / "reference_top.toml").read_text(encoding="utf-8")
        path.write_text(text + 'formulation = "reduced"\n', encoding="utf-8")  # [simulate] is last
        return path
    return SCENES / f"{name}.toml"


def _build_and_run(folder: Path) -> dict:
    build = subprocess.run(["make", "-s", "-C", str(folder), STRICT], capture_output=True, text=True)
    assert build.returncode == 0, build.stderr
    for made in ("example", f"lib{json.loads(_only(folder, '.json').read_text())['name']}.a"):
        assert (folder / made).is_file()
    run = subprocess.run([str(folder / "example")], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    lines = run.stdout.splitlines()
    assert len(lines) == 1
    return json.loads(lines[0])


def _only(folder: Path, suffix: str) -> Path:
    found = [p for p in folder.iterdir() if p.suffix == suffix]
    assert len(found) == 1, found
    return found[0]


@pytest.mark.parametrize("scene, method", [
    ("reference_top", None),  # heavy_top, Euler angles with the pole check, dop853
    ("reduced", None),        # derived parameters written by the init map
    pytest.param("tennis_racket", "rk4", marks=pytest.mark.slow),  # a fixed step from the scene
    pytest.param("kovalevskaya_top", "splitting4", marks=pytest.mark.slow),  # a splitting's own file
])
def test_example_prints_what_simulate_gives(tmp_path, capsys, scene, method):
    path = _scene(tmp_path, scene)
    folder = tmp_path / "export"
    flags = ["--method", method] if method else []
    rc, out, err = _cli(capsys, "export", path, "--out", folder, *flags)
    assert rc == 0, err
    for name in ("Makefile", "README.md", "example.c"):
        assert (folder / name).is_file()
    got = _build_and_run(folder)

    npz = tmp_path / "ref.npz"
    rc, out, err = _cli(capsys, "simulate", path, "-o", npz, "--json", *flags)
    assert rc == 0, err
    summary = json.loads(out)
    assert got["nfev"] == summary["nfev"]
    assert got["t_end"] == summary["t_end"]
    ref = np.load(npz)
    assert got["t_end"] == float(ref["t"][-1])
    compared = 0
    for name in ref.files:
        if ref[name].ndim == 0 or name in ("t",) or name.startswith("integral_"):
            continue  # metadata; the integrals of an integrable case are computed in Python
        want = np.atleast_1d(ref[name][-1])
        have = np.atleast_1d(np.asarray(got[name], dtype=float))
        assert have.shape == want.shape, name
        assert np.all(np.abs(have - want) <= 1e-12 * np.maximum(1.0, np.abs(want))), name
        compared += 1
    assert compared == len([k for k in got if k not in ("t_end", "nfev")]) == 10


def test_export_readme_names_state_params_and_init_map(tmp_path, capsys):
    folder = tmp_path / "export"
    rc, _, err = _cli(capsys, "export", _scene(tmp_path, "reduced"), "--out", folder)
    assert rc == 0, err
    readme = (folder / "README.md").read_text(encoding="utf-8")
    desc = json.loads((folder / "heavy_top_reduced.json").read_text(encoding="utf-8"))
    for name in desc["states"] + desc["params"] + desc["outputs"]:
        assert f"`{name}`" in readme
    for key in ("body.I1", "gravity.M", "initial.beta", "initial.rates_given"):
        assert f"`{key}`" in readme
    assert "rates_given = 1" in readme and "written by the init map" in readme
    # The NumPy module is the model's own, importable without derive.
    ns: dict = {}
    exec(compile((folder / "heavy_top_reduced.py").read_text(encoding="utf-8"), "m", "exec"), ns)
    assert ns["STATE_NAMES"] == tuple(desc["states"])
    # Nothing in the folder points at the machine it was made on.
    for path in folder.iterdir():
        assert str(tmp_path) not in path.read_text(encoding="utf-8"), path.name


def test_export_refuses_a_folder_that_is_not_empty(tmp_path, capsys):
    folder = tmp_path / "taken"
    folder.mkdir()
    (folder / "mine.txt").write_text("keep me")
    rc, out, err = _cli(capsys, "export", SCENES / "reference_top.toml", "--out", folder)
    assert rc == 2
    assert err.count("\n") == 1 and err.startswith(f"error: {folder}: --out: ")
    assert sorted(p.name for p in folder.iterdir()) == ["mine.txt"]
    assert (folder / "mine.txt").read_text() == "keep me"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["taken"]  # no temporary left


def test_export_fills_an_empty_folder(tmp_path, capsys):
    folder = tmp_path / "empty"
    folder.mkdir()
    rc, _, err = _cli(capsys, "export", SCENES / "reference_top.toml", "--out", folder)
    assert rc == 0, err
    assert (folder / "example.c").is_file()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["empty"]


@pytest.mark.parametrize("case", ["scene-as-out", "missing-scene", "scipy-method", "unknown-method",
                                  "both-targets", "no-target"])
def test_export_bad_input_is_exit_2_and_writes_nothing(tmp_path, capsys, case):
    scene = tmp_path / "top.toml"
    text = (SCENES / "reference_top.toml").read_text(encoding="utf-8")
    scene.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    argv = {
        "scene-as-out": ["export", scene, "--out", scene],
        "missing-scene": ["export", tmp_path / "nope.toml", "--out", out],
        "scipy-method": ["export", scene, "--out", out, "--method", "scipy-rk45"],
        "unknown-method": ["export", scene, "--out", out, "--method", "rk5"],
        "both-targets": ["export", scene, "--out", out, "--fmu", tmp_path / "x.fmu"],
        "no-target": ["export", scene],
    }[case]
    rc, stdout, err = _cli(capsys, *argv)
    assert rc == 2
    assert err.startswith("error: ") and err.count("\n") == 1, err
    assert "Traceback" not in err
    if case in ("scipy-method", "unknown-method"):
        assert "method" in err
    assert scene.read_text(encoding="utf-8") == text
    assert sorted(p.name for p in tmp_path.iterdir()) == ["top.toml"]


def test_export_of_a_failing_scene_is_exit_3_and_writes_nothing(tmp_path, capsys):
    scene = tmp_path / "top.toml"
    text = (SCENES / "reference_top.toml").read_text(encoding="utf-8")
    scene.write_text(text + "max_steps = 5\n", encoding="utf-8")
    rc, _, err = _cli(capsys, "export", scene, "--out", tmp_path / "out")
    assert rc == 3
    assert err.startswith("error: ") and err.count("\n") == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["top.toml"]
