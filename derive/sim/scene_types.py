"""The scene's types: a validated scene (:class:`Scene`, its :class:`Body`, effect tables
(:class:`TableValues`), :class:`Initial` state and :class:`Simulate` settings), the limits the
validator holds it to.

Takes: the registries (effects, formulations, methods). Gives: the types :mod:`derive.sim.scene`
loads a scene into.
"""
from __future__ import annotations

import dataclasses
import functools
import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from derive.methods import registry as solvers
from derive.symbolic import effects
from derive.symbolic import formulations
from derive.symbolic import terms as user_terms


#: Integration methods: name -> one-line description (from the solver registry).
METHODS: dict[str, str] = solvers.scene_methods()


#: The methods that take a fixed step size ``h``.
FIXED_STEP_METHODS = solvers.fixed_step_methods()


#: Formulations of the equations of motion: name -> one-line description (the registry).
FORMULATIONS: dict[str, str] = formulations.CHOICES


#: Defaults of the optional ``[simulate]`` keys (t_end has none: it is required).
SIMULATE_DEFAULTS = {
    "samples": 1001, "method": "auto", "rtol": 1e-10, "atol": 1e-12, "formulation": "auto",
    "h": None, "max_steps": 1_000_000,
}


MAX_SAMPLES = 10_000_000


#: Smallest rtol accepted, inclusive: 100 machine epsilons written as the documented 2.2e-14
#: (100 eps itself is 2.220446...e-14, so a user typing the documented limit was refused).
MIN_RTOL = float(f"{100 * np.finfo(float).eps:.1e}")


#: |sin(beta)| below this counts as "at a pole" of the z-y-z Euler angles.
POLE_TOLERANCE = 1e-9


MAX_STEPS_LIMIT = 10**12


#: Relative slack of the triangle inequality, so that a flat plate (I3 = I1 + I2) survives rounding.
TRIANGLE_SLACK = 1e-12


def _vanishes(values: "TableValues") -> bool:
    """True when a table's values make its effect vanish (the effects contract, item 7)."""
    effect = effects.REGISTRY[values.effect]
    return effect.vanishes(effect.values(values))


def _acting(tables: dict, terms: tuple = ()) -> tuple[str, ...]:
    """The effects of ``tables`` that act on the body (vanishing ones left out) and those of the
    user's ``terms``, in registry order."""
    return effects.ordered(tuple(t.effect for t in tables.values() if not _vanishes(t))
                              + tuple(t.effect for t in terms))


@dataclass(frozen=True)
class Body:
    """Principal moments of inertia in kg m^2, about the fixed point (about the centre of mass
    when the scene has no gravity). Axis 3 is the symmetry axis of a symmetric body."""

    I1: float
    I2: float
    I3: float

    @property
    def moments(self) -> tuple[float, float, float]:
        return (self.I1, self.I2, self.I3)


class TableValues(Mapping):
    """The validated values of an effect's table (``scene.gravity.M``, ``scene.damping.c``),
    absent optional keys as None; ``effect`` names the registry effect they select. For gravity,
    ``com`` is always set ((0, 0, l) when l was given) and ``l`` is com[2] when the centre of
    mass is on axis 3, else None."""

    def __init__(self, table: str, values: dict, effect: str):
        self.__dict__.update(_table=table, _values=dict(values), effect=effect)

    def __getattr__(self, key):
        try:
            return self.__dict__["_values"][key]
        except KeyError:
            raise AttributeError(key) from None

    def __setattr__(self, key, value):
        raise AttributeError("scene tables are read-only")

    def __getitem__(self, key):
        return self._values[key]

    def __iter__(self):
        return iter(self._values)

    def __len__(self):
        return len(self._values)

    def __eq__(self, other):
        return (isinstance(other, TableValues) and self._table == other._table
                and self._values == other._values)

    def __hash__(self):
        return hash((self._table, tuple(sorted(self._values.items()))))

    def __repr__(self):
        return f"TableValues({self._table!r}, {self._values!r})"

    def given(self) -> dict:
        """The keys as a scene file would give them (None values and derived keys dropped)."""
        return {k: (list(v) if isinstance(v, tuple) else v) for k, v in self._values.items()
                if v is not None and k in self.__dict__["_given"]}


@dataclass(frozen=True)
class Initial:
    """Initial orientation (z-y-z Euler angles, rad) and angular velocity.

    ``omega`` (body frame, rad/s) is always set. The Euler-angle rates (rad/s) are set only when
    the scene gave them; when it gave ``omega`` they are None, because the inverse map divides
    by sin(beta).
    """

    alpha: float
    beta: float
    gamma: float
    alpha_dot: float | None
    beta_dot: float | None
    gamma_dot: float | None
    omega: tuple[float, float, float]

    @property
    def has_rates(self) -> bool:
        return self.alpha_dot is not None

    @property
    def at_pole(self) -> bool:
        """True when beta is (numerically) 0 or pi, where the Euler angles are singular."""
        return abs(math.sin(self.beta)) < POLE_TOLERANCE


@dataclass(frozen=True)
class Simulate:
    """How to integrate: up to ``t_end`` (s), output at ``samples`` equally spaced times from 0
    to t_end inclusive, with ``method`` (a key of METHODS), tolerances ``rtol``/``atol``, the
    ``formulation`` (a key of FORMULATIONS) and, for fixed-step methods, step ``h`` (s) or None."""

    t_end: float
    samples: int
    method: str
    rtol: float
    atol: float
    formulation: str
    h: float | None
    max_steps: int = SIMULATE_DEFAULTS["max_steps"]


@dataclass(frozen=True)
class Scene:
    """A validated scene. ``gravity``/``damping`` are None when their table is absent.
    ``source`` names the origin in error messages and is ignored by ``==``."""

    title: str | None
    body: Body
    tables: dict  # effect table name -> TableValues, for the tables present
    initial: Initial
    simulate: Simulate
    source: str = field(default="<dict>", compare=False)
    #: The user's terms (``[[potential]]``, ``[[torque]]``: :class:`derive.symbolic.terms.Term`),
    #: potentials first, each kind in the file's order.
    terms: tuple = ()

    def __getattr__(self, name):
        # An effect table's values (scene.gravity, scene.damping, …), or None when absent.
        if name.startswith("_") or name not in effects.TABLES:
            raise AttributeError(name)
        return self.tables.get(name)

    @functools.cached_property
    def effects(self) -> tuple[str, ...]:
        """The registry effects acting on the body, in registry order, e.g.
        ("gravity", "damping") or ("gravity_general",): the ones the scene's tables select,
        less those whose values make them vanish (``[damping] c = 0``, ``g = 0``; the effects
        contract, item 7). They fix the model: a term that is zero costs nothing."""
        return _acting(self.tables, self.terms)

    @property
    def named_effects(self) -> tuple[str, ...]:
        """Every effect the scene's tables select, acting or not, in registry order."""
        return effects.ordered(tuple(t.effect for t in self.tables.values())
                                  + tuple(t.effect for t in self.terms))

    def param_values(self) -> dict[str, float]:
        """Every model parameter the scene fixes: the moments and each effect's parameters."""
        b = self.body
        values = {"I1": b.I1, "I2": b.I2, "I3": b.I3}
        for t in self.tables.values():
            values.update(effects.REGISTRY[t.effect].values(t))
        for term in self.terms:
            values.update({term.model_param(p): v for p, v in term.params})
        return values

    @property
    def symmetric(self) -> bool:
        return self.body.I1 == self.body.I2

    @property
    def t_out(self) -> np.ndarray:
        """Output times (s): ``samples`` points from 0 to t_end inclusive (what np.linspace
        gives, bit for bit: k·(t_end/(samples − 1)), the last one t_end exactly)."""
        n, t_end = self.simulate.samples, self.simulate.t_end
        t = np.arange(n, dtype=np.float64) * (t_end / (n - 1))
        t[-1] = t_end
        return t

    def to_dict(self) -> dict:
        """The scene as a TOML-shaped dict; ``load_scene(scene.to_dict()) == scene``."""
        ini = self.initial
        initial = {"alpha": ini.alpha, "beta": ini.beta, "gamma": ini.gamma}
        if ini.has_rates:
            initial.update(alpha_dot=ini.alpha_dot, beta_dot=ini.beta_dot, gamma_dot=ini.gamma_dot)
        else:
            initial["omega"] = list(ini.omega)
        simulate = {k: v for k, v in dataclasses.asdict(self.simulate).items() if v is not None}
        data = {"body": dataclasses.asdict(self.body)}
        for name, values in self.tables.items():
            data[name] = values.given()
        for kind in user_terms.KINDS:
            given = [t.given() for t in self.terms if t.kind == kind]
            if given:
                data[kind] = given
        data.update(initial=initial, simulate=simulate)
        if self.title is not None:
            data["title"] = self.title
        return data
