"""Measures of a trajectory, computed in the compiled loop while integrating (for sweeps).

A measure is one registry entry (:data:`REGISTRY`): its name, unit, what it reads and, if it
takes one, its option. Nothing else names a measure by a string; :mod:`derive.sweeps` asks the
registry which columns a measure gives and reads them from one compiled call.

Contract of an entry (:class:`Measure`):

1. ``name``: the key in ``[measure] names`` and the result's column (``columns`` when several).
2. ``reads``: where the numbers come from, one of

   * ``"slot"``: an accumulator of ``templates/c/measures.c.j2`` (``slot``), updated by the
     driver's hook after every accepted step, with the step's dense output at hand;
   * ``"stats"``: the solver's statistics record (``nfev``);
   * ``"final"``: the outputs at t_end (the output map, in C);
   * ``"slots"``: a ``formula`` of the accumulators (``nutation`` = beta_max − beta_min).
3. ``options``: {option: (default, unit, one-line meaning)} — read from the sweep file's
   ``[measure.<name>]`` table and passed to the compiled loop through ``config`` (index
   ``CONFIG``). Only ``time_to_tilt`` has one (``angle``).
4. ``needs``: the compiled loop's work flags (``CONFIG``): ``steps`` runs the per-step hook
   (the dense output is then formed on every accepted step: DOP853's three dense stages per
   step, counted in ``nfev``, plus the output map at each step end); ``flip_time`` and
   ``tilt_time`` locate those times. A sweep asking only for ``nfev`` and ``final_state`` runs
   the plain loop's work.

The accumulators (``SLOTS``) are all updated whenever the hook runs (a compare or two per
step; the extrema search runs only at the turning points).

Conventions: beta is the z-y-z nutation angle in [0, pi] (the output map's, made canonical);
omega2 the body-frame component ω̃₂; energy T + V; p_alpha, p_gamma the conjugate momenta.
"""
from __future__ import annotations

import ctypes
import math
from dataclasses import dataclass, field

import numpy as np

#: The compiled accumulators, in the order of the C enum (rendered from this tuple).
SLOTS = ("beta_max", "beta_min", "energy_drift", "p_alpha_drift", "p_gamma_drift", "flips",
         "time_to_flip", "time_to_tilt")
#: config[] of the compiled loop: the option values and the work flags a measure ``needs``.
CONFIG = {"angle": 0, "steps": 1, "flip_time": 2, "tilt_time": 3}
#: The outputs the compiled loop reads (by name; their indices come from the model's outputs).
READS = ("beta", "energy", "omega2", "p_alpha", "p_gamma")
#: The outputs ``final_state`` reports at t_end.
FINAL = ("alpha", "beta", "gamma", "omega1", "omega2", "omega3")


@dataclass(frozen=True)
class Measure:
    name: str
    unit: str
    doc: str
    reads: str  # "slot" | "stats" | "final" | "slots" (formula of the accumulators)
    slot: str | None = None
    formula: object = None  # reads == "slots": {slot: (N,) array} -> (N,) array
    options: dict = field(default_factory=dict)
    needs: tuple = ()  # work flags of the compiled loop (CONFIG): "steps", "flip_time", "tilt_time"

    @property
    def columns(self) -> tuple[str, ...]:
        return tuple(f"final_{n}" for n in FINAL) if self.reads == "final" else (self.name,)


REGISTRY: dict[str, Measure] = {m.name: m for m in (
    Measure("beta_max", "rad", "largest nutation angle beta, located on the dense output", "slot",
            "beta_max", needs=("steps",)),
    Measure("beta_min", "rad", "smallest nutation angle beta, located on the dense output", "slot",
            "beta_min", needs=("steps",)),
    Measure("nutation", "rad", "beta_max - beta_min: the nutation amplitude (a top released at a "
            "turning point)", "slots", formula=lambda r: r["beta_max"] - r["beta_min"],
            needs=("steps",)),
    Measure("energy_drift", "", "max over the steps of |E - E0| / |E0|", "slot", "energy_drift",
            needs=("steps",)),
    Measure("p_alpha_drift", "kg m^2/s", "max over the steps of |p_alpha - p_alpha(0)|", "slot",
            "p_alpha_drift", needs=("steps",)),
    Measure("p_gamma_drift", "kg m^2/s", "max over the steps of |p_gamma - p_gamma(0)|", "slot",
            "p_gamma_drift", needs=("steps",)),
    Measure("flips", "", "sign changes of omega2 (body frame) between step ends", "slot", "flips",
            needs=("steps",)),
    Measure("time_to_flip", "s", "first sign change of omega2, on the dense output (NaN: none)",
            "slot", "time_to_flip", needs=("steps", "flip_time")),
    Measure("time_to_tilt", "s", "first time beta exceeds the option angle (NaN: never)", "slot",
            "time_to_tilt", options={"angle": (math.pi / 2, "rad", "the tilt threshold")},
            needs=("steps", "tilt_time")),
    Measure("nfev", "", "right-hand-side evaluations (the dense stages of every step included)",
            "stats"),
    Measure("final_state", "", "alpha, beta, gamma, omega1..3 at t_end (alpha, gamma unwrapped "
            "from the start alone: equal to a sampled run's modulo 2 pi)", "final"),
)}

DEFAULT = ("beta_max", "beta_min", "energy_drift", "nfev")


def owner(column: str) -> str | None:
    """The measure that gives this result column (``final_beta`` -> ``final_state``), or None."""
    for m in REGISTRY.values():
        if column == m.name or column in m.columns:
            return m.name
    return None


def config_of(names, options: dict | None = None) -> np.ndarray:
    """The compiled loop's config[] for the measures ``names``: the options ({measure: {option:
    value}}, defaults filled in) and the work flags they need."""
    options = options or {}
    cfg = np.zeros(len(CONFIG))
    for name in names:
        m = REGISTRY[name]
        for flag in m.needs:
            cfg[CONFIG[flag]] = 1.0
    for m in REGISTRY.values():
        for opt, (default, _, _) in m.options.items():
            cfg[CONFIG[opt]] = float(options.get(m.name, {}).get(opt, default))
    return cfg


def read(names, desc, res, stats, final) -> dict:
    """{column: 1-D array} of the measures ``names`` from one compiled call's results: ``res``
    (N, len(SLOTS)), ``stats`` (N,) records, ``final`` (N, NOBS) outputs at t_end."""
    out = {}
    for name in names:
        m = REGISTRY[name]
        if m.reads == "slot":
            values = res[:, SLOTS.index(m.slot)]
            out[name] = values.astype(np.int64) if name == "flips" and np.isfinite(values).all() else values
        elif m.reads == "slots":
            out[name] = m.formula({s: res[:, k] for k, s in enumerate(SLOTS)})
        elif m.reads == "stats":
            out[name] = stats["nfev"].astype(np.int64)
        else:
            for col, o in zip(m.columns, FINAL):
                out[col] = final[:, desc.outputs.index(o)]
    return out


# ---------------------------------------------------------------------------------------------
# The compiled (model, method) library with the measures (one per process, like ModelKernel)


def source(desc, method: str) -> str:
    """``<name>_measures.c`` for a model and method (rendered from templates/c/measures.c.j2)."""
    from .render import environment
    from .solvers import METHODS, _method_context

    idx = {f"i_{n}": desc.outputs.index(n) for n in READS}
    m = _method_context(METHODS[method])  # the stage array's size, as the driver declares it
    return environment().get_template("c/measures.c.j2").render(
        prefix=desc.name, method=method, slots=SLOTS, config=CONFIG, n_k=m["n_k"],
        n_stages=m["s"], n_dense=len(m["dense"]["stages"]), **idx)


class MeasureKernel:
    """``<name>_measure_batch_<method>``: N measured simulations in one C call (init map,
    integration with the measures' hook, outputs at the requested times)."""

    _cache: dict = {}

    def __init__(self, desc, method, lib):
        self.desc, self.method, self.lib = desc, method, lib
        self.ny, self.nout = len(desc.states), len(desc.outputs)
        vp, cl, cd = ctypes.c_void_p, ctypes.c_long, ctypes.c_double
        fn = getattr(lib, f"{desc.name}_measure_batch_{method}")
        fn.argtypes = [cl, vp, vp, vp, cl, cd, cd, cd, cl, vp, vp, vp, vp, vp]
        fn.restype = ctypes.c_int
        self._fn = fn
        guard = getattr(lib, f"{desc.name}_interrupt_guard")
        guard.argtypes, guard.restype = [ctypes.c_int], ctypes.c_int
        self._guard = guard
        # The measures' accumulators are static in the library: one run at a time (a Dask
        # worker with several threads would otherwise mix trajectories).
        import threading

        self._lock = threading.Lock()

    @classmethod
    def load(cls, desc, method: str) -> "MeasureKernel":
        """Compiled once per machine (the compile cache), loaded once per process."""
        from .cbuild import DEFAULT_FLAGS, compile_library
        from .solvers import METHODS

        if METHODS[method].driver != "adaptive":
            raise ValueError(f"measures need an adaptive method, not {method}")
        key = (desc.folder, desc.name, method)
        kernel = cls._cache.get(key)
        if kernel is None:
            sources = desc.c_sources()
            sources[f"{desc.name}_measures.c"] = source(desc, method)
            unity = f"{desc.name}_{method}_measures_unit.c"
            sources[unity] = "".join(f'#include "{n}"\n' for n in (
                f"{desc.name}.c", f"{desc.name}_solvers.c", f"{desc.name}_measures.c"))
            flags = list(DEFAULT_FLAGS) + ["-DDERIVE_SELECT", f"-DDERIVE_WITH_{method.upper()}",
                                           "-DDERIVE_MEASURES"]
            lib = compile_library(f"{desc.name}_{method}_measures", sources, unity, flags)
            kernel = cls._cache[key] = cls(desc, method, lib)
        return kernel

    def run(self, inputs, ps, t, args, config):
        """(res (N, len(SLOTS)), out (N, NOBS, n), stats (N,)) for inputs (N, NIN), ps (N, NP),
        output times t and the driver's arguments (rtol, atol, h0, max_steps)."""
        import threading

        from .integrate import STATS_DTYPE
        from .status import Status

        nb, n = inputs.shape[0], t.shape[0]
        inputs = np.ascontiguousarray(inputs, dtype=np.float64)
        ps = np.array(ps, dtype=np.float64, order="C")
        t = np.ascontiguousarray(t, dtype=np.float64)
        config = np.ascontiguousarray(config, dtype=np.float64)
        y = np.empty((nb, n, self.ny))
        out = np.empty((nb, self.nout, n))
        st = np.zeros(max(nb, 1), dtype=STATS_DTYPE)
        res = np.empty((max(nb, 1), len(SLOTS)))
        ptr = lambda a: a.ctypes.data  # noqa: E731
        main = threading.current_thread() is threading.main_thread()
        with self._lock:
            if main:
                self._guard(1)
            try:
                rc = self._fn(nb, ptr(inputs), ptr(ps), ptr(t), n, *args, ptr(config), ptr(y),
                              ptr(out), ptr(st), ptr(res))
            finally:
                interrupted = self._guard(0) if main else 0
        if interrupted or rc == Status.INTERRUPTED:
            raise KeyboardInterrupt
        return res[:nb], out, st[:nb]
