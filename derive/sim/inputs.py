"""A validated scene as the numbers a compiled kernel takes: the init map's inputs, the
model's parameters, the method, and the driver's settings (a fixed step and its budget).

Takes a :class:`derive.sim.scene.Scene` and a model description
(:class:`derive.runtime.catalogue.Description`); gives NumPy arrays and plain numbers.
"""
from __future__ import annotations

import math

import numpy as np

from derive.errors import SceneError
from derive.methods.registry import DEFAULT_METHOD
from derive.runtime.integrate import ModelKernel
from derive.runtime.records import driver_args
from derive.sim.scene import Scene
from derive.symbolic import effects


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


#: The scene's method (and formulation) that lets derive choose.
AUTO = "auto"


def choose_method(scene: Scene) -> str:
    """The scene's method, or the default one for :data:`AUTO` (a plan then weighs the Taylor
    method per model: :func:`derive.sim.plan.auto_method`)."""
    return DEFAULT_METHOD if scene.simulate.method == AUTO else scene.simulate.method


def fastest_rate(scene: Scene) -> float:
    """The fastest natural rate of the scene's motion, rad/s: the spin |ω̃| scaled by the
    moments' spread (the body rates' upper bound, I_max/I_min |ω̃|), or a rate an effect sets
    (its ``natural_rate``: √(M g l / I) for gravity, …), at least 1e-12."""
    b, w = scene.body, scene.initial.omega
    moments = b.moments
    fastest = math.sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]) * max(moments) / min(moments)
    for t in scene.tables.values():
        fastest = max(fastest, effects.REGISTRY[t.effect].natural_rate(t, b))
    return max(fastest, 1e-12)


def default_step(scene: Scene) -> float:
    """A fixed step for the fixed-step methods when the scene gives none: 1/200 of the fastest
    natural period (:func:`fastest_rate`), and no larger than the output spacing."""
    dt_out = scene.simulate.t_end / (scene.simulate.samples - 1)
    return float(min(2 * np.pi / fastest_rate(scene) / 200, dt_out))


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
    return driver_args(kernel.method, s.rtol, s.atol, h, s.max_steps)
