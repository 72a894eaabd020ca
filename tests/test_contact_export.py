"""`derive export` of tops on a table: the folder builds under strict warnings and its example
prints what `derive simulate` gives; the FMU validates and its co-simulation follows it.

The exported driver (``generated/contact/contact_run.inc``) runs the same phase loop with the
same switch rules as :mod:`derive.contact.phases`, so the example's numbers are the output
file's last row (the same rhs evaluations, the same switches).
"""
from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from derive.cli import main

ROOT = Path(__file__).resolve().parent.parent
CONTACT = ROOT / "scenes" / "contact"
STRICT = "CFLAGS=-std=c99 -O2 -Wall -Wextra -Werror -pedantic"

pytestmark = pytest.mark.skipif(shutil.which("make") is None, reason="needs make")


def _cli(capsys, *argv) -> tuple[int, str, str]:
    rc = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return rc, out, err


def _short(tmp_path: Path, name: str, t_end: float, samples: int) -> Path:
    """The example scene ``name`` with a shorter run ([simulate] is the last table of each)."""
    text = (CONTACT / f"{name}.toml").read_text(encoding="utf-8")
    head, _, _ = text.partition("[simulate]")
    path = tmp_path / f"{name}.toml"
    path.write_text(head + f"[simulate]\nt_end = {t_end}\nsamples = {samples}\n", encoding="utf-8")
    return path


@pytest.mark.parametrize("name, t_end, samples", [
    ("round_peg_top", 1.0, 101),     # exact Coulomb: slides, then a stick event into rolling
    ("rolling_sphere", 0.5, 51),     # rolling: v = -w x a
    ("tippe_top", 0.3, 31),          # viscous sliding on a sphere with Jellett's integral
])
def test_contact_example_prints_what_simulate_gives(tmp_path, capsys, name, t_end, samples):
    path = _short(tmp_path, name, t_end, samples)
    folder = tmp_path / "export"
    rc, out, err = _cli(capsys, "export", path, "--out", folder)
    assert rc == 0, err
    for made in ("Makefile", "README.md", "NOTICE.md", "example.c", "contact_run.inc",
                 "contact_phase_loop.inc"):
        assert (folder / made).is_file(), made
    assert "SciPy Developers" in (folder / "NOTICE.md").read_text(encoding="utf-8")
    build = subprocess.run(["make", "-s", "-C", str(folder), STRICT], capture_output=True, text=True)
    assert build.returncode == 0, build.stderr
    run = subprocess.run([str(folder / "example")], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    lines = run.stdout.splitlines()
    assert len(lines) == 1
    got = json.loads(lines[0])

    npz = tmp_path / "ref.npz"
    rc, out, err = _cli(capsys, "simulate", path, "-o", npz, "--json")
    assert rc == 0, err
    assert got["nfev"] == json.loads(out)["nfev"]
    ref = np.load(npz)
    assert got["t_end"] == float(ref["t"][-1])
    assert got["switches"] == len(ref["switch_t"])
    assert got["phase"] == str(ref["phase"][-1])
    compared = 0
    for key, value in got.items():
        if key in ("t_end", "nfev", "switches", "phase"):
            continue
        want = np.atleast_1d(ref[key][-1])
        have = np.atleast_1d(np.asarray(value, dtype=float))
        assert have.shape == want.shape, key
        assert np.all(np.abs(have - want) <= 1e-12 * np.maximum(1.0, np.abs(want))), key
        compared += 1
    assert compared >= 13


def test_round_peg_example_reports_its_stick_switch(tmp_path, capsys):
    path = _short(tmp_path, "round_peg_top", 1.0, 11)
    folder = tmp_path / "export"
    assert _cli(capsys, "export", path, "--out", folder)[0] == 0
    assert subprocess.run(["make", "-s", "-C", str(folder), "example"], capture_output=True).returncode == 0
    got = json.loads(subprocess.run([str(folder / "example")], capture_output=True, text=True).stdout)
    assert got["switches"] >= 1 and got["phase"] == "roll"


def test_contact_export_refuses_the_python_stepper(tmp_path, capsys):
    folder = tmp_path / "export"
    rc, out, err = _cli(capsys, "export", CONTACT / "round_peg_top.toml", "--out", folder,
                        "--method", "scipy-dop853")
    assert rc == 2
    assert "simulate.method" in err and len(err.strip().splitlines()) == 1
    assert not folder.exists()


def test_contact_export_of_bad_input_is_exit_2_naming_the_key(tmp_path, capsys):
    bad = tmp_path / "bad.toml"
    text = (CONTACT / "round_peg_top.toml").read_text(encoding="utf-8")
    bad.write_text(text.replace("mu = 0.3", "mu = -0.3"), encoding="utf-8")
    folder = tmp_path / "export"
    rc, out, err = _cli(capsys, "export", bad, "--out", folder)
    assert rc == 2 and "contact.mu" in err
    assert not folder.exists()
