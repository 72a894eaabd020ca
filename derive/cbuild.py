"""Compile generated C into a shared library, once, and load it with ctypes.

Builds live in a cache outside the source tree (``$DERIVE_CACHE``, default ``~/.cache/derive``)
keyed by the SHA-256 of the sources, the compiler (its command and ``--version``) and the flags,
so an unchanged model is compiled once per machine. Each build happens in a private temporary
directory and is moved into place with ``os.replace``: concurrent processes (parallel pytest
workers) may both compile, but neither ever loads a half-written library.

No ``-ffast-math``: the solvers rely on IEEE semantics (non-finite checks, compensated
summation). ``-std=c99`` also keeps GCC from contracting ``a*b + c`` into FMAs.
"""
from __future__ import annotations

import ctypes
import functools
import hashlib
import os
import shlex
import shutil
import subprocess
import tempfile
import threading
from pathlib import Path

from .errors import CompilerError

DEFAULT_FLAGS: tuple[str, ...] = ("-std=c99", "-O3", "-fPIC")
# What the generated code must survive: every warning an error, strict ISO C99.
STRICT_FLAGS: tuple[str, ...] = ("-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic")
# -O0: with the sanitizers, -O1 compiles the unrolled DOP853 stages ~7x slower.
SANITIZE_FLAGS: tuple[str, ...] = ("-std=c99", "-g", "-O0", "-fno-omit-frame-pointer",
                                   "-fsanitize=address,undefined",
                                   "-fno-sanitize-recover=undefined")
STDERR_LINES = 20

_loaded: dict[str, ctypes.CDLL] = {}
_lock = threading.Lock()


def cache_dir() -> Path:
    """Where compiled libraries are kept: ``$DERIVE_CACHE`` or ``~/.cache/derive``."""
    env = os.environ.get("DERIVE_CACHE")
    return Path(env).expanduser() if env else Path.home() / ".cache" / "derive"


def compiler() -> list[str]:
    """The C compiler command: ``$CC`` (may carry arguments), default ``cc``."""
    return shlex.split(os.environ.get("CC", "cc")) or ["cc"]


@functools.lru_cache(maxsize=None)
def _compiler_identity(cmd: tuple[str, ...]) -> str:
    """``<command> --version`` output: part of the cache key, and the check that it works."""
    try:
        out = subprocess.run([*cmd, "--version"], capture_output=True, text=True, timeout=60)
    except (FileNotFoundError, PermissionError, OSError) as exc:
        raise CompilerError(
            f"no working C compiler: {' '.join(cmd)!r} cannot be run ({exc.strerror or exc}); "
            "install gcc or set CC") from None
    if out.returncode != 0:
        raise CompilerError(f"no working C compiler: '{' '.join(cmd)} --version' failed; "
                            "install gcc or set CC")
    return out.stdout.strip()


def _key(sources: dict[str, str], main: list[str], cmd: list[str], flags: list[str]) -> str:
    h = hashlib.sha256()
    for part in (cmd, flags, main, [_compiler_identity(tuple(cmd))]):
        h.update(repr(part).encode())
    for name in sorted(sources):
        h.update(b"\0" + name.encode() + b"\0" + sources[name].encode())
    return h.hexdigest()


def _write_sources(folder: Path, sources: dict[str, str]) -> None:
    for name, text in sources.items():
        if Path(name).name != name:
            raise ValueError(f"source names must be plain file names, got {name!r}")
        (folder / name).write_text(text)


def _run(cmd: list[str], cwd: Path, what: str) -> None:
    try:
        proc = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    except (FileNotFoundError, PermissionError) as exc:
        raise CompilerError(f"no working C compiler: {cmd[0]!r} cannot be run "
                            f"({exc.strerror or exc}); install gcc or set CC") from None
    if proc.returncode != 0:
        lines = proc.stderr.strip().splitlines()
        head = "\n".join(lines[:STDERR_LINES])
        more = f"\n... ({len(lines) - STDERR_LINES} more lines)" if len(lines) > STDERR_LINES else ""
        raise CompilerError(f"{what} failed ({' '.join(cmd)}):\n{head}{more}")


def _mains(main: str | list[str], sources: dict[str, str]) -> list[str]:
    mains = [main] if isinstance(main, str) else list(main)
    for m in mains:
        if m not in sources:
            raise ValueError(f"main file {m!r} is not among the sources")
    return mains


def compile_library(name: str, sources: dict[str, str], main: str | list[str],
                    flags: tuple[str, ...] | list[str] = DEFAULT_FLAGS) -> ctypes.CDLL:
    """Compile ``main`` (one or more of ``sources``' file names) into a shared library and load it.

    ``sources`` maps file names to their text (headers included). The result is cached on disk
    (see :func:`cache_dir`) and in-process: a second call with the same inputs returns the same
    :class:`ctypes.CDLL` without running the compiler. Raises :class:`CompilerError` if there is
    no working compiler or the code does not compile (with the first lines of its stderr).
    """
    if not name.isidentifier():
        raise ValueError(f"library name {name!r} must be an identifier")
    mains = _mains(main, sources)
    cmd = compiler()
    flags = list(flags)
    key = _key(sources, mains, cmd, flags)
    with _lock:
        lib = _loaded.get(key)
        if lib is not None:
            return lib
        root = cache_dir()
        target = root / f"{name}-{key[:24]}.so"
        if not target.exists():
            root.mkdir(parents=True, exist_ok=True)
            with tempfile.TemporaryDirectory(prefix=f".{name}-", dir=root) as tmp:
                work = Path(tmp)
                _write_sources(work, sources)
                out = work / target.name
                _run([*cmd, *flags, "-shared", "-o", str(out), *mains, "-lm"], work,
                     f"compiling {name}")
                os.replace(out, target)  # atomic: a reader sees no library or the whole one
        lib = ctypes.CDLL(str(target))
        _loaded[key] = lib
        return lib


def check_compiles(sources: dict[str, str], main: str | list[str],
                   flags: tuple[str, ...] | list[str] = STRICT_FLAGS,
                   executable: str | os.PathLike | None = None) -> Path | None:
    """Compile ``main`` with ``flags`` (default: ``-Wall -Wextra -Werror -pedantic``).

    Without ``executable`` only compiles (``-c``) and returns None; with it, links an executable
    at that path (e.g. with :data:`SANITIZE_FLAGS`) and returns the path. Raises
    :class:`CompilerError` with the compiler's first lines of stderr on failure.
    """
    mains = _mains(main, sources)
    cmd = compiler()
    _compiler_identity(tuple(cmd))
    with tempfile.TemporaryDirectory(prefix="derive-check-") as tmp:
        work = Path(tmp)
        _write_sources(work, sources)
        if executable is None:
            for m in mains:
                _run([*cmd, *flags, "-c", "-o", "out.o", m], work,
                     f"compiling {m}")
            return None
        exe = Path(executable).resolve()
        out = work / "a.out"
        _run([*cmd, *flags, "-o", str(out), *mains, "-lm"], work, f"building {exe.name}")
        exe.parent.mkdir(parents=True, exist_ok=True)
        shutil.move(str(out), exe)
        return exe
