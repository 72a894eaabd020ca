"""A scene with a ``[contact]`` table, validated: the body, gravity, the contact and the start.

The format (see ``docs/contact.md``): ``[body]`` I1, I2 (default I1), I3 about the centre of
mass; ``[gravity]`` M, g (no ``l``/``com``: the contact places the centre of mass);
``[contact]`` shape, radius, offset, friction, mu, regularization, restitution, the law's
extensions ``rolling_resistance`` and ``spin_friction`` (lengths, :data:`derive.contact.laws.EXTENSIONS`),
and ``stem`` (a second sphere on axis 3, ``{radius, offset}``, with a sphere: the tippe top's stem);
``[initial]`` the z-y-z angles, their rates or ``omega``, and ``vx``, ``vy`` (not with
``rolling``); ``[simulate]`` t_end, samples, method, rtol, atol, max_steps. Every problem is a
:class:`~derive.errors.SceneError` ``<file>: <key>: <what>``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from derive.contact.laws import EXTENSIONS
from derive.errors import scene_error
from derive.methods.registry import DEFAULT_METHOD, REFERENCE_METHODS
from derive.symbolic.effects import TABLES

FRICTIONS = ("none", "coulomb", "viscous", "rolling")
#: The shapes of :data:`derive.contact.geometry.SHAPES` (named here so reading a scene needs no SymPy).
SHAPES = ("point", "sphere", "disc")
#: The shapes whose ``spherical`` is set there: the contact point on a sphere about a point of
#: the symmetry axis (a tip is a sphere of radius 0).
SPHERICAL = ("point", "sphere")
#: The effect table that holds M and g (the only effect a contact scene has besides the contact).
GRAVITY = next(name for name, t in TABLES.items() if {"M", "g"} <= {k.name for k in t.keys})
#: The steppers: the compiled phase loop on the registry's DOP853 tableau ("auto"), and SciPy's
#: DOP853 stepping the same compiled right-hand sides from Python (a reference).
COMPILED = DEFAULT_METHOD
METHOD = next(name for name, (cls, _) in REFERENCE_METHODS.items() if cls == "DOP853")
METHODS = ("auto", COMPILED, METHOD)
_KEYS = {
    "body": ("I1", "I2", "I3"),
    GRAVITY: ("M", "g"),
    "contact": ("shape", "radius", "offset", "friction", "mu", "regularization", "restitution", "stem",
                *EXTENSIONS),
    "initial": ("alpha", "beta", "gamma", "alpha_dot", "beta_dot", "gamma_dot", "omega", "vx", "vy"),
    "simulate": ("t_end", "samples", "method", "rtol", "atol", "max_steps"),
}
# The limits every scene has (derive.sim.scene's, which this stage may not import): rtol from
# 100 machine epsilons (written as the documented 2.2e-14), samples and steps capped so that a
# typo cannot exhaust memory or time, the triangle inequality with a slack for rounding.
MIN_RTOL = float(f"{100 * 2.0 ** -52:.1e}")
MAX_SAMPLES = 10_000_000
MAX_STEPS_LIMIT = 10**12
TRIANGLE_SLACK = 1e-12
_REQUIRED = {"body": ("I1", "I3"), GRAVITY: ("M", "g"), "contact": ("shape", "friction")}


@dataclass(frozen=True)
class ContactScene:
    """The validated numbers of a top on a table (SI units, radians)."""

    source: str
    title: str
    I1: float
    I2: float
    I3: float
    M: float
    g: float
    shape: str
    radius: float
    offset: float
    friction: str
    mu: float
    regularization: float | None
    restitution: float
    angles: tuple[float, float, float]
    rates: tuple[float, float, float] | None
    omega: tuple[float, float, float] | None
    vx: float
    vy: float
    t_end: float
    samples: int
    method: str
    rtol: float
    atol: float
    max_steps: int
    #: The second sphere (radius, offset along ê₃ from the centre of mass), or None.
    stem: tuple[float, float] | None = None
    #: The law's extensions' lengths by their key (:data:`~derive.contact.laws.EXTENSIONS`; 0: off).
    extensions: tuple[tuple[str, float], ...] = ()

    def extension(self, key: str) -> float:
        """The length of the extension ``key`` (0 when the scene does not set it)."""
        return dict(self.extensions).get(key, 0.0)

    @property
    def moments(self) -> bool:
        """Whether an extension's moment acts (some length is positive)."""
        return any(v > 0 for _, v in self.extensions)

    @property
    def law(self) -> str:
        return "coulomb_regularized" if self.friction == "coulomb" and self.regularization is not None \
            else self.friction

    @property
    def symmetric(self) -> bool:
        return self.I1 == self.I2

    @property
    def simulate(self):
        return self  # rtol, atol as the [simulate] table of other scenes


def _number(source, t, table, key, default=None, test=None, must="a finite number"):
    if key not in t:
        if default is None and key in _REQUIRED.get(table, ()):
            raise scene_error(source, f"{table}.{key}", "missing")
        return default
    v = t[key]
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
        raise scene_error(source, f"{table}.{key}", f"must be {must}")
    if test is not None and not test(v):
        raise scene_error(source, f"{table}.{key}", f"must be {must}")
    return float(v)


def read(data: dict, source: str = "<dict>", **overrides) -> ContactScene:
    """Validate a contact scene.

    Parameters
    ----------
    data : dict
        The scene, shaped like the TOML.
    source : str
        What names the scene in error messages.
    **overrides
        Replace keys of ``[simulate]``; None means "not given".

    Returns
    -------
    ContactScene
        The numbers, SI units and radians (z-y-z angles: α about ẑ, β about the intermediate
        y′ axis, γ about the body axis ê₃).

    Raises
    ------
    SceneError
        ``<source>: <table.key>: <what is wrong>``, the first problem found.
    """
    for key in data:
        if key == "title":
            continue
        if key not in _KEYS:
            raise scene_error(source, key, f"unknown table beside [contact] (tables: {', '.join(_KEYS)})")
        if not isinstance(data[key], dict):
            raise scene_error(source, key, "must be a table")
        for k in data[key]:
            if key == GRAVITY and k in ("l", "com"):
                raise scene_error(source, f"{GRAVITY}.{k}", "not with [contact]: the contact places the centre of mass")
            if k not in _KEYS[key]:
                raise scene_error(source, f"{key}.{k}", f"unknown key (known: {', '.join(_KEYS[key])})")
    for table in ("body", GRAVITY, "contact"):
        if table not in data:
            raise scene_error(source, table, "missing table")
    b, gr, c = data["body"], data[GRAVITY], data["contact"]
    ini, sim = data.get("initial", {}), dict(data.get("simulate", {}))
    sim.update({k: v for k, v in overrides.items() if v is not None})
    pos = lambda x: x > 0
    I1 = _number(source, b, "body", "I1", test=pos, must="a positive number")
    I2 = _number(source, b, "body", "I2", I1, test=pos, must="a positive number")
    I3 = _number(source, b, "body", "I3", test=pos, must="a positive number")
    for i, j, k in ((I1, I2, I3), (I2, I3, I1), (I3, I1, I2)):
        if i + j < k * (1 - TRIANGLE_SLACK):
            raise scene_error(source, "body", "the moments violate the triangle inequality I1 + I2 >= I3")
    M = _number(source, gr, GRAVITY, "M", test=pos, must="a positive number")
    g = _number(source, gr, GRAVITY, "g", test=lambda x: x >= 0, must="a number >= 0")
    shape = c.get("shape")
    if shape not in SHAPES:
        raise scene_error(source, "contact.shape", f"unknown shape {shape!r} (known: {', '.join(SHAPES)})")
    friction = c.get("friction")
    if friction not in FRICTIONS:
        raise scene_error(source, "contact.friction", f"unknown law {friction!r} (known: {', '.join(FRICTIONS)})")
    radius = _number(source, c, "contact", "radius", 0.0, lambda x: x >= 0, "a number >= 0")
    if shape != "point" and not radius > 0:
        raise scene_error(source, "contact.radius", f"must be a positive number for a {shape}")
    if shape == "point" and radius != 0:
        raise scene_error(source, "contact.radius", "must be 0 (or absent) for a point")
    offset = _number(source, c, "contact", "offset", 0.0)
    needs_mu = friction in ("coulomb", "viscous")
    mu = _number(source, c, "contact", "mu", None, lambda x: x >= 0, "a number >= 0")
    if needs_mu and mu is None:
        raise scene_error(source, "contact.mu", f"missing (friction = {friction!r} needs it)")
    if not needs_mu and mu is not None:
        raise scene_error(source, "contact.mu", f"not with friction = {friction!r}")
    reg = _number(source, c, "contact", "regularization", None, pos, "a positive number (m/s)")
    if reg is not None and friction != "coulomb":
        raise scene_error(source, "contact.regularization", "only with friction = 'coulomb'")
    stem = _stem(source, c, shape)
    extensions = []
    for key, ext in EXTENSIONS.items():
        length = _number(source, c, "contact", key, None, lambda x: x >= 0, "a length >= 0 (m)")
        if length is not None and friction not in ext.frictions:
            raise scene_error(source, f"contact.{key}", f"not with friction = {friction!r} "
                                                  f"(only with {' or '.join(map(repr, ext.frictions))})")
        extensions.append((key, 0.0 if length is None else length))
    e = _number(source, c, "contact", "restitution", 0.0, lambda x: 0 <= x <= 1, "a number in [0, 1]")
    angles = tuple(_number(source, ini, "initial", k, 0.0) for k in ("alpha", "beta", "gamma"))
    has_rates = any(k in ini for k in ("alpha_dot", "beta_dot", "gamma_dot"))
    rates = omega = None
    if "omega" in ini:
        if has_rates:
            raise scene_error(source, "initial.omega", "give either the rates or omega, not both")
        w = ini["omega"]
        if not (isinstance(w, list) and len(w) == 3 and all(
                isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x) for x in w)):
            raise scene_error(source, "initial.omega", "must be three finite numbers")
        omega = tuple(float(x) for x in w)
    else:
        rates = tuple(_number(source, ini, "initial", k, 0.0) for k in ("alpha_dot", "beta_dot", "gamma_dot"))
    if friction == "rolling":
        for k in ("vx", "vy"):
            if k in ini:
                raise scene_error(source, f"initial.{k}", "not with friction = 'rolling' (the no-slip condition sets it)")
    vx, vy = (_number(source, ini, "initial", k, 0.0) for k in ("vx", "vy"))
    t_end = _number(source, sim, "simulate", "t_end", 1.0, pos, "a positive number")
    samples = sim.get("samples", 1001)
    if isinstance(samples, bool) or not isinstance(samples, int) or not 2 <= samples <= MAX_SAMPLES:
        raise scene_error(source, "simulate.samples", f"must be an integer from 2 to {MAX_SAMPLES}")
    method = sim.get("method", "auto")
    if method not in METHODS:
        raise scene_error(source, "simulate.method", f"unknown method {method!r} for a contact scene "
                                               f"(known: {', '.join(METHODS)})")
    rtol = _number(source, sim, "simulate", "rtol", 1e-10, lambda x: MIN_RTOL <= x < 1,
                   f"a number in [{MIN_RTOL:.1e}, 1) (100 machine epsilons and up)")
    atol = _number(source, sim, "simulate", "atol", 1e-12, pos, "a positive number")
    max_steps = sim.get("max_steps", 1_000_000)
    if isinstance(max_steps, bool) or not isinstance(max_steps, int) or not 1 <= max_steps <= MAX_STEPS_LIMIT:
        raise scene_error(source, "simulate.max_steps", f"must be an integer from 1 to {MAX_STEPS_LIMIT:.0e}")
    title = data.get("title", "")
    if not isinstance(title, str):
        raise scene_error(source, "title", "must be a string")
    return ContactScene(source, title, I1, I2, I3, M, g, shape, radius, offset, friction,
                        0.0 if mu is None else mu, reg, e, angles, rates, omega, vx, vy,
                        t_end, samples, method, rtol, atol, max_steps, stem=stem, extensions=tuple(extensions))


def _stem(source, c, shape):
    """``[contact] stem = {radius, offset}``: a second sphere the body may touch the plane with."""
    if "stem" not in c:
        return None
    st = c["stem"]
    if shape != "sphere":
        raise scene_error(source, "contact.stem", "only with shape = 'sphere'")
    if not isinstance(st, dict) or set(st) - {"radius", "offset"} or "radius" not in st:
        raise scene_error(source, "contact.stem", "must be a table {radius = ..., offset = ...}")
    r = _number(source, st, "contact.stem", "radius", None, lambda x: x > 0, "a positive number")
    return r, _number(source, st, "contact.stem", "offset", 0.0)


def integrals_held(shape: str, law: str, symmetric: bool, moments: bool = False) -> tuple[str, ...]:
    """The integrals a case has, by what the law, the shape and the body's symmetry allow:
    E frictionless or rolling; p_α frictionless, and p_γ with I₁ = I₂; Jellett's J = (I ω)·a
    for an axisymmetric body on a spherical surface, and Routh's for a ball rolling. An
    extension's moment (``moments``: rolling resistance, spin friction) dissipates E and has a
    part along a, so none of them holds then."""
    if moments:
        return ()
    out = []
    if law in ("none", "rolling"):
        out.append("energy")
    if law == "none":
        out.append("p_alpha")
        if symmetric:
            out.append("p_gamma")
    if symmetric and shape in SPHERICAL:
        out.append("jellett")
        if law == "rolling" and shape == "sphere":
            out.append("routh")
    return tuple(out)
