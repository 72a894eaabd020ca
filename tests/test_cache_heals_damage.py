"""The compile cache owns only what it made (it knows its own files by
the marks it wrote, never by a name pattern, and never reaches through a symbolic link), and it
heals every damage to a cached library, checksum, derived-model description or C source once,
after which the next run is warm.

Every run goes through the command line in a fresh process with a fresh ``DERIVE_CACHE`` (what
the cache lists and clears is asked of ``derive cache`` in this process); the damaged caches are
copies of one undamaged cache (built by the same commands, and kept between runs for the exact
sources it is built from), and each healed run is compared with the undamaged run's results."""
import hashlib
import os
import re
import shlex
import shutil
import subprocess
import sys
import time
from importlib import metadata
from pathlib import Path

import numpy as np
import pytest

import compile_once
from cli_in_process import derive_main

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "scenes" / "free_symmetric.toml"  # no gravity: the cheapest model to compile
DERIVED = ("--formulation", "quaternion")  # a model not shipped in generated/: derived into models/
DAY = 86400.0  # older than any build a running compile could own


def derive_cli(cache: Path, *argv: str, cc: str | None = None) -> subprocess.CompletedProcess:
    """``python -m derive ...`` with ``DERIVE_CACHE=cache`` (and ``CC``), in a fresh process."""
    env = dict(os.environ, DERIVE_CACHE=str(cache))
    if cc is not None:
        env["CC"] = cc
    return subprocess.run([sys.executable, "-m", "derive", *argv], capture_output=True, text=True,
                          env=env, cwd=ROOT, timeout=300)


def simulate(cache: Path, out: Path, *flags: str, cc: str | None = None):
    """``derive simulate`` of the free body into ``out``; the CompletedProcess. The method is
    dop853 unless ``flags`` name one (the tests look for its library by name; auto may weigh
    the Taylor method for this body)."""
    method = () if "--method" in flags else ("--method", "dop853")
    return derive_cli(cache, "simulate", str(SCENE), "-o", str(out), *method, *flags, cc=cc)


def same_results(a: Path, b: Path) -> bool:
    x, y = np.load(a), np.load(b)
    return sorted(x.files) == sorted(y.files) and all(np.array_equal(x[k], y[k]) for k in x.files)


def snapshot(*paths: Path) -> dict:
    """Every entry under ``paths`` (links not followed): its kind, bytes and mtime."""
    out = {}
    for top in paths:
        for p in [top, *sorted(top.rglob("*"))] if top.is_dir() and not top.is_symlink() else [top]:
            st = os.lstat(p)
            body = p.read_bytes() if p.is_file() and not p.is_symlink() else os.readlink(p) \
                if p.is_symlink() else None
            out[str(p)] = (st.st_mode, st.st_mtime_ns, body)
    return out


def cache_command(cache: Path, *argv: str) -> subprocess.CompletedProcess:
    """``derive cache ...`` with ``DERIVE_CACHE=cache``, run by ``derive.cli.main`` in this process."""
    return derive_main("cache", *argv, env={"DERIVE_CACHE": str(cache)})


def listed(cache: Path) -> list[str]:
    """The names `derive cache` lists."""
    r = cache_command(cache)
    assert r.returncode == 0 and r.stderr == "", r.stderr
    return [ln.split()[0] for ln in r.stdout.splitlines()[1:-1]]


def kept(name: str, build) -> tuple[Path, Path]:
    """The cache and the results ``build(folder)`` leaves in ``folder`` (``cache``, ``ref.npz``),
    kept between runs for the exact package, templates, generated code, scene and libraries they
    come from (``compile_once.once``, keyed by the compiler too): a run is a function of these, and
    any change to one builds them afresh. The tests only copy them."""
    inputs = compile_once.files_under(ROOT / "derive", ROOT / "templates", ROOT / "generated")
    inputs[str(SCENE)] = SCENE.read_bytes()
    what = [name, sys.version, *(f"{dist} {metadata.version(dist)}" for dist in ("numpy", "sympy", "jinja2")),
            repr(sorted((k, v) for k, v in os.environ.items() if k.startswith("SYMPY_")))]
    done = compile_once.once(what, inputs, build)
    return done / "cache", done / "ref.npz"


@pytest.fixture(scope="session")
def pristine():
    """An undamaged cache with two libraries of the free body (dop853 and rk4), and the dop853
    run's results."""
    def build(top: Path) -> None:
        cache, out = top / "cache", top / "ref.npz"
        for r in (simulate(cache, out), simulate(cache, top / "rk4.npz", "--method", "rk4")):
            assert r.returncode == 0 and r.stderr == "", r.stderr

    return kept("pristine", build)


@pytest.fixture(scope="session")
def pristine_derived():
    """An undamaged cache holding a model derived on demand (the free body in quaternions) and
    its library, and the run's results."""
    def build(top: Path) -> None:
        r = simulate(top / "cache", top / "ref.npz", *DERIVED)
        assert r.returncode == 0 and r.stderr == "", r.stderr

    return kept("pristine-derived", build)


def copy_of(source: Path, cache: Path) -> Path:
    shutil.copytree(source, cache, symlinks=True)
    return cache


def library(cache: Path, method: str = "dop853") -> Path:
    (so,) = cache.glob(f"*_{method}-*.so")
    return so


def checksum_of(so: Path) -> Path:
    return so.with_name(so.name + ".sha256")


def ident(path: Path) -> tuple:
    st = os.lstat(path)
    return st.st_ino, st.st_mtime_ns


# ---------------------------------------------------------------------------------------------
# item 2: the cache owns only what it made

FOREIGN = (".backup-20240101", ".env-defaults", ".git-template", ".build-mine-abcd1234")


def foreign_files(cache: Path) -> list[Path]:
    """The user's hidden files the old name pattern took for build folders, one of them even
    named like one; old enough for a stale build."""
    cache.mkdir(parents=True, exist_ok=True)
    made = []
    for name in FOREIGN:
        path = cache / name
        if name == ".env-defaults":
            path.write_text("EDITOR=vi\n")
        else:
            path.mkdir()
            (path / "keep.txt").write_text(f"the user's {name}\n")
        old = time.time() - DAY
        os.utime(path, (old, old))
        made.append(path)
    return made


def test_foreign_hidden_names_survive_a_cold_compile_and_clear(cache, tmp_path):
    mine = foreign_files(cache)
    before = snapshot(*mine)
    r = simulate(cache, tmp_path / "out.npz")  # a cold compile: cleans stale build folders
    assert r.returncode == 0 and r.stderr == "", r.stderr
    assert snapshot(*mine) == before
    names = listed(cache)
    assert library(cache).name in names and not set(FOREIGN) & set(names)
    r = cache_command(cache, "--clear")
    # the library, the runtime's object linked into it, and their checksums
    assert r.returncode == 0 and r.stdout.startswith("removed 4 entries"), r.stdout
    assert snapshot(*mine) == before
    assert sorted(p.name for p in cache.iterdir()) == sorted(FOREIGN)  # the folder stays too


def test_clear_removes_the_cache_folder_it_leaves_empty(cache, pristine):
    copy_of(pristine[0], cache)
    r = cache_command(cache, "--clear")  # two libraries, their one runtime object, three checksums
    assert r.returncode == 0 and r.stdout.startswith("removed 6 entries"), r.stdout
    assert not cache.exists()


def outside_models(tmp_path: Path) -> Path:
    """A folder outside the cache that looks like a derive cache's models/: a killed
    derivation's marked temporary (which the cache would clean in its own models/), a variant
    and a user file."""
    from derive.runtime import cache  # the marker's name and text: what makes a folder the cache's

    outside = tmp_path / "elsewhere"
    for name in (".quaternion_sym-0123abcd-4567ef-k2j4h5g6", "quaternion_sym-0123abcd-4567ef"):
        (outside / name).mkdir(parents=True)
        (outside / name / cache.MARKER).write_text(cache.MARKER_TEXT)
        old = time.time() - DAY
        os.utime(outside / name, (old, old))
    (outside / "notes.txt").write_text("the user's own file\n")
    return outside


def test_a_models_symlink_is_never_followed_by_a_compile_or_clear(cache, tmp_path):
    outside = outside_models(tmp_path)
    cache.mkdir()
    (cache / "models").symlink_to(outside, target_is_directory=True)
    before = snapshot(outside)
    r = simulate(cache, tmp_path / "out.npz")  # a cold compile of a shipped model
    assert r.returncode == 0 and r.stderr == "", r.stderr  # nothing derived: nothing to say
    assert snapshot(outside) == before
    assert "models" not in listed(cache)
    r = cache_command(cache, "--clear")
    assert r.returncode == 0 and r.stdout.startswith("removed 4 entries"), r.stdout
    assert snapshot(outside) == before and (cache / "models").is_symlink()


@pytest.mark.slow
def test_a_models_symlink_is_not_written_through(cache, tmp_path, pristine_derived):
    """A model derived while ``models`` is a symbolic link goes to a private folder, with one
    warning; the folder the link points to is untouched and the results are right."""
    outside = outside_models(tmp_path)
    cache.mkdir()
    (cache / "models").symlink_to(outside, target_is_directory=True)
    before = snapshot(outside)
    r = simulate(cache, tmp_path / "out.npz", *DERIVED)
    lines = r.stderr.splitlines()
    assert r.returncode == 0 and len(lines) == 1, r.stderr
    assert lines[0].startswith(f"warning: compile cache entry {cache / 'models'} is not a folder")
    assert snapshot(outside) == before
    assert same_results(tmp_path / "out.npz", pristine_derived[1])


# ---------------------------------------------------------------------------------------------
# item 8: every damage healed once, the next run warm


def another_library(cache: Path) -> str:
    """Another model's valid library over this one, with a checksum to match: it verifies, but
    lacks the symbols (an undefined symbol at load, before)."""
    so, other = library(cache), library(cache, "rk4")
    shutil.copyfile(other, so)
    checksum_of(so).write_text(f"{hashlib.sha256(so.read_bytes()).hexdigest()}  {so.name}\n")
    return "was not built from these sources (another library, or an older derive's)"


def stamp_as_text_only(cache: Path) -> str:
    """A library whose bytes hold the stamp's text but which does not define it: it passes every
    check on the file, and only the lookup of the stamp symbol once loaded (ctypes'
    AttributeError) tells; the rebuilt library must then really be loaded, not the open one."""
    so = library(cache)
    (stamp,) = set(re.findall(rb"derive_build_[0-9a-f]{64}", so.read_bytes()))
    src = cache.parent / "impostor.c"
    src.write_text(f'const char *impostor_text = "{stamp.decode()}";\n')
    cc = shlex.split(os.environ.get("CC", "cc"))
    subprocess.run([*cc, "-shared", "-fPIC", "-o", str(so), str(src)], check=True, timeout=60)
    checksum_of(so).write_text(f"{hashlib.sha256(so.read_bytes()).hexdigest()}  {so.name}\n")
    return "lacks the symbols it was built with (another library)"


def folder_at_library(cache: Path) -> str:
    so = library(cache)
    so.unlink()
    (so / "sub").mkdir(parents=True)
    (so / "sub" / "mine.txt").write_text("something of the user's\n")  # moved aside, not lost
    return "is a folder, not a library"


def folder_at_checksum(cache: Path) -> str:
    side = checksum_of(library(cache))
    side.unlink()
    side.mkdir()
    return "has a folder where its checksum should be"


@pytest.mark.parametrize("damage", [another_library, folder_at_checksum,
                                    # the same healing path again: `make test-slow`
                                    pytest.param(stamp_as_text_only, marks=pytest.mark.slow),
                                    pytest.param(folder_at_library, marks=pytest.mark.slow)])
def test_a_damaged_library_is_rebuilt_once(cache, tmp_path, pristine, damage):
    copy_of(pristine[0], cache)
    so = library(cache)
    why = damage(cache)
    r = simulate(cache, tmp_path / "healed.npz")
    lines = r.stderr.splitlines()
    assert r.returncode == 0 and lines, r.stderr
    assert lines[0] == f"note: cached library {so} {why}; rebuilding it"
    assert same_results(tmp_path / "healed.npz", pristine[1])
    if damage is folder_at_library:
        (aside,) = cache.glob(so.name + ".moved-*")
        assert lines[1:] == [f"note: moved {so} aside to {aside.name} "
                             "(the cache keeps its own file there)"]
        assert (aside / "sub" / "mine.txt").read_text() == "something of the user's\n"
    else:
        assert len(lines) == 1, r.stderr
    healed = ident(so), ident(checksum_of(so))
    r = simulate(cache, tmp_path / "warm.npz")
    assert r.returncode == 0 and r.stderr == "", r.stderr
    assert (ident(so), ident(checksum_of(so))) == healed  # warm: nothing rebuilt
    assert same_results(tmp_path / "warm.npz", pristine[1])


def test_a_damaged_library_without_a_compiler_is_one_line_exit_4(cache, tmp_path, pristine):
    copy_of(pristine[0], cache)
    folder_at_checksum(cache)
    r = simulate(cache, tmp_path / "out.npz", cc=str(tmp_path / "no-such-cc"))
    assert r.returncode == 4 and len(r.stderr.splitlines()) == 1, r.stderr
    assert r.stderr.startswith("error: no working C compiler")
    assert not (tmp_path / "out.npz").exists()


def variant(cache: Path) -> Path:
    (folder,) = [p for p in (cache / "models").iterdir() if not p.name.startswith(".")]
    return folder


def truncated_description(folder: Path) -> str:
    (json_,) = (folder / "models").glob("*.json")
    json_.write_bytes(json_.read_bytes()[:100])
    return f"has a damaged models/{json_.name} (it does not match its checksum)"


def missing_description(folder: Path) -> str:
    (json_,) = (folder / "models").glob("*.json")
    json_.unlink()
    return f"is missing models/{json_.name}"


def garbage_c_source(folder: Path) -> str:
    (c,) = [p for p in (folder / "c").glob("*.c")
            if not p.name.endswith(("_solvers.c", "_taylor.c")) and not p.name.startswith("derive_")]
    c.write_text("this is not C\n}}}\n")  # used to be six lines of compiler output, exit 1
    return f"has a damaged c/{c.name} (it does not match its checksum)"


# one kind of damage in make test, each other derives the model again in make test-slow
@pytest.mark.parametrize("damage", [truncated_description, pytest.param(missing_description, marks=pytest.mark.slow),
                                    pytest.param(garbage_c_source, marks=pytest.mark.slow)])
def test_a_damaged_derived_model_is_derived_again_once(cache, tmp_path, pristine_derived, damage):
    copy_of(pristine_derived[0], cache)
    folder = variant(cache)
    why = damage(folder)
    r = simulate(cache, tmp_path / "healed.npz", *DERIVED)
    assert r.returncode == 0, r.stderr
    assert r.stderr.splitlines() == [f"note: derived model {folder} {why}; deriving it again"]
    assert same_results(tmp_path / "healed.npz", pristine_derived[1])
    healed = {p: ident(p) for p in [folder, *folder.rglob("*")]}
    r = simulate(cache, tmp_path / "warm.npz", *DERIVED)
    assert r.returncode == 0 and r.stderr == "", r.stderr
    assert {p: ident(p) for p in [folder, *folder.rglob("*")]} == healed  # not derived again
    assert same_results(tmp_path / "warm.npz", pristine_derived[1])
