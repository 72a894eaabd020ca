"""The compile cache's folder: where it is, what in it is the cache's own, and whether a library
in it is whole.

The cache (``$DERIVE_CACHE``, default ``~/.cache/derive``; see :mod:`derive.runtime.cbuild` for
what is built into it) owns only what it made, and knows it by a mark it wrote, never by a name
pattern (``$DERIVE_CACHE`` may name a folder that holds the user's own files):
* every folder it creates (a build folder, a derived model's folder under ``models/``) holds a
  :data:`MARKER` file (a cache directory tag naming derive, :data:`MARKER_TEXT`);
* every library is linked with a stamp, the symbol ``derive_build_<key>``, and has a sidecar
  ``<name>-<key>.so.sha256`` (``sha256sum`` format) naming it; so has the runtime's object
  (``derive_runtime-<key>.o``, compiled once and linked into each library);
* it removes a folder only if it is a real folder (never through a symbolic link) holding that
  marker, a file only if it is a library or checksum carrying those marks, and it neither reads
  nor writes through a ``models`` entry that is not a real folder.

A cache that cannot be written is replaced for the rest of the process by a private temporary
folder (:func:`writable_cache_dir`); build folders left by a killed compile are removed once
older than :data:`STALE_BUILD_SECONDS` (:func:`remove_stale_builds`). Processes that need the
same entry at once (parallel test workers) make it once: the first holds its lock
(:func:`entry_lock`, a file holding :data:`LOCK_TEXT`, removed when the entry is made), the others
wait and then find it made. ``derive cache`` lists the cache (:func:`cache_entries`); ``derive
cache --clear`` empties it (:func:`clear_cache`); old kept folders go by :func:`keep_newest`.
"""
from __future__ import annotations

import atexit
import contextlib
import fcntl
import hashlib
import os
import re
import secrets
import shutil
import stat
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

from derive.errors import CompilerError

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
STAMP_PREFIX = "derive_build_"
_CHECKSUM_LINE = re.compile(r"([0-9a-f]{64})  (.+)\n")
_KEY_IN_NAME = re.compile(r".+-([0-9a-f]{24})\.s?o")  # which stamp a library (object) should carry
# Models derived on demand (derive.runtime.catalogue) live in MODELS: each variant in a marked folder,
# written as a hidden marked temporary (".<variant>-XXXXXXXX") and renamed into place
# (write_folder), with a MANIFEST of its files' SHA-256 that read_folder checks.
MODELS = "models"
MANIFEST = "SHA256SUMS"  # in a derived folder: `sha256sum -c SHA256SUMS` checks it
ABSENT = "is absent"
# The mark of a lock file (:func:`entry_lock`): a file holding exactly this text is the cache's.
LOCK_TEXT = "A lock of derive's compile cache: one process makes an entry, the others wait.\n"
LOCK_SUFFIX = ".lock"


_fallback: Path | None = None  # the private cache of this process, once the real one failed




def cache_dir() -> Path:
    """Where compiled libraries are kept: ``$DERIVE_CACHE`` or ``~/.cache/derive``."""
    env = os.environ.get("DERIVE_CACHE")
    return Path(env).expanduser() if env else Path.home() / ".cache" / "derive"


def library_roots() -> list[Path]:
    """The folders a cached library is looked for in: :func:`cache_dir`, then this process's
    private fallback if it has one."""
    return [cache_dir()] + ([_fallback] if _fallback is not None else [])


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


def warn(line: str) -> None:
    print(line, file=sys.stderr, flush=True)


def why(exc: OSError) -> str:
    return exc.strerror or str(exc)


def _private_cache(root: Path, exc: OSError) -> Path:
    """The process's fallback cache (created on first use, removed at exit), with a warning."""
    global _fallback
    if _fallback is None:
        _fallback = Path(tempfile.mkdtemp(prefix="derive-cache-"))
        atexit.register(shutil.rmtree, _fallback, True)
        warn(f"warning: compile cache {root} is not writable ({why(exc)}); "
              f"using {_fallback} for this run (set DERIVE_CACHE to a writable folder)")
    return _fallback


def mark(folder: Path) -> None:
    """Write the cache's :data:`MARKER` into ``folder``, a folder this module just created: the
    mark by which the cache later knows the folder is its own to remove."""
    (Path(folder) / MARKER).write_text(MARKER_TEXT)


def is_marked(path: str | os.PathLike) -> bool:
    """Whether ``path`` is a real folder (not a symbolic link) holding the cache's marker: a
    folder the cache made, and so may remove."""
    return stat.S_ISDIR(_lmode(path)) and _holds_exactly(os.path.join(path, MARKER), MARKER_TEXT)


def _holds_exactly(path: str | os.PathLike, text: str) -> bool:
    """Whether ``path`` is a regular file (not a symbolic link) holding exactly ``text``."""
    data = text.encode()
    try:
        st = os.lstat(path)
        if not stat.S_ISREG(st.st_mode) or st.st_size != len(data):
            return False
        with open(path, "rb") as f:
            return f.read() == data
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


def keep_newest(folder: Path, prefix: str, keep: int) -> None:
    """Remove all but the ``keep`` most recently used folders the cache made (:func:`is_marked`)
    named ``<prefix>…`` in ``folder``; nothing else there is touched."""
    made = []
    for entry in os.scandir(folder):
        if entry.name.startswith(prefix) and is_marked(entry.path):
            with contextlib.suppress(OSError):
                made.append((entry.stat(follow_symlinks=False).st_mtime, entry.name))
    for _, old in sorted(made, reverse=True)[keep:]:
        remove_marked(folder / old)


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
        warn(f"warning: compile cache entry {path} is not a folder ({_kind(st)}); left alone, "
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
        raise CompilerError(f"cannot clear {path} for the cache ({why(exc)}); "
                            "remove it or set DERIVE_CACHE") from None
    warn(f"note: moved {path} aside to {aside.name} (the cache keeps its own "
          f"{'folder' if folder else 'file'} there)")


@contextlib.contextmanager
def entry_lock(folder: Path, name: str):
    """Hold the lock of making the entry ``name`` of ``folder`` (a library, a derived model):
    a process that enters while another holds it waits until that one is done, and should then
    look for the entry again before making it. The lock file (``.<name>.lock``, holding
    :data:`LOCK_TEXT`) is removed on release; one left by a killed process is removed with the
    stale build folders. Without a lock file (a folder that takes none) the entry is made
    unlocked: at worst twice, each write being atomic."""
    path = Path(folder) / f".{name}{LOCK_SUFFIX}"
    try:
        fd = os.open(path, os.O_RDWR | os.O_CREAT | os.O_NOFOLLOW, 0o644)
    except OSError:
        yield
        return
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)
        if os.fstat(fd).st_size == 0:
            os.write(fd, LOCK_TEXT.encode())
        yield
    finally:
        with contextlib.suppress(OSError):  # only the file locked here: another may have made a new one
            if os.stat(path, follow_symlinks=False).st_ino == os.fstat(fd).st_ino:
                os.unlink(path)
        os.close(fd)  # releases the lock


def is_lock(path: str | os.PathLike) -> bool:
    """Whether ``path`` is a lock file the cache wrote (:func:`entry_lock`): a regular file (not
    a symbolic link) holding exactly :data:`LOCK_TEXT`."""
    return _holds_exactly(path, LOCK_TEXT)


def stamp_symbol(key: str) -> str:
    """The symbol that marks a library as built for ``key``."""
    return STAMP_PREFIX + key


def _checksum(side: Path, fname: str) -> tuple[str | None, str | None]:
    """(the SHA-256 the sidecar ``side`` gives for library ``fname``, None), or (None, why not)."""
    try:
        st = os.lstat(side)
    except FileNotFoundError:
        return None, "has no checksum"
    except OSError as exc:
        return None, f"has an unreadable checksum ({why(exc)})"
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


def library_problem(target: Path, key: str | None = None) -> str | None:
    """Why the cached library ``target`` cannot be trusted, or None if it is a file that matches
    its checksum and carries the stamp of ``key`` (without ``key``, of the key prefix its name
    gives)."""
    try:
        st = os.lstat(target)
    except FileNotFoundError:
        return "is missing"
    except OSError as exc:
        return f"cannot be read ({why(exc)})"
    if not stat.S_ISREG(st.st_mode):
        return f"is {_kind(st)}, not a library"
    expected, problem = _checksum(target.with_name(target.name + CHECKSUM), target.name)
    if problem is not None:
        return problem
    try:
        data = target.read_bytes()
    except OSError as exc:
        return f"cannot be read ({why(exc)})"
    if hashlib.sha256(data).hexdigest() != expected:
        return "does not match its checksum (corrupt or truncated)"
    stamp = stamp_symbol(key) if key is not None else _name_stamp(target.name)
    if stamp is None or stamp.encode() not in data:
        return "was not built from these sources (another library, or an older derive's)"
    return None


def _name_stamp(fname: str) -> str | None:
    """The start of the stamp a library named ``fname`` (``<name>-<key24>.so``) carries."""
    m = _KEY_IN_NAME.fullmatch(fname)
    return None if m is None else stamp_symbol(m.group(1))


def remove_stale_builds(root: Path, age: float = STALE_BUILD_SECONDS) -> int:
    """Remove the build folders in ``root`` (and half-written model folders in its ``models``)
    and the lock files (:func:`is_lock`) older than ``age`` seconds, left by killed compiles;
    returns how many were removed. Only folders that carry the cache's :data:`MARKER` and files
    that hold :data:`LOCK_TEXT` are touched, and a ``models`` that is not a real folder is not
    looked into."""
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
                if now - e.stat(follow_symlinks=False).st_mtime <= age:
                    continue
                if is_lock(e.path):
                    os.unlink(e.path)
                    removed += 1
                elif remove_marked(e.path):
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
    """A library (or the runtime's object) the cache built: a file named ``*.so`` (``*.o``) that a
    sidecar of the cache names, or (its checksum lost) whose bytes carry the stamp its name
    gives."""
    if not (path.name.endswith((".so", ".o")) and stat.S_ISREG(_lmode(path))):
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
        elif is_lock(path):
            out.append(CacheEntry(name, os.lstat(path).st_size, "lock"))
        elif _own_library(path):
            out.append(CacheEntry(name, os.lstat(path).st_size, library_problem(path) or "ok"))
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


def read_plain(path: Path) -> bytes:
    """The bytes of ``path`` if it is a regular file (not a link, a folder or a device); else
    OSError."""
    fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK)
    try:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            raise OSError(f"{path} is not a regular file")
        with os.fdopen(fd, "rb", closefd=False) as f:
            return f.read()
    finally:
        os.close(fd)


def _manifest(folder: Path) -> tuple[list[tuple[str, str]] | None, str]:
    """([(sha256, relative path)] of ``folder``'s :data:`MANIFEST`, "") or (None, why not)."""
    try:
        if not stat.S_ISDIR(os.lstat(folder).st_mode):
            return None, "is not a folder"
        text = read_plain(folder / MANIFEST).decode("ascii")
    except FileNotFoundError:
        return None, "has no checksums"
    except (OSError, UnicodeDecodeError):
        return None, "has unreadable checksums"
    listed = re.findall(r"^([0-9a-f]{64})  ([\w./-]+)$", text, re.MULTILINE)
    if len(listed) != text.count("\n") or any(rel.startswith("/") or ".." in rel.split("/")
                                              for _, rel in listed):
        return None, "has unreadable checksums"
    return listed, ""


def read_folder(folder: Path, required: str) -> tuple[dict[str, bytes] | None, str]:
    """({relative path: bytes} of every file :func:`write_folder` wrote into ``folder``, "") if
    each matches the SHA-256 of its :data:`MANIFEST` and ``required`` is among them; else (None,
    why not), :data:`ABSENT` if there is nothing there. Files are read without following
    symbolic links out of the folder."""
    if not os.path.lexists(folder):
        return None, ABSENT
    listed, problem = _manifest(folder)
    if listed is None:
        return None, problem
    if required not in {rel for _, rel in listed}:
        return None, "has unreadable checksums"
    files = {}
    for digest, rel in listed:
        try:
            data = read_plain(folder / rel)
        except OSError:
            return None, f"is missing {rel}"
        if hashlib.sha256(data).hexdigest() != digest:
            return None, f"has a damaged {rel} (it does not match its checksum)"
        files[rel] = data
    return files, ""


def write_folder(folder: Path, files: dict[str, str], required: str, replace: bool = False) -> None:
    """Write ``files`` ({relative path: text}, UTF-8) with the cache's marker and a
    :data:`MANIFEST` of them into ``folder``, atomically: a reader sees no folder or the whole
    one. A damaged folder already there is replaced: removed if the cache made it (marked),
    else moved aside (:func:`make_room`); a whole one (another process got there first, with
    the same content, the name being a hash of it) is kept, unless ``replace`` (a folder whose
    content grows under one name): then a whole one the cache made is replaced too."""
    folder.parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f".{folder.name}-", dir=folder.parent))
    try:
        mark(tmp)
        sums = []
        for rel, text in sorted(files.items()):
            path = tmp / rel
            path.parent.mkdir(parents=True, exist_ok=True)
            data = text.encode("utf-8")
            path.write_bytes(data)
            sums.append(f"{hashlib.sha256(data).hexdigest()}  {rel}\n")
        (tmp / MANIFEST).write_text("".join(sums), encoding="ascii")  # last: the folder is whole
        for attempt in range(2):
            try:
                os.replace(tmp, folder)
                return
            except OSError:
                if attempt or (read_folder(folder, required)[0] is not None
                               and not (replace and is_marked(folder))):
                    return
                # A damaged folder in the way: the cache's own goes (into a marked trash
                # first, so the name is free at once), anything else is moved aside.
                if is_marked(folder):
                    trash = Path(tempfile.mkdtemp(prefix=f".{folder.name}-", dir=folder.parent))
                    mark(trash)
                    with contextlib.suppress(OSError):
                        os.replace(folder, trash / "old")
                    remove_marked(trash)
                else:
                    make_room(folder, folder=True)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def derivation_fingerprint(folders) -> str:
    """SHA-256 of every input of a derivation run in a fresh process: each file under
    ``folders`` (the package's source, the templates: path and bytes, ``__pycache__`` left out),
    the interpreter (``sys.version``, its implementation), the name and version of every
    installed distribution (SymPy, mpmath, Jinja2, NumPy, gmpy2, …: the whole environment, so
    that no library a derivation reaches is missed) and the ``SYMPY_*`` environment variables
    (the ground types SymPy computes with)."""
    import importlib.metadata  # only when a derivation's cache is consulted

    h = hashlib.sha256()
    for base in folders:
        base = Path(base)
        h.update(b"folder\0" + base.name.encode() + b"\0")
        for path in sorted(p for p in base.rglob("*") if p.is_file() and "__pycache__" not in p.parts):
            h.update(path.relative_to(base).as_posix().encode() + b"\0")
            h.update(hashlib.sha256(path.read_bytes()).digest())
    h.update(repr((sys.version, sys.implementation.name, sys.implementation.version)).encode())
    dists = sorted({(d.metadata["Name"] or "", d.version) for d in importlib.metadata.distributions()})
    h.update(repr(dists).encode())
    h.update(repr(sorted((k, v) for k, v in os.environ.items() if k.startswith("SYMPY_"))).encode())
    return h.hexdigest()


def _rmdir_if_empty(path: Path) -> None:
    try:
        os.rmdir(path)  # only ever succeeds on an empty folder
    except OSError:
        pass
