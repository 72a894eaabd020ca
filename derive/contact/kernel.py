"""The contact equations as C: one evaluator per shape and law, compiled and loaded once.

The derivation (:mod:`derive.contact.equations`) is printed block by block with common
subexpressions shared inside each block (``sympy.cse``): the contact point a(n), the sliding
normal force and contact force, the rolling system (A, b) whose 3×3 solve is in the template,
Euler's equations for a given force, and the monitored integrals. The template
``templates/contact/contact.c.j2`` holds the state layout, the quaternion kinematics and
the phase switch; :func:`kernel` compiles it through the package's compile cache.

Every shape and law's source is also written by ``make derive`` into ``generated/contact/``
(:func:`generated_sources`); a kernel takes its text from there when it is present, so a run
derives nothing (``tests`` check that ``generated/`` is what the derivation gives).
"""
from __future__ import annotations

import ctypes
import functools

import numpy as np
import sympy as sp

from derive.codegen.render import GENERATED, c_double, render
from derive.contact.geometry import SHAPES
from derive.contact.equations import FORCE, I1, I2, I3, MASS, GRAV, contact, omega_dot
from derive.contact.geometry import OFFSET, RADIUS
from derive.contact.integrals import expressions
from derive.contact.laws import EPS, LAWS, MU, NORMAL
from derive.methods.registry import DEFAULT_METHOD, METHODS
from derive.runtime.cbuild import compile_library

#: The parameter vector's layout (the C names are the symbols' names).
PARAMS = (I1, I2, I3, MASS, GRAV, RADIUS, OFFSET, MU, EPS)
PARAM_NAMES = tuple(str(p) for p in PARAMS)
#: The evaluator's ``out`` array, in order.
OUTPUTS = ("N", "ft_x", "ft_y", "ft_z", "slip_x", "slip_y", "slip_z", "gap", "power",
           "a_x", "a_y", "a_z", "u_n", "energy", "p_alpha", "p_gamma", "jellett", "routh", "z", "vx", "vy", "vz", "slip_floor")
STATE = ("q0", "q1", "q2", "q3", "w1", "w2", "w3", "x", "y", "z", "vx", "vy", "vz")
PHASES = {"slide": 0, "roll": 1, "flight": 2}


def c_block(assign: list[tuple[str, sp.Expr]]) -> str:
    """C statements assigning each expression to its (already declared) name, subexpressions
    shared through ``sympy.cse``."""
    subs, reduced = sp.cse([e for _, e in assign], symbols=sp.numbered_symbols("x"), optimizations="basic")
    lines = [f"const double {s} = {sp.ccode(e)};" for s, e in subs]
    lines += [f"{name} = {sp.ccode(e)};" for (name, _), e in zip(assign, reduced)]
    return "\n".join(lines)


@functools.lru_cache(maxsize=None)
def source(shape: str, law: str) -> str:
    """The C source of the evaluator for ``shape`` under the contact law ``law``."""
    c = contact(shape)
    lw = LAWS[law]
    geometry = c_block([(f"a{i + 1}", c.a[i]) for i in range(3)])
    slide = ""
    if lw.slides:
        N, f = c.sliding(lw)
        slide = c_block([("N", N)] + [(f"f{i + 1}", f[i].subs(NORMAL, sp.Symbol("N"))) for i in range(3)])
    roll = ""
    if lw.rolls:
        A, b = c.rolling
        roll = c_block([(f"A[{3 * i + j}]", A[i, j]) for i in range(3) for j in range(3)]
                       + [(f"b[{i}]", b[i]) for i in range(3)])
    accel = c_block([(f"wd{i + 1}", e) for i, e in enumerate(omega_dot(c.a, FORCE))])
    ints = expressions(c)
    monitors = c_block([(f"out[{13 + i}]", e) for i, e in enumerate(ints.values())])

    return render("contact/contact.c.j2", prefix=f"contact_{shape}_{law}", shape=shape, law=law,
                  ny=len(STATE), np=len(PARAMS), nout=len(OUTPUTS), params=PARAM_NAMES,
                  outputs=OUTPUTS, geometry=geometry, slide=slide, roll=roll, accel=accel,
                  monitors=monitors)


def _dop853() -> dict:
    """The registry's DOP853 tableau as C double literals for the template's step loop: A with
    the FSAL row (b) and the three dense-output stages, 16 × 16; the two error weights with
    the FSAL stage's zero; the dense output's D."""
    t = METHODS[DEFAULT_METHOD].tableau
    lit = lambda row, n: [c_double(x) for x in row] + ["0.0"] * (n - len(row))
    A = [lit(row, 16) for row in t.A] + [lit(t.b, 16)] + [lit(row, 16) for row in t.dense.A_extra]
    return {"A": A, "B": lit(t.b, 12), "E3": lit(t.b_err2, 13), "E5": lit(t.b_err, 13),
            "D": [lit(row, 16) for row in t.dense.D]}


#: The phase loop's file name: one text that every shape and law's source includes.
LOOP = "contact_phase_loop.inc"


@functools.lru_cache(maxsize=None)
def loop_source() -> str:
    """The phase loop (DOP853 on the method registry's tableau, dense output, located events),
    shared by every contact model: each defines ``NY``, ``NOUT``, ``CONTACT_EVAL`` and
    ``CONTACT_ADVANCE`` and includes it."""
    return render("contact/dop853.c.j2", dop=_dop853(), dop_name=DEFAULT_METHOD)


#: The phase driver's file name: the phases joined by their switch rules, in C (what an export
#: and an FMU run; :mod:`derive.contact.phases` is the same rules driving the phase loop from
#: Python).
RUN = "contact_run.inc"


@functools.lru_cache(maxsize=None)
def run_source() -> str:
    """The phase driver (``contact_initial``, ``contact_start``, ``contact_integrate``), shared by
    every contact model's export: the including file includes a model first and defines
    ``CONTACT_SLIDES`` and ``CONTACT_ROLLS``."""
    return render("contact/run.c.j2")


def generated_sources() -> dict[str, str]:
    """Every shape and law's C source, the phase loop they share and the phase driver, keyed by
    their paths under ``generated/``."""
    out = {f"contact/contact_{shape}_{law}.c": source(shape, law) for shape in SHAPES for law in LAWS}
    out[f"contact/{LOOP}"] = loop_source()
    out[f"contact/{RUN}"] = run_source()
    return out


def shipped_text(name: str, fallback) -> str:
    """``generated/contact/<name>`` as ``make derive`` wrote it, or ``fallback()`` rendered now."""
    path = GENERATED / "contact" / name
    return path.read_text(encoding="utf-8") if path.is_file() else fallback()


def shipped_source(shape: str, law: str) -> str | None:
    """The source ``make derive`` wrote for ``shape`` and ``law``, or None."""
    path = GENERATED / "contact" / f"contact_{shape}_{law}.c"
    return path.read_text(encoding="utf-8") if path.is_file() else None


class Kernel:
    """A loaded evaluator: ``eval(phase, y, p, dir)`` → (dy/dt, outputs), NumPy arrays."""

    def __init__(self, shape: str, law: str):
        name = f"contact_{shape}_{law}"
        text = shipped_source(shape, law) or source(shape, law)
        loop = GENERATED / "contact" / LOOP
        shared = loop.read_text(encoding="utf-8") if loop.is_file() else loop_source()
        lib = compile_library(name, {f"{name}.c": text, LOOP: shared}, f"{name}.c")
        self.fn = getattr(lib, f"{name}_eval")
        self.fn.restype = ctypes.c_int
        self.fn.argtypes = [ctypes.c_int] + [ctypes.c_void_p] * 5
        self.dy = np.zeros(len(STATE))
        self.out = np.zeros(len(OUTPUTS))
        self._dy, self._out = self.dy.ctypes.data, self.out.ctypes.data
        self.many = getattr(lib, f"{name}_outputs")
        self.many.restype = ctypes.c_long
        self.many.argtypes = [ctypes.c_long] + [ctypes.c_void_p] * 5
        self.step = getattr(lib, f"{name}_advance")
        self.step.restype = ctypes.c_int
        self.step.argtypes = ([ctypes.c_int, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_double]
                              + [ctypes.c_void_p] * 2 + [ctypes.c_double, ctypes.c_double, ctypes.c_void_p,
                                                         ctypes.c_long, ctypes.c_int]
                              + [ctypes.c_void_p] * 2 + [ctypes.c_long] + [ctypes.c_void_p] * 5)
        self.nfev = 0

    def rhs(self, phase: int, y: np.ndarray, p: np.ndarray, d: np.ndarray) -> np.ndarray:
        """dy/dt in ``phase``; a fresh array. Raises FloatingPointError outside the domain."""
        y = np.ascontiguousarray(y, dtype=float)
        self.nfev += 1
        if self.fn(phase, y.ctypes.data, p.ctypes.data, d.ctypes.data, self._dy, None):
            raise FloatingPointError("the contact is singular here")
        return self.dy.copy()

    def outputs(self, phase: int, y: np.ndarray, p: np.ndarray, d: np.ndarray) -> np.ndarray:
        """The monitored outputs (``OUTPUTS``) at the state ``y`` in ``phase``; a fresh array."""
        y = np.ascontiguousarray(y, dtype=float)
        if self.fn(phase, y.ctypes.data, p.ctypes.data, d.ctypes.data, self._dy, self._out):
            raise FloatingPointError("the contact is singular here")
        return self.out.copy()


    def advance(self, phase: int, t: float, y: np.ndarray, t_end: float, p: np.ndarray, d: np.ndarray,
                rtol: float, atol: float, h: float, max_steps: int, events: np.ndarray, ref: np.ndarray,
                ts: np.ndarray, its: int, ys: np.ndarray, counts: np.ndarray):
        """One phase integrated in C (``{name}_advance``) until an event or ``t_end``: returns
        (code, t, which, h, its) with ``y``, ``ref``, ``ys`` and ``counts`` updated in place."""
        tt, hh, ii, which = ctypes.c_double(t), ctypes.c_double(h), ctypes.c_long(its), ctypes.c_int(-1)
        code = self.step(phase, ctypes.addressof(tt), y.ctypes.data, t_end, p.ctypes.data, d.ctypes.data,
                         rtol, atol, ctypes.addressof(hh), max_steps, len(events), events.ctypes.data,
                         ref.ctypes.data, len(ts), ts.ctypes.data, ctypes.addressof(ii), ys.ctypes.data,
                         ctypes.addressof(which), counts.ctypes.data)
        return code, tt.value, which.value, hh.value, ii.value

    def outputs_many(self, phase: np.ndarray, y: np.ndarray, p: np.ndarray, d: np.ndarray) -> np.ndarray:
        """The outputs of many states (rows of ``y``, a phase and a direction each), one C call."""
        phase = np.ascontiguousarray(phase, dtype=np.intc)
        y, d = (np.ascontiguousarray(a, dtype=float) for a in (y, d))
        out = np.empty((len(y), len(OUTPUTS)))
        bad = self.many(len(y), phase.ctypes.data, y.ctypes.data, p.ctypes.data, d.ctypes.data,
                        out.ctypes.data)
        if bad:
            raise FloatingPointError(f"the contact is singular at sample {bad - 1}")
        return out


@functools.lru_cache(maxsize=None)
def kernel(shape: str, law: str) -> Kernel:
    """The compiled evaluator of a shape and law (compiled once, then from the cache)."""
    return Kernel(shape, law)
