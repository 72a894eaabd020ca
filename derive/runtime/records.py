"""The records a generated run driver shares with Python: its statistics (``derive_stats`` of
``<prefix>_solvers.h``, :data:`STATS_DTYPE`), what it saves (``derive_saveat``, :class:`SaveAt`),
the C types of a method's extra driver parameters (:data:`C_TYPES`) and the solvers' defaults.
Both kernels (:mod:`derive.runtime.kernel`, :mod:`derive.runtime.integrate`) and the batch
engines read them.
"""
from __future__ import annotations

import ctypes

import numpy as np

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
