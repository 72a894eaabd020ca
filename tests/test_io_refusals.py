"""Inputs and outputs: an output never replaces an input,
special and oversized files are refused before they are read, a key named twice in any spelling
is refused, `analyze` survives extreme but finite numbers, and the smaller holes (bench and
generate output folders, a NUL in a path, the documented rtol floor, huge titles, the SciPy step
budget). Each failure is one `error:` line, and the input file is byte-identical afterwards."""
import contextlib
import io
import json
import os
import re
import subprocess
import sys

import pytest

import derive
from derive import cli
from derive.codegen.render import ROOT
from small_scenes import HEAVY_TOP

TOP = HEAVY_TOP

SWEEP = 'scene = "top.toml"\n[vary]\ninitial.beta = { values = [0.4, 0.5] }\n'


def run(*args):
    """``derive ARGS`` through the command line's own entry (derive.cli.main) in this process:
    its exit status and what it printed. (A real process's exit and its stderr are pinned in
    tests/test_cli_robust.py; the special files a read could block on run in one, bounded in time.)"""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = cli.main([*map(str, args)])
    return subprocess.CompletedProcess(args, code, out.getvalue(), err.getvalue())


def run_process(*args, timeout=60):
    """``derive ARGS`` in a fresh interpreter (the console script's path, bounded in time)."""
    return subprocess.run([sys.executable, "-m", "derive", *map(str, args)], capture_output=True,
                          text=True, timeout=timeout)


def one_error_line(p) -> str:
    """The single stderr line of a failed command (no traceback, no second line)."""
    lines = p.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), p.stderr
    assert "Traceback" not in p.stderr and "internal error" not in p.stderr
    return lines[0]


@pytest.fixture
def files(tmp_path):
    """A scene and a sweep naming it, in tmp_path; yields (scene, sweep) and checks at teardown
    that neither changed by a byte."""
    scene, sweep = tmp_path / "top.toml", tmp_path / "s.toml"
    scene.write_text(TOP)
    sweep.write_text(SWEEP)
    before = scene.read_bytes(), sweep.read_bytes()
    yield scene, sweep
    assert (scene.read_bytes(), sweep.read_bytes()) == before


# ---------------------------------------------------------------------------------------------
# item 1: an output never destroys an input


@pytest.mark.parametrize("flags", [("-o", "{scene}"), ("--plot", "{scene}"),
                                   ("-o", "{symlink}"), ("-o", "{hardlink}"),
                                   ("-o", "x.npz", "--plot", "{symlink}")])
def test_simulate_refuses_an_output_that_is_its_scene(files, flags):
    scene, _ = files
    (scene.parent / "link.toml").symlink_to(scene.name)
    os.link(scene, scene.parent / "hard.toml")
    names = {"scene": scene, "symlink": scene.parent / "link.toml",
             "hardlink": scene.parent / "hard.toml"}
    args = [f.format(**names) if "{" in f else f if f.startswith("-") else str(scene.parent / f)
            for f in flags]
    p = run("simulate", scene, *args)
    assert p.returncode == 2
    line = one_error_line(p)
    assert line.endswith(f": output: would overwrite the input {scene}"), line
    assert not (scene.parent / "x.npz").exists()  # all or nothing: the good output is not written


def test_simulate_refuses_two_outputs_that_are_one_file(files):
    scene, _ = files
    out = scene.parent / "x.npz"
    p = run("simulate", scene, "-o", out, "--plot", out)
    assert p.returncode == 2 and "the same file as" in one_error_line(p)
    assert not out.exists()
    out.write_bytes(b"old results")
    os.link(out, scene.parent / "y.png")  # an existing hard link: the same file by inode
    p = run("simulate", scene, "-o", out, "--plot", scene.parent / "y.png")
    assert p.returncode == 2 and "the same file as" in one_error_line(p)
    assert out.read_bytes() == b"old results"


@pytest.mark.parametrize("target", ["s.toml", "top.toml", "link.toml"])
def test_sweep_refuses_an_output_that_is_its_file_or_its_scene(files, target):
    scene, sweep = files
    (scene.parent / "link.toml").symlink_to(scene.name)
    p = run("sweep", sweep, "-o", scene.parent / target)
    assert p.returncode == 2
    line = one_error_line(p)
    assert ": output: would overwrite the input " in line, line
    p = run("sweep", sweep, "-o", scene.parent / "r.parquet", "--plot", scene.parent / target)
    assert p.returncode == 2 and "would overwrite the input" in one_error_line(p)
    assert not (scene.parent / "r.parquet").exists()


def test_the_python_writers_refuse_their_inputs(files):
    # Internal modules: derive.simulate and derive.sweep return results; the writers that put
    # them into files are simulation.write_outputs and sweeps.write.
    from derive.sim.simulation import write_outputs
    from derive.sweeps.result import write

    scene, sweep = files
    res = derive.simulate(str(scene))
    with pytest.raises(derive.SceneError, match="would overwrite the input"):
        write_outputs(res, npz=str(scene))
    sw = derive.sweep(str(sweep), progress=False)
    for target in (scene, sweep):
        with pytest.raises(derive.SceneError, match="would overwrite the input"):
            write(sw, str(target))
    write(sw, str(scene.parent / "r.parquet"))  # a path that is no input is written
    assert (scene.parent / "r.parquet").stat().st_size > 0


# ---------------------------------------------------------------------------------------------
# item 7: analyze on extreme but finite numbers


def _extreme(text: str, old: str, new: str) -> str:
    assert old in text
    return text.replace(old, new)


@pytest.mark.parametrize("old,new", [("I1 = 1.0", "I1 = 1e300"), ("M = 1.0", "M = 1e300"),
                                     ("gamma_dot = 10.0", "gamma_dot = 1e200"),
                                     ("l = 0.1", "com = [0, 0, 1e300]")])
def test_analyze_extreme_numbers_exit_0_or_3_with_one_line(tmp_path, capsys, old, new):
    # The CLI's own entry (derive.cli.main) in this process: analyze's derivations are cached
    # per process, so the four cases cost a second, not four fresh SymPy imports.
    from derive.cli import main

    path = tmp_path / "top.toml"
    path.write_text(_extreme(TOP, old, new))
    rc = main(["analyze", str(path), "--format", "json"])
    out, err = capsys.readouterr()
    assert rc in (0, 3), err
    if rc == 0:
        assert err == ""
        doc = json.loads(out)  # strict JSON: no Infinity or NaN in what it reports
        assert "Infinity" not in out and "NaN" not in out and doc["equilibria"]
    else:
        lines = err.splitlines()
        assert len(lines) == 1 and re.match(rf"error: {re.escape(str(path))}: analyze: [a-z-]+: "
                                            r".+ overflows double precision", lines[0]), err


def test_analyze_verdicts_at_1e300_are_those_of_the_scaled_top(tmp_path):
    """M = 1e300 with a slow spin: the sleeping top is unstable (p_gamma far below the threshold
    sqrt(4 M g l I1)), the hanging top stable, as at ordinary numbers with the same ordering."""
    from derive.lecture import analysis

    path = tmp_path / "top.toml"
    path.write_text(_extreme(TOP, "M = 1.0", "M = 1e300"))
    eqs = {e.kind: e for e in analysis.analyze(str(path)).equilibria}
    assert eqs["sleeping"].stable is False and eqs["hanging"].stable is True
    assert eqs["sleeping"].values["threshold"] > 1e150 > eqs["sleeping"].values["p_gamma"]


# ---------------------------------------------------------------------------------------------
# item 9: sweep and scene files


@pytest.mark.parametrize("body", [
    '[vary]\n"initial.beta" = { values = [0.4] }\ninitial.beta = { values = [0.5] }\n',
    '[vary.initial.beta]\nvalues = [0.4]\n[vary."initial.beta"]\nvalues = [0.5]\n',
    '[random]\nn = 2\nseed = 1\ninitial.beta = { low = 0.4, high = 0.5 }\n'
    '"initial.beta" = { low = 0.1, high = 0.2 }\n',
])
def test_a_sweep_key_given_twice_in_two_spellings_is_refused(files, body):
    scene, sweep = files
    sweep.write_text('scene = "top.toml"\n' + body)
    before = sweep.read_bytes()
    out = scene.parent / "r.parquet"
    p = run("sweep", sweep, "-o", out)
    assert p.returncode == 2 and not out.exists() and sweep.read_bytes() == before
    line = one_error_line(p)
    assert re.match(rf"error: {re.escape(str(sweep))}: (vary|random)\.initial\.beta: given twice",
                    line), line
    sweep.write_text(SWEEP)  # the fixture's teardown compares with the original


def test_a_quoted_dotted_key_in_a_scene_is_refused(tmp_path):
    path = tmp_path / "top.toml"
    path.write_text('"initial.beta" = 0.4\n' + TOP)
    with pytest.raises(derive.SceneError, match=r"top\.toml: initial\.beta: unknown key"):
        derive.simulate(str(path))


def test_an_empty_vary_table_is_a_bad_sweep_not_an_internal_error(files):
    scene, sweep = files
    sweep.write_text('scene = "top.toml"\n[vary]\ninitial = {}\n')
    p = run("sweep", sweep, "-o", scene.parent / "r.parquet")
    assert p.returncode == 2
    assert one_error_line(p).startswith(f"error: {sweep}: vary.initial: ")
    sweep.write_text(SWEEP)


#: The special files no read blocks on: refused by the command line's entry in this process.
IN_PROCESS_KINDS = ("directory", "big")


@pytest.mark.parametrize("kind, command", [
    (k, c) if (i + j) % 2 == 0 or k in IN_PROCESS_KINDS else pytest.param(k, c, marks=pytest.mark.slow)
    for i, k in enumerate(["device", "fifo", "directory", "big"])
    for j, c in enumerate(["sweep", "simulate"])])  # every kind fast; in a process, the commands in turn
def test_special_and_oversized_files_are_refused_before_reading(tmp_path, command, kind):
    path = {"device": "/dev/zero", "fifo": tmp_path / "f.toml", "directory": tmp_path,
            "big": tmp_path / "big.toml"}[kind]
    if kind == "fifo":
        os.mkfifo(path)  # no writer: a blocking open would wait forever
    if kind == "big":
        path.write_text(TOP + "# " + "x" * (1 << 20) + "\n")
    args = ["-o", tmp_path / "r.parquet"] if command == "sweep" else []
    if kind in IN_PROCESS_KINDS:
        p = run(command, path, *args)
    else:
        p = run_process(command, path, *args, timeout=60)  # a blocking read would hang: bounded
    assert p.returncode == 2
    what = {"device": "not a regular file", "fifo": "not a regular file",
            "directory": "is a directory", "big": "larger than 1 MiB"}[kind]
    assert one_error_line(p).startswith(f"error: {path}: file: {what}"), p.stderr


def test_a_sweep_naming_a_fifo_as_its_scene_does_not_hang(files):
    scene, sweep = files
    os.mkfifo(scene.parent / "fifo.toml")
    sweep.write_text('scene = "fifo.toml"\n[vary]\ninitial.beta = { values = [0.4] }\n')
    p = run("sweep", sweep, "-o", scene.parent / "r.parquet")
    assert p.returncode == 2 and "fifo.toml: file: not a regular file" in one_error_line(p)
    sweep.write_text(SWEEP)


# ---------------------------------------------------------------------------------------------
# item 11: the smaller ones


@pytest.mark.parametrize("args", [("bench", "-o", "{file}", "--quick"),
                                  ("bench", "-o", "{file}/sub", "--quick"),
                                  ("generate", "--out", "{file}"),
                                  ("generate", "--out", "{file}/sub")])
def test_bench_and_generate_refuse_a_file_as_their_folder(tmp_path, args):
    f = tmp_path / "results"
    f.write_text("keep me")
    p = run(*(a.format(file=f) for a in args))
    assert p.returncode == 2
    # a file where the folder should be is the flag's; a file above it, the output's parent
    key = "output" if args[2].endswith("/sub") else args[1]
    assert one_error_line(p).startswith(f"error: {args[2].format(file=f)}: {key}: ")
    assert f.read_text() == "keep me"


def test_a_nul_byte_in_a_scene_path_is_a_scene_error():
    with pytest.raises(derive.SceneError, match=r"a\\0b: file: not a file name"):
        derive.simulate("a\0b")


def test_the_documented_rtol_floor_is_accepted_and_is_the_floor(tmp_path):
    # The limit as generated/scene-format.md prints it is what the validator enforces.
    doc = (ROOT / "generated" / "scene-format.md").read_text()
    floor = float(re.search(r"\| rtol \|.*?\| \[([0-9.e+-]+), 1\)", doc).group(1))
    path = tmp_path / "top.toml"
    path.write_text(TOP)
    p = run("simulate", path, "--rtol", repr(floor))
    assert p.returncode == 0, p.stderr
    below = float(f"{floor * 0.99:.3e}")
    p = run("simulate", path, "--rtol", repr(below))
    assert p.returncode == 2 and "simulate.rtol" in one_error_line(p)


def test_a_huge_title_is_cut_for_the_plot(tmp_path, monkeypatch):
    from derive.sim import plots
    from derive.sim.plots import TITLE_DISPLAY_LIMIT, display_title

    shown = display_title("a $b$ title\nover lines " + "x" * 10**6)
    assert len(shown.replace("\\$", "$")) == TITLE_DISPLAY_LIMIT and shown.endswith("…")
    assert "\n" not in shown and "\\$b\\$" in shown
    path, png = tmp_path / "top.toml", tmp_path / "top.png"
    path.write_text(TOP.replace('"A heavy top"', '"' + "a heavy top " * 87_000 + '"'))
    assert path.stat().st_size > 10**6 - 10**5
    titles = []
    title = plots._title
    monkeypatch.setattr(plots, "_title", lambda res: titles.append(title(res)) or titles[-1])
    p = run("simulate", path, "--plot", png)
    assert p.returncode == 0, p.stderr
    assert titles and len(titles[0].split("\n")[0]) == TITLE_DISPLAY_LIMIT  # the figure's, cut
    assert png.stat().st_size > 10_000


FAST = TOP.replace("gamma_dot = 10.0", "gamma_dot = 3000.0").replace("t_end = 0.05", "t_end = 2.0")


def _just_above_the_floor(method: str) -> int:
    """A budget the up-front estimate lets start (a fifth above its floor) that the run spends."""
    from derive.methods.costs import least_steps
    from derive.sim.inputs import fastest_rate
    from derive.sim.scene import load_scene

    sc = load_scene(_dict(FAST))
    return int(1.2 * least_steps(method, sc.simulate.t_end * fastest_rate(sc), sc.simulate.rtol,
                                 sc.simulate.atol)) + 1


def test_the_step_budget_stops_a_scipy_method(tmp_path):
    path = tmp_path / "fast.toml"
    path.write_text(FAST)
    budget = _just_above_the_floor("scipy-rk45")
    p = run("simulate", path, "--method", "scipy-rk45", "--max-steps", budget)
    assert p.returncode == 3
    assert re.match(rf"error: t = [0-9.e-]+: step budget spent \(simulate\.max_steps = {budget}\)",
                    one_error_line(p)), p.stderr


@pytest.mark.parametrize("method", ["scipy-dop853", pytest.param("scipy-radau", marks=pytest.mark.slow),
                                    "scipy-lsoda"])  # Radau's Python loop: make test-slow
def test_the_step_budget_holds_for_every_scipy_method(method):
    budget = _just_above_the_floor(method)
    with pytest.raises(derive.IntegrationError, match=rf"step budget spent \(simulate\.max_steps = {budget}\)"):
        derive.simulate(_dict(FAST), method=method, max_steps=budget)
    with pytest.raises(derive.IntegrationError, match=r"needs at least about .*simulate\.max_steps = 20;"):
        derive.simulate(_dict(FAST), method=method, max_steps=20)  # below the floor: refused at once
    # within the budget the same call succeeds: the budget is what stopped it
    res = derive.simulate(_dict(TOP), method=method, max_steps=10_000)
    assert res.method == method and res.nfev > 0


def _dict(text: str) -> dict:
    import tomllib

    return tomllib.loads(text)
