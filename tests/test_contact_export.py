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
from tests.compile_once import kept_fmu, make_once

ROOT = Path(__file__).resolve().parent.parent
CONTACT = ROOT / "scenes" / "contact"
STRICT = "CFLAGS=-std=c99 -O2 -Wall -Wextra -Werror -pedantic"

# The examples build with the Makefile's -O2, and simulate must agree with them as a user builds
# it: the suite's -O0 kernels differ in last bits (libm's pow for a square, not x*x), which a
# run through several touch events carries past 1e-12.
pytestmark = [pytest.mark.skipif(shutil.which("make") is None, reason="needs make"), pytest.mark.optimised]


def _cli(capsys, *argv) -> tuple[int, str, str]:
    rc = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return rc, out, err


#: Variants of the example scenes that take the driver's other switch rules: a round peg with
#: little friction on a thin peg sticks and slips in turn; one knocked into the air lands
#: (the impact law) and lifts off again.
VARIANTS = {
    "stick_slip": ("round_peg_top", {"mu = 0.3": "mu = 0.05", "radius = 0.005": "radius = 0.002"}),
    "knocked": ("round_peg_top", {"gamma_dot = 150.0": "gamma_dot = 150.0\nbeta_dot = 40.0"}),
}


def _short(tmp_path: Path, name: str, t_end: float, samples: int) -> Path:
    """The example scene ``name`` (or a :data:`VARIANTS` of one) with a shorter run ([simulate]
    is the last table of each)."""
    base, edits = VARIANTS.get(name, (name, {}))
    text = (CONTACT / f"{base}.toml").read_text(encoding="utf-8")
    for old, new in edits.items():
        assert old in text
        text = text.replace(old, new)
    head, _, _ = text.partition("[simulate]")
    path = tmp_path / f"{name}.toml"
    path.write_text(head + f"[simulate]\nt_end = {t_end}\nsamples = {samples}\n", encoding="utf-8")
    return path


@pytest.mark.parametrize("name, t_end, samples", [
    ("round_peg_top", 1.0, 101),     # exact Coulomb: slides, then a stick event into rolling
    pytest.param("rolling_sphere", 0.5, 51, marks=pytest.mark.slow),     # rolling: v = -w x a
    pytest.param("tippe_top", 0.3, 31, marks=pytest.mark.slow),          # viscous sliding on a sphere with Jellett's integral
    pytest.param("frictionless_top", 0.5, 51, marks=pytest.mark.slow),   # a point on a frictionless plane
    pytest.param("euler_disk", 0.3, 31, marks=pytest.mark.slow),         # a disc's rim, rolling
    pytest.param("stick_slip", 0.5, 51, marks=pytest.mark.slow),         # slip and stick events in turn
    ("knocked", 0.1, 41),            # landing and lift-off events, the impact law
    ("tippe_top_stem", 0.7, 71),     # touch events: onto the stem, back to the ball, the stem again
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
    build = make_once(folder, STRICT)
    assert build.returncode == 0, build.stderr
    run = subprocess.run([str(folder / "example")], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    lines = run.stdout.splitlines()
    assert len(lines) == 1
    got = json.loads(lines[0])

    npz = tmp_path / "ref.npz"
    rc, out, err = _cli(capsys, "simulate", path, "-o", npz, "--json")
    assert rc == 0, err
    # simulate runs a frictionless axisymmetric top in its reduced formulation (p_alpha, p_gamma
    # as parameters), the export the full one: the two agree to the integration's error
    same_path = json.loads(out)["formulation"] != "contact-reduced"
    rtol = 1e-12 if same_path else 1e-8
    if same_path:
        assert got["nfev"] == json.loads(out)["nfev"]
    ref = np.load(npz)
    assert got["t_end"] == float(ref["t"][-1])
    assert got["switches"] == len(ref["switch_t"])
    if name in VARIANTS:
        assert got["switches"] >= 4  # the rules the variant is there for did run
    if name == "round_peg_top":  # the example reports its stick switch: it ends rolling
        assert got["switches"] >= 1 and got["phase"] == "roll"
    if name == "tippe_top_stem":  # the spheres changed roles, and the run ends on the stem
        assert {"stem", "ball"} <= set(map(str, ref["switch_event"]))
        assert str(ref["switch_event"][-1]) == "stem"
    assert got["phase"] == str(ref["phase"][-1])
    compared = 0
    for key, value in got.items():
        if key in ("t_end", "nfev", "switches", "phase"):
            continue
        want = np.atleast_1d(ref[key][-1])
        have = np.atleast_1d(np.asarray(value, dtype=float))
        assert have.shape == want.shape, key
        assert np.all(np.abs(have - want) <= rtol * np.maximum(1.0, np.abs(want))), key
        compared += 1
    assert compared >= 13


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


# ---------------------------------------------------------------------------------------------
# the FMU (co-simulation)

@pytest.fixture(scope="module")
def peg_fmu(tmp_path_factory):
    """The round-peg top's FMU on a short run (exact Coulomb: it slides, sticks and rolls), kept
    between runs for its exact inputs (``compile_once.kept_fmu``), and its scene."""
    pytest.importorskip("fmpy")
    tmp = tmp_path_factory.mktemp("cfmu")
    scene = _short(tmp, "round_peg_top", 0.5, 51)

    def export(kept_scene: Path, path: Path) -> None:
        assert main(["export", str(kept_scene), "--fmu", str(path)]) == 0

    return kept_fmu("peg", scene.read_text(encoding="utf-8"), export), scene


_COLUMNS = ("alpha", "beta", "gamma", "omega1", "omega2", "omega3", "axis_x", "axis_z", "energy",
            "com_x", "com_y", "com_z", "contact_x", "normal_force", "slip_speed",
            "integral_jellett")


def _columns(res) -> dict:
    return {"alpha": res.alpha, "beta": res.beta, "gamma": res.gamma, "omega1": res.omega[:, 0],
            "omega2": res.omega[:, 1], "omega3": res.omega[:, 2], "axis_x": res.axis[:, 0],
            "axis_z": res.axis[:, 2], "energy": res.energy, "com_x": res.com[:, 0],
            "com_y": res.com[:, 1], "com_z": res.com[:, 2], "contact_x": res.contact[:, 0],
            "normal_force": res.normal_force, "slip_speed": res.slip_speed,
            "integral_jellett": res.integrals["jellett"]}


def _cosimulate(path, scene, start_values=None):
    import fmpy

    import derive

    res = derive.simulate(scene)
    got = fmpy.simulate_fmu(str(path), fmi_type="CoSimulation", stop_time=float(res.t[-1]),
                            output_interval=float(res.t[1] - res.t[0]),
                            start_values=start_values or {},
                            output=[*_COLUMNS, "phase", "switches"])
    assert len(got) == len(res.t)
    return got, res


def test_contact_fmu_validates_and_is_co_simulation_only(peg_fmu):
    import fmpy
    from fmpy.validation import validate_fmu

    path, _ = peg_fmu
    assert validate_fmu(str(path)) == []
    md = fmpy.read_model_description(str(path))
    assert md.coSimulation and not md.modelExchange
    params = {v.name: float(v.start) for v in md.modelVariables if v.causality == "parameter"}
    assert params["contact.mu"] == 0.3 and params["contact.offset"] == -0.01
    assert params["initial.beta"] == 0.5 and params["initial.omega3"] == 150.0
    assert "contact.regularization" not in params  # exact Coulomb reads no epsilon
    with __import__("zipfile").ZipFile(path) as zf:
        names = set(zf.namelist())
    assert {"sources/fmu.c", "sources/contact_run.inc", "sources/NOTICE.md"} <= names


def test_contact_fmu_cosimulation_follows_derive_simulate(peg_fmu):
    path, scene = peg_fmu
    got, res = _cosimulate(path, scene)
    # Each communication step restarts the step size from the FMU's state: the trajectories
    # agree to the tolerance's order (rtol 1e-10), and the phases and switches are the same.
    for name, want in _columns(res).items():
        scale = max(1.0, float(np.max(np.abs(want))))
        assert np.max(np.abs(got[name] - want)) <= 1e-8 * scale, name
    codes = {"slide": 0, "roll": 1, "flight": 2}
    assert list(got["phase"]) == [codes[str(p)] for p in res.phase]
    assert got["switches"][-1] == len(res.switches) >= 1


def test_contact_fmu_start_values_change_the_start(peg_fmu):
    from derive.sim.reader import read_toml

    path, scene = peg_fmu
    data = read_toml(str(scene))
    data["initial"] = {"beta": 0.3, "omega": [0.0, 0.0, 120.0]}
    got, res = _cosimulate(path, data, {"initial.beta": 0.3, "initial.omega3": 120.0})
    assert abs(got["beta"][0] - 0.3) < 1e-15
    for name, want in _columns(res).items():
        scale = max(1.0, float(np.max(np.abs(want))))
        assert np.max(np.abs(got[name] - want)) <= 1e-8 * scale, name


def test_contact_fmu_of_the_tippe_top_with_its_stem_changes_spheres_as_simulate_does(tmp_path):
    pytest.importorskip("fmpy")
    import fmpy

    scene = _short(tmp_path, "tippe_top_stem", 0.7, 71)

    def export(kept_scene: Path, fmu: Path) -> None:
        assert main(["export", str(kept_scene), "--fmu", str(fmu)]) == 0

    path = kept_fmu("stem", scene.read_text(encoding="utf-8"), export)  # (kept for its exact inputs)
    md = fmpy.read_model_description(str(path))
    params = {v.name: float(v.start) for v in md.modelVariables if v.causality == "parameter"}
    assert params["contact.stem.radius"] == 0.005 and params["contact.stem.offset"] == 0.016
    got, res = _cosimulate(path, scene)
    for name, want in _columns(res).items():
        scale = max(1.0, float(np.max(np.abs(want))))
        assert np.max(np.abs(got[name] - want)) <= 1e-8 * scale, name
    codes = {"slide": 0, "roll": 1, "flight": 2}
    assert list(got["phase"]) == [codes[str(p)] for p in res.phase]
    assert [s.event for s in res.switches] == ["stem", "ball", "stem"]
    assert got["switches"][-1] == len(res.switches)
