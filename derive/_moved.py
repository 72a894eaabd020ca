"""The modules' old homes: ``derive.simulation``, ``derive.scene``, … (the flat layout before the
stage subpackages) still import, as the module that now holds them, with a DeprecationWarning
naming the new place.

Split modules map to the part that kept most of them: ``derive.solvers`` is
:mod:`derive.methods.registry` (the C rendering is :mod:`derive.codegen.solvers`),
``derive.splitting`` is :mod:`derive.methods.splitting` (rendering
:mod:`derive.codegen.splitting`, the compiled solver :mod:`derive.runtime.splitter`, the
benchmark :mod:`derive.bench.splitting`), ``derive.codegen`` the package whose
:mod:`~derive.codegen.sources` renders a model (``derive generate``'s job is
:mod:`derive.generate`).
"""
from __future__ import annotations

import importlib
import importlib.abc
import importlib.util
import sys
import warnings

#: old module (under ``derive.``) -> its new home
MOVED = {
    "analysis": "lecture.analysis", "auto": "sim.auto", "catalogue": "runtime.catalogue",
    "cbuild": "runtime.cbuild", "docs": "sim.scene_doc", "effects": "symbolic.effects",
    "elliptic": "reference.elliptic", "exact": "reference.exact",
    "formulations": "symbolic.formulations", "inertia": "symbolic.inertia",
    "integrable": "symbolic.integrable", "integrate": "runtime.integrate",
    "kernelspec": "codegen.kernelspec", "lagrangian": "symbolic.lagrangian",
    "measures": "sweeps.measures", "models": "symbolic.models",
    "outputs": "sim.outputs", "plots": "sim.plots", "render": "codegen.render",
    "report": "lecture.report", "rotations": "symbolic.rotations", "scene": "sim.scene",
    "simulation": "sim.simulation", "solvers": "methods.registry",
    "splitting": "methods.splitting", "stability": "symbolic.stability",
    "status": "methods.status", "sweep_maps": "sweeps.maps",
    "tableaux": "methods.tableaux", "verify": "lecture.verify",
    "bench_contenders": "bench.contenders", "bench_internals": "bench.internals",
    "bench_report": "bench.report", "bench_targets": "bench.targets",
}


class _Alias(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Finds ``derive.<old>`` and loads it as the new module (the same object, so attributes
    and monkeypatches are shared)."""

    def find_spec(self, fullname, path=None, target=None):
        head, _, old = fullname.partition(".")
        if head != "derive" or old not in MOVED:
            return None
        return importlib.util.spec_from_loader(fullname, self)

    def create_module(self, spec):
        new = "derive." + MOVED[spec.name.partition(".")[2]]
        warnings.warn(f"{spec.name} has moved to {new}; import it from there",
                      DeprecationWarning, stacklevel=3)
        return importlib.import_module(new)

    def exec_module(self, module):
        pass  # the new module is already executed


def forward(package: str, module: str):
    """A module ``__getattr__`` for ``package``, which was once the single module ``module`` now
    holds: its old names resolve, loaded on first use. A submodule's name or a dunder is not
    forwarded (the import system asks for those, and must not load ``module`` to learn it)."""
    def __getattr__(name):
        if name.startswith("__") or importlib.util.find_spec(f"{package}.{name}") is not None:
            raise AttributeError(name)
        try:
            return getattr(importlib.import_module(module), name)
        except AttributeError:
            raise AttributeError(f"module {package!r} has no attribute {name!r}") from None
    return __getattr__


def install() -> None:
    """Put the alias finder on ``sys.meta_path`` (once)."""
    if not any(isinstance(f, _Alias) for f in sys.meta_path):
        sys.meta_path.append(_Alias())
