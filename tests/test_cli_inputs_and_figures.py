"""Inputs of the wrong shape, output extensions, overrides, figures and notes on the command line.

1. Validation: a value of the wrong shape where a vector belongs (a 0-d array, a NumPy scalar,
   an array of another shape, a ragged list, a string, booleans) is a SceneError naming the key,
   never a raw TypeError; the suite's Hypothesis settings are deterministic.
5. Outputs mean what their extension says: ``-o`` .npz or .csv, ``--plot`` .png, .pdf or .svg;
   anything else is exit 2 naming the flag and the allowed extensions, before any work.
6. ``derive simulate --t-end / --samples`` override the scene, validated like the scene keys.
9. Figures that do not mislead: the trajectory's ω̃₃ axis, the sweep map's title, labels and
   NaN points, the work–precision plot's series and legend (matplotlib objects inspected).
10. Slow steps say so: one ``note:`` line on stderr, never on stdout.

The command line runs in a real process (``python -m derive``) where the exit status, the
streams and the files are what is checked; in-process (``derive.cli.main``) where a slow step is
replaced by a stub (``derive.runtime.catalogue`` and ``derive.lecture.analysis`` are imported for that).
"""
from __future__ import annotations

import copy
import subprocess
import sys

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

import derive
from small_scenes import HEAVY_TOP

# A cheap free asymmetric body given by omega, and a cheap heavy top whose centre of mass is a
# vector: the two vector keys of a scene.
FREE = {"body": {"I1": 1.0, "I2": 2.0, "I3": 2.5},
        "initial": {"alpha": 0.1, "beta": 1.0, "gamma": 0.2, "omega": [0.1, 3.0, 0.1]},
        "simulate": {"t_end": 0.05, "samples": 3}}
TOP = {"body": {"I1": 0.8, "I3": 0.3},
       "gravity": {"M": 0.5, "g": 9.81, "com": [0.0, 0.0, 0.05]},
       "initial": {"alpha": 0.0, "beta": 0.3, "gamma": 0.0, "gamma_dot": 20.0},
       "simulate": {"t_end": 0.05, "samples": 3}}
VECTORS = [(FREE, "initial", "omega"), (TOP, "gravity", "com")]


def derive_cli(*argv, cwd=None, env=None, timeout=120):
    """``python -m derive ARGV`` in a real process: the CompletedProcess (text streams)."""
    return subprocess.run([sys.executable, "-m", "derive", *map(str, argv)], capture_output=True,
                          text=True, cwd=cwd, env=env, timeout=timeout)


def with_value(base: dict, table: str, key: str, value) -> dict:
    scene = copy.deepcopy(base)
    scene[table][key] = value
    return scene


# --- 1. vectors of the wrong shape ------------------------------------------------------------

NOT_A_VECTOR = [
    np.array(2.0),                      # len() of a 0-d array raises
    np.array(2.0, dtype=object),
    np.float64(2.0), np.int64(3), np.bool_(True), 2.0, 3, True,
    np.array([[1.0, 2.0, 3.0]]), np.array([[1.0], [2.0], [3.0]]), np.zeros((3, 3)),
    np.array([1.0, 2.0]), np.array([1.0, 2.0, 3.0, 4.0]), np.array([]),
    np.array(["1", "2", "3"]), np.array([True, False, True]), np.array([1.0, np.nan, 3.0]),
    np.ma.masked_array([1.0, 2.0, 3.0], [0, 1, 0]),
    [[1.0, 2.0], 3.0, 4.0], [1.0, [2.0], 3.0], [np.array(1.0), 2.0, 3.0], [1.0, 2.0, "3"],
    [True, 1.0, 2.0], [1 + 0j, 2.0, 3.0], "abc", "1,2,3", b"abc", {"x": 1.0}, None, range(3),
    {1.0, 2.0, 3.0},
]


@pytest.mark.parametrize("base,table,key", VECTORS, ids=["omega", "com"])
@pytest.mark.parametrize("value", NOT_A_VECTOR, ids=repr)
def test_a_value_that_is_not_three_numbers_is_a_scene_error_naming_the_vector(base, table, key,
                                                                              value):
    with pytest.raises(derive.SceneError) as err:
        derive.simulate(with_value(base, table, key, value))
    message = str(err.value)
    assert message.startswith(f"<dict>: {table}.{key}: must be ") and "\n" not in message


@pytest.mark.parametrize("base,table,key", VECTORS, ids=["omega", "com"])
@pytest.mark.parametrize("value", [np.array([0.1, 3.0, 0.1]), (0.1, 3.0, 0.1),
                                   [np.float32(0.1), np.int64(3), 0.1],
                                   np.array([0.1, 3, 0.1], dtype=object)], ids=repr)
def test_three_reals_in_any_container_are_a_vector(base, table, key, value):
    res = derive.simulate(with_value(base, table, key, value))
    assert np.all(np.isfinite(res.beta))


def test_a_0d_array_for_a_scalar_key_names_the_key_and_shows_the_value():
    bad = copy.deepcopy(FREE)
    bad["simulate"]["samples"] = np.array(5)
    with pytest.raises(derive.SceneError, match=r"simulate\.samples: .*got a 0-d array \(5\)"):
        derive.simulate(bad)


def test_a_deeply_nested_list_is_shown_cut_not_a_recursion_error():
    deep = inner = []
    for _ in range(5000):
        inner.append([])
        inner = inner[0]
    with pytest.raises(derive.SceneError, match=r"initial\.omega: .*\[\[\[.*\.\.\."):
        derive.simulate(with_value(FREE, "initial", "omega", deep))


# Arrays of every small shape and several dtypes, and lists mixing arrays and scalars.
_arrays = hnp.arrays(dtype=st.sampled_from([np.float64, np.float32, np.int64, np.bool_, object,
                                            np.complex128, "U3"]),
                     shape=hnp.array_shapes(min_dims=0, max_dims=3, min_side=0, max_side=4),
                     elements=None, fill=st.nothing())
_items = st.one_of(st.floats(-10, 10), st.integers(-5, 5), st.booleans(), st.text(max_size=2),
                   st.none(), _arrays)
_shaped = st.one_of(_arrays, st.lists(_items, max_size=5), st.tuples(_items, _items, _items))


@settings(max_examples=120, deadline=None)
@given(st.sampled_from(VECTORS), _shaped)
def test_any_shape_where_a_vector_belongs_is_a_vector_or_a_scene_error(where, value):
    base, table, key = where
    try:
        res = derive.simulate(with_value(base, table, key, value))
    except derive.SceneError as err:
        assert f": {table}.{key}: " in str(err) and "\n" not in str(err)
    except derive.IntegrationError:
        pass  # three finite but absurd numbers (a centre of mass 1e300 m away) may be that
    else:
        arr = np.asarray(value, dtype=object)
        assert arr.shape == (3,)  # only a vector of three is taken
        assert np.all(np.isfinite(res.beta))


def test_the_suite_runs_hypothesis_deterministically_without_a_database():
    """A failing example found once must not be replayed from .hypothesis/ ever after (how a
    clone went red on its second run): no database; the same examples every run unless a seed
    asks to explore (tests/conftest.py)."""
    default = settings.get_profile("derive")
    assert default.database is None and default.derandomize
    explore = settings.get_profile("explore")
    assert explore.database is None and not explore.derandomize
    assert settings.default.database is None


# --- 5. outputs are what their extension says; 6. --t-end and --samples -------------------------

SCENE_TOML = HEAVY_TOP


@pytest.fixture
def scene(tmp_path):
    path = tmp_path / "top.toml"
    path.write_text(SCENE_TOML)
    return path


def run_in_process(capsys, *argv):
    """``derive.cli.main`` in this process: (exit status, stdout, stderr)."""
    from derive import cli

    code = cli.main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def listing(folder):
    return sorted(p.name for p in folder.iterdir())


@pytest.fixture
def small_figure(monkeypatch):
    """plots.figure replaced by a one-line figure: these tests are about the file format, and
    the real figure (seven panels, two in 3-D) takes a second or two to draw."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from derive.sim import plots

    def figure(res):
        fig, ax = plt.subplots(figsize=(2, 2))
        ax.plot(res.t, res.beta)
        return fig

    monkeypatch.setattr(plots, "figure", figure)


def test_csv_output_holds_the_npz_arrays_bit_for_bit_and_the_metadata(capsys, tmp_path, scene,
                                                                      small_figure):
    csv, npz, pdf = tmp_path / "out.csv", tmp_path / "out.npz", tmp_path / "out.pdf"
    code, _, err = run_in_process(capsys, "simulate", scene, "-o", csv, "--plot", pdf)
    assert code == 0, err
    assert run_in_process(capsys, "simulate", scene, "-o", npz)[0] == 0
    text = csv.read_text()
    assert not text.startswith("PK")  # not a zip (an npz) under a .csv name
    comments = [ln for ln in text.splitlines() if ln.startswith("#")]
    header = text.splitlines()[len(comments)].split(",")
    table = np.genfromtxt(csv, delimiter=",", names=True, skip_header=len(comments))
    with np.load(npz) as data:
        meta = {f"# {k}: {data[k].item()}" for k in data.files if data[k].ndim == 0}
        assert set(comments) == meta == {f"# method: {data['method']}",
                                         f"# formulation: {data['formulation']}",
                                         f"# nfev: {int(data['nfev'])}"}
        expected = []
        for k in data.files:
            a = data[k]
            if a.ndim == 1:
                expected.append((k, a))
            elif a.ndim == 2:
                names = [f"{k}_{c}" for c in "xyz"] if k == "axis" else [f"{k}{i + 1}" for i in range(3)]
                expected += [(n, a[:, i]) for i, n in enumerate(names)]
        assert header[0] == "t" and sorted(header) == sorted(n for n, _ in expected)
        assert {"omega1", "omega3", "axis_x", "axis_z", "energy", "beta"} <= set(header)
        for name, column in expected:
            np.testing.assert_array_equal(table[name], column, err_msg=name)
    assert pdf.read_bytes().startswith(b"%PDF-")


MAGIC = {"png": b"\x89PNG\r\n\x1a\n", "pdf": b"%PDF-", "svg": b"<?xml"}


@pytest.mark.parametrize("ext", ["png", "pdf", "svg", "PDF"])
def test_plot_is_written_in_the_format_its_extension_names(capsys, tmp_path, scene, ext,
                                                          small_figure):
    plot = tmp_path / f"out.{ext}"
    code, out, err = run_in_process(capsys, "simulate", scene, "--plot", plot)
    assert code == 0, err
    data = plot.read_bytes()
    assert data.startswith(MAGIC[ext.lower()])
    if ext.lower() == "svg":
        assert b"<svg" in data[:2000]


@pytest.mark.parametrize("flag, name, allowed", [
    ("-o", "out.txt", ".npz, .csv"), ("-o", "out", ".npz, .csv"), ("-o", "out.png", ".npz, .csv"),
    ("--plot", "out.jpg", ".png, .pdf, .svg"), ("--plot", "out.npz", ".png, .pdf, .svg"),
    ("--plot", "plot", ".png, .pdf, .svg")])
def test_an_extension_naming_no_format_is_exit_2_before_the_run(capsys, tmp_path, scene,
                                                                monkeypatch, flag, name, allowed):
    from derive.sim import simulation

    def never(*a, **k):
        raise AssertionError("simulate ran although the output could not be written")

    monkeypatch.setattr(simulation, "simulate", never)
    code, out, err = run_in_process(capsys, "simulate", scene, flag, tmp_path / name)
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and err.startswith(f"error: {tmp_path / name}: {flag}: ")
    assert err.rstrip().endswith(allowed)
    assert listing(tmp_path) == ["top.toml"]


def test_a_bad_plot_extension_leaves_an_existing_output_untouched(capsys, tmp_path, scene):
    old = tmp_path / "out.npz"
    old.write_bytes(b"old")
    code, _, err = run_in_process(capsys, "simulate", scene, "-o", old, "--plot",
                                  tmp_path / "out.gif")
    assert code == 2 and "--plot" in err
    assert old.read_bytes() == b"old" and listing(tmp_path) == ["out.npz", "top.toml"]


SWEEP_TOML = """\
scene = "top.toml"
[vary]
initial.beta = { values = [0.3, 0.5] }
[measure]
names = ["beta_max", "nfev"]
"""


def test_sweep_writes_csv_and_refuses_extensions_it_cannot_write(capsys, tmp_path, scene):
    sweep = tmp_path / "sweep.toml"
    sweep.write_text(SWEEP_TOML)
    csv = tmp_path / "r.csv"
    code, out, err = run_in_process(capsys, "sweep", sweep, "-o", csv)
    assert code == 0, err
    lines = csv.read_text().splitlines()
    assert lines[0] == "initial.beta,beta_max,nfev,status" and len(lines) == 3
    assert [float(ln.split(",")[0]) for ln in lines[1:]] == [0.3, 0.5]
    assert all(float(ln.split(",")[1]) >= b for ln, b in zip(lines[1:], (0.3, 0.5)))
    for flag, name in (("-o", "r.xlsx"), ("--plot", "m.jpeg")):
        argv = ["sweep", sweep, "-o", tmp_path / "r.parquet", flag, tmp_path / name]
        if flag == "-o":
            argv = ["sweep", sweep, "-o", tmp_path / name]
        code, out, err = run_in_process(capsys, *argv)
        assert code == 2 and err.count("\n") == 1 and f": {flag}: " in err, err
    assert listing(tmp_path) == ["r.csv", "sweep.toml", "top.toml"]


def test_t_end_and_samples_flags_override_the_scene(capsys, tmp_path, scene):
    npz = tmp_path / "out.npz"
    code, out, err = run_in_process(capsys, "simulate", scene, "--t-end", "0.125",
                                    "--samples", "6", "-o", npz, "--json")
    assert code == 0, err
    summary = __import__("json").loads(out)
    assert summary["t_end"] == 0.125 and summary["samples"] == 6
    with np.load(npz) as data:
        np.testing.assert_array_equal(data["t"], np.linspace(0.0, 0.125, 6))


@pytest.mark.parametrize("flag, value, what", [
    ("--t-end", "-1", "simulate.t_end: must be a positive finite number"),
    ("--t-end", "0", "simulate.t_end: must be a positive finite number"),
    ("--t-end", "nan", "simulate.t_end: must be a positive finite number"),
    ("--t-end", "inf", "simulate.t_end: must be a positive finite number"),
    ("--t-end", "soon", "argument --t-end: invalid float value"),
    ("--samples", "1", "simulate.samples: must be an integer from 2"),
    ("--samples", "99999999999", "simulate.samples: must be an integer from 2"),
    ("--samples", "2.5", "argument --samples: invalid int value"),
])
def test_bad_t_end_or_samples_is_exit_2_naming_the_flag(capsys, tmp_path, scene, flag, value, what):
    npz = tmp_path / "out.npz"
    code, out, err = run_in_process(capsys, "simulate", scene, f"{flag}={value}", "-o", npz)
    assert code == 2 and out == "" and err.count("\n") == 1
    assert what in err and flag in err
    assert not npz.exists()


# --- 10. slow steps say so, on a terminal's stderr -------------------------------------------


class _Terminal:
    """A text stream that says it is a terminal (what the command line checks)."""

    def __init__(self):
        import io

        self.buffer = io.StringIO()

    def write(self, text):
        return self.buffer.write(text)

    def flush(self):
        pass

    def isatty(self):
        return True

    def getvalue(self):
        return self.buffer.getvalue()


def run_with_stderr(stderr, *argv):
    """cli.main with this stderr object: (exit status, stdout, stderr text)."""
    import contextlib
    import io

    from derive import cli

    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(stderr):
        code = cli.main([str(a) for a in argv])
    return code, out.getvalue(), stderr.getvalue()


DAMPED_EULER_ANGLES = SCENE_TOML + "formulation = \"euler-angles\"\n[damping]\nc = 0.01\n"


@pytest.fixture
def unshipped(tmp_path, monkeypatch):
    """A scene whose model (Euler angles, gravity and damping) is not in generated/, an empty
    compile cache, and a derivation that stops at once (as Ctrl-C would): what the command line
    says before the slow step is what is checked, without spending its seconds."""
    from derive.runtime import catalogue

    path = tmp_path / "damped.toml"
    path.write_text(DAMPED_EULER_ANGLES)
    monkeypatch.setenv("DERIVE_CACHE", str(tmp_path / "cache"))

    def interrupted(key, folder):
        raise KeyboardInterrupt

    monkeypatch.setattr(catalogue, "derive_model", interrupted)
    catalogue.clear_memory()  # descriptions loaded by earlier tests point at the usual cache
    yield path
    catalogue.clear_memory()


def test_deriving_an_unshipped_model_is_announced_on_a_terminal(unshipped):
    code, out, err = run_with_stderr(_Terminal(), "simulate", unshipped, "--json")
    assert (code, out) == (130, "")
    lines = err.splitlines()
    assert len(lines) == 2 and lines[1] == "error: interrupted"
    assert lines[0].startswith("note: deriving model euler_angles_sym_gravity_damping with SymPy")
    assert "first run" in lines[0]


def test_no_note_when_stderr_is_not_a_terminal(unshipped):
    import io

    code, out, err = run_with_stderr(io.StringIO(), "simulate", unshipped, "--json")
    assert (code, out, err) == (130, "", "error: interrupted\n")


def test_a_cached_model_runs_without_a_note(tmp_path):
    path = tmp_path / "top.toml"
    path.write_text(SCENE_TOML)
    run_with_stderr(_Terminal(), "simulate", path)  # compiled now if it was not
    code, out, err = run_with_stderr(_Terminal(), "simulate", path, "--json")
    assert code == 0 and err == ""
    assert __import__("json").loads(out)["samples"] == 3


@pytest.mark.parametrize("argv, stub, output", [
    (["analyze", "SCENE", "--format", "json"], ("lecture.analysis", "render", lambda scene, fmt: "{}"),
     "{}\n"),
    (["verify"], ("lecture.verify", "table", lambda fmt: "table"), "table\n"),
    (["generate", "--check"], ("generate", "generate_all", dict), ""),
])
def test_analyze_verify_and_generate_announce_themselves_on_stderr_only(tmp_path, monkeypatch,
                                                                        argv, stub, output):
    import importlib

    module, name, fake = stub
    monkeypatch.setattr(importlib.import_module(f"derive.{module}"), name, fake)
    if module == "lecture.verify":
        monkeypatch.setattr(importlib.import_module("derive.lecture.verify"), "mismatches", lambda: [])
    if module == "generate":
        monkeypatch.setattr(importlib.import_module("derive.generate"), "stale", lambda f, o: [])
    scene = tmp_path / "top.toml"
    scene.write_text(SCENE_TOML)
    argv = [scene if a == "SCENE" else a for a in argv]
    code, out, err = run_with_stderr(_Terminal(), *argv)
    assert code == 0 and out == output
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("note: ") and "second" in lines[0]


def test_bad_input_to_analyze_is_one_error_line_without_a_note(tmp_path):
    code, out, err = run_with_stderr(_Terminal(), "analyze", tmp_path / "missing.toml")
    assert code == 2 and out == ""
    assert err.splitlines() == [f"error: {tmp_path / 'missing.toml'}: file: not found"]


def _run_on_a_terminal(argv, env, timeout=300):
    """A real process whose stderr is a pseudo-terminal: (exit status, stdout, stderr)."""
    import os
    import pty

    master, slave = pty.openpty()
    try:
        p = subprocess.run([sys.executable, "-m", "derive", *map(str, argv)], stdout=subprocess.PIPE,
                           stderr=slave, text=True, env=env, timeout=timeout)
    finally:
        os.close(slave)
    chunks = []
    while True:
        try:
            chunk = os.read(master, 65536)
        except OSError:  # EIO: the other side is closed and everything was read
            break
        if not chunk:
            break
        chunks.append(chunk)
    os.close(master)
    return p.returncode, p.stdout, b"".join(chunks).decode().replace("\r\n", "\n")


@pytest.mark.slow  # two real derivations and compilations of a model (5-10 s each)
def test_first_run_of_an_unshipped_model_notes_on_a_terminal_and_keeps_stdout_clean(tmp_path):
    import json
    import os

    scene = tmp_path / "damped.toml"
    scene.write_text(DAMPED_EULER_ANGLES)
    piped_env = dict(os.environ, DERIVE_CACHE=str(tmp_path / "cache-a"))
    r = derive_cli("simulate", scene, "--json", env=piped_env, timeout=300)
    assert r.returncode == 0 and r.stderr == ""  # a pipe: nothing but what failed
    assert json.loads(r.stdout)["formulation"] == "euler-angles"
    tty_env = dict(os.environ, DERIVE_CACHE=str(tmp_path / "cache-b"))
    code, out, err = _run_on_a_terminal(["simulate", scene, "--json"], tty_env)
    assert code == 0 and json.loads(out) == {**json.loads(out), "formulation": "euler-angles"}
    notes = err.splitlines()
    assert notes[0].startswith("note: deriving model euler_angles_sym_gravity_damping")
    assert all(n.startswith("note: ") for n in notes) and any("compiling" in n for n in notes)
    code, out, err = _run_on_a_terminal(["simulate", scene, "--json"], tty_env)
    assert code == 0 and err == ""  # the second run: derived and compiled already


# --- 9. figures that do not mislead (derive.sim.plots, derive.sweeps.maps, derive.bench.runner) ------------


@pytest.fixture(scope="module")
def mpl():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    yield plt
    plt.close("all")


LOOPING = {"title": "looping top",
           "body": {"I1": 1.8e-4, "I3": 4.0e-5},
           "gravity": {"M": 0.1, "g": 9.81, "l": 0.04},
           "initial": {"alpha": 0.0, "beta": 0.5, "gamma": 0.0, "alpha_dot": 0.0, "beta_dot": 0.0,
                       "gamma_dot": 150.0},
           "simulate": {"t_end": 0.5, "samples": 201}}


def test_trajectory_figure_draws_a_constant_spin_at_its_true_scale(mpl):
    from derive.sim import plots

    res = derive.simulate(LOOPING)
    w3 = res.omega[:, 2]
    dev = float(np.max(np.abs(w3 - w3[0])))
    assert 0 <= dev < 1e-6 * abs(w3[0])  # ω̃₃ is conserved: only round-off moves it (or nothing:
    # in the reduced formulations it is p_γ / I₃, a parameter)
    fig = plots.figure(res)
    assert fig.get_suptitle().startswith("looping top\n")
    (left,) = [ax for ax in fig.axes if ax.get_label() == "omega"]
    (right,) = [ax for ax in fig.axes if ax.get_label() == "omega:twin"]
    assert right.get_ylabel() == "ω̃₃ [rad/s]" and left.get_ylabel() == "ω̃₁, ω̃₂ [rad/s]"
    (line,) = right.get_lines()
    np.testing.assert_array_equal(line.get_ydata(), w3)  # ω̃₃ itself, not ω̃₃ − ω̃₃(0)
    lo, hi = right.get_ylim()
    assert lo < 0 < np.max(w3) < hi
    assert np.ptp(w3) / (hi - lo) < 1e-9  # the round-off wobble stays invisible: a flat line
    # The two axes share their zero line, so heights compare.
    l_lo, l_hi = left.get_ylim()
    assert -l_lo / (l_hi - l_lo) == pytest.approx(-lo / (hi - lo), rel=1e-12)
    labels = [t.get_text() for t in left.get_legend().get_texts()]
    expected = "constant exactly" if dev == 0 else f"constant within {dev:.1e} rad/s"
    assert f"ω̃₃ (right axis), {expected}" in labels


def _sweep(spec):
    return derive.sweep(spec, processes=1)


@pytest.fixture(scope="module")
def sleeping_map():
    """A small spin × tilt map of a sleeping top; at high spin the top never tilts past 1 rad
    within t_end, so those points have time_to_tilt = NaN."""
    scene = {"title": "Sleeping top (spin above the stability threshold)",
             "body": {"I1": 1.8e-4, "I3": 4.0e-5}, "gravity": {"M": 0.1, "g": 9.81, "l": 0.04},
             "initial": {"alpha": 0.0, "beta": 0.1, "gamma": 0.0, "alpha_dot": 0.0,
                         "beta_dot": 0.0, "gamma_dot": 200.0},
             "simulate": {"t_end": 1.0, "rtol": 1e-8}}
    return _sweep({"scene": scene,
                   "vary": {"initial.beta": {"from": 0.05, "to": 0.5, "num": 3},
                            "initial.gamma_dot": {"values": [60.0, 100.0, 250.0, 300.0]}},
                   "measure": {"names": ["time_to_tilt"], "time_to_tilt": {"angle": 1.0}}})


def test_sweep_map_is_titled_by_the_sweep_labelled_by_symbol_and_marks_nan(mpl, sleeping_map):
    from derive.sweeps import maps as sweep_maps

    res = sleeping_map
    z = res.measures["time_to_tilt"]
    never = int(np.sum(res.ok & np.isnan(z)))
    assert 0 < never < len(z)  # both kinds of point, else the test proves nothing
    fig = sweep_maps.sweep_figure(res, "time_to_tilt")
    (ax,) = [a for a in fig.axes if a.get_label() == "sweep"]
    head, base = ax.get_title().split("\n")
    assert head == f"time_to_tilt over β₀ × γ̇₀: {len(z)} points (0 failed)"
    assert base == "base scene: Sleeping top (spin above the stability threshold)"
    assert ax.get_xlabel() == "γ̇₀ (initial.gamma_dot) [rad/s]"
    assert ax.get_ylabel() == "β₀ (initial.beta) [rad]"
    (painted,) = [c for c in ax.collections if c.get_gid() == "nan"]
    cells = np.ma.getmaskarray(painted.get_array())
    assert int(np.sum(~cells)) == never  # exactly the NaN cells are painted
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert f"time_to_tilt = NaN (never within t_end = 1 s): {never} points" in legend
    assert not [c for c in ax.collections if c.get_gid() == "failed"]


def test_sweep_map_marks_failed_points_apart_from_nan(mpl, sleeping_map):
    import dataclasses

    from derive.sweeps import maps as sweep_maps

    status = sleeping_map.status.copy()
    status[0] = "t = 0.5: step budget spent"
    res = dataclasses.replace(sleeping_map, status=status)
    fig = sweep_maps.sweep_figure(res, "time_to_tilt")
    (ax,) = [a for a in fig.axes if a.get_label() == "sweep"]
    (failed,) = [c for c in ax.collections if c.get_gid() == "failed"]
    assert int(np.sum(~np.ma.getmaskarray(failed.get_array()))) == 1
    assert "(1 failed)" in ax.get_title()
    assert "failed: 1 point (see the status column)" in [t.get_text() for t in ax.get_legend().get_texts()]


def test_flip_line_is_one_based_with_its_slope_per_decade_and_nan_marked(mpl):
    import math

    from derive.sweeps import maps as sweep_maps

    I1, I2, I3, w2 = 1.0e-3, 2.0e-3, 2.5e-3, 10.0
    spec = {"scene": {"title": "Tennis racket", "body": {"I1": I1, "I2": I2, "I3": I3},
                      "initial": {"alpha": 0.0, "beta": math.pi / 2, "gamma": math.pi / 2,
                                  "omega": [1e-3, w2, 0.0]},
                      "simulate": {"t_end": 2.0}},
            "vary": {"initial.omega.0": {"values": [1e-8, 1e-6, 1e-2, 1e-1, 1.0]}},
            "measures": ["time_to_flip"]}
    res = _sweep(spec)
    z = res.measures["time_to_flip"]
    assert np.sum(np.isnan(z)) == 2  # ε = 1e-8, 1e-6: no flip within 2 s
    fig = sweep_maps.sweep_figure(res, "time_to_flip")
    (ax,) = [a for a in fig.axes if a.get_label() == "sweep"]
    assert ax.get_xlabel() == "ω̃₁(0), body frame [rad/s]" and ax.get_xscale() == "log"
    assert "initial.omega.0" not in ax.get_xlabel() + ax.get_title()
    assert ax.get_title().startswith("time_to_flip over ω̃₁(0): 5 points")
    (nan,) = [ln for ln in ax.get_lines() if ln.get_gid() == "nan"]
    np.testing.assert_array_equal(np.sort(nan.get_xdata()), [1e-8, 1e-6])
    assert nan.get_label() == "time_to_flip = NaN (none within t_end = 2 s): 2 points"
    lam = w2 * math.sqrt((I2 - I1) * (I3 - I2) / (I1 * I3))
    (pred,) = [ln for ln in ax.get_lines() if ln.get_label().startswith("linearised")]
    assert f"slope −ln 10/λ = −{math.log(10) / lam:.3g} s per decade of ω̃₁(0)" in pred.get_label()
    x, y = np.asarray(pred.get_xdata()), np.asarray(pred.get_ydata())
    slope = np.polyfit(np.log10(x), y, 1)[0]  # what a reader measures on the log10 axis
    assert slope == pytest.approx(-math.log(10) / lam, rel=1e-12)


def _wp_points(family, method, formulation, t0, n, failed=0):
    from derive.bench.workprecision import Point

    pts = [Point("s", family, method, formulation, f"rtol=1e-{k + 4}", t0 * 1.6 ** k,
                 int(1000 * 1.6 ** k), 10.0 ** (-4 - k)) for k in range(n)]
    pts += [Point("s", family, method, formulation, "rtol=1e-14", t0 * 100, 10**6, float("nan"),
                  "failed") for _ in range(failed)]
    return pts


def test_work_precision_series_differ_by_colour_and_marker_in_a_grouped_legend(mpl):
    from matplotlib.colors import to_rgba

    from derive.bench.workprecision import Curve, work_precision_figure

    curves = [Curve("ours", "dop853", form, _wp_points("ours", "dop853", form, 1e-3 * (1 + k), 6,
                                                         failed=int(form == "quaternion")))
              for k, form in enumerate(["reduced", "euler-angles", "quaternion", "euler-poisson"])]
    curves += [Curve("ours", m, "euler-angles", _wp_points("ours", m, "euler-angles", 2e-3, 5))
               for m in ("rk4", "gauss4", "gauss6")]
    curves += [Curve("scipy", m, "euler-angles", _wp_points("scipy", m, "euler-angles", 5e-3, 5,
                                                             failed=2 * (m == "scipy-radau")))
               for m in ("scipy-dop853", "scipy-lsoda", "scipy-radau", "scipy-odeint")]
    curves += [Curve("casadi", m, "quaternion", _wp_points("casadi", m, "quaternion", 4e-3, 5))
               for m in ("casadi-cvodes-adams", "casadi-cvodes-bdf", "casadi-idas")]
    curves.append(Curve("pydy", "pydy-odeint", "euler-angles",
                        _wp_points("pydy", "pydy-odeint", "euler-angles", 6e-3, 5)))
    wp = {"scene": "s", "title": "A top", "t_end": 2.0, "reference": "exact", "curves": curves}
    fig = work_precision_figure(wp)
    time_ax, nfev_ax = fig.axes
    assert (time_ax.get_label(), nfev_ax.get_label()) == ("time", "nfev")
    assert fig.get_suptitle().startswith("A top — work–precision")
    assert time_ax.get_xlabel().startswith("wall time") and nfev_ax.get_xlabel().startswith("right-hand")
    assert time_ax.get_ylabel().startswith("max |ê₃ − ê₃,ref|")
    series = [ln for ln in time_ax.get_lines() if not ln.get_label().startswith("_")]
    assert len(series) == len(curves) == 15
    keys = {(to_rgba(ln.get_color()), ln.get_marker()) for ln in series}
    assert len(keys) == len(series)  # colour + marker tell every series apart
    assert len({to_rgba(ln.get_color()) for ln in series if ln.get_marker() == "s"}) == \
        sum(ln.get_marker() == "s" for ln in series)  # the same formulation: colours differ
    # Failed runs are drawn (x on the top edge), not dropped, and counted in the legend.
    failed = [ln for ln in time_ax.get_lines() if ln.get_gid() == "failed"]
    assert sorted(len(ln.get_xdata()) for ln in failed) == [1, 2]
    (legend,) = fig.legends
    texts = legend.get_texts()
    bold = [t.get_text() for t in texts if t.get_fontweight() == "bold"]
    assert bold == ["derive (filled, solid)", "SciPy (hollow, dashed)", "CasADi (hollow, dashed)",
                    "PyDy (hollow, dashed)"]
    labels = [t.get_text() for t in texts]
    assert labels.index("dop853 / quaternion (1 failed, x on the top edge)") < labels.index(bold[1])
    assert "scipy-radau / euler-angles (2 failed, x on the top edge)" in labels
    assert len(labels) == len(curves) + len(bold)
