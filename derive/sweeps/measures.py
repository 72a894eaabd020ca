"""Measures of a trajectory, computed in the compiled loop while integrating (for sweeps).

A measure is one registry entry (:data:`REGISTRY`): its name, unit, what it reads and, if it
takes one, its option. Nothing else names a measure by a string; :mod:`derive.sweeps.engine` asks the
registry which columns a measure gives and reads them from one compiled call.

Contract of an entry (:class:`Measure`):

1. ``name``: the key in ``[measure] names`` and the result's column (``columns`` when several).
2. ``reads``: where the numbers come from, one of

   * ``"slot"``: an accumulator of ``templates/c/measures.c.j2`` (``slot``), updated by the
     driver's hook after every accepted step, with the step's dense output at hand (DOP853's
     polynomial, or a Taylor step's series: the window's flavour is the method family's
     :func:`derive.methods.registry.measure_window`);
   * ``"stats"``: the solver's statistics record (``nfev``);
   * ``"final"``: the outputs at t_end (the output map, in C);
   * ``"slots"``: a ``formula`` of the accumulators (``nutation`` = beta_max − beta_min);
   * ``"contact"``: a top on a table's run (:mod:`derive.sweeps.contact`), its ``contact``
     function of the run's result. Only a sweep over a ``[contact]`` scene takes them, and it
     takes only the measures that have a ``contact`` function (``nfev`` too).
3. ``options``: {option: (default, unit, one-line meaning)} — read from the sweep file's
   ``[measure.<name>]`` table. A number is passed to the compiled loop through ``config``
   (index ``CONFIG``: ``time_to_tilt``'s ``angle``); a name (``choices`` lists the allowed
   ones: ``integral_drift``'s ``integral``) selects per-point data built in Python
   (``integral_rows``).
4. ``needs``: the compiled loop's work flags (``CONFIG``): ``steps`` runs the per-step hook
   (the outputs read at each step end; the dense output — DOP853's three dense stages, counted
   in ``nfev`` — only on the steps a search reads, when it first reads them: of the two steps
   around a discrete extremum of beta those its evaluations fall in, the first and the last
   step, the steps of the first tilt and the first flip);
   ``extrema`` runs the searches for beta's extrema (and keeps each step for the next one's
   search), so a sweep without a beta measure forms no dense output for them; ``flip_time``
   and ``tilt_time`` locate those times; ``beta``, ``energy``, ``p_alpha``, ``p_gamma`` and
   ``omega2`` name the outputs read at every step end: only those are computed there (each
   alone: the output map inlined and cut down by the compiler, the same bits), so that a sweep
   of beta's extrema and the energy drift computes no omega, no axis and none of their sines
   and cosines per step. A sweep asking only for ``nfev`` and ``final_state`` runs the plain
   loop's work. ``dense_always`` (no measure sets it) forms the dense output on every step, so
   that the tests can check that the lazy choice moves no value.

The accumulators (``SLOTS``) of the outputs read are updated whenever the hook runs (a compare
or two per step; the extrema search runs only at the turning points); the others are NaN in
the compiled call's result (``integral_drift`` too where the point has no integral).

``integral_drift`` — the drift of the extra first integral of the integrable cases
(:mod:`derive.symbolic.integrable`: |L|² for Euler's free body, L₃ = I₃ω̃₃ = p_γ about the symmetry axis
for Lagrange's top, L·r_c for a spherical body, Kovalevskaya's K, Goryachev–Chaplygin's G) is

    max over the accepted step ends of |I(t) − I(0)| / S,

S the integral's size at t = 0: the sum over the monomials c·L^a·n^b of its expanded formula of
|c|·|L(0)|^|a|·|n(0)|^|b| (a bound on |I| for any L, n of those lengths; rounding alone moves I
by about eps·S), or 1 if S = 0 (a body at rest without gravity: the drift is then absolute). I is
evaluated in the compiled loop from the outputs L and n (body axes), so it is the same for every
formulation (Euler–Poisson, quaternion; for the Euler-angle models L₃ is p_γ). Its C code is
``generated/c/derive_integrals.h``, printed by SymPy from the formulas of
:mod:`derive.symbolic.integrable` at ``derive generate`` time (one source, no SymPy on the warm path).
Which integral: option ``integral = "case"`` (default) takes each point's own case (the points
of a sweep may differ: varying I₃ crosses the Kovalevskaya ratio), with a body symmetric about
axis 1 or 2 relabelled as :mod:`derive.symbolic.integrable` does; a point with no extra integral (the
general case, or a damped body) gets NaN, its status stays ``ok`` (``p_alpha_drift`` and
``energy_drift`` still apply to an undamped one). Naming an integral (``integral =
"kovalevskaya"``) evaluates that one at every point whatever its case — the drift of K as the
body leaves the Kovalevskaya ratio — in the formulas' axes (the point's own relabelling when its
case is that integral's); the Casimirs ``n_squared`` (|n|²) and ``p_alpha`` (L·n) can be named
too. G is conserved only on L·n = 0: a point off that level reports G's real drift.

Conventions: beta is the z-y-z nutation angle in [0, pi] (the output map's, made canonical);
omega2 the body-frame component ω̃₂; energy T + V; p_alpha, p_gamma the conjugate momenta.
"""
from __future__ import annotations

import ctypes
import math
import threading
from dataclasses import dataclass, field

import numpy as np

from derive.codegen.render import environment
from derive.codegen.solvers import _method_context
from derive.methods.registry import METHODS, measure_window, method as compiled
from derive.methods.status import Status
from derive.runtime.cbuild import DEFAULT_FLAGS, compile_library
from derive.runtime import records
from derive.runtime.records import STATS_DTYPE
from derive.symbolic.integrable import C_INTEGRALS, C_PARAMS, classify_values, relabel_params

#: The compiled accumulators, in the order of the C enum (rendered from this tuple).
SLOTS = ("beta_max", "beta_min", "energy_drift", "p_alpha_drift", "p_gamma_drift", "flips",
         "time_to_flip", "time_to_tilt", "integral_drift")
#: config[] of the compiled loop: the option values and the work flags a measure ``needs``.
CONFIG = {"angle": 0, "steps": 1, "flip_time": 2, "tilt_time": 3, "dense_always": 4, "extrema": 5,
          "beta": 6, "energy": 7, "p_alpha": 8, "p_gamma": 9, "omega2": 10}
#: The outputs the compiled loop reads (by name; their indices come from the model's outputs).
READS = ("beta", "energy", "omega2", "p_alpha", "p_gamma", "L1", "L2", "L3", "n1", "n2", "n3")
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
    needs: tuple = ()  # work flags of the compiled loop (CONFIG): "steps", "extrema", "flip_time", ...
    choices: dict = field(default_factory=dict)  # {option: allowed names} of a named option
    contact: object = None  # a top on a table's run -> the value (derive.sweeps.contact)

    @property
    def columns(self) -> tuple[str, ...]:
        return tuple(f"final_{n}" for n in FINAL) if self.reads == "final" else (self.name,)


REGISTRY: dict[str, Measure] = {m.name: m for m in (
    Measure("beta_max", "rad", "largest nutation angle beta, located on the dense output", "slot",
            "beta_max", needs=("steps", "extrema", "beta")),
    Measure("beta_min", "rad", "smallest nutation angle beta, located on the dense output", "slot",
            "beta_min", needs=("steps", "extrema", "beta")),
    Measure("nutation", "rad", "beta_max - beta_min: the nutation amplitude (a top released at a "
            "turning point)", "slots", formula=lambda r: r["beta_max"] - r["beta_min"],
            needs=("steps", "extrema", "beta")),
    Measure("energy_drift", "", "max over the steps of |E - E0| / |E0|", "slot", "energy_drift",
            needs=("steps", "energy")),
    Measure("p_alpha_drift", "kg m^2/s", "max over the steps of |p_alpha - p_alpha(0)|", "slot",
            "p_alpha_drift", needs=("steps", "p_alpha")),
    Measure("p_gamma_drift", "kg m^2/s", "max over the steps of |p_gamma - p_gamma(0)|", "slot",
            "p_gamma_drift", needs=("steps", "p_gamma")),
    Measure("flips", "", "sign changes of omega2 (body frame) between step ends", "slot", "flips",
            needs=("steps", "omega2")),
    Measure("time_to_flip", "s", "first sign change of omega2, on the dense output (NaN: none)",
            "slot", "time_to_flip", needs=("steps", "flip_time", "omega2")),
    Measure("time_to_tilt", "s", "first time beta exceeds the option angle (NaN: never)", "slot",
            "time_to_tilt", options={"angle": (math.pi / 2, "rad", "the tilt threshold")},
            needs=("steps", "tilt_time", "extrema", "beta")),  # "rose and fell back": a maximum's search
    Measure("integral_drift", "", "max over the steps of |I - I0| / S for the extra integral I of "
            "the point's integrable case (|L|^2, L3 = p_gamma, L.r_c, Kovalevskaya's K, "
            "Goryachev-Chaplygin's G), S its size at t = 0 (NaN: no extra integral)", "slot",
            "integral_drift", needs=("steps",),
            options={"integral": ("case", "", "which integral: each point's own ('case') or one "
                                  "named for every point")},
            choices={"integral": ("case", *(i.name for i in C_INTEGRALS))}),
    Measure("nfev", "", "right-hand-side evaluations (dop853: the dense stages included, formed "
            "only on the steps a search reads; taylor: its steps, one jet each)", "stats",
            contact=lambda r: r.nfev),
    Measure("final_state", "", "alpha, beta, gamma, omega1..3 at t_end (alpha, gamma unwrapped "
            "from the start alone: equal to a sampled run's modulo 2 pi)", "final"),
)}

DEFAULT = ("beta_max", "beta_min", "energy_drift", "nfev")


def _first_past(t: np.ndarray, v: np.ndarray, dv: np.ndarray, level: float) -> float:
    """The first time ``v`` reaches ``level`` from below (NaN: never): between the two samples
    around it, the root of the cubic Hermite interpolant of v and its rate ``dv`` (an error of
    order h⁴ in the sample spacing h), found by bisection."""
    above = np.flatnonzero(v >= level)
    if not above.size:
        return math.nan
    k = int(above[0])
    if k == 0:
        return float(t[0])
    t0, h = float(t[k - 1]), float(t[k] - t[k - 1])
    y0, y1, m0, m1 = v[k - 1] - level, v[k] - level, dv[k - 1] * h, dv[k] * h

    def cubic(x):
        return ((2 * x**3 - 3 * x**2 + 1) * y0 + (x**3 - 2 * x**2 + x) * m0
                + (-2 * x**3 + 3 * x**2) * y1 + (x**3 - x**2) * m1)

    lo, hi = 0.0, 1.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if cubic(mid) < 0 else (lo, mid)
    return t0 + h * hi


def _tilt_rate(r) -> np.ndarray:
    """β̇ = ω̃₁ sin γ + ω̃₂ cos γ (z-y-z, ω̃ in body axes)."""
    return r.omega[:, 0] * np.sin(r.gamma) + r.omega[:, 1] * np.cos(r.gamma)


def _relative_drift(v) -> float:
    return math.nan if v is None else float(np.max(np.abs(v - v[0])) / (abs(v[0]) or 1.0))


#: A top on a table's measures (``reads = "contact"``), from its run's samples and switches;
#: the tilt is the z-y-z β of body axis 3 from the vertical (θ of the tippe-top literature).
CONTACT_MEASURES: dict[str, Measure] = {m.name: m for m in (
    Measure("final_tilt", "rad", "the tilt beta at t_end", "contact", contact=lambda r: float(r.beta[-1])),
    Measure("min_tilt", "rad", "the smallest tilt beta over the samples (how far it rose)", "contact",
            contact=lambda r: float(np.min(r.beta))),
    Measure("max_tilt", "rad", "the largest tilt beta over the samples", "contact",
            contact=lambda r: float(np.max(r.beta))),
    Measure("inverted", "", "1 if the tilt beta passed 90 degrees (the body turned over), else 0",
            "contact", contact=lambda r: float(np.max(r.beta) >= math.pi / 2)),
    Measure("time_to_invert", "s", "the first time beta passes 90 degrees, located between the "
            "samples on the cubic through beta and its rate (NaN: never)", "contact",
            contact=lambda r: _first_past(r.t, r.beta, _tilt_rate(r), math.pi / 2)),
    Measure("switches", "", "phase switches (slide, roll, flight) located in the run", "contact",
            contact=lambda r: len(r.switches)),
    Measure("final_spin", "rad/s", "omega3, the spin about body axis 3, at t_end", "contact",
            contact=lambda r: float(r.omega[-1, 2])),
    Measure("jellett_drift", "", "max over the samples of |J - J0| / |J0| for Jellett's J = L.a "
            "(NaN: the case has no Jellett integral)", "contact",
            contact=lambda r: _relative_drift(r.integrals.get("jellett"))),
)}
REGISTRY.update(CONTACT_MEASURES)
#: The measures of a contact sweep that names none.
CONTACT_DEFAULT = ("final_tilt", "min_tilt", "switches", "nfev")


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
            if opt not in m.choices:  # a named option selects per-point data instead
                cfg[CONFIG[opt]] = float(options.get(m.name, {}).get(opt, default))
    return cfg


#: The per-point row of integral_drift's data: the integral's code (0: none), the body axes
#: (0-based) that play the formulas' axes 1, 2, 3, and the general parameters in those axes.
INTEGRAL_ROW = ("code", "axis1", "axis2", "axis3", *C_PARAMS)


def integral_rows(general: np.ndarray, damping: np.ndarray, choice: str = "case") -> np.ndarray:
    """(N, len(INTEGRAL_ROW)) rows for the compiled integral_drift from each point's general
    parameters ``general`` (N, len(C_PARAMS): I1, I2, I3, M, g, cx, cy, cz in body axes) and
    damping coefficient (N,): the integral of the point's case (``choice`` "case") or the one
    named, classified once per distinct body (:func:`derive.symbolic.integrable.classify_values`)."""
    general = np.asarray(general, dtype=float).reshape(-1, len(C_PARAMS))
    body = np.column_stack([general, np.asarray(damping, dtype=float).reshape(-1)])
    if body.shape[0] == 0:
        return np.zeros((0, len(INTEGRAL_ROW)))
    codes = {i.name: k + 1 for k, i in enumerate(C_INTEGRALS)}
    uniq, inverse = np.unique(body, axis=0, return_inverse=True)
    per = np.zeros((len(uniq), len(INTEGRAL_ROW)))
    for u, row in enumerate(uniq):
        p = dict(zip(C_PARAMS, (float(x) for x in row[:-1])))
        c = classify_values(p["I1"], p["I2"], p["I3"], p["M"], p["g"], (p["cx"], p["cy"], p["cz"]),
                            float(row[-1]))
        own = c.canonical_extra
        name = (own.name if own is not None else None) if choice == "case" else choice
        axes = c.axes if own is not None and own.name == name else (0, 1, 2)
        q = relabel_params(p, axes)
        per[u] = [codes[name] if name is not None else 0, *axes, *(q[k] for k in C_PARAMS)]
    return per[np.ravel(inverse)]


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
    """``<name>_measures.c`` for a model and method (rendered from templates/c/measures.c.j2, in
    the flavour of the method's measure window: :func:`derive.methods.registry.measure_window`)."""
    window = measure_window(method)
    if window is None:
        raise ValueError(f"measures need a method with a dense output between its steps, not {method}")
    idx = {f"i_{n}": desc.outputs.index(n) for n in READS}
    idx["i_L"] = [desc.outputs.index(f"L{k}") for k in (1, 2, 3)]
    idx["i_n"] = [desc.outputs.index(f"n{k}") for k in (1, 2, 3)]
    params = compiled(method).params
    ctx = {"decl": ", ".join(f"{ty} {nm}" for ty, nm in params),
           "args": ", ".join(nm for _, nm in params)}
    if window == "stages":
        m = _method_context(METHODS[method])  # the stage array's size, as the driver declares it
        ctx.update(n_k=m["n_k"], n_stages=m["s"], n_dense=len(m["dense"]["stages"]))
    return environment().get_template("c/measures.c.j2").render(
        prefix=desc.name, method=method, window=window, slots=SLOTS, config=CONFIG,
        nip=len(INTEGRAL_ROW), has_beta=desc.has_angles,
        out_index={n: desc.outputs.index(n) for n in READS}, **ctx, **idx)


def driver_args(method: str, rtol: float, atol: float, max_steps: int) -> tuple:
    """The measured driver's arguments for a tolerance-driven ``method``
    (:func:`derive.runtime.records.driver_args`)."""
    return tuple(records.driver_args(method, rtol, atol, None, max_steps))


def c_sources(desc, method: str) -> dict[str, str]:
    """{file name: text} of the measured unit's inputs: the model and its solvers, the rendered
    ``<name>_measures.c`` and the generated integrals it includes."""
    sources = desc.c_sources()
    sources[f"{desc.name}_measures.c"] = source(desc, method)
    sources["derive_integrals.h"] = desc.source("c/derive_integrals.h")
    return sources


class MeasureKernel:
    """``<name>_measure_batch_<method>``: N measured simulations in one C call (init map,
    integration with the measures' hook, outputs at the requested times)."""
    _cache: dict = {}

    def __init__(self, desc, method, lib):
        self.desc, self.method, self.lib = desc, method, lib
        self.ny, self.nout = len(desc.states), len(desc.outputs)

        vp, cl, ci = ctypes.c_void_p, ctypes.c_long, ctypes.c_int
        self._fn = records.bind(lib, f"{desc.name}_measure_batch_{method}",
                                [cl, vp, vp, vp, cl, *(records.C_TYPES[ty] for ty, _ in compiled(method).params),
                                 ci, vp, vp, vp, vp, vp, vp])
        self._guard = records.bind(lib, "derive_sigint_guard", [ci])
        # The measures' accumulators are static in the library: one run at a time (a Dask
        # worker with several threads would otherwise mix trajectories).
        self._lock = threading.Lock()

    @classmethod
    def load(cls, desc, method: str) -> "MeasureKernel":
        """Compiled once per machine (the compile cache), loaded once per process."""
        key = (desc.folder, desc.name, method)
        kernel = cls._cache.get(key)
        if kernel is None:
            sources = c_sources(desc, method)  # (ValueError for a method without a measure window)
            # a Taylor method's solver is its own file, after the solvers (the interrupt flag,
            # the bookkeeping and the measuring flag are theirs)
            family = [f"{desc.name}_taylor.c"] if measure_window(method) == "series" else []
            if family and family[0] not in sources:
                raise ValueError(f"method {method!r} was not generated for the model {desc.name}")
            unity = f"{desc.name}_{method}_measures_unit.c"
            sources[unity] = "".join(f'#include "{n}"\n' for n in (
                f"{desc.name}.c", f"{desc.name}_solvers.c", *family, f"{desc.name}_measures.c"))
            flags = list(DEFAULT_FLAGS) + ["-DDERIVE_SELECT", f"-DDERIVE_WITH_{method.upper()}",
                                           "-DDERIVE_MEASURES", "-fno-semantic-interposition"]
            lib = compile_library(f"{desc.name}_{method}_measures", sources, unity, flags)
            kernel = cls._cache[key] = cls(desc, method, lib)
        return kernel

    def run(self, inputs, ps, t, args, config, integral=None, pole_check: int = 0):
        """(res (N, len(SLOTS)), out (N, NOBS, n), stats (N,)) for inputs (N, NIN), ps (N, NP),
        output times t, the driver's arguments (:func:`driver_args`) and the per-point
        ``integral_rows`` (None: no integral, integral_drift NaN). ``pole_check``: the driver's
        check of each start (:func:`derive.sim.auto.pole_mode`; 0 none): a start it refuses
        has status RANGE and NaN measures, and the other points run on."""
        nb, n = inputs.shape[0], t.shape[0]
        inputs = np.ascontiguousarray(inputs, dtype=np.float64)
        ps = np.array(ps, dtype=np.float64, order="C")
        t = np.ascontiguousarray(t, dtype=np.float64)
        config = np.ascontiguousarray(config, dtype=np.float64)
        if config.shape != (len(CONFIG),):  # the compiled loop reads every entry (config_of)
            raise ValueError(f"config must hold {len(CONFIG)} numbers (config_of), got shape "
                             f"{config.shape}")
        integral = (np.zeros((nb, len(INTEGRAL_ROW))) if integral is None
                    else np.ascontiguousarray(integral, dtype=np.float64).reshape(nb, len(INTEGRAL_ROW)))
        y = np.empty((nb, n, self.ny))
        out = np.empty((nb, self.nout, n))
        st = np.zeros(max(nb, 1), dtype=STATS_DTYPE)
        res = np.empty((max(nb, 1), len(SLOTS)))
        ptr = lambda a: a.ctypes.data  # noqa: E731
        guard = self._guard if threading.current_thread() is threading.main_thread() else None
        with self._lock:
            rc = records.guarded(guard, self._fn, nb, ptr(inputs), ptr(ps), ptr(t), n, *args, int(pole_check),
                                 ptr(config), ptr(integral), ptr(y), ptr(out), ptr(st), ptr(res))
        if rc == Status.INTERRUPTED:  # off the main thread: a request, as the status says
            raise KeyboardInterrupt
        return res[:nb], out, st[:nb]
