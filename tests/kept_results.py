"""A costly pure result a test computes itself (a high-precision reference integration), kept
between test runs in the suite's cache, as tests/kept_readings.py keeps the reader's claims.

A result is kept under ``$DERIVE_CACHE/kept-results/<name>/<source key>/``, named by everything
it depends on: the arguments it is computed from (``what``, by their ``repr``), the paths and
bytes of the files whose code computes it (``sources``: the test module holding the reference,
say) and the environment (:func:`derive.runtime.cache.derivation_fingerprint` without folders:
the interpreter, every installed library's version, SymPy's settings). A run computes again
whatever any of them changed; a run after one that changed nothing compares the code under test
with the same reference without computing it. A computation that raises is never kept. The
:data:`KEEP` most recently used source keys of each name stay.
"""
from __future__ import annotations

import functools
import hashlib
import os
import pickle
from pathlib import Path

from derive.runtime.cache import derivation_fingerprint

FOLDER, KEEP = "kept-results", 3


@functools.cache
def _environment() -> str:
    """The interpreter, the installed libraries and SymPy's settings (no source folder)."""
    return derivation_fingerprint([])


def source_key(sources) -> str:
    """The key of ``sources``' bytes (with their paths) and of the environment."""
    h = hashlib.sha256(_environment().encode())
    for path in sources:
        path = Path(path).resolve()
        h.update(str(path).encode() + b"\0" + hashlib.sha256(path.read_bytes()).digest())
    return h.hexdigest()[:32]


def _prune(root: Path) -> None:
    """Remove all but the :data:`KEEP` most recently used folders of ``root``."""
    folders = sorted(((f.stat().st_mtime, f) for f in root.iterdir() if f.is_dir()), reverse=True)
    for _, old in folders[KEEP:]:
        for kept in old.iterdir():
            kept.unlink(missing_ok=True)
        old.rmdir()


def kept(name: str, what, compute, sources):
    """``compute()`` read from the suite's cache under ``name``, the ``repr`` of ``what`` and
    :func:`source_key` of ``sources``; computed and kept there when it is not (or is damaged).

    Parameters
    ----------
    name : str
        The family of results (one folder of source keys, pruned on its own).
    what : object
        Every argument the result is computed from; its ``repr`` names the result.
    compute : callable
        ``compute()`` gives the result (picklable).
    sources : iterable of path
        The files whose code computes it.
    """
    return kept_in(Path(os.environ["DERIVE_CACHE"]) / FOLDER / name / source_key(sources), what, compute)


def kept_in(folder: Path, what, compute):
    """``compute()`` read from ``folder`` under the name of ``what``'s ``repr``; computed and kept
    there when it is not (or is damaged), and all but the :data:`KEEP` most recently used folders
    beside ``folder`` removed (tests/kept_readings.py keeps its readings so too)."""
    path = folder / (hashlib.sha256(repr(what).encode()).hexdigest()[:32] + ".pickle")
    try:
        value = pickle.loads(path.read_bytes())
        os.utime(folder)
        return value
    except Exception:  # not kept yet, or damaged (a cut pickle raises one of several errors)
        pass
    value = compute()
    try:  # keeping it is a saving for the next run, never a reason for this one to fail
        folder.mkdir(parents=True, exist_ok=True)
        part = path.with_suffix(f".{os.getpid()}.part")
        part.write_bytes(pickle.dumps(value))
        part.replace(path)
        _prune(folder.parent)
    except OSError:
        pass
    return value
