"""The contact models' layout: the names of their parameters, states and outputs, the phase
codes, and the C shared by every model (the phase loop, the phase driver).

What the derivation (:mod:`derive.contact.sources`) writes and the run side
(:mod:`derive.contact.kernel`, :mod:`derive.contact.reduced`, :mod:`derive.export.contact`)
reads both come from here; nothing here needs SymPy.
"""
from __future__ import annotations

import functools

from derive.codegen.render import c_double, render
from derive.contact.laws import EXTENSIONS
from derive.methods.registry import DEFAULT_METHOD, METHODS

#: The parameter vector's layout (:data:`derive.contact.sources.PARAMS`: the symbols' names): the
#: body, gravity, the shape, the law, then the law's extensions' lengths (0: off).
PARAM_NAMES = ("I1", "I2", "I3", "M", "g", "r", "s", "mu", "epsilon") + tuple(e.param for e in EXTENSIONS.values())

#: The evaluator's ``out`` array, in order.
OUTPUTS = ("N", "ft_x", "ft_y", "ft_z", "slip_x", "slip_y", "slip_z", "gap", "power",
           "a_x", "a_y", "a_z", "u_n", "energy", "p_alpha", "p_gamma", "jellett", "routh", "z", "vx", "vy", "vz", "slip_floor")
STATE = ("q0", "q1", "q2", "q3", "w1", "w2", "w3", "x", "y", "z", "vx", "vy", "vz")
PHASES = {"slide": 0, "roll": 1, "flight": 2}


def _dop853() -> dict:
    """The registry's DOP853 tableau as C double literals for the template's step loop: A with
    the FSAL row (b) and the three dense-output stages, 16 × 16; the two error weights with
    the FSAL stage's zero; the dense output's D."""
    t = METHODS[DEFAULT_METHOD].tableau
    lit = lambda row, n: [c_double(x) for x in row] + ["0.0"] * (n - len(row))
    A = [lit(row, 16) for row in t.A] + [lit(t.b, 16)] + [lit(row, 16) for row in t.dense.A_extra]
    return {"A": A, "B": lit(t.b, 12), "E3": lit(t.b_err2, 13), "E5": lit(t.b_err, 13),
            "D": [lit(row, 16) for row in t.dense.D]}


#: The part of every shape and law's evaluator they share (the state, its kinematics, the
#: phases' forces put together, the outputs): one text each ``contact_<shape>_<law>.c`` includes
#: with its shape's formulas, ``contact_<shape>.inc``.
MODEL = "contact_model.inc"


#: What every shape's reduced evaluator (``contact_<shape>_reduced.c``) shares and includes.
REDUCED = "contact_reduced.inc"


def shape_file(shape: str) -> str:
    """The name of the file of a shape's formulas, shared by its laws' evaluators."""
    return f"contact_{shape}.inc"


#: The phase loop's file name: one text that every shape and law's source includes.
LOOP = "contact_phase_loop.inc"


@functools.lru_cache(maxsize=None)
def loop_source() -> str:
    """The phase loop (DOP853 on the method registry's tableau, dense output, located events),
    shared by every contact model: each defines ``NY``, ``NOUT``, ``CONTACT_EVAL`` and
    ``CONTACT_ADVANCE`` and includes it."""
    return render("contact/dop853.c.j2", dop=_dop853(), dop_name=DEFAULT_METHOD)


#: The phase driver's file name: the phases joined by their switch rules, in C (what
#: ``derive simulate``'s compiled method, an export and an FMU run; :mod:`derive.contact.phases`
#: keeps the same rules as the reference stepper).
RUN = "contact_run.inc"


@functools.lru_cache(maxsize=None)
def run_source() -> str:
    """The phase driver (``contact_initial``, ``contact_start``, ``contact_integrate``,
    ``contact_simulate``), shared by every contact model's run and export: the including file
    includes a model first and defines ``CONTACT_SLIDES``, ``CONTACT_ROLLS`` and ``CONTACT_STEM``."""
    return render("contact/run.c.j2")
