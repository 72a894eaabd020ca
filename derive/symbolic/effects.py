"""Effects: what acts on the body besides its own inertia. A registry, one entry per effect.

Numbered contract of an entry (what a new effect provides, and nothing else needs editing):

1. ``name``: the registry key, also the part of a model's name that says the effect is present.
2. ``table``: the scene table that switches it on (``[gravity]``, ``[damping]``, …) with its
   keys (:class:`Key`: name, unit, meaning, check, default); several effects may share a table
   (axial and general gravity), and ``claims(values)`` says which one a table's values select.
3. ``params``: the model parameters it adds, in order, each a :class:`Param` with its SymPy
   assumptions, and ``values(table values) -> {param: float}``.
4. ``potential(R, sym)`` (conservative) or ``torque(omega, R, sym)`` (anything else), symbolic:
   ``R`` maps body to inertial components (v⁰ = R ṽ), ẑ is the inertial vertical, ω̃ is in body
   axes, ``sym(name)`` returns the parameter's SymPy symbol. Every formulation derives its
   equations from these two things:

   * Lagrangian (Euler angles): V enters L = T − V; a torque enters as the generalised force
     Q_j = τ̃ · ∂ω̃/∂q̇_j (virtual power).
   * Newton–Euler (quaternion, Euler–Poisson): τ̃ is used directly; a potential yields its
     torque by a virtual rotation R → R (1 + [δθ]ₓ):  τ̃_k = −∂V/∂δθ_k |₀.
5. ``axisymmetric``: the effect leaves the symmetry of a symmetric body about axis 3 and the
   vertical intact (V depends on the tilt alone), so p_α and p_γ stay conserved — what the
   reduced formulation needs. ``conservative``: it has a potential and no torque.
6. ``natural_rate(values, body)``: a rate (1/s) the effect sets, for default fixed steps.
7. ``vanishes(params) -> bool``: True when these parameter values (what ``values`` returns)
   make the potential and the torque identically zero (damping with c = 0, gravity with g = 0
   or the centre of mass at the pivot). Such an effect is not part of the scene's model: a
   scene pays nothing for a term that is zero, and the same body gets the same formulation
   however it is spelt (``Scene.effects`` leaves it out; its table's values stay readable).

Nothing here imports SymPy at module level: scene validation uses the tables on the warm path,
and only deriving a model calls ``potential``/``torque``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable

REQUIRED = object()  # a key without a default


@dataclass(frozen=True)
class Key:
    """One key of a scene table: ``kind`` "real" or "vector3"; ``check(x)`` must hold for a
    real (for a vector: for the vector as a tuple); ``must`` says what it must be."""

    name: str
    unit: str
    doc: str
    kind: str = "real"
    check: Callable[[Any], bool] | None = None
    must: str = "a finite number"
    default: Any = REQUIRED


@dataclass(frozen=True)
class Param:
    """A model parameter an effect adds: its name and SymPy assumptions."""

    name: str
    assumptions: tuple = ()  # e.g. (("positive", True),)


@dataclass(frozen=True)
class Table:
    """A scene table owned by effects: its keys, and groups of keys of which exactly one must be
    given (``one_of``; e.g. gravity's ``l`` or ``com``)."""

    name: str
    doc: str
    keys: tuple[Key, ...]
    one_of: tuple[tuple[str, ...], ...] = ()
    #: Fills derived keys from the validated values (gravity: com from l and l from com).
    complete: Callable[[dict], dict] = lambda values: values


@dataclass(frozen=True)
class Effect:
    """One effect (see the module docstring for the contract)."""

    name: str
    table: str
    description: str
    params: tuple[Param, ...]
    values: Callable[[dict], dict]
    claims: Callable[[dict], bool] = lambda values: True
    potential: Callable | None = None
    torque: Callable | None = None
    axisymmetric: bool = False
    natural_rate: Callable[[dict, Any], float] = lambda values, body: 0.0
    vanishes: Callable[[dict], bool] = lambda params: False

    @property
    def conservative(self) -> bool:
        return self.torque is None

    @property
    def param_names(self) -> tuple[str, ...]:
        return tuple(p.name for p in self.params)


# ---------------------------------------------------------------------------------------------
# the entries

def _positive(x):
    return x > 0


def _nonnegative(x):
    return x >= 0


def _com(values) -> tuple[float, float, float]:
    """The centre of mass (body axes, m, from the pivot): ``com``, or (0, 0, l)."""
    com = values.get("com")
    if com is not None:
        return tuple(map(float, com))  # map: no generator frame (scene validation calls this)
    return (0.0, 0.0, float(values["l"]))


def _on_axis(com) -> bool:
    return com[0] == 0.0 and com[1] == 0.0


def _axial(values) -> bool:
    return _on_axis(_com(values))


def _complete_gravity(values, com) -> dict:
    """The gravity table's values with ``com`` always set and ``l`` = com[2] when the centre of
    mass is on axis 3, else None. A centre of mass on axis 3 is ``l`` whichever key gave it:
    com is then (0.0, 0.0, l) exactly (a −0.0 spelt in the file does not survive), and the
    scene's canonical spelling is ``l`` (the first key of the one-of group the values fill)."""
    if _on_axis(com):
        return {**values, "com": (0.0, 0.0, com[2]), "l": com[2]}
    return {**values, "com": com, "l": None}


def _no_field(params) -> bool:
    """Gravity vanishes without a field or with the centre of mass at the pivot (M > 0)."""
    return params["g"] == 0.0 or all(params.get(k, 0.0) == 0.0 for k in ("l", "cx", "cy", "cz"))


def _gravity_potential(com_names):
    def V(R, sym):
        import sympy as sp

        com = sp.Matrix([sym(n) if isinstance(n, str) else n for n in com_names])
        # Height of the centre of mass, ẑ · (R r_c), times M g (g along −ẑ).
        return sym("M") * sym("g") * (R[2, :] * com)[0, 0]

    return V


def _gravity_rate(values, body) -> float:
    # Pendulum rate √(M g |r_c| / I_min).
    r = math.sqrt(sum(c * c for c in _com(values)))
    return math.sqrt(values["M"] * values["g"] * r / min(body.I1, body.I2, body.I3))


def _viscous(omega, R, sym):
    import sympy as sp

    return -sym("c") * sp.Matrix(omega)


GRAVITY_TABLE = Table(
    "gravity",
    "uniform field g along −z acting on mass M whose centre of mass sits at `com` (body principal "
    "axes, from the pivot), or on body axis 3 at signed distance `l` (l < 0: below the pivot "
    "when axis 3 points up). Absent table: no gravity terms at all.",
    keys=(
        Key("M", "kg", "mass", check=_positive, must="a positive finite number (kg)"),
        Key("g", "m/s^2", "field strength", check=_nonnegative,
            must="a non-negative finite number (m/s^2)"),
        Key("l", "m", "centre of mass on body axis 3 at this signed distance from the pivot",
            must="a finite number (m; negative = below the pivot)", default=None),
        Key("com", "m", "centre of mass [x, y, z] in body principal axes, from the pivot",
            kind="vector3", must="a list of 3 finite numbers [x, y, z] (m, body axes)",
            default=None),
    ),
    one_of=(("l", "com"),),
    complete=lambda v: _complete_gravity(v, _com(v)),
)

DAMPING_TABLE = Table(
    "damping",
    "viscous torque −c ω̃ about the fixed point (c = 0: no term, the undamped model runs; a "
    "scene pays nothing for a term that is zero)",
    keys=(Key("c", "N m s", "viscous coefficient", check=_nonnegative,
              must="a non-negative finite number (N m s)"),),
)

TABLES: dict[str, Table] = {t.name: t for t in (GRAVITY_TABLE, DAMPING_TABLE)}

#: The effect of a centre of mass anywhere (the analysis derives the general heavy body with it).
GENERAL_GRAVITY = "gravity_general"

REGISTRY: dict[str, Effect] = {e.name: e for e in (
    Effect(
        "gravity", "gravity",
        "uniform gravity g along −z, centre of mass on body axis 3 at distance l from the pivot",
        params=(Param("M", (("positive", True),)), Param("g", (("positive", True),)),
                Param("l", (("positive", True),))),
        values=lambda v: {"M": v["M"], "g": v["g"], "l": _com(v)[2]},
        claims=_axial,
        potential=_gravity_potential((0, 0, "l")),
        axisymmetric=True,
        natural_rate=_gravity_rate,
        vanishes=_no_field,
    ),
    Effect(
        "gravity_general", "gravity",
        "uniform gravity g along −z, centre of mass at (cx, cy, cz) in body axes",
        params=(Param("M", (("positive", True),)), Param("g", (("positive", True),)),
                Param("cx", (("real", True),)), Param("cy", (("real", True),)),
                Param("cz", (("real", True),))),
        values=lambda v: dict(zip(("M", "g", "cx", "cy", "cz"), (v["M"], v["g"], *_com(v)))),
        claims=lambda v: not _axial(v),
        potential=_gravity_potential(("cx", "cy", "cz")),
        natural_rate=_gravity_rate,
        vanishes=_no_field,
    ),
    Effect(
        "damping", "damping", "viscous torque −c ω about the pivot",
        params=(Param("c", (("nonnegative", True),)),),
        values=lambda v: {"c": v["c"]},
        torque=_viscous,
        natural_rate=lambda v, body: v["c"] / min(body.I1, body.I2, body.I3),
        vanishes=lambda params: params["c"] == 0.0,
    ),
)}


#: The scene's arrays of tables whose entries are terms written by the user (``[[potential]]``,
#: ``[[torque]]``; :mod:`derive.symbolic.terms`): each term is an effect of its own, registered
#: by content when a scene names it, and these names are not tables of TABLES.
USER_TABLES = ("potential", "torque")


def register(effect: Effect, table: Table | None = None) -> None:
    """Add an effect (and, if new, its table). Tables and effects keep registration order, which
    fixes the order of a model's parameters."""
    if table is not None:
        TABLES[table.name] = table
    if effect.table not in TABLES and effect.table not in USER_TABLES:
        raise ValueError(f"effect {effect.name!r}: unknown table {effect.table!r}")
    REGISTRY[effect.name] = effect


def unregister(name: str) -> None:
    """Remove an effect, and its table when no other effect uses it (tests register toys)."""
    effect = REGISTRY.pop(name)
    if not any(e.table == effect.table for e in REGISTRY.values()):
        TABLES.pop(effect.table, None)


def for_table(table: str, values: dict) -> Effect:
    """The effect a table's (validated) values select."""
    for e in REGISTRY.values():
        if e.table == table and e.claims(values):
            return e
    raise ValueError(f"no effect claims the values of [{table}]")


def ordered(names) -> tuple[str, ...]:
    """The effects named, in registry order: the built-in (and registered) tables' effects in
    the order they were registered, then the user's terms by kind (``USER_TABLES``) and name
    (a digest of their content). So a model's effects, its name and its parameter layout depend
    neither on the order a scene lists them in nor on which user terms this process registered
    first (a second process, registering the scene's terms afresh, finds the same model)."""
    unknown = [n for n in names if n not in REGISTRY]
    if unknown:
        raise KeyError(f"unknown effect {unknown[0]!r} (known: {', '.join(REGISTRY)})")
    wanted = set(names)
    tables = [n for n, e in REGISTRY.items() if n in wanted and e.table not in USER_TABLES]
    users = sorted((n for n in wanted if REGISTRY[n].table in USER_TABLES),
                   key=lambda n: (USER_TABLES.index(REGISTRY[n].table), n))
    return tuple(tables + users)


def lookup(names) -> tuple[Effect, ...]:
    """The effects named, in registry order (:func:`ordered`)."""
    return tuple(REGISTRY[n] for n in ordered(names))
