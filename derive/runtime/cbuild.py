"""Compile generated C into a shared library, once, and load it with ctypes.

Builds live in a cache outside the source tree (``$DERIVE_CACHE``, default ``~/.cache/derive``)
keyed by the SHA-256 of the sources, the compiler (its command and ``--version``) and the flags
(and, for a build for this CPU's vector width, :data:`BUILDS`, the CPU), so an unchanged model is
compiled once per machine. Each build happens in a private hidden
folder (``.build-<name>-XXXXXXXX``) and is moved into place with ``os.replace``: concurrent
processes (parallel pytest workers) may both compile, but neither ever loads a half-written
library.

The cache owns only what it made, and knows it by a mark it wrote, never by a name pattern
(``$DERIVE_CACHE`` may name a folder that holds the user's own files):
* every folder it creates (a build folder, a derived model's folder under ``models/``) holds a
  :data:`MARKER` file (a cache directory tag naming derive, :data:`MARKER_TEXT`);
* every library is linked with a stamp, the symbol ``derive_build_<key>``, and has a sidecar
  ``<name>-<key>.so.sha256`` (``sha256sum`` format) naming it;
* it removes a folder only if it is a real folder (never through a symbolic link) holding that
  marker, a file only if it is a library or checksum carrying those marks, and it neither reads
  nor writes through a ``models`` entry that is not a real folder.

The cache heals itself:
* a library is verified before it is loaded: a sidecar must name it with the SHA-256 of its
  bytes, and its bytes, then the loaded library, must carry the stamp of its key (another
  library copied over it, with a checksum to match, has not); one that fails, or is not a
  file, or whose sidecar is missing or not a file, is rebuilt once, with a one-line note on
  stderr, and the next run finds it whole;
* a cache that cannot be written (read-only ``$DERIVE_CACHE``, unwritable ``HOME``) is replaced
  for the rest of the process by a private temporary folder, with a one-line warning;
* build folders left by a compile that was killed are removed once older than
  :data:`STALE_BUILD_SECONDS`.
``derive cache`` lists the cache (:func:`cache_entries`); ``derive cache --clear`` empties it
(:func:`clear_cache`), removing only what carries the marks above.

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
import secrets
import shlex
import shutil
import signal
import stat
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import dataclass
from pathlib import Path

from derive.codegen.render import TEMPLATES
from derive.errors import CompilerError, note

DEFAULT_FLAGS: tuple[str, ...] = ("-std=c99", "-O3", "-fPIC", "-fno-math-errno")
# What the generated code must survive: every warning an error, strict ISO C99.
STRICT_FLAGS: tuple[str, ...] = ("-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic")
# -O0: with the sanitizers, -O1 compiles the unrolled DOP853 stages ~7x slower.
SANITIZE_FLAGS: tuple[str, ...] = ("-std=c99", "-g", "-O0", "-fno-omit-frame-pointer",
                                   "-fsanitize=address,undefined",
                                   "-fno-sanitize-recover=undefined")
# The vector build: this CPU's vector width (-march=native) for the scalar drivers' loops over
# samples (a Taylor step's output map over a block of samples takes 4 or 8 at a time where the
# portable build's SSE2 takes 2). Such a
# library runs only on the CPU it was built for, so its key also holds that CPU's identity
# (:func:`_native_identity`). Its numbers must be the portable build's bit for bit: no fused
# multiply-add. ISO C mode contracts nothing, but gcc 12's straight-line (SLP) vectoriser still
# fuses a pair a*b - c, a*b + c into one vfmaddsub (seen in rigid_body_init with AVX-512, also
# under -ffp-contract=off and -mno-fma): it is turned off; the loops are vectorised by the loop
# vectoriser.
VECTOR_FLAGS: tuple[str, ...] = ("-march=native", "-ffp-contract=off", "-fno-tree-slp-vectorize")
# The lanes build (the Taylor batch, templates/c/taylor_lanes_driver.c.j2): the vector build with
# the lanes compiled in, and no complete peeling of small loops: peeled, the lanes' loops over W
# become straight lines the loop vectoriser never sees. The scalar drivers want the peeling
# (their loops over 4 states or 4 samples), hence two builds.
NATIVE_FLAGS: tuple[str, ...] = VECTOR_FLAGS + ("--param=max-completely-peel-times=1", "-DDERIVE_LANES")
#: The builds of a library: name -> the flags each adds to DEFAULT_FLAGS. ``portable`` runs on
#: any CPU of the architecture; ``vector`` and ``lanes`` (above) on this one, with the same
#: numbers. A compiler that refuses -march=native gets them without it (:func:`compile_library`).
BUILDS: dict[str, tuple[str, ...]] = {"portable": (), "vector": VECTOR_FLAGS, "lanes": NATIVE_FLAGS}
_NATIVE = "-march=native"
_native_refused: set[tuple[str, ...]] = set()  # the compilers that failed a build with it
STDERR_LINES = 20
STALE_BUILD_SECONDS = 600  # a build folder this old belongs to a compile that was killed
CHECKSUM = ".sha256"       # sidecar suffix: <library>.so.sha256
BUILD_PREFIX = ".build-"
# The mark of every folder the cache creates: a cache directory tag (https://bford.info/cachedir/,
# so backup tools skip the folder too) whose text names derive. Only a real folder holding this
# exact file is the cache's to remove.
MARKER = "CACHEDIR.TAG"
MARKER_TEXT = ("Signature: 8a477f597d28d172789f06886806bc55\n"
               "# This folder was made by derive's compile cache; `derive cache --clear`\n"
               "# removes it. See https://bford.info/cachedir/ for cache directory tags.\n")
# The stamp linked into every library: a symbol naming the library's full key, in a source
# file the cache adds to the compile (a name no generated source has: it is not an identifier).
STAMP_SOURCE = "derive-build-stamp.c"
# The runtime and Ctrl-C for Python (templates/c/host_sigint.c): a translation unit of its own in
# every library whose sources hold the runtime (derive_runtime.h), the model's units compiled with
# RUNTIME_LINKED so that the runtime is compiled once there; the library then exports
# derive_sigint_guard and derive_sigint_request. The runtime itself installs no signal handler.
HOST_SOURCE = "derive_host.c"
RUNTIME_HEADER = "derive_runtime.h"
RUNTIME_LINKED = "-DDERIVE_RUNTIME_LINKED"
STAMP_PREFIX = "derive_build_"
_CHECKSUM_LINE = re.compile(r"([0-9a-f]{64})  (.+)\n")
_KEY_IN_NAME = re.compile(r".+-([0-9a-f]{24})\.so")  # which stamp a library should carry
# Models derived on demand (derive.runtime.catalogue) live in MODELS: each variant in a marked folder,
# written as a hidden marked temporary (".<variant>-XXXXXXXX") and renamed into place.
MODELS = "models"

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


def mark(folder: Path) -> None:
    """Write the cache's :data:`MARKER` into ``folder``, a folder this module just created: the
    mark by which the cache later knows the folder is its own to remove."""
    (Path(folder) / MARKER).write_text(MARKER_TEXT)


def is_marked(path: str | os.PathLike) -> bool:
    """Whether ``path`` is a real folder (not a symbolic link) holding the cache's marker: a
    folder the cache made, and so may remove."""
    try:
        if not stat.S_ISDIR(os.lstat(path).st_mode):
            return False
        tag = os.path.join(path, MARKER)
        st = os.lstat(tag)
        if not stat.S_ISREG(st.st_mode) or st.st_size != len(MARKER_TEXT.encode()):
            return False
        with open(tag, encoding="utf-8", errors="replace") as f:
            return f.read() == MARKER_TEXT
    except OSError:
        return False


def remove_marked(path: str | os.PathLike) -> bool:
    """Remove ``path`` if it is a folder the cache made (:func:`is_marked`); never follows a
    symbolic link (``shutil.rmtree`` unlinks links inside, refuses one at the top). Returns
    whether it was removed."""
    if not is_marked(path):
        return False
    shutil.rmtree(path, ignore_errors=True)
    return not os.path.lexists(path)


_private_models: Path | None = None  # models derived this run, when <cache>/models is unusable
_private_models_told = False


def models_dir(root: Path | None = None, writing: bool = False) -> Path:
    """Where derived models live: ``<root>/models`` (``root``: :func:`cache_root` by default),
    unless something that is not a real folder (a symbolic link, a file) stands there: then that
    entry is left alone, neither read nor written through, and the process keeps its models in
    a private temporary folder (removed at exit), announced by a one-line warning the first
    time a model is to be written there (``writing``)."""
    global _private_models, _private_models_told
    path = (root or cache_root()) / MODELS
    try:
        st = os.lstat(path)
    except OSError:
        return path  # absent (created when a model is derived) or unreachable (reported then)
    if stat.S_ISDIR(st.st_mode):
        return path
    if _private_models is None:
        _private_models = Path(tempfile.mkdtemp(prefix="derive-models-"))
        atexit.register(shutil.rmtree, _private_models, True)
    if writing and not _private_models_told:
        _private_models_told = True
        _note(f"warning: compile cache entry {path} is not a folder ({_kind(st)}); left alone, "
              f"deriving models in {_private_models} for this run")
    return _private_models


def _kind(st: os.stat_result) -> str:
    """What a directory entry is, in words (for a note about something in the way)."""
    mode = st.st_mode
    return ("a symbolic link" if stat.S_ISLNK(mode) else "a folder" if stat.S_ISDIR(mode)
            else "a file" if stat.S_ISREG(mode) else "a special file")


def make_room(path: Path, folder: bool = False) -> None:
    """Clear the way for what the cache is about to rename to ``path`` (its own name, a hash of
    what it holds): a file, or with ``folder`` a folder. ``os.replace`` puts a file in place of a
    file or a symbolic link (never touching what the link points to), but nothing in place of a
    non-empty folder, and a folder only in place of an empty one. What is in the way is removed
    if the cache made it (:func:`is_marked`) or it is an empty folder; anything else that would
    block the rename is moved aside to ``<path>.moved-XXXXXXXX`` with a one-line note, so that
    nothing of the user's is lost."""
    try:
        is_dir = stat.S_ISDIR(os.lstat(path).st_mode)
    except OSError:
        return
    if is_dir:
        if remove_marked(path):
            return
        try:
            os.rmdir(path)
            return
        except OSError:
            pass
    elif not folder:
        return
    aside = path.with_name(f"{path.name}.moved-{secrets.token_hex(4)}")
    try:
        os.rename(path, aside)
    except FileNotFoundError:  # another process cleared it first
        return
    except OSError as exc:
        raise CompilerError(f"cannot clear {path} for the cache ({_why(exc)}); "
                            "remove it or set DERIVE_CACHE") from None
    _note(f"note: moved {path} aside to {aside.name} (the cache keeps its own "
          f"{'folder' if folder else 'file'} there)")


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


@functools.lru_cache(maxsize=None)
def _native_identity(cmd: tuple[str, ...]) -> str:
    """What ``-march=native`` means here, so a cache shared by machines of other CPUs never loads
    a library built for another: the CPU's model and instruction sets as Linux reports them
    (the first processor of ``/proc/cpuinfo``: what the compiler reads, by cpuid, to resolve
    the flag; the compiler itself is keyed by its ``--version``), or else the target macros the
    compiler defines with the flag (a preprocessor run, which the first simulation of every
    process would pay)."""
    try:
        with open("/proc/cpuinfo", encoding="utf-8", errors="replace") as f:
            first = f.read(1 << 16).split("\n\n", 1)[0]
    except OSError:
        first = ""
    keep = [line for line in first.splitlines()
            if line.split(":", 1)[0].strip() in _CPU_FIELDS]
    return "\n".join(keep) if keep else native_macros(cmd)


@functools.lru_cache(maxsize=None)
def native_macros(cmd: tuple[str, ...]) -> str:
    """The target macros the compiler ``cmd`` defines with ``-march=native`` (``#define
    __AVX2__ 1``, ...; sorted lines), "?" when it cannot be run."""
    try:
        out = subprocess.run([*cmd, _NATIVE, "-dM", "-E", "-x", "c", os.devnull],
                             capture_output=True, text=True)
    except OSError:
        return "?"
    return "\n".join(sorted(line for line in out.stdout.splitlines() if line.startswith("#define __")))


# The fields of /proc/cpuinfo that name a CPU (x86: vendor, family, model, flags; Arm: the
# implementer, part and features).
_CPU_FIELDS = frozenset({"vendor_id", "cpu family", "model", "model name", "stepping", "flags",
                         "CPU implementer", "CPU architecture", "CPU variant", "CPU part",
                         "CPU revision", "Features", "isa", "uarch"})


def _key(sources: dict[str, str], main: list[str], cmd: list[str], flags: list[str]) -> str:
    h = hashlib.sha256()
    native = [_native_identity(tuple(cmd))] if _NATIVE in flags else []
    for part in (cmd, flags, main, [_compiler_identity(tuple(cmd))], *([native] if native else [])):
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
    ``flags`` with ``-march=native`` (:data:`BUILDS`) that the compiler fails are retried
    without it, and the flag is left out of this compiler's builds for the rest of the process.
    """
    if not name.isidentifier():
        raise ValueError(f"library name {name!r} must be an identifier")
    for reserved in (STAMP_SOURCE, MARKER):
        if reserved in sources:
            raise ValueError(f"{reserved!r} is the cache's own file name, not a source name")
    mains = _mains(main, sources)
    flags = list(flags)
    if RUNTIME_HEADER in sources and HOST_SOURCE not in mains:
        sources = {**sources, HOST_SOURCE: _host_source()}
        mains.append(HOST_SOURCE)
        flags += [RUNTIME_LINKED] if RUNTIME_LINKED not in flags else []
    cmd = compiler()
    if _NATIVE in flags and tuple(cmd) in _native_refused:
        flags.remove(_NATIVE)
    key = _key(sources, mains, cmd, flags)
    with _lock:
        lib = _loaded.get(key)
        if lib is not None:
            return lib
        try:
            lib = _loaded[key] = _load_or_build(f"{name}-{key[:24]}.so", key, name, sources, mains,
                                                cmd, flags)
            return lib
        except CompilerError:
            if _NATIVE not in flags:
                raise
            # a compiler that knows no -march=native (older clang on Arm): the same build for
            # the architecture's baseline, the same numbers (see VECTOR_FLAGS)
            _native_refused.add(tuple(cmd))
    return compile_library(name, sources, main, flags)


@functools.lru_cache(maxsize=1)
def _host_source() -> str:
    return (TEMPLATES / "c" / "host_sigint.c").read_text(encoding="utf-8")


def _sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _stamp(key: str) -> str:
    """The symbol that marks a library as built for ``key``."""
    return STAMP_PREFIX + key


def _checksum(side: Path, fname: str) -> tuple[str | None, str | None]:
    """(the SHA-256 the sidecar ``side`` gives for library ``fname``, None), or (None, why not)."""
    try:
        st = os.lstat(side)
    except FileNotFoundError:
        return None, "has no checksum"
    except OSError as exc:
        return None, f"has an unreadable checksum ({_why(exc)})"
    if not stat.S_ISREG(st.st_mode):
        return None, f"has {_kind(st)} where its checksum should be"
    try:
        with open(side, "rb") as f:
            text = f.read(4096).decode("ascii")
    except (OSError, UnicodeDecodeError):
        return None, "has an unreadable checksum"
    line = _CHECKSUM_LINE.fullmatch(text)
    if line is None or line.group(2) != fname:
        return None, "has an unreadable checksum"
    return line.group(1), None


def _problem(target: Path, key: str | None = None) -> str | None:
    """Why the cached library ``target`` cannot be trusted, or None if it is a file that matches
    its checksum and carries the stamp of ``key`` (without ``key``, of the key prefix its name
    gives)."""
    try:
        st = os.lstat(target)
    except FileNotFoundError:
        return "is missing"
    except OSError as exc:
        return f"cannot be read ({_why(exc)})"
    if not stat.S_ISREG(st.st_mode):
        return f"is {_kind(st)}, not a library"
    expected, problem = _checksum(target.with_name(target.name + CHECKSUM), target.name)
    if problem is not None:
        return problem
    try:
        data = target.read_bytes()
    except OSError as exc:
        return f"cannot be read ({_why(exc)})"
    if hashlib.sha256(data).hexdigest() != expected:
        return "does not match its checksum (corrupt or truncated)"
    stamp = _stamp(key) if key is not None else _name_stamp(target.name)
    if stamp is None or stamp.encode() not in data:
        return "was not built from these sources (another library, or an older derive's)"
    return None


def _name_stamp(fname: str) -> str | None:
    """The start of the stamp a library named ``fname`` (``<name>-<key24>.so``) carries."""
    m = _KEY_IN_NAME.fullmatch(fname)
    return None if m is None else _stamp(m.group(1))


def _unload(lib: ctypes.CDLL) -> None:
    """dlclose a library that must not stay loaded: the loader reuses an open library of the same
    path, so the one rebuilt there would otherwise never be loaded."""
    try:
        import _ctypes

        _ctypes.dlclose(lib._handle)
    except (ImportError, AttributeError, OSError):
        pass


def _load(target: Path, key: str) -> tuple[ctypes.CDLL | None, str | None]:
    """(library, None) if ``target`` verifies and loads; (None, why not) otherwise."""
    problem = _problem(target, key)
    if problem is None:
        try:
            lib = ctypes.CDLL(str(target))
        except OSError as exc:
            return None, f"cannot be loaded ({str(exc).splitlines()[0] if str(exc) else exc})"
        try:  # what the caller's symbols will be looked up in: the stamp must be among them
            getattr(lib, _stamp(key))
        except AttributeError:
            _unload(lib)
            return None, "lacks the symbols it was built with (another library)"
        return lib, None
    return None, problem


def _load_or_build(fname: str, key: str, name: str, sources: dict[str, str], mains: list[str],
                   cmd: list[str], flags: list[str]) -> ctypes.CDLL:
    """Load the cached library ``fname`` if it verifies, else build it (once) and load that."""
    roots = [cache_dir()] + ([_fallback] if _fallback is not None else [])
    for root in roots:
        target = root / fname
        if os.path.lexists(target):
            lib, problem = _load(target, key)
            if lib is not None:
                return lib
            _note(f"note: cached library {target} {problem}; rebuilding it")
    target = _build(fname, key, name, sources, mains, cmd, flags)
    lib, problem = _load(target, key)
    if lib is None:
        raise CompilerError(f"the library just built for {name} ({target}) {problem}")
    return lib


def _build(fname: str, key: str, name: str, sources: dict[str, str], mains: list[str],
           cmd: list[str], flags: list[str]) -> Path:
    """Compile into a marked build folder of the cache (with the stamp of ``key``) and move the
    checksum, then the library, into place; an unwritable cache moves the build to the
    process's private cache."""
    root = writable_cache_dir()
    remove_stale_builds(root)
    note(f"compiling {name} (once: kept in the compile cache {root})")
    try:
        work = Path(tempfile.mkdtemp(prefix=f"{BUILD_PREFIX}{name}-", dir=root))
    except OSError as exc:
        raise CompilerError(f"cannot create a build folder in {root} ({_why(exc)})") from None
    try:
        mark(work)
        _write_sources(work, sources)
        (work / STAMP_SOURCE).write_text(
            "/* Written by derive's compile cache: the library's key, checked at load. */\n"
            f"const int {_stamp(key)} = 1;\n")
        out = work / fname
        _run([*cmd, *flags, "-shared", "-o", str(out), *mains, STAMP_SOURCE, "-lm"], work,
             f"compiling {name}")
        side = work / (fname + CHECKSUM)
        side.write_text(f"{_sha256(out)}  {fname}\n")
        target = root / fname
        for dest in (target.with_name(fname + CHECKSUM), target):
            make_room(dest)
        os.replace(side, target.with_name(fname + CHECKSUM))
        os.replace(out, target)  # atomic: a reader sees no library or the whole one
        return target
    finally:
        shutil.rmtree(work, ignore_errors=True)


def remove_stale_builds(root: Path, age: float = STALE_BUILD_SECONDS) -> int:
    """Remove the build folders in ``root`` (and half-written model folders in its ``models``)
    older than ``age`` seconds, left by killed compiles; returns how many were removed. Only
    folders that carry the cache's :data:`MARKER` are touched, and a ``models`` that is not a
    real folder is not looked into."""
    removed = 0
    now = time.time()
    folders = [root]
    if stat.S_ISDIR(_lmode(root / MODELS)):
        folders.append(root / MODELS)
    for folder in folders:
        try:
            entries = list(os.scandir(folder))
        except OSError:
            continue
        for e in entries:
            # In models/ the finished variants are marked too: only the hidden temporaries
            # (".<variant>-XXXXXXXX") can be a killed derivation's.
            if folder != root and not e.name.startswith("."):
                continue
            try:
                if now - e.stat(follow_symlinks=False).st_mtime > age and remove_marked(e.path):
                    removed += 1
            except OSError:
                pass
    return removed


def _lmode(path: Path) -> int:
    """The mode of ``path`` itself (a symbolic link is not followed), 0 if there is nothing."""
    try:
        return os.lstat(path).st_mode
    except OSError:
        return 0


@dataclass(frozen=True)
class CacheEntry:
    """One file or build folder in the cache, as ``derive cache`` lists it."""

    name: str
    size: int     # bytes (a folder: the sum of its files)
    status: str   # libraries: "ok" or why not; checksums: "checksum"; folders: what they hold


def _size(path: str) -> int:
    if os.path.isdir(path) and not os.path.islink(path):
        return sum(_size(os.path.join(path, n)) for n in os.listdir(path))
    return os.lstat(path).st_size


def _own_checksum(path: Path) -> bool:
    """A sidecar the cache wrote: a file holding one ``<sha256>  <its library's name>`` line."""
    fname = path.name[:-len(CHECKSUM)]
    return path.name.endswith(CHECKSUM) and _checksum(path, fname)[1] is None


def _own_library(path: Path) -> bool:
    """A library the cache built: a file named ``*.so`` that a sidecar of the cache names, or
    (its checksum lost) whose bytes carry the stamp its name gives."""
    if not (path.name.endswith(".so") and stat.S_ISREG(_lmode(path))):
        return False
    if _own_checksum(path.with_name(path.name + CHECKSUM)):
        return True
    stamp = _name_stamp(path.name)
    try:
        return stamp is not None and stamp.encode() in path.read_bytes()
    except OSError:
        return False


def _own_models(path: Path) -> list[str]:
    """The entries of ``models/`` the cache made (marked folders), if it is a real folder."""
    if not stat.S_ISDIR(_lmode(path)):
        return []
    try:
        return sorted(e.name for e in os.scandir(path) if is_marked(e.path))
    except OSError:
        return []


def cache_entries(root: Path | None = None) -> list[CacheEntry]:
    """What the cache holds (only what carries its marks: see the module docstring), sorted by
    name. Raises OSError if the cache folder exists but cannot be listed."""
    root = cache_dir() if root is None else root
    if not root.exists():
        return []
    out = []
    for name in sorted(os.listdir(root)):
        path = root / name
        if name == MODELS:
            variants = _own_models(path)
            if not variants:
                continue
            size = sum(_size(str(path / v)) for v in variants)
            done = sum(not v.startswith(".") for v in variants)
            out.append(CacheEntry(name, size, f"derived models ({done} variants)"))
        elif _own_checksum(path):
            out.append(CacheEntry(name, os.lstat(path).st_size, "checksum"))
        elif _own_library(path):
            out.append(CacheEntry(name, os.lstat(path).st_size, _problem(path) or "ok"))
        elif is_marked(path):
            try:
                size = _size(str(path))
            except OSError:
                size = 0
            out.append(CacheEntry(name, size, "build folder"))
    return out


def clear_cache(root: Path | None = None) -> tuple[int, int]:
    """Remove every library, checksum, build folder and derived model the cache made (by its
    marks, never by a name pattern); leaves anything else (``DERIVE_CACHE`` may point at a folder
    holding other files), and the cache folder itself unless it is left empty. Returns
    (entries, bytes)."""
    root = cache_dir() if root is None else root
    count = size = 0
    for e in cache_entries(root):
        path = root / e.name
        if e.name == MODELS:
            for v in _own_models(path):
                remove_marked(path / v)
            _rmdir_if_empty(path)
        elif e.status == "build folder":
            remove_marked(path)
        else:
            path.unlink()
        count += 1
        size += e.size
    _rmdir_if_empty(root)
    return count, size


def _rmdir_if_empty(path: Path) -> None:
    try:
        os.rmdir(path)  # only ever succeeds on an empty folder
    except OSError:
        pass


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
