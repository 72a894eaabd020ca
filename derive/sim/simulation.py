"""Simulate a scene: scene → model → compiled kernel → one C call → results.

The flow runs one way:

1. the scene (validated, :mod:`derive.sim.scene`) names the body, its effects and the settings;
2. :mod:`derive.sim.auto` picks the formulation (and the method, for "auto") from derived
   quantities: the formulations' costs and, for the ones with a singular set, the β range from
   the Routh reduction's polynomial, evaluated in compiled code;
3. :mod:`derive.runtime.catalogue` gives the generated model (shipped in generated/, or derived once and
   cached) and :class:`derive.runtime.integrate.ModelKernel` its compiled (model, method) library;
4. one C call runs the init map (scene inputs → state and derived parameters), the integration
   and the output map at every sample (angles made canonical) into preallocated arrays;
5. the arrays become a :class:`Result`; ``integral_<name>`` arrays are added for the integrable
   cases (:mod:`derive.symbolic.integrable`).

Nothing on this path imports SymPy (unless a model must be derived first), matplotlib or the
reference solutions of :mod:`derive.reference.exact`.
"""
from __future__ import annotations

import contextvars
import functools
import math
from dataclasses import dataclass, field

import numpy as np

from derive.sim import auto, plan
from derive.runtime import catalogue
from derive.symbolic import effects as fx
from derive.errors import IntegrationError, SceneError
from derive.symbolic.formulations import OUTPUTS, REGISTRY
from derive.runtime.integrate import ModelKernel
from derive.sim.saveat import SaveAt
from derive.sim.inputs import AUTO, _check_budget, _settings, choose_method, default_step, inputs_of, params_of
from derive.sim.scene import FIXED_STEP_METHODS, Scene, load_scene
from derive.methods.registry import DEFAULT_METHOD
from derive.methods.registry import tolerance_driven
from derive.methods.status import Status
from derive.methods.status import message as status_message

FIXED_STEP = FIXED_STEP_METHODS
SCIPY_METHODS = plan.SCIPY_METHODS


@dataclass
class Result:
    """One simulated motion: the arrays of the output file, as attributes.

    Attributes
    ----------
    t : ndarray, shape (n,)
        Output times, s (uniform from 0 to ``t_end``).
    alpha, beta, gamma : ndarray, shape (n,)
        z-y-z Euler angles, rad: β ∈ [0, π]; α and γ continuous (not wrapped to ±π).
    omega : ndarray, shape (n, 3)
        Angular velocity in body axes (ω̃₁, ω̃₂, ω̃₃), rad/s.
    axis : ndarray, shape (n, 3)
        Inertial components of the body axis ê₃.
    energy : ndarray, shape (n,)
        Total energy T + V, J (conserved without damping).
    p_alpha, p_gamma : ndarray, shape (n,)
        Momenta conjugate to α and γ, kg m²/s (conserved for a symmetric top without damping).
    n, L : ndarray, shape (n, 3)
        The upward vertical, and the angular momentum about the pivot (kg m²/s), in body axes.
    integrals : dict
        ``{name: (n,) array}``: the extra integral of an integrable case (also readable as
        ``res.integral_<name>``); empty for a general body.
    method, formulation : str
        What actually ran.
    nfev : int
        Right-hand-side evaluations.
    model : str
        The generated model's name (its C prefix).
    """

    t: np.ndarray
    alpha: np.ndarray
    beta: np.ndarray
    gamma: np.ndarray
    omega: np.ndarray
    axis: np.ndarray
    energy: np.ndarray
    p_alpha: np.ndarray
    p_gamma: np.ndarray
    n: np.ndarray
    L: np.ndarray
    method: str
    formulation: str
    nfev: int
    model: str = ""
    #: The effects in the model that ran (registry names): a table whose values make its effect
    #: vanish (``[damping] c = 0``) is absent here, and ``model`` names the kernel without it.
    effects: tuple = ()
    integrals: dict = field(default_factory=dict)
    state: np.ndarray | None = field(default=None, repr=False)
    scene: Scene | None = field(default=None, repr=False)

    def arrays(self) -> dict:
        """Everything the output file holds, by name (``integral_<name>`` for the integrals,
        ``method``, ``formulation`` and ``nfev`` as 0-d arrays)."""
        out = {name: getattr(self, name) for name, _ in OUTPUTS if getattr(self, name) is not None}
        out["t"] = self.t
        out.update({f"integral_{k}": v for k, v in self.integrals.items()})
        out.update(method=np.array(self.method), formulation=np.array(self.formulation),
                   nfev=np.array(self.nfev, dtype=np.int64))
        return out

    def __getattr__(self, name):
        # (called only for a name the instance does not hold yet)
        d = self.__dict__
        row = _VIEWS.get(name)
        if row is not None and name not in d.get("_kept", (name,)):
            return None  # not kept (SaveAt.outputs)
        if row is not None and "_out" in d:  # an output of the C call's buffer: its view, once
            value = d[name] = _view(d["_out"], *row)
            return value
        if name.startswith("integral_") and name[9:] in d.get("integrals", {}):
            return self.integrals[name[9:]]
        raise AttributeError(name)


# ---------------------------------------------------------------------------------------------
# results


def _explain(desc, stats, max_steps) -> str:
    """The solver's one-line failure message; for a domain error, what the domain is."""
    status = int(stats["status"])
    if status == Status.DOMAIN and desc.domain_note:
        return f"t = {float(stats['t_fail']):.8g}: {desc.domain_note}"
    if status == Status.NONFINITE_OUTPUT and 0 <= int(stats["fail_index"]) < len(_COLUMN_OUTPUT):
        return (f"t = {float(stats['t_fail']):.6g}: non-finite {_COLUMN_OUTPUT[int(stats['fail_index'])]} "
                f"in the output")
    return status_message(stats, desc.states, max_steps)


def _output_slices() -> list:
    k, slices = 0, []
    for name, width in OUTPUTS:
        slices.append((name, k if width == 1 else slice(k, k + width), width > 1))
        k += width
    return slices


_SLICES = _output_slices()
_VIEWS = {name: (s, wide) for name, s, wide in _SLICES}  # output -> (rows of out, transposed)
_L_ROWS, _N_ROWS = _VIEWS["L"][0], _VIEWS["n"][0]  # the rows of out holding L and n
_COLUMN_OUTPUT = tuple(name for name, width in OUTPUTS for _ in range(width))  # column -> output
_RANGE = int(Status.RANGE)  # an int: no enum lookup per call
_EPS = float(np.finfo(float).eps)
_FEW = 32  # samples below which a list beats NumPy's reductions


def _result(desc, out, y, t, scene, method, nfev, finite: bool = False, integrals=None) -> Result:
    """The Result of one trajectory's outputs ``out`` (NOBS, n); ``finite``: the caller has
    checked them already (a batch checks all trajectories at once); ``integrals``: the scene's
    integral formulas when the caller has them (:attr:`derive.sim.plan.Plan.integral_rows`)."""
    if not finite and not np.isfinite(out).all():  # find where only when something is wrong
        for name, s, wide in _SLICES:
            bad = ~np.isfinite(_view(out, s, wide))
            if bad.any():
                j = int(np.argwhere(bad)[0][0])
                raise IntegrationError(f"t = {t[j]:.6g}: non-finite {name} in the output")
    rows = plan.integral_rows_of(scene) if integrals is None else integrals
    return _new_result(out, y, t, scene, method, desc, int(nfev), _integral_arrays(rows, out, t))


def _view(out: np.ndarray, rows, wide: bool) -> np.ndarray:
    """An output's view of ``out`` (NOBS, n): its row, or its rows transposed to (n, width)."""
    return out[rows].T if wide else out[rows]


def _new_result(out: np.ndarray, y: np.ndarray, t: np.ndarray, scene, method: str, desc, nfev: int,
                integrals: dict) -> Result:
    """A Result whose outputs are the rows of ``out`` (NOBS, n), each view made when first read
    (:meth:`Result.__getattr__`: a batch of 1000 would otherwise make 10 000 views)."""
    return _filled(_shared_fields(t, method, desc), out, y, nfev, integrals, scene)


def _shared_fields(t: np.ndarray, method: str, desc) -> dict:
    """The fields of a Result that every trajectory of one run shares."""
    return {"t": t, "method": method, "formulation": desc.formulation, "model": desc.name,
            "effects": desc.effects}


def _filled(shared: dict, out: np.ndarray, y: np.ndarray, nfev: int, integrals: dict, scene) -> Result:
    """A Result of the ``shared`` fields and its own, its outputs the rows of ``out``."""
    res = object.__new__(Result)  # every other field is given: what Result(**fields) would make
    d = res.__dict__
    d.update(shared)
    d["_out"] = out
    d["state"] = y
    d["nfev"] = nfev
    d["integrals"] = integrals
    d["scene"] = scene
    return res


def _all_finite(values: np.ndarray) -> bool:
    """Whether every entry is finite (a list for a short array: cheaper than the ufunc and its
    reduction)."""
    if values.ndim == 1 and values.shape[0] <= _FEW:
        return all(map(math.isfinite, values.tolist()))
    return bool(np.isfinite(values).all())


def _integral_arrays(rows, out: np.ndarray, t: np.ndarray) -> dict:
    """``integral_<name>`` arrays of the scene's integrable case (none for a general body) from
    its formulas ``rows`` (:func:`derive.sim.plan.integral_rows_of`) on the L and n rows of the
    outputs ``out`` (NOBS, n), the formulas' own layout, with NumPy's floating-point errors
    ignored (:func:`_ignoring`: absurd numbers may overflow there); IntegrationError naming the
    first non-finite value."""
    if not rows:
        return {}
    L, n = out[_L_ROWS], out[_N_ROWS]
    found = {}
    for name, formula, values, component in rows:
        if component is not None:  # L's own component: a copy of the row, finite as L was checked
            found[name] = L[component].copy()
            continue
        found[name] = values = np.asarray(_ignoring(formula, L, n, values), dtype=float)
        if not _all_finite(values):
            j = int(np.argwhere(~np.isfinite(values))[0][0])
            raise IntegrationError(f"t = {t[j]:.6g}: non-finite integral_{name} in the output "
                                   f"(overflow: the scene's numbers are out of range)")
    return found


def _clear_of_pole(sin_beta, rtol):
    """The rule: eps/sin²β, the relative error of q̈ there, within the tolerance (scalars or
    arrays)."""
    return sin_beta * sin_beta >= _EPS / rtol


def _check_pole(desc, t, beta, rtol):
    """The Euler-angle equations divide by sin β: q̈ has relative error ~ eps/sin²β. Refuse a
    trajectory whose closest approach to a pole made that larger than the tolerance.

    The output β is canonical, in [0, π], where sin is concave: the smallest sin β over the
    samples is at the smallest or the largest β (two reductions, not a sine per sample)."""
    if not REGISTRY[desc.formulation].pole_loss:
        return
    if beta.shape[0] <= _FEW:  # a short output: Python's min and max cost less than two reductions
        b = beta.tolist()
        lo, hi = min(b), max(b)
        if lo != lo or hi != hi:  # a NaN: Python's min and max may not see it
            lo = hi = math.nan
    else:
        lo, hi = float(beta.min()), float(beta.max())
    if not (math.isfinite(lo) and math.isfinite(hi)):
        return  # _result names the non-finite output
    if _clear_of_pole(min(math.sin(lo), math.sin(hi)), rtol):
        return
    s = np.abs(np.sin(beta))
    k = int(s.argmin())
    if not _clear_of_pole(s[k], rtol):
        raise IntegrationError(f"t = {t[k]:.6g}: coordinate singularity of the Euler-angle formulation "
                               f"(|sin beta| = {s[k]:.3g}); use formulation = \"quaternion\" or \"auto\"")


# ---------------------------------------------------------------------------------------------
# entry points


def _quiet(fn):
    """Run ``fn`` with NumPy's floating-point warnings off: absurd but finite inputs overflow on
    the way, and what counts is the result, which is checked (a non-finite state or output is
    an IntegrationError); a warning printed before that error line would only confuse."""
    @functools.wraps(fn)
    def quiet(*args, **kwargs):
        with np.errstate(all="ignore"):
            return fn(*args, **kwargs)
    return quiet


def _context_ignoring_errors():
    """A context (:mod:`contextvars`) in which NumPy ignores floating-point errors, made once;
    None where NumPy keeps its error state outside the context (NumPy < 2: per thread)."""
    before = np.geterr()
    ctx = contextvars.copy_context()
    ctx.run(np.seterr, all="ignore")
    if np.geterr() != before:  # the setting escaped the context: undo it, use np.errstate
        np.seterr(**before)
        return None
    return ctx


_IGNORING = _context_ignoring_errors()


def _ignoring(fn, *args):
    """``fn(*args)`` with NumPy's floating-point warnings off, for a few NumPy operations: in a
    copy of :data:`_IGNORING` (cheaper than entering an ``np.errstate``). The copy holds
    the context variables as they were at import: ``fn`` must read none but NumPy's error
    state (the integral formulas: arithmetic on arrays)."""
    if _IGNORING is None:
        with np.errstate(all="ignore"):
            return fn(*args)
    return _IGNORING.copy().run(fn, *args)


#: What a SaveAt may name: the outputs of the output file and the integrator's state.
KNOWN = tuple(name for name, _ in OUTPUTS) + ("state",)


def selection(saveat: SaveAt) -> tuple[bool, tuple[str, ...]]:
    """(final, names) of a :class:`~derive.sim.saveat.SaveAt`: whether only t_end is kept, and
    the outputs kept (every one and the state when it names none); SceneError naming
    ``outputs`` for a name that is not an output."""
    names = saveat.outputs or KNOWN
    for n in names:
        if n not in KNOWN:
            raise SceneError(f"<saveat>: outputs: unknown output {n!r} (the outputs: {', '.join(KNOWN)})")
    return saveat.final, names


def kept(res: Result, saveat: SaveAt | None) -> Result:
    """``res`` as ``saveat`` keeps it: with ``t="final"`` every array at t_end alone (length 1
    along time), with ``outputs`` only those outputs (the others None; ``arrays()`` leaves them
    out). The default SaveAt keeps ``res`` as it is."""
    if saveat is None or saveat.everything:
        return res
    final, names = selection(saveat)
    d = res.__dict__
    out, y, t = d["_out"], res.state, res.t
    integrals = res.integrals
    if final:
        out, y, t = out[:, -1:], y[-1:], t[-1:]
        integrals = {k: v[-1:] for k, v in integrals.items()}
    new = _filled(_shared_fields(t, res.method, _Ran(res.formulation, res.model, res.effects)), out,
                  y if "state" in names else None, res.nfev, integrals, res.scene)
    if saveat.outputs is not None:
        new.__dict__["_kept"] = frozenset(names)
    return new


@dataclass(frozen=True)
class _Ran:
    """What :func:`_shared_fields` reads of a model description."""

    formulation: str
    name: str
    effects: tuple


@_quiet
def simulate(scene, saveat: SaveAt | None = None, **overrides) -> Result:
    """Simulate a scene (path or dict shaped like the TOML); overrides replace [simulate] keys:
    validate it, plan it, run the plan, keep what ``saveat`` asks for (:func:`kept`)."""
    return kept(run(plan.make(load_scene(scene, **overrides))), saveat)


def run(pl: "plan.Plan", inputs: np.ndarray | None = None, params: dict | None = None) -> Result:
    """Run a plan: the C call of the first candidate whose pole check passes (or SciPy on the
    generated NumPy right-hand side), then the Result. ``inputs`` replaces the plan's init-map
    inputs and ``params`` ({name: value}) some of the model's parameters, unchecked (the plan's
    caller, :class:`derive.sim.prepared.Prepared`, checks them).

    NumPy's floating-point warnings are off wherever a NumPy operation could raise one (the
    SciPy path, the integrals: see :func:`_quiet`); the compiled path's other operations
    (copies, views, the pole check on finite angles) cannot warn."""
    if pl.scipy:
        return _run_scipy(pl, pl.inputs if inputs is None else inputs, params)
    # The compiled path: the candidates' calls were bound once per plan (layout, pointers,
    # converted arguments), so a run is an allocation, the C call and the Result.
    t = pl.t
    given = inputs is not None and inputs is not pl.inputs
    if given:
        inputs = np.ascontiguousarray(inputs, dtype=np.float64)
    same = not (given or params)
    for c in pl.candidates:
        bound = c.bound(t, pl.inputs)
        out, y, p, status, nfev, buf = bound(c.params if not params else _with(c, params),
                                             inputs if given else None, same=same)
        if status != _RANGE:
            break
    if status:
        raise IntegrationError(_explain(c.desc, bound.stats(buf), pl.scene.simulate.max_steps))
    if c.pole_loss:
        _check_pole(c.desc, t, out[1], pl.scene.simulate.rtol)
    # The compiled drivers checked the outputs finite (status NONFINITE_OUTPUT).
    return _compiled_result(pl, c, out, y, nfev)


@_quiet
def _run_scipy(pl: "plan.Plan", inputs: np.ndarray, params: dict | None) -> Result:
    sc, t, c = pl.scene, pl.t, pl.candidates[0]
    desc = c.desc
    out, y, _, nfev = _solve_scipy(desc, pl.scipy, inputs, _with(c, params), t, sc)
    _check_pole(desc, t, out[1], sc.simulate.rtol)
    # SciPy's solver did not check the outputs finite: _result does
    return _result(desc, out, y, t, sc, pl.method, nfev, integrals=pl.integral_rows)


def _compiled_result(pl: "plan.Plan", c: "plan.Candidate", out: np.ndarray, y: np.ndarray,
                     nfev: int) -> Result:
    """What :func:`_result` gives for outputs the C driver checked finite, with the plan's
    integral formulas (:func:`_integral_arrays`)."""
    return _new_result(out, y, pl.t, pl.scene, c.method, c.desc, nfev,
                       _integral_arrays(pl.integral_rows, out, pl.t))


def _with(c, params: dict | None) -> np.ndarray:
    """The candidate's parameter vector, with ``params`` ({name: value}) replacing entries."""
    if not params:
        return c.params
    p = c.params.copy()
    for name, value in params.items():
        p[c.desc.params.index(name)] = value
    return p


@_quiet
def simulate_batch(scenes, **overrides) -> list[Result]:
    """Simulate many scenes that differ only in numbers (initial state, moments, effect
    parameters) with one call into C: init, integration and outputs of every trajectory run in
    the compiled loop.

    All scenes must have the same effects, body symmetry, output times, method and
    tolerances. With formulation "auto", the scenes share one formulation: the common choice
    if they agree, else one without a singular set (safe for every one of them). The batch
    runs one model, with every effect that acts in any of its scenes; a scene whose table makes
    that effect vanish (``[damping] c = 0`` beside c > 0) runs the term with its zero
    coefficient, and a scene without the table cannot join such a batch (nothing gives c).
    """
    bp = batch_plan(scenes, **overrides)
    return [] if bp is None else batch_results(bp)


def batch_results(bp: "BatchPlan") -> list[Result]:
    """A batch plan run, one Result per trajectory (what :func:`simulate_batch` returns):
    its candidate formulations in turn until no start is refused, by the full batch driver
    (a Taylor method's lanes for a batch of at least LANES_MIN). The integrals of the
    integrable cases are classified once per body and effect values
    (:func:`derive.sim.plan.integrals_key`)."""
    scs, t, method = bp.scenes, bp.t, bp.method
    for formulation, pole_check in bp.candidates:
        desc, kernel, args = bp.kernel(formulation)
        ps = bp.params(desc)
        lanes = kernel.full_lanes(len(scs))  # a Taylor method's trajectories W at a time
        if lanes is not None:
            out, y, ps, st = lanes.simulate_batch(bp.inputs, ps, t, args, pole_check, lanes=True)
        else:
            out, y, ps, st = kernel.simulate_batch(bp.inputs, ps, t, args, pole_check)
        if not (st["status"] == Status.RANGE).any():
            break
    bp.raise_failure(desc, st)
    # The pole check of every trajectory at once; one that fails is then found and named per
    # scene. The C call has checked the outputs finite (status NONFINITE_OUTPUT).
    suspect = _pole_suspects(desc, out[:, 1], scs[0].simulate.rtol)
    for b in np.flatnonzero(suspect).tolist():
        _check_pole(desc, t, out[b, 1], scs[b].simulate.rtol)
    nfev = st["nfev"].tolist()
    rows: dict = {}
    results = []
    for b, sc in enumerate(scs):
        key = plan.integrals_key(sc)
        if key not in rows:
            rows[key] = plan.integral_rows_of(sc)
        results.append(_result(desc, out[b], y[b], t, sc, method, nfev[b], finite=True, integrals=rows[key]))
    return results


@dataclass
class BatchPlan:
    """What a batch runs, decided once for all its scenes (:func:`batch_plan`): the validated
    ``scenes``, the ``method``, the shared output times ``t``, the init-map ``inputs`` (N, NIN),
    the ``effects`` of the one model, the fixed step ``h`` (None: the scene's or adaptive) and
    the ``candidates`` (formulation, pole check) in the order they are tried."""

    scenes: list
    method: str
    t: np.ndarray
    inputs: np.ndarray
    effects: tuple
    h: float | None
    candidates: tuple

    def kernel(self, formulation: str):
        """(model description, compiled kernel, driver arguments) of one candidate."""
        first = self.scenes[0]
        desc = catalogue.describe((formulation, first.symmetric, self.effects))
        kernel = ModelKernel.load(desc, self.method)
        if self.h is not None:
            args = kernel.driver_args(first.simulate.rtol, first.simulate.atol, self.h, first.simulate.max_steps)
        else:
            args = _settings(first, self.method, kernel)
        return desc, kernel, args

    def params(self, desc, rows: slice = slice(None)) -> np.ndarray:
        """The parameter vectors (N, NP) of the scenes ``rows`` (default: all) for a model."""
        return np.array([params_of(sc, desc) for sc in self.scenes[rows]])

    def where(self, b: int) -> str:
        """How an error names trajectory ``b``: its scene's source."""
        return self.scenes[b].source

    def raise_failure(self, desc, st, offset: int = 0) -> None:
        """IntegrationError naming the first trajectory whose status (in ``st``, the stats of
        trajectories ``offset``, ``offset + 1``, …) is a failure; nothing when all succeeded."""
        status = st["status"]
        if status.any():
            b = int(np.flatnonzero(status)[0])
            sc = self.scenes[offset + b]
            raise IntegrationError(f"{self.where(offset + b)}: {_explain(desc, st[b], sc.simulate.max_steps)}")


def batch_plan(scenes, **overrides) -> BatchPlan | None:
    """Validate the scenes of a batch and decide what it runs (None for no scenes): one model
    with every effect that acts in any scene, the shared method, output times and settings."""
    scs = [load_scene(s, **overrides) for s in scenes]
    if not scs:
        return None
    first = scs[0]

    # One model for the batch: the effects that act in any scene (registry order), each named
    # by every scene so that each gives its parameters.
    effects = first.effects
    if any(sc.effects != effects for sc in scs):
        effects = tuple(e.name for e in fx.lookup(set().union(*(sc.effects for sc in scs))))

    def shared(sc):
        s = sc.simulate
        return (sc.symmetric, set(effects) <= set(sc.named_effects), s.samples, s.t_end,
                choose_method(sc), s.rtol, s.atol, s.h, s.max_steps, s.formulation)

    ref = shared(first)
    for sc in scs[1:]:
        if shared(sc) != ref or not set(sc.effects) <= set(first.named_effects):
            raise SceneError(f"{sc.source}: simulate: a batch needs the same effects, body symmetry, output "
                             f"times, method, tolerances and formulation as {first.source}")
    method = choose_method(first)
    if method in SCIPY_METHODS:
        raise SceneError(f"{first.source}: simulate.method: batches run in the C kernels, not {method}")
    h = None
    if not tolerance_driven(method) and first.simulate.h is None:
        h = min(default_step(sc) for sc in scs)
        for sc in scs:
            _check_budget(sc, method, h)
    candidates = tuple(auto.batch_plan(scs, effects))
    if first.simulate.method == AUTO and candidates:
        # one method for the batch: the cost model's, for its first scene and first model
        desc = catalogue.describe((candidates[0][0], first.symmetric, effects))
        method = plan.auto_method(first, desc)
    return BatchPlan(scs, method, first.t_out, np.array([inputs_of(sc) for sc in scs]), effects, h,
                     candidates)


def _pole_suspects(desc, betas: np.ndarray, rtol: float) -> np.ndarray:
    """Per trajectory (rows of canonical β), whether ``_check_pole`` could object: the smallest
    sin β is at the smallest or the largest β (sin is concave on [0, π]). The outputs are finite
    here (the C call checked them; a NaN would make its row a suspect anyway)."""
    if not REGISTRY[desc.formulation].pole_loss:
        return np.zeros(len(betas), dtype=bool)
    return ~_clear_of_pole(np.minimum(np.sin(betas.min(axis=1)), np.sin(betas.max(axis=1))), rtol)


def _budgeted(method: str, max_steps: int, where: list):
    """SciPy's solver class ``method`` ("RK45", "DOP853", "Radau", "LSODA", ...) with the scene's
    step budget, as the compiled drivers apply it: the step after ``max_steps`` steps fails the
    solve instead of being taken, its time is appended to ``where``. SciPy's steps cost about a
    thousand times the compiled ones (Python per step), so without it a fast top ran for minutes.
    A step is one call of the solver's ``_step_impl`` (rejected tries inside it included)."""
    from scipy import integrate

    class Budgeted(getattr(integrate, method)):
        steps = 0

        def _step_impl(self):
            if self.steps >= max_steps:
                where.append(self.t)
                return False, _BUDGET_SPENT
            self.steps += 1
            return super()._step_impl()

    Budgeted.__name__ = Budgeted.__qualname__ = f"Budgeted{method}"
    return Budgeted


_BUDGET_SPENT = "step budget spent"


def _solve_scipy(desc, method, inputs, p, t, sc):
    """SciPy's solve_ivp on the generated NumPy right-hand side (a reference, not the fast
    path): the compiled init map gives y0, the compiled output map the outputs. The step budget
    ``max_steps`` holds as for the compiled methods (exit 3 when spent)."""
    from scipy.integrate import solve_ivp

    kernel = ModelKernel.load(desc, DEFAULT_METHOD)  # for its init and output maps
    y0, p, rc = kernel.init(inputs, p)  # p: a copy with the derived parameters written
    if rc:
        raise IntegrationError(f"t = {t[0]:.6g}: the initial state is not finite")
    mod = numpy_module(desc)
    s = sc.simulate
    spent: list = []
    sol = solve_ivp(mod.rhs, (t[0], t[-1]), y0, method=_budgeted(method, s.max_steps, spent),
                    t_eval=t, rtol=s.rtol, atol=s.atol, args=(p,),
                    **({"jac": mod.jac} if method in ("Radau", "BDF", "LSODA") else {}))
    if spent:
        raise IntegrationError(status_message({"status": int(Status.MAX_STEPS), "t_fail": spent[0]},
                                              max_steps=s.max_steps))
    if not sol.success:
        raise IntegrationError(f"t = {sol.t[-1] if sol.t.size else t[0]:.6g}: scipy {method}: {sol.message}")
    y = sol.y.T.copy()
    return kernel.outputs_at(t, y, p), y, p, sol.nfev


@functools.lru_cache(maxsize=None)
def _numpy_module(folder: str, name: str):
    import importlib.util
    from pathlib import Path

    spec = importlib.util.spec_from_file_location(f"derive_generated_{name}",
                                                  Path(folder) / "numpy" / f"{name}.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def numpy_module(desc):
    """The generated NumPy module of a model (imported from its file)."""
    return _numpy_module(desc.folder, desc.name)


# ---------------------------------------------------------------------------------------------
# derivation-side helpers (SymPy; tests and benchmarks, never the simulate path)


@functools.lru_cache(maxsize=None)
def model_for(formulation: str, symmetric: bool, effects: tuple):
    from derive.symbolic import models

    return models.build(formulation, symmetric, effects)


@functools.lru_cache(maxsize=None)
def sources_for(formulation: str, symmetric: bool, effects: tuple) -> dict:
    """The generated files of a model (CSE and rendering done once per process)."""
    from derive.codegen.sources import model_sources

    return model_sources(model_for(formulation, symmetric, effects))


@functools.lru_cache(maxsize=None)
def kernel_for(formulation: str, symmetric: bool, effects: tuple):
    """The compiled C kernel (model + every solver) for a model, for tests and benchmarks."""
    from pathlib import Path

    from derive.runtime.integrate import Kernel

    model = model_for(formulation, symmetric, effects)
    files = sources_for(formulation, symmetric, effects)
    sources = {Path(k).name: v for k, v in files.items() if k in (f"c/{model.name}.h", f"c/{model.name}.c")}
    return Kernel.from_sources(model.name, sources)


def effect_names(scene: Scene) -> tuple[str, ...]:
    """The registry effects a scene calls for."""
    return scene.effects


def choose_formulation(scene: Scene) -> str:
    """The formulation ``simulate`` runs for this scene."""
    return auto.model_key(scene)[0]


def _initial_state(scene: Scene, model) -> np.ndarray:
    """y0 of ``model`` for the scene (by the compiled init map)."""
    return _init(scene, model)[0]


def _params(scene: Scene, model) -> np.ndarray:
    """p of ``model`` for the scene, derived parameters included (by the compiled init map)."""
    return _init(scene, model)[1]


def _init(scene: Scene, model):
    desc = catalogue.describe((model.formulation, model.symmetric, model.effects))
    y0, p, rc = ModelKernel.load(desc, None).init(inputs_of(scene), params_of(scene, desc))
    if rc:
        raise IntegrationError("the initial state is not finite")
    return y0, p


def _quaternion(a, b, c) -> np.ndarray:
    """q of R = Rz(α) Ry(β) Rz(γ), scalar first (the quaternion model's init map, in NumPy)."""
    qa = np.array([np.cos(a / 2), 0.0, 0.0, np.sin(a / 2)])
    qb = np.array([np.cos(b / 2), 0.0, np.sin(b / 2), 0.0])
    qc = np.array([np.cos(c / 2), 0.0, 0.0, np.sin(c / 2)])
    return _qmul(_qmul(qa, qb), qc)


def _qmul(p, q) -> np.ndarray:
    p0, pv, q0, qv = p[0], p[1:], q[0], q[1:]
    return np.concatenate([[p0 * q0 - pv @ qv], p0 * qv + q0 * pv + np.cross(pv, qv)])


def write_outputs(res: Result, npz: str | None = None, png: str | None = None) -> None:
    """Write the arrays (``npz``) and the plot (``png``), all or nothing (see
    :mod:`derive.sim.outputs`), each in the format its extension names: the arrays as .npz (NumPy)
    or .csv (``outputs.write_csv``), the plot as .png, .pdf or .svg. Another extension raises
    SceneError naming ``-o`` or ``--plot`` before anything is written; neither may be the
    scene file the result came from (SceneError naming both)."""
    from derive.sim.outputs import (PLOT_FORMATS, RESULT_FORMATS, check_paths, output_format,
                                    write_all, write_csv)

    source = res.scene.source if res.scene is not None else None
    inputs = [source] if source and source != "<dict>" else []
    check_paths([npz, png], inputs=inputs)  # a clash with the scene first: it is what matters most
    data_format = output_format(npz, "-o", RESULT_FORMATS) if npz else None
    plot_format = output_format(png, "--plot", PLOT_FORMATS) if png else None
    writers = {}
    if data_format == "csv":
        arrays = res.arrays()
        writers[npz] = lambda f: write_csv(f, {"t": arrays.pop("t"), **arrays})  # t first
    elif data_format == "npz":
        writers[npz] = lambda f: np.savez(f, **res.arrays())
    if plot_format:
        def plot(f):
            from derive.sim.plots import plot_result

            plot_result(res, f, plot_format)

        writers[png] = plot
    write_all(writers, inputs=inputs)
