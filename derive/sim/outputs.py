"""Output files, all or nothing.

``check_paths`` looks at every output path before any work is done and names the first problem
(a directory, a missing or non-directory parent, no permission, a read-only or pseudo file
system such as /proc) as a :class:`SceneError` ``<path>: <what>`` (CLI exit 2).

An output never replaces an input: both ``check_paths`` and ``write_all`` take the files the
command read (the scene, the sweep file, the scene the sweep names) and refuse an output that is
one of them, compared by resolved path (symbolic links followed) and, where the output exists,
by device and inode (a hard link is the same file under another name); two outputs that are the
same file are refused alike.

``write_all`` then writes each output to a temporary file in its target's directory (so the final
rename never crosses a file system) and renames them into place only after *all* of them were
produced. If anything fails -- a writer raises, the disk fills up, Ctrl-C -- every temporary is
removed and the existing files are untouched. Should a rename fail half-way (rare: the directory
was checked), the targets already replaced are restored from hard-linked backups where the file
system allows it.

``output_format`` says which format an output path's extension names (``derive simulate -o``:
``RESULT_FORMATS``; ``--plot``: ``PLOT_FORMATS``; ``derive sweep -o``: ``TABLE_FORMATS``), and
refuses any other extension as SceneError ``<path>: <flag>: ...`` (exit 2), so that a file is
always what its name says. ``write_csv`` writes the arrays of a result as CSV.

New files get the mode the umask gives a new file (``0o666 & ~umask``), as ``open()`` would;
``tempfile.mkstemp`` alone makes them 0600. The umask is read from ``/proc/self/status`` where
it can be (setting it to read it is process-wide, so that fallback happens under a lock).
"""
from __future__ import annotations

import contextlib
import errno
import os
import stat
import tempfile
import threading
from pathlib import Path
from typing import Callable, Mapping

from derive.errors import SceneError

Writer = Callable[[object], None]  # called with a binary file object open for writing

#: ``derive simulate -o``: extension -> format (the arrays of the output file).
RESULT_FORMATS = {".npz": "npz", ".csv": "csv"}
#: ``--plot``: extension -> matplotlib ``savefig`` format.
PLOT_FORMATS = {".png": "png", ".pdf": "pdf", ".svg": "svg"}
#: ``derive sweep -o``: extension -> format (one row per point).
TABLE_FORMATS = {".parquet": "parquet", ".csv": "csv"}

_umask_lock = threading.Lock()


def umask() -> int:
    """The process's umask, without changing it where the system allows."""
    try:
        with open("/proc/self/status", encoding="ascii", errors="replace") as f:
            for line in f:
                if line.startswith("Umask:"):
                    return int(line.split()[1], 8)
    except (OSError, ValueError, IndexError):
        pass
    with _umask_lock:  # os.umask both sets and returns: set it back at once
        mask = os.umask(0o022)
        os.umask(mask)
    return mask


def _target(path: str | os.PathLike) -> Path:
    """Where ``path`` really is: a symlink is followed, so the file it points to is replaced
    (not the link); the path's own parent otherwise."""
    p = Path(path)
    return Path(os.path.realpath(p)) if p.is_symlink() else p


_WHY = {errno.EROFS: "read-only file system", errno.EACCES: "permission denied",
        errno.EPERM: "permission denied", errno.ENOSPC: "no space left on device",
        errno.EDQUOT: "disk quota exceeded",
        errno.ENOENT: "the file system takes no new files there"}  # e.g. /proc


def _why(err: OSError) -> str:
    return _WHY.get(err.errno) or err.strerror or str(err)


class _File:
    """A path's identity: its resolved path, and its (st_dev, st_ino) when it exists."""

    __slots__ = ("name", "real", "id")

    def __init__(self, name: str):
        self.name = name
        self.real = os.path.realpath(name)
        try:
            st = os.stat(name)  # follows a symbolic link, as the writer does
            self.id = (st.st_dev, st.st_ino)
        except (OSError, ValueError):
            self.id = None

    def same(self, other: "_File") -> bool:
        return self.real == other.real or (self.id is not None and self.id == other.id)


def _name_of(path) -> str:
    """``os.fspath(path)`` that is a usable file name, else SceneError (CLI exit 2)."""
    name = os.fspath(path)
    if not name or name.endswith(os.sep) or "\0" in name:
        shown = repr(name) if not name or "\0" in name else name
        raise SceneError(f"{shown}: output: not a file name")
    return name


def _check_clashes(names: list[str], inputs) -> None:
    """SceneError for an output that is one of ``inputs`` (``<output>: output: would overwrite
    the input <input>``) or the same file as an earlier output; inputs that do not exist (a
    scene given as a dict, a file removed since) have nothing to lose and are skipped."""
    ins = [f for f in (_File(os.fspath(p)) for p in inputs if p is not None) if f.id is not None]
    seen: list[_File] = []
    for name in names:
        me = _File(name)
        for f in ins:
            if me.same(f):
                raise SceneError(f"{name}: output: would overwrite the input {f.name}")
        for f in seen:
            if me.same(f):
                raise SceneError(f"{name}: output: the same file as {f.name}")
        seen.append(me)


def check_paths(paths, inputs=()) -> None:
    """Raise SceneError ``<path>: <what>`` for the first output path that cannot be written.

    Parameters
    ----------
    paths : iterable of str or os.PathLike or None
        The outputs; None is an output not asked for.
    inputs : iterable of str or os.PathLike or None
        The files the command reads (scene, sweep file, the scene a sweep names): no output may
        be one of them (by resolved path, or by inode when the output exists).

    Checked: an output that is an input, the same file named twice, the path is a directory or
    another non-regular file, its parent is missing or not a directory, and a probe file can
    actually be created (and removed) in the parent, which catches permissions, read-only
    mounts and pseudo file systems alike.
    """
    names = [_name_of(p) for p in paths if p is not None]
    _check_clashes(names, inputs)
    for name in names:
        target = _target(name)
        try:
            st = target.stat()
        except (FileNotFoundError, NotADirectoryError):
            st = None  # the parent's problem, named below
        except OSError as err:
            raise SceneError(f"{name}: output: {_why(err)}") from None
        if st is not None and stat.S_ISDIR(st.st_mode):
            raise SceneError(f"{name}: output: is a directory")
        if st is not None and not stat.S_ISREG(st.st_mode):
            raise SceneError(f"{name}: output: not a regular file")
        parent = target.parent
        check_parent(name)
        try:
            fd, probe = tempfile.mkstemp(dir=parent, prefix=f".{target.name}.", suffix=".probe")
        except OSError as err:
            raise SceneError(f"{name}: output: cannot create a file in {str(parent)!r} "
                             f"({_why(err)})") from None
        os.close(fd)
        os.unlink(probe)


def check_parent(path) -> None:
    """Raise SceneError when the folder that is to hold the output ``path`` is missing or is
    not a folder.

    One rule for every output flag, a file's (``-o``, ``--plot``, ``--fmu``, ``--to``) and a folder's
    (``export --out``, ``bench -o``, ``generate --out``): derive makes the one thing it was
    asked to write and no folder above it, as the shell's ``>`` and ``mkdir`` without ``-p``
    do, so that a mistyped path fails at once instead of leaving a tree of new folders.

    Parameters
    ----------
    path : str or os.PathLike
        The output (a file or a folder to create).

    Raises
    ------
    SceneError
        ``<path>: output: directory '<parent>' does not exist`` or ``... '<parent>' is not a
        directory`` (CLI exit 2).
    """
    name = os.fspath(path)
    parent = _target(name.rstrip(os.sep) or name).parent
    if not parent.exists():
        raise SceneError(f"{name}: output: directory {str(parent)!r} does not exist")
    if not parent.is_dir():
        raise SceneError(f"{name}: output: {str(parent)!r} is not a directory")


def write_all(outputs: Mapping[str | os.PathLike, Writer], inputs=()) -> None:
    """Write every ``{path: writer}`` output, all or nothing.

    Each writer is called with a binary file object (a temporary beside its target). Only when
    every writer has returned are the temporaries renamed onto their targets. On any exception
    (including KeyboardInterrupt) the temporaries are removed and the exception propagates;
    an ``OSError`` while writing is re-raised as SceneError ``<path>: output: <what>``.
    Before anything is written, an output that is one of ``inputs`` (the files the results were
    computed from) or the same file as another output is a SceneError (see ``check_paths``).
    """
    _check_clashes([_name_of(p) for p in outputs], inputs)
    mode = 0o666 & ~umask()  # what open(path, "w") would give a new file
    staged: list[tuple[str, Path, str]] = []  # (name, target, temporary)
    try:
        for path, writer in outputs.items():
            name = os.fspath(path)
            target = _target(name)
            try:
                fd, tmp = tempfile.mkstemp(dir=target.parent, prefix=f".{target.name}.",
                                           suffix=".part")
            except OSError as err:
                raise SceneError(f"{name}: output: cannot create a file in "
                                 f"{str(target.parent)!r} ({_why(err)})") from None
            staged.append((name, target, tmp))
            try:
                os.fchmod(fd, mode)
                with os.fdopen(fd, "wb") as fh:
                    writer(fh)
            except OSError as err:
                raise SceneError(f"{name}: output: cannot write ({_why(err)})") from None
        _commit(staged)
    except BaseException:
        for _, _, tmp in staged:
            with contextlib.suppress(FileNotFoundError):
                os.unlink(tmp)
        raise


def _commit(staged: list[tuple[str, Path, str]]) -> None:
    """Rename every temporary onto its target; if one rename fails, undo the earlier ones."""
    backups: list[str] = []
    done: list[tuple[Path, bool, str | None]] = []  # (target, existed, backup of old content)
    try:
        for name, target, tmp in staged:
            existed, backup = target.exists(), None
            if existed:
                try:
                    os.link(target, f"{tmp}.old")
                    backup = f"{tmp}.old"
                    backups.append(backup)
                except OSError:
                    pass  # no hard links here: this one rename cannot be undone
            try:
                os.replace(tmp, target)
            except OSError as err:
                raise SceneError(f"{name}: output: cannot write ({_why(err)})") from None
            done.append((target, existed, backup))
    except BaseException:
        for target, existed, backup in reversed(done):
            with contextlib.suppress(OSError):
                if backup is not None:
                    os.replace(backup, target)
                elif not existed:
                    os.unlink(target)
        raise
    finally:
        for backup in backups:
            with contextlib.suppress(FileNotFoundError):
                os.unlink(backup)


def write_data_and_plot(data, data_writers: Mapping[str, Writer], formats: Mapping[str, str], plot,
                        plot_writer, inputs=()) -> None:
    """Write a command's table or arrays (``data``: ``-o``) and its figure (``plot``:
    ``--plot``; either None when not asked for), each in the format its extension names
    (``data_writers``: format -> writer, among ``formats``; ``plot_writer(fmt)`` -> writer),
    all or nothing (:func:`write_all`); neither may be one of ``inputs`` (checked first: a
    clash with an input is what matters most), and another extension is refused before
    anything is written."""
    check_paths([data, plot], inputs=inputs)
    data_format = output_format(data, "-o", formats) if data else None
    plot_format = output_format(plot, "--plot", PLOT_FORMATS) if plot else None
    writers = {data: data_writers[data_format]} if data_format else {}
    if plot_format:
        writers[plot] = plot_writer(plot_format)
    write_all(writers, inputs=inputs)


def output_format(path, flag: str, formats: Mapping[str, str]) -> str | None:
    """The format the extension of ``path`` names among ``formats`` (extension -> format,
    matched without regard to case), None when ``path`` is None.

    Any other extension, or none, raises SceneError ``<path>: <flag>: ...`` naming the allowed
    extensions: writing PNG bytes into ``x.pdf`` or an npz into ``x.csv`` would give a file
    that is not what its name says.
    """
    if path is None:
        return None
    name = os.fspath(path)
    ext = os.path.splitext(name)[1].lower()
    if ext in formats:
        return formats[ext]
    allowed = ", ".join(formats)
    what = f"extension {ext!r} is not a format {flag} writes" if ext else "no extension"
    raise SceneError(f"{name}: {flag}: {what}; name the file with one of {allowed}")


#: Component names of the (n, 3) arrays in a CSV: inertial vectors by axis, body vectors 1-based
#: like the notes' indices (omega1 is ω̃₁).
INERTIAL_VECTORS = ("axis",)


def write_csv(fh, arrays: Mapping[str, object]) -> None:
    """Write ``arrays`` (name -> array, as in the .npz) to the binary file ``fh`` as CSV.

    Layout: first the metadata (the 0-d arrays), one comment line ``# <name>: <value>`` each;
    then one header row; then one row per sample, a column per 1-D array and per component of
    an (n, k) array (``axis_x, axis_y, axis_z`` for the inertial ``axis``, ``omega1, omega2,
    omega3`` for a body vector). Numbers are written as Python's ``repr`` of the double, the
    shortest text that reads back to the same bits. Read it with ``pandas.read_csv(path,
    comment="#")``, or with NumPy skipping the comment lines (three for a `derive simulate`
    result: method, formulation, nfev):
    ``numpy.genfromtxt(path, delimiter=",", names=True, skip_header=3)``.
    """
    import numpy as np

    header, columns, meta = [], [], {}
    for name, value in arrays.items():
        a = np.asarray(value)
        if a.ndim == 0:
            meta[name] = str(a.item())
        elif a.ndim == 1:
            header.append(name)
            columns.append(a)
        elif a.ndim == 2:
            suffixes = (("_x", "_y", "_z") if name in INERTIAL_VECTORS and a.shape[1] == 3
                        else tuple(str(k + 1) for k in range(a.shape[1])))
            header += [name + s for s in suffixes]
            columns += list(a.T)
        else:
            raise ValueError(f"{name}: a {a.ndim}-d array has no CSV columns")
    lines = [f"# {k}: {' '.join(v.split())}" for k, v in meta.items()]
    lines.append(",".join(header))
    rows = zip(*(c.tolist() for c in columns))
    lines += [",".join(map(repr, row)) for row in rows]
    fh.write(("\n".join(lines) + "\n").encode("utf-8"))
