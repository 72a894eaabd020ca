"""The C phase driver as the compiled method's run: one ctypes call per scene.

A library per shape and law (and with or without a stem) holds the model's evaluator, the phase
loop and the driver (``contact_run.inc``) — the translation unit :func:`lib_source` writes, the
one ``derive export`` ships — and :func:`run` calls its ``contact_simulate``: the phases joined
by their switch rules (:mod:`derive.contact.phases` states them) from the start to the last
sample, with the samples, their phase, sphere and slip direction, and every switch.
"""
from __future__ import annotations

import ctypes
import functools

import numpy as np

from derive.contact.kernel import PARAM_NAMES, RUN, STATE, model_sources, text
from derive.contact.laws import LAWS
from derive.contact.phases import PHASE_NAMES, Run, Switch
from derive.errors import IntegrationError
from derive.methods.status import Status
from derive.runtime.cbuild import compile_library
from derive.runtime.records import bind, guarded, sigint_guard

#: How many phase switches a run may make.
MAX_SWITCHES = 10_000
#: The names of ``contact_event_names``: a switch's event code indexes them.
EVENT_NAMES = ("landing", "lift-off", "slip", "stick", "stem", "ball")
#: What ``contact_integrate``'s failure codes mean.
FAILURES = {2: "the step budget is spent", 3: "the step size fell below the spacing of doubles",
            4: "the contact is singular or the state not finite"}
_TOO_MANY_SWITCHES = 5
_NY = len(STATE)


class _RunState(ctypes.Structure):
    """``contact_run``: the time, state, phase, slip direction, sphere and the counts."""

    _fields_ = [("t", ctypes.c_double), ("y", ctypes.c_double * _NY), ("phase", ctypes.c_int),
                ("dir", ctypes.c_double * 3), ("sphere", ctypes.c_int), ("nstep", ctypes.c_long),
                ("nfev", ctypes.c_long), ("nswitch", ctypes.c_long)]


class _Settings(ctypes.Structure):
    """``contact_settings``."""

    _fields_ = [("rtol", ctypes.c_double), ("atol", ctypes.c_double), ("restitution", ctypes.c_double),
                ("max_steps", ctypes.c_long), ("max_switches", ctypes.c_long)]


#: ``contact_switch`` as a NumPy record (C's alignment).
SWITCH = np.dtype([("t", "f8"), ("before", "i4"), ("after", "i4"), ("event", "i4"),
                   ("energy_before", "f8"), ("energy_after", "f8")], align=True)


def lib_source(shape: str, law: str, stem: bool) -> str:
    """``<model>_lib.c``: the evaluator (which defines its law's phases, ``CONTACT_SLIDES`` and
    ``CONTACT_ROLLS``), then the driver, with the stem defined (``CONTACT_STEM``)."""
    spec = LAWS[law]
    name = f"contact_{shape}_{law}"
    return (f"/* {name}_lib.c: the contact model {name} and the phase driver as one translation\n"
            f" * unit; the law's phases ({', '.join(spec.phases)}) select the driver's switch rules.\n"
            f" * Written by `derive export`. */\n"
            f"#define CONTACT_STEM {int(stem)}\n"
            f'#include "{name}.c"\n#include "{RUN}"\n')


@functools.lru_cache(maxsize=None)
def library(shape: str, law: str, stem: bool):
    """``contact_simulate`` of a shape and law's driver library (compiled once, then cached) and
    the library (its Ctrl-C guard: :func:`derive.runtime.records.sigint_guard`)."""
    name = f"contact_{shape}_{law}"
    lib_name = f"{name}_stem_run" if stem else f"{name}_run"
    sources = {**model_sources(shape, law), RUN: text(RUN), f"{name}_lib.c": lib_source(shape, law, stem)}
    lib = compile_library(lib_name, sources, f"{name}_lib.c")
    fn = bind(lib, "contact_simulate", [ctypes.POINTER(_RunState)] + [ctypes.c_void_p] * 3
              + [ctypes.POINTER(_Settings), ctypes.c_long] + [ctypes.c_void_p] * 6 + [ctypes.c_long])
    return fn, lib


def run(shape: str, law: str, p: np.ndarray, stem, y0: np.ndarray, t_out: np.ndarray, *,
        restitution: float, rtol: float, atol: float, max_steps: int,
        direction=(1.0, 0.0, 0.0), max_switches: int = MAX_SWITCHES) -> Run:
    """Run the phases from ``y0`` at t = 0 over the samples ``t_out`` (ascending, last = t_end).

    Parameters
    ----------
    shape, law : str
        The model (``contact_<shape>_<law>``).
    p : ndarray
        The model's parameters (I1, I2, I3, M, g, r, s, μ, ε); ``stem``: the stem's (radius,
        offset) or None.
    y0 : ndarray, shape (13,)
        q, ω̃ (body), the centre of mass and its velocity, touching the plane.
    t_out : ndarray
        The sample times.
    restitution, rtol, atol, max_steps
        The landing's restitution, the tolerances and the step budget of the whole run.
    direction : sequence of 3 floats
        The slip direction exact Coulomb friction starts with at zero slip.

    Returns
    -------
    Run
        The samples with their phase, sphere and slip direction, every switch, the counts.

    Raises
    ------
    KeyboardInterrupt
        Ctrl-C during the run (the C loop stops at its next step).
    IntegrationError
        Step budget spent, step size underflow, a singular contact, a non-finite state, or more
        than ``max_switches`` switches, with the time.
    """
    fn, lib = library(shape, law, stem is not None)
    if len(p) != len(PARAM_NAMES):
        raise ValueError(f"a contact model takes {len(PARAM_NAMES)} parameters, not {len(p)}")
    pr = np.ascontiguousarray(np.concatenate([p, stem]) if stem is not None else p, dtype=float)
    y0 = np.ascontiguousarray(y0, dtype=float)
    ts = np.ascontiguousarray(t_out, dtype=float)
    n = len(ts)
    ys, dirs = np.zeros((n, _NY)), np.zeros((n, 3))
    phases, spheres = np.zeros(n, dtype=np.intc), np.zeros(n, dtype=np.intc)
    sw = np.zeros(max_switches + 1, dtype=SWITCH)
    d0 = np.ascontiguousarray(direction, dtype=float)
    state = _RunState()
    settings = _Settings(rtol, atol, restitution, max_steps, max_switches)
    code = guarded(sigint_guard(lib), fn, ctypes.byref(state), y0.ctypes.data, pr.ctypes.data,
                   d0.ctypes.data, ctypes.byref(settings), n, ts.ctypes.data, ys.ctypes.data,
                   phases.ctypes.data, spheres.ctypes.data, dirs.ctypes.data, sw.ctypes.data, len(sw))
    if code == Status.INTERRUPTED:  # a request from another thread, unguarded
        raise KeyboardInterrupt
    kept = sw[:min(state.nswitch, len(sw))]
    if code == _TOO_MANY_SWITCHES:
        raise IntegrationError(f"more than {max_switches} phase switches by t = {state.t:.8g} "
                               f"(last: {EVENT_NAMES[kept[-1]['event']]})")
    if code in FAILURES:
        raise IntegrationError(f"t = {state.t:.8g}: {FAILURES[code]} ({PHASE_NAMES[state.phase]})")
    switches = [Switch(float(s["t"]), PHASE_NAMES[int(s["before"])], PHASE_NAMES[int(s["after"])],
                       EVENT_NAMES[int(s["event"])], float(s["energy_before"]), float(s["energy_after"]))
                for s in kept]
    return Run(ts, ys, phases.astype(int), dirs, switches, sphere=spheres.astype(int),
               nfev=int(state.nfev), nstep=int(state.nstep))
