"""A compiled model and its solvers called from Python: :class:`Kernel`.

A :class:`Kernel` wraps one loaded library holding a model (``<prefix>_rhs``, ``<prefix>_jac``,
the state and parameter names) and its rendered solvers: one driver per method,
``<prefix>_run_<method>``, told what to save by a ``derive_saveat``
(:class:`~derive.runtime.records.SaveAt`). Python enters C once per trajectory (``solve``) or
once per batch (``solve_batch``); the stepping, step-size control and dense output all run in C.

Methods are the registry :data:`derive.methods.registry.METHODS` (``dop853``, ``rk4``, ``gauss4``,
``gauss6``, ``dop853_fixed``); how each is called follows from its driver's parameter list
(:data:`derive.methods.registry.DRIVER_PARAMS`), so a new method needs no code here.

Failures come back from C as a status code (:data:`derive.codegen.solvers.STATUS`) plus where they
happened; :func:`derive.methods.status.message` turns them into the one line that
:class:`~derive.errors.IntegrationError` carries, naming the state by its model name.
"""
from __future__ import annotations

import ctypes
from dataclasses import dataclass, field

import numpy as np

from derive.codegen.solvers import render_solvers
from derive.errors import IntegrationError
from derive.methods.registry import METHODS, compiled_methods
from derive.methods.status import message as failure_message
from derive.runtime.cbuild import DEFAULT_FLAGS, compile_library
from derive.runtime.records import (DEFAULT_MAX_STEPS, DEFAULT_NEWTON_MAXITER,
                                    DEFAULT_NEWTON_TOL, STATS_DTYPE, Driver, bind, saveat)

_F64 = np.ctypeslib.ndpointer(dtype=np.float64, flags="C_CONTIGUOUS")


def _fmt(x: float) -> str:
    return f"{x:.8g}"


@dataclass(frozen=True)
class Solution:
    """One trajectory: ``y[k]`` is the state at ``t[k]``; rows after a failure are NaN."""

    t: np.ndarray
    y: np.ndarray
    method: str
    status: int
    nfev: int
    njev: int
    nstep: int
    naccept: int
    nreject: int
    nlu: int
    message: str = "success"
    t_fail: float | None = None
    fail_index: int | None = None

    @property
    def success(self) -> bool:
        return self.status == 0


@dataclass(frozen=True)
class BatchSolution:
    """``n_batch`` trajectories on the same output times: ``y[b, k]`` is trajectory ``b`` at
    ``t[k]``; the statistics are arrays over ``b`` (``stats`` is the raw record array)."""

    t: np.ndarray
    y: np.ndarray
    method: str
    stats: np.ndarray = field(repr=False)
    messages: tuple[str, ...] = ()

    @property
    def status(self) -> np.ndarray:
        return self.stats["status"].copy()

    @property
    def nfev(self) -> np.ndarray:
        return self.stats["nfev"].copy()

    def __len__(self) -> int:
        return len(self.y)

    def __getitem__(self, b: int) -> Solution:
        st = self.stats[b]
        status = int(st["status"])
        return Solution(
            t=self.t, y=self.y[b], method=self.method, status=status,
            nfev=int(st["nfev"]), njev=int(st["njev"]), nstep=int(st["nstep"]),
            naccept=int(st["naccept"]), nreject=int(st["nreject"]), nlu=int(st["nlu"]),
            message=self.messages[b],
            t_fail=float(st["t_fail"]) if status else None,
            fail_index=int(st["fail_index"]) if status == 2 else None)


class Kernel:
    """A compiled model and its solvers.

    ``prefix``, ``ny``, ``np``, ``state_names``, ``param_names`` come from the library itself
    (``<prefix>_dims`` and the model's name arrays); ``methods`` lists the registered solvers it
    holds (``solve``, ``solve_batch``); :meth:`driver` binds any compiled method it holds.
    """

    def __init__(self, lib: ctypes.CDLL, prefix: str):
        self.lib = lib
        self.prefix = prefix
        dims = (ctypes.c_int * 4).in_dll(lib, f"{prefix}_dims")
        self.ny, self.np = int(dims[0]), int(dims[1])
        self.state_names = self._names("state_names", self.ny)
        self.param_names = self._names("param_names", self.np)
        self._rhs = bind(self.lib, f"{prefix}_rhs", [ctypes.c_double, _F64, _F64, _F64])
        self._jac = bind(self.lib, f"{prefix}_jac", [ctypes.c_double, _F64, _F64, _F64])
        self.methods = tuple(m for m in METHODS if hasattr(lib, f"{prefix}_run_{m}"))
        self._drivers: dict[str, Driver] = {}

    def __repr__(self) -> str:
        return (f"Kernel({self.prefix!r}, y=({', '.join(self.state_names)}), "
                f"p=({', '.join(self.param_names)}))")

    # ---------------------------------------------------------------------------------------
    @classmethod
    def from_sources(cls, prefix: str, ny: int, sources: dict[str, str],
                     methods: list[str] | None = None, flags=DEFAULT_FLAGS) -> "Kernel":
        """Render the solvers for the model in ``sources`` (``<prefix>.h``, ``<prefix>.c``, ...),
        compile everything as one translation unit (so the compiler can inline the rhs into the
        stepper) and load it. Compiled once per machine, loaded once per process.

        ``ny`` is the model's state count, given by whoever produced the sources (the model or
        its description), never read back from them.
        """
        files = dict(sources)
        files.update(render_solvers(prefix, ny, methods))
        unity = f"{prefix}_unity.c"
        model_c = [f"{prefix}.c"] + sorted(n for n in sources
                                           if n.endswith(".c") and n != f"{prefix}.c")
        files[unity] = "".join(f'#include "{n}"\n' for n in [*model_c, f"{prefix}_solvers.c"])
        return cls(compile_library(prefix, files, unity, flags), prefix)

    # ---------------------------------------------------------------------------------------
    def _names(self, what: str, n: int) -> tuple[str, ...]:
        if n == 0:
            return ()
        arr = (ctypes.c_char_p * n).in_dll(self.lib, f"{self.prefix}_{what}")
        return tuple(x.decode() for x in arr)

    def driver(self, method: str) -> Driver:
        """The run driver of ``method`` in this library, bound once: its arguments unchecked,
        an interrupt its status (:class:`~derive.runtime.records.Driver`)."""
        if method not in self._drivers:
            if method not in compiled_methods():
                raise ValueError(f"unknown method {method!r}; known: "
                                 f"{', '.join(compiled_methods())}")
            if not hasattr(self.lib, f"{self.prefix}_run_{method}"):
                raise ValueError(f"method {method!r} was not compiled into {self.prefix}")
            self._drivers[method] = Driver(self.lib, self.prefix, method, interruptible=False)
        return self._drivers[method]

    def _vector(self, x, n: int, what: str) -> np.ndarray:
        a = np.ascontiguousarray(x, dtype=np.float64)
        if a.shape != (n,):
            raise ValueError(f"{what} must have shape ({n},), got {a.shape}")
        return a

    # ---------------------------------------------------------------------------------------
    def rhs(self, t: float, y, p) -> np.ndarray:
        """f(t, y; p) as an array; raises IntegrationError if the model rejects the state."""
        y = self._vector(y, self.ny, "y")
        out = np.empty(self.ny)
        rc = self._rhs(float(t), y, self._vector(p, self.np, "p"), out)
        if rc:
            raise IntegrationError(
                f"t = {_fmt(t)}: state outside the model's domain (rhs returned {rc})")
        return out

    def jac(self, t: float, y, p) -> np.ndarray:
        """df_i/dy_j as an (ny, ny) array."""
        y = self._vector(y, self.ny, "y")
        out = np.empty(self.ny * self.ny)
        rc = self._jac(float(t), y, self._vector(p, self.np, "p"), out)
        if rc:
            raise IntegrationError(
                f"t = {_fmt(t)}: state outside the model's domain (jac returned {rc})")
        return out.reshape(self.ny, self.ny)

    # ---------------------------------------------------------------------------------------
    def _settings(self, method, t_out, rtol, atol, h, max_steps, newton_tol, newton_maxiter):
        """Validate the common arguments; returns (t_out array, driver arguments)."""
        m = METHODS.get(method)
        if m is None:
            raise ValueError(f"unknown method {method!r}; known: {', '.join(METHODS)}")
        t = np.ascontiguousarray(t_out, dtype=np.float64)
        if t.ndim != 1 or t.size < 1:
            raise ValueError("t_out must be a non-empty 1-D array")
        if not np.all(np.isfinite(t)):
            raise ValueError("t_out must be finite")
        if t.size > 1 and not np.all(np.diff(t) > 0):
            raise ValueError("t_out must be strictly increasing")
        if h is not None and not (np.isfinite(h) and h > 0):
            raise ValueError(f"h must be finite and > 0, got {h}")
        values = {}
        if m.driver == "adaptive":
            if not (np.isfinite(rtol) and np.isfinite(atol) and rtol >= 0 and atol >= 0
                    and (rtol > 0 or atol > 0)):
                raise ValueError(f"rtol and atol must be finite, >= 0 and not both 0, "
                                 f"got rtol={rtol}, atol={atol}")
            if int(max_steps) < 1:
                raise ValueError("max_steps must be >= 1")
            values = {"rtol": float(rtol), "atol": float(atol),
                      "h0": 0.0 if h is None else float(h), "max_steps": int(max_steps)}
        else:
            if h is None:
                raise ValueError(f"method {method!r} is fixed-step: pass the step size h")
            if t.size > 1 and np.max(np.diff(t)) / h >= 1e15:
                raise ValueError(f"h = {h} is too small for the output spacing")
            values = {"h": float(h)}
            if m.driver == "implicit":
                if not (np.isfinite(newton_tol) and newton_tol > 0):
                    raise ValueError("newton_tol must be finite and > 0")
                if int(newton_maxiter) < 1:
                    raise ValueError("newton_maxiter must be >= 1")
                values.update(newton_tol=float(newton_tol), newton_maxiter=int(newton_maxiter))
        return t, [values[name] for _, name in m.params]

    def solve(self, method: str, y0, p, t_out, rtol: float = 1e-10, atol: float = 1e-12,
              h: float | None = None, max_steps: int = DEFAULT_MAX_STEPS,
              newton_tol: float = DEFAULT_NEWTON_TOL,
              newton_maxiter: int = DEFAULT_NEWTON_MAXITER, check: bool = True) -> Solution:
        """Integrate from ``t_out[0]`` (state ``y0``) and return the state at every ``t_out``.

        ``dop853`` uses ``rtol``/``atol`` (``h``: initial step, default automatic) and
        ``max_steps``; fixed-step methods need ``h`` (each output interval is split into
        ``ceil(dt/h)`` equal steps); Gauss methods also use ``newton_tol``/``newton_maxiter``.
        With ``check`` (default) a failure raises :class:`IntegrationError`; otherwise it is
        reported in ``Solution.status``/``message``.
        """
        y0, p = self._vector(y0, self.ny, "y0"), self._vector(p, self.np, "p")
        sol = self.solve_batch(method, y0[None], p, t_out,
                               rtol, atol, h, max_steps, newton_tol, newton_maxiter, check=False)[0]
        if check and sol.status:
            raise IntegrationError(sol.message)
        return sol

    def solve_batch(self, method: str, y0s, ps, t_out, rtol: float = 1e-10,
                    atol: float = 1e-12, h: float | None = None,
                    max_steps: int = DEFAULT_MAX_STEPS, newton_tol: float = DEFAULT_NEWTON_TOL,
                    newton_maxiter: int = DEFAULT_NEWTON_MAXITER,
                    check: bool = True) -> BatchSolution:
        """Integrate ``len(y0s)`` trajectories (one C call). ``y0s``: (n_batch, ny); ``ps``:
        (n_batch, np), or (np,) shared by all. Each trajectory is bit-for-bit what ``solve``
        gives. With ``check``, the first failure raises ``IntegrationError``
        (``trajectory <b>: <message>``)."""
        t, extra = self._settings(method, t_out, rtol, atol, h, max_steps, newton_tol,
                                  newton_maxiter)
        y0s = np.ascontiguousarray(y0s, dtype=np.float64)
        if y0s.ndim != 2 or y0s.shape[1] != self.ny:
            raise ValueError(f"y0s must have shape (n_batch, {self.ny}), got {y0s.shape}")
        if not np.all(np.isfinite(y0s)):
            raise ValueError("y0s must be finite")
        n = y0s.shape[0]
        ps = np.asarray(ps, dtype=np.float64)
        if ps.ndim == 1:
            ps = np.broadcast_to(ps, (n, ps.shape[0]))
        ps = np.ascontiguousarray(ps)
        if ps.shape != (n, self.np):
            raise ValueError(f"ps must have shape ({n}, {self.np}) or ({self.np},), "
                             f"got {ps.shape}")
        if not np.all(np.isfinite(ps)):
            raise ValueError("ps must be finite")
        y = np.full((n, t.size, self.ny), np.nan)
        st = np.zeros(max(n, 1), dtype=STATS_DTYPE)
        self.driver(method)(saveat(t, outputs=False), n, y0s, ps, extra, y, None, st)
        st = st[:n]
        messages = tuple(failure_message(s, self.state_names, max_steps) if s["status"]
                         else "success" for s in st)
        if check:
            for b, s in enumerate(st):
                if s["status"]:
                    raise IntegrationError(f"trajectory {b}: {messages[b]}")
        return BatchSolution(t=t, y=y, method=method, stats=st, messages=messages)
