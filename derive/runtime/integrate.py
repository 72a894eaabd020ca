"""Integrate a compiled model: the Python face of the generated C solvers.

A :class:`Kernel` wraps one loaded library holding a model (``<prefix>_rhs``, ``<prefix>_jac``,
the state and parameter names) and its rendered solvers: one driver per method,
``<prefix>_run_<method>``, told what to save by a ``derive_saveat`` (:class:`SaveAt`). Python
enters C once per trajectory (``solve``) or once per batch (``solve_batch``); the stepping,
step-size control and dense output all run in C.

Methods are the registry :data:`derive.methods.registry.METHODS` (``dop853``, ``rk4``, ``gauss4``,
``gauss6``, ``dop853_fixed``); how each is called follows from its driver's parameter list
(:data:`derive.methods.registry.DRIVER_PARAMS`), so a new method needs no code here.

Failures come back from C as a status code (:data:`derive.codegen.solvers.STATUS`) plus where they
happened; :func:`failure_message` turns them into the one line that
:class:`~derive.errors.IntegrationError` carries, naming the state by its model name.
"""
from __future__ import annotations

import ctypes
import re
import time
from dataclasses import dataclass, field

import numpy as np

from derive.runtime.cbuild import BUILDS, DEFAULT_FLAGS, compile_library
from derive.errors import IntegrationError
from derive.methods.registry import METHODS, TOLERANCE_DRIVERS
from derive.methods.registry import build as method_build, method as compiled_method
from derive.codegen.solvers import render_solvers
from derive.methods.status import Status
from derive.methods.status import message as _status_message

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

_STATS_DOUBLES = STATS_DTYPE.itemsize // 8
assert STATS_DTYPE.itemsize % 8 == 0 and STATS_DTYPE.alignment <= 8  # a record fits a double slice

_C_TYPES = {"double": ctypes.c_double, "long": ctypes.c_long, "int": ctypes.c_int}


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
_F64 = np.ctypeslib.ndpointer(dtype=np.float64, flags="C_CONTIGUOUS")
_STATS = np.ctypeslib.ndpointer(dtype=STATS_DTYPE, flags="C_CONTIGUOUS")


def _fmt(x: float) -> str:
    return f"{x:.8g}"


def failure_message(stats, state_names=(), max_steps: int | None = None) -> str:
    """The one-line description of a failed solve (``stats``: a STATS_DTYPE record)."""
    return _status_message(stats, state_names, max_steps)


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
        return _solution(self.t, self.y[b], self.method, self.stats[b], self.messages[b])


def _solution(t, y, method, st, message) -> Solution:
    status = int(st["status"])
    return Solution(
        t=t, y=y, method=method, status=status,
        nfev=int(st["nfev"]), njev=int(st["njev"]), nstep=int(st["nstep"]),
        naccept=int(st["naccept"]), nreject=int(st["nreject"]), nlu=int(st["nlu"]),
        message=message,
        t_fail=float(st["t_fail"]) if status else None,
        fail_index=int(st["fail_index"]) if status == 2 else None)


def _header_ny(prefix: str, sources: dict[str, str]) -> int:
    header = sources.get(f"{prefix}.h")
    if header is None:
        raise ValueError(f"sources lack the model header {prefix}.h")
    m = re.search(rf"^\s*#\s*define\s+{re.escape(prefix)}_NY\s+\(?\s*(\d+)\s*\)?", header, re.M)
    if not m:
        raise ValueError(f"{prefix}.h does not #define {prefix}_NY as an integer literal")
    return int(m.group(1))


class Kernel:
    """A compiled model and its solvers.

    ``prefix``, ``ny``, ``np``, ``state_names``, ``param_names`` come from the library itself
    (``<prefix>_dims`` and the model's name arrays); ``methods`` lists the solvers it holds.
    """

    def __init__(self, lib: ctypes.CDLL, prefix: str):
        self.lib = lib
        self.prefix = prefix
        dims = (ctypes.c_int * 4).in_dll(lib, f"{prefix}_dims")
        self.ny, self.np = int(dims[0]), int(dims[1])
        self.state_names = self._names("state_names", self.ny)
        self.param_names = self._names("param_names", self.np)
        self._rhs = self._bind(f"{prefix}_rhs", [ctypes.c_double, _F64, _F64, _F64])
        self._jac = self._bind(f"{prefix}_jac", [ctypes.c_double, _F64, _F64, _F64])
        self.methods = tuple(m for m in METHODS if hasattr(lib, f"{prefix}_run_{m}"))
        self._solvers: dict[str, tuple] = {}

    def __repr__(self) -> str:
        return (f"Kernel({self.prefix!r}, y=({', '.join(self.state_names)}), "
                f"p=({', '.join(self.param_names)}))")

    # ---------------------------------------------------------------------------------------
    @classmethod
    def from_sources(cls, prefix: str, sources: dict[str, str], methods: list[str] | None = None,
                     flags=DEFAULT_FLAGS) -> "Kernel":
        """Render the solvers for the model in ``sources`` (``<prefix>.h``, ``<prefix>.c``, ...),
        compile everything as one translation unit (so the compiler can inline the rhs into the
        stepper) and load it. Compiled once per machine, loaded once per process."""
        ny = _header_ny(prefix, sources)
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

    def _bind(self, symbol: str, argtypes):
        fn = getattr(self.lib, symbol)
        fn.argtypes = argtypes
        fn.restype = ctypes.c_int
        return fn

    def _solver(self, method: str):
        if method not in self._solvers:
            if method not in METHODS:
                raise ValueError(f"unknown method {method!r}; known: {', '.join(METHODS)}")
            if method not in self.methods:
                raise ValueError(f"method {method!r} was not compiled into {self.prefix}")
            extra = [_C_TYPES[ty] for ty, _ in METHODS[method].params]
            self._solvers[method] = self._bind(
                f"{self.prefix}_run_{method}",
                [ctypes.POINTER(SaveAt), ctypes.c_long, _F64, _F64, *extra, _F64, ctypes.c_void_p,
                 _STATS])
        return self._solvers[method]

    def _vector(self, x, n: int, what: str) -> np.ndarray:
        a = np.ascontiguousarray(x, dtype=np.float64)
        if a.shape != (n,):
            raise ValueError(f"{what} must have shape ({n},), got {a.shape}")
        return a

    def _params(self, p) -> np.ndarray:
        a = self._vector(p, self.np, "p")
        if not np.all(np.isfinite(a)):
            raise ValueError("p must be finite")
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
        t, extra = self._settings(method, t_out, rtol, atol, h, max_steps, newton_tol,
                                  newton_maxiter)
        y0 = self._vector(y0, self.ny, "y0")
        if not np.all(np.isfinite(y0)):
            raise ValueError("y0 must be finite")
        p = self._params(p)
        y = np.full((t.size, self.ny), np.nan)
        st = np.zeros(1, dtype=STATS_DTYPE)
        self._solver(method)(saveat(t, outputs=False), 1, y0, p, *extra, y, None, st)
        st = st[0]
        message = "success"
        if st["status"]:
            message = failure_message(st, self.state_names, max_steps)
            if check:
                raise IntegrationError(message)
        return _solution(t, y, method, st, message)

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
        self._solver(method)(saveat(t, outputs=False), n, y0s, ps, *extra, y, None, st)
        st = st[:n]
        messages = tuple(failure_message(s, self.state_names, max_steps) if s["status"]
                         else "success" for s in st)
        if check:
            for b, s in enumerate(st):
                if s["status"]:
                    raise IntegrationError(f"trajectory {b}: {messages[b]}")
        return BatchSolution(t=t, y=y, method=method, stats=st, messages=messages)


# ---------------------------------------------------------------------------------------------
# One C call per simulation: a (model, method) library built from a generated model's files.

def _ptr(a: np.ndarray) -> int:
    # ndarray.ctypes.data: __array_interface__ would build a structured dtype's description
    # (derive_stats) on every call.
    return a.ctypes.data


def _interruptible(lib, prefix: str):
    """Run a C call with SIGINT handled by the library (the loops poll its flag) when called
    from the main thread; a call from another thread relies on ``derive_sigint_request``."""
    import threading

    guard = lib.derive_sigint_guard
    return guard if threading.current_thread() is threading.main_thread() else None


class ModelKernel:
    """A compiled (model, method) pair: ``<name>_run_<method>`` runs the init map, the whole
    integration and the output map in one call, writing into arrays passed in; what it saves
    (every sample or the last, one trajectory or a batch, lanes) is its :class:`SaveAt`.

    Built from a :class:`derive.runtime.catalogue.Description` and its generated C files (the model and
    its solvers, one translation unit compiled with only this method: ``-DDERIVE_SELECT
    -DDERIVE_WITH_<METHOD>``). ``method=None`` builds the model alone (init map, checks).
    """

    _cache: dict = {}

    def __init__(self, desc, method: str | None, lib: ctypes.CDLL):
        self.desc, self.method, self.lib = desc, method, lib
        p = desc.name
        self.ny, self.np, self.nout, self.nin = (len(desc.states), len(desc.params),
                                                 len(desc.outputs), desc.nin)
        vp, cl, ci = ctypes.c_void_p, ctypes.c_long, ctypes.c_int
        self._init = self._fn(f"{p}_init", [vp, vp, vp])
        self._checks = self._fn(f"{p}_checks", [vp, vp, vp]) if desc.checks else None
        self.lanes = 0
        self.has_lanes = self.has_final = False
        if method is not None:
            spec = compiled_method(method)
            extra = [_C_TYPES[ty] for ty, _ in spec.params]
            self._arg_names = tuple(name for _, name in spec.params)
            self.adaptive = spec.driver in TOLERANCE_DRIVERS  # steps by rtol/atol, not by h
            # the final-only saves: the methods that step by the tolerance alone (a fixed step's
            # samples set its steps)
            self.has_final = self.adaptive
            self._run = self._fn(f"{p}_run_{method}", [vp, cl, vp, vp, *extra, vp, vp, vp])
            self._pole_clear = self._fn(f"{p}_pole_clear", [vp, vp, ci])
            self._outputs_at = self._fn(f"{p}_outputs_at", [cl, vp, vp, vp, vp])
            # a Taylor method has lanes (its lanes library built for this CPU, where the
            # compiler has GNU C's vectors, holds them: taylor_lanes, the lanes' width)
            self.has_lanes = hasattr(lib, f"{p}_taylor_has_lanes")
            self.lanes = (int(ctypes.c_int.in_dll(lib, f"{p}_taylor_lanes").value)
                          if hasattr(lib, f"{p}_taylor_lanes") else 0)
            self._guard = _interruptible(lib, p)
            if self._guard is not None:
                self._guard.argtypes = [ci]
                self._guard.restype = ci
        self._bound_parts: dict = {}

    def _unchecked_call(self, args):
        """(driver, guard, driver arguments as ctypes instances) for :class:`BoundRun`: the
        driver and the guard without argtypes (they convert nothing), made once per kernel and
        set of arguments."""
        key = tuple(args)
        parts = self._bound_parts.get(key)
        if parts is None:
            run = self._run
            conv = tuple(ty(v) for ty, v in zip(run.argtypes[4:], args))
            guard = None if self._guard is None else _unchecked(self.lib, self._guard.__name__)
            parts = self._bound_parts[key] = (_unchecked(self.lib, run.__name__), guard, conv)
        return parts

    def _fn(self, symbol, argtypes):
        fn = getattr(self.lib, symbol)
        fn.argtypes = argtypes
        fn.restype = ctypes.c_int
        return fn

    @classmethod
    def load(cls, desc, method: str | None, build: str | None = None) -> "ModelKernel":
        """Compiled once per machine (the cache), loaded once per process. ``build``
        (:data:`derive.runtime.cbuild.BUILDS`): ``"lanes"`` for the lanes driver of a Taylor
        method (:meth:`simulate_lanes_batch`), ``"portable"`` for the baseline build; by
        default the method's own (:func:`derive.methods.registry.build`). The scalar drivers
        give the same numbers in every build."""
        build = build or method_build(method)
        key = (desc.folder, desc.name, method, build)
        kernel = cls._cache.get(key)
        if kernel is None:
            sources = desc.c_sources()
            unity = f"{desc.name}_{method or 'model'}_unit.c"
            includes = [f"{desc.name}.c"] + ([f"{desc.name}_solvers.c"] if method else [])
            if method is not None and method not in METHODS:  # a splitting or a Taylor method:
                family = "taylor" if compiled_method(method).driver == "taylor" else "splitting"
                includes.append(f"{desc.name}_{family}.c")  # its own file, after the solvers
                if f"{desc.name}_{family}.c" not in sources:  # (interrupt flag, drivers)
                    raise ValueError(f"method {method!r} was not generated for the model {desc.name}")
            sources[unity] = "".join(f'#include "{n}"\n' for n in includes)
            flags = list(DEFAULT_FLAGS) + list(BUILDS[build])
            if method is not None:
                flags += ["-DDERIVE_SELECT", f"-DDERIVE_WITH_{method.upper()}"]
            lib = compile_library(f"{desc.name}_{method or 'model'}{'' if build == 'portable' else '_' + build}",
                                  sources, unity, flags)
            kernel = cls._cache[key] = cls(desc, method, lib)
        return kernel

    def driver_args(self, rtol, atol, h, max_steps, newton_tol=DEFAULT_NEWTON_TOL,
                    newton_maxiter=DEFAULT_NEWTON_MAXITER) -> list:
        values = {"rtol": rtol, "atol": atol, "h0": 0.0, "max_steps": max_steps, "h": h,
                  "newton_tol": newton_tol, "newton_maxiter": newton_maxiter}
        return [values[name] for name in self._arg_names]

    def init(self, inputs: np.ndarray, p: np.ndarray) -> tuple[np.ndarray, np.ndarray, int]:
        """(y0, p with the derived parameters written, return code) from the init map."""
        y = np.empty(self.ny)
        p = np.array(p, dtype=np.float64)
        rc = self._init(_ptr(np.ascontiguousarray(inputs, dtype=np.float64)), _ptr(p), _ptr(y))
        return y, p, rc

    def checks(self, y: np.ndarray, p: np.ndarray) -> np.ndarray:
        out = np.empty(len(self.desc.checks))
        self._checks(_ptr(np.ascontiguousarray(y, dtype=np.float64)),
                     _ptr(np.ascontiguousarray(p, dtype=np.float64)), _ptr(out))
        return out

    def _call(self, fn, *args):
        if self._guard is None:
            return fn(*args)
        self._guard(1)
        try:
            rc = fn(*args)
        finally:
            interrupted = self._guard(0)
        if interrupted or rc == Status.INTERRUPTED:
            raise KeyboardInterrupt
        return rc

    def pole_clear(self, y, p, mode: int) -> bool:
        """The model's compiled Routh check (see ``<name>_pole_clear``)."""
        return bool(self._pole_clear(_ptr(np.ascontiguousarray(y, dtype=np.float64)),
                                     _ptr(np.ascontiguousarray(p, dtype=np.float64)), mode))

    def simulate(self, inputs, p, t, args, pole_check: int = 0):
        """One trajectory: returns (out (NOBS, n), y (n, NY), p (derived parameters written),
        stats record). ``args``: the driver's arguments (``driver_args``); ``pole_check`` 1 or 2
        refuses (status RANGE, nothing integrated) a start that fails ``pole_clear``. A
        one-off :class:`BoundRun` (its one buffer layout and guarded call)."""
        bound = self.bind(t, inputs, args, pole_check)
        out, y, pp, _, _, buf = bound(np.asarray(p, dtype=np.float64))
        return out, y, pp, bound.stats(buf)

    def bind(self, t: np.ndarray, inputs: np.ndarray, args, pole_check: int = 0) -> "BoundRun":
        """The C call of :meth:`simulate` with everything that does not change per run worked out
        once (see :class:`BoundRun`): for a prepared simulation run many times."""
        return BoundRun(self, t, inputs, args, pole_check)

    def simulate_batch(self, inputs, ps, t, args, pole_check: int = 0, buffers=None, lanes: bool = False):
        """N trajectories (inputs (N, NIN), ps (N, NP)): (out (N, NOBS, n), y (N, n, NY), ps,
        stats (N,)); each bit-for-bit what ``simulate`` gives. With ``pole_check`` the first
        start that fails it stops the batch (its status RANGE). ``buffers``: (out, y) arrays to
        write into instead of new ones (C-contiguous float64, at least N trajectories long; the
        first N are used), so a caller running chunks maps its work arrays once. ``lanes``: by
        a Taylor method's lanes (``SaveAt.lanes``, :attr:`has_lanes_full`: :attr:`lanes`
        trajectories at once), the same numbers, statuses and statistics; a refused start then
        stops the batch before anything is integrated."""
        if lanes and not self.has_lanes_full:
            raise ValueError(f"{self.desc.name}: method {self.method!r} has no full-grid lanes batch driver")
        nb, n = inputs.shape[0], t.shape[0]
        if buffers is None:
            out = np.empty((nb, self.nout, n))
            y = np.empty((nb, n, self.ny))
        else:
            out, y = buffers[0][:nb], buffers[1][:nb]
            if (out.shape != (nb, self.nout, n) or y.shape != (nb, n, self.ny) or out.dtype != np.float64
                    or y.dtype != np.float64 or not (out.flags.c_contiguous and y.flags.c_contiguous)):
                raise ValueError("simulate_batch: buffers must be C-contiguous float64 arrays of shapes "
                                 f"(>= {nb}, {self.nout}, {n}) and (>= {nb}, {n}, {self.ny})")
        ps = np.array(ps, dtype=np.float64, order="C")
        st = np.zeros(max(nb, 1), dtype=STATS_DTYPE)
        inputs = np.ascontiguousarray(inputs, dtype=np.float64)
        t = np.ascontiguousarray(t, dtype=np.float64)
        save = saveat(t, pole_check=pole_check, lanes=lanes)
        self._call(self._run, ctypes.byref(save), nb, _ptr(inputs), _ptr(ps), *args,
                   _ptr(y), _ptr(out), _ptr(st))
        return out, y, ps, st[:nb]

    def full_lanes(self, n: int) -> "ModelKernel | None":
        """The kernel whose full-grid lanes driver runs this kernel's full batch of ``n``
        trajectories (``simulate_batch(..., lanes=True)``: the same numbers), or None: a Taylor
        method's lanes library (built for this CPU, compiled on first use) where the compiler
        has GNU C's vectors, for a batch of at least :data:`LANES_MIN` (a smaller one gains
        nothing from the lanes and would compile their library for it)."""
        if not self.has_lanes or n < LANES_MIN:
            return None
        lanes = ModelKernel.load(self.desc, self.method, "lanes")
        return lanes if lanes.has_lanes_full else None

    @property
    def has_lanes_full(self) -> bool:
        """Whether the library holds the full-grid lanes driver (``simulate_batch(lanes=True)``):
        a Taylor method's lanes library (``load(..., "lanes")``) built with GNU C's vectors."""
        return self.lanes > 0

    def simulate_lanes_batch(self, inputs, ps, t, args, pole_check: int = 0):
        """:meth:`simulate_final_batch` with the trajectories run :attr:`lanes` at a time by a
        Taylor method's lanes (``SaveAt.lanes``, :attr:`has_lanes_full`): each trajectory's
        numbers, status and statistics are the scalar driver's bit for bit (every lane its own
        steps). Every start is made first: a refused one (``pole_check``) stops the batch with
        status RANGE before anything is integrated. Same arguments and results."""
        if not self.has_lanes_full:
            raise ValueError(f"{self.desc.name}: method {self.method!r} has no lanes batch driver")
        return self._final_call(True, inputs, ps, t, args, pole_check)

    def simulate_final_batch(self, inputs, ps, t, args, pole_check: int = 0):
        """N trajectories integrated straight to ``t[-1]``, the last sample only.

        The C driver ``<name>_run_<method>`` saving the last time (``SaveAt.final``): the same steps as
        :meth:`simulate_batch` (its interior samples are dense output), no output map but at the
        end, and the angles of that one sample made canonical alone (β's range, no unwrapping
        from the samples before: for formulations whose α, γ are states, see
        :attr:`derive.symbolic.formulations.Formulation.angle_states`).

        Parameters
        ----------
        inputs : ndarray, shape (N, NIN)
            The init map's inputs per trajectory.
        ps : ndarray, shape (N, NP)
            The parameter vectors (copied; the copy gets the derived parameters).
        t : ndarray
            The output times of the full grid (its first and last are used, the rest checked).
        args : list
            The driver's arguments (:meth:`driver_args`).
        pole_check : int
            0, 1 or 2, as for :meth:`simulate_batch` (the first refusal stops the batch).

        Returns
        -------
        tuple
            (out (N, NOBS), y (N, NY), ps, stats (N,)).
        """
        if not self.has_final:
            raise ValueError(f"{self.desc.name}: method {self.method!r} has no final-only batch driver")
        return self._final_call(False, inputs, ps, t, args, pole_check)

    def _final_call(self, lanes, inputs, ps, t, args, pole_check):
        nb = inputs.shape[0]
        out = np.empty((nb, self.nout))
        y = np.empty((nb, self.ny))
        ps = np.array(ps, dtype=np.float64, order="C")
        st = np.zeros(max(nb, 1), dtype=STATS_DTYPE)
        inputs = np.ascontiguousarray(inputs, dtype=np.float64)
        t = np.ascontiguousarray(t, dtype=np.float64)
        save = saveat(t, final=True, pole_check=pole_check, lanes=lanes)
        self._call(self._run, ctypes.byref(save), nb, _ptr(inputs), _ptr(ps), *args,
                   _ptr(y), _ptr(out), _ptr(st))
        return out, y, ps, st[:nb]

    def outputs_at(self, t, y, p) -> np.ndarray:
        """The outputs (NOBS, n) of given states y (n, NY) (e.g. from SciPy's solve_ivp)."""
        n = t.shape[0]
        out = np.empty((self.nout, n))
        y = np.ascontiguousarray(y, dtype=np.float64)
        self._outputs_at(n, _ptr(np.ascontiguousarray(t, dtype=np.float64)), _ptr(y),
                         _ptr(np.ascontiguousarray(p, dtype=np.float64)), _ptr(out))
        return out


#: The fewest trajectories a full batch runs in lanes (:meth:`ModelKernel.full_lanes`): one
#: lane set of AVX-512.
LANES_MIN = 8

_STATUS_OFFSET = STATS_DTYPE.fields["status"][1]
_NFEV_OFFSET = STATS_DTYPE.fields["nfev"][1]


_INTERRUPTED = int(Status.INTERRUPTED)
_ON, _OFF = ctypes.c_int(1), ctypes.c_int(0)  # the guard's arguments, made once

#: Seconds under which a guarded prepared call counts as short (see :class:`BoundRun`): far
#: below the half second within which Ctrl-C must stop a run, even on a loaded machine.
SHORT_CALL = 0.02


def _unchecked(lib, symbol: str):
    """A fresh function object of ``symbol`` with no argtypes (int result): called with ctypes
    instances only, it converts nothing (the library's own object keeps its argtypes)."""
    fn = lib[symbol]
    fn.restype = ctypes.c_int
    return fn


class BoundRun:
    """One trajectory's whole-simulation call (:meth:`ModelKernel.simulate`) bound to its output
    times, init-map inputs, driver arguments and pole check: the buffer layout, the pointers of
    the arrays it keeps (``t``, ``inputs``) and the converted driver arguments are worked out
    once, so a call allocates its one output buffer and enters C.

    Parameters
    ----------
    kernel : ModelKernel
        The compiled (model, method) pair.
    t : ndarray
        The output times (C-contiguous float64; kept, not copied: the caller must not change it).
    inputs : ndarray
        The init map's inputs (as ``t``).
    args : list
        The driver's arguments (:meth:`ModelKernel.driver_args`).
    pole_check : int
        0, 1 or 2, as for :meth:`ModelKernel.simulate`.
    """

    __slots__ = ("kernel", "t", "inputs", "_size", "_shape_out", "_shape_y", "_k_y", "_k_p", "_k_st",
                 "_fn", "_save", "_head", "_settings", "_guard", "_status", "_nfev", "_short")

    def __init__(self, kernel: "ModelKernel", t: np.ndarray, inputs: np.ndarray, args, pole_check: int = 0):
        t = np.ascontiguousarray(t, dtype=np.float64)
        inputs = np.ascontiguousarray(inputs, dtype=np.float64)
        self.kernel, self.t, self.inputs = kernel, t, inputs
        n = t.shape[0]
        size_out, size_y = kernel.nout * n, n * kernel.ny
        self._k_y, self._k_p = size_out, size_out + size_y
        self._k_st = self._k_p + kernel.np
        self._size = self._k_st + _STATS_DOUBLES
        self._shape_out, self._shape_y = (kernel.nout, n), (n, kernel.ny)
        # The driver without argtypes, given ctypes instances: nothing is converted per call
        # (the instances of the arguments that do not change are made once per kernel).
        self._fn, self._guard, self._settings = kernel._unchecked_call(args)
        self._save = saveat(t, pole_check=pole_check)  # (kept: the driver reads it each call)
        self._head = (ctypes.c_void_p(ctypes.addressof(self._save)), ctypes.c_long(1),
                      ctypes.c_void_p(inputs.ctypes.data))
        self._status = 8 * self._k_st + _STATUS_OFFSET
        self._nfev = 8 * self._k_st + _NFEV_OFFSET
        self._short = False

    def __call__(self, p: np.ndarray, inputs: np.ndarray | None = None, same: bool = False):
        """Run once.

        Parameters
        ----------
        p : ndarray
            The parameter vector (copied into the call's buffer; the init map writes the
            derived parameters there).
        inputs : ndarray, optional
            C-contiguous float64 inputs replacing the bound ones for this call.
        same : bool
            The caller's word that ``p`` and the inputs are those of every other ``same`` call
            (a prepared run without new values): the C work is then the same each time, and once
            a guarded call has shown it short (:data:`SHORT_CALL`), the interrupt guard is left
            out, as a Ctrl-C during so short a call is raised by Python when it returns.

        Returns
        -------
        tuple
            (out (NOBS, n), y (n, NY), p (derived parameters written), status, nfev, buf): fresh
            arrays of one buffer ``buf`` (:meth:`stats` reads its stats record).
        """
        # Uninitialised but for the stats record, cleared as in simulate (every driver path starts
        # it with stats_init; clearing it too costs nothing): the outputs and states are written
        # by the driver before they are read, so zeroing the whole buffer would be wasted work.
        # On a failure they are never read (the caller raises).
        buf = np.empty(self._size)
        k_p, k_st = self._k_p, self._k_st
        buf[k_st:] = 0.0
        buf[k_p:k_st] = p
        base = ctypes.addressof(ctypes.c_char.from_buffer(buf))
        head = self._head if inputs is None else (*self._head[:2], ctypes.c_void_p(inputs.ctypes.data))
        args = (*head, ctypes.c_void_p(base + 8 * k_p), *self._settings,
                ctypes.c_void_p(base + 8 * self._k_y), ctypes.c_void_p(base),
                ctypes.c_void_p(base + 8 * k_st))
        guard = self._guard
        if guard is None or (same and self._short):
            rc = self._fn(*args)
        else:
            t0 = time.perf_counter()
            guard(_ON)
            try:
                rc = self._fn(*args)
            finally:
                interrupted = guard(_OFF)
            if interrupted or rc == _INTERRUPTED:
                raise KeyboardInterrupt
            if same and time.perf_counter() - t0 < SHORT_CALL:
                self._short = True
        # a driver returns its record's status; read the record only when it is not OK
        status = ctypes.c_int.from_buffer(buf, self._status).value if rc else 0
        nfev = ctypes.c_long.from_buffer(buf, self._nfev).value
        return (buf[:self._k_y].reshape(self._shape_out), buf[self._k_y:k_p].reshape(self._shape_y),
                buf[k_p:k_st], status, nfev, buf)

    def stats(self, buf: np.ndarray):
        """The stats record (STATS_DTYPE) of a call's ``buf``."""
        return buf[self._k_st:].view(STATS_DTYPE)[0]
