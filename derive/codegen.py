"""Render models through the templates into source files, and keep generated/ in step.

model (symbolic) → KernelSpec (layout + CSE) → templates/ → {relative path: text}

`generate_all()` returns every file `derive generate` writes, as text; `write` and `stale` compare
that against a directory. Nothing here reads the clock or iterates over unordered collections,
so two runs produce identical bytes.
"""
from __future__ import annotations

import os
import tempfile
from pathlib import Path

from .kernelspec import KernelSpec
from .models import CATALOGUE, Model
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
    for fname, text in render_solvers(model.name, len(model.states)).items():
        files[f"c/{fname}"] = text
    return files


def generate_all(models=None) -> dict[str, str]:
    """Every generated file, keyed by its path relative to generated/."""
    files: dict[str, str] = {}
    for name, build in CATALOGUE.items():
        if models is None or name in models:
            files.update(model_sources(build()))
    if models is None:
        from . import report

        files["numpy/__init__.py"] = render("numpy/__init__.py.j2", models=list(CATALOGUE))
        files.update(report.documents())
    return dict(sorted(files.items()))


def _atomic_write(path: Path, text: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.")
    with os.fdopen(fd, "w", encoding="utf-8", newline="\n") as fh:
        fh.write(text)
    os.replace(tmp, path)


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
