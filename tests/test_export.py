"""`derive export`: the scene's model as a self-contained C99 folder and as an FMI 2.0 FMU.

The folder's ``./example`` is built with the C compiler under the strictest warnings
(``-std=c99 -Wall -Wextra -Werror -pedantic``) and must print what ``derive simulate --json``
and its output file say: the same nfev, the outputs at the last sample to 1e-12. The FMU is
validated by FMPy and its co-simulation compared with derive.simulate.
"""
from __future__ import annotations

import contextlib
import io
import json
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from derive.cli import main
from derive.export import fmi
from tests.compile_once import kept_fmu, make_once

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
    build = make_once(folder, STRICT)
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


def test_export_carries_the_shared_runtime_and_the_notice_of_what_it_ported(tmp_path, capsys):
    """A Taylor export holds the shared runtime (compiled once on its own by the Makefile,
    under strict warnings) and derive_libm.h, the fdlibm port, with Sun's notice in the file
    and in NOTICE.md."""
    folder = tmp_path / "export"
    rc, out, err = _cli(capsys, "export", _scene(tmp_path, "reference_top"), "--out", folder,
                        "--method", "taylor")
    assert rc == 0, err
    sun = "Copyright (C) 1993 by Sun Microsystems, Inc. All rights reserved."
    for name in ("derive_libm.h", "NOTICE.md"):
        text = (folder / name).read_text(encoding="utf-8")
        assert sun in text and "provided that this notice" in text, name
    assert "derive_runtime.o" in (folder / "Makefile").read_text(encoding="utf-8")
    _build_and_run(folder)
    assert (folder / "derive_runtime.o").is_file()


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


# ---------------------------------------------------------------------------------------------
# the FMU

try:
    import fmpy  # the test extra
except ImportError:  # pragma: no cover - the folder tests above still run
    fmpy = None


#: The warnings the FMU's binary is built under in the tests (derive adds -std=c99 -O2).
STRICT_WARNINGS = ("-Wall", "-Wextra", "-Werror", "-pedantic")


class _StrictBuildFailed(Exception):
    """The FMU's binary did not compile under :data:`STRICT_WARNINGS` (the message: why)."""


@pytest.fixture(scope="module")
def top_fmu_build(tmp_path_factory):
    """(path, why the strict build failed or None): the reference top's FMU (dop853,
    heavy_top), built for the tests below (:func:`kept_fmu`), its binary compiled from its
    sources under :data:`STRICT_WARNINGS` (which change no code); should that fail, built as
    derive builds it for the other tests. The scene names the Euler-angle formulation and
    DOP853: auto would now take the cheaper reduced-u model and the Taylor method, and these
    tests are about the heavy_top's FMU (its states beta, beta_dot, ...) with DOP853."""
    pytest.importorskip("fmpy")
    text = (SCENES / "reference_top.toml").read_text(encoding="utf-8")
    pinned = '[simulate]\nformulation = "euler-angles"\nmethod = "dop853"'
    text = text.replace("[simulate]", pinned, 1)
    assert "euler-angles" in text
    strict = [*fmi.compiler(), *STRICT_WARNINGS]

    def export_strictly(scene: Path, path: Path) -> None:
        err = io.StringIO()
        with pytest.MonkeyPatch.context() as patch, contextlib.redirect_stderr(err):
            patch.setattr(fmi, "compiler", lambda: strict)
            rc = main(["export", str(scene), "--fmu", str(path)])
        if rc != 0:
            raise _StrictBuildFailed(err.getvalue() or f"exit {rc}")

    try:
        return kept_fmu("top", text, export_strictly, strict), None
    except _StrictBuildFailed as exc:
        tmp = tmp_path_factory.mktemp("fmu")
        scene, path = tmp / "reference_top.toml", tmp / "top.fmu"
        scene.write_text(text, encoding="utf-8")
        assert main(["export", str(scene), "--fmu", str(path)]) == 0
        return path, str(exc)


@pytest.fixture(scope="module")
def top_fmu(top_fmu_build):
    return top_fmu_build[0]


def _cosimulate(path: Path, scene, start_values=None):
    """The FMU's co-simulation on the scene's output times, and derive.simulate's result."""
    import derive

    res = derive.simulate(scene)
    dt = float(res.t[1] - res.t[0])
    got = fmpy.simulate_fmu(str(path), fmi_type="CoSimulation", stop_time=float(res.t[-1]),
                            output_interval=dt, start_values=start_values or {},
                            output=["alpha", "beta", "gamma", "omega1", "omega2", "omega3",
                                    "axis_x", "axis_y", "axis_z", "energy", "p_alpha", "L3"])
    assert len(got) == len(res.t)
    assert np.allclose(got["time"], res.t, rtol=0, atol=1e-12)
    return got, res


def _columns(res):
    return {"alpha": res.alpha, "beta": res.beta, "gamma": res.gamma, "omega1": res.omega[:, 0],
            "omega2": res.omega[:, 1], "omega3": res.omega[:, 2], "axis_x": res.axis[:, 0],
            "axis_y": res.axis[:, 1], "axis_z": res.axis[:, 2], "energy": res.energy,
            "p_alpha": res.p_alpha, "L3": res.L[:, 2]}


def test_fmu_validates_with_no_problem(top_fmu):
    from fmpy.validation import validate_fmu

    assert validate_fmu(str(top_fmu)) == []
    with __import__("zipfile").ZipFile(top_fmu) as zf:
        names = set(zf.namelist())
    assert "modelDescription.xml" in names and "binaries/linux64/heavy_top_dop853.so" in names
    assert {"sources/fmu.c", "sources/fmi2Functions.h"} <= names


def test_fmu_names_parameters_as_the_scene_and_outputs_as_the_output_file(top_fmu):
    md = fmpy.read_model_description(str(top_fmu))
    assert md.fmiVersion == "2.0" and md.modelExchange and md.coSimulation
    params = {v.name: v for v in md.modelVariables if v.causality == "parameter"}
    scene = {"body.I1": 1.0, "body.I3": 0.5, "gravity.M": 1.0, "gravity.g": 1.0, "gravity.l": 1.0,
             "initial.beta": 0.8, "initial.alpha_dot": -0.4, "initial.gamma_dot": 6.0,
             "simulate.rtol": 1e-10, "simulate.atol": 1e-12}
    for name, value in scene.items():
        assert float(params[name].start) == value, name
    assert params["initial.rates_given"].type == "Boolean"
    outputs = [v.name for v in md.modelVariables if v.causality == "output"]
    desc = json.loads((ROOT / "generated" / "models" / "heavy_top.json").read_text())
    assert outputs == desc["outputs"]
    assert {"beta", "energy", "axis_x", "omega1"} <= set(outputs)
    states = [v.name for v in md.modelVariables if v.name.startswith("state.")]
    assert states == [f"state.{s}" for s in desc["states"]]


def test_fmu_cosimulation_follows_derive_simulate(top_fmu):
    got, res = _cosimulate(top_fmu, SCENES / "reference_top.toml")
    # Each communication step restarts dop853 at rtol 1e-10 from the FMU's state: the
    # trajectories agree to the tolerance's order, not bit for bit.
    for name, want in _columns(res).items():
        scale = max(1.0, float(np.max(np.abs(want))))
        assert np.max(np.abs(got[name] - want)) <= 1e-8 * scale, name


def test_fmu_start_values_rerun_the_init_map(top_fmu):
    from derive.sim.scene import load_scene

    scene = load_scene(SCENES / "reference_top.toml").to_dict()
    scene["initial"].update(beta=0.5, gamma_dot=4.0)
    scene["simulate"]["t_end"], scene["simulate"]["samples"] = 2.0, 201
    got, res = _cosimulate(top_fmu, scene, {"initial.beta": 0.5, "initial.gamma_dot": 4.0})
    for name, want in _columns(res).items():
        scale = max(1.0, float(np.max(np.abs(want))))
        assert np.max(np.abs(got[name] - want)) <= 1e-8 * scale, name


def test_fmu_model_exchange_integrates_the_right_hand_side(top_fmu):
    # FMPy's own integrator (CVODE, BDF) on the FMU's derivatives: an independent integration.
    import derive

    res = derive.simulate(SCENES / "reference_top.toml", t_end=3.0, samples=31)
    got = fmpy.simulate_fmu(str(top_fmu), fmi_type="ModelExchange", stop_time=3.0,
                            output_interval=0.1, relative_tolerance=1e-10,
                            output=["beta", "energy", "state.beta", "der(state.beta)"])
    t = got["time"]
    beta = np.interp(t, res.t, res.beta)  # CVODE reports at its own event-free grid
    assert np.max(np.abs(got["beta"] - beta)) < 1e-6
    assert np.max(np.abs(got["energy"] - res.energy[0])) < 1e-6
    assert np.allclose(got["state.beta"], got["beta"], atol=1e-12)  # no pole passage here


def test_fmu_sources_compile_under_strict_warnings(top_fmu_build):
    """The binary in the FMU was compiled from the sources it carries (``fmu.c``, which
    includes the rest) by derive's own command with -Wall -Wextra -Werror -pedantic added."""
    import zipfile

    path, problem = top_fmu_build
    assert problem is None, problem
    with zipfile.ZipFile(path) as zf:
        names = set(zf.namelist())
    assert "sources/fmu.c" in names and any(n.startswith("binaries/") for n in names)


@pytest.mark.slow
@pytest.mark.parametrize("scene, method, tol", [
    ("tennis_racket", "rk4", 1e-9),   # fixed steps split each interval as the driver does
    ("reduced", None, 1e-8),          # derived parameters, pole check 2
    ("kovalevskaya_top", "splitting4", 1e-9),
])
def test_fmu_cosimulation_of_other_models(tmp_path, capsys, scene, method, tol):
    pytest.importorskip("fmpy")
    from fmpy.validation import validate_fmu

    path = _scene(tmp_path, scene)
    fmu = tmp_path / "x.fmu"
    rc, _, err = _cli(capsys, "export", path, "--fmu", fmu, *(["--method", method] if method else []))
    assert rc == 0, err
    assert validate_fmu(str(fmu)) == []
    import derive

    res = derive.simulate(path, method=method)
    got = fmpy.simulate_fmu(str(fmu), fmi_type="CoSimulation", stop_time=float(res.t[-1]),
                            output_interval=float(res.t[1] - res.t[0]),
                            output=["alpha", "beta", "gamma", "energy", "omega3"])
    for name, want in {"alpha": res.alpha, "beta": res.beta, "gamma": res.gamma,
                       "energy": res.energy, "omega3": res.omega[:, 2]}.items():
        scale = max(1.0, float(np.max(np.abs(want))))
        assert np.max(np.abs(got[name] - want)) <= tol * scale, name


@pytest.mark.parametrize("case", ["not-fmu", "the-scene"])
def test_fmu_bad_path_is_exit_2(tmp_path, capsys, case):
    scene = tmp_path / "top.toml"
    text = (SCENES / "reference_top.toml").read_text(encoding="utf-8")
    scene.write_text(text, encoding="utf-8")
    target = tmp_path / "top.zip" if case == "not-fmu" else scene
    rc, _, err = _cli(capsys, "export", scene, "--fmu", target)
    assert rc == 2
    assert err.startswith("error: ") and err.count("\n") == 1, err
    assert scene.read_text(encoding="utf-8") == text
    assert sorted(p.name for p in tmp_path.iterdir()) == ["top.toml"]
