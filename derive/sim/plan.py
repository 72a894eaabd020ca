"""A simulation planned once: scene → (method, output times, inputs, the formulations to try,
each with its model, kernel, parameters and driver settings).

Each stage is asked once and hands its result down: the scene's numbers
(:mod:`derive.sim.inputs`), auto's candidates (:mod:`derive.sim.auto`), the model descriptions
(:mod:`derive.runtime.catalogue`) and the compiled kernels (:mod:`derive.runtime.integrate`,
loaded when a candidate is first run, so a fallback formulation costs nothing unless it is
needed). :func:`derive.sim.simulation.run` then makes the C call; a :class:`Plan` kept by the
caller (``derive.prepare``) runs again without validation or look-ups.

Takes: a validated :class:`derive.sim.scene.Scene`. Gives: a :class:`Plan`.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from derive.errors import IntegrationError
from derive.methods import costs
from derive.methods.registry import DEFAULT_METHOD, REFERENCE_METHODS
from derive.runtime import catalogue
from derive.runtime.integrate import BoundRun, ModelKernel
from derive.sim import auto
from derive.sim.inputs import AUTO, _settings, choose_method, fastest_rate, inputs_of, params_of
from derive.sim.scene import Scene
from derive.symbolic import integrable
from derive.symbolic.formulations import REGISTRY

#: SciPy reference methods: scene name -> solve_ivp method
SCIPY_METHODS = {name: ivp for name, (ivp, _) in REFERENCE_METHODS.items()}


@dataclass
class Candidate:
    """One formulation to try: its model description, the pole check its run must pass
    (0 none; see :func:`derive.sim.auto.pole_mode`), and, on first use, its kernel, parameters
    and driver arguments."""

    scene: Scene
    #: The method, or :data:`AUTO`: the cost model's for ``desc`` (:func:`auto_method`), worked
    #: out when :attr:`method` is first asked (a fallback formulation rarely runs).
    given: str
    desc: catalogue.Description
    pole_check: int

    @functools.cached_property
    def method(self) -> str:
        """The method this candidate runs."""
        return auto_method(self.scene, self.desc) if self.given == AUTO else self.given

    @functools.cached_property
    def kernel(self) -> ModelKernel:
        # a SciPy reference takes the init and output maps from the default method's library
        return ModelKernel.load(self.desc, self.method if self.method not in SCIPY_METHODS
                                else DEFAULT_METHOD)

    @functools.cached_property
    def params(self) -> np.ndarray:
        return params_of(self.scene, self.desc)

    @functools.cached_property
    def args(self) -> list:
        return _settings(self.scene, self.method, self.kernel)

    @functools.cached_property
    def pole_loss(self) -> bool:
        """Whether the formulation loses accuracy near β = 0, π (the result's pole check)."""
        return REGISTRY[self.desc.formulation].pole_loss

    def bound(self, t: np.ndarray, inputs: np.ndarray) -> BoundRun:
        """The kernel's C call bound to the plan's output times and inputs (made on first use,
        then kept: a candidate belongs to one plan, whose ``t`` and ``inputs`` do not change)."""
        b = self.__dict__.get("_bound")
        if b is None:
            b = self.__dict__["_bound"] = self.kernel.bind(t, inputs, self.args, self.pole_check)
        return b


@dataclass
class Plan:
    """What one simulation runs, decided once: the scene, the method (the first candidate's;
    with ``method = "auto"`` each candidate has the cost model's for its model), the output times ``t``,
    the init map's ``inputs`` and the ``candidates`` in the order they are tried (the C
    driver's pole check refuses a singular formulation's start with status RANGE: the next
    one runs)."""

    scene: Scene
    method: str
    t: np.ndarray
    inputs: np.ndarray
    candidates: tuple

    def __post_init__(self):
        s = self.scene.simulate  # a run its step budget cannot cover is refused before it starts
        why = costs.over_budget(self.method, s.t_end * fastest_rate(self.scene), s.rtol, s.atol, s.max_steps)
        if why:
            raise IntegrationError(f"{self.scene.source}: {why}")

    @property
    def scipy(self) -> str | None:
        """The solve_ivp method of a SciPy reference run, else None."""
        return SCIPY_METHODS.get(self.method)

    @functools.cached_property
    def integral_rows(self) -> list:
        """The scene's integrals (:func:`integral_rows_of`), looked up once per plan: a prepared
        run does not classify its scene again."""
        return integral_rows_of(self.scene)


def integral_rows_of(scene: Scene) -> list:
    """``[(name, formula, values, component)]``: the extra integral of the scene's integrable
    case (empty for a general body) as its formula, ``formula(L, n, values)`` with L and n rows
    of shape (3, N) (the layout of the C call's outputs: nothing is converted per run), the
    scene's numbers, and the component of L it is when it is one (else None; see
    :attr:`derive.symbolic.integrable.Integral.component`); what
    :func:`derive.symbolic.integrable.integrals_for` wraps."""
    integral = integrable.classify(scene).extra
    return [] if integral is None else [(integral.name, integral.formula, integrable.parameters(scene),
                                         integral.component)]


def make(scene: Scene) -> Plan:
    """The plan of a validated scene (formulation "auto": every applicable candidate, cheapest
    first; a named formulation: that one; a SciPy method: the formulation auto picks for it)."""
    method = choose_method(scene)
    key = (scene.symmetric, scene.effects)
    if method in SCIPY_METHODS:
        steps = [(auto.model_key(scene, method)[0], 0)]
    else:
        steps = auto.plan(scene)
    given = AUTO if scene.simulate.method == AUTO and method not in SCIPY_METHODS else method
    # each candidate's method for its own model (a fallback model may weigh differently), so
    # that a fallback runs what a plan of its model would run
    candidates = tuple(Candidate(scene, given, catalogue.describe((name, *key)), mode) for name, mode in steps)
    return Plan(scene, candidates[0].method if candidates else method, scene.t_out, inputs_of(scene),
                candidates)


def auto_method(scene: Scene, desc: catalogue.Description, samples: int | None = None) -> str:
    """The method ``method = "auto"`` runs on the model ``desc``: the one of
    :data:`derive.methods.costs.CHOICES` that the cost model (:mod:`derive.methods.costs`)
    finds cheapest at the scene's tolerance, output count and span. ``samples``: the output
    times the run keeps when they are not the scene's (a sweep keeps t = 0 and t_end)."""
    if desc.jet_weight <= 0:  # no Taylor kernel: nothing to weigh
        return costs.CHOICES[0]
    s = scene.simulate
    work = costs.Work(rhs_cost=desc.cost, jet_weight=desc.jet_weight, output_cost=desc.output_cost,
                      ny=len(desc.states), n_out=len(desc.outputs),
                      samples=s.samples if samples is None else samples,
                      span=s.t_end * fastest_rate(scene))
    return costs.choose(work, s.rtol, s.atol)
