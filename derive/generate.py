"""`derive generate` / `make derive`: every file of ``generated/``, and keeping it in step.

The one job that knows every stage: the model kernels (:mod:`derive.codegen.sources`), the
lecture's verification and derivation reports (:mod:`derive.lecture.report`), and the reference
pages written from the registries (:mod:`derive.sim.scene_doc`). :func:`generate_all` returns
every file as text; :func:`write` and :func:`stale` compare that against a directory. Nothing
here reads the clock or iterates over unordered collections, so two runs produce identical bytes.
"""
from __future__ import annotations

import concurrent.futures
import functools
import multiprocessing
import os
from pathlib import Path

from derive.codegen.render import render
from derive.codegen.sources import model_sources, shipped_keys
from derive.contact.sources import generated_sources as contact_sources  # contact hook
from derive.lecture import report
from derive.sim import scene_doc
from derive.sim.outputs import write_all
from derive.symbolic.models import build


def _sources_of(names) -> dict[str, str]:
    keys = shipped_keys()
    files: dict[str, str] = {}
    for name in names:
        files.update(model_sources(build(*keys[name])))
    return files


def generate_all(models=None) -> dict[str, str]:
    """Every generated file, keyed by its path relative to generated/.

    The model kernels and the two reports are independent derivations; on a machine with more
    than one core the kernels are derived in a forked worker while this process writes the
    reports (the results are merged by file name, so the output does not depend on timing).
    """
    names = [n for n in shipped_keys() if models is None or n in models]
    if models is not None:
        return dict(sorted(_sources_of(names).items()))
    return dict(_generate_everything())


@functools.lru_cache(maxsize=1)
def _generate_everything() -> tuple:
    """All files, computed once per process (the derivations are pure)."""
    names = list(shipped_keys())
    files: dict[str, str] = {"numpy/__init__.py": render("numpy/__init__.py.j2", models=names)}
    files.update(scene_doc.documents())
    files.update(contact_sources())  # contact hook: the kernels of tops on a table, full and reduced
    if (os.cpu_count() or 1) > 1 and "fork" in multiprocessing.get_all_start_methods():
        # Two workers derive the kernels (split so the costly Lagrangian models are shared out)
        # while this process writes the reports.
        ctx = multiprocessing.get_context("fork")
        with concurrent.futures.ProcessPoolExecutor(max_workers=2, mp_context=ctx) as pool:
            parts = [pool.submit(_sources_of, names[i::2]) for i in range(2)]
            files.update(report.documents())
            for part in parts:
                files.update(part.result())
    else:
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
