"""Simulate a scene: scene → model → kernel → integrator → results.

The scene names the effects; the model is built from exactly those (`models.build`), compiled
once per process (`kernel_for`), integrated in C (or by SciPy on the generated NumPy
right-hand side, for comparison), and the outputs of the contract are computed from the
state by the model's generated observables, whatever formulation ran.

Formulation "auto":
* symmetric body, conservative effects, and a β range that stays clear of the poles (or meets
  a pole only where the reduced equations are regular: p_α = ±p_γ) → ``reduced``: the one
  degree of freedom that is left once p_α, p_γ are conserved;
* otherwise → ``quaternion``, which has no coordinate singularity.
The Euler-angle formulation runs only when asked for; it then refuses (IntegrationError) to
return a trajectory that came closer to β = 0 or π than its accuracy allows.
"""
from __future__ import annotations

import functools
import types
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from . import models
from .errors import IntegrationError, SceneError
from .scene import Scene, load_scene

FIXED_STEP = ("rk4", "gauss4", "gauss6")
SCIPY_METHODS = {"scipy-rk45": "RK45", "scipy-dop853": "DOP853", "scipy-radau": "Radau", "scipy-lsoda": "LSODA"}
# Closest approach to a pole (|sin β|) at which the reduced and Euler-angle formulations still
# keep their accuracy; nearer than this, "auto" takes the quaternion formulation.
POLE_CLEARANCE = 1e-3


@dataclass
class Result:
    """The arrays of the output file (see INTERFACE.md), as attributes."""

    t: np.ndarray
    alpha: np.ndarray
    beta: np.ndarray
    gamma: np.ndarray
    omega: np.ndarray
    axis: np.ndarray
    energy: np.ndarray
    p_alpha: np.ndarray
    p_gamma: np.ndarray
    method: str
    formulation: str
    nfev: int
    model: str = ""
    state: np.ndarray | None = field(default=None, repr=False)
    scene: Scene | None = field(default=None, repr=False)

    def arrays(self) -> dict:
        return dict(t=self.t, alpha=self.alpha, beta=self.beta, gamma=self.gamma, omega=self.omega,
                    axis=self.axis, energy=self.energy, p_alpha=self.p_alpha, p_gamma=self.p_gamma,
                    method=np.array(self.method), formulation=np.array(self.formulation),
                    nfev=np.array(self.nfev, dtype=np.int64))


# ---------------------------------------------------------------------------------------------
# model and kernel


def effect_names(scene: Scene) -> tuple[str, ...]:
    """The registry effects a scene calls for (gravity only when it has a [gravity] table, …)."""
    return scene.effects


@functools.lru_cache(maxsize=None)
def model_for(formulation: str, symmetric: bool, effects: tuple) -> models.Model:
    return models.build(formulation, symmetric, effects)


@functools.lru_cache(maxsize=None)
def sources_for(formulation: str, symmetric: bool, effects: tuple) -> dict:
    """The generated files of a model (CSE and rendering done once per process)."""
    from .codegen import model_sources

    return model_sources(model_for(formulation, symmetric, effects))


@functools.lru_cache(maxsize=None)
def kernel_for(formulation: str, symmetric: bool, effects: tuple):
    """The compiled C kernel (model + solvers) for a model; derived and compiled once."""
    from .integrate import Kernel

    model = model_for(formulation, symmetric, effects)
    files = sources_for(formulation, symmetric, effects)
    sources = {Path(k).name: v for k, v in files.items() if k in (f"c/{model.name}.h", f"c/{model.name}.c")}
    return Kernel.from_sources(model.name, sources)


@functools.lru_cache(maxsize=None)
def numpy_module_for(formulation: str, symmetric: bool, effects: tuple) -> types.ModuleType:
    """The generated NumPy module of a model, loaded from its rendered text."""
    model = model_for(formulation, symmetric, effects)
    text = sources_for(formulation, symmetric, effects)[f"numpy/{model.name}.py"]
    mod = types.ModuleType(f"derive_generated_{model.name}")
    exec(compile(text, f"<generated {model.name}>", "exec"), mod.__dict__)
    return mod


# ---------------------------------------------------------------------------------------------
# initial state and parameters per formulation


def _momenta(scene: Scene) -> tuple[float, float]:
    """(p_α, p_γ) as the reduced kernel receives them, p_α formed as p_γ + (p_α − p_γ) with the
    difference computed without cancellation, so a top with p_α = p_γ gets exactly equal
    parameters even at β₀ ~ 1e-8 (where p_α computed directly is off by an ulp of p_γ).

    p_α = ẑ·(R I ω̃), the ẑ row of R being (−sinβ cosγ, sinβ sinγ, cosβ), so
    p_α − p_γ = row₁₂ · (I ω̃)₁₂ − 2 sin²(β/2) I₃ω̃₃.
    """
    b, i = scene.body, scene.initial
    w = np.asarray(i.omega, dtype=float)
    p_gamma = b.I3 * w[2]
    sb = np.sin(i.beta)
    diff = float(-sb * np.cos(i.gamma) * b.I1 * w[0] + sb * np.sin(i.gamma) * b.I2 * w[1]
                 - 2.0 * np.sin(i.beta / 2) ** 2 * p_gamma)
    return float(p_gamma + diff), float(p_gamma)


def _params(scene: Scene, model: models.Model) -> np.ndarray:
    values = scene.param_values()
    if model.formulation == "reduced":
        values["p_alpha"], values["p_gamma"] = _momenta(scene)
    return np.array([values[n] for n in model.param_names], dtype=float)


def _quaternion(a, b, c) -> np.ndarray:
    """q of R = Rz(α) Ry(β) Rz(γ), scalar first: product of the three half-angle quaternions."""
    qa = np.array([np.cos(a / 2), 0.0, 0.0, np.sin(a / 2)])
    qb = np.array([np.cos(b / 2), 0.0, np.sin(b / 2), 0.0])
    qc = np.array([np.cos(c / 2), 0.0, 0.0, np.sin(c / 2)])
    return _qmul(_qmul(qa, qb), qc)


def _qmul(p, q) -> np.ndarray:
    p0, pv, q0, qv = p[0], p[1:], q[0], q[1:]
    return np.concatenate([[p0 * q0 - pv @ qv], p0 * qv + q0 * pv + np.cross(pv, qv)])


def _initial_state(scene: Scene, model: models.Model) -> np.ndarray:
    i = scene.initial
    if model.formulation == "quaternion":
        return np.concatenate([_quaternion(i.alpha, i.beta, i.gamma), i.omega])
    if model.formulation == "reduced":
        return np.array([i.alpha, i.beta, i.gamma, _beta_dot(scene)])
    if model.formulation == "euler-angles":
        rates = euler_rates(scene)
        if rates is None:
            raise SceneError(f"{scene.source}: initial: the Euler-angle rates are undefined at sin(beta) = "
                             f"{np.sin(i.beta):.3g}; give the rates, or use formulation = \"quaternion\"")
        return np.array([i.alpha, i.beta, i.gamma, *rates])
    raise ValueError(model.formulation)


def euler_rates(scene: Scene):
    """(α̇, β̇, γ̇) as given, or from ω̃ by the inverse map
    α̇ = (−ω̃₁ cos γ + ω̃₂ sin γ)/sin β, β̇ = ω̃₁ sin γ + ω̃₂ cos γ, γ̇ = ω̃₃ − α̇ cos β;
    None where that map is too ill-conditioned to use (|sin β| < POLE_CLEARANCE)."""
    i = scene.initial
    if i.alpha_dot is not None:
        return float(i.alpha_dot), float(i.beta_dot), float(i.gamma_dot)
    s = np.sin(i.beta)
    if abs(s) < POLE_CLEARANCE:
        return None
    w1, w2, w3 = i.omega
    cg, sg = np.cos(i.gamma), np.sin(i.gamma)
    ad = (-w1 * cg + w2 * sg) / s
    return float(ad), float(w1 * sg + w2 * cg), float(w3 - ad * np.cos(i.beta))


def _beta_dot(scene: Scene) -> float:
    i = scene.initial
    if i.beta_dot is not None:
        return float(i.beta_dot)
    w1, w2, _ = i.omega
    return float(w1 * np.sin(i.gamma) + w2 * np.cos(i.gamma))


# ---------------------------------------------------------------------------------------------
# choosing the formulation


def beta_range(scene: Scene) -> tuple[float, float]:
    """[β_min, β_max] of |β| for a conservative symmetric top: the turning points of
    f(u) = (1 − u²)(2/I₁)(E′ − M g l u) − ((p_α − p_γ u)/I₁)², u = cos β.

    The roots come from the exact solution's cubic (`exact.heavy_top`), which is centred at the
    initial point and refined next to each pole, so a double root (steady precession) or a
    turning point at the start (β̇₀ = 0) needs no special case here. Where the Euler rates are
    undefined (ω̃ given at a pole) the range is reported as the initial tilt alone.
    """
    from . import exact

    i = scene.initial
    beta0 = abs(float(i.beta))
    rates = euler_rates(scene)
    if rates is None:
        return beta0, beta0
    g = scene.gravity
    M, gg, l = (g.M, g.g, g.l) if g is not None else (1.0, 0.0, 0.0)
    info = exact.heavy_top(scene.body.I1, scene.body.I3, M, gg, l, i.alpha, i.beta, i.gamma,
                           *rates, [0.0]).info
    if "y_roots" not in info:  # an equilibrium: β stays where it is
        return beta0, beta0
    y1, y2 = info["y_roots"][:2]
    # y = sin²(β/2) of the problem exact.py solved (mirrored β → π − β when β₀ > π/2).
    lo, hi = (2.0 * np.arcsin(np.sqrt(np.clip(y, 0.0, 1.0))) for y in (y1, y2))
    if info.get("mirrored"):
        lo, hi = np.pi - hi, np.pi - lo
    return float(lo), float(hi)


def choose_formulation(scene: Scene) -> str:
    requested = scene.simulate.formulation
    if requested != "auto":
        return requested
    from . import effects

    if not scene.symmetric or any(not (e.conservative and e.axisymmetric)
                                  for e in effects.lookup(scene.effects)):
        return "quaternion"
    p_alpha, p_gamma = _momenta(scene)
    b_lo, b_hi = beta_range(scene)
    near_top = np.sin(b_lo) < POLE_CLEARANCE and b_lo < np.pi / 2
    near_bottom = np.sin(b_hi) < POLE_CLEARANCE and b_hi > np.pi / 2
    # At a pole the reduced equations stay regular only when the matching momentum sum vanishes,
    # as the kernel sees it.
    if (near_top and p_alpha - p_gamma != 0.0) or (near_bottom and p_alpha + p_gamma != 0.0):
        return "quaternion"
    return "reduced"


def choose_method(scene: Scene) -> str:
    return "dop853" if scene.simulate.method == "auto" else scene.simulate.method


# ---------------------------------------------------------------------------------------------
# outputs


def _euler_from_quaternion(q: np.ndarray):
    """Continuous z-y-z angles of R(q): β ∈ [0, π], α and γ unwrapped."""
    q = q / np.linalg.norm(q, axis=1, keepdims=True)
    q0, q1, q2, q3 = q.T
    r13 = 2 * (q1 * q3 + q0 * q2)
    r23 = 2 * (q2 * q3 - q0 * q1)
    r31 = 2 * (q1 * q3 - q0 * q2)
    r32 = 2 * (q2 * q3 + q0 * q1)
    # cos β = q0² − q1² − q2² + q3², sin β = 2 √((q0² + q3²)(q1² + q2²)): both accurate near the poles.
    a2, b2 = q0**2 + q3**2, q1**2 + q2**2
    beta = np.arctan2(2 * np.sqrt(a2 * b2), a2 - b2)
    alpha = np.unwrap(np.arctan2(r23, r13))
    gamma = np.unwrap(np.arctan2(r32, -r31))
    return alpha, beta, gamma


def _outputs(model: models.Model, mod, t, Y, p, scene, method, nfev) -> Result:
    obs = mod.observables(t, Y.T, p)
    named = dict(zip(mod.OBSERVABLE_NAMES, obs))
    if model.formulation == "quaternion":
        alpha, beta, gamma = _euler_from_quaternion(Y[:, :4])
    else:
        alpha, beta, gamma = Y[:, 0], Y[:, 1], Y[:, 2]
    res = Result(
        t=t, alpha=alpha, beta=beta, gamma=gamma,
        omega=np.stack([named["omega1"], named["omega2"], named["omega3"]], axis=1),
        axis=np.stack([named["axis_x"], named["axis_y"], named["axis_z"]], axis=1),
        energy=np.broadcast_to(named["energy"], t.shape).copy(),
        p_alpha=np.broadcast_to(named["p_alpha"], t.shape).astype(float).copy(),
        p_gamma=np.broadcast_to(named["p_gamma"], t.shape).astype(float).copy(),
        method=method, formulation=model.formulation, nfev=int(nfev), model=model.name, state=Y, scene=scene,
    )
    for name in ("alpha", "beta", "gamma", "omega", "axis", "energy"):
        arr = getattr(res, name)
        bad = ~np.isfinite(arr)
        if bad.any():
            k = int(np.argwhere(bad)[0][0])
            raise IntegrationError(f"t = {t[k]:.6g}: non-finite {name} in the output")
    return res


def _check_pole(model: models.Model, t, Y, rtol):
    """The Euler-angle equations divide by sin β: q̈ has relative error ~ eps/sin²β. Refuse a
    trajectory whose closest approach to a pole made that larger than the tolerance."""
    if model.formulation != "euler-angles":
        return
    s = np.abs(np.sin(Y[:, 1]))
    k = int(np.argmin(s))
    if s[k] ** 2 < np.finfo(float).eps / rtol:
        raise IntegrationError(f"t = {t[k]:.6g}: coordinate singularity of the Euler-angle formulation "
                               f"(|sin beta| = {s[k]:.3g}); use formulation = \"quaternion\" or \"auto\"")


# ---------------------------------------------------------------------------------------------
# entry point


def simulate(scene, **overrides) -> Result:
    """Simulate a scene (path or dict shaped like the TOML); overrides replace [simulate] keys."""
    sc = load_scene(scene, **overrides)
    formulation = choose_formulation(sc)
    method = choose_method(sc)
    key = (formulation, sc.symmetric, effect_names(sc))
    model = model_for(*key)
    p = _params(sc, model)
    y0 = _initial_state(sc, model)
    t = sc.t_out
    s = sc.simulate
    if method in SCIPY_METHODS:
        Y, nfev = _solve_scipy(numpy_module_for(*key), SCIPY_METHODS[method], y0, p, t, s.rtol, s.atol)
    else:
        kernel = kernel_for(*key)
        h = s.h
        if method in FIXED_STEP and h is None:
            h = default_step(sc)
        _check_budget(sc, method, h)
        sol = kernel.solve(method, y0, p, t, rtol=s.rtol, atol=s.atol, h=h, max_steps=s.max_steps, check=False)
        if sol.status != 0:
            raise IntegrationError(_explain(model, sol))
        Y, nfev = sol.y, sol.nfev
    _check_pole(model, t, Y, s.rtol)
    return _outputs(model, numpy_module_for(*key), t, Y, p, sc, method, nfev)


def simulate_batch(scenes, **overrides) -> list[Result]:
    """Simulate many scenes that differ only in numbers (initial state, moments, effect
    parameters) with one call into C: the loop over trajectories runs in the solver kernel.

    All scenes must name the same effects, body symmetry, output times, method and
    tolerances. With formulation "auto", the scenes share one formulation: the common choice
    if they agree, else the quaternion formulation (safe for every one of them).
    """
    scs = [load_scene(s, **overrides) for s in scenes]
    if not scs:
        return []
    first = scs[0]
    shared = lambda sc: (sc.symmetric, effect_names(sc), sc.simulate.samples, sc.simulate.t_end,  # noqa: E731
                         choose_method(sc), sc.simulate.rtol, sc.simulate.atol, sc.simulate.h)
    for sc in scs[1:]:
        if shared(sc) != shared(first):
            raise SceneError(f"{sc.source}: simulate: a batch needs the same effects, body symmetry, output "
                             f"times, method and tolerances as {first.source}")
    forms = {choose_formulation(sc) for sc in scs}
    formulation = forms.pop() if len(forms) == 1 else "quaternion"
    method = choose_method(first)
    if method in SCIPY_METHODS:
        raise SceneError(f"{first.source}: simulate.method: batches run in the C kernels, not {method}")
    key = (formulation, first.symmetric, effect_names(first))
    model = model_for(*key)
    y0s = np.array([_initial_state(sc, model) for sc in scs])
    ps = np.array([_params(sc, model) for sc in scs])
    s = first.simulate
    h = s.h if s.h is not None or method not in FIXED_STEP else min(default_step(sc) for sc in scs)
    _check_budget(first, method, h)
    batch = kernel_for(*key).solve_batch(method, y0s, ps, first.t_out, rtol=s.rtol, atol=s.atol, h=h,
                                         max_steps=s.max_steps, check=False)
    results = []
    for b, sc in enumerate(scs):
        sol = batch[b]
        if sol.status != 0:
            raise IntegrationError(f"{sc.source}: {_explain(model, sol)}")
        _check_pole(model, sc.t_out, sol.y, s.rtol)
        results.append(_outputs(model, numpy_module_for(*key), sc.t_out, sol.y, ps[b], sc, method, sol.nfev))
    return results


DOMAIN_STATUS = 4  # derive_stats: the rhs reported a state outside the model's domain


def _explain(model: models.Model, sol) -> str:
    """The solver's one-line failure message; for a domain error, what the domain is."""
    if sol.status == DOMAIN_STATUS and model.domain_note:
        return f"t = {sol.t_fail:.8g}: {model.domain_note}"
    return sol.message


def _check_budget(scene: Scene, method: str, h: float | None) -> None:
    """A fixed-step run takes ceil(Δt/h) steps per output interval: refuse it up front (bad
    input, before any work) when that exceeds ``[simulate] max_steps``."""
    if method not in FIXED_STEP:
        return
    # The count of the C drivers' substeps() (templates/c/solvers.c.j2): a ratio within a
    # relative 1e-10 above an integer counts as that integer.
    r = np.diff(scene.t_out) / h
    n = np.ceil(r)
    n = np.where((n > 1.0) & (n - r > 1.0 - 1e-10 * r), n - 1.0, n)
    steps = int(np.sum(np.maximum(n, 1.0)))
    if steps > scene.simulate.max_steps:
        raise SceneError(f"{scene.source}: simulate.max_steps: {method} with h = {h:.6g} s needs {steps} "
                         f"steps, more than max_steps = {scene.simulate.max_steps}")


def default_step(scene: Scene) -> float:
    """A fixed step for RK4 / Gauss–Legendre when the scene gives none: 1/200 of the fastest
    natural period (spin, precession or pendulum), and no larger than the output spacing."""
    from . import effects

    b, i = scene.body, scene.initial
    rates = [np.linalg.norm(i.omega) * max(b.I1, b.I2, b.I3) / min(b.I1, b.I2, b.I3)]
    for t in scene.tables.values():
        rates.append(effects.REGISTRY[t.effect].natural_rate(t, b))
    fastest = max(max(rates), 1e-12)
    dt_out = scene.simulate.t_end / (scene.simulate.samples - 1)
    return float(min(2 * np.pi / fastest / 200, dt_out))


def _solve_scipy(mod, method, y0, p, t, rtol, atol):
    from scipy.integrate import solve_ivp

    sol = solve_ivp(mod.rhs, (t[0], t[-1]), y0, method=method, t_eval=t, rtol=rtol, atol=atol, args=(p,),
                    **({"jac": mod.jac} if method in ("Radau", "BDF", "LSODA") else {}))
    if not sol.success:
        raise IntegrationError(f"t = {sol.t[-1] if sol.t.size else t[0]:.6g}: scipy {method}: {sol.message}")
    return sol.y.T.copy(), sol.nfev


def write_outputs(res: Result, npz: str | None = None, png: str | None = None) -> None:
    """Write the .npz and/or the plot, all or nothing (see `derive.outputs`): every path is
    checked first, each file goes to a temporary beside its target, and the temporaries are
    renamed into place only once all of them were written."""
    from .outputs import check_paths, write_all

    check_paths([npz, png])
    writers = {}
    if npz:
        writers[npz] = lambda f: np.savez(f, **res.arrays())
    if png:
        from .plots import plot_result

        writers[png] = lambda f: plot_result(res, f)
    write_all(writers)
