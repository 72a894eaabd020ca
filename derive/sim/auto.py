"""Formulation "auto": the cheapest formulation that represents the scene accurately.

1. The candidates are the registry's formulations whose ``applicable(scene)`` has no objection.
2. They are tried in order of cost: the weighted operation count of the generated right-hand
   side plus the stepper's work per state component (``cost`` in the model's description), for
   the models the package ships (generated/; never the cache's, so the choice does not depend
   on what was derived before); the others after those, in registry order, which lists the
   formulations cheapest first for a typical body (choosing must not cost a derivation).
3. A formulation with a singular set (sin β = 0) is taken only when the derived β range keeps
   clear of it: the model's compiled ``checks`` (run by the simulate driver itself, before it
   integrates: ``<name>_simulate_checked_<method>``) evaluate the Routh polynomial
   f(u) = u̇² (u = cos β) at u = ±u_c, u_c = √(1 − s²), s = ``POLE_CLEARANCE`` (see
   ``models.routh_checks``); the motion stays in |sin β| ≥ s exactly when |u₀| < u_c and
   f(±u_c) < 0. The reduced formulation may also meet a pole where its equations stay regular:
   p_α = p_γ at β = 0, p_α = −p_γ at β = π, as the kernel receives them. Without a Routh
   reduction (an asymmetric body, damping, gravity off axis 3) the range is not known and the
   singular formulations are not chosen.
"""
from __future__ import annotations

import functools

from derive.runtime import catalogue
from derive.symbolic import effects as fx
from derive.symbolic.formulations import REGISTRY
from derive.methods.registry import DEFAULT_METHOD, compiled_methods, method_reason
from derive.runtime.integrate import ModelKernel
from derive.sim.inputs import choose_method, inputs_of, params_of


def _known_cost(key) -> float | None:
    """The cost of a model the package ships (generated/), else None: not the cache's, so that
    the order, and with it the formulation a scene runs, is the same in every process and on
    every machine whatever was derived before."""
    desc = catalogue.shipped(key)
    return None if desc is None else desc.cost


def has_routh(symmetric: bool, effects) -> bool:
    """A symmetric body under axisymmetric conservative effects: p_α, p_γ are conserved and the
    Routh reduction bounds β."""
    return symmetric and all(e.conservative and e.axisymmetric for e in fx.lookup(effects))


def pole_mode(name: str) -> int:
    """The C drivers' ``pole_check`` for a formulation: 0 none, 1 clear of both poles, 2 clear
    or meeting a pole only where the reduced equations are regular."""
    f = REGISTRY[name]
    return 0 if not f.singular else f.pole_check or (2 if f.needs_routh else 1)


def plan(scene, effects: tuple | None = None) -> list[tuple[str, int]]:
    """The formulations to try, in order, each with the pole check its run must pass: the
    singular ones only with a Routh reduction, up to the first one without a singular set;
    only formulations the scene's method can run (a splitting method: Euler–Poisson).
    ``effects``: the model's effects when they are not the scene's own (a batch's or a sweep's
    model has every effect that acts at any of its points)."""
    if scene.simulate.formulation != "auto":  # asked for by name: only its own pole check
        return [(scene.simulate.formulation, REGISTRY[scene.simulate.formulation].pole_check)]
    effects = scene.effects if effects is None else effects
    out = []
    for name, mode in structural(scene.symmetric, effects, scene.simulate.method):
        if REGISTRY[name].applicable(scene) is None:  # the scene's numbers (e.g. its start)
            out.append((name, mode))
            if not mode:
                break
    return out


def structural(symmetric: bool, effects: tuple, method: str) -> tuple:
    """The formulations ``plan`` would try for this body symmetry, these effects and this
    method, cheapest first, each with its pole mode, before the scene's numbers are looked at
    (a sweep's or a batch's model: :func:`derive.sweeps.plan.sweep_plan`).

    Returns
    -------
    tuple of (str, int)
        (formulation, pole mode) pairs; see :func:`pole_mode`.
    """
    out, effects = [], tuple(effects)
    routh = has_routh(symmetric, effects)
    for name in _by_cost(symmetric, effects):
        if method_reason(method, name, effects):
            continue
        mode = pole_mode(name)
        if mode and not routh:
            continue
        out.append((name, mode))
    return tuple(out)


def _clear(scene, name: str, method: str) -> bool:
    """The pole check of ``plan`` run on its own (compiled: the model's ``<name>_pole_clear``),
    for a caller that does not go through the simulate driver."""
    desc = catalogue.describe((name, scene.symmetric, scene.effects))
    kernel = ModelKernel.load(desc, method)
    y, p, rc = kernel.init(inputs_of(scene), params_of(scene, desc))
    return rc == 0 and kernel.pole_clear(y, p, pole_mode(name))


@functools.lru_cache(maxsize=256)
def _by_cost(symmetric, effects) -> tuple:
    """Every registered formulation for this body symmetry and these effects, cheapest first
    (cached: the shipped models and their costs are fixed, and looking them up reads the disk)."""
    known = {name: _known_cost((name, symmetric, effects)) for name in REGISTRY}
    rank = {name: i for i, name in enumerate(REGISTRY)}
    return tuple(sorted(REGISTRY, key=lambda n: (known[n] is None, known[n] or 0, rank[n])))


def formulation(scene, method: str | None = None) -> str:
    """The formulation ``simulate`` runs for the scene (with ``method``, whose library the
    check loads; default the scene's)."""
    requested = scene.simulate.formulation
    if requested != "auto":
        return requested
    method = method or choose_method(scene)
    if method not in compiled_methods():  # a SciPy reference: the checks come from dop853's library
        method = DEFAULT_METHOD
    for name, mode in plan(scene):
        if not mode or _clear(scene, name, method):
            return name
    raise AssertionError("no formulation applies")  # one without a singular set applies to all


def model_key(scene, method: str | None = None) -> tuple:
    """(formulation, symmetric body, effects): the model a scene runs."""
    return (formulation(scene, method), scene.symmetric, scene.effects)


def batch_plan(scenes, effects: tuple | None = None) -> list[tuple[str, int]]:
    """The plan for a batch that shares one model (with ``effects``, default the first
    scene's): the first scene's plan, kept to the formulations every scene accepts (a singular
    one runs with its pole check for every trajectory in C; one refusal sends the whole batch
    to the next)."""
    return [(name, mode) for name, mode in plan(scenes[0], effects)
            if all(REGISTRY[name].applicable(sc) is None for sc in scenes)]
