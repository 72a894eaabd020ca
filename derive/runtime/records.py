"""A generated run driver as Python calls it: the driver itself, bound once (:class:`Driver`),
and the records it shares with Python: its statistics (``derive_stats`` of
``<prefix>_solvers.h``, :data:`STATS_DTYPE`), what it saves (``derive_saveat``, :class:`SaveAt`),
the C types of a method's extra driver parameters (:data:`C_TYPES`) and the solvers' defaults.
Every kernel (:mod:`derive.runtime.kernel`, :mod:`derive.runtime.integrate`,
:mod:`derive.runtime.splitter`) and the batch engines use them.
"""
from __future__ import annotations

import ctypes
import threading

import numpy as np

from derive.methods.registry import method as compiled_method
from derive.methods.status import Status

DEFAULT_MAX_STEPS = 1_000_000
DEFAULT_NEWTON_TOL = 1e-15
DEFAULT_NEWTON_MAXITER = 20

# derive_stats of <prefix>_solvers.h, as a NumPy record (aligned = the C layout), so a batch's
# statistics are one array.
_LONG = np.dtype(f"i{ctypes.sizeof(ctypes.c_long)}")
STATS_DTYPE = np.dtype([
    ("nfev", _LONG), ("njev", _LONG), ("nstep", _LONG), ("naccept", _LONG),
    ("nreject", _LONG), ("nlu", _LONG), ("t_fail", np.float64), ("fail_index", np.intc),
    ("status", np.intc), ("h_fail", np.float64), ("rhs_code", np.intc)], align=True)

STATS_DOUBLES = STATS_DTYPE.itemsize // 8


def driver_args(method: str, rtol: float, atol: float, h: float | None, max_steps: int) -> list:
    """The run driver's arguments after ``n_out`` for the compiled ``method``, in its C order
    (its registry entry's ``params``: DOP853's ``rtol, atol, h0, max_steps``, a fixed-step
    method's ``h``, …; ``h0`` = 0, the driver's own first step; Newton's settings the defaults)."""
    values = {"rtol": rtol, "atol": atol, "h0": 0.0, "max_steps": max_steps, "h": h,
              "newton_tol": DEFAULT_NEWTON_TOL, "newton_maxiter": DEFAULT_NEWTON_MAXITER}
    return [values[name] for _, name in compiled_method(method).params]
assert STATS_DTYPE.itemsize % 8 == 0 and STATS_DTYPE.alignment <= 8  # a record fits a double slice

C_TYPES = {"double": ctypes.c_double, "long": ctypes.c_long, "int": ctypes.c_int}


class SaveAt(ctypes.Structure):
    """``derive_saveat`` of ``derive_runtime.h``: what a run driver ``<prefix>_run_<method>``
    saves. ``t_out``/``n_out``: the output times; ``final``: 1 for the last time alone;
    ``outputs``: 1 when the inputs go through the init map and the checked outputs are written
    (0: the inputs are start states, the states alone are written); ``pole_check``: 0, 1 or 2;
    ``lanes``: 1 to run a Taylor method's trajectories several at once where compiled."""

    _fields_ = [("t_out", ctypes.c_void_p), ("n_out", ctypes.c_long), ("final", ctypes.c_int),
                ("outputs", ctypes.c_int), ("pole_check", ctypes.c_int), ("lanes", ctypes.c_int)]


def saveat(t: np.ndarray, *, final: bool = False, outputs: bool = True, pole_check: int = 0,
           lanes: bool = False) -> SaveAt:
    """A :class:`SaveAt` over the C-contiguous float64 times ``t`` (the caller keeps ``t``)."""
    return SaveAt(t.ctypes.data, t.shape[0], int(final), int(outputs), int(pole_check), int(lanes))


_INTERRUPTED = int(Status.INTERRUPTED)
_ON, _OFF = ctypes.c_int(1), ctypes.c_int(0)  # the guard's arguments, made once


def sigint_guard(lib: ctypes.CDLL):
    """The Ctrl-C guard ``int derive_sigint_guard(int on)`` of a loaded library (every library
    whose sources hold the shared runtime exports it, :mod:`derive.runtime.cbuild`), bound; None
    off the main thread, where its SIGINT handler cannot be installed."""
    if threading.current_thread() is not threading.main_thread():
        return None
    return bind(lib, "derive_sigint_guard", [ctypes.c_int])


def guarded(guard, fn, *args) -> int:
    """``fn(*args)``, a compiled loop that asks the runtime's interrupt hook once per step, under
    the Ctrl-C guard ``guard`` (:func:`sigint_guard`; None: a plain call whose interrupt is its
    return code). Returns ``fn``'s return code.

    Raises
    ------
    KeyboardInterrupt
        A SIGINT came during the call, or the call returned ``DERIVE_INTERRUPTED`` (a request
        from another thread, ``derive_sigint_request``).
    """
    if guard is None:
        return fn(*args)
    guard(_ON)
    try:
        rc = fn(*args)
    finally:
        interrupted = guard(_OFF)
    if interrupted or rc == _INTERRUPTED:
        raise KeyboardInterrupt
    return rc


class Driver:
    """The run driver of one compiled method in a loaded library, bound once::

        int <prefix>_run_<method>(const derive_saveat *save, long n_batch, const double *ins,
                                  double *ps, <the method's parameters>, double *y,
                                  double *out, derive_stats *st);

    whatever library holds it (a model with one method, a model with every solver, a
    splitting). The method's parameters are its registry entry's
    (:func:`derive.methods.registry.method`), in that order (:attr:`params` names them).

    Parameters
    ----------
    lib : ctypes.CDLL
        The loaded library.
    prefix : str
        The model's C prefix.
    method : str
        A compiled method (:func:`derive.methods.registry.compiled_methods`).
    interruptible : bool
        Run each call under the library's Ctrl-C guard (``derive_sigint_guard``) when bound in
        the main thread, an interrupt surfacing as KeyboardInterrupt; otherwise an interrupt
        is the call's status (:attr:`Status.INTERRUPTED`) like any other.
    """

    def __init__(self, lib: ctypes.CDLL, prefix: str, method: str, interruptible: bool = True):
        spec = compiled_method(method)
        self.lib, self.method = lib, method
        self.params = tuple(name for _, name in spec.params)
        vp = ctypes.c_void_p
        self.fn = bind(lib, f"{prefix}_run_{method}",
                       [vp, ctypes.c_long, vp, vp, *(C_TYPES[ty] for ty, _ in spec.params), vp, vp, vp])
        self.guard = sigint_guard(lib) if interruptible else None
        self._unchecked: dict = {}

    def __call__(self, save: SaveAt, n_batch: int, ins, ps, args, y, out, st) -> int:
        """Run once: the arrays (C-contiguous, of the driver's layout) or None for NULL, ``args``
        the method's parameters in :attr:`params` order. Returns the driver's return code."""
        return guarded(self.guard, self.fn, ctypes.byref(save), n_batch, _ptr(ins), _ptr(ps),
                       *args, _ptr(y), _ptr(out), _ptr(st))

    def unchecked(self, args) -> tuple:
        """(driver, guard or None, ``args`` as ctypes instances) for a caller that converts its
        own arguments (:class:`derive.runtime.integrate.BoundRun`): the driver and the guard as
        function objects without argtypes, which then convert nothing. Made once per set of
        arguments."""
        key = tuple(args)
        parts = self._unchecked.get(key)
        if parts is None:
            conv = tuple(ty(v) for ty, v in zip(self.fn.argtypes[4:], args))
            guard = None if self.guard is None else _bare(self.lib, self.guard.__name__)
            parts = self._unchecked[key] = (_bare(self.lib, self.fn.__name__), guard, conv)
        return parts


def bind(lib: ctypes.CDLL, symbol: str, argtypes: list, restype=ctypes.c_int):
    """The function ``symbol`` of ``lib`` with these argument types and result type."""
    fn = getattr(lib, symbol)
    fn.argtypes, fn.restype = argtypes, restype
    return fn


def _ptr(a) -> int | None:
    # ndarray.ctypes.data: __array_interface__ would build a structured dtype's description
    # (derive_stats) on every call.
    return None if a is None else a.ctypes.data


def _bare(lib, symbol: str):
    """A fresh function object of ``symbol`` with no argtypes (int result): called with ctypes
    instances only, it converts nothing (the library's own object keeps its argtypes)."""
    fn = lib[symbol]
    fn.restype = ctypes.c_int
    return fn
