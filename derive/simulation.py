"""Simulate a scene: scene → model → compiled kernel → one C call → results.

The flow runs one way:

1. the scene (validated, :mod:`derive.scene`) names the body, its effects and the settings;
2. :mod:`derive.auto` picks the formulation (and the method, for "auto") from derived
   quantities: the formulations' costs and, for the ones with a singular set, the β range from
   the Routh reduction's polynomial, evaluated in compiled code;
3. :mod:`derive.catalogue` gives the generated model (shipped in generated/, or derived once and
   cached) and :class:`derive.integrate.ModelKernel` its compiled (model, method) library;
4. one C call runs the init map (scene inputs → state and derived parameters), the integration
   and the output map at every sample (angles made canonical) into preallocated arrays;
5. the arrays become a :class:`Result`; ``integral_<name>`` arrays are added for the integrable
   cases (:mod:`derive.integrable`).

Nothing on this path imports SymPy (unless a model must be derived first), matplotlib or the
reference solutions of :mod:`derive.exact`.
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

import numpy as np

from . import auto, catalogue
from .errors import IntegrationError, SceneError
from .formulations import OUTPUTS, REGISTRY
from .integrate import ModelKernel
from .scene import FIXED_STEP_METHODS, Scene, load_scene
from .solvers import DEFAULT_METHOD, REFERENCE_METHODS
from .solvers import method as compiled_method
from .status import Status
from .status import message as status_message

FIXED_STEP = FIXED_STEP_METHODS
SCIPY_METHODS = {name: ivp for name, (ivp, _) in REFERENCE_METHODS.items()}


@dataclass
class Result:
    """The arrays of the output file (see the README, "Output file"), as attributes."""

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
    integrals: dict = field(default_factory=dict)
    state: np.ndarray | None = field(default=None, repr=False)
    scene: Scene | None = field(default=None, repr=False)

    def arrays(self) -> dict:
        """Everything the .npz holds, by name."""
        out = {name: getattr(self, name) for name, _ in OUTPUTS}
        out["t"] = self.t
        out.update({f"integral_{k}": v for k, v in self.integrals.items()})
        out.update(method=np.array(self.method), formulation=np.array(self.formulation),
                   nfev=np.array(self.nfev, dtype=np.int64))
        return out

    def __getattr__(self, name):
        if name.startswith("integral_") and name[9:] in self.__dict__.get("integrals", {}):
            return self.integrals[name[9:]]
        raise AttributeError(name)


# ---------------------------------------------------------------------------------------------
# scene → numbers


def inputs_of(scene: Scene) -> np.ndarray:
    """The init map's inputs (`formulations.INPUT_NAMES`): angles, body ω̃, the Euler-angle rates
    where the scene gave them (rates_given = 1), else zeros (rates_given = 0)."""
    i = scene.initial
    rates = (i.alpha_dot, i.beta_dot, i.gamma_dot) if i.has_rates else (0.0, 0.0, 0.0)
    return np.array([i.alpha, i.beta, i.gamma, *i.omega, *rates, 1.0 if i.has_rates else 0.0])


def params_of(scene: Scene, desc) -> np.ndarray:
    """The model's parameters from the scene; the ones the init map derives start as 0."""
    values = scene.param_values()
    derived = set(desc.derived_params)
    return np.array([0.0 if k in derived else values[name] for k, name in enumerate(desc.params)])


def choose_method(scene: Scene) -> str:
    return DEFAULT_METHOD if scene.simulate.method == "auto" else scene.simulate.method


def default_step(scene: Scene) -> float:
    """A fixed step for the fixed-step methods when the scene gives none: 1/200 of the fastest
    natural period (spin, or a rate an effect sets), and no larger than the output spacing."""
    from . import effects

    b, i = scene.body, scene.initial
    rates = [float(np.linalg.norm(i.omega)) * max(b.moments) / min(b.moments)]
    for t in scene.tables.values():
        rates.append(effects.REGISTRY[t.effect].natural_rate(t, b))
    fastest = max(max(rates), 1e-12)
    dt_out = scene.simulate.t_end / (scene.simulate.samples - 1)
    return float(min(2 * np.pi / fastest / 200, dt_out))


def fixed_steps(scene: Scene, h: float) -> int:
    """How many steps a fixed-step run takes: ceil(Δt/h) per output interval, counted as the C
    drivers count them (a ratio within a relative 1e-10 above an integer counts as that
    integer)."""
    dt = scene.simulate.t_end / (scene.simulate.samples - 1)
    r = dt / h
    if not math.isfinite(r) or r > 1e15:
        return 10**18
    n = math.ceil(r)
    if n > 1 and n - r > 1.0 - 1e-10 * r:
        n -= 1
    return max(n, 1) * (scene.simulate.samples - 1)


def _check_budget(scene: Scene, method: str, h: float) -> None:
    """A fixed-step run is refused up front (bad input, before any work) when its steps exceed
    ``[simulate] max_steps``."""
    steps = fixed_steps(scene, h)
    if steps > scene.simulate.max_steps:
        shown = f"{steps}" if steps < 10**18 else "more than 1e18"
        raise SceneError(f"{scene.source}: simulate.h: {method} with h = {h:.6g} s over t_end = "
                         f"{scene.simulate.t_end:.6g} s takes {shown} steps, more than "
                         f"simulate.max_steps = {scene.simulate.max_steps}")


def _settings(scene: Scene, method: str, kernel: ModelKernel) -> list:
    s = scene.simulate
    h = s.h
    if not kernel.adaptive:
        h = default_step(scene) if h is None else h
        _check_budget(scene, method, h)
    return kernel.driver_args(s.rtol, s.atol, h, s.max_steps)


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
_COLUMN_OUTPUT = tuple(name for name, width in OUTPUTS for _ in range(width))  # column -> output
_RANGE = int(Status.RANGE)  # an int: no enum lookup per call
_EPS = float(np.finfo(float).eps)


def _result(desc, out, y, t, scene, method, nfev, p, finite: bool = False) -> Result:
    """The Result of one trajectory's outputs ``out`` (NOBS, n); ``finite``: the caller has
    checked them already (a batch checks all trajectories at once)."""
    views = {name: (out[s].T if wide else out[s]) for name, s, wide in _SLICES}
    if not finite and not np.isfinite(out).all():  # find where only when something is wrong
        for name, _ in OUTPUTS:
            bad = ~np.isfinite(views[name])
            if bad.any():
                j = int(np.argwhere(bad)[0][0])
                raise IntegrationError(f"t = {t[j]:.6g}: non-finite {name} in the output")
    res = Result(t=t, method=method, formulation=desc.formulation, nfev=int(nfev),
                 model=desc.name, state=y, scene=scene, **views)
    res.integrals = _integrals(scene, res, p)
    for name, values in res.integrals.items():
        if not np.isfinite(values).all():
            j = int(np.argwhere(~np.isfinite(values))[0][0])
            raise IntegrationError(f"t = {t[j]:.6g}: non-finite integral_{name} in the output "
                                   f"(overflow: the scene's numbers are out of range)")
    return res


def _integrals(scene: Scene, res: Result, p) -> dict:
    """``integral_<name>`` arrays of the scene's integrable case (none for a general body)."""
    return {name: np.asarray(fn(res.L, res.n), dtype=float) for name, fn in _integrals_of(scene)}


def _integrals_of(scene: Scene):
    from .integrable import integrals_for, on_area_level

    # The case depends on the body and the effects' numbers, and for a Goryachev–Chaplygin body
    # on whether the state is on L·n = 0 (a cheap test): classified once per body and level.
    key = (scene.body, tuple((k, v.effect, tuple(v._values.values())) for k, v in scene.tables.items()),
           on_area_level(scene))
    found = _INTEGRALS.get(key)
    if found is None:
        found = _INTEGRALS[key] = integrals_for(scene)
    return found


_INTEGRALS: dict = {}


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


@_quiet
def simulate(scene, **overrides) -> Result:
    """Simulate a scene (path or dict shaped like the TOML); overrides replace [simulate] keys."""
    sc = load_scene(scene, **overrides)
    method = choose_method(sc)
    t = sc.t_out
    inputs = inputs_of(sc)
    if method in SCIPY_METHODS:
        desc = catalogue.describe(auto.model_key(sc, method))
        out, y, p, nfev = _solve_scipy(desc, SCIPY_METHODS[method], inputs, params_of(sc, desc), t, sc)
    else:
        # auto's plan: the cheapest formulations first; a singular one runs with its pole check,
        # which the driver does before integrating (status RANGE: try the next).
        for formulation, pole_check in auto.plan(sc):
            desc = catalogue.describe((formulation, sc.symmetric, sc.effects))
            kernel = ModelKernel.load(desc, method)
            args = _settings(sc, method, kernel)
            out, y, p, st = kernel.simulate(inputs, params_of(sc, desc), t, args, pole_check)
            status = int(st["status"])
            if status != _RANGE:
                break
        if status:
            raise IntegrationError(_explain(desc, st, sc.simulate.max_steps))
        nfev = int(st["nfev"])
    _check_pole(desc, t, out[1], sc.simulate.rtol)
    # The compiled drivers checked the outputs finite (status NONFINITE_OUTPUT); SciPy's did not.
    return _result(desc, out, y, t, sc, method, nfev, p, finite=method not in SCIPY_METHODS)


@_quiet
def simulate_batch(scenes, **overrides) -> list[Result]:
    """Simulate many scenes that differ only in numbers (initial state, moments, effect
    parameters) with one call into C: init, integration and outputs of every trajectory run in
    the compiled loop.

    All scenes must name the same effects, body symmetry, output times, method and
    tolerances. With formulation "auto", the scenes share one formulation: the common choice
    if they agree, else one without a singular set (safe for every one of them).
    """
    scs = [load_scene(s, **overrides) for s in scenes]
    if not scs:
        return []
    first = scs[0]

    def shared(sc):
        s = sc.simulate
        return (sc.symmetric, sc.effects, s.samples, s.t_end, choose_method(sc), s.rtol, s.atol,
                s.h, s.max_steps, s.formulation)

    ref = shared(first)
    for sc in scs[1:]:
        if shared(sc) != ref:
            raise SceneError(f"{sc.source}: simulate: a batch needs the same effects, body symmetry, output "
                             f"times, method, tolerances and formulation as {first.source}")
    method = choose_method(first)
    if method in SCIPY_METHODS:
        raise SceneError(f"{first.source}: simulate.method: batches run in the C kernels, not {method}")
    h = None
    if compiled_method(method).driver != "adaptive" and first.simulate.h is None:
        h = min(default_step(sc) for sc in scs)
        for sc in scs:
            _check_budget(sc, method, h)
    inputs = np.array([inputs_of(sc) for sc in scs])
    t = first.t_out
    for formulation, pole_check in auto.batch_plan(scs):
        desc = catalogue.describe((formulation, first.symmetric, first.effects))
        kernel = ModelKernel.load(desc, method)
        if h is not None:
            args = kernel.driver_args(first.simulate.rtol, first.simulate.atol, h, first.simulate.max_steps)
        else:
            args = _settings(first, method, kernel)
        ps = np.array([params_of(sc, desc) for sc in scs])
        out, y, ps, st = kernel.simulate_batch(inputs, ps, t, args, pole_check)
        if not (st["status"] == Status.RANGE).any():
            break
    status = st["status"]
    if status.any():
        b = int(np.flatnonzero(status)[0])
        raise IntegrationError(f"{scs[b].source}: {_explain(desc, st[b], scs[b].simulate.max_steps)}")
    # The pole check of every trajectory at once; one that fails is then found and named per
    # scene. The C call has checked the outputs finite (status NONFINITE_OUTPUT).
    suspect = _pole_suspects(desc, out[:, 1], first.simulate.rtol)
    nfev = st["nfev"].tolist()
    results = []
    for b, sc in enumerate(scs):
        if suspect[b]:
            _check_pole(desc, t, out[b, 1], sc.simulate.rtol)
        results.append(_result(desc, out[b], y[b], t, sc, method, nfev[b], ps[b], finite=True))
    return results


def _pole_suspects(desc, betas: np.ndarray, rtol: float) -> np.ndarray:
    """Per trajectory (rows of canonical β), whether ``_check_pole`` could object: the smallest
    sin β is at the smallest or the largest β (sin is concave on [0, π]). The outputs are finite
    here (the C call checked them; a NaN would make its row a suspect anyway)."""
    if not REGISTRY[desc.formulation].pole_loss:
        return np.zeros(len(betas), dtype=bool)
    return ~_clear_of_pole(np.minimum(np.sin(betas.min(axis=1)), np.sin(betas.max(axis=1))), rtol)


def _solve_scipy(desc, method, inputs, p, t, sc):
    """SciPy's solve_ivp on the generated NumPy right-hand side (a reference, not the fast
    path): the compiled init map gives y0, the compiled output map the outputs."""
    from scipy.integrate import solve_ivp

    kernel = ModelKernel.load(desc, DEFAULT_METHOD)  # for its init and output maps
    y0, p, rc = kernel.init(inputs, p)
    if rc:
        raise IntegrationError(f"t = {t[0]:.6g}: the initial state is not finite")
    mod = numpy_module(desc)
    s = sc.simulate
    sol = solve_ivp(mod.rhs, (t[0], t[-1]), y0, method=method, t_eval=t, rtol=s.rtol,
                    atol=s.atol, args=(p,),
                    **({"jac": mod.jac} if method in ("Radau", "BDF", "LSODA") else {}))
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
    from . import models

    return models.build(formulation, symmetric, effects)


@functools.lru_cache(maxsize=None)
def sources_for(formulation: str, symmetric: bool, effects: tuple) -> dict:
    """The generated files of a model (CSE and rendering done once per process)."""
    from .codegen import model_sources

    return model_sources(model_for(formulation, symmetric, effects))


@functools.lru_cache(maxsize=None)
def kernel_for(formulation: str, symmetric: bool, effects: tuple):
    """The compiled C kernel (model + every solver) for a model, for tests and benchmarks."""
    from pathlib import Path

    from .integrate import Kernel

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
    """Write the .npz (and the plot), all or nothing (see :mod:`derive.outputs`)."""
    from .outputs import write_all

    writers = {}
    if npz:
        writers[npz] = lambda f: np.savez(f, **res.arrays())
    if png:
        def plot(f):
            from .plots import plot_result

            plot_result(res, f)

        writers[png] = plot
    write_all(writers)
