"""The contact evaluators as compiled C: one per shape and law, loaded once.

The C text of each model is :mod:`derive.contact.sources`'s derivation as ``make derive`` wrote
it into ``generated/contact/``; :func:`text` reads it there and derives it (SymPy) only when the
file is missing, so a run derives nothing. A shape and law's evaluator ``contact_<shape>_<law>.c``
(``templates/contact/contact.c.j2``: the law's sliding force) includes what every model shares,
``contact_model.inc`` (``model.c.j2``: the state layout, the quaternion kinematics, the phases'
forces put together), and its shape's formulas, ``contact_<shape>.inc`` (``shape.c.j2``), each
written once; :func:`kernel` compiles it through the package's compile cache.
"""
from __future__ import annotations

import ctypes
import functools

import numpy as np

from derive.codegen.render import GENERATED
from derive.contact.layout import (LOOP, MODEL, OUTPUTS, REDUCED, PARAM_NAMES, PHASES, RUN, STATE, loop_source, run_source,
                                   shape_file)
from derive.runtime.cbuild import compile_library
from derive.runtime.records import bind

__all__ = ["LOOP", "MODEL", "OUTPUTS", "REDUCED", "PARAM_NAMES", "PHASES", "RUN", "RUNTIME", "STATE", "Kernel", "kernel",
           "loop_source", "loop_sources", "model_sources", "reduced_sources", "run_source", "runtime_sources", "shape_file", "text"]

#: The shared runtime the phase loop asks for an interrupt (``generated/c/``): compiled with the
#: contact libraries as with the pivoted models' (:mod:`derive.runtime.cbuild` adds the host's
#: Ctrl-C guard to every library whose sources hold it), shipped with every contact export.
RUNTIME = ("derive_runtime.h", "derive_runtime.c")


def text(name: str) -> str:
    """``generated/contact/<name>`` as ``make derive`` wrote it, or derived now on a miss."""
    path = GENERATED / "contact" / name
    if path.is_file():
        return path.read_text(encoding="utf-8")
    from derive.contact import sources  # SymPy loads only when a model must be derived

    return sources.derive(name)


def runtime_sources() -> dict[str, str]:
    """The shared runtime's files (:data:`RUNTIME`) by name, as ``make derive`` wrote them."""
    return {n: (GENERATED / "c" / n).read_text(encoding="utf-8") for n in RUNTIME}


def loop_sources(name: str) -> dict[str, str]:
    """The evaluator ``<name>.c`` with what it includes: the phase loop and the runtime."""
    return {f"{name}.c": text(f"{name}.c"), LOOP: text(LOOP), **runtime_sources()}


def model_sources(shape: str, law: str) -> dict[str, str]:
    """The evaluator ``contact_<shape>_<law>.c`` with what it includes: the shared model, the
    shape's formulas, the phase loop and the runtime."""
    return {**loop_sources(f"contact_{shape}_{law}"), MODEL: text(MODEL), shape_file(shape): text(shape_file(shape))}


def reduced_sources(shape: str) -> dict[str, str]:
    """The reduced evaluator ``contact_<shape>_reduced.c`` with what it includes: the evaluator
    every shape shares, the phase loop and the runtime."""
    return {**loop_sources(f"contact_{shape}_reduced"), REDUCED: text(REDUCED)}


def _check(p: np.ndarray) -> None:
    """The C code reads every parameter of :data:`PARAM_NAMES`: a shorter vector is refused."""
    if len(p) < len(PARAM_NAMES):
        raise ValueError(f"a contact model takes {len(PARAM_NAMES)} parameters ({', '.join(PARAM_NAMES)}), "
                         f"not {len(p)}")


class Kernel:
    """A loaded evaluator: ``eval(phase, y, p, dir)`` → (dy/dt, outputs), NumPy arrays."""

    def __init__(self, shape: str, law: str):
        name = f"contact_{shape}_{law}"
        lib = compile_library(name, model_sources(shape, law), f"{name}.c")
        self.fn = bind(lib, f"{name}_eval", [ctypes.c_int] + [ctypes.c_void_p] * 5)
        self.dy = np.zeros(len(STATE))
        self.out = np.zeros(len(OUTPUTS))
        self._dy, self._out = self.dy.ctypes.data, self.out.ctypes.data
        self.many = bind(lib, f"{name}_outputs", [ctypes.c_long] + [ctypes.c_void_p] * 5, ctypes.c_long)
        self.nfev = 0

    def rhs(self, phase: int, y: np.ndarray, p: np.ndarray, d: np.ndarray) -> np.ndarray:
        """dy/dt in ``phase``; a fresh array. Raises FloatingPointError outside the domain."""
        y = np.ascontiguousarray(y, dtype=float)
        self.nfev += 1
        _check(p)
        if self.fn(phase, y.ctypes.data, p.ctypes.data, d.ctypes.data, self._dy, None):
            raise FloatingPointError("the contact is singular here")
        return self.dy.copy()

    def outputs(self, phase: int, y: np.ndarray, p: np.ndarray, d: np.ndarray) -> np.ndarray:
        """The monitored outputs (``OUTPUTS``) at the state ``y`` in ``phase``; a fresh array."""
        y = np.ascontiguousarray(y, dtype=float)
        _check(p)
        if self.fn(phase, y.ctypes.data, p.ctypes.data, d.ctypes.data, self._dy, self._out):
            raise FloatingPointError("the contact is singular here")
        return self.out.copy()

    def outputs_many(self, phase: np.ndarray, y: np.ndarray, p: np.ndarray, d: np.ndarray) -> np.ndarray:
        """The outputs of many states (rows of ``y``, a phase and a direction each), one C call."""
        phase = np.ascontiguousarray(phase, dtype=np.intc)
        y, d = (np.ascontiguousarray(a, dtype=float) for a in (y, d))
        out = np.empty((len(y), len(OUTPUTS)))
        _check(p)
        bad = self.many(len(y), phase.ctypes.data, y.ctypes.data, p.ctypes.data, d.ctypes.data,
                        out.ctypes.data)
        if bad:
            raise FloatingPointError(f"the contact is singular at sample {bad - 1}")
        return out


@functools.lru_cache(maxsize=None)
def kernel(shape: str, law: str) -> Kernel:
    """The compiled evaluator of a shape and law (compiled once, then from the cache)."""
    return Kernel(shape, law)
