"""Compiles the suite repeats with the same inputs, kept in the suite's compile cache.

A compile is a function of its inputs: the bytes of every file it can read, its command line and
the compiler (``<cc> --version``, and the machine for ``-march=native``). A compile that
succeeded once for a key succeeds again for it, so a test that needs "these sources compile
cleanly under these flags" (or the executable they make) runs the compiler the first time and
reads the outcome from ``$DERIVE_CACHE/test-builds/<key>`` afterwards; any change to a source, a
flag or the compiler is another key, compiled afresh. A failure is never kept. The folder lives
in the suite's own cache (``.cache/derive-tests``), so a fresh checkout compiles everything.

Other builds that are functions of their inputs are kept the same way: a wheel and the virtual
environment it is installed in (:func:`kept_in_place`, as a venv only works where it was made),
an undamaged compile cache that the cache's healing tests copy and damage, an exported FMU
(:func:`kept_fmu`).
"""
from __future__ import annotations

import fcntl
import functools
import hashlib
import os
import platform
import shutil
import subprocess
import sys
import tempfile
from importlib import metadata
from pathlib import Path
from typing import Callable, Iterable

from derive.runtime.cache import cache_dir, entry_lock
from derive.runtime.cbuild import STRICT_FLAGS, _compiler_identity, check_compiles

CC = os.environ.get("CC", "cc")


@functools.lru_cache(maxsize=None)
def _identity(cc: str) -> str:
    # derive's own (per-process) answer to ``<cc> --version``: a test process that also builds
    # libraries then asks the compiler once for both keys
    return _compiler_identity((cc,)) + "\n" + " ".join(platform.uname())


def files_in(*folders: Path) -> dict[str, bytes]:
    """Every file of ``folders`` (not recursive), by path: what an ``-I`` can reach."""
    return {str(p): p.read_bytes() for folder in folders for p in sorted(Path(folder).iterdir())
            if p.is_file()}


def files_under(*folders: Path) -> dict[str, bytes]:
    """Every file under ``folders`` (recursive; bytecode caches left out), by path: what a run
    of the package can read from its sources, templates and generated code."""
    return {str(p): p.read_bytes() for folder in folders for p in sorted(Path(folder).rglob("*"))
            if p.is_file() and "__pycache__" not in p.parts}


def _key(what: Iterable[str], inputs: dict[str, str | bytes], cc: str) -> str:
    h = hashlib.sha256(cc.encode() + b"\0" + _identity(cc).encode())  # a wrapper may report cc's version
    for part in what:
        h.update(b"\0a" + part.encode())
    for name in sorted(inputs):
        data = inputs[name]
        h.update(b"\0n" + name.encode() + b"\0d" + (data.encode() if isinstance(data, str) else data))
    return h.hexdigest()[:32]


def once(what: Iterable[str], inputs: dict[str, str | bytes], build: Callable[[Path], None],
         cc: str = CC) -> Path:
    """The folder holding what ``build(folder)`` made for this key (``what``: the command line
    or anything else the outcome depends on; ``inputs``: name -> contents of every file the
    compile reads); ``build`` runs only when no earlier success is kept, and must raise (or
    fail an assertion) when the compile fails."""
    root = cache_dir() / "test-builds"
    done = root / _key(what, inputs, cc)
    if (done / ".ok").is_file():
        return done
    root.mkdir(parents=True, exist_ok=True)
    with entry_lock(root, done.name):  # two workers that need it at once: one builds, one waits
        if (done / ".ok").is_file():
            return done
        work = Path(tempfile.mkdtemp(prefix=".building-", dir=root))
        try:
            build(work)
            (work / ".ok").write_text("compiled cleanly\n")
            try:
                os.rename(work, done)
            except OSError:  # another worker kept the same outcome first
                if not (done / ".ok").is_file():
                    raise
        finally:
            shutil.rmtree(work, ignore_errors=True)
    return done


def kept_in_place(what: Iterable[str], inputs: dict[str, str | bytes],
                  build: Callable[[Path], None], cc: str = CC) -> Path:
    """:func:`once` for an outcome that works only where it was made (a virtual environment: its
    scripts name their interpreter by absolute path): ``build(folder)`` runs in the kept folder
    itself, under a lock the test processes share; a folder left unfinished (no ``.ok``) is
    emptied and built again."""
    root = cache_dir() / "test-builds"
    root.mkdir(parents=True, exist_ok=True)
    done = root / f"{_key(what, inputs, cc)}-in-place"
    with open(root / f"{done.name}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if (done / ".ok").is_file():
            return done
        shutil.rmtree(done, ignore_errors=True)
        done.mkdir()
        build(done)
        (done / ".ok").write_text("built cleanly\n")
    return done


def compiles_once(sources: dict[str, str], main: str | list[str], flags=None) -> None:
    """``derive.runtime.cbuild.check_compiles(sources, main, flags)`` (a clean compile of rendered
    sources, strict flags by default), kept for these exact sources, flags and compiler."""
    flags = list(STRICT_FLAGS if flags is None else flags)
    mains = [main] if isinstance(main, str) else list(main)
    once(["check", *mains, *flags], sources, lambda work: check_compiles(sources, mains, flags))


def make_once(folder: Path, *argv: str) -> subprocess.CompletedProcess:
    """``make -s -C folder *argv`` for an exported folder, kept for its exact files, arguments and
    compiler: the files the build adds to ``folder`` are kept, and copied back in (mode and all)
    when the same folder is built again. The CompletedProcess of the build, or of a kept one
    (return code 0, no output)."""
    folder = Path(folder)
    assert all(p.is_file() for p in folder.iterdir()), "a flat folder: every input is in the key"
    before = files_in(folder)
    result: list[subprocess.CompletedProcess] = []

    def build(work):
        proc = subprocess.run(["make", "-s", "-C", str(folder), *argv], capture_output=True, text=True)
        result.append(proc)
        if proc.returncode != 0:
            raise subprocess.CalledProcessError(proc.returncode, proc.args, proc.stdout, proc.stderr)
        for made in sorted(set(files_in(folder)) - set(before)):
            shutil.copy2(made, work / Path(made).name)

    try:
        done = once(["make", *argv, os.environ.get("CFLAGS", "")],
                    {Path(k).name: v for k, v in before.items()}, build)
    except subprocess.CalledProcessError:
        return result[0]
    if result:
        return result[0]
    for made in done.iterdir():
        if made.name != ".ok":
            shutil.copy2(made, folder / made.name)
    return subprocess.CompletedProcess(["make", "-s", "-C", str(folder), *argv], 0, "", "")


def kept_fmu(name: str, scene_text: str, export: Callable[[Path, Path], None], how: Iterable[str] = ()) -> Path:
    """The FMU ``export(scene, fmu)`` writes for a scene file of ``scene_text`` (``how``: anything
    else ``export`` does that the outcome depends on), kept for the exact package, templates,
    generated code, scene, libraries and compiler it is built from (:func:`once`): any change to
    one builds it again, and a failed build (``export`` raises) is not kept."""
    root = Path(__file__).resolve().parents[1]
    inputs = files_under(root / "derive", root / "templates", root / "generated")
    what = ["fmu", name, scene_text, *how, sys.version,
            *(f"{dist} {metadata.version(dist)}" for dist in ("numpy", "sympy", "jinja2")),
            repr(sorted((k, v) for k, v in os.environ.items() if k.startswith("SYMPY_") or k == "DERIVE_CFLAGS"))]

    def build(work: Path) -> None:
        scene = work / "scene.toml"
        scene.write_text(scene_text, encoding="utf-8")
        export(scene, work / f"{name}.fmu")

    return once(what, inputs, build) / f"{name}.fmu"
