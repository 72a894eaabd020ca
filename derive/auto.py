"""Formulation "auto": the cheapest formulation that represents the scene accurately.

1. The candidates are the registry's formulations whose ``applicable(scene)`` has no objection.
2. They are tried in order of cost: the weighted operation count of the generated right-hand
   side plus the stepper's work per state component (``cost`` in the model's description), for
   the models already generated or cached; a model that would have to be derived first is tried
   after those, in registry order (choosing must not cost a derivation).
3. A formulation with a singular set (sin β = 0) is taken only when the derived β range keeps
   clear of it: the reduced model's compiled ``checks`` evaluate the Routh polynomial
   f(u) = u̇² (u = cos β) at u = ±u_c, u_c = √(1 − s²), s = ``POLE_CLEARANCE`` (see
   ``models.routh_checks``); the motion stays in |sin β| ≥ s exactly when |u₀| < u_c and
   f(±u_c) < 0. The reduced formulation may also meet a pole where its equations stay regular:
   p_α = p_γ at β = 0, p_α = −p_γ at β = π, as the kernel receives them. Without a Routh
   reduction (an asymmetric body, damping, gravity off axis 3) the range is not known and the
   singular formulations are not chosen.
"""
from __future__ import annotations

import functools
import math

from . import catalogue
from . import effects as fx
from .formulations import POLE_CLEARANCE, REGISTRY
from .solvers import DEFAULT_METHOD
from .solvers import METHODS as _C_METHODS


def _known_cost(key) -> float | None:
    """The cost of a model whose description exists without deriving anything, else None."""
    desc = catalogue.available(key)
    return None if desc is None else desc.cost


def _routh(scene, name: str, method: str):
    """(f(u_c), f(−u_c), u₀, p_α − p_γ, p_α + p_γ) from the compiled ``checks`` of the model
    that would run (the same library: choosing compiles nothing extra), or None when the scene
    has no Routh reduction or the initial state is outside the formulation's init map."""
    effects = fx.lookup(scene.effects)
    if not scene.symmetric or any(not (e.conservative and e.axisymmetric) for e in effects):
        return None
    from .integrate import ModelKernel
    from .simulation import inputs_of, params_of

    desc = catalogue.describe((name, True, scene.effects))
    if not desc.checks:
        return None
    kernel = ModelKernel.load(desc, method)
    y, p, rc = kernel.init(inputs_of(scene), params_of(scene, desc))
    if rc:
        return None
    return tuple(kernel.checks(y, p))


def _clear(routh, formulation: str) -> bool:
    """Does the motion keep clear of the poles (or meet one where the formulation is regular)?"""
    f_top, f_bottom, u0, diff, total = routh
    uc = math.sqrt(1.0 - POLE_CLEARANCE**2)
    top = u0 < uc and f_top < 0.0
    bottom = u0 > -uc and f_bottom < 0.0
    if REGISTRY[formulation].needs_routh:
        return (top or diff == 0.0) and (bottom or total == 0.0)
    return top and bottom


def candidates(scene) -> list[str]:
    """The applicable formulations, cheapest first (see the module docstring)."""
    return [name for name in _by_cost(scene.symmetric, scene.effects, fx.VERSION[0])
            if REGISTRY[name].applicable(scene) is None]


@functools.lru_cache(maxsize=256)
def _by_cost(symmetric, effects, version) -> tuple:
    """Every registered formulation for this body symmetry and these effects, cheapest first
    (cached: the costs are fixed once the models are generated)."""
    known = {name: _known_cost((name, symmetric, effects)) for name in REGISTRY}
    rank = {name: i for i, name in enumerate(REGISTRY)}
    return tuple(sorted(REGISTRY, key=lambda n: (known[n] is None, known[n] or 0, rank[n])))


def formulation(scene, method: str | None = None) -> str:
    """The formulation ``simulate`` runs for the scene (with ``method``, whose library the
    check loads; default the scene's)."""
    requested = scene.simulate.formulation
    if requested != "auto":
        return requested
    from .simulation import choose_method

    method = method or choose_method(scene)
    if method not in _C_METHODS:  # a SciPy reference method: the checks come from dop853's library
        method = DEFAULT_METHOD
    for name in candidates(scene):
        if REGISTRY[name].singular:
            routh = _routh(scene, name, method)
            if routh is None or not _clear(routh, name):
                continue
        return name
    raise AssertionError("no formulation applies")  # euler-poisson applies to every scene


def model_key(scene, method: str | None = None) -> tuple:
    """(formulation, symmetric body, effects): the model a scene runs."""
    return (formulation(scene, method), scene.symmetric, scene.effects)


def batch_key(scenes) -> tuple:
    """One model for a batch: the common choice, else the cheapest formulation without a
    singular set that every scene's ``applicable`` accepts."""
    keys = {model_key(sc) for sc in scenes}  # the batch's shared method, so one library
    if len(keys) == 1:
        return keys.pop()
    first = scenes[0]
    for name in candidates(first):
        if not REGISTRY[name].singular and all(REGISTRY[name].applicable(sc) is None for sc in scenes):
            return (name, first.symmetric, first.effects)
    raise AssertionError("no formulation without a singular set applies to every scene")
