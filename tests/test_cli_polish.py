"""Command-line polish: `--version`, help text on every flag, `simulate --h / --max-steps`
overriding the scene, and the one-line `simulate --json` summary."""
from __future__ import annotations

import argparse
import json
import re

import numpy as np
import pytest

from derive import cli

SCENE = """\
title = "cli test: free symmetric body"
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
t_end = 0.1
samples = 11
"""


@pytest.fixture()
def scene(tmp_path):
    path = tmp_path / "scene.toml"
    path.write_text(SCENE)
    return path


def _run(capsys, *argv):
    code = cli.main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def test_version_comes_from_the_package(capsys):
    code, out, err = _run(capsys, "--version")
    assert code == 0 and err == ""
    assert out.strip() == f"derive {cli.version()}"
    # The installed metadata (pyproject.toml reads derive.__version__); an editable install made
    # before a version bump may lag, so only the form is checked here -- tests/test_wheel.py
    # checks the value of a fresh install.
    assert re.fullmatch(r"\d+(\.\d+)*([a-z]+\d*)?(\.dev\d+)?", cli.version())


def _subparsers(p: argparse.ArgumentParser):
    for action in p._actions:
        if isinstance(action, argparse._SubParsersAction):
            yield from action.choices.items()


def test_every_flag_of_every_subcommand_has_help():
    p = cli.parser()
    subs = dict(_subparsers(p))
    assert {"generate", "verify", "simulate", "bench"} <= set(subs)
    missing = []
    for name, sub in [("derive", p), *subs.items()]:
        for action in sub._actions:
            if isinstance(action, argparse._SubParsersAction):
                continue
            if not action.help or action.help == argparse.SUPPRESS:
                missing.append(f"{name} {'/'.join(action.option_strings) or action.dest}")
    assert not missing, f"flags without help text: {missing}"


def test_h_flag_overrides_the_fixed_step(capsys, scene):
    nfev = {}
    for h in (1e-3, 5e-4):
        code, out, err = _run(capsys, "simulate", scene, "--method", "rk4", "--h", h, "--json")
        assert code == 0, err
        nfev[h] = json.loads(out)["nfev"]
    # RK4: four evaluations per step, t_end / h steps.
    assert nfev == {1e-3: 4 * 100, 5e-4: 4 * 200}


def test_max_steps_flag_is_the_step_budget(capsys, scene, tmp_path):
    out_npz = tmp_path / "out.npz"
    # (dop853: its steps are many; a Taylor step may span the whole run)
    code, out, err = _run(capsys, "simulate", scene, "--method", "dop853", "--max-steps", 3, "-o", out_npz)
    assert code == 3, err
    assert err.startswith("error: ") and err.count("\n") == 1 and "max_steps" in err
    assert not out_npz.exists()
    # A fixed-step run that would need more steps is refused before it starts (bad input).
    code, out, err = _run(capsys, "simulate", scene, "--method", "rk4", "--h", 1e-3, "--max-steps", 99)
    assert code == 2 and err.count("\n") == 1 and "simulate.max_steps" in err and "100 steps" in err
    code, out, err = _run(capsys, "simulate", scene, "--method", "rk4", "--h", 1e-3, "--max-steps", 100)
    assert code == 0, err


@pytest.mark.parametrize("flag, value", [("--max-steps", "many"), ("--h", "small"), ("--rtol", "tight")])
def test_bad_flag_values_are_one_line_errors(capsys, scene, flag, value):
    code, out, err = _run(capsys, "simulate", scene, flag, value)
    assert code == 2
    assert err.startswith("error: derive simulate: ") and err.count("\n") == 1 and flag in err


def test_json_summary_is_one_line_matching_the_outputs(capsys, scene, tmp_path):
    npz = tmp_path / "out.npz"
    code, out, err = _run(capsys, "simulate", scene, "-o", npz, "--json")
    assert code == 0, err
    assert out.count("\n") == 1
    s = json.loads(out)
    data = np.load(npz)
    E = data["energy"]
    assert s["method"] == str(data["method"]) and s["formulation"] == str(data["formulation"])
    assert s["nfev"] == int(data["nfev"]) > 0
    assert s["samples"] == len(data["t"]) == 11 and s["t_end"] == 0.1
    assert s["energy_drift"] == float(np.max(np.abs(E - E[0])) / abs(E[0]))
    assert s["energy_drift_relative"] is True
    assert s["rtol"] == 1e-10 and s["atol"] == 1e-12
    assert s["wall_time"] > 0
    assert s["outputs"] == {"npz": str(npz), "png": None}


def test_generate_out_never_deletes_files_it_did_not_generate(capsys, tmp_path, monkeypatch):
    from derive import generate as codegen

    files = {"c/m.c": "int x;\n", "m.md": "# m\n"}
    monkeypatch.setattr(codegen, "generate_all", lambda **kw: dict(files))
    out = tmp_path / "out"
    out.mkdir()
    (out / "notes.txt").write_text("mine")
    code, _, err = _run(capsys, "generate", "--out", out)
    assert code == 2 and err.count("\n") == 1 and "notes.txt" in err
    assert (out / "notes.txt").read_text() == "mine" and not (out / "m.md").exists()
    (out / "notes.txt").unlink()
    code, stdout, err = _run(capsys, "generate", "--out", out)
    assert code == 0, err
    assert (out / "c" / "m.c").read_text() == "int x;\n"
