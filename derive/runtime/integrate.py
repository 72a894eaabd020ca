"""One C call per simulation: a (model, method) library built from a generated model's files.

A :class:`ModelKernel` is a compiled (model, method) pair: its run driver ``<name>_run_<method>``
runs the init map, the whole integration and the output map in one call, told what to save by a
``derive_saveat`` (:class:`~derive.runtime.records.SaveAt`). A :class:`BoundRun` binds one
trajectory's call to its arrays once, so a repeated call only enters C. The generic kernel over
any model's sources is :class:`derive.runtime.kernel.Kernel`; all bind their drivers through
:class:`~derive.runtime.records.Driver`.

Failures come back from C as a status code (:data:`derive.codegen.solvers.STATUS`) in the
statistics record (:data:`~derive.runtime.records.STATS_DTYPE`).
"""
from __future__ import annotations

import ctypes

import numpy as np

from derive.methods.registry import METHODS, TOLERANCE_DRIVERS
from derive.methods.registry import build as method_build, method as compiled_method
from derive.runtime.cbuild import BUILDS, DEFAULT_FLAGS, compile_library
from derive.runtime.records import (STATS_DOUBLES, STATS_DTYPE, Driver, _ptr, bind, guarded,
                                    saveat)


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
        self._init = bind(lib, f"{p}_init", [vp, vp, vp])
        self._checks = bind(lib, f"{p}_checks", [vp, vp, vp]) if desc.checks else None
        self.lanes = 0
        self.has_lanes = self.has_final = False
        if method is not None:
            self.adaptive = compiled_method(method).driver in TOLERANCE_DRIVERS  # rtol/atol, not h
            # the final-only saves: the methods that step by the tolerance alone (a fixed step's
            # samples set its steps)
            self.has_final = self.adaptive
            self._run = Driver(lib, p, method)
            self._pole_clear = bind(lib, f"{p}_pole_clear", [vp, vp, ci])
            self._outputs_at = bind(lib, f"{p}_outputs_at", [cl, vp, vp, vp, vp])
            # a Taylor method has lanes (its lanes library built for this CPU, where the
            # compiler has GNU C's vectors, holds them: taylor_lanes, the lanes' width)
            self.has_lanes = hasattr(lib, f"{p}_taylor_has_lanes")
            self.lanes = (int(ctypes.c_int.in_dll(lib, f"{p}_taylor_lanes").value)
                          if hasattr(lib, f"{p}_taylor_lanes") else 0)

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

    def pole_clear(self, y, p, mode: int) -> bool:
        """The model's compiled Routh check (see ``<name>_pole_clear``)."""
        return bool(self._pole_clear(_ptr(np.ascontiguousarray(y, dtype=np.float64)),
                                     _ptr(np.ascontiguousarray(p, dtype=np.float64)), mode))

    def simulate(self, inputs, p, t, args, pole_check: int = 0):
        """One trajectory: returns (out (NOBS, n), y (n, NY), p (derived parameters written),
        stats record). ``args``: the driver's arguments
        (:func:`derive.runtime.records.driver_args`); ``pole_check`` 1 or 2 refuses (status
        RANGE, nothing integrated) a start that fails ``pole_clear``. A one-off :class:`BoundRun` (its one buffer layout and guarded call)."""
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
        return self._call(False, lanes, inputs, ps, t, args, pole_check, y, out)

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
            The driver's arguments (:func:`derive.runtime.records.driver_args`).
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
        return self._call(True, lanes, inputs, ps, t, args, pole_check, np.empty((nb, self.ny)),
                          np.empty((nb, self.nout)))

    def _call(self, final, lanes, inputs, ps, t, args, pole_check, y, out):
        """The run driver over a batch, writing into ``y`` and ``out``: (out, y, ps, stats)."""
        nb = inputs.shape[0]
        ps = np.array(ps, dtype=np.float64, order="C")
        st = np.zeros(max(nb, 1), dtype=STATS_DTYPE)
        inputs = np.ascontiguousarray(inputs, dtype=np.float64)
        t = np.ascontiguousarray(t, dtype=np.float64)
        save = saveat(t, final=final, pole_check=pole_check, lanes=lanes)
        self._run(save, nb, inputs, ps, args, y, out, st)
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
        The driver's arguments (:func:`derive.runtime.records.driver_args`).
    pole_check : int
        0, 1 or 2, as for :meth:`ModelKernel.simulate`.
    """

    __slots__ = ("kernel", "t", "inputs", "_size", "_shape_out", "_shape_y", "_k_y", "_k_p", "_k_st",
                 "_fn", "_save", "_head", "_settings", "_guard", "_status", "_nfev")

    def __init__(self, kernel: "ModelKernel", t: np.ndarray, inputs: np.ndarray, args, pole_check: int = 0):
        t = np.ascontiguousarray(t, dtype=np.float64)
        inputs = np.ascontiguousarray(inputs, dtype=np.float64)
        self.kernel, self.t, self.inputs = kernel, t, inputs
        n = t.shape[0]
        size_out, size_y = kernel.nout * n, n * kernel.ny
        self._k_y, self._k_p = size_out, size_out + size_y
        self._k_st = self._k_p + kernel.np
        self._size = self._k_st + STATS_DOUBLES
        self._shape_out, self._shape_y = (kernel.nout, n), (n, kernel.ny)
        # The driver without argtypes, given ctypes instances: nothing is converted per call
        # (the instances of the arguments that do not change are made once per kernel).
        self._fn, self._guard, self._settings = kernel._run.unchecked(args)
        self._save = saveat(t, pole_check=pole_check)  # (kept: the driver reads it each call)
        self._head = (ctypes.c_void_p(ctypes.addressof(self._save)), ctypes.c_long(1),
                      ctypes.c_void_p(inputs.ctypes.data))
        self._status = 8 * self._k_st + _STATUS_OFFSET
        self._nfev = 8 * self._k_st + _NFEV_OFFSET

    def __call__(self, p: np.ndarray, inputs: np.ndarray | None = None):
        """Run once.

        Parameters
        ----------
        p : ndarray
            The parameter vector (copied into the call's buffer; the init map writes the
            derived parameters there).
        inputs : ndarray, optional
            C-contiguous float64 inputs replacing the bound ones for this call.
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
        rc = guarded(self._guard, self._fn, *args)  # Ctrl-C stops the C loop from the main thread
        # a driver returns its record's status; read the record only when it is not OK
        status = ctypes.c_int.from_buffer(buf, self._status).value if rc else 0
        nfev = ctypes.c_long.from_buffer(buf, self._nfev).value
        return (buf[:self._k_y].reshape(self._shape_out), buf[self._k_y:k_p].reshape(self._shape_y),
                buf[k_p:k_st], status, nfev, buf)

    def stats(self, buf: np.ndarray):
        """The stats record (STATS_DTYPE) of a call's ``buf``."""
        return buf[self._k_st:].view(STATS_DTYPE)[0]
