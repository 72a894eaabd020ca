"""`derive generate` / `make derive`: every file of ``generated/``, and keeping it in step.

The one job that knows every stage: the model kernels (:mod:`derive.codegen.sources`), the
lecture's verification and derivation reports (:mod:`derive.lecture.report`), and the reference
pages written from the registries (:mod:`derive.sim.scene_doc`). :func:`generate_all` returns
every file as text; :func:`write` and :func:`stale` compare that against a directory. Nothing
here reads the clock or iterates over unordered collections, so two runs produce identical bytes.

``generate_all(cache=True)`` (what ``derive generate`` runs) keeps the files in the compile cache,
in a folder of ``models/`` named by :func:`derivation_key`, a hash of every input of the
derivation: a repeated run with unchanged sources reads them back instead of deriving again. The
folder is checked against its SHA-256 manifest; one that does not verify is derived again. Only a
fresh process may use it: the key cannot see what a process changed in itself (a registered toy
effect, a patched function), so the default, for callers inside a longer process, is to derive.
"""
from __future__ import annotations

import concurrent.futures
import contextlib
import functools
import multiprocessing
import os
import sys
from pathlib import Path

from derive.codegen.render import TEMPLATES, render
from derive.codegen.sources import model_sources, shipped_keys
from derive.contact.sources import generated_sources as contact_sources  # contact hook
from derive.lecture import report
from derive.runtime.cache import (ABSENT, derivation_fingerprint, keep_newest, models_dir, read_folder,
                                  writable_cache_dir, write_folder)
from derive.sim import scene_doc
from derive.sim.outputs import write_all
from derive.symbolic.models import build

PACKAGE = Path(__file__).resolve().parent
#: The cache's folders of generated files are named ``<PREFIX><key>``; the newest ``KEEP`` stay.
PREFIX, KEEP = "generated-", 3
#: A file every generation writes (the cache's check that a folder holds a whole generation).
REQUIRED = "numpy/__init__.py"


def _sources_of(names) -> dict[str, str]:
    keys = shipped_keys()
    files: dict[str, str] = {}
    for name in names:
        files.update(model_sources(build(*keys[name])))
    return files


def generate_all(models=None, cache: bool = False) -> dict[str, str]:
    """Every generated file, keyed by its path relative to generated/ (with ``models``, only
    those models' files).

    The model kernels and the two reports are independent derivations; on a machine with more
    than one core the kernels are derived in a forked worker while this process writes the
    reports (the results are merged by file name, so the output does not depend on timing).
    With ``cache`` (a fresh process only: see the module docstring) every file comes from the
    compile cache when a generation from the same inputs is kept there, and is kept there
    otherwise.
    """
    names = [n for n in shipped_keys() if models is None or n in models]
    if models is not None:
        return dict(sorted(_sources_of(names).items()))
    return dict(_cached_everything() if cache else _generate_everything())


def derivation_key() -> str:
    """The hash naming a generation in the cache: :func:`derive.runtime.cache.derivation_fingerprint`
    of this package's source and the templates (with the interpreter, the installed libraries'
    versions and SymPy's settings)."""
    return derivation_fingerprint((PACKAGE, TEMPLATES))[:32]


@functools.lru_cache(maxsize=1)
def _cached_everything() -> tuple:
    """:func:`_generate_everything` read from the compile cache, or derived and kept there."""
    name = PREFIX + derivation_key()
    folder = models_dir() / name
    files, problem = read_folder(folder, REQUIRED)
    if files is not None:
        with contextlib.suppress(OSError):  # just used: keep_newest keeps the most recently used
            os.utime(folder)
        return tuple(sorted((rel, data.decode("utf-8")) for rel, data in files.items()))
    if problem != ABSENT:
        print(f"note: cached generation {folder} {problem}; deriving it again", file=sys.stderr, flush=True)
    everything = _generate_everything()
    folder = models_dir(writable_cache_dir(), writing=True) / name
    try:  # keeping it is a saving for the next run, never a reason for this one to fail
        write_folder(folder, dict(everything), REQUIRED)
        keep_newest(folder.parent, PREFIX, KEEP)
    except OSError as exc:
        print(f"note: cannot keep the generation in {folder} ({exc.strerror or exc})", file=sys.stderr,
              flush=True)
    return everything


@functools.lru_cache(maxsize=1)
def _generate_everything() -> tuple:
    """All files, computed once per process (the derivations are pure)."""
    names = list(shipped_keys())
    files: dict[str, str] = {"numpy/__init__.py": render("numpy/__init__.py.j2", models=names)}
    files.update(scene_doc.documents())
    if (os.cpu_count() or 1) > 1 and "fork" in multiprocessing.get_all_start_methods():
        # Two workers derive the contact kernels (the costliest part, first) and the models'
        # (split so that each reduced model shares a worker with its u = cos β form) while this
        # process writes the reports.
        ctx = multiprocessing.get_context("fork")
        with concurrent.futures.ProcessPoolExecutor(max_workers=2, mp_context=ctx) as pool:
            parts = [pool.submit(contact_sources)] + [pool.submit(_sources_of, names[i::2]) for i in range(2)]
            files.update(report.documents())
            for part in parts:
                files.update(part.result())
    else:
        files.update(contact_sources())  # contact hook: the kernels of tops on a table, full and reduced
        files.update(report.documents())
        files.update(_sources_of(names))
    return tuple(sorted(files.items()))


def _atomic_write(path: Path, text: str) -> None:
    """Write ``text`` (UTF-8, newlines as given) atomically with the umask's mode."""
    path.parent.mkdir(parents=True, exist_ok=True)
    write_all({path: lambda fh: fh.write(text.encode("utf-8"))})


def stale(files: dict[str, str], out: Path) -> list[str]:
    """Paths whose content in ``out`` differs from ``files`` (or is missing, or is extra)."""
    bad = [rel for rel, text in files.items()
           if not (out / rel).is_file() or (out / rel).read_text(encoding="utf-8") != text]
    if out.is_dir():
        present = {p.relative_to(out).as_posix() for p in out.rglob("*") if p.is_file()
                   and "__pycache__" not in p.parts}
        bad += sorted(present - set(files))
    return sorted(bad)


def write(files: dict[str, str], out: Path) -> list[str]:
    """Write the files that changed; remove generated files no longer produced. Returns paths written."""
    changed = stale(files, out)
    for rel in changed:
        if rel in files:
            _atomic_write(out / rel, files[rel])
        else:
            (out / rel).unlink()
    return changed
