"""Compile generated C into a shared library, once, and load it with ctypes.

Builds live in a cache outside the source tree (``$DERIVE_CACHE``, default ``~/.cache/derive``)
keyed by the SHA-256 of the sources, the compiler (its command and ``--version``) and the flags,
so an unchanged model is compiled once per machine. Each build happens in a private hidden
folder (``.build-<name>-XXXXXXXX``) and is moved into place with ``os.replace``: concurrent
processes (parallel pytest workers) may both compile, but neither ever loads a half-written
library.

The cache heals itself:
* every library ``<name>-<key>.so`` has a sidecar ``<name>-<key>.so.sha256`` (``sha256sum``
  format) with the SHA-256 of its bytes, written before the library is moved into place; a
  library is verified against it before it is loaded, and one that is missing its sidecar, does
  not match it or fails to load is rebuilt once, with a one-line note on stderr;
* a cache that cannot be written (read-only ``$DERIVE_CACHE``, unwritable ``HOME``) is replaced
  for the rest of the process by a private temporary folder, with a one-line warning;
* build folders left by a compile that was killed are removed once older than
  :data:`STALE_BUILD_SECONDS`.
``derive cache`` lists the cache (:func:`cache_entries`); ``derive cache --clear`` empties it
(:func:`clear_cache`), removing only what this module puts there.

No ``-ffast-math``: the solvers rely on IEEE semantics (non-finite checks, compensated
summation). ``-std=c99`` also keeps GCC from contracting ``a*b + c`` into FMAs.
``-fno-math-errno`` changes no value (nothing reads errno): it lets GCC fuse sin and cos of one
angle into one sincos call and inline sqrt.
"""
from __future__ import annotations

import atexit
import ctypes
import functools
import hashlib
import os
import re
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import dataclass
from pathlib import Path

from .errors import CompilerError, note

DEFAULT_FLAGS: tuple[str, ...] = ("-std=c99", "-O3", "-fPIC", "-fno-math-errno")
# What the generated code must survive: every warning an error, strict ISO C99.
STRICT_FLAGS: tuple[str, ...] = ("-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic")
# -O0: with the sanitizers, -O1 compiles the unrolled DOP853 stages ~7x slower.
SANITIZE_FLAGS: tuple[str, ...] = ("-std=c99", "-g", "-O0", "-fno-omit-frame-pointer",
                                   "-fsanitize=address,undefined",
                                   "-fno-sanitize-recover=undefined")
STDERR_LINES = 20
STALE_BUILD_SECONDS = 600  # a build folder this old belongs to a compile that was killed
CHECKSUM = ".sha256"       # sidecar suffix: <library>.so.sha256
BUILD_PREFIX = ".build-"
# What this module puts in the cache (and so what --clear may remove): libraries, their
# checksums, build folders (also the older ".<name>-XXXXXXXX" form) and sidecar temporaries.
_LIBRARY = re.compile(r"[A-Za-z_]\w*-[0-9a-f]{24}\.so(\.sha256)?")
_BUILD = re.compile(r"\.(build-)?[A-Za-z_]\w*-[a-z0-9_]{8}")
# Models derived on demand (derive.catalogue) live in MODELS; its own half-written folders
# (".<variant>-XXXXXXXX") are cleaned like build folders.
MODELS = "models"
_MODEL_TMP = re.compile(r"\..+-[a-z0-9_]{8}")

_loaded: dict[str, ctypes.CDLL] = {}
_lock = threading.Lock()
_fallback: Path | None = None  # the private cache of this process, once the real one failed


def cache_dir() -> Path:
    """Where compiled libraries are kept: ``$DERIVE_CACHE`` or ``~/.cache/derive``."""
    env = os.environ.get("DERIVE_CACHE")
    return Path(env).expanduser() if env else Path.home() / ".cache" / "derive"


def cache_root() -> Path:
    """The cache folder in use: :func:`cache_dir`, or this process's private fallback once that
    proved unwritable."""
    return _fallback or cache_dir()


def writable_cache_dir() -> Path:
    """A cache folder this process can write into: :func:`cache_dir` (created if need be), or,
    if that cannot be written, a private temporary folder used for the rest of the process
    (removed at exit), announced by a one-line warning on stderr."""
    root = cache_root()
    if root == _fallback:
        return root
    try:
        root.mkdir(parents=True, exist_ok=True)
        os.rmdir(tempfile.mkdtemp(prefix=".probe-", dir=root))
    except OSError as exc:
        return _private_cache(root, exc)
    return root


def _note(line: str) -> None:
    print(line, file=sys.stderr, flush=True)


def _why(exc: OSError) -> str:
    return exc.strerror or str(exc)


def _private_cache(root: Path, exc: OSError) -> Path:
    """The process's fallback cache (created on first use, removed at exit), with a warning."""
    global _fallback
    if _fallback is None:
        _fallback = Path(tempfile.mkdtemp(prefix="derive-cache-"))
        atexit.register(shutil.rmtree, _fallback, True)
        _note(f"warning: compile cache {root} is not writable ({_why(exc)}); "
              f"using {_fallback} for this run (set DERIVE_CACHE to a writable folder)")
    return _fallback


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
    if proc.returncode == -signal.SIGINT:  # Ctrl-C reached the compiler first: an interrupt,
        raise KeyboardInterrupt             # not a compile error
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
        if lib is None:
            lib = _load_or_build(f"{name}-{key[:24]}.so", name, sources, mains, cmd, flags)
            _loaded[key] = lib
        return lib


def _sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _problem(target: Path) -> str | None:
    """Why the cached library ``target`` cannot be trusted, or None if it matches its checksum."""
    side = target.with_name(target.name + CHECKSUM)
    try:
        expected = side.read_text().split()[0]
    except FileNotFoundError:
        return "has no checksum"
    except (OSError, UnicodeDecodeError, IndexError):
        return "has an unreadable checksum"
    try:
        actual = _sha256(target)
    except OSError as exc:
        return f"cannot be read ({_why(exc)})"
    return None if actual == expected else "does not match its checksum (corrupt or truncated)"


def _load(target: Path) -> tuple[ctypes.CDLL | None, str | None]:
    """(library, None) if ``target`` verifies and loads; (None, why not) otherwise."""
    problem = _problem(target)
    if problem is None:
        try:
            return ctypes.CDLL(str(target)), None
        except OSError as exc:
            problem = f"cannot be loaded ({str(exc).splitlines()[0] if str(exc) else exc})"
    return None, problem


def _load_or_build(fname: str, name: str, sources: dict[str, str], mains: list[str],
                   cmd: list[str], flags: list[str]) -> ctypes.CDLL:
    """Load the cached library ``fname`` if it verifies, else build it (once) and load that."""
    roots = [cache_dir()] + ([_fallback] if _fallback is not None else [])
    for root in roots:
        target = root / fname
        if target.exists():
            lib, problem = _load(target)
            if lib is not None:
                return lib
            _note(f"note: cached library {target} {problem}; rebuilding it")
    target = _build(fname, name, sources, mains, cmd, flags)
    lib, problem = _load(target)
    if lib is None:
        raise CompilerError(f"the library just built for {name} ({target}) {problem}")
    return lib


def _build(fname: str, name: str, sources: dict[str, str], mains: list[str], cmd: list[str],
           flags: list[str]) -> Path:
    """Compile into a hidden build folder of the cache and move the checksum, then the library,
    into place; an unwritable cache moves the build to the process's private cache."""
    root = writable_cache_dir()
    remove_stale_builds(root)
    note(f"compiling {name} (once: kept in the compile cache {root})")
    try:
        work = Path(tempfile.mkdtemp(prefix=f"{BUILD_PREFIX}{name}-", dir=root))
    except OSError as exc:
        raise CompilerError(f"cannot create a build folder in {root} ({_why(exc)})") from None
    try:
        _write_sources(work, sources)
        out = work / fname
        _run([*cmd, *flags, "-shared", "-o", str(out), *mains, "-lm"], work, f"compiling {name}")
        side = work / (fname + CHECKSUM)
        side.write_text(f"{_sha256(out)}  {fname}\n")
        target = root / fname
        os.replace(side, target.with_name(fname + CHECKSUM))
        os.replace(out, target)  # atomic: a reader sees no library or the whole one
        return target
    finally:
        shutil.rmtree(work, ignore_errors=True)


def remove_stale_builds(root: Path, age: float = STALE_BUILD_SECONDS) -> int:
    """Remove build folders in ``root`` (and half-written model folders in ``root/models``)
    older than ``age`` seconds, left by killed compiles; returns how many were removed."""
    removed = 0
    now = time.time()
    for folder, pattern in ((root, _BUILD), (root / MODELS, _MODEL_TMP)):
        try:
            entries = list(os.scandir(folder))
        except OSError:
            continue
        for e in entries:
            try:
                if pattern.fullmatch(e.name) and e.is_dir(follow_symlinks=False) \
                        and now - e.stat(follow_symlinks=False).st_mtime > age:
                    shutil.rmtree(e.path, ignore_errors=True)
                    removed += 1
            except OSError:
                pass
    return removed


@dataclass(frozen=True)
class CacheEntry:
    """One file or build folder in the cache, as ``derive cache`` lists it."""

    name: str
    size: int     # bytes (a folder: the sum of its files)
    status: str   # libraries: "ok" or why not; checksums: "checksum"; folders: what they hold


def _ours(name: str) -> bool:
    return bool(name == MODELS or _LIBRARY.fullmatch(name) or _BUILD.fullmatch(name))


def _size(path: str) -> int:
    if os.path.isdir(path) and not os.path.islink(path):
        return sum(_size(os.path.join(path, n)) for n in os.listdir(path))
    return os.lstat(path).st_size


def cache_entries(root: Path | None = None) -> list[CacheEntry]:
    """What the cache holds (only what this module puts there), sorted by name. Raises OSError
    if the cache folder exists but cannot be listed."""
    root = cache_dir() if root is None else root
    if not root.exists():
        return []
    out = []
    for name in sorted(os.listdir(root)):
        if not _ours(name):
            continue
        path = root / name
        try:
            size = _size(str(path))
        except OSError:
            size = 0
        if name == MODELS:
            status = (f"derived models ({sum(1 for _ in os.scandir(path))} variants)"
                      if path.is_dir() else "not a folder")
        elif name.endswith(CHECKSUM):
            status = "checksum"
        elif name.endswith(".so"):
            status = _problem(path) or "ok"
        else:
            status = "build folder"
        out.append(CacheEntry(name, size, status))
    return out


def clear_cache(root: Path | None = None) -> tuple[int, int]:
    """Remove every library, checksum and build folder from the cache; leaves anything else
    (``DERIVE_CACHE`` may point at a folder holding other files). Returns (entries, bytes)."""
    root = cache_dir() if root is None else root
    count = size = 0
    for e in cache_entries(root):
        path = root / e.name
        if path.is_dir() and not path.is_symlink():
            shutil.rmtree(path)
        else:
            path.unlink()
        count += 1
        size += e.size
    return count, size


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
