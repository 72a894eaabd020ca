"""The command line never shows a traceback: Ctrl-C (exit 130), the entry's validation gaps, NumPy
warnings, and a last-resort handler for the unforeseen (exit 1)."""
import contextlib
import io
import math
import os
import re
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

import derive
from derive import SceneError, cli
from derive import errors as derive_errors
from derive.codegen.render import ROOT

TOP = {
    "body": {"I1": 1.0, "I3": 0.5},
    "gravity": {"M": 1.0, "g": 9.81, "l": 0.1},
    "initial": {"alpha": 0.0, "beta": 0.5, "gamma": 0.0,
                "alpha_dot": 0.0, "beta_dot": 0.0, "gamma_dot": 10.0},
    "simulate": {"t_end": 0.05, "samples": 3},
}


def toml(scene: dict) -> str:
    """A scene dict as TOML (numbers, strings and tables are all these tests need)."""
    def value(v):
        if isinstance(v, str):
            return '"' + v + '"'
        if isinstance(v, float) and not math.isfinite(v):
            return "nan" if math.isnan(v) else ("inf" if v > 0 else "-inf")
        return repr(v)

    lines = []
    for table, keys in scene.items():
        lines.append(f"[{table}]")
        lines += [f"{k} = {value(v)}" for k, v in keys.items()]
        lines.append("")
    return "\n".join(lines)


def with_(base=TOP, **tables):
    """``base`` with some keys replaced: ``with_(simulate={"method": "rk4"})``."""
    out = {t: dict(keys) for t, keys in base.items()}
    for t, keys in tables.items():
        out.setdefault(t, {}).update(keys)
    return out


def run(*argv):
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = cli.main([str(a) for a in argv])
    return rc, out.getvalue(), err.getvalue()


def errors(stderr):
    return [ln for ln in stderr.splitlines() if not ln.startswith("note: cached library")]


def assert_contract(tmp_path, scene_file, rc, out, err, npz):
    """Exit 0, 2 or 3; on failure one `error:` line and no file; no traceback, no leftovers."""
    assert "Traceback" not in err + out and "Warning" not in err
    assert rc in (0, 2, 3), (rc, err)
    if rc == 0:
        with np.load(npz) as data:
            for name in data.files:
                if data[name].dtype.kind == "f":
                    assert np.all(np.isfinite(data[name])), name
        assert sorted(p.name for p in tmp_path.iterdir()) == sorted([scene_file.name, npz.name])
    else:
        lines = errors(err)
        assert len(lines) == 1 and lines[0].startswith("error: "), err
        assert sorted(p.name for p in tmp_path.iterdir()) == [scene_file.name]


def simulate_file(tmp_path, text, *flags):
    scene = tmp_path / "scene.toml"
    scene.write_bytes(text if isinstance(text, bytes) else text.encode())
    npz = tmp_path / "out.npz"
    rc, out, err = run("simulate", scene, "-o", npz, *flags)
    assert_contract(tmp_path, scene, rc, out, err, npz)
    return rc, errors(err)


# --- the Python API's entry -------------------------------------------------------------------


@pytest.mark.parametrize("bad", [None, [TOP], b"scenes/looping_top.toml", 1.5, 3, object()])
def test_api_rejects_what_is_not_a_scene(bad):
    with pytest.raises(SceneError) as err:
        derive.simulate(bad)
    assert "\n" not in str(err.value) and type(bad).__name__ in str(err.value)


# --- encodings ------------------------------------------------------------------------------


def test_utf8_byte_order_mark_is_accepted(tmp_path):
    rc, _ = simulate_file(tmp_path, b"\xef\xbb\xbf" + toml(TOP).encode())
    assert rc == 0


@pytest.mark.parametrize("codec, name", [("utf-16", "UTF-16"), ("utf-32", "UTF-32")])
def test_utf16_and_utf32_are_named(tmp_path, codec, name):
    rc, lines = simulate_file(tmp_path, toml(TOP).encode(codec))
    assert rc == 2 and lines == [f"error: {tmp_path / 'scene.toml'}: file: is {name} text; "
                                 "scene files are UTF-8"]


@pytest.mark.parametrize("path, what", [("/dev/null", "not a regular file"),
                                        ("/dev/zero", "not a regular file")])
def test_special_files_are_refused_without_reading(path, what):
    rc, out, err = run("simulate", path)
    assert rc == 2 and errors(err) == [f"error: {path}: file: {what}"]


def test_deeply_nested_toml_is_a_scene_error(tmp_path):
    rc, lines = simulate_file(tmp_path, "x = " + "[" * 20000 + "]" * 20000 + "\n")
    assert rc == 2 and "nested too deeply" in lines[0]


def test_huge_file_is_refused(tmp_path):
    rc, lines = simulate_file(tmp_path, "# " + "x" * (2 << 20) + "\n" + toml(TOP))
    assert rc == 2 and "not a scene file" in lines[0]


# --- numbers --------------------------------------------------------------------------------


def test_reduced_with_zero_damping_has_no_traceback(tmp_path):
    """[damping] c = 0.0 with formulation = "reduced" ended in a ValueError traceback."""
    scene = with_(damping={"c": 0.0}, simulate={"formulation": "reduced"})
    rc, lines = simulate_file(tmp_path, toml(scene))
    assert rc == 0 or (rc == 2 and "simulate.formulation" in lines[0]), lines


@pytest.mark.parametrize("tables", [
    {"gravity": {"l": 1e200}},
    {"gravity": {"M": 1e300, "l": 1e300}},
    {"body": {"I1": 1e-300, "I3": 1e-300}},
    {"body": {"I1": 1e300, "I3": 1e300}},
    {"initial": {"gamma_dot": 1e200}},
    {"initial": {"alpha": 1e300, "gamma": -1e300}},
    {"simulate": {"t_end": 1e300}},
    {"simulate": {"t_end": 1e300, "method": "rk4"}},
    {"simulate": {"t_end": 1e-300}},
    {"simulate": {"atol": 1e-300}},
])
def test_absurd_but_finite_numbers_give_no_warning(tmp_path, tables):
    """No RuntimeWarning reaches the user: exit 0 with finite outputs, or one error line."""
    simulate_file(tmp_path, toml(with_(**tables)))


@pytest.mark.parametrize("tables", [
    {"gravity": {"M": 1.0, "g": 9.81, "l": 1e200}},
    {"body": {"I1": 1e-300, "I3": 1e-300}},
    {"body": {"I1": 1e300, "I3": 1e300}},
    {"initial": {"alpha": 0.0, "beta": 0.5, "gamma": 0.0, "omega": [1e300, 1e300, 1e300]}},
])
def test_the_api_shows_no_numpy_warning(tables):
    """The Python API too: the outcome is a result or one exception, never a RuntimeWarning."""
    import warnings

    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        for run_ in (derive.simulate, lambda s: derive.simulate_batch([s, s])):
            try:
                run_(with_(**tables))
            except (derive.SceneError, derive.IntegrationError):
                pass
    assert [str(w.message) for w in seen if issubclass(w.category, RuntimeWarning)] == []


def test_warnings_are_silenced_but_errors_still_reported(tmp_path, monkeypatch):
    from derive.sim import simulation

    def noisy(*a, **k):
        np.float64(1e308) * 10  # RuntimeWarning: overflow
        import warnings
        warnings.warn("something odd", UserWarning)
        raise derive.IntegrationError("t = 0.5: non-finite state")

    monkeypatch.setattr(simulation, "simulate", noisy)
    rc, lines = simulate_file(tmp_path, toml(TOP))
    assert rc == 3 and lines == ["error: t = 0.5: non-finite state"]


# --- the last-resort handler and Ctrl-C in-process ------------------------------------------


def test_an_unforeseen_exception_is_one_line_exit_1(tmp_path, monkeypatch):
    from derive.sim import simulation

    def bug(*a, **k):
        return {}["missing\nkey"]

    monkeypatch.setattr(simulation, "simulate", bug)
    scene = tmp_path / "scene.toml"
    scene.write_text(toml(TOP))
    rc, out, err = run("simulate", scene, "-o", tmp_path / "out.npz")
    assert rc == 1 and err == "error: internal error: KeyError: 'missing\\nkey'\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml"]


def test_keyboard_interrupt_in_process_is_exit_130(tmp_path, monkeypatch):
    from derive.sim import simulation

    def interrupted(*a, **k):
        raise KeyboardInterrupt

    monkeypatch.setattr(simulation, "simulate", interrupted)
    scene = tmp_path / "scene.toml"
    scene.write_text(toml(TOP))
    rc, out, err = run("simulate", scene, "-o", tmp_path / "out.npz")
    assert (rc, out, err) == (130, "", "error: interrupted\n")


def test_keyboard_interrupt_while_writing_removes_the_temporaries(tmp_path, monkeypatch):
    from derive.sim import simulation

    def interrupted(res, fh, *a, **k):
        fh.write(b"\x89PNG half")
        raise KeyboardInterrupt

    monkeypatch.setattr(simulation, "plot_result", interrupted)  # (what write_outputs calls)
    scene = tmp_path / "scene.toml"
    scene.write_text(toml(TOP))
    old = tmp_path / "out.npz"
    old.write_bytes(b"old")
    rc, out, err = run("simulate", scene, "-o", old, "--plot", tmp_path / "out.png")
    assert (rc, err) == (130, "error: interrupted\n")
    assert old.read_bytes() == b"old"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.npz", "scene.toml"]


# --- real processes and real signals --------------------------------------------------------


def start(*argv):
    """`python -m derive ...` with SIGINT delivered as in a terminal (a test runner started in
    the background may have it ignored, and the child would inherit that)."""
    return subprocess.Popen([sys.executable, "-m", "derive", *map(str, argv)], cwd=ROOT,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))


def wait_until_mapped(proc, pattern, timeout=300.0):
    """Wait until the process has mapped a file matching ``pattern`` (a regex on its
    /proc/<pid>/maps): it has reached the phase that loads it. Without /proc: a fixed wait."""
    maps = f"/proc/{proc.pid}/maps"
    end = time.monotonic() + timeout
    while time.monotonic() < end and proc.poll() is None:
        try:
            with open(maps) as f:
                if re.search(pattern, f.read(), re.M):
                    return
        except FileNotFoundError:
            time.sleep(3.0)
            return
        time.sleep(0.05)


def cpu_seconds(pid) -> float:
    """User plus system CPU seconds the process ``pid`` has used (``/proc/<pid>/stat``; a
    process that has exited but is not yet reaped still shows its totals)."""
    fields = open(f"/proc/{pid}/stat").read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def interrupt_after(proc, seconds, mapped=None):
    """SIGINT ``seconds`` after the process mapped ``mapped`` (see wait_until_mapped); returns
    (exit status, stdout, stderr, CPU seconds the process used from the signal to its exit).

    What the signal costs is counted in the process's own CPU time, not on the wall clock: on
    a loaded machine the scheduler may hold a process off its core for seconds, which says
    nothing about how soon it stops its loop. The wall clock only bounds the wait."""
    if mapped:
        wait_until_mapped(proc, mapped)
    time.sleep(seconds)
    assert proc.poll() is None, "finished before it could be interrupted"
    before = cpu_seconds(proc.pid)
    proc.send_signal(signal.SIGINT)
    # wait for the exit without reaping it, so that its CPU totals can still be read
    end = time.monotonic() + 120
    while os.waitid(os.P_PID, proc.pid, os.WEXITED | os.WNOWAIT | os.WNOHANG) is None:
        if time.monotonic() > end:
            proc.kill()
            proc.communicate()
            pytest.fail("still running 120 s after SIGINT")
        time.sleep(0.01)
    took = cpu_seconds(proc.pid) - before
    out, err = proc.communicate(timeout=60)
    return proc.returncode, out, err, took


def test_sigint_during_a_python_phase(tmp_path):
    """SciPy's solve_ivp is a Python loop: Ctrl-C there is exit 130 with one line, no file."""
    scene = tmp_path / "long.toml"
    scene.write_text(toml(with_(simulate={"t_end": 1e5, "samples": 11, "method": "scipy-rk45",
                                          "max_steps": 10**11})))
    out = tmp_path / "out.npz"
    rc, stdout, stderr, took = interrupt_after(start("simulate", scene, "-o", out), 0.5,
                                               mapped=r"scipy/integrate/")
    assert (rc, stdout, stderr) == (130, "", "error: interrupted\n")
    assert took < 2.0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["long.toml"]


@pytest.mark.parametrize("method, extra", [("rk4", {"h": 1e-6}),
                                           ("dop853", {"rtol": 1e-13, "t_end": 1e10})])
def test_sigint_inside_a_compiled_loop(tmp_path, method, extra):
    """A long run in a compiled loop stops within 0.5 s of Ctrl-C: at most 0.5 s of the
    process's CPU from the signal to its exit, the interpreter's shutdown included."""
    scene = tmp_path / "long.toml"
    scene.write_text(toml(with_(simulate={"t_end": 1e5, "samples": 11, "method": method,
                                          "max_steps": 10**12, **extra})))
    out = tmp_path / "out.npz"
    proc = start("simulate", scene, "-o", out)
    # the solver library (cache name <name>-<key>.so) is loaded: its loop is about to run
    rc, stdout, stderr, took = interrupt_after(proc, 0.5, mapped=r"-[0-9a-f]{24}\.so$")
    assert (rc, stdout, stderr) == (130, "", "error: interrupted\n")
    assert took < 0.5
    assert sorted(p.name for p in tmp_path.iterdir()) == ["long.toml"]


@pytest.mark.parametrize("name, library", [("tippe_top", "contact_sphere_viscous_run"),
                                           ("frictionless_top", "contact_point_reduced")])
def test_sigint_inside_a_compiled_contact_run(tmp_path, name, library):
    """A long contact run (the phase driver; the frictionless top's reduced loop) stops within
    0.5 s of the process's CPU after Ctrl-C, with exit 130, one line and no output file."""
    scene = tmp_path / "long.toml"
    text = (ROOT / "scenes" / "contact" / f"{name}.toml").read_text(encoding="utf-8")
    text = re.sub(r"(?m)^t_end = .*$", "t_end = 1e5\nmax_steps = 1000000000000", text)
    scene.write_text(re.sub(r"(?m)^samples = .*$", "samples = 11", text))
    out = tmp_path / "out.npz"
    proc = start("simulate", scene, "-o", out)
    rc, stdout, stderr, took = interrupt_after(proc, 0.5, mapped=library + r"-[0-9a-f]{24}\.so$")
    assert (rc, stdout, stderr) == (130, "", "error: interrupted\n")
    assert took < 0.5
    assert sorted(p.name for p in tmp_path.iterdir()) == ["long.toml"]


@pytest.mark.parametrize("argv, code", [
    (["simulate", "scenes/does-not-exist.toml"], 2),
    pytest.param(["simulate", "scenes/looping_top.toml", "--rtol", "nan"], 2, marks=pytest.mark.slow),
    (["simulate", "scenes/looping_top.toml", "-o", "/proc/x.npz"], 2),
    (["simulate", "--no-such-flag"], 2),
    pytest.param(["cache", "--bogus"], 2, marks=pytest.mark.slow),
])
def test_real_process_failures_are_one_line(argv, code):
    r = subprocess.run([sys.executable, "-m", "derive", *argv], cwd=ROOT, capture_output=True,
                       text=True, timeout=120)
    lines = errors(r.stderr)
    assert r.returncode == code and len(lines) == 1 and lines[0].startswith("error: "), r.stderr
    assert "Traceback" not in r.stderr


@pytest.fixture
def python_ctrl_c():
    """SIGINT handled as in a terminal's foreground process (a test runner started in the
    background inherits it ignored), restored afterwards."""
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, previous)


def test_a_ctrl_c_that_a_library_turns_into_another_error_is_still_exit_130(monkeypatch, capsys,
                                                                              python_ctrl_c):
    """A Ctrl-C that lands in an import NumPy rewraps (ImportError) is still an interrupt: the
    CLI's handler recorded it, so the error line is ``interrupted``, not an internal error."""
    def command(argv):
        try:
            signal.raise_signal(signal.SIGINT)
        except KeyboardInterrupt:
            raise ImportError("the C-extensions failed to import") from None
        return 0

    monkeypatch.setattr(cli, "_main", command)
    assert cli.main([]) == 130
    assert capsys.readouterr().err == "error: interrupted\n"
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler  # restored after


def test_an_import_error_without_a_ctrl_c_stays_an_internal_error(monkeypatch, capsys):
    def command(argv):
        raise ImportError("no such module")

    monkeypatch.setattr(cli, "_main", command)
    assert cli.main([]) == 1
    assert capsys.readouterr().err == "error: internal error: ImportError: no such module\n"


def test_a_recorded_ctrl_c_stops_a_scipy_run_at_its_next_step(monkeypatch):
    """A Ctrl-C the CLI recorded but a library swallowed (a finaliser) still stops SciPy's
    Python loop: each step asks for a recorded interrupt first."""
    monkeypatch.setattr(derive_errors, "SIGNALLED", [signal.SIGINT])
    with pytest.raises(KeyboardInterrupt):
        derive.simulate(with_(simulate={"t_end": 1.0, "samples": 3, "method": "scipy-rk45"}))
