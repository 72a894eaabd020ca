"""Render models through the templates into source files, and keep generated/ in step.

model (symbolic) → KernelSpec (layout + CSE) → templates/ → {relative path: text}

`generate_all()` returns every file `derive generate` writes, as text; `write` and `stale` compare
that against a directory. Nothing here reads the clock or iterates over unordered collections,
so two runs produce identical bytes.
"""
from __future__ import annotations

import concurrent.futures
import functools
import multiprocessing
import os
from pathlib import Path

from .catalogue import SHIPPED, description_json
from .kernelspec import KernelSpec
from .models import Model
from .render import render


def model_sources(model: Model) -> dict[str, str]:
    """C header, C source and NumPy module of one model, plus its C solver kernels."""
    from .solvers import render_solvers

    spec = KernelSpec.of(model)
    c_ctx, np_ctx = spec.context("c"), spec.context("numpy")
    files = {
        f"c/{model.name}.h": render("c/model.h.j2", **c_ctx),
        f"c/{model.name}.c": render("c/model.c.j2", **c_ctx),
        f"numpy/{model.name}.py": render("numpy/model.py.j2", **np_ctx),
    }
    for fname, text in render_solvers(model.name, len(model.states),
                                      has_angles=c_ctx["has_angles"]).items():
        files[f"c/{fname}"] = text
    from . import splitting

    if splitting.applicable(model) is None:
        files.update({f"c/{k}": v for k, v in splitting.render_splitting(model).items()})
    files[f"models/{model.name}.json"] = description_json(spec)
    from .integrable import c_header

    files["c/derive_integrals.h"] = c_header()  # the measures' integrals (one file for every model)
    return files


def shipped_keys() -> dict[str, tuple]:
    """{model name: key} of every model written to generated/: the contract's catalogue, then
    the models the example scenes run (`catalogue.SHIPPED`)."""
    from .formulations import model_name
    from .models import CATALOGUE_KEYS

    keys = dict(CATALOGUE_KEYS)
    for key in SHIPPED:
        keys.setdefault(model_name(*key), key)
    return keys


def _sources_of(names) -> dict[str, str]:
    from .models import build

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
    from . import report

    from . import docs

    names = list(shipped_keys())
    files: dict[str, str] = {"numpy/__init__.py": render("numpy/__init__.py.j2", models=names)}
    files.update(docs.documents())
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
    from .outputs import write_all

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
