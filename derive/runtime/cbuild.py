"""Compile generated C into a shared library, once, and load it with ctypes.

Builds live in a cache outside the source tree (``$DERIVE_CACHE``, default ``~/.cache/derive``)
keyed by the SHA-256 of the sources, the compiler (its command and ``--version``) and the flags
(and, for a build for this CPU's vector width, :data:`BUILDS`, the CPU), so an unchanged model is
compiled once per machine. Each build happens in a private hidden
folder (``.build-<name>-XXXXXXXX``) and is moved into place with ``os.replace``, so no process
ever loads a half-written library; concurrent processes (parallel pytest workers) that need the
same library compile it once: one builds under the library's lock
(:func:`derive.runtime.cache.entry_lock`), the others wait for it and load what it built.

What in the cache is its own (a mark on every folder, a stamp and a checksum on every library),
where it is, and how it is listed and cleared live in :mod:`derive.runtime.cache`. The cache
heals itself:
* a library is verified before it is loaded (:func:`derive.runtime.cache.library_problem`, then
  the loaded library must carry the stamp of its key); one that fails is rebuilt once, with a
  one-line note on stderr, and the next run finds it whole;
* a cache that cannot be written is replaced for the rest of the process by a private
  temporary folder, with a one-line warning;
* build folders left by a compile that was killed are removed before each build.

No ``-ffast-math``: the solvers rely on IEEE semantics (non-finite checks, compensated
summation). ``-std=c99`` also keeps GCC from contracting ``a*b + c`` into FMAs.
``-fno-math-errno`` changes no value (nothing reads errno): it lets GCC fuse sin and cos of one
angle into one sincos call and inline sqrt.
"""
from __future__ import annotations

import ctypes
import functools
import hashlib
import os
import re
import shlex
import shutil
import signal
import subprocess
import tempfile
import threading
from pathlib import Path

from derive.codegen.render import TEMPLATES
from derive.errors import CompilerError, note
from derive.runtime.cache import (BUILD_PREFIX, CHECKSUM, MARKER, entry_lock, library_problem,
                                  library_roots, make_room, mark, read_plain, remove_stale_builds,
                                  stamp_symbol, warn, why, writable_cache_dir)

DEFAULT_FLAGS: tuple[str, ...] = ("-std=c99", "-O3", "-fPIC", "-fno-math-errno")
# What the generated code must survive: every warning an error, strict ISO C99.
STRICT_FLAGS: tuple[str, ...] = ("-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic")
# -O0: with the sanitizers, -O1 compiles the unrolled DOP853 stages many times slower.
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
# The lanes build (the Taylor batch, the lanes of templates/c/taylor.inc.j2): the vector build with
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
# That unit is the same in most libraries: it is compiled once per preprocessed text and
# compiler flags into an object kept in the cache (``derive_runtime-<key>.o``, with a checksum
# and a stamp like a library's, :func:`_runtime_object`) and linked into each library from there.
RUNTIME_OBJECT = "derive_runtime"
_QUOTED_INCLUDE = re.compile(r'^[ \t]*#[ \t]*include[ \t]*"([^"]+)"', re.MULTILINE)
_loaded: dict[str, ctypes.CDLL] = {}
# The runtime's unit as the preprocessor gave it, by compiler, flags, unit sources and include
# path: a process building many libraries of one flag set (the suite, a sweep over models) would
# otherwise preprocess the same unit for each; system headers are taken as fixed while it runs,
# as the compiler is (_compiler_identity). Bounded: a few flag sets are all a process uses.
_PREPROCESSED: dict[tuple, str] = {}
_PREPROCESSED_KEEP = 32
_INCLUDE_PATH_VARIABLES = ("CPATH", "C_INCLUDE_PATH", "GCC_EXEC_PREFIX", "COMPILER_PATH")
# Flags that make the preprocessor read the user's files (include folders, forced includes, a
# sysroot, response files), which may change between two builds: never remembered.
_FLAGS_READING_FILES = ("-I", "-i", "--sysroot", "-B", "@")
_lock = threading.Lock()
def compiler() -> list[str]:
    """The C compiler command: ``$CC`` (may carry arguments), default ``cc``."""
    return shlex.split(os.environ.get("CC", "cc")) or ["cc"]


def extra_flags() -> list[str]:
    """The user's own compiler flags, ``$DERIVE_CFLAGS``, put after derive's (the last ``-O``
    wins): ``-O1`` for quicker compiles of short runs, ``-g`` for a debugger. They enter the key."""
    return shlex.split(os.environ.get("DERIVE_CFLAGS", ""))


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
    ``$DERIVE_CFLAGS`` (:func:`extra_flags`) follows ``flags``. Those
    with ``-march=native`` (:data:`BUILDS`) that the compiler fails are retried
    without it, and the flag is left out of this compiler's builds for the rest of the process.
    """
    if not name.isidentifier():
        raise ValueError(f"library name {name!r} must be an identifier")
    for reserved in (STAMP_SOURCE, MARKER):
        if reserved in sources:
            raise ValueError(f"{reserved!r} is the cache's own file name, not a source name")
    mains = _mains(main, sources)
    requested, flags = flags, [*flags, *extra_flags()]
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
    return compile_library(name, sources, main, requested)


@functools.lru_cache(maxsize=1)
def _host_source() -> str:
    return (TEMPLATES / "c" / "host_sigint.c").read_text(encoding="utf-8")


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
    problem = library_problem(target, key)
    if problem is None:
        try:
            lib = ctypes.CDLL(str(target))
        except OSError as exc:
            return None, f"cannot be loaded ({str(exc).splitlines()[0] if str(exc) else exc})"
        try:  # what the caller's symbols will be looked up in: the stamp must be among them
            getattr(lib, stamp_symbol(key))
        except AttributeError:
            _unload(lib)
            return None, "lacks the symbols it was built with (another library)"
        return lib, None
    return None, problem


def _load_or_build(fname: str, key: str, name: str, sources: dict[str, str], mains: list[str],
                   cmd: list[str], flags: list[str]) -> ctypes.CDLL:
    """Load the cached library ``fname`` if it verifies, else build it (once, whatever the number
    of processes asking: under its lock) and load that."""
    for root in library_roots():
        target = root / fname
        if os.path.lexists(target):
            lib, problem = _load(target, key)
            if lib is not None:
                return lib
            warn(f"note: cached library {target} {problem}; rebuilding it")
    with entry_lock(writable_cache_dir(), fname):
        target = writable_cache_dir() / fname
        if os.path.lexists(target):  # built by the process this one waited for
            lib, _ = _load(target, key)
            if lib is not None:
                return lib
        target = _build(fname, key, name, sources, mains, cmd, flags)
    lib, problem = _load(target, key)
    if lib is None:
        raise CompilerError(f"the library just built for {name} ({target}) {problem}")
    return lib


def _build(fname: str, key: str, name: str, sources: dict[str, str], mains: list[str],
           cmd: list[str], flags: list[str]) -> Path:
    """Compile the library ``fname`` into the cache (:func:`_compile_into_cache`), linking the
    runtime's object in place of its unit (:func:`_runtime_object`)."""
    note(f"compiling {name} (once: kept in the compile cache {writable_cache_dir()})")

    def command(work: Path, out: Path) -> list[str]:
        units = list(mains)
        if HOST_SOURCE in units:  # the runtime's unit: its object, compiled once and kept
            (work / f"{RUNTIME_OBJECT}.o").write_bytes(_runtime_object(work, sources, cmd, flags))
            units[units.index(HOST_SOURCE)] = f"{RUNTIME_OBJECT}.o"
        return [*cmd, *flags, "-shared", "-o", str(out), *units, STAMP_SOURCE, "-lm"]

    stamp = ("/* Written by derive's compile cache: the library's key, checked at load. */\n"
             f"const int {stamp_symbol(key)} = 1;\n")
    return _compile_into_cache(fname, name, sources, stamp, command, f"compiling {name}")


def _compile_into_cache(fname: str, name: str, sources: dict[str, str], stamp: str, command,
                        what: str) -> Path:
    """Write ``sources`` and the ``stamp`` unit into a marked build folder of the cache, run
    ``command(work, out)`` there, and move the checksum, then ``out``, into place as ``fname``
    (atomic: a reader sees nothing or the whole file); an unwritable cache moves the build to the
    process's private cache."""
    root = writable_cache_dir()
    remove_stale_builds(root)
    try:
        work = Path(tempfile.mkdtemp(prefix=f"{BUILD_PREFIX}{name}-", dir=root))
    except OSError as exc:
        raise CompilerError(f"cannot create a build folder in {root} ({why(exc)})") from None
    try:
        mark(work)
        _write_sources(work, sources)
        (work / STAMP_SOURCE).write_text(stamp)
        out = work / fname
        _run(command(work, out), work, what)
        side = work / (fname + CHECKSUM)
        side.write_text(f"{hashlib.sha256(out.read_bytes()).hexdigest()}  {fname}\n")
        target = root / fname
        for dest in (target.with_name(fname + CHECKSUM), target):
            make_room(dest)
        os.replace(side, target.with_name(fname + CHECKSUM))
        os.replace(out, target)
        return target
    finally:
        shutil.rmtree(work, ignore_errors=True)


def _included(sources: dict[str, str], main: str) -> dict[str, str]:
    """``main`` and every source it includes by a quoted ``#include``, transitively: what its
    compile can read of ``sources``. All of ``sources`` when an include is not a plain
    ``#include "name"`` of one of them (a computed one cannot be followed)."""
    todo, unit = [main], {}
    while todo:
        name = todo.pop()
        if name in unit:
            continue
        if name not in sources:
            return dict(sources)
        unit[name] = sources[name]
        if re.search(r"^[ \t]*#[ \t]*include[ \t]*[^\s<\"]", sources[name], re.MULTILINE):
            return dict(sources)
        todo += _QUOTED_INCLUDE.findall(sources[name])
    return unit


def _preprocessed(work: Path, cmd: list[str], flags: list[str], unit: dict[str, str]) -> str:
    """:data:`HOST_SOURCE` of the sources written in ``work`` (``unit``: those it can read) as
    the preprocessor gives it with ``flags`` (``-E -P``): every file it includes and every macro
    it reads, by name or pasted, and nothing else. Run once per process for a compiler, flags,
    unit and include path (:data:`_PREPROCESSED`) unless a flag names files of the user's."""
    key = (tuple(cmd), tuple(flags), tuple(sorted(unit.items())),
           tuple(os.environ.get(name) for name in _INCLUDE_PATH_VARIABLES))
    if key in _PREPROCESSED:
        return _PREPROCESSED[key]
    _run([*cmd, *flags, "-E", "-P", "-o", "derive-runtime-unit.i", HOST_SOURCE], work,
         "preprocessing the runtime")
    text = (work / "derive-runtime-unit.i").read_text(errors="replace")
    if not any(f.startswith(_FLAGS_READING_FILES) for f in flags):  # (under compile_library's _lock)
        if len(_PREPROCESSED) >= _PREPROCESSED_KEEP:
            _PREPROCESSED.pop(next(iter(_PREPROCESSED)))
        _PREPROCESSED[key] = text
    return text


def _runtime_object(work: Path, sources: dict[str, str], cmd: list[str], flags: list[str]) -> bytes:
    """The bytes of :data:`HOST_SOURCE` (of ``sources``, written in ``work``) compiled (``-c``)
    with ``flags``: kept in the cache as ``derive_runtime-<key>.o``, verified (checksum and
    stamp) before use, built under its lock when missing or damaged (a damaged one with a
    one-line note), like a library. The key: the compiler, the unit as the preprocessor gives it
    (:func:`_preprocessed`) and the flags other than ``-D``/``-U`` (whose effect is all in that
    text), so that a macro the runtime never reads (a model's method selection) shares it."""
    unit = _included(sources, HOST_SOURCE)
    text = _preprocessed(work, cmd, flags, unit)
    key = _key({HOST_SOURCE: text}, [HOST_SOURCE, "-c"], cmd,
               [f for f in flags if not f.startswith(("-D", "-U"))])
    fname = f"{RUNTIME_OBJECT}-{key[:24]}.o"
    for root in library_roots():
        target = root / fname
        if os.path.lexists(target):
            problem = library_problem(target, key)
            if problem is None:
                return read_plain(target)
            warn(f"note: cached object {target} {problem}; rebuilding it")
    root = writable_cache_dir()
    with entry_lock(root, fname):
        target = root / fname
        if library_problem(target, key) is not None:  # else built by the process waited for
            target = _build_object(fname, key, unit, cmd, flags)
        problem = library_problem(target, key)
        if problem is not None:
            raise CompilerError(f"the runtime object just built ({target}) {problem}")
        return read_plain(target)


def _build_object(fname: str, key: str, unit: dict[str, str], cmd: list[str],
                  flags: list[str]) -> Path:
    """Compile the runtime's unit with the stamp of ``key`` into the cache as ``fname``."""
    stamp = ("/* Written by derive's compile cache: the runtime's unit with the object's key,\n"
             " * checked before the object is linked. */\n"
             f'#include "{HOST_SOURCE}"\n'
             f"const int {stamp_symbol(key)} = 1;\n")
    return _compile_into_cache(fname, RUNTIME_OBJECT, unit, stamp,
                               lambda work, out: [*cmd, *flags, "-c", "-o", str(out), STAMP_SOURCE],
                               "compiling the runtime")


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
