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
from dataclasses import dataclass, field

import numpy as np

from derive.errors import IntegrationError
from derive.methods import costs
from derive.methods.registry import DEFAULT_METHOD, REFERENCE_METHODS
from derive.runtime import catalogue
from derive.runtime.integrate import BoundRun, ModelKernel
from derive.sim import auto
from derive.sim.inputs import AUTO, _settings, choose_method, fastest_rate, inputs_of, params_of
from derive.sim.scene import Scene, same_numbers
from derive.symbolic import effects, integrable
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
        if self.adopt():
            return self.__dict__["kernel"]
        # a SciPy reference takes the init and output maps from the default method's library
        return ModelKernel.load(self.desc, self.method if self.method not in SCIPY_METHODS
                                else DEFAULT_METHOD)

    @functools.cached_property
    def params(self) -> np.ndarray:
        return params_of(self.scene, self.desc)

    @functools.cached_property
    def args(self) -> list:
        if self.adopt() and "args" in self.__dict__:
            return self.__dict__["args"]
        return _settings(self.scene, self.method, self.kernel)

    def sibling(self, scene: Scene, same: bool) -> "Candidate":
        """This candidate for ``scene``, a scene of the same family (:func:`_family`: the same
        settings, model and source; other numbers). Its parameters are this one's where the
        scene has the very same body and effect values (``same``:
        :func:`derive.sim.scene.same_numbers`; a run copies them into its buffer: shared, never
        written); its method is worked out for
        ``scene``, and where it is this one's the rest is shared too (:meth:`adopt`)."""
        other = Candidate(scene, self.given, self.desc, self.pole_check)
        other.__dict__["_near"] = self
        if same:
            other.__dict__["params"] = self.params
        return other

    def adopt(self) -> bool:
        """Whether this candidate is a sibling running its near candidate's method; if so, take
        what they share (once), set straight into the instance: the kernel, and for an adaptive
        method (its driver arguments are the settings alone) the driver arguments and the bound
        C call, bound to the near plan's inputs (a run passes its own: ``BoundRun.inputs`` tells
        which were bound). The one place these rules live: the properties ask it first."""
        d = self.__dict__
        near = d.get("_near")
        if near is None or near.method != self.method:
            return False
        if "kernel" not in d:
            d["kernel"] = kernel = near.kernel
            if kernel.adaptive:
                d["args"] = near.args
                b = near.__dict__.get("_bound")
                if b is not None:
                    d["_bound"] = b
        return True

    @functools.cached_property
    def pole_loss(self) -> bool:
        """Whether the formulation loses accuracy near β = 0, π (the result's pole check)."""
        return REGISTRY[self.desc.formulation].pole_loss

    def bound(self, t: np.ndarray, inputs: np.ndarray) -> BoundRun:
        """The kernel's C call bound to the plan's output times and inputs (made on first use,
        then kept: a candidate belongs to one plan, whose ``t`` and ``inputs`` do not change).
        A sibling takes its near candidate's (:meth:`adopt`)."""
        b = self.__dict__.get("_bound")
        if b is None and self.adopt():
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
    #: The plan this one was made from (:func:`sibling`), else None.
    near: "Plan | None" = field(default=None, repr=False, compare=False)
    #: :func:`derive.runtime.catalogue.generation` when the candidates' descriptions were made.
    generation: int = field(default_factory=catalogue.generation, repr=False, compare=False)

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
        run does not classify its scene again; a sibling plan with its near plan's body and
        effect values takes its rows, unless its case may depend on the state)."""
        near, sc = self.near, self.scene
        if near is not None and same_numbers(sc, near.scene) and not integrals_depend_on_state(sc):
            return near.integral_rows
        return integral_rows_of(sc)


def integrals_depend_on_state(scene: Scene) -> bool:
    """Whether the scene's integrable case may depend on its initial state, not on its body and
    effect values alone (a Goryachev–Chaplygin body: the case holds on L·n = 0 only): scenes
    that differ only in their start then may not share :func:`integral_rows_of`."""
    return integrable.needs_area_level(*scene.body.moments)


def _integrals_key(scene: Scene) -> tuple:
    # The case depends on the body and the effects' numbers, and for a Goryachev–Chaplygin body
    # on whether the state is on L·n = 0 (a cheap test): classified once per body and level.
    level = integrable.on_area_level(scene) if integrals_depend_on_state(scene) else None
    return (scene.body, tuple((k, v.effect, tuple(v._values.values())) for k, v in scene.tables.items()),
            level)


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
    def make():
        integral = integrable.classify(scene).extra
        return [] if integral is None else [(integral.name, integral.formula, integrable.parameters(scene),
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
    family = _family(scene)
    near = _FAMILIES.get(family)
    pl = sibling(near, scene) if near is not None and _current(near) else None
    if pl is None:
        pl = _keep(_FAMILIES, family, make(scene))
    return _keep(_PLANS, key, pl)


def for_dict(key: tuple, load) -> Plan:
    """The plan of a scene dict whose raw content has the key ``key``
    (:func:`derive.sim.scene.dict_key`): the plan kept for an equal dict among the last
    :data:`MEMO_SIZE`, else :func:`recent`'s plan of ``load()`` (the dict validated), kept. An
    equal dict validates to an equal scene, so ``derive.simulate`` of a dict it ran recently
    skips the validation too: a short call 25 -> 12-17 us."""
    kept = _DICT_PLANS.pop(key, None)  # out and in again: the most recent last
    if kept is None or not _current(kept):
        kept = recent(load())
    return _keep(_DICT_PLANS, key, kept)


def sibling(near: Plan, scene: Scene) -> Plan | None:
    """The plan of ``scene`` made from ``near``, the plan of a scene of the same family
    (:func:`_family`: other numbers, the rest equal), or None when the numbers change what
    auto decides (the formulations to try, their pole checks, the first one's method): then
    :func:`make` plans it. The candidates are ``near``'s siblings (:meth:`Candidate.sibling`):
    what :func:`make` would give, with the kernels and bound C calls ``near`` has set up
    already (a scene with new numbers is validated and planned, but its C call is not set up
    again)."""
    method = choose_method(scene)
    steps = [(auto.model_key(scene, method)[0], 0)] if method in SCIPY_METHODS else auto.plan(scene)
    if len(steps) != len(near.candidates) or any(
            c.desc.formulation != name or c.pole_check != mode for c, (name, mode) in zip(near.candidates, steps)):
        return None
    same = same_numbers(scene, near.scene)
    candidates = tuple(c.sibling(scene, same) for c in near.candidates)
    if candidates:
        if candidates[0].method != near.candidates[0].method:
            return None
        candidates[0].adopt()  # now (the others on first use: a fallback rarely runs)
    # the same settings (the family's): the same output times, and the bound calls keep near's
    return Plan(scene, candidates[0].method if candidates else method, near.t, inputs_of(scene), candidates,
                near, near.generation)


def _family(scene: Scene) -> tuple:
    """A key of what a plan takes from a scene other than its numbers (the initial state, the
    moments, the effects' values): the settings, the source and title, the model (body
    symmetry, acting effects, each table's effect), the shape of the initial state (rates or
    ω̃), the terms and the effects registry's version. Scenes of one family differ only in
    numbers, and a plan of one is the start of the others' (:func:`sibling`)."""
    return (scene.source, scene.title, scene.simulate, scene.symmetric, scene.effects,
            tuple((name, v.effect) for name, v in scene.tables.items()), scene.initial.alpha_dot is None,
            repr(scene.terms) if scene.terms else (), effects.VERSION[0])


def forget() -> None:
    """Empty the memos of :func:`recent` and :func:`for_dict` (and the integrals' memos)."""
    _PLANS.clear()
    _DICT_PLANS.clear()
    _FAMILIES.clear()
    _INTEGRAL_ROWS.clear()


def _current(pl: Plan) -> bool:
    """Whether a kept plan's model descriptions are still the catalogue's: the catalogue has
    not forgotten its descriptions since (``catalogue.clear_memory``: a new cache). A newly
    registered effect changes the memos' keys instead (the effects registry's version)."""
    return pl.generation == catalogue.generation()


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
#: The plans of recent scene dicts, by their raw content (:func:`for_dict`).
_DICT_PLANS: dict = {}
#: The latest plan made anew (:func:`make`) of each family (:func:`_family`).
_FAMILIES: dict = {}
