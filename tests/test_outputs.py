"""Output files, all or nothing (derive.sim.outputs), and the simulate command's use of them."""
import contextlib
import errno
import io
import os
import stat

import numpy as np
import pytest

from derive import SceneError, cli
from derive.sim import outputs
from small_scenes import HEAVY_TOP

SCENE = HEAVY_TOP


@pytest.fixture
def umask():
    """Set the umask for one test, then put the old one back."""
    old = os.umask(0o022)
    yield os.umask
    os.umask(old)


def listing(folder):
    return sorted(p.name for p in folder.iterdir())


def run(*argv):
    """cli.main in-process: (exit status, stdout, stderr)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = cli.main([str(a) for a in argv])
    return rc, out.getvalue(), err.getvalue()


def error_lines(stderr):
    """stderr without the cache's healing notes (a stale cache may legitimately print them)."""
    return [ln for ln in stderr.splitlines() if not ln.startswith("note: cached library")]


# --- write_all ----------------------------------------------------------------------------


def test_write_all_writes_every_file(tmp_path):
    a, b = tmp_path / "a.bin", tmp_path / "b.bin"
    outputs.write_all({a: lambda f: f.write(b"AAA"), str(b): lambda f: f.write(b"BB")})
    assert a.read_bytes() == b"AAA" and b.read_bytes() == b"BB"
    assert listing(tmp_path) == ["a.bin", "b.bin"]


@pytest.mark.parametrize("exc", [RuntimeError("plot failed"), KeyboardInterrupt()])
def test_a_failing_writer_leaves_existing_files_and_no_temporaries(tmp_path, exc):
    a, b = tmp_path / "a.npz", tmp_path / "b.png"
    a.write_bytes(b"old a")

    def boom(f):
        f.write(b"half a plot")
        raise exc

    with pytest.raises(type(exc)):
        outputs.write_all({a: lambda f: f.write(b"new a"), b: boom})
    assert a.read_bytes() == b"old a"
    assert listing(tmp_path) == ["a.npz"]


def test_an_os_error_while_writing_names_the_path(tmp_path):
    a = tmp_path / "a.npz"

    def full(f):
        raise OSError(errno.ENOSPC, "No space left on device")

    with pytest.raises(SceneError, match=r"a\.npz: output: cannot write \(no space left on device\)"):
        outputs.write_all({a: full})
    assert listing(tmp_path) == []


def test_a_failed_rename_restores_the_targets_already_replaced(tmp_path, monkeypatch):
    a, b = tmp_path / "a", tmp_path / "b"
    a.write_bytes(b"old a")
    b.write_bytes(b"old b")
    real = os.replace
    calls = []

    def flaky(src, dst):
        calls.append(dst)
        if str(dst) == str(b):
            raise OSError(errno.EIO, "Input/output error")
        return real(src, dst)

    monkeypatch.setattr(outputs.os, "replace", flaky)
    with pytest.raises(SceneError, match="b: output: cannot write"):
        outputs.write_all({a: lambda f: f.write(b"new a"), b: lambda f: f.write(b"new b")})
    assert str(b) in map(str, calls)  # the failure happened after a was replaced
    assert a.read_bytes() == b"old a" and b.read_bytes() == b"old b"
    assert listing(tmp_path) == ["a", "b"]


def test_a_symlink_is_written_through(tmp_path):
    real = tmp_path / "data" / "out.npz"
    real.parent.mkdir()
    real.write_bytes(b"old")
    link = tmp_path / "link.npz"
    link.symlink_to(real)
    outputs.write_all({link: lambda f: f.write(b"new")})
    assert link.is_symlink() and real.read_bytes() == b"new"


@pytest.mark.parametrize("mask, mode", [(0o022, 0o644), (0o077, 0o600), (0o002, 0o664)])
def test_new_files_get_the_mode_the_umask_gives(tmp_path, umask, mask, mode):
    umask(mask)
    assert outputs.umask() == mask
    target = tmp_path / "out.bin"
    outputs.write_all({target: lambda f: f.write(b"x")})
    assert stat.S_IMODE(target.stat().st_mode) == mode
    # the same as open() gives a new file
    plain = tmp_path / "plain"
    plain.write_bytes(b"x")
    assert stat.S_IMODE(plain.stat().st_mode) == mode


def test_overwriting_a_0644_file_keeps_0644(tmp_path, umask):
    umask(0o022)
    target = tmp_path / "out.npz"
    target.write_bytes(b"old")
    target.chmod(0o644)
    outputs.write_all({target: lambda f: f.write(b"new")})
    assert stat.S_IMODE(target.stat().st_mode) == 0o644 and target.read_bytes() == b"new"


# --- check_paths ----------------------------------------------------------------------------


@pytest.mark.parametrize("make, what", [
    (lambda d: d / "sub", "is a directory"),
    (lambda d: d / "missing" / "out.npz", "does not exist"),
    (lambda d: d / "file" / "out.npz", "is not a directory"),
    (lambda d: "/proc/out.npz", "cannot create a file in '/proc'"),
    (lambda d: "/dev/null", "not a regular file"),
])
def test_check_paths_names_the_problem(tmp_path, make, what):
    (tmp_path / "sub").mkdir()
    (tmp_path / "file").write_text("x")
    path = make(tmp_path)
    with pytest.raises(SceneError) as err:
        outputs.check_paths([None, path])
    assert str(err.value).startswith(f"{path}: output: ") and what in str(err.value)
    assert sorted(listing(tmp_path)) == ["file", "sub"]  # the probe file is gone


def test_check_paths_refuses_the_same_file_twice(tmp_path):
    with pytest.raises(SceneError, match="the same file as"):
        outputs.check_paths([tmp_path / "x.npz", str(tmp_path / "." / "x.npz")])


@pytest.mark.skipif(os.geteuid() == 0, reason="root may write into a 0555 folder")
def test_check_paths_unwritable_folder(tmp_path):
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o555)
    try:
        with pytest.raises(SceneError, match="permission denied"):
            outputs.check_paths([ro / "out.npz"])
    finally:
        ro.chmod(0o755)


def test_check_paths_accepts_writable_paths(tmp_path):
    (tmp_path / "old.npz").write_bytes(b"old")
    outputs.check_paths([tmp_path / "old.npz", tmp_path / "new.png", None])
    assert listing(tmp_path) == ["old.npz"]


# --- the simulate command -------------------------------------------------------------------


@pytest.fixture
def scene(tmp_path):
    path = tmp_path / "scene.toml"
    path.write_text(SCENE)
    return path


def test_plot_into_a_directory_keeps_the_existing_output(tmp_path, scene):
    """`-o old.npz --plot d` with d a directory replaced old.npz and left a
    temporary behind."""
    old = tmp_path / "old.npz"
    old.write_text("old\n")
    (tmp_path / "d").mkdir()
    rc, out, err = run("simulate", scene, "-o", old, "--plot", tmp_path / "d")
    assert rc == 2 and out == ""
    assert error_lines(err) == [f"error: {tmp_path / 'd'}: output: is a directory"]
    assert old.read_text() == "old\n"
    assert listing(tmp_path) == ["d", "old.npz", "scene.toml"] and listing(tmp_path / "d") == []


@pytest.mark.parametrize("target", ["d", "missing/out.npz", "/proc/out.npz"])
def test_bad_output_path_is_exit_2_before_the_run(tmp_path, scene, target, monkeypatch):
    (tmp_path / "d").mkdir()
    from derive.sim import simulation

    def never(*a, **k):
        raise AssertionError("simulate ran although the output path was known to be bad")

    monkeypatch.setattr(simulation, "simulate", never)
    path = target if target.startswith("/") else tmp_path / target
    rc, out, err = run("simulate", scene, "-o", path)
    lines = error_lines(err)
    assert rc == 2 and len(lines) == 1 and lines[0].startswith(f"error: {path}: output: ")
    assert listing(tmp_path) == ["d", "scene.toml"]


def test_failing_plot_after_the_npz_leaves_nothing(tmp_path, scene, monkeypatch):
    old = tmp_path / "out.npz"
    old.write_bytes(b"old")
    from derive.sim import simulation

    def full(res, fh, *a, **k):
        fh.write(b"\x89PNG partial")
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(simulation, "plot_result", full)  # (what write_outputs calls)
    rc, out, err = run("simulate", scene, "-o", old, "--plot", tmp_path / "out.png")
    assert rc == 2 and error_lines(err) == [
        f"error: {tmp_path / 'out.png'}: output: cannot write (no space left on device)"]
    assert old.read_bytes() == b"old" and listing(tmp_path) == ["out.npz", "scene.toml"]


def test_simulate_writes_both_outputs_with_umask_modes(tmp_path, scene, umask):
    umask(0o027)
    npz, png = tmp_path / "out.npz", tmp_path / "out.png"
    rc, out, err = run("simulate", scene, "-o", npz, "--plot", png)
    assert rc == 0, err
    assert listing(tmp_path) == ["out.npz", "out.png", "scene.toml"]
    for f in (npz, png):
        assert stat.S_IMODE(f.stat().st_mode) == 0o640
    with np.load(npz) as data:
        assert data["t"].shape == (3,) and np.all(np.isfinite(data["beta"]))
    assert png.read_bytes()[:4] == b"\x89PNG"
