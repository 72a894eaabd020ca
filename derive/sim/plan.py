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
import math
import struct
from dataclasses import dataclass

import numpy as np

from derive.methods import costs
from derive.methods.registry import DEFAULT_METHOD, REFERENCE_METHODS
from derive.runtime import catalogue
from derive.runtime.integrate import BoundRun, ModelKernel
from derive.sim import auto
from derive.sim.inputs import AUTO, _settings, choose_method, fastest_rate, inputs_of, params_of
from derive.sim.scene import Scene
from derive.symbolic import effects
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

    @property
    def scipy(self) -> str | None:
        """The solve_ivp method of a SciPy reference run, else None."""
        return SCIPY_METHODS.get(self.method)

    @functools.cached_property
    def integral_rows(self) -> list:
        """The scene's integrals (:func:`integral_rows_of`), looked up once per plan: a prepared
        run does not classify its scene again."""
        return integral_rows_of(self.scene)


def _integrals_key(scene: Scene) -> tuple:
    # The case depends on the body and the effects' numbers, and for a Goryachev–Chaplygin body
    # on whether the state is on L·n = 0 (a cheap test): classified once per body and level.
    from derive.symbolic.integrable import on_area_level

    return (scene.body, tuple((k, v.effect, tuple(v._values.values())) for k, v in scene.tables.items()),
            on_area_level(scene))


def _memo(memo: dict, key, make):
    """``memo[key]``, made by ``make()`` when absent (:func:`_keep`)."""
    found = memo.get(key)
    return _keep(memo, key, make()) if found is None else found


def _keep(memo: dict, key, value):
    """``value``, kept as ``memo[key]``; the memo holds at most :data:`MEMO_SIZE` entries, the
    oldest inserted going first (a sweep of many bodies must not grow it without bound)."""
    try:
        while len(memo) >= MEMO_SIZE:
            del memo[next(iter(memo))]
    except (KeyError, RuntimeError, StopIteration):  # another thread changed it: it is only a memo
        pass
    memo[key] = value
    return value


#: Entries kept by each of this module's memos (classifications, plans).
MEMO_SIZE = 64


def integral_rows_of(scene: Scene) -> list:
    """``[(name, formula, values, component)]``: the extra integral of the scene's integrable
    case (empty for a general body) as its formula, ``formula(L, n, values)`` with L and n rows
    of shape (3, N) (the layout of the C call's outputs: nothing is converted per run), the
    scene's numbers, and the component of L it is when it is one (else None; see
    :attr:`derive.symbolic.integrable.Integral.component`); what
    :func:`derive.symbolic.integrable.integrals_for` wraps."""
    from derive.symbolic.integrable import classify, parameters

    def make():
        integral = classify(scene).extra
        return [] if integral is None else [(integral.name, integral.formula, parameters(scene),
                                             integral.component)]

    return _memo(_INTEGRAL_ROWS, _integrals_key(scene), make)


_INTEGRAL_ROWS: dict = {}


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


def recent(scene: Scene) -> Plan:
    """The plan of a validated scene: :func:`make`'s, or the one made for an equal scene among
    the last :data:`MEMO_SIZE` (its candidates' calls bound already: ``derive.simulate`` of a
    scene it ran recently skips the planning and the set-up of its C call).

    The memo's key is the scene's whole content (:func:`_content`: its numbers, signed zeros
    told apart, its settings, its source and title) and the version of the effects registry;
    a kept plan is used only while the model descriptions it was made with are still the ones
    :func:`derive.runtime.catalogue.describe` gives (``catalogue.clear_memory`` forgets them:
    a new cache, a registered effect), so a plan from the memo is the one :func:`make` would make.
    """
    key = _content(scene)
    kept = _PLANS.pop(key, None)  # out and in again: the most recent last (least recent first)
    if kept is not None and _current(kept):
        _PLANS[key] = kept
        return kept
    return _keep(_PLANS, key, make(scene))


def forget() -> None:
    """Empty the memo of :func:`recent` (and the integrals' memos)."""
    _PLANS.clear()
    _INTEGRAL_ROWS.clear()


def _current(pl: Plan) -> bool:
    """Whether a kept plan's model descriptions are still the catalogue's (forgotten together:
    the first candidate's tells)."""
    if not pl.candidates:
        return True
    c, sc = pl.candidates[0], pl.scene
    return catalogue.describe((c.desc.formulation, sc.symmetric, sc.effects)) is c.desc


def _content(scene: Scene) -> tuple:
    """A key of everything a plan is made from: ``Scene.__eq__``'s fields (the body, the effect
    tables, the initial state, the settings, the title and the terms) with their zeros signed
    (``-0.0 == 0.0``, but the sign can reach the outputs), the source (which ``==`` ignores but
    the error messages name) and the effects registry's version. The initial state goes in as
    its bytes (signed zeros apart; NaN, which no validated number is, for rates not given), the
    tables and terms by their text (``repr`` tells every float apart, -0.0 from 0.0 too); the
    body and the settings are positive numbers, names and None."""
    i = scene.initial
    ad = i.alpha_dot
    initial = _NINE(i.alpha, i.beta, i.gamma, *((ad, i.beta_dot, i.gamma_dot) if ad is not None else _NO_RATES),
                    *i.omega)
    return (scene.source, scene.title, scene.body, scene.simulate, initial,
            tuple((name, v.effect, repr(tuple(v._values.values()))) for name, v in scene.tables.items()),
            repr(scene.terms) if scene.terms else (), effects.VERSION[0])


_NINE = struct.Struct("9d").pack
_NO_RATES = (math.nan,) * 3
_PLANS: dict = {}
